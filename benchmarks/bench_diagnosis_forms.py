"""Generalisation benchmark of the diagnosis: every truth form of every effect, on every plant,
with the motion channels a user records.

Each effect has at least three truth forms from different physics (its record's ``truths``,
:mod:`diagnosis.benchmark.truths` and :mod:`diagnosis.benchmark.forms`; backlash and GMS in
their own modules), integrated on a grid ten times finer than sampled; positions are
quantised to an encoder count and differentiated as a user would (gradient, backward
differences or a low-passed gradient; 50-1000 counts per sample at the top speed, taken in
turn, :data:`diagnosis.benchmark.runner.MEASURED`). The **sealed** family
(:mod:`diagnosis.benchmark.sealed`, one more form per effect) is written once and run only
with ``--sealed``, at the end of a piece of work, and reported separately. The first sealed
family, whose results are below, was seen at the end of session 7 and moved into the open
grid (:mod:`diagnosis.benchmark.seen`); the present one (2026-11-24, session 8: one form for
each of the ten effects with truths, backlash and gms included) has not been run.

    python benchmarks/bench_diagnosis_forms.py [--sealed] [--workers N] [--quick]
                                               [--full-protocols] [--checkpoint FILE]
                                               [--json OUT]

Figures: top-1 over all cases and over the detectable ones (an oracle that knows the truth
can tell it from the base fit), clean and out-of-library cases, the mean |shrink error|
(reported gap closed against the truth's), per plant, per effect and per truth form; seconds
per case against one base identification of the plant timed in the same worker.

Results (2026-11-24, short protocols, 2 workers, 752 s wall, code of commit 3ced1d1): 580
cases, top-1 **53.1 %** (54.7 % of the 562 detectable ones), mean |shrink error| 0.254; clean
cases named 0 of 20 (13 ``none``, 7 ``unexplained``), ripple named 0 of 20. Wrong names on 28
of 560 effect cases (5 %): load -> asymmetry 6, inertia -> acceleration 6, gms ->
acceleration 5, drift -> load 4, acceleration -> inertia 3 / asymmetry 2, stribeck_shape ->
asymmetry 1 / inertia 1; every other miss is ``unexplained`` or ``none``. By effect: load
51/60, drift 49/60, position 41/48, asymmetry 36/60, inertia 34/60, acceleration 22/60, delay
21/60, backlash 18/36, gms 3/48, stribeck_shape 0/48. The first forms (the default benchmark's
truths, which score 99 % on the exact motion) score 66 % here (116/176): the measured
channels and the fine-grid truth cost the rest. What the new forms show the candidates cannot reach:
frictional memory and rate-and-state slip memory (3/20 each), a Stribeck curve of another
shape under a base that frees its exponent (0/48), presliding other than the candidate's
four blocks (Dahl, elasto-plastic: 0/24), an impacting backlash contact (0/12), a level step
at a change of the motion (lubricant_step 10/20, the base absorbs it in its speed
dependence), a waviness of 7 % of the stroke on short strokes (9/16); and a delay under 1.5
samples is refused by its size (the moving average over 2 s samples: 5/20).

First sealed family (``--sealed``, one form per effect, written before the first run, run on
the final code; since moved into the open grid, :mod:`diagnosis.benchmark.seen`, so the
open-grid figures above predate it): 146 cases (6 skipped: a stiction peak the motion never
dwells in), top-1 **34.9 %** (36.4 % of the detectable), 9 wrong names (6 %: acceleration ->
position 3 / asymmetry 1, load -> asymmetry 2, drift -> position 2 / load 1), mean |shrink
error| 0.30. By form: squeeze_film (load) 15/20, cable_chain (inertia) 10/20,
direction_curve (asymmetry) 9/20, screw_runout (position) 7/16, encoder_latency (delay)
5/20, thermal (drift) 4/20, stiction_spike 1/10, film_dynamics (acceleration) 0/20. (A first
sealed run was made on a commit whose verdict also named 1-1.5-sample delays of large
imprint - encoder_latency 10/20 - before that rule was reverted; its delay cases were run
again on the final code.)
"""
import os

# one BLAS thread: a diagnosis's matrices are a few columns wide (see bench_diagnosis.py)
os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")

import argparse  # noqa: E402
import json  # noqa: E402
import time  # noqa: E402

import numpy as np  # noqa: E402

from diagnosis.benchmark import PLANT_NAMES, format_summary, run_benchmark  # noqa: E402


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--sealed", action="store_true",
                    help="the sealed family only (run once, at the end of a piece of work)")
    ap.add_argument("--workers", type=int, default=2)
    ap.add_argument("--quick", action="store_true",
                    help="one strength and noise level")
    ap.add_argument("--full-protocols", action="store_true",
                    help="the plants' full protocols (default: their short ones, 1,400-5,000 "
                         "samples a record, as the clean-record run)")
    ap.add_argument("--plants", default=",".join(PLANT_NAMES))
    ap.add_argument("--effects", default=None, help="comma-separated effects (default: all)")
    ap.add_argument("--checkpoint", default=None,
                    help="JSON-lines file of finished cases; run again with it to resume")
    ap.add_argument("--json", default=None)
    args = ap.parse_args(argv)
    strengths = (1.0,) if args.quick else (0.5, 1.0)
    noises = (0.02,) if args.quick else (0.01, 0.03)
    kw = {} if args.effects is None else {"effects": tuple(args.effects.split(","))}
    family = "sealed" if args.sealed else "all"
    t0 = time.perf_counter()
    res = run_benchmark(strengths=strengths, noises=noises, plants=args.plants.split(","),
                        quick=not args.full_protocols, workers=args.workers, forms=family,
                        measured=True,
                        progress=lambda n, info: print(info, flush=True),
                        checkpoint=args.checkpoint, **kw)
    wall = time.perf_counter() - t0
    print(format_summary(res, f"{family} truth forms, measured motion: strengths {strengths}, "
                              f"noise {noises} x std(F), {len(res['rows'])} cases, "
                              f"{len(res['skipped'])} skipped, {wall:.0f} s wall on "
                              f"{args.workers} worker(s)"))
    if args.json:
        with open(args.json, "w") as fh:
            json.dump({k: res[k] for k in ("overall", "per_plant", "per_effect", "per_form",
                                           "rows", "skipped")}, fh, indent=1,
                      default=lambda o: o.item() if isinstance(o, np.generic) else str(o))


if __name__ == "__main__":
    main()
