"""Proofs that the FMU co-simulation reproduces the reference integrator.

Mass + friction loop (available for every law): the ``mass`` FMU (m dv/dt = u(t) - F)
coupled with a friction-law FMU, against :func:`friction.reference.simulate_mass` (the
monolithic ``solve_ivp`` ODE of mass and law states). Plants: see :mod:`fmus.plant_fmus`.

The co-simulation error is dominated by the zero-order hold of the coupling signals over a
communication step, so it shrinks about linearly with the step; :func:`observed_order`
reports the slope of log(error) over log(step).
"""
from __future__ import annotations

import math

import numpy as np

__all__ = ["MASS_SCENARIOS", "mass_scenario", "mass_connections", "mass_cosim",
           "mass_reference", "mass_loop_plant", "mass_proof", "observed_order"]

#: per-law mass loop: mass [kg], drive u0 + u_amp sin(2 pi u_freq t) [N, Hz], initial
#: velocity [m/s], constant load [N] (load-dependent laws), horizon [s]; chosen so that the
#: loop sticks and slips (LuGre family) and the explicit coupling is far from its stability
#: limit (sqrt(sigma0/m) h << 1).
MASS_SCENARIOS = {
    "lugre": dict(m=1.0, u0=0.0, u_amp=2.0, u_freq=1.0, v0=0.0, stop=1.0),
    "stribeck": dict(m=1.0, u0=3.0, u_amp=1.0, u_freq=1.0, v0=0.05, stop=1.0),
    "modified_lugre": dict(m=1.0, u0=0.0, u_amp=12.0, u_freq=1.0, v0=0.0, stop=1.0),
    # under load the coefficients jump at vc (two regimes, seed 004 Table 3): the mass
    # slides along |v| = vc for a while (Filippov; mass_reference uses the plants' hybrid
    # reference)
    "load_lugre": dict(m=1e5, u0=0.0, u_amp=8e5, u_freq=0.5, v0=0.0, load=500.0, stop=1.0),
    # the isolator's spring k0 x sits inside the law FMU, so the mass-spring loop itself is
    # coupled through the one-step hold: it needs a finer step than the others for 1e-3
    "mre_lugre": dict(m=100.0, u0=0.0, u_amp=200.0, u_freq=2.0, v0=0.0, stop=1.0, step=5e-5),
}


def mass_scenario(law: str) -> dict:
    """The scenario of ``law``; a new law gets a lugre-like one scaled to its force level.

    Parameters
    ----------
    law : str
        Registry name of the law.
    """
    if law in MASS_SCENARIOS:
        return dict(MASS_SCENARIOS[law])
    import friction
    model = friction.make_model(law)
    level = float(np.max(np.abs(model.steady_state(np.array([1e-2, -1e-2])))))
    return dict(m=1.0, u0=0.0, u_amp=2.0 * max(level, 1e-6), u_freq=1.0, v0=0.0, stop=1.0)


def mass_connections(law: str) -> list[tuple[str, str]]:
    """Connections mass <-> friction law (the law's extra kinematic inputs included).

    Parameters
    ----------
    law : str
        Registry name of the law.
    """
    import friction
    cls = friction.MODELS[law]
    conns = [("mass.v", "friction.v"), ("friction.F", "mass.F_friction")]
    if "a" in cls.extra_inputs:
        conns.append(("mass.a", "friction.a"))
    if "x" in cls.extra_inputs:
        conns.append(("mass.x", "friction.x"))
    return conns


