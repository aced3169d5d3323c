"""Trajectory-level diagnosis through the user's own plant FMU.

The procedure is :func:`diagnosis.trajectory.diagnose_trajectory` (base fit, held-out score,
every candidate re-identified and scored, greedy stacking, verdict); the plant is the user's
FMU, coupled with the friction-law FMU and driven by the measured columns as a connection
file says (:mod:`fmus.connect`). Candidates enter as friction-FMU parameters (``asymmetry``,
``stribeck_shape``, ``presliding``), as the ``friction_effects`` FMU block between the law
and the plant (``acceleration``, ``position``, ``drift``, ``load``: switched on by its
Boolean ``use_*`` parameters, fed by the plant outputs the connection's ``[friction]``
table names), as the plant's mass parameter (``inertia``) or as a shift of the compared
output (``delay``). A candidate the connection cannot express (``position`` without a
plant output for x, ``inertia`` without a mass parameter...) is listed under ``skipped``
with the reason.

>>> from diagnosis.plant_fmu import diagnose_plant_fmu                 # doctest: +SKIP
>>> rep = diagnose_plant_fmu("fit.csv", ["heldout.csv"], "rig.fmu", "rig.toml", "lugre")
>>> rep["verdict"]
"""
from __future__ import annotations

import copy
import os
from types import SimpleNamespace

import numpy as np

from .records import TrajectoryRecord

__all__ = ["FMUPlantModel", "ChannelRecord", "diagnose_plant_fmu", "plant_fmu_records",
           "expressible"]


class ChannelRecord(TrajectoryRecord):
    """A measured run of the user's plant: the compared channel ``y`` (any unit; its plant
    output is ``signal``) and the measured columns that drive the plant
    (``options["measured"]``, a :class:`fmus.connect.MeasuredRecord` on the same clock)."""

    def __post_init__(self):
        from friction._validation import as_float_array, check_finite, check_same_length, \
            check_time
        try:
            self.t = as_float_array("t", np.ravel(self.t))
            self.y = as_float_array("y", np.ravel(self.y))
            check_same_length("t", self.t.size, y=self.y)
            if self.t.size < 10:
                raise ValueError(f"need at least 10 samples, got {self.t.size}")
            check_finite("y", self.y)
            check_time(self.t)
        except ValueError as exc:
            raise ValueError(f"record {self.name!r}: {exc}") from None
        self.options = dict(self.options)


def plant_fmu_records(measured, conn, channel: str | None = None) -> ChannelRecord:
    """A :class:`ChannelRecord` of one measured run (a :class:`fmus.connect.MeasuredRecord`
    or a file): times from 0 (the absolute start kept as ``t_start``), the compared channel
    ``channel`` (a ``[compare]`` plant output; default the first)."""
    from fmus.connect import MeasuredRecord, load_measured
    rec = measured if isinstance(measured, MeasuredRecord) else load_measured(measured, conn)
    spec = conn.compare[0] if channel is None else next(
        (s for s in conn.compare if s.variable == channel), None)
    if spec is None:
        raise ValueError(f"{conn.source}: no [compare] entry for plant output {channel!r} "
                         f"(compared: {[s.variable for s in conn.compare]})")
    t0 = float(rec.t[0])
    shifted = MeasuredRecord(rec.t - t0, rec.columns, rec.name)
    return ChannelRecord(shifted.t, shifted.column(spec.column) * spec.scale,
                         {"measured": shifted}, name=rec.name, signal=spec.variable,
                         t_start=t0)


def expressible(conn, mass_parameter) -> dict:
    """Candidates the connection cannot express -> why (the others run)."""
    out = {}
    if "x" not in conn.law_inputs:
        out["position"] = ("no plant output gives the position: name it in [friction] "
                           "x = \"NAME\"")
    if "a" not in conn.law_inputs:
        out["acceleration"] = ("no plant output gives the acceleration: name it in "
                               "[friction] a = \"NAME\"")
    if "load" not in conn.law_inputs:
        out["load"] = ("no plant output gives the normal load: name it in [friction] "
                       "load = \"NAME\"")
    if mass_parameter is None:
        out["inertia"] = ("the plant has no mass parameter (M, m, mass): name it with "
                          "mass = \"NAME\" in the connection file")
    return out


