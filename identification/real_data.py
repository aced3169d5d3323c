"""Loaders for the real measured friction data in ``../shared/data/real/`` (see its README).

Every loader returns a :class:`friction.dataset.Dataset` in SI units (rotary joints: rad,
rad/s, N m) with the measured friction force in ``F``. The data are read in place from the
shared folder (never copied into the project); the folder is found from the environment
variable ``FRICTIONLAB_SHARED`` or next to the repository (``<repo>/../shared``).

Sources (cite them with any figure):

* EMPS: Janot, Gautier, Brunot, "Data set and reference models of EMPS", nonlinearbenchmark.org
  (copy: forgi86/sysid-neural-continuous @ 956aa7ec).
* Pneumatic seal: Zillen, TU Delft, EvaZillen/3D-printed-pneumatic-actuator @ 6e0bcb46 (CC0).
* Franka joints: longshike/NNFM-A-Novel-Neural-Network-Modeling-Approach-for-Robot-Flexible-
  Joints-Friction @ a343d3a3.
* Joint steady state: igricart/FrictionIdentification @ 449ef59d.
* Rack and pinion: Mnich, Lodz University of Technology, KonradMnich/friction-identification
  @ 8b477df1.
"""
from __future__ import annotations

import csv
import os
import pathlib
from dataclasses import dataclass

import numpy as np

from friction.dataset import Dataset

__all__ = ["real_data_dir", "load_emps", "emps_baseline", "EMPS_PUBLISHED", "load_pneumatic",
           "load_franka", "franka_paper_rms", "load_joint_steady_state", "SteadyStateMap",
           "PNEUMATIC_AREA", "load_rack_pinion"]

#: published inverse-dynamic-model baseline of the EMPS benchmark (README of emps/)
EMPS_PUBLISHED = {"M": 95.1089, "Fv": 203.5034, "Fc": 20.3935, "OF": -3.1648}
#: piston area of the pneumatic cylinder [m^2] (bore 25 mm)
PNEUMATIC_AREA = np.pi * 0.0125 ** 2

_SEALS = ("O-ring", "NAPN", "KDN")
_BARS = (1, 3, 5, 7)
_SPEEDS = ("slow", "middle", "high")
_FRANKA_JOINT = {3: 2, 4: 7}


def real_data_dir() -> pathlib.Path:
    """Folder of the shared real data (``$FRICTIONLAB_SHARED/data/real``).

    Raises
    ------
    FileNotFoundError
        If the folder is absent, naming where it was looked for.
    """
    env = os.environ.get("FRICTIONLAB_SHARED")
    repo = pathlib.Path(__file__).resolve().parents[1]
    shared = pathlib.Path(env) if env else repo.parent / "shared"
    real = shared / "data" / "real"
    if not real.is_dir():
        raise FileNotFoundError(
            f"real data folder not found at {real}; set FRICTIONLAB_SHARED to the folder that "
            f"holds data/real/")
    return real


def _file(*parts) -> pathlib.Path:
    path = real_data_dir().joinpath(*parts)
    if not path.exists():
        raise FileNotFoundError(f"real data file not found: {path}")
    return path


# ------------------------------------------------------------------------------ EMPS
def _emps_raw(which: str) -> dict:
    from scipy.io import loadmat
    names = {"estimation": "DATA_EMPS.mat", "validation": "DATA_EMPS_PULSES.mat"}
    if which not in names:
        raise ValueError(f"which = {which!r}: must be one of {sorted(names)}")
    raw = loadmat(_file("emps", names[which]))
    return {k: np.asarray(v, float).ravel() for k, v in raw.items() if not k.startswith("__")}


def _emps_signals(which: str, decimate: int, cutoff: float = 100.0, order: int = 4):
    """Filtered/decimated EMPS signals: t, q, dq, ddq, motor force, pulses (or None)."""
    from scipy import signal
    raw = _emps_raw(which)
    t, q, vir = raw["t"], raw["qm"], raw["vir"]
    gtau = float(raw["gtau"][0])
    fs = 1.0 / float(np.median(np.diff(t)))
    # the benchmark's own pre-processing: 4th-order Butterworth 100 Hz, zero phase,
    # on position and on the controller output, then central differences
    b, a = signal.butter(order, cutoff / (fs / 2.0))
    qf = signal.filtfilt(b, a, q)
    uf = signal.filtfilt(b, a, vir)
    dq = np.gradient(qf, t)
    ddq = np.gradient(dq, t)
    if not (isinstance(decimate, (int, np.integer)) and decimate >= 1):
        raise ValueError(f"decimate = {decimate!r}: must be an integer >= 1")
    sl = slice(0, None, int(decimate))  # keep every k-th filtered sample (benchmark procedure)
    pulses = raw.get("pulses_N")
    return (t[sl], qf[sl], dq[sl], ddq[sl], gtau * uf[sl],
            None if pulses is None else pulses[sl])


