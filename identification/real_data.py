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
* CICESE two-link direct-drive arm: "A Novel Method for Obtaining the Friction Models of
  Direct-Drive Robot Manipulators: Characterization and Quantitative Comparison" (under
  review), jorgevchin/Friction-Identification @ d455ff83.
"""
from __future__ import annotations

import csv
import os
import pathlib
from dataclasses import dataclass

import numpy as np

from friction.dataset import Dataset, SteadyStateMap

__all__ = ["real_data_dir", "load_emps", "emps_baseline", "EMPS_PUBLISHED", "load_pneumatic",
           "load_franka", "franka_paper_rms", "load_joint_steady_state", "SteadyStateMap",
           "PNEUMATIC_AREA", "load_rack_pinion", "CICESE_PUBLISHED", "load_cicese_run",
           "cicese_runs", "cicese_test2_map", "cicese_breakaway", "load_cicese_presliding"]

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


# ------------------------------------------------------------------------------ CICESE arm
#: what the source documents (README of cicese_arm/): static friction per direction
#: (+, -) [N m] by joint, from its Test 1 torque ramps; joint inertias [kg m^2] and viscous
#: coefficients [N m s/rad] of its Test 3 analysis
CICESE_PUBLISHED = {"static": {1: (10.75, -12.00), 2: (1.49, -1.45)},
                    "inertia": {1: 2.519, 2: 0.102},
                    "viscous": {1: 3.1465, 2: 0.1237}}
#: torque limits of the drives [N m]
CICESE_TORQUE_LIMIT = {1: 200.0, 2: 15.0}
_DEG = np.pi / 180.0
#: Test 1 torque-ramp runs per joint (README: +-0.5 N m/s joint 1, +-0.1 N m/s joint 2)
_CICESE_RAMPS = {1: ("05_exp1", "05_exp2", "05_exp3", "05_exp4",
                     "n05_exp1", "n05_exp2", "n05_exp3", "n05_exp4"),
                 2: ("01_exp5", "01_exp6", "01_exp7", "01_exp8",
                     "n01_exp1", "n01_exp2", "n01_exp3", "n01_exp4")}
_CICESE_PREFIX = {1: "est", 2: "cin"}


def _cicese_read(test: int, prefix: str, kind: str, tag: str) -> np.ndarray:
    path = _file("cicese_arm", f"Test_{test}", f"{prefix}_{kind}_{tag}_gan.t")
    raw = np.loadtxt(path)
    if raw.ndim != 2 or raw.shape[1] != 2:
        raise ValueError(f"{path.name}: expected two columns (time, value), got {raw.shape}")
    return raw


def _diff7(y: np.ndarray, h: float) -> np.ndarray:
    """Seven-point central difference (sixth order) with step ``h`` [s], as the source
    differentiates its positions; second-order differences at the three samples of each
    end."""
    d = np.gradient(y, h)
    if y.size >= 7:
        d[3:-3] = (-y[:-6] + 9 * y[1:-5] - 45 * y[2:-4] + 45 * y[4:-2] - 9 * y[5:-1]
                   + y[6:]) / (60.0 * h)
    return d


def load_cicese_run(test: int, tag: str, joint: int, *, prefix: str | None = None,
                    smooth_hz: float | None = None, inertia: bool = True) -> Dataset:
    """One run of the CICESE two-link direct-drive arm, as the friction torque of one joint.

    The six files of a run (``pos``, ``vel``, ``tau`` of both joints, 15 ms) are read; the
    positions [deg] become rad, velocity and acceleration are seven-point central
    differences of the position (the source's choice; the logged ``vel`` is the controller's
    quantised signal and is not used), and the friction torque of the joint is the applied
    torque minus the rigid two-link inverse dynamics with the source's numbers (README):
    ``tau_f = tau - M(q) qdd - C(q, qd) qd - g(q)``.

    Parameters
    ----------
    test : {1, 2, 3}
        ``Test_1`` (torque ramps), ``Test_2`` (constant velocity), ``Test_3`` (presliding).
    tag : str
        The run's file tag between the signal name and ``_gan.t``: ``"05_exp1"`` (Test 1),
        ``"40_exp"``, ``"n40_exp"``, ``"40_exp2"`` (Test 2), ``"6_exp1"`` (Test 3).
    joint : {1, 2}
    prefix : str, optional
        File prefix (default ``est`` / ``cin``; Test 3: ``sig0`` or ``sig1``, required).
    smooth_hz : float, optional
        Zero-phase Butterworth low-pass (order 2) of both positions before differentiating
        [Hz] (presliding records move a few encoder counts: their differentiated velocity is
        mostly quantisation noise).
    inertia : bool
        Subtract the inertia torque ``M(q) qdd``. The constant-velocity analysis leaves it
        out (the source's Test 2 script does): over a plateau the mean acceleration is zero,
        and the twice-differentiated 15 ms position turns a few-hertz ripple of the speed
        into +-10 N m of torque on joint 1 that the applied torque does not show.

    Returns
    -------
    Dataset
        ``t`` [s], ``x`` = q [rad], ``v`` [rad/s], ``a`` [rad/s^2], ``F`` = friction torque
        [N m]; ``extra``: ``tau`` (applied) [N m], ``gravity`` [N m], ``exclude`` (1 where
        either drive is at its torque limit). A run without the other joint's files (the
        Test 1 ramps move one joint) takes that joint at rest at q = 0.
    """
    if joint not in (1, 2):
        raise ValueError(f"joint = {joint!r}: must be 1 or 2")
    if test not in (1, 2, 3):
        raise ValueError(f"test = {test!r}: must be 1, 2 or 3")
    if prefix is None:
        if test == 3:
            raise ValueError("Test 3 runs need prefix='sig0' (sine) or 'sig1' (step)")
        prefix = _CICESE_PREFIX[test]
    own, other = f"{joint}", f"{3 - joint}"
    sig = {k: _cicese_read(test, prefix, k, tag) for k in ("pos" + own, "tau" + own)}
    try:
        for k in ("pos" + other, "tau" + other):
            sig[k] = _cicese_read(test, prefix, k, tag)
        other_logged = True
    except FileNotFoundError:
        # Test 1 ramps one joint at a time (the other's files carry other tags): the
        # other joint is taken at rest at q = 0, as the source's analysis does
        ref = sig["pos" + own]
        for k in ("pos" + other, "tau" + other):
            sig[k] = np.column_stack([ref[:, 0], np.zeros(ref.shape[0])])
        other_logged = False
    base = sig["pos" + own]
    keep = np.concatenate([[True], np.diff(base[:, 0]) > 0])  # repeated stamps dropped
    t = base[keep, 0]

    def on_t(a):  # a file logged a few samples more or less: read on the position's clock
        tt, y = a[:, 0], a[:, 1]
        ok = np.concatenate([[True], np.diff(tt) > 0])
        return np.interp(t, tt[ok], y[ok])

    q1, q2 = on_t(sig["pos1"]) * _DEG, on_t(sig["pos2"]) * _DEG
    tau1, tau2 = on_t(sig["tau1"]), on_t(sig["tau2"])
    h = float(np.median(np.diff(t)))
    if smooth_hz is not None:
        from scipy import signal
        b, a = signal.butter(2, smooth_hz / (0.5 / h))
        q1, q2 = signal.filtfilt(b, a, q1), signal.filtfilt(b, a, q2)
    qd1, qd2 = _diff7(q1, h), _diff7(q2, h)
    qdd1, qdd2 = _diff7(qd1, h), _diff7(qd2, h)
    w = 1.0 if inertia else 0.0
    c2, s2 = np.cos(q2), np.sin(q2)
    m11, m12, m22 = 2.351 + 0.168 * c2, 0.102 + 0.084 * c2, 0.102
    g = 9.81
    g1 = g * (3.921 * np.sin(q1) + 0.186 * np.sin(q1 + q2))
    g2 = g * 0.186 * np.sin(q1 + q2)
    if joint == 1:
        tau, grav, q, qd, qdd = tau1, g1, q1, qd1, qdd1
        F = tau1 - w * (m11 * qdd1 + m12 * qdd2) - (-0.168 * s2 * qd2 * qd1
                                                 - 0.084 * s2 * qd2 * qd2) - g1
    else:
        tau, grav, q, qd, qdd = tau2, g2, q2, qd2, qdd2
        F = tau2 - w * (m12 * qdd1 + m22 * qdd2) - 0.084 * s2 * qd1 * qd1 - g2
    sat = (np.abs(tau1) >= 0.99 * CICESE_TORQUE_LIMIT[1]) | \
        (np.abs(tau2) >= 0.99 * CICESE_TORQUE_LIMIT[2])
    return Dataset.from_arrays(t, F, x=q, v=qd, a=qdd, check_units=False,
                               name=f"CICESE test {test} {prefix} {tag} joint {joint}",
                               extra={"tau": tau, "gravity": grav,
                                      "exclude": sat.astype(float)})


def cicese_runs(joint: int = 1) -> list[tuple[str, float]]:
    """Test 2 constant-velocity runs: ``(tag, commanded velocity [rad/s])``, both
    directions and the ``exp2`` repetitions, without the repetitions that are byte copies
    of their first run (README: the ``exp2`` files at 0.2-0.4 deg/s)."""
    import hashlib
    folder = real_data_dir() / "cicese_arm" / "Test_2"
    out, seen = [], set()
    for path in sorted(folder.glob(f"cin_tau{joint}_*_gan.t")):
        tag = path.name[len(f"cin_tau{joint}_"):-len("_gan.t")]
        speed, rep = tag.split("_", 1)
        sign = -1.0 if speed.startswith("n") else 1.0
        digits = speed.lstrip("n")
        deg = float(digits) / 10.0 if digits.startswith("0") else float(digits)
        digest = hashlib.sha1(path.read_bytes()).hexdigest()
        if digest in seen:
            continue
        seen.add(digest)
        out.append((tag, sign * deg * _DEG))
    out.sort(key=lambda tv: tv[1])
    return out


def cicese_test2_map(joint: int = 1, *, tolerance: float = 0.2, smooth: float = 0.3,
                     min_speed: float = 0.0) -> SteadyStateMap:
    """Steady-state friction map of one joint from Test 2 (one plateau per run, both
    directions, the repetitions included).

    Each run's plateau (:func:`identification.steady_state.plateau`): the longest stretch
    whose velocity (moving average over ``smooth`` s) is within ``tolerance`` of the
    commanded one, excluding samples at a torque limit (which also drops the fast runs'
    braking at |q1| near 180 deg); the plateau's velocity is its mean position slope
    [rad/s], its torque the median friction torque [N m] (``tau - C(q, qd) qd - g(q)``,
    the inertia torque left out as the source does: see :func:`load_cicese_run`).

    Parameters
    ----------
    joint : {1, 2}
    tolerance, smooth : float
        Plateau band (relative) and smoothing window [s].
    min_speed : float
        Commanded speeds below this [rad/s] are left out.
    """
    from .steady_state import plateau
    v, F, rows = [], [], {"F_spread": [], "t0": [], "t1": [], "v_command": []}
    skipped = 0
    for tag, vt in cicese_runs(joint):
        if abs(vt) < min_speed:
            continue
        run = load_cicese_run(2, tag, joint, inertia=False)
        p = plateau(run, vt, tolerance=tolerance, smooth=smooth,
                    exclude=run.extra["exclude"] > 0)
        if p is None:
            skipped += 1
            continue
        v.append(p["v"])
        F.append(p["F"])
        for k in ("F_spread", "t0", "t1"):
            rows[k].append(p[k])
        rows["v_command"].append(vt)
    notes = (f"{skipped} run(s) without a plateau",) if skipped else ()
    return SteadyStateMap(np.array(v), np.array(F), name=f"CICESE test 2 joint {joint}",
                          extra={k: np.array(a) for k, a in rows.items()}, notes=notes)


def cicese_breakaway(joint: int = 1, v_threshold: float = 0.2 * _DEG) -> dict:
    """Static friction per direction from the Test 1 torque ramps
    (:func:`identification.steady_state.breakaway` of each run).

    ``v_threshold`` [rad/s]: the joint counts as sliding once its seven-point velocity
    exceeds it (default 0.2 deg/s: above the presliding creep the ramps show, twice the
    slowest Test 2 plateau).

    Returns
    -------
    dict
        ``"+"`` and ``"-"``: mean static friction [N m] per direction; ``"runs"``:
        ``tag -> torque`` [N m] (None for a run that never slides).
    """
    from .steady_state import breakaway
    runs = {}
    for tag in _CICESE_RAMPS[joint]:
        r = breakaway(load_cicese_run(1, tag, joint), v_threshold)
        runs[tag] = None if r is None else r["F"]
    pos = [f for tg, f in runs.items() if f is not None and not tg.startswith("n")]
    neg = [f for tg, f in runs.items() if f is not None and tg.startswith("n")]
    return {"+": float(np.mean(pos)) if pos else None,
            "-": float(np.mean(neg)) if neg else None, "runs": runs}


def load_cicese_presliding(joint: int = 1, run: int = 1, kind: str = "sig0",
                           smooth_hz: float | None = 5.0) -> Dataset:
    """A Test 3 presliding record of one joint: a 0.5 Hz torque sine of 6 N m (joint 1) /
    0.8 N m (joint 2) (``sig0``) or a torque step to that level at 1.02 s (``sig1``), the
    joint moving a few thousandths of a degree. Friction torque as
    :func:`load_cicese_run` (at rest g(q) and the inertia torque are tiny: friction is
    about the applied torque), positions low-passed at ``smooth_hz`` before
    differentiating.
    """
    if kind not in ("sig0", "sig1"):
        raise ValueError(f"kind = {kind!r}: must be 'sig0' or 'sig1'")
    level = "6" if joint == 1 else "08"
    return load_cicese_run(3, f"{level}_exp{int(run)}", joint, prefix=kind,
                           smooth_hz=smooth_hz)


# ------------------------------------------------------------------------------ diagnosis protocols
# Held-out designs for diagnosis.diagnose on the real data (issue 15): what the pulse signal
# of the EMPS pulse record is, the pulse record without its step transients, and the CICESE
# Test 2 plateaus split by speed.
__all__ += ["emps_pulse_evidence", "emps_pulse_segments", "cicese_plateau_runs",
            "cicese_speed_split"]


def emps_pulse_evidence(steady_accel: float = 0.05, steady_speed: float = 0.02) -> dict:
    """What the ``pulses_N`` signal of ``DATA_EMPS_PULSES.mat`` is, read from the data.

    Three checks on the 1 kHz record (README of emps/: unit and point of application
    uncertain):

    1. The benchmark's controller, ``u(k) = kv (kp (qg(k) - qf(k)) - dqf(k))`` with
       ``qf(k) = (qm(k) + qm(k-1)) / 2`` and ``dqf`` its backward difference, is recomputed
       from the logged ``qg``, ``qm``; ``vir - u = c0 + c * pulses_N`` is fitted at lags of
       -3..3 samples. ``c`` near 1 V per unit at lag 0 says the pulse is *added to the
       controller output in volts* and the logged ``vir`` already holds it.
    2. In steady motion (``|a| < steady_accel``, ``|v| > steady_speed``), per direction,
       the motor force ``gtau vir`` regressed on ``v``, a constant and the pulse: an external
       5 N on the carriage would move the motor force by 5 N (the PD loop has no integral
       action, so the force balance holds in steady motion); a pulse inside ``vir`` moves
       it by nothing.
    3. The tracking error ``qg - qm`` shifts between pulse on and off by
       ``-c * pulse / (kv kp)`` if the pulse is a controller-output voltage.

    Parameters
    ----------
    steady_accel : float
        Largest |acceleration| of a steady-motion sample [m/s^2].
    steady_speed : float
        Smallest |velocity| of a steady-motion sample [m/s].

    Returns
    -------
    dict
        ``volts_per_unit`` (c [V per unit of pulses_N]), ``lag`` [samples] of the best fit,
        ``offset`` c0 [V], ``rms_without`` / ``rms_with`` (RMS of ``vir - u`` before and
        after the pulse term [V]; the estimation record's own RMS is ``rms_estimation``),
        ``step_force`` (``gtau c max(pulses_N)``, the motor-force step [N]),
        ``steady_force_change`` ({+1, -1}: change of the motor force with the pulse on
        [N], per direction), ``error_shift`` (mean ``qg - qm`` on minus off [m]) and
        ``error_shift_expected`` (``-c max(pulses_N) / (kv kp)`` [m]).
    """
    def controller_gap(raw):
        qm, qg, vir = raw["qm"], raw["qg"], raw["vir"]
        kp, kv = float(raw["kp"][0]), float(raw["kv"][0])
        qf = qm.copy()
        qf[1:] = 0.5 * (qm[1:] + qm[:-1])
        dqf = np.zeros_like(qf)
        dqf[1:] = np.diff(qf) / float(np.median(np.diff(raw["t"])))
        return vir - kv * (kp * (qg - qf) - dqf), kp, kv

    raw = _emps_raw("validation")
    gap, kp, kv = controller_gap(raw)
    pulses = raw["pulses_N"]
    inner = slice(5, -5)  # the controller's two-sample memory and the lags' wrap-round
    best = None
    for lag in range(-3, 4):
        A = np.column_stack([np.ones_like(pulses), np.roll(pulses, lag)])[inner]
        theta, *_ = np.linalg.lstsq(A, gap[inner], rcond=None)
        rms = float(np.sqrt(np.mean((gap[inner] - A @ theta) ** 2)))
        if best is None or rms < best[0]:
            best = (rms, lag, theta)
    rms_with, lag, (c0, c) = best
    gap_est, _, _ = controller_gap(_emps_raw("estimation"))
    # steady motion: the motor force with and without the pulse, per direction
    _, _, dq, ddq, fm, pul = _emps_signals("validation", 1)
    steady = (np.abs(ddq) < steady_accel) & (np.abs(dq) > steady_speed)
    change = {}
    for s in (1, -1):
        m = steady & (np.sign(dq) == s)
        A = np.column_stack([dq[m], np.ones(m.sum()), pul[m] > 0])
        theta, *_ = np.linalg.lstsq(A, fm[m], rcond=None)
        change[s] = float(theta[2])
    err = raw["qg"] - raw["qm"]
    on = pulses > 0
    gtau = float(raw["gtau"][0])
    return {"volts_per_unit": float(c), "lag": int(lag), "offset": float(c0),
            "rms_without": float(np.sqrt(np.mean(gap[inner] ** 2))), "rms_with": rms_with,
            "rms_estimation": float(np.sqrt(np.mean(gap_est[inner] ** 2))),
            "step_force": gtau * float(c) * float(pulses.max()),
            "steady_force_change": change,
            "error_shift": float(np.mean(err[on]) - np.mean(err[~on])),
            "error_shift_expected": -float(c) * float(pulses.max()) / (kv * kp)}


def emps_pulse_segments(drop: float = 0.03, decimate: int = 10, min_samples: int = 20,
                        keep_start: bool = False) -> list[Dataset]:
    """The EMPS pulse record cut at its pulse steps, the first ``drop`` seconds after each
    step left out: held-out records for a friction diagnosis.

    The pulse is a 5 V step of the controller output every 0.5 s, already inside the
    logged ``vir`` (:func:`emps_pulse_evidence`): the motor force ``gtau vir`` and so the
    friction force of :func:`load_emps` account for it as a measured input. What the
    friction law cannot follow is the carriage's response to a 176 N force step within
    about 1 ms: the structural flexibility it excites and the 100 Hz filter smearing the
    step against the inverse dynamics (README: known effects outside the baseline). That
    transient holds most of the held-out residual in the first 30 ms after each step;
    leaving it out keeps the steady and slowly varying motion of both directions.

    Parameters
    ----------
    drop : float
        Time after each pulse step that is left out [s] (0 keeps every sample).
    decimate : int
        As :func:`load_emps`.
    min_samples : int
        Segments shorter than this after the cut are left out.
    keep_start : bool
        Keep the record's first 0.34 s, the start from rest before the first pulse step.
        Left out by default: its filtered velocity is not exactly zero, so the diagnosis
        starts the law from the steady state of a near-zero velocity instead of from rest
        with a warm-up, and that start-up misfit alone makes any candidate's paired
        improvement insignificant (z 2.5-2.9 with it, 6.4-7.0 without).

    Returns
    -------
    list of Dataset
        One record per pulse half-period, in time order (``x`` [m], ``v`` [m/s],
        ``a`` [m/s^2], ``F`` [N], ``extra["pulses_N"]``), each starting in motion (the
        diagnosis starts the law from its steady state at the first velocity).
    """
    if not drop >= 0:
        raise ValueError(f"drop = {drop!r} is out of bounds: must be >= 0 [s]")
    val = load_emps("validation", decimate=decimate)
    pulses = val.extra["pulses_N"]
    edges = np.r_[0, np.flatnonzero(np.diff(pulses) != 0) + 1, len(val)]
    out = []
    for a, b in zip(edges[:-1], edges[1:]):
        if a == 0 and not keep_start:
            continue
        i0 = int(np.searchsorted(val.t, val.t[a] + drop - 1e-9)) if a > 0 else a
        if b - i0 >= min_samples:
            seg = val.select(slice(i0, b))
            seg.name = f"EMPS validation {val.t[i0]:.2f}-{val.t[b - 1]:.2f} s"
            out.append(seg)
    return out


def cicese_plateau_runs(joint: int = 1, direction: int = 1, *,
                        min_speed: float = 0.45 * _DEG, tolerance: float = 0.2,
                        smooth: float = 0.3) -> list[tuple[str, float, Dataset]]:
    """Test 2 runs of one joint and one direction, each cut to its constant-velocity
    plateau (the cleaned part a friction diagnosis can use).

    The plateau is that of :func:`cicese_test2_map`: after the acceleration transient, no
    sample at a torque limit (which also drops the fast runs' braking near |q1| = 180 deg),
    velocity within ``tolerance`` of the commanded one. The friction torque leaves the
    inertia torque out as the source's Test 2 script does (:func:`load_cicese_run`).

    Parameters
    ----------
    joint : {1, 2}
    direction : {1, -1}
        Sign of the commanded velocity (the source fits the two directions separately).
    min_speed : float
        Runs slower than this [rad/s] are left out (default 0.45 deg/s: the source's
        Stribeck fit starts at the 0.5 deg/s plateaus; the 0.1-0.4 deg/s runs stick and
        slip, their plateaus are short stretches of a few encoder counts).
    tolerance, smooth : float
        As :func:`identification.steady_state.plateau` (relative band, window [s]).

    Returns
    -------
    list of (str, float, Dataset)
        ``(tag, commanded velocity [rad/s], plateau record)`` sorted by speed, the
        ``exp2`` repetitions included (``t`` [s], ``x`` = q [rad], ``v`` [rad/s], ``F``
        [N m]).
    """
    from .steady_state import plateau
    if direction not in (1, -1):
        raise ValueError(f"direction = {direction!r}: must be 1 or -1")
    out = []
    for tag, vt in cicese_runs(joint):
        if abs(vt) < min_speed or np.sign(vt) != direction:
            continue
        run = load_cicese_run(2, tag, joint, inertia=False)
        p = plateau(run, vt, tolerance=tolerance, smooth=smooth,
                    exclude=run.extra["exclude"] > 0)
        if p is None:
            continue
        seg = run.select((run.t >= p["t0"]) & (run.t <= p["t1"]))
        out.append((tag, vt, seg))
    out.sort(key=lambda r: (abs(r[1]), r[0]))
    return out


def _staircase(records: list[Dataset], name: str) -> Dataset:
    """Records laid end to end on one clock (each starts one sample after the previous
    one ends); positions, velocities and forces kept as measured."""
    t, t0 = [], 0.0
    for r in records:
        t.append(r.t - r.t[0] + t0)
        t0 = t[-1][-1] + r.dt
    cat = lambda key: np.concatenate([getattr(r, key) for r in records])  # noqa: E731
    return Dataset.from_arrays(np.concatenate(t), cat("F"), x=cat("x"), v=cat("v"),
                               a=cat("a"), check_units=False, name=name)


def cicese_speed_split(joint: int = 1, direction: int | None = None, **plateau_options):
    """A fit record and held-out records from the CICESE Test 2 plateaus: interleaved
    speeds, so the held-out speeds lie between fitted ones.

    The plateau runs (:func:`cicese_plateau_runs`) sorted by speed are dealt alternately:
    the 1st, 3rd, 5th ... to the fit record, laid end to end on one clock (a staircase of
    constant speeds; the law's state follows each step within a few samples), the 2nd,
    4th ... held out, each a record of its own that starts in motion.

    Parameters
    ----------
    joint : {1, 2}
    direction : {1, -1} or None
        One direction (the source's separate fits), or None for both: the fit staircase
        then alternates the directions so that both span it.
    **plateau_options
        ``min_speed``, ``tolerance``, ``smooth`` of :func:`cicese_plateau_runs`.

    Returns
    -------
    (Dataset, list of Dataset)
        The fit staircase and the held-out plateaus (``x`` = q [rad], ``v`` [rad/s],
        ``F`` = friction torque [N m]).
    """
    dirs = (1, -1) if direction is None else (direction,)
    fit, held = {}, []
    for d in dirs:
        runs = cicese_plateau_runs(joint, d, **plateau_options)
        fit[d] = [r for k, (_, _, r) in enumerate(runs) if k % 2 == 0]
        held += [r for k, (_, _, r) in enumerate(runs) if k % 2 == 1]
    if direction is None:  # alternate the directions along the fit staircase
        pos, neg = fit[1], fit[-1]
        order = [r for pair in zip(pos, neg) for r in pair] + pos[len(neg):] + neg[len(pos):]
    else:
        order = fit[direction]
    label = "both directions" if direction is None else f"direction {direction:+d}"
    return _staircase(order, f"CICESE test 2 joint {joint} {label} fit speeds"), held
