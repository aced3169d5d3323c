"""Trajectory-level diagnosis of the XML-350 stage: no friction force is measured, only the
encoder position. The 'real' stage (simulated here) has direction-dependent friction the
classic LuGre model lacks; each candidate effect is put into the plant's friction, the closed
loop is re-simulated against the measured positions of a fit sine (50 um, 5 Hz) and scored
on a held-out sine (100 um, 3 Hz). Writes the contract JSON and a self-contained HTML report.

    python examples/diagnose_xml350_trajectory.py [--out DIR] [--all]

``--all`` tries every candidate (about half a minute; the generic plant stepper runs the
candidates that live inside the friction law), the default a quick subset.
"""
import argparse
import math
import os

from diagnosis import diagnose_trajectory, record_from_result
from diagnosis.trajectory import write_trajectory_html
from friction import make_model
from plants.sources import Sine
from plants.xml350 import XML350, xml350_friction


def _sine(A, f):
    return Sine(A, f, offset=A, phase=-0.5 * math.pi)  # starts at rest


def run_diagnose_xml350_trajectory(out="diagnose-xml350-trajectory", every_candidate=False,
                                   show_plot=False):
    """Run the diagnosis; returns the report (``report["verdict"]["cause"]``)."""
    os.makedirs(out, exist_ok=True)
    loop = dict(compensation=False, controller="pid")   # the identification loop of seed 003
    fit_opts = dict(trajectory=_sine(50e-6, 5.0), **loop)
    val_opts = dict(trajectory=_sine(100e-6, 3.0), **loop)
    p = xml350_friction().params
    truth_law = make_model("modified_lugre", sigma0=p.sigma0, sigma1=p.sigma1, sigma2=p.sigma2,
                           Fc=p.Fc, Fs=p.Fs, vs=p.vs, b=p.b, shape=p.shape, f_a=0.0,
                           Fc_neg=0.80, Fs_neg=0.95, vs_neg=2e-5, sigma2_neg=12.0)
    real = XML350(truth_law, f_current=2000.0)
    fit = record_from_result(real.simulate(0.2, **fit_opts), fit_opts, signal="x_meas",
                             noise=3e-10, seed=1, name="sine 50um 5Hz")
    val = record_from_result(real.simulate(0.34, **val_opts), val_opts, signal="x_meas",
                             noise=3e-10, seed=2, name="sine 100um 3Hz")
    model = XML350(xml350_friction(Fc=1.0), f_current=2000.0)  # what the user has
    cands = None if every_candidate else ["asymmetry", "inertia", "delay", "stribeck_shape"]
    rep = diagnose_trajectory(fit, model, "lugre", validation=val, candidates=cands,
                              progress=True)
    rep.to_json(os.path.join(out, "diagnosis_xml350_trajectory.json"))
    write_trajectory_html(rep, os.path.join(out, "diagnosis_xml350_trajectory.html"))
    if show_plot:
        import webbrowser
        webbrowser.open(os.path.abspath(os.path.join(out, "diagnosis_xml350_trajectory.html")))
    return rep


if __name__ == "__main__":
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--out", default="diagnose-xml350-trajectory")
    ap.add_argument("--all", action="store_true", help="every candidate")
    a = ap.parse_args()
    print(run_diagnose_xml350_trajectory(a.out, a.all).summary())