def load_emps(which: str = "estimation", M: float = EMPS_PUBLISHED["M"],
              decimate: int = 10) -> Dataset:
    """EMPS prismatic joint: friction force from inverse dynamics.

    ``F = gtau * vir - M * ddq`` with the published moving mass ``M``, on position and
    controller output filtered by a 4th-order Butterworth at 100 Hz (zero phase), central
    differences for velocity and acceleration, and every ``decimate``-th sample kept.

    Parameters
    ----------
    which : {"estimation", "validation"}
        ``DATA_EMPS.mat`` or ``DATA_EMPS_PULSES.mat``.
    M : float
        Moving mass [kg] used in the inverse dynamics.
    decimate : int
        Keep every k-th sample of the 1 kHz record (10 gives 100 Hz, the benchmark's choice).

    Returns
    -------
    Dataset
        ``x`` [m], ``v`` [m/s], ``a`` [m/s^2], ``F`` [N]. ``extra`` holds ``motor_force`` [N]
        (gtau*vir) and, for the validation set, ``pulses_N`` [N].

    Notes
    -----
    The external force of the pulse set (0/5 N square wave on the carriage) is **not**
    subtracted: ``F`` is the apparent friction that a friction model has to explain, exactly
    as the benchmark's validation of its baseline treats it (the pulses are a disturbance the
    baseline leaves out). ``extra["pulses_N"]`` keeps it for analyses that want it.
    """
    if not M > 0:
        raise ValueError(f"M = {M!r} is out of bounds: must be M > 0 [kg]")
    t, q, dq, ddq, fm, pulses = _emps_signals(which, decimate)
    extra = {"motor_force": fm}
    if pulses is not None:
        extra["pulses_N"] = pulses
    return Dataset.from_arrays(t, fm - M * ddq, x=q, v=dq, a=ddq, extra=extra,
                               name=f"EMPS {which}", check_units=False)


@dataclass
class EMPSBaseline:
    """Inverse-dynamic-model least squares ``M ddq + Fv dq + Fc sign(dq) + OF = gtau vir``."""
    M: float
    Fv: float
    Fc: float
    OF: float
    relative_error: float  #: ||y - A theta|| / ||y|| on the estimation set
    validation_error: float  #: the same on the pulse set (parameters from estimation)

    def predict(self, v, a) -> np.ndarray:
        """Motor force predicted by the baseline [N]."""
        v, a = np.asarray(v, float), np.asarray(a, float)
        return self.M * a + self.Fv * v + self.Fc * np.sign(v) + self.OF

    def friction(self, v) -> np.ndarray:
        """Friction part of the baseline [N]."""
        v = np.asarray(v, float)
        return self.Fv * v + self.Fc * np.sign(v) + self.OF

    def as_dict(self) -> dict:
        return dict(M=self.M, Fv=self.Fv, Fc=self.Fc, OF=self.OF,
                    relative_error=self.relative_error, validation_error=self.validation_error)


def emps_baseline(decimate: int = 10) -> EMPSBaseline:
    """Re-run the published EMPS baseline (linear least squares on the inverse dynamic model).

    Returns the identified ``M`` [kg], ``Fv`` [N s/m], ``Fc`` [N], ``OF`` [N] and the relative
    errors ``||gtau vir - prediction|| / ||gtau vir||`` on the estimation and pulse sets.
    """
    def regress(which):
        _, _, dq, ddq, fm, _ = _emps_signals(which, decimate)
        A = np.column_stack([ddq, dq, np.sign(dq), np.ones_like(dq)])
        return A, fm
    A, y = regress("estimation")
    theta, *_ = np.linalg.lstsq(A, y, rcond=None)
    err = float(np.linalg.norm(y - A @ theta) / np.linalg.norm(y))
    Av, yv = regress("validation")
    verr = float(np.linalg.norm(yv - Av @ theta) / np.linalg.norm(yv))
    return EMPSBaseline(*map(float, theta), relative_error=err, validation_error=verr)