def mass_cosim(fmu_dir, law: str, *, step: float, stop: float | None = None,
               algorithm: str = "gauss-seidel", scenario: dict | None = None,
               master=None, iterations: int = 0, native: bool = False) -> np.ndarray:
    """Co-simulate ``mass.fmu`` + ``<law>.fmu`` from ``fmu_dir``; returns the result array.

    Pass an open ``master`` (from :func:`mass_master`) to reuse loaded FMUs across runs.

    Parameters
    ----------
    fmu_dir : str or path
        Folder of built FMUs.
    law : str
        Registry name of the law.
    step : float
        Communication step [s].
    stop : float, optional
        End of the run [s] (default: the scenario's).
    algorithm : {"gauss-seidel", "jacobi"}
        Master algorithm.
    scenario : dict, optional
        The loop's scenario (default :func:`mass_scenario`).
    master : Master, optional
        An open master of the loop to reuse.
    iterations : int
        Fixed-point iterations per step.
    native : bool
        Use the native C law FMU.
    """
    sc = scenario or mass_scenario(law)
    stop = sc["stop"] if stop is None else stop
    if master is not None:
        return master.simulate(stop_time=stop, step_size=step)
    with mass_master(fmu_dir, law, algorithm=algorithm, scenario=sc,
                     iterations=iterations, native=native) as m:
        return m.simulate(stop_time=stop, step_size=step)


def mass_master(fmu_dir, law: str, *, algorithm: str = "gauss-seidel",
                scenario: dict | None = None, iterations: int = 0, native: bool = False):
    """An open :class:`fmus.master.Master` of the mass + ``law`` loop (``native``: the
    native C FMUs ``mass_native.fmu`` and ``<law>_native.fmu`` of ``fmu_dir``)."""
    from .master import Master, fmu_file
    sc = scenario or mass_scenario(law)
    fmus = {"mass": fmu_file(fmu_dir, "mass", native),
            "friction": fmu_file(fmu_dir, law, native)}
    params = {"mass": {"m": sc["m"], "u0": sc["u0"], "u_amp": sc["u_amp"],
                       "u_freq": sc["u_freq"], "v0": sc["v0"]}}
    start = {"friction": {"load": sc["load"]}} if "load" in sc else {}
    return Master(fmus, mass_connections(law), algorithm=algorithm, parameters=params,
                  start_values=start, iterations=iterations,
                  record=["mass.x", "mass.v", "friction.F"])


def mass_reference(law: str, t, scenario: dict | None = None, rtol: float = 1e-10) -> dict:
    """Monolithic reference of the same loop (:func:`friction.reference.simulate_mass`).

    A law whose coefficients jump at |v| = vc (``friction.reference.regime_split``) goes
    through the plants' hybrid reference instead (:func:`mass_loop_plant`: regime held per
    segment, crossings located, Filippov sliding along |v| = vc); ``t`` must then be the
    uniform grid ``0, h, 2h, ...``. Returns a dict with ``x``, ``v``, ``F``.

    Parameters
    ----------
    law : str
        Registry name of the law.
    t : array_like
        Output instants [s].
    scenario : dict, optional
        The loop's scenario (default :func:`mass_scenario`).
    rtol : float
        Relative tolerance of the reference integrator.
    """
    import friction
    from friction.reference import regime_split, simulate_mass
    sc = scenario or mass_scenario(law)
    model = friction.make_model(law)
    if regime_split(model) is not None:
        t = np.asarray(t, float)
        h = float(t[1] - t[0]) if t.size > 1 else 0.0
        if t[0] != 0.0 or not h > 0 or np.max(np.abs(np.diff(t) - h)) > 1e-9 * h:
            raise ValueError(f"mass_reference({law!r}): t must be the uniform grid 0, h, 2h, "
                             "... (the hybrid reference samples at its data rate)")
        res = mass_loop_plant(sc, h)(friction=model).simulate(
            float(t[-1]), method="reference", rtol=rtol)
        return {"t": np.asarray(res["time"]), "x": np.asarray(res["x"]),
                "v": np.asarray(res["v"]), "F": np.asarray(res["F"])}
    w = 2.0 * math.pi * sc["u_freq"]
    load = (lambda tq: sc["load"]) if "load" in sc else None
    return simulate_mass(model, sc["m"], t,
                         lambda tq: sc["u0"] + sc["u_amp"] * math.sin(w * tq),
                         v0=sc["v0"], load=load, rtol=rtol)


