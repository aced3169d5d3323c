"""Diagnose the sim-to-real gap of a LuGre law on the real EMPS data (Janot, Gautier, Brunot;
nonlinearbenchmark.org): fit on DATA_EMPS, hold out DATA_EMPS_PULSES, and name the effect
that closes the held-out gap (the documentation reports a direction asymmetry of the worn
ball screw). Writes the contract JSON and a self-contained HTML report.

    python examples/diagnose_emps.py [--out DIR]
"""
import argparse
import os

from diagnosis import diagnose
from identification.real_data import load_emps


def run_diagnose_emps(out="diagnose-emps", show_plot=False):
    """Run the EMPS diagnosis; returns the report (``report["verdict"]["cause"]``)."""
    os.makedirs(out, exist_ok=True)
    rep = diagnose(load_emps("estimation"), "lugre", validation=load_emps("validation"))
    rep.to_json(os.path.join(out, "diagnosis_emps.json"))
    from diagnosis.report_html import write_html
    write_html(rep, os.path.join(out, "diagnosis_emps.html"))
    if show_plot:
        import webbrowser
        webbrowser.open(os.path.abspath(os.path.join(out, "diagnosis_emps.html")))
    return rep


if __name__ == "__main__":
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--out", default="diagnose-emps")
    args = ap.parse_args()
    print(run_diagnose_emps(args.out).summary())
