"""Seed 004 studies on the forging press: crawling at ultra-low speed, the no-load
Stribeck curve of Section 4, and their figure (the press part of the ``plants`` demo
stage).

* :func:`crawl_metrics` - stick-slip indicators over a constant-speed window;
* :func:`steady_friction` - no-load constant-speed tests, friction by Eq. 1;
* :func:`demo_figures` - Stribeck curve with vc, crawl at 0.002 mm/s vs 1.2 mm/s.

Crawling (:func:`crawl_metrics`): steady sliding can only lose stability where the
steady-state friction falls with speed, i.e. below the critical velocity vc = 0.19 mm/s of
Eq. 13 (the oil columns are the spring, the Stribeck drop the negative damping). What the
simulations show with the seed's parameters:

* no-load constant-speed runs crawl from 0.01 to 0.15 mm/s and run smoothly from 0.3 mm/s up
  (``examples/forging_press_crawl.py``);
* at 0.002 mm/s, started from rest without load, the beam creeps smoothly: far below vs the
  Gaussian Stribeck slope vanishes like v and the bristle memory g/sigma0 damps the drop, so
  steady creep is locally stable;
* in the Table 1 schedule the beam comes down from the loaded faster steps; while it sticks the
  workpiece relaxes, and the press lands on the stick-slip cycle that coexists with the creep:
  it crawls at 0.05 and 0.002 mm/s and moves smoothly at 1.2 mm/s (the default experiment).
  Over the full 1370 s of Table 1 (``examples/forging_press_crawl.py --full``; slips counted
  over the last 60 % of each step): smooth at 1.2 mm/s, crawling at 0.1 mm/s (19 slips) and
  0.002 mm/s (18 slips), strongly fluctuating at 0.05 mm/s (37 slips, peaks of 2.8 v_ref);
  the total reduction is 90 mm as printed. (The slip counts at 0.1 and 0.05 mm/s were 37 and
  122 with the earlier stepper that chattered about vc instead of sliding along it; the
  regime-exact stepper converges to the reference, see ``plants.stepper.PlantStepper``.)
"""
from __future__ import annotations

import numpy as np

from ..forging_press import ForgingPress

from ._figures import folder, pyplot, save

__all__ = ["crawl_metrics", "steady_friction", "demo_figures"]


def crawl_metrics(res, *, t_from: float | None = None, t_to: float | None = None):
    """Crawling (stick-slip) indicators over a constant-speed window of a press run.

    Parameters
    ----------
    res : structured array
        Press result with ``time``, ``v``, ``v_ref``.
    t_from, t_to : float, optional
        Window [s] (default: the last 70 % of the record).

    Returns
    -------
    dict
        ``v_ref`` [m/s]; ``intermittency``: share of samples moving slower than v_ref / 2
        (stuck or moving back); ``peak_ratio``: max |v - v_ref| / v_ref; ``cv``: std(v) / v_ref;
        ``slips``: number of slip events (upward crossings of 3 v_ref); ``crawling``:
        intermittency > 0.3 and peak_ratio > 3 (stick-slip inside the window); ``stalled``:
        the beam stays below v_ref / 2 for more than 90 % of the window (a stick phase
        longer than the window).
    """
    t = np.asarray(res["time"])
    t_from = t[0] + 0.3 * (t[-1] - t[0]) if t_from is None else t_from
    t_to = t[-1] if t_to is None else t_to
    m = (t >= t_from) & (t <= t_to)
    if m.sum() < 10:
        raise ValueError(f"window [{t_from:g}, {t_to:g}] s holds fewer than 10 samples")
    v = np.asarray(res["v"])[m]
    vr = float(np.median(np.asarray(res["v_ref"])[m]))
    if vr <= 0:
        raise ValueError("crawl_metrics needs a positive constant speed reference in the window")
    inter = float(np.mean(v < 0.5 * vr))
    pk = float(np.max(np.abs(v - vr)) / vr)
    above = v > 3.0 * vr
    slips = int(np.sum(above[1:] & ~above[:-1]))
    return {"v_ref": vr, "intermittency": inter, "peak_ratio": pk,
            "cv": float(np.std(v) / vr), "slips": slips,
            "crawling": bool(inter > 0.3 and pk > 3.0), "stalled": bool(inter > 0.9)}