class _ConnEngine:
    """The trajectory diagnosis' engine over :class:`fmus.connect.PlantLoop` (one loop per
    law FMU and with/without the effects block)."""
    name = "fmu"

    def __init__(self, plant):
        self.plant = plant
        self.loops = {}

    def _loop(self, law_name, effects):
        from fmus.connect import PlantLoop
        key = (law_name, bool(effects))
        if key not in self.loops:
            p = self.plant
            self.loops[key] = PlantLoop(p.plant_fmu, p.conn, law_name, native=p.native,
                                        fmu_dir=self._law_dir(law_name), effects=bool(effects))
        return self.loops[key]

    def _law_dir(self, law_name):
        # a candidate that changes the law (backlash, gms) needs that law's FMU: built once
        # per process when the user gave no folder, else the candidate is skipped saying so
        from fmus.master import fmu_file
        from identification.cosim import fmu_dir_for
        from .trajectory import _NotApplicable
        p = self.plant
        if os.path.exists(fmu_file(p.fmu_dir, law_name, p.native)):
            return p.fmu_dir
        if p.user_fmu_dir is None:
            return fmu_dir_for([law_name], None, p.native)
        name = os.path.basename(fmu_file(p.fmu_dir, law_name, p.native))
        raise _NotApplicable(f"{name} is not in {p.fmu_dir}: build it with frictionlab "
                             f"build-fmus --out {p.fmu_dir}")

    def run(self, law, plant_params: dict, options: dict, stop: float, signals):
        from diagnosis.effect_law import EffectLaw
        from fmus.master import law_parameters
        block = None
        if isinstance(law, EffectLaw):
            from friction.extensions import EXTENSION_INDEX
            block = {n: float(law._e[i]) for n, i in EXTENSION_INDEX.items()}
            block["t0"] -= law.time0  # the block's clock starts at 0 with the run
            law = law.base
        rec = options.get("measured")
        if rec is None:
            raise ValueError("the record carries no measured columns (build it with "
                             "diagnosis.plant_fmu.plant_fmu_records)")
        loop = self._loop(law.name, block is not None)
        run = loop.run(rec, law_parameters(law), {**self.plant.values, **plant_params},
                       block, start=0.0, stop=stop)
        return run.time, {s: run.values[s] for s in signals}

    def close(self):
        for loop in self.loops.values():
            loop.close()
        self.loops.clear()


