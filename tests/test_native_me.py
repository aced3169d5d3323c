"""Model Exchange interface of the native FMUs against the reference integrators.

(a) Each law's ME interface, driven through fmpy's ``simulate_fmu`` (CVode), equals a
reference integration of the law's continuous-time equations (``derivatives``/``force`` in
Python, scipy Radau at tight tolerances). fmpy applies an input at the start of each output
interval and holds it, so the prescribed motion is made of plateaus whose boundaries fmpy
sees as input events (each boundary given twice); the reference integrates plateau by plateau.

(b) A mass and a law coupled through their ME interfaces by our ME master
(:class:`fmus.me_master.MEMaster`, one implicit solver for both FMUs' states) equals the
reference mass + friction integrator ``friction.reference.simulate_mass``.
"""
from __future__ import annotations

import numpy as np
import pytest
from scipy.integrate import solve_ivp

import friction
from friction.metrics import nrmse
from friction.reference import simulate_mass, simulate_prescribed
from fmus.me_master import MEMaster
from fmus.native.build import SUFFIX
from fmus.testing import built_native_fmus

LAWS = sorted(friction.MODELS)


@pytest.fixture(scope="module")
def ndir():
    return built_native_fmus()


def _plateaus(law, n_pl=40, P=0.01):
    rng = np.arange(n_pl)
    amp = {"mre_lugre": 0.05, "load_lugre": 3e-4}.get(law, 3e-3)
    return P, {"v": amp * np.sin(2 * np.pi * rng / n_pl * 2 + 0.3),
               "a": 5.0 * np.cos(rng), "load": 1e5 * (1 + 0.5 * np.sin(rng)),
               "x": 1e-3 * np.sin(0.7 * rng)}


@pytest.mark.parametrize("law", [pytest.param(n, marks=pytest.mark.slow) if n == "modified_lugre" else n
                                 for n in LAWS])  # modified_lugre's reference: 13 s
def test_me_interface_through_fmpy_cvode_equals_the_reference(ndir, law):
    from fmpy import simulate_fmu
    cls = friction.MODELS[law]
    model = cls()
    P, lev = _plateaus(law)
    n_pl = lev["v"].size
    T, dt = n_pl * P, 1e-3
    names = ["v"] + [n for n in ("a", "load", "x") if n in cls.extra_inputs]
    tb = np.arange(n_pl + 1) * P
    ti = np.concatenate([[0.0], np.repeat(tb[1:-1], 2), [T]])
    pi = np.concatenate([[0], np.repeat(np.arange(n_pl - 1), 2) + np.tile([0, 1], n_pl - 1),
                         [n_pl - 1]])
    inp = np.zeros(ti.size, dtype=[("time", float)] + [(n, float) for n in names])
    inp["time"] = ti
    for n in names:
        inp[n] = lev[n][pi]
    outs = ["F"] + list(cls.state_names)
    res = simulate_fmu(str(ndir / f"{law}{SUFFIX}.fmu"), fmi_type="ModelExchange", input=inp,
                       output=outs, stop_time=T, output_interval=dt,
                       relative_tolerance=1e-10)
    # events add rows (input events twice at a plateau boundary, state events at |v| = vc):
    # keep the grid rows, the last (post-event) one where several fall on one grid point
    rt = res["time"]
    grid = np.round(rt / dt)
    on_grid = np.abs(rt - grid * dt) < 1e-12
    last = np.concatenate([grid[1:] != grid[:-1], [True]])
    res = res[on_grid & last]
    t = np.round(np.arange(0.0, T + dt / 2, dt), 12)
    assert np.allclose(res["time"], t, rtol=0, atol=1e-12)
    idx = np.minimum((t / P + 1e-9).astype(int), n_pl - 1)
    s = model.initial_state()
    S, F = np.zeros((t.size, s.size)), np.zeros(t.size)
    for i in range(n_pl):
        kw = {n: lev[n][i] for n in names if n != "v"}
        v = lev["v"][i]
        ks = np.flatnonzero(idx == i)
        te = t[ks]
        t_end = max((i + 1) * P, te[-1])
        tev = np.concatenate([te, [t_end]]) if te[-1] < t_end else te
        if s.size:
            sol = solve_ivp(lambda tt, y: model.derivatives(y, v, **kw), (min(i * P, te[0]), t_end),
                            s, method="Radau", t_eval=tev, rtol=1e-12, atol=1e-16)
            Y = sol.y
            s = Y[:, -1]
        else:
            Y = np.zeros((0, tev.size))
        for j, k in enumerate(ks):
            S[k] = Y[:, j]
            F[k] = model.force(Y[:, j], v, **kw)
    assert nrmse(F, res["F"]) < 1e-6, nrmse(F, res["F"])
    for j, name in enumerate(cls.state_names):
        assert nrmse(S[:, j], res[name]) < 1e-6, (name, nrmse(S[:, j], res[name]))


