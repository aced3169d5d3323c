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

__all__ = ["MREIsolatorParams", "MREIsolator", "isolator_law", "isolator_dataset",
           "SAMPLE_RATE", "AMPLITUDES", "CURRENTS"]

SAMPLE_RATE = 256.0               # Hz
AMPLITUDES = (2e-3, 4e-3, 8e-3)   # m
CURRENTS = (0.0, 1.0, 2.0, 3.0)   # A


def isolator_law(current: float = 2.0) -> FrictionModel:
    """Seed-002 isolator law at coil current ``current`` [A] (simplified model, Eqs. 13-14)."""
    if not 0.0 <= current <= 3.0:
        raise ValueError(f"current = {current!r} A is out of the tested range [0, 3] A")
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

    Parameters
    ----------
    friction : FrictionModel or str, optional
        The isolator's law (default :func:`isolator_law` at the parameter ``current``).
    external_friction : bool
        The law runs outside (its force is the input ``F_friction``).
    params : MREIsolatorParams, optional
        Plant parameters; default their defaults.
    **overrides
        Plant parameter values (SI units) replacing those of ``params``.
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
               "a": ("m/s^2", "shear acceleration"), "x_table": ("m", "table position"),
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
        """Table reference (x, v, a): A sin(2 pi f t) [m, m/s, m/s^2].

        Parameters
        ----------
        t : float or array_like
            Time [s].
        """
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


def isolator_dataset(res, name: str = "mre_isolator"):
    """A shake-table run as a :class:`friction.dataset.Dataset`: F = load-cell force."""
    from friction.dataset import Dataset
    return Dataset.from_arrays(res["time"], res["F_meas"], x=res["x"], v=res["v"], a=res["a"],
                               name=name, extra={"F_true": np.asarray(res["F"])})
