"""Seed 003's LuGre identification protocol on the simulated XML-350 stage, end to end.

Static step (trapezoid plateaus -> Stribeck fit), dynamic step (PRBS pre-sliding frequency
response -> second-order transfer function with ``control``: sigma0 = M wn^2,
sigma1 = 2 M zeta wn), refinement (coloured noise, k = 5 alternations of nonlinear/linear
least squares in Theta(0.5)). Prints the parameters of each step and the accuracy
100 (1 - NRMSE) on the identification and validation sets (paper, real stage: 82.8 % / 74.4 %).

    python examples/identify_xml350.py [--quick] [--json OUT]
"""
import argparse
import json

from friction.progress import Progress
from identification.xml350_protocol import run_xml350_protocol


def run_identify_xml350(quick: bool = False, noise_x: float = 0.0, json_out=None) -> dict:
    """Run the protocol; print the parameters of each step and the accuracies.

    Parameters
    ----------
    quick : bool
        Shorter records.
    noise_x : float
        Encoder noise RMS [m].
    json_out : str, optional
        Write the protocol's result as JSON here.

    Returns
    -------
    dict
        The result of :func:`identification.xml350_protocol.run_xml350_protocol`.
    """
    out = run_xml350_protocol(quick=quick, noise_x=noise_x,
                              progress=Progress(label="xml350 protocol", interval=0))
    print(f"{'parameter':<8} {'true':>12} {'init':>12} {'final':>12}")
    for n in out["final"]:
        print(f"{n:<8} {out['true'][n]:>12.5g} {out['init'][n]:>12.5g} {out['final'][n]:>12.5g}")
    print(f"accuracy identification {out['accuracy']['identification']:.1%} "
          f"(paper 82.8 %), validation {out['accuracy']['validation']:.1%} (paper 74.4 %)")
    print(f"samples {out['samples']}, time {out['timings']['total']:.0f} s")
    if json_out:
        with open(json_out, "w") as fh:
            json.dump(out, fh, indent=2, default=float)
    return out


if __name__ == "__main__":
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--quick", action="store_true", help="shorter records")
    ap.add_argument("--noise-x", type=float, default=0.0, help="encoder noise RMS [m]")
    ap.add_argument("--json", default=None)
    args = ap.parse_args()
    run_identify_xml350(args.quick, args.noise_x, args.json)