# ------------------------------------------------------------------------------ pneumatic
def load_pneumatic(seal: str = "O-ring", bar: int = 1, smooth_hz: float | None = 5.0) -> Dataset:
    """Seal friction of the 3D-printed pneumatic cylinder (TU Delft).

    Friction ``F = F_measured - p * 1e5 * A`` with ``A = pi * 0.0125^2`` m^2; position mm -> m,
    time ms -> s. The pressure force ``p * 1e5 * A`` [N] is the ``load`` (the normal load of
    the pressurised seal grows with it).

    Parameters
    ----------
    seal : {"O-ring", "NAPN", "KDN"}
    bar : {1, 3, 5, 7}
        Supply pressure [bar] of the record.
    smooth_hz : float or None
        The record is sampled irregularly (10-22 ms); it is interpolated onto a uniform 10 ms
        grid and the position low-passed at this cut-off (zero-phase Butterworth, order 2)
        before velocity/acceleration are differentiated. ``None``: raw samples, plain
        central differences.
    """
    if seal not in _SEALS:
        raise ValueError(f"seal = {seal!r}: must be one of {_SEALS}")
    if bar not in _BARS:
        raise ValueError(f"bar = {bar!r}: must be one of {_BARS}")
    raw = np.loadtxt(_file("pneumatic_seal", f"{seal}_{bar}bar.csv"))
    if raw.ndim != 2 or raw.shape[1] != 7:
        raise ValueError(f"pneumatic file {seal}_{bar}bar.csv: expected 7 columns, got {raw.shape}")
    t = raw[:, 0] * 1e-3
    x = raw[:, 4] * 1e-3
    p = raw[:, 5]
    Fm = raw[:, 6]
    if smooth_hz is None:
        load = p * 1e5 * PNEUMATIC_AREA
        return Dataset.from_arrays(t, Fm - load, x=x, load=load, name=f"pneumatic {seal} {bar} bar",
                                   extra={"pressure_bar": p, "measured_force": Fm})
    from scipy import signal
    dt = 0.01
    tu = np.arange(t[0], t[-1] + 0.5 * dt, dt)
    xu, pu, Fu = (np.interp(tu, t, s) for s in (x, p, Fm))
    b, a = signal.butter(2, smooth_hz / (0.5 / dt))
    xs = signal.filtfilt(b, a, xu)
    v = np.gradient(xs, tu)
    acc = np.gradient(v, tu)
    load = pu * 1e5 * PNEUMATIC_AREA
    return Dataset.from_arrays(tu, Fu - load, x=xs, v=v, a=acc, load=load,
                               name=f"pneumatic {seal} {bar} bar",
                               extra={"pressure_bar": pu, "measured_force": Fu})


# ------------------------------------------------------------------------------ Franka
def _read_csv_columns(path) -> dict[str, np.ndarray]:
    with open(path, newline="") as fh:
        reader = csv.reader(fh)
        header = [h.strip() for h in next(reader)]
        data = np.array([[float(c) for c in row] for row in reader if row], dtype=float)
    return {h: data[:, j] for j, h in enumerate(header)}


def load_franka(case: int = 3, speed: str = "slow") -> Dataset:
    """Franka Panda joint friction (case 3 = joint 2, case 4 = joint 7).

    Rotary joint, so the SI units are angular: ``x`` = q [rad], ``v`` = dq [rad/s],
    ``F`` = measured friction torque ``q*_tau_J_compensate`` [N m]. The files' ``ddq`` column
    is zero, so ``a`` is derived from ``dq`` by central differences. The source paper's model
    predictions (CV, Dahl, Stribeck, LuGre, SVM, ...) are kept in ``extra``.
    """
    if case not in _FRANKA_JOINT:
        raise ValueError(f"case = {case!r}: must be one of {sorted(_FRANKA_JOINT)}")
    if speed not in _SPEEDS:
        raise ValueError(f"speed = {speed!r}: must be one of {_SPEEDS}")
    j = _FRANKA_JOINT[case]
    cols = _read_csv_columns(_file("franka_joint", f"franka_case{case}_{speed}.csv"))
    t = cols.pop("time")
    q, dq = cols.pop(f"q{j}"), cols.pop(f"dq{j}")
    cols.pop(f"ddq{j}", None)
    tau = cols.pop(f"q{j}_tau_J_compensate")
    return Dataset.from_arrays(t, tau, x=q, v=dq, extra=cols,
                               name=f"franka case{case} {speed} (joint {j})")


