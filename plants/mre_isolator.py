"""Shake-table test of the MRE base isolator of seed 002 (YU, LI, LI 2015).

Test set-up (Section 5.1): the shake table, fixed to the bottom of the isolator, imposes a
sinusoidal shear (4 Hz, amplitudes 2/4/8 mm); a DC supply sets the coil current (0, 1, 2,
3 A); the load cell on the top plate measures the shear force; signals are sampled at 256 Hz.

Model::

    m_t d2x_t/dt2 = f_act - F                                        (table, position servo)
    f_act = m_t a_ref + K_t (x_ref - x_t) + D_t (v_ref - v_t)
    m_top d2x_top/dt2 = F - k_lc x_top - c_lc dx_top/dt               (top plate on load cell)
    F = isolator force at shear x = x_t - x_top, v = v_t - v_top      (mre_lugre, Eqs. 1a,b)
    F_meas = k_lc x_top + c_lc dx_top/dt                              (load cell reading)

Default isolator law: ``mre_lugre`` in its simplified form (Eqs. 13a,b) with the
current-dependent alpha, k0, eps of Eqs. (14a*-c*) (the re-fit of Table 6); the plant
parameter ``current`` selects them.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from friction.base import FrictionModel, param

from .base import Experiment, Plant, PlantParams
from .components import Damper, Mass, Spring

__all__ = ["MREIsolatorParams", "MREIsolator", "isolator_law", "loop_metrics", "isolator_dataset",
           "SAMPLE_RATE", "AMPLITUDES", "CURRENTS", "demo_figures"]

SAMPLE_RATE = 256.0               # Hz
AMPLITUDES = (2e-3, 4e-3, 8e-3)   # m
CURRENTS = (0.0, 1.0, 2.0, 3.0)   # A


def isolator_law(current: float = 2.0) -> FrictionModel:
    """Seed-002 isolator law at coil current ``current`` [A] (simplified model, Eqs. 13-14)."""
    from friction import MODELS, make_model
    if not 0.0 <= current <= 3.0:
        raise ValueError(f"current = {current!r} A is out of the tested range [0, 3] A")
    if "mre_lugre" not in MODELS:
        raise NotImplementedError("the mre_lugre law (friction/mre_lugre.py) is missing")
    from friction.mre_lugre import MRELuGre, parameters_at_current
    return MRELuGre.simplified(**parameters_at_current(current))


@dataclass(frozen=True)
class MREIsolatorParams(PlantParams):
    """Shake-table and load-cell parameters (seed 002 prints none of them)."""
    current: float = param(2.0, "A", "coil current (selects the default law)", lower=0,
                           upper=3.0)
    m_t: float = param(60.0, "kg", "shake-table platen + bottom plate", lower=0,
                       lower_open=True)
    K_t: float = param(6.0e6, "N/m", "table servo position gain", lower=0)
    D_t: float = param(2.4e4, "N.s/m", "table servo velocity gain", lower=0)
    m_top: float = param(5.0, "kg", "top plate between isolator and load cell", lower=0,
                         lower_open=True)
    k_lc: float = param(1.0e7, "N/m", "load-cell + reaction-frame stiffness", lower=0,
                        lower_open=True)
    c_lc: float = param(300.0, "N.s/m", "load-cell damping", lower=0)


class MREIsolator(Plant):
    """MRE isolator on a shake table (see the module docstring).

    Outputs: ``x`` shear displacement [m], ``v`` shear velocity [m/s], ``a`` [m/s^2],
    ``x_table`` [m], ``x_ref`` [m], ``F_meas`` load-cell force [N], ``F`` isolator force [N].
    Options: ``freq`` [Hz], ``amplitude`` [m], ``ramp_cycles`` (fade-in length, cycles).
    """

    name = "mre_isolator"
    Params = MREIsolatorParams
    main_output = "F_meas"
    data_rate = SAMPLE_RATE
    default_experiment = Experiment(start=0.0, stop=1.25, step=1.0 / SAMPLE_RATE)
    state_names = ("x_t", "v_t", "x_top", "v_top")
    state_scale = (1e-3, 1e-2, 1e-6, 1e-4)
    output_names = ("x", "v", "a", "x_table", "x_ref", "F_meas")
    max_substep = 1e-4
    options = {"freq": 4.0, "amplitude": 8e-3, "ramp_cycles": 1.0}
    signals = {"x": ("m", "shear displacement"), "v": ("m/s", "shear velocity"),
               "a": ("m/s2", "shear acceleration"), "x_table": ("m", "table position"),
               "x_ref": ("m", "table reference"), "F_meas": ("N", "load-cell force"),
               "F": ("N", "isolator shear force"),
               "F_friction": ("N", "isolator force input (external law)")}

    def __init__(self, friction=None, *, external_friction=False, params=None, **overrides):
        super().__init__(friction, external_friction=external_friction, params=params,
                         **overrides)
        if friction is None and not external_friction and self.params.current != 2.0:
            self.friction = isolator_law(self.params.current)

    @classmethod
    def default_friction(cls) -> FrictionModel:
        return isolator_law(2.0)

    def reference(self, t):
        """Table reference (x, v, a): A sin(2 pi f t) [m, m/s, m/s^2]."""
        A, f = float(self.opts["amplitude"]), float(self.opts["freq"])
        if not 0 < A <= 0.05:
            raise ValueError(f"amplitude = {A!r} m is out of bounds: must be in (0, 0.05] m")
        if not 0 < f <= 50:
            raise ValueError(f"freq = {f!r} Hz is out of bounds: must be in (0, 50] Hz")
        w = 2.0 * math.pi * f
        x, v, a = A * math.sin(w * t), A * w * math.cos(w * t), -A * w * w * math.sin(w * t)
        Tr = float(self.opts["ramp_cycles"]) / f
        if t < Tr:  # raised-cosine fade-in: no force step on the load cell at t = 0
            wr = math.pi / Tr
            r, dr, ddr = (0.5 * (1 - math.cos(wr * t)), 0.5 * wr * math.sin(wr * t),
                          0.5 * wr * wr * math.cos(wr * t))
            x, v, a = r * x, r * v + dr * x, r * a + 2 * dr * v + ddr * x
        return x, v, a

    def build_parts(self) -> tuple[Mass, Mass, Spring, Damper]:
        """(table, top plate, load cell's stiffness, load cell's damping): the top plate sits
        on the load cell (flange a: the reaction frame, flange b: the plate)."""
        p = self.params
        return Mass(m=p.m_t), Mass(m=p.m_top), Spring(c=p.k_lc), Damper(d=p.c_lc)

    def initial_state(self):
        x0, v0, _ = self.reference(0.0)
        return np.array([x0, v0, 0.0, 0.0])

    def derivatives(self, t, s, d, F, u):
        p = self.params
        xt, vt, xtop, vtop = s
        table, top, stiffness, damping = self.parts
        xr, vr, ar = self.reference(t)
        f_act = p.m_t * ar + p.K_t * (xr - xt) + p.D_t * (vr - vt)   # the table's servo
        return np.array([vt, table.acceleration(f_act - F), vtop,
                         top.acceleration(F + stiffness.reaction_on_b(xtop, vtop)
                                          + damping.reaction_on_b(xtop, vtop))])

    def contact(self, t, s, d, u):
        return float(s[0] - s[2]), float(s[1] - s[3]), None

    def contact_acceleration(self, t, s, ds, d, u):
        return float(ds[1] - ds[3])

    def output(self, t, s, d, F, u):
        _, _, stiffness, damping = self.parts
        ds = self.derivatives(t, s, d, F, u)
        xtop, vtop = float(s[2]), float(s[3])
        return {"x": float(s[0] - s[2]), "v": float(s[1] - s[3]), "a": float(ds[1] - ds[3]),
                "x_table": float(s[0]), "x_ref": self.reference(t)[0],
                "F_meas": stiffness.force(xtop, vtop) + damping.force(xtop, vtop)}


def loop_metrics(res, freq: float = 4.0, cycles: int = 1):
    """Effective stiffness and loop area of the last ``cycles`` force-displacement cycles.

    Returns
    -------
    dict
        ``k_eff`` = (F(x_max) - F(x_min)) / (x_max - x_min) [N/m] (slope of the loop),
        ``area`` = closed-loop integral of F dx [J] (energy dissipated per cycle), ``F_max``.
    """
    t = np.asarray(res["time"])
    n = int(round(cycles / freq / (t[1] - t[0])))
    x = np.asarray(res["x"])[-n - 1:]
    F = np.asarray(res["F_meas"])[-n - 1:]
    i, j = int(np.argmax(x)), int(np.argmin(x))
    k_eff = (F[i] - F[j]) / (x[i] - x[j])
    area = abs(float(np.sum(0.5 * (F[1:] + F[:-1]) * np.diff(x)))) / cycles
    return {"k_eff": float(k_eff), "area": area, "F_max": float(np.max(np.abs(F)))}


def isolator_dataset(res, name: str = "mre_isolator"):
    """A shake-table run as a :class:`friction.dataset.Dataset`: F = load-cell force."""
    from friction.dataset import Dataset
    return Dataset.from_arrays(res["time"], res["F_meas"], x=res["x"], v=res["v"], a=res["a"],
                               name=name, extra={"F_true": np.asarray(res["F"])})


def demo_figures(out, summary: dict, quick: bool = True):
    """Isolator figures: loops vs amplitude at 2 A (Fig. 9) and vs current at 4 mm (Fig. 10)."""
    import pathlib

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    out = pathlib.Path(out)
    out.mkdir(parents=True, exist_ok=True)
    fig, ax = plt.subplots(1, 2, figsize=(10, 4))
    rows = {}
    for A in AMPLITUDES:
        r = MREIsolator().simulate(1.0, amplitude=A)
        k = r["time"] >= 0.75
        ax[0].plot(r["x"][k] * 1e3, r["F_meas"][k], label=f"{A * 1e3:g} mm")
        rows[f"2A_{A * 1e3:g}mm"] = {k2: round(v2, 4) for k2, v2 in loop_metrics(r).items()}
    for I in CURRENTS:
        r = MREIsolator(current=I).simulate(1.0, amplitude=4e-3)
        k = r["time"] >= 0.75
        ax[1].plot(r["x"][k] * 1e3, r["F_meas"][k], label=f"{I:g} A")
        rows[f"{I:g}A_4mm"] = {k2: round(v2, 4) for k2, v2 in loop_metrics(r).items()}
    ax[0].set(xlabel="x [mm]", ylabel="F [N]", title="4 Hz, 2 A (seed 002 Fig. 9)")
    ax[1].set(xlabel="x [mm]", ylabel="F [N]", title="4 Hz, 4 mm (seed 002 Fig. 10)")
    for a in ax:
        a.legend(fontsize=7)
    fig.tight_layout()
    p1 = out / "mre_isolator_loops.png"
    fig.savefig(p1, dpi=110)
    plt.close(fig)
    summary.setdefault("figures", []).append(str(p1))
    summary["mre_isolator"] = rows
    return [p1]