def mass_loop_plant(scenario: dict, step: float):
    """The mass + friction loop of ``scenario`` as a :class:`plants.base.Plant` class
    (states ``x, v``; output interval ``step`` [s]), for the plants' reference integrator.

    Parameters
    ----------
    scenario : dict
        The loop's scenario (mass, force amplitude and frequency, law).
    step : float
        Output interval [s].
    """
    from plants.base import Experiment, Plant, PlantParams
    sc = dict(scenario)
    w = 2.0 * math.pi * sc["u_freq"]

    class MassLoop(Plant):
        """Rigid mass m dv/dt = u0 + u_amp sin(2 pi u_freq t) - F at a constant load."""
        name = "mass_loop"
        Params = PlantParams
        main_output = "x"
        data_rate = 1.0 / step
        default_experiment = Experiment(0.0, float(sc["stop"]), step)
        state_names = ("x", "v")
        state_scale = (1e-3, 1e-3)
        output_names = ("x", "v")

        def initial_state(self):
            return np.array([0.0, float(sc["v0"])])

        def derivatives(self, t, s, d, F, u):
            return np.array([s[1], (sc["u0"] + sc["u_amp"] * math.sin(w * t) - F) / sc["m"]])

        def contact(self, t, s, d, u):
            return float(s[0]), float(s[1]), sc.get("load")

        def output(self, t, s, d, F, u):
            return {"x": float(s[0]), "v": float(s[1])}

    return MassLoop


def observed_order(steps, errors) -> float:
    """Least-squares slope of log(error) against log(step) (1: first order).

    Parameters
    ----------
    steps : array_like
        Communication steps [s].
    errors : array_like
        The errors at those steps.
    """
    return float(np.polyfit(np.log(np.asarray(steps, float)),
                            np.log(np.asarray(errors, float)), 1)[0])


def mass_proof(fmu_dir, law: str, *, step: float | None = None, refinements: int = 3,
               stop: float | None = None, rtol: float = 1e-10,
               algorithm: str = "gauss-seidel") -> dict:
    """NRMSE of the co-simulated position against the reference, and its observed order.

    ``step`` defaults to the scenario's (1e-4 s unless it says otherwise). Runs the
    co-simulation at ``step * 2**k`` for k = refinements-1 ... 0 and compares each
    with the reference sampled at the same instants.

    Parameters
    ----------
    fmu_dir, law
        As for :func:`mass_cosim`.
    step : float, optional
        Finest communication step [s].
    refinements : int
        Number of steps ``step * 2**k`` run.
    stop : float, optional
        End of the run [s] (default: the scenario's).
    rtol : float
        Relative tolerance of the reference.
    algorithm : {"gauss-seidel", "jacobi"}
        Master algorithm.

    Returns
    -------
    dict
        ``nrmse`` (at ``step``), ``steps``, ``errors``, ``order``.
    """
    from friction.metrics import nrmse
    sc = mass_scenario(law)
    stop = sc["stop"] if stop is None else stop
    step = sc.get("step", 1e-4) if step is None else step
    n = int(round(stop / step))
    t = step * np.arange(n + 1)
    ref = mass_reference(law, t, sc, rtol=rtol)
    steps, errors = [], []
    with mass_master(fmu_dir, law, algorithm=algorithm, scenario=sc) as m:
        for k in reversed(range(refinements)):
            h = step * 2 ** k
            res = m.simulate(stop_time=n * step, step_size=h)
            errors.append(nrmse(ref["x"][:: 2 ** k], res["mass.x"]))
            steps.append(h)
    return {"nrmse": errors[-1], "steps": steps, "errors": errors,
            "order": observed_order(steps, errors) if refinements > 1 else float("nan")}
