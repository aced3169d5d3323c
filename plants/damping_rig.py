"""Vertical valve damping test rig of seed 001 (piston with rubber ring in a suspended cylinder).

The piston is driven vertically (a DC linear motor: 0-200 Hz, strokes up to 200 mm; or a
piezo motor: 200-1000 Hz, travel up to 120 um); the steel cylinder it slides in hangs on four
force sensors and touches nothing else, so the sensors see the friction of the rubber ring
directly, shaped by the suspension: with ``x_c`` the cylinder displacement,

    m_c d2x_c/dt2 = F(v_p - v_c) - k_s x_c - c_s dx_c/dt          (suspended cylinder)
    F_meas       = k_s x_c + c_s dx_c/dt  (= F - m_c a_c)          (sum of the four sensors)

``F`` is the friction law of the ring on the cylinder, driven by the relative motion. The
sensors' stiffness and the cylinder mass form a resonance (default ~1.1 kHz): at the linear
motor's frequencies the sensors read the friction; towards the piezo's 1 kHz the inertia of
the cylinder enters the reading.

Drives (option ``drive``):

* ``"linear"``: position-controlled linear motor, modelled as an ideal kinematic source
  (``sine``, ``triangle`` or ``trapezoid`` waveform; frequency <= 200 Hz, amplitude <= 100 mm),
  force sampled at 1 kHz;
* ``"piezo"``: the same kinematic source for 200-1000 Hz and amplitudes <= 60 um (120 um
  travel), sampled at 50 kHz (``step=2e-5``; :data:`PIEZO_RATE`);
* ``"open_loop"``: the identification experiment of Eqs. (17)-(18): the piston is a free mass
  driven by the motor force ``u = U sin(w t)`` (U = 1.1 N, w = 5 rad/s), ``m a = u - F``.

Default friction: classic LuGre with seed 001 Table I (AGA, 4 Hz): Fc = 5.27 N, Fs = 34.43 N,
vs = 0.021 m/s, sigma2 = 48.55 N.s/m, sigma1 = 138.83 N.s/m, sigma0 = 4457.9 N/m.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from friction.base import FrictionModel, param

from .base import Experiment, Plant, PlantParams
from .components import Damper, Mass, PositionSource, Spring
from .sources import Sine, Triangle

__all__ = ["DampingRigParams", "DampingRig", "rig_friction", "Trapezoid", "TABLE_I",
           "LINEAR_RATE", "PIEZO_RATE", "rig_dataset"]

LINEAR_RATE = 1000.0    # Hz, force sampling with the linear motor
PIEZO_RATE = 50_000.0   # Hz, with the piezo motor
#: seed 001 Table I (AGA): frequency [Hz] -> (Fc, Fs, vs, sigma2, sigma1, sigma0) in SI
TABLE_I = {4.0: (5.27, 34.43, 0.021, 48.55, 138.83, 4457.9),
           10.0: (5.79, 39.17, 0.017, 48.66, 136.83, 4286.02),
           300.0: (5.88, 37.6, 0.0053, 48.92, 112.92, 2006.5),
           600.0: (7.4, 43.2, 0.003, 7.43, 162.3, 344.96)}


def rig_friction(freq: float = 4.0, **overrides) -> FrictionModel:
    """Classic LuGre with the Table I parameters identified at ``freq`` (4, 10, 300, 600 Hz)."""
    from friction import make_model
    if freq not in TABLE_I:
        raise ValueError(f"freq = {freq!r}: Table I has {sorted(TABLE_I)} Hz")
    Fc, Fs, vs, s2, s1, s0 = TABLE_I[freq]
    kw = dict(sigma0=s0, sigma1=s1, sigma2=s2, Fc=Fc, Fs=Fs, vs=vs)
    kw.update(overrides)
    return make_model("lugre", **kw)


class Trapezoid:
    """Position trapezoid of ``amplitude`` [m], ``frequency`` [Hz]: ramps at constant speed
    joined by dwells of ``dwell`` (fraction of the period) at each end of the stroke."""

    def __init__(self, amplitude: float, frequency: float, dwell: float = 0.2):
        if not frequency > 0:
            raise ValueError(f"frequency = {frequency!r} is out of bounds: must be > 0 [Hz]")
        if not 0 <= dwell < 0.5:
            raise ValueError(f"dwell = {dwell!r} is out of bounds: must be in [0, 0.5)")
        self.amplitude, self.frequency, self.dwell = float(amplitude), float(frequency), dwell

    def __call__(self, t):
        t = np.asarray(t, dtype=float)
        A, f, d = self.amplitude, self.frequency, self.dwell
        k = 1.0 / (1.0 - 2.0 * d)              # triangle gain so the ramps reach +-A early
        ph = np.mod(t * f + 0.25, 1.0)
        tri = 1.0 - 4.0 * np.abs(ph - 0.5)
        s = A * np.clip(k * tri, -1.0, 1.0)
        v = np.where(np.abs(k * tri) < 1.0, np.where(ph < 0.5, 4 * A * f * k, -4 * A * f * k),
                     0.0)
        if np.ndim(t) == 0:
            return float(s), float(v), 0.0
        return s, v, np.zeros_like(s)


@dataclass(frozen=True)
class DampingRigParams(PlantParams):
    """Rig parameters (seed 001 gives the structure, not these numbers)."""
    m_c: float = param(2.0, "kg", "suspended steel cylinder", lower=0, lower_open=True)
    k_s: float = param(1.0e8, "N/m", "stiffness of the four force sensors together", lower=0,
                       lower_open=True)
    c_s: float = param(560.0, "N.s/m", "damping of the suspension (about 2 %)", lower=0)
    m_p: float = param(1.0, "kg", "piston + rod (moving object of Eq. 17)", lower=0,
                       lower_open=True)
    U: float = param(1.1, "N", "open-loop force amplitude (Eq. 18)")
    w_u: float = param(5.0, "rad/s", "open-loop force frequency (Eq. 18)", lower=0,
                       lower_open=True)


_DRIVES = ("linear", "piezo", "open_loop")
_WAVES = ("sine", "triangle", "trapezoid")


class DampingRig(Plant):
    """Valve damping test rig of seed 001 (see the module docstring).

    Outputs: ``x`` sliding displacement piston - cylinder [m], ``v`` sliding velocity [m/s],
    ``a`` relative acceleration [m/s^2], ``x_p`` piston displacement [m], ``x_c`` cylinder
    displacement [m], ``F_meas`` sum of the four sensor forces [N], ``u`` motor force in the
    open-loop experiment (0 for the kinematic drives) [N], ``F`` friction.
    Options: ``drive`` ("linear", "piezo", "open_loop"), ``waveform`` ("sine", "triangle",
    "trapezoid"), ``freq`` [Hz], ``amplitude`` [m].

    Parameters
    ----------
    friction : FrictionModel or str, optional
        The ring's friction law (default :func:`rig_friction`).
    **kwargs
        Plant parameter values (SI units), ``external_friction`` or ``params``, as for
        :class:`plants.base.Plant`.
    """

    name = "damping_rig"
    Params = DampingRigParams
    main_output = "F_meas"
    data_rate = LINEAR_RATE
    default_experiment = Experiment(start=0.0, stop=0.5, step=1.0 / LINEAR_RATE)
    state_names = ("s_p", "v_p", "x_c", "v_c")
    state_scale = (1e-3, 1e-2, 1e-7, 1e-4)
    output_names = ("x", "v", "a", "x_p", "x_c", "F_meas", "u")
    max_substep = 2e-5
    options = {"drive": "linear", "waveform": "sine", "freq": 4.0, "amplitude": 0.02}
    signals = {"x": ("m", "sliding displacement piston-cylinder"),
               "x_p": ("m", "piston displacement"),
               "v": ("m/s", "sliding velocity piston-cylinder"),
               "a": ("m/s^2", "relative acceleration"), "x_c": ("m", "cylinder displacement"),
               "F_meas": ("N", "sum of the four force sensors"),
               "u": ("N", "motor force (open-loop experiment)"),
               "F": ("N", "ring friction on the cylinder"),
               "F_friction": ("N", "friction force input (external friction)")}

    def __init__(self, friction=None, **kwargs):
        super().__init__(friction, **kwargs)
        self._check_options()

    @classmethod
    def default_friction(cls) -> FrictionModel:
        return rig_friction(4.0)

    def with_options(self, **options):
        new = super().with_options(**options)
        new._check_options()
        return new

    def _check_options(self):
        o = self.opts
        if o["drive"] not in _DRIVES:
            raise ValueError(f"drive = {o['drive']!r}: must be one of {_DRIVES}")
        if o["waveform"] not in _WAVES:
            raise ValueError(f"waveform = {o['waveform']!r}: must be one of {_WAVES}")
        f, A = float(o["freq"]), float(o["amplitude"])
        if o["drive"] == "linear":
            if not 0 < f <= 200:
                raise ValueError(f"freq = {f!r} Hz is out of the linear motor's range (0, 200] Hz")
            if not 0 < A <= 0.1:
                raise ValueError(f"amplitude = {A!r} m is out of the linear motor's range "
                                 "(0, 0.1] m (200 mm stroke)")
        elif o["drive"] == "piezo":
            if not 200 <= f <= 1000:
                raise ValueError(f"freq = {f!r} Hz is out of the piezo's range [200, 1000] Hz")
            if not 0 < A <= 60e-6:
                raise ValueError(f"amplitude = {A!r} m is out of the piezo's range (0, 6e-05] m "
                                 "(120 um travel)")
        if o["waveform"] == "sine":
            # start at the bottom of the stroke at rest (s = -A cos w t): no velocity jump
            traj = Sine(A, f, phase=-0.5 * math.pi)
        else:
            traj = {"triangle": Triangle, "trapezoid": Trapezoid}[o["waveform"]](A, f)
        self._drive = PositionSource(traj)

    # -- components ------------------------------------------------------------------------------
    def build_parts(self) -> tuple[Mass, Spring, Damper, Mass]:
        """(cylinder, sensors' stiffness, sensors' damping, piston): the cylinder hangs on
        the force sensors (flange a: the frame, flange b: the cylinder)."""
        p = self.params
        return Mass(m=p.m_c), Spring(c=p.k_s), Damper(d=p.c_s), Mass(m=p.m_p)

    # -- plant contract -------------------------------------------------------------------------
    def _open(self) -> bool:
        return self.opts["drive"] == "open_loop"

    def _piston(self, t, s):
        if self._open():
            return float(s[0]), float(s[1])
        sp, vp, _ = self._drive.kinematics(t)
        return sp, vp

    def motor_force(self, t) -> float:
        """Open-loop motor force u = U sin(w t) [N] (Eq. 18).

        Parameters
        ----------
        t : float
            Time [s].
        """
        p = self.params
        return p.U * math.sin(p.w_u * t)

    def initial_state(self):
        return np.zeros(4)

    def derivatives(self, t, s, d, F, u):
        _, vp, xc, vc = s
        cylinder, stiffness, damping, piston = self.parts
        ac = cylinder.acceleration(F + stiffness.reaction_on_b(xc, vc)
                                   + damping.reaction_on_b(xc, vc))
        if self._open():
            ap = piston.acceleration(self.motor_force(t) - F)      # Eq. (17): m a = u - F
            return np.array([vp, ap, vc, ac])
        return np.array([0.0, 0.0, vc, ac])

    def contact(self, t, s, d, u):
        sp, vp = self._piston(t, s)
        return sp - float(s[2]), vp - float(s[3]), None

    def contact_acceleration(self, t, s, ds, d, u):
        ap = float(ds[1]) if self._open() else self._drive.kinematics(t)[2]
        return ap - float(ds[3])

    def output(self, t, s, d, F, u):
        _, stiffness, damping, _ = self.parts
        ds = self.derivatives(t, s, d, F, u)
        sp, vp = self._piston(t, s)
        xc, vc = float(s[2]), float(s[3])
        return {"x": sp - xc, "v": vp - vc,
                "a": self.contact_acceleration(t, s, ds, d, u), "x_p": sp, "x_c": xc,
                "F_meas": stiffness.force(xc, vc) + damping.force(xc, vc),
                "u": self.motor_force(t) if self._open() else 0.0}


def rig_dataset(res, name: str = "damping_rig"):
    """A rig run as a :class:`friction.dataset.Dataset`: F = the four sensors' force."""
    from friction.dataset import Dataset
    return Dataset.from_arrays(res["time"], res["F_meas"], x=res["x"], v=res["v"], a=res["a"],
                               name=name, extra={"F_true": np.asarray(res["F"])})