def _mass_case(ndir, law, T):
    cls = friction.MODELS[law]
    m, amp, f = 1.0, (200.0 if law == "mre_lugre" else 2.0), 1.0
    conns = [("mass.v", "law.v")]
    if "x" in cls.extra_inputs:
        conns.append(("mass.x", "law.x"))
    conns.append(("law.F", "mass.F_friction"))
    if "a" in cls.extra_inputs:
        conns.append(("mass.a", "law.a"))
    t = np.linspace(0.0, T, int(round(T * 1000)) + 1)
    with MEMaster({"mass": ndir / f"mass{SUFFIX}.fmu", "law": ndir / f"{law}{SUFFIX}.fmu"},
                  conns, parameters={"mass": {"m": m, "u_amp": amp, "u_freq": f}}) as M:
        res = M.simulate(t, record=["mass.x", "mass.v", "law.F"], rtol=1e-9)
    ref = simulate_mass(cls(), m, t, lambda tt: amp * np.sin(2 * np.pi * f * tt))
    for key, r in (("mass.x", "x"), ("mass.v", "v"), ("law.F", "F")):
        assert nrmse(ref[r], res[key]) <= 1e-4, (law, key, nrmse(ref[r], res[key]))
    return res


def test_me_master_mass_and_lugre_equal_the_reference(ndir):
    res = _mass_case(ndir, "lugre", 1.0)
    assert np.ptp(res["mass.x"]) > 0.05  # it slid, reversed and stuck


@pytest.mark.slow
@pytest.mark.parametrize("law", ["modified_lugre", "mre_lugre"])
def test_me_master_mass_and_law_equal_the_reference(ndir, law):
    _mass_case(ndir, law, 2.0)


def test_me_master_follows_the_load_law_switch_as_events(ndir):
    """load_lugre driven across |v| = vc: the event indicator ends the solver's segments at
    the jump; the result equals the reference with the prescribed motion."""
    cls = friction.MODELS["load_lugre"]
    model = cls()
    vc = model.regimes().vc
    t = np.linspace(0.0, 0.4, 801)
    v = 3 * vc * np.sin(2 * np.pi * 5 * t)
    load = 3e4 * (1 + 0.3 * np.sin(2 * np.pi * 2 * t))  # Fc, Fs > 0 in both regimes
    with MEMaster({"law": ndir / f"load_lugre{SUFFIX}.fmu"}, [],
                  inputs={"law.v": lambda tt: np.interp(tt, t, v),
                          "law.load": lambda tt: np.interp(tt, t, load)}) as M:
        res = M.simulate(t, record=["law.F"], rtol=1e-10, max_step=float(t[1] - t[0]))
    ref = simulate_prescribed(model, t, v, load=load)
    assert nrmse(ref, res["law.F"]) < 1e-5, nrmse(ref, res["law.F"])


def test_me_instance_refuses_cs_calls_and_wrong_sizes(ndir):
    import fmpy
    from fmpy.fmi1 import FMICallException
    from fmpy.fmi2 import FMU2Model
    path = ndir / f"lugre{SUFFIX}.fmu"
    md = fmpy.read_model_description(str(path))
    d = fmpy.extract(str(path))
    fmu = FMU2Model(guid=md.guid, unzipDirectory=d, modelIdentifier=md.modelExchange.modelIdentifier,
                    instanceName="me")
    fmu.instantiate()
    fmu.setupExperiment(startTime=0.0)
    fmu.enterInitializationMode()
    fmu.exitInitializationMode()
    import ctypes
    x = (ctypes.c_double * 2)()
    with pytest.raises(FMICallException):
        fmu.getDerivatives(x, 2)   # one state, not two
    nan = (ctypes.c_double * 1)(float("nan"))
    with pytest.raises(FMICallException):
        fmu.setContinuousStates(nan, 1)
    fmu.terminate()
    fmu.freeInstance()


def test_me_master_refuses_bad_output_times_and_connections(ndir):
    path = ndir / f"lugre{SUFFIX}.fmu"
    with MEMaster({"law": path}, [], inputs={"law.v": lambda t: 1e-3}) as M:
        for bad, match in (([0.0, 0.2, 0.1], "strictly increasing"),
                           ([0.0, float("nan")], "finite"), ([0.0], "at least 2")):
            with pytest.raises(ValueError, match=match):
                M.simulate(bad)
    with pytest.raises(ValueError, match="not an input"):
        MEMaster({"mass": ndir / f"mass{SUFFIX}.fmu", "law": path}, [("law.F", "mass.x")])
    with pytest.raises(KeyError, match="no variable"):
        MEMaster({"law": path}, [], inputs={"law.nonsense": lambda t: 0.0})