def steady_friction(plant: ForgingPress, speeds, *, duration: float = 6.0, progress=None):
    """No-load constant-speed tests (Section 4): mean F_r by Eq. 1 over the last half [N]."""
    out = []
    for vref in speeds:
        res = plant.simulate(duration, schedule=((float(vref), duration + 1.0),),
                             workpiece=False, progress=progress)
        Fr = plant.friction_from_eq1(res)
        h = res.size // 2
        out.append((float(np.mean(res["v"][h:])), float(np.mean(Fr[h:]))))
    return np.array(out)


def _step_windows(schedule):
    t0, out = 0.0, []
    for _, dur in schedule:
        out.append((t0, t0 + dur))
        t0 += dur
    return out


def demo_figures(out, summary: dict, quick: bool = True):
    """Press figures: Stribeck curve with vc, crawl at 0.002 mm/s vs 1.2 mm/s, schedule run."""
    plt = pyplot()
    out = folder(out)
    plant = ForgingPress()
    law = plant.friction
    vgrid = np.logspace(-6, -2.3, 300)
    kw = {"load": np.zeros_like(vgrid)} if "load" in law.extra_inputs else {}
    Fss = law.steady_state(vgrid, **kw)
    vc = float(vgrid[np.argmin(Fss)])
    speeds = (0.3e-3, 0.6e-3, 1.2e-3) if quick else (0.25e-3, 0.4e-3, 0.7e-3, 1.2e-3, 2e-3)
    meas = steady_friction(plant, speeds, duration=4.0 if quick else 8.0)
    fig, ax = plt.subplots(1, 3, figsize=(14, 4))
    ax[0].semilogx(vgrid * 1e3, Fss / 1e3, label="load_lugre steady state (Eq. 8)")
    ax[0].semilogx(meas[:, 0] * 1e3, meas[:, 1] / 1e3, "o", label="plant, Eq. 1")
    ax[0].axvline(vc * 1e3, color="k", ls="--", lw=0.8, label=f"vc = {vc * 1e3:.3f} mm/s")
    ax[0].set(xlabel="v [mm/s]", ylabel="friction [kN]", title="no-load Stribeck curve")
    ax[0].legend(fontsize=7)
    res = plant.simulate()              # shortened Table 1 schedule with the workpiece
    windows = _step_windows(plant.opts["schedule"])
    crawl = {}
    for (t0, t1), (vref, _) in zip(windows, plant.opts["schedule"]):
        cm = crawl_metrics(res, t_from=t0 + 0.4 * (t1 - t0), t_to=t1)
        crawl[f"{vref * 1e3:g}mm/s"] = {k: (float(f"{v:.4g}") if isinstance(v, float) else v)
                                        for k, v in cm.items()}
    for axk, (t0, t1), (vref, _) in ((1, windows[0], plant.opts["schedule"][0]),
                                     (2, windows[-1], plant.opts["schedule"][-1])):
        m = (res["time"] >= t0) & (res["time"] <= t1)
        ax[axk].plot(res["time"][m], res["v"][m] * 1e3, lw=0.8, label="beam")
        ax[axk].plot(res["time"][m], res["v_ref"][m] * 1e3, "k--", lw=0.8, label="reference")
        cm = crawl[f"{vref * 1e3:g}mm/s"]
        state = "crawls" if cm["crawling"] else ("stalled" if cm["stalled"] else "smooth")
        ax[axk].set(xlabel="t [s]", ylabel="v [mm/s]",
                    title=f"schedule step at {vref * 1e3:g} mm/s: {state}")
        ax[axk].legend(fontsize=7)
    p1 = save(fig, out / "forging_press_crawl.png")
    summary.setdefault("figures", []).append(str(p1))
    summary["forging_press"] = {"vc_mm_s": round(vc * 1e3, 4), "crawl": crawl}
    return [p1]
