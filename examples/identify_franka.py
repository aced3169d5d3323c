"""Fit our LuGre law to the Franka Panda joint friction data (case 3 = joint 2, case 4 =
joint 7; source: longshike/NNFM...) and compare its RMS [N m] with the source paper's LuGre
RMS (friction_model_comparison_all_results_filtered.csv), case by case and speed by speed.

    python examples/identify_franka.py
"""
from friction import make_model
from friction.metrics import rmse
from identification import identify
from identification.real_data import franka_paper_rms, load_franka

NAMES = ["sigma0", "sigma1", "sigma2", "sigma2_neg", "Fc", "Fc_neg", "Fs", "Fs_neg", "vs", "b"]


def run_identify_franka(cases=(3, 4), speeds=("slow", "middle", "high"), every: int = 5,
                        max_evals=None) -> dict:
    """Fit the LuGre law to each case and speed; print and return ours vs the paper's RMS.

    Parameters
    ----------
    cases : tuple of int
        Franka data cases (3 = joint 2, 4 = joint 7).
    speeds : tuple of str
        Speeds among ``"slow"``, ``"middle"``, ``"high"``.
    every : int
        Fit on every ``every``-th sample (scored on the whole record).
    max_evals : int, optional
        Evaluation budget per fit (simulations); default the algorithm's.

    Returns
    -------
    dict
        ``{(case, speed): (ours, paper)}``, RMS [N m].
    """
    out = {}
    print(f"{'case':<6}{'speed':<8}{'ours [N m]':>12}{'paper LuGre':>14}")
    for case in cases:
        for speed in speeds:
            d = load_franka(case, speed)
            start = make_model("lugre", sigma0=100.0, sigma1=1.0, sigma2=0.5, sigma2_neg=0.5,
                               Fc=0.3, Fc_neg=0.3, Fs=0.4, Fs_neg=0.4, vs=0.01, b=0.0)
            r = identify(d.select(slice(0, None, every)), start, algorithm="least_squares",
                         names=NAMES, max_evals=max_evals)
            ours = rmse(d.F, r.model.simulate(d.t, d.v))
            out[(case, speed)] = (ours, franka_paper_rms(case, speed))
            print(f"{case:<6}{speed:<8}{ours:>12.4f}{out[(case, speed)][1]:>14.4f}",
                  flush=True)
    return out


if __name__ == "__main__":
    run_identify_franka()