class FMUPlantModel:
    """The user's plant FMU as the plant of :func:`diagnosis.trajectory.diagnose_trajectory`
    (what that procedure reads of a plant: name, outputs, parameters, the friction it
    starts from, a simulation of the base law's kinematics, and its engine).

    Parameters
    ----------
    plant_fmu : path
    conn : fmus.connect.PlantConnection or path
    law : FrictionModel
        The base law (its values start the fit).
    native : bool
        Native C law and effects FMUs (default) or the pythonfmu ones.
    fmu_dir : path, optional
        Folder with the law FMUs and ``friction_effects``; default: built once per process.
    """
    external_friction = False
    any_signal = True      # the compared channel may be any output (position, force ...)
    options: dict = {}
    opts: dict = {}

    def __init__(self, plant_fmu, conn, law, *, native: bool = True, fmu_dir=None):
        from fmus.connect import _declared_unit, check_plant, load_connection
        from identification.cosim import fmu_dir_for
        from .trajectory import MASS_PARAMETERS
        self.conn = load_connection(conn)
        self.plant_fmu = os.fspath(plant_fmu)
        V = check_plant(self.conn, self.plant_fmu, law)
        self.native = bool(native)
        laws = sorted({law.name, "lugre", "friction_effects"})
        self.user_fmu_dir = fmu_dir
        self.fmu_dir = fmu_dir_for(laws, fmu_dir, self.native)
        self.name = os.path.splitext(os.path.basename(self.plant_fmu))[0]
        self.main_output = self.conn.compare[0].variable
        self.all_output_names = tuple(n for n, v in V.items() if v.causality == "output")
        self.signals = {n: (_declared_unit(v) or "",) for n, v in V.items()
                        if v.causality == "output"}
        reals = {n: v for n, v in V.items() if v.causality == "parameter" and v.type == "Real"}
        self.parameter_names = tuple(reals)
        vals = {}
        for n, v in reals.items():
            val = self.conn.parameters.get(n, v.start)
            try:
                vals[n] = float(val)
            except (TypeError, ValueError):
                continue
        self.params = SimpleNamespace(**vals)
        self.values = {}   # plant parameters on top of the connection's (with_params)
        self.mass_parameter = self.conn.mass or next(
            (n for n in MASS_PARAMETERS if n in reals), None)
        self.friction = law
        self._engine = None

    def default_friction(self):
        return self.friction

    def _copy(self):
        return copy.copy(self)

    def with_params(self, **values):
        out = copy.copy(self)
        out.values = {**self.values, **values}
        out.params = SimpleNamespace(**{**vars(self.params), **values})
        return out

    def trajectory_engine(self, engine=None):
        if engine not in (None, "fmu"):
            raise ValueError(f"engine = {engine!r}: the user's plant FMU runs through the "
                             f"co-simulation engine 'fmu' only")
        if self._engine is None:
            self._engine = _ConnEngine(self)
        return self._engine

    def simulate(self, stop, method=None, **options):
        """The base law's run on a record (``measured=`` its columns): ``time``, the
        kinematics ``x, v, a`` (x integrated from v, a differentiated, where the plant does
        not output them), the law's force ``F`` and ``load``, and the compared outputs."""
        eng = self.trajectory_engine()
        kin = self.conn.law_inputs
        signals = list(dict.fromkeys([kin[k] for k in kin] + ["friction.F"] +
                                     [s.variable for s in self.conn.compare]))
        t, out = eng.run(self.friction, dict(self.values), options, stop, signals)
        v = out[kin["v"]]
        x = out[kin["x"]] if "x" in kin else np.concatenate(
            ([0.0], np.cumsum(0.5 * (v[1:] + v[:-1]) * np.diff(t))))
        a = out[kin["a"]] if "a" in kin else np.gradient(v, t)
        cols = {"time": t, "x": x, "v": v, "a": a, "F": out["friction.F"]}
        if "load" in kin:
            cols["load"] = out[kin["load"]]
        for s in self.conn.compare:
            cols.setdefault(s.variable, out[s.variable])
        res = np.empty(t.size, dtype=[(k, float) for k in cols])
        for k, arr in cols.items():
            res[k] = arr
        return res

    def close(self):
        if self._engine is not None:
            self._engine.close()
            self._engine = None


def _start_from(start, law, conn):
    """Law and connection with the values of an identification (an
    :class:`identification.result.IdentificationResult`, its JSON dict, or the JSON file
    ``identify --json`` wrote): the fitted law's parameters and ``plant_params``."""
    import json
    from fmus.connect import with_parameters
    if isinstance(start, (str, os.PathLike)):
        path = os.fspath(start)
        if not os.path.isfile(path):
            raise FileNotFoundError(f"--start: no such file: {path}")
        try:
            with open(path) as fh:
                start = json.load(fh)
        except ValueError as exc:
            raise ValueError(f"--start {path}: not a JSON result of identify ({exc})") from None
    model = start.get("model") if isinstance(start, dict) else None
    if hasattr(model, "params"):
        values = {k: v for k, v in model.params.as_dict().items()}
        name = model.name
    elif isinstance(model, dict) and isinstance(model.get("params"), dict):
        values, name = dict(model["params"]), model.get("name")
    else:
        raise ValueError("start: not an identification result (no fitted model in it)")
    if name is not None and name != law.name:
        raise ValueError(f"start: the identification fitted {name!r}, the base law is "
                         f"{law.name!r}")
    try:
        law = law.with_values(**values)
    except (TypeError, ValueError, KeyError) as exc:
        raise ValueError(f"start: {exc}") from None
    plant = dict(start.get("plant_params") or {})
    return law, with_parameters(conn, **plant) if plant else conn