def franka_paper_rms(case: int, speed: str, model: str = "LuGre") -> float:
    """The source paper's RMS [N m] of ``model`` on a case/speed (may be ``inf``)."""
    path = _file("franka_joint", "friction_model_comparison_all_results_filtered.csv")
    with open(path, newline="") as fh:
        for row in csv.DictReader(fh):
            if row["Case"] == f"case{case}" and row["Speed"] == speed and row["Model"] == model:
                return float(row["RMS"])
    raise KeyError(f"no paper RMS for case{case} {speed} {model}")


# ------------------------------------------------------------------------------ steady state
@dataclass
class SteadyStateMap:
    """A steady-state friction map: effort ``F`` at constant velocity ``v`` (sorted by v)."""
    v: np.ndarray
    F: np.ndarray
    name: str = "steady state"

    def as_dataset(self) -> Dataset:
        """The map as a quasi-static Dataset (``t`` = sample index [s], a = 0)."""
        t = np.arange(self.v.size, dtype=float)
        return Dataset.from_arrays(t, self.F, v=self.v, a=np.zeros_like(self.v),
                                   name=self.name, check_units=False)


def load_joint_steady_state() -> SteadyStateMap:
    """Steady-state friction map of a robot joint (``steadyState_friction.mat``).

    The file's variable names are swapped relative to their meaning: ``u`` is the swept
    constant velocity (continuous from -0.25 to 0.34) and ``dx`` the effort (about
    ``2 sgn(v) + v``, a Coulomb level plus viscous slope; ``dx`` has no values in (-2, 2), so it
    cannot be the velocity sweep). Returned sorted by velocity.

    Note that the repository's script (Script_Friction.m) sets exactly Fc = 2, sigma2 = 1
    ("Kermani paper parameters"), so this map may come from their Simulink model rather than
    from the joint itself.
    """
    from scipy.io import loadmat
    raw = loadmat(_file("joint_steady_state", "steadyState_friction.mat"))
    v = np.asarray(raw["u"], float).ravel()
    F = np.asarray(raw["dx"], float).ravel()
    order = np.argsort(v, kind="stable")
    return SteadyStateMap(v=v[order], F=F[order], name="joint steady state")


# ------------------------------------------------------------------------------ rack and pinion
def load_rack_pinion() -> Dataset:
    """One accelerating stroke of the rack-and-pinion rig (Lodz University of Technology).

    ``sample_workspace_4.mat``: 807 samples at 1.5 kHz; position ``x`` [m], velocity ``v``
    [m/s], acceleration ``a`` [m/s^2] (about 3 m/s^2 up to 0.62 m/s), drive force ``F`` [N]
    and the friction force ``F_fric = F - m a`` [N] with the reduced mass m = 24.7 kg (the
    source's inverse dynamics). ``F`` of the returned dataset is ``F_fric``. The source's
    own 4-coefficient friction model, evaluated on its first 400 samples, is kept in
    ``extra["F_model_source"]`` (NaN outside them) to compare an identified law against.
    """
    from scipy.io import loadmat
    raw = loadmat(_file("rack_pinion", "sample_workspace_4.mat"))
    g = {k: np.asarray(v, float).ravel() for k, v in raw.items() if not k.startswith("__")}
    for key in ("t", "x", "v", "a", "F_fric", "F_model", "range", "reduced_mass"):
        if key not in g:
            raise ValueError(f"rack_pinion/sample_workspace_4.mat: variable {key!r} missing")
    n = g["t"].size
    source = np.full(n, np.nan)
    idx = g["range"].astype(int) - 1  # MATLAB indices of the samples the model covers
    if idx.min() < 0 or idx.max() >= n or idx.size != g["F_model"].size:
        raise ValueError("rack_pinion: 'range' does not index the F_model samples")
    source[idx] = g["F_model"]
    return Dataset.from_arrays(g["t"], g["F_fric"], x=g["x"], v=g["v"], a=g["a"],
                               name="rack and pinion stroke",
                               extra={"F_model_source": source, "drive_force": g["F"],
                                      "reduced_mass": np.full(n, g["reduced_mass"][0])})
