"""Voice-coil electromagnetic valve actuator (VEMA) of seed 000 (SHAO et al. 2018).

Plant (seed 000 Eq. 1, ``EQUATIONS.md`` A.1)::

    dS/dt = v
    m dv/dt = fmag(S, i) - k (S + const) - F_f                         const = 6 mm
    tau_i di/dt = i_cmd - i                                            (driver current loop)

``fmag(S, i)`` is a 2-D table over position and current (:mod:`plants.tables`; force nearly
proportional to current, mild position dependence, as Fig. 4). The valve is position
controlled at 20 kHz (the ACS SPiiPlus loop): a PID on the encoder position (quantised to
``q_S``) plus the model feedforward ``m a_ref + k (S_ref + const)``; the force command is
turned into a current command through the inverse of the force table.

Protocol (Section 2.2): sinusoids at 1/5/10/20 Hz and 2/4/6/8 mm. "Magnitude" is the
peak-to-peak lift: the valve opens from its seat, ``S_ref = M/2 (1 - cos 2 pi f t)``. This
reading is the one consistent with the paper's own numbers: v_max = pi f M = 0.126 m/s at
5 Hz / 8 mm ("0.12 m/s"), and at 10 Hz the speed is 0.247 m/s at t = 0.0225 s and 0.251 m/s
at 0.0245 s (Fig. 10(b) text).

Friction "measured" as the paper does (:func:`recover_friction`): the encoder position and
the current are zero-phase Butterworth filtered (``scipy.signal.filtfilt``, analysis time
only), differentiated twice, and Eq. (1) is solved for F_f.

The paper's studies (loops, steady-state tests, the explicit-Euler observer of Eqs. 27-30)
and their figures are in :mod:`plants.studies.valve`.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from friction.base import FrictionModel, param

from .base import Experiment, Plant, PlantParams
from .components import Mass, Spring
from .tables import Table2D, bilinear, bilinear_inverse_y, make_fmag_table

__all__ = ["ValveParams", "ValveActuator", "valve_friction", "classic_lugre_twin",
           "sine_reference", "recover_friction", "valve_dataset", "FREQUENCIES",
           "MAGNITUDES", "SAMPLE_RATE"]

#: seed 000 protocol
FREQUENCIES = (1.0, 5.0, 10.0, 20.0)      # Hz, at 8 mm
MAGNITUDES = (2e-3, 4e-3, 6e-3, 8e-3)     # m peak-to-peak, at 5 Hz
SAMPLE_RATE = 20_000.0                    # Hz (0.05 ms)


@dataclass(frozen=True)
class ValveParams(PlantParams):
    """VEMA parameters (seed 000; the paper prints none but ``const`` and the 20 kHz rate)."""
    m: float = param(0.12, "kg", "moving mass: valve + coil + 1/3 spring", lower=0,
                     lower_open=True)
    k: float = param(2500.0, "N/m", "spring stiffness (low: holds the valve closed)", lower=0)
    const: float = param(6e-3, "m", "spring pre-deformation (seed 000: 6 mm)")
    Kf: float = param(25.0, "N/A", "voice-coil force constant at mid-stroke", lower=0,
                      lower_open=True)
    position_drop: float = param(0.06, "1", "relative force loss 6 mm from mid-stroke",
                                 lower=0, upper=0.9)
    i_max: float = param(10.0, "A", "current limit of the driver", lower=0, lower_open=True)
    tau_i: float = param(1e-4, "s", "current-loop time constant of the driver", lower=0,
                         lower_open=True)
    Kp: float = param(1.9e5, "N/m", "position-loop proportional gain", lower=0)
    Ki: float = param(2.4e7, "N/(m.s)", "position-loop integral gain", lower=0)
    Kd: float = param(210.0, "N.s/m", "position-loop derivative gain", lower=0)
    tau_d: float = param(1e-4, "s", "derivative filter time constant", lower=0)
    q_S: float = param(1e-7, "m", "encoder resolution (0: no quantisation)", lower=0)


def valve_friction(**overrides) -> FrictionModel:
    """Seed-000 friction of the valve guide: modified LuGre.

    Fc / sigma0 = 1.235e-5 m (Euler critical velocity 0.247 m/s at 20 kHz, EQUATIONS.md A.7),
    mild asymmetry (the paper identifies two direction sets), switch band v1 = 0.1 m/s,
    v2 = 0.2 m/s below v_cr.
    """
    from friction import make_model
    base = dict(sigma0=4.86e5, sigma1=40.0, sigma2=20.0, Fc=6.0, Fs=6.5, vs=5e-3,
                alpha=2.0, Fc_neg=5.6, Fs_neg=6.0, sigma2_neg=18.0, f_a=2.0, a_s=20.0,
                v_c=0.5, beta=1.0, gamma=1.0, tau=5e-4, v1=0.1, v2=0.2)
    base.update(overrides)
    return make_model("modified_lugre", **base)


def classic_lugre_twin(law: FrictionModel) -> FrictionModel:
    """Classic LuGre with the same Stribeck and bristle parameters as ``law``."""
    from friction import make_model
    p = law.params
    keys = ("sigma0", "sigma1", "sigma2", "Fc", "Fs", "vs", "alpha", "b", "Fc_neg", "Fs_neg",
            "vs_neg", "sigma2_neg", "shape")
    return make_model("lugre", **{k: getattr(p, k) for k in keys if hasattr(p, k)})


def sine_reference(t, freq: float, magnitude: float):
    """Lift reference ``S = M/2 (1 - cos 2 pi f t)`` and its two derivatives [m, m/s, m/s^2]."""
    w = 2.0 * math.pi * freq
    r = 0.5 * magnitude
    return (r * (1.0 - np.cos(w * t)), r * w * np.sin(w * t), r * w * w * np.cos(w * t))


class ValveActuator(Plant):
    """Position-controlled voice-coil valve (seed 000). See the module docstring.

    Outputs: ``x`` lift S [m], ``v`` [m/s], ``a`` [m/s^2], ``i`` coil current [A],
    ``i_cmd`` [A], ``S_ref`` [m], ``S_meas`` quantised encoder position [m], ``F`` friction [N].
    Options: ``freq`` [Hz], ``magnitude`` [m] (peak-to-peak lift); ``speed`` [m/s] (nonzero:
    constant-speed stroke of the steady-state tests instead of the sinusoid), ``t_acc`` [s].
    """

    name = "valve"
    Params = ValveParams
    main_output = "x"
    data_rate = SAMPLE_RATE
    default_experiment = Experiment(start=0.0, stop=0.2, step=1.0 / SAMPLE_RATE)
    state_names = ("S", "v", "i")
    state_scale = (1e-3, 0.1, 1.0)
    output_names = ("x", "v", "a", "i", "i_cmd", "S_ref", "S_meas")
    discrete_names = ("i_cmd", "integ", "S_prev", "v_filt")
    control_rate = SAMPLE_RATE
    max_substep = 2.5e-5
    options = {"freq": 10.0, "magnitude": 8e-3, "speed": 0.0, "t_acc": 0.02}
    signals = {"x": ("m", "valve lift S"), "v": ("m/s", "valve velocity"),
               "a": ("m/s^2", "valve acceleration"), "i": ("A", "coil current"),
               "i_cmd": ("A", "current command"), "S_ref": ("m", "lift reference"),
               "S_meas": ("m", "encoder position (quantised)"),
               "F": ("N", "friction force on the valve, opposing v"),
               "F_friction": ("N", "friction force input (external friction)")}

    @classmethod
    def default_friction(cls) -> FrictionModel:
        return valve_friction()

    # -- components ----------------------------------------------------------------------------
    def build_parts(self) -> tuple[Mass, Spring]:
        """(moving mass, return spring): the valve is a mass on a spring preloaded by
        ``const`` (tension ``k (S + const)``)."""
        p = self.params
        return Mass(m=p.m), Spring(c=p.k, preload=p.const)

    @property
    def spring(self) -> Spring:
        """The return spring: tension ``k (S + const)`` with the 6 mm pre-deformation."""
        return self.parts[1]

    # -- force table -------------------------------------------------------------------------
    @property
    def fmag(self) -> Table2D:
        """Voice-coil force table fmag(S [m], i [A]) -> N for the current parameters."""
        p = self.params
        key = (p.Kf, p.position_drop, p.i_max)
        if getattr(self, "_fmag_key", None) != key:
            self._fmag = make_fmag_table(Kf=p.Kf, position_drop=p.position_drop,
                                         i_max=p.i_max)
            self._fmag_key = key
        return self._fmag

    def reference(self, t):
        """(S_ref, v_ref, a_ref) of the current options at time(s) ``t``.

        ``speed = 0``: the lift sinusoid; otherwise a constant-speed stroke (seed 000's
        steady-state tests under velocity control) from the start lift, reaching ``speed``
        [m/s] with a constant acceleration over ``t_acc`` [s].

        Parameters
        ----------
        t : float or array_like
            Time [s].
        """
        speed = float(self.opts["speed"])
        if speed == 0.0:
            return sine_reference(t, self.opts["freq"], self.opts["magnitude"])
        ta = float(self.opts["t_acc"])
        t = np.asarray(t, float)
        S0 = self._start_lift()
        tc = np.minimum(t, ta)
        S = S0 + speed * (0.5 * tc * tc / ta + np.maximum(t - ta, 0.0))
        return S, speed * tc / ta, np.where(t < ta, speed / ta, 0.0)

    def _start_lift(self) -> float:
        """Start lift [m]: 0 for the sinusoids; 1 mm (speed > 0) or 7 mm (speed < 0) ramps."""
        speed = float(self.opts["speed"])
        if speed == 0.0:
            return 0.0
        return 1e-3 if speed > 0 else 7e-3

    def _quantise(self, S):
        q = self.params.q_S
        return S if q == 0 else q * math.floor(S / q + 0.5)

    # -- plant contract -------------------------------------------------------------------------
    def _hold_current(self) -> float:
        p = self.params
        S0 = self._start_lift()
        xg, yg, Z = self.fmag.arrays()
        return float(bilinear_inverse_y(xg, yg, Z, S0, self.spring.force(S0)))

    def initial_state(self):
        return np.array([self._start_lift(), 0.0, self._hold_current()])

    def initial_discrete(self):
        S0 = self._quantise(self._start_lift())
        return np.array([self._hold_current(), 0.0, S0, 0.0])

    def derivatives(self, t, s, d, F, u):
        p = self.params
        S, v, i = s
        mass, spring = self.parts
        xg, yg, Z = self.fmag.arrays()
        fm = bilinear(xg, yg, Z, S, i)
        return np.array([v, mass.acceleration(fm + spring.reaction_on_b(S, v) - F),
                         (d[0] - i) / p.tau_i])

    def contact(self, t, s, d, u):
        return float(s[0]), float(s[1]), None

    def discrete_update(self, t, s, d, u):
        p = self.params
        Ts = 1.0 / self.control_rate
        _, integ, S_prev, v_filt = d
        S_m = self._quantise(float(s[0]))
        S_r, v_r, a_r = (float(x) for x in self.reference(t))
        e = S_r - S_m
        v_raw = (S_m - S_prev) / Ts
        v_filt = v_filt + Ts / (p.tau_d + Ts) * (v_raw - v_filt)
        integ = integ + p.Ki * e * Ts
        F_cmd = p.m * a_r + self.spring.force(S_r) + p.Kp * e + integ + p.Kd * (v_r - v_filt)
        xg, yg, Z = self.fmag.arrays()
        i_cmd = bilinear_inverse_y(xg, yg, Z, S_m, F_cmd)
        return np.array([i_cmd, integ, S_m, v_filt])

    def output(self, t, s, d, F, u):
        ds = self.derivatives(t, s, d, F, u)
        S_r = float(self.reference(t)[0])
        return {"x": float(s[0]), "v": float(s[1]), "a": float(ds[1]), "i": float(s[2]),
                "i_cmd": float(d[0]), "S_ref": S_r, "S_meas": self._quantise(float(s[0]))}


# -- analysis: the paper's friction recovery --------------------------------------------------
def recover_friction(res, plant: ValveActuator, *, cutoff: float = 1000.0, order: int = 4,
                     current_noise: float = 0.0, seed: int | None = 0):
    """Friction "measured" from encoder position and current by Eq. (1), as the paper does.

    Parameters
    ----------
    res : structured array
        A :meth:`ValveActuator.simulate` result (fields ``time``, ``S_meas``, ``i``).
    plant : ValveActuator
        The plant (mass, spring and force table used in Eq. (1)).
    cutoff : float
        Butterworth low-pass cut-off [Hz] (zero-phase, ``filtfilt``).
    order : int
        Filter order.
    current_noise : float
        Standard deviation of white current-sensor noise added before filtering [A].
    seed : int, optional
        Noise seed.

    Returns
    -------
    dict
        ``t``, ``x``, ``v``, ``a``, ``i``, ``F`` (recovered friction [N]) arrays.
    """
    from scipy.signal import butter, filtfilt  # analysis time only

    t = np.asarray(res["time"], float)
    if t.size < 3 * (order + 1) * 3:
        raise ValueError(f"record too short ({t.size} samples) for a filtfilt of order {order}")
    dt = float(np.mean(np.diff(t)))
    fs = 1.0 / dt
    if not 0 < cutoff < 0.5 * fs:
        raise ValueError(f"cutoff = {cutoff!r} Hz must be in (0, {0.5 * fs:g}) Hz (Nyquist)")
    b, a = butter(order, cutoff / (0.5 * fs))
    S = filtfilt(b, a, np.asarray(res["S_meas"], float))
    i = np.asarray(res["i"], float)
    if current_noise > 0:
        i = i + np.random.default_rng(seed).normal(0.0, current_noise, i.size)
    i = filtfilt(b, a, i)
    v = filtfilt(b, a, np.gradient(S, t))
    acc = np.gradient(v, t)
    F = plant.fmag(S, i) - plant.spring.force(S) - plant.params.m * acc
    return {"t": t, "x": S, "v": v, "a": acc, "i": i, "F": F}


def valve_dataset(freq: float = 10.0, magnitude: float = 8e-3, *, cycles: float = 2.0,
                  plant: ValveActuator | None = None, cutoff: float = 1000.0,
                  current_noise: float = 0.0, seed: int | None = 0):
    """A seed-000 sinusoid run as a :class:`friction.dataset.Dataset` (friction by Eq. 1).

    Parameters
    ----------
    freq, magnitude : float
        Sinusoid frequency [Hz] and peak-to-peak lift [m].
    cycles : float
        Number of periods simulated.
    plant : ValveActuator, optional
        Plant (default: its own modified LuGre).
    cutoff, current_noise, seed
        See :func:`recover_friction`.

    Returns
    -------
    Dataset
        ``t, x, v, a, F`` with F recovered as the paper does; the plant's true friction is
        kept as the extra column ``F_true``.
    """
    from friction.dataset import Dataset

    plant = plant or ValveActuator()
    res = plant.simulate(cycles / freq, freq=freq, magnitude=magnitude)
    rec = recover_friction(res, plant, cutoff=cutoff, current_noise=current_noise, seed=seed)
    return Dataset.from_arrays(rec["t"], rec["F"], x=rec["x"], v=rec["v"], a=rec["a"],
                               name=f"valve_{freq:g}Hz_{magnitude * 1e3:g}mm",
                               extra={"F_true": np.asarray(res["F"]), "i": rec["i"]})
