"""Identify friction on the real EMPS benchmark data (Janot, Gautier, Brunot;
nonlinearbenchmark.org): re-run the published inverse-dynamic-model baseline
(M ddq + Fv dq + Fc sign(dq) + OF = gtau vir) and fit an asymmetric LuGre law on DATA_EMPS,
then compare both on DATA_EMPS_PULSES (relative motor-force error).

    python examples/identify_emps.py [--algorithm NAME] [--json OUT]
"""
import argparse

import numpy as np

from friction import make_model
from identification import identify
from identification.real_data import EMPS_PUBLISHED, emps_baseline, load_emps

NAMES = ["sigma0", "sigma1", "sigma2", "sigma2_neg", "Fc", "Fc_neg", "Fs", "Fs_neg", "vs", "b"]


def relative_error(ds, friction_force):
    y = ds.extra["motor_force"]
    return np.linalg.norm(y - (EMPS_PUBLISHED["M"] * ds.a + friction_force)) / np.linalg.norm(y)


def run_identify_emps(algorithm: str = "least_squares", json_out=None, max_evals=None,
                      every: int = 1, progress=True) -> dict:
    """Re-run the baseline, fit the LuGre law on DATA_EMPS, score both on both records.

    Parameters
    ----------
    algorithm : str
        Identification algorithm (``identification.ALGORITHMS``).
    json_out : str, optional
        Write the identification result as JSON here.
    max_evals : int, optional
        Evaluation budget (simulations); default the algorithm's.
    every : int
        Fit on every ``every``-th sample of DATA_EMPS (1: all; larger for a quick run).
    progress : bool
        Progress lines on stderr.

    Returns
    -------
    dict
        ``baseline`` (fitted vs published values), ``result`` (the identification
        result), ``errors`` (relative motor-force error per record, baseline and LuGre).
    """
    base = emps_baseline()
    print("baseline (this run) vs published:")
    for k, v in EMPS_PUBLISHED.items():
        print(f"  {k:<3} {getattr(base, k):10.4f}  published {v:10.4f}  "
              f"({getattr(base, k) / v - 1:+.2%})")
    est, val = load_emps("estimation"), load_emps("validation")
    start = make_model("lugre", sigma0=1e5, sigma1=100.0, sigma2=200.0, sigma2_neg=200.0,
                       Fc=20.0, Fc_neg=20.0, Fs=25.0, Fs_neg=25.0, vs=0.01, b=-3.0)
    fit = est if every == 1 else est.select(slice(0, None, every))
    r = identify(fit, start, algorithm=algorithm, names=NAMES, validation=val,
                 progress=progress, max_evals=max_evals)
    print(r.summary())
    errors = {}
    for label, ds in (("DATA_EMPS       ", est), ("DATA_EMPS_PULSES", val)):
        eb = relative_error(ds, base.friction(ds.v))
        el = relative_error(ds, r.model.simulate(ds.t, ds.v))
        errors[label.strip()] = {"baseline": eb, "lugre": el}
        print(f"relative error on {label}: baseline {eb:.2%}, LuGre {el:.2%}")
    if json_out:
        r.to_json(json_out)
    return {"baseline": {k: getattr(base, k) for k in EMPS_PUBLISHED}, "result": r,
            "errors": errors}


if __name__ == "__main__":
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--algorithm", default="least_squares")
    ap.add_argument("--json", default=None)
    args = ap.parse_args()
    run_identify_emps(args.algorithm, args.json)