def diagnose_plant_fmu(fit, heldout, plant_fmu, connect, model=None, *, candidates=None,
                       channel: str | None = None, native: bool = True, fmu_dir=None,
                       start=None, fit_plant=None, progress=None, **options):
    """Name the sim-to-real gap of a friction law inside the user's plant FMU.

    Parameters
    ----------
    fit : path, MeasuredRecord, or an IdentificationResult's record
        The fitted run (columns as the connection names them).
    heldout : path, record or list, optional
        Held-out run(s); default: the last 30 % of ``fit``.
    plant_fmu : path
    connect : path, dict or fmus.connect.PlantConnection
    model : str or FrictionModel, optional
        The base law (default: the connection's ``[law] model``, else ``lugre``), started
        from its values and ``[law] start`` (an identified law, e.g.
        ``identify_plant_fmu(...).model``, is a good start).
    candidates : list of str, optional
        Effects to try (default: every one the FMU engine and the connection can express;
        the others are listed under ``skipped``). A named one the connection cannot express
        is a one-line error.
    channel : str, optional
        The compared plant output (default the first ``[compare]`` entry).
    start : IdentificationResult, dict or path, optional
        An identification through the same plant (:func:`identification.plant_fmu.
        identify_plant_fmu`, or the JSON ``identify --json`` wrote): the base law starts
        from its fitted values and the plant from its ``plant_params``.
    native : bool
        Native C law and effects FMUs (default).
    fit_plant : dict, optional
        Plant parameters re-fitted with the base and every candidate, ``name -> (low,
        high)``; default: the connection's ``[identify]`` ones (an identification that
        fitted them with an incomplete law left them compensating for what it lacked;
        ``{}``: keep them fixed). The ``inertia`` candidate is skipped when the mass is
        among them.
    **options
        Passed to :func:`diagnosis.trajectory.diagnose_trajectory` (``fit_names``,
        ``max_sims``, ``max_sims_base``, ``spread``, ``greedy``, ``fit_fraction``).

    Returns
    -------
    DiagnosisReport
        As the trajectory level (``baseline``, ``where``, ``effects``, ``verdict``...), with
        ``plant`` the FMU's name, ``engine`` ``"fmu"``, ``plant_fmu`` and ``connection``.
    """
    from fmus.connect import load_connection
    from identification.plant_fmu import start_law
    from .trajectory import FMU_EFFECTS, diagnose_trajectory
    conn = load_connection(connect)
    law = start_law(model, conn)
    if start is not None:
        law, conn = _start_from(start, law, conn)
    plant = FMUPlantModel(plant_fmu, conn, law, native=native, fmu_dir=fmu_dir)
    try:
        fit_rec = plant_fmu_records(fit, conn, channel)
        vals = heldout if isinstance(heldout, (list, tuple)) else \
            ([] if heldout is None else [heldout])
        val_recs = [plant_fmu_records(v, conn, channel) for v in vals]
        why = expressible(conn, plant.mass_parameter)
        if candidates is None:
            names = [c for c in FMU_EFFECTS if c not in why]
        else:
            names = list(candidates)
            for c in names:
                if c in why:
                    raise ValueError(f"candidate {c!r} cannot run through {plant.name}: "
                                     f"{why[c]}")
        if fit_plant is None:
            fit_plant = {p.name: (p.lower, p.upper, p.log) for p in conn.identify}
        rep = diagnose_trajectory(fit_rec, plant, law, validation=val_recs or None,
                                  candidates=names, engine="fmu", progress=progress,
                                  fit_plant=fit_plant, **options)
    finally:
        plant.close()
    if candidates is None:
        skipped = dict(rep.get("skipped") or {})
        skipped.update({c: w for c, w in why.items() if c in FMU_EFFECTS})
        from .effects import EFFECT_NAMES
        for c in EFFECT_NAMES:
            if c not in FMU_EFFECTS:
                skipped.setdefault(c, "the FMU engine has no parameters for it")
        rep["skipped"] = skipped
    rep["plant_fmu"] = os.path.basename(os.fspath(plant_fmu))
    rep["connection"] = conn.source
    rep["law_fmu"] = "native" if native else "pythonfmu"
    return rep
