"""Plant base and components: a mass-spring-friction test plant driven by a force.

Fast stepper vs the plant's reference ODE, the reference vs ``friction.reference.simulate_mass``,
convergence to a tighter run, the stepper contract, the components' constitutive lines.
"""
from dataclasses import dataclass

import numpy as np
import pytest

from friction import ParameterError, make_model
from friction.base import param
from friction.metrics import nrmse
from friction.reference import simulate_mass
from plants.base import Experiment, Plant, PlantParams
from plants.components import Damper, Mass, Spring


@dataclass(frozen=True)
class OscParams(PlantParams):
    m: float = param(0.5, "kg", "moving mass", lower=0, lower_open=True)
    c: float = param(2e3, "N/m", "spring stiffness", lower=0)
    preload: float = param(0.0, "m", "spring pre-deflection")
    F0: float = param(3.0, "N", "force amplitude", lower=0)
    f: float = param(5.0, "Hz", "force frequency", lower=0, lower_open=True)


class Oscillator(Plant):
    """Mass on a friction contact, spring to ground, driven by F0 sin(2 pi f t)."""
    name = "oscillator"
    Params = OscParams
    main_output = "x"
    data_rate = 2000.0
    default_experiment = Experiment(0.0, 0.4, 1 / 2000.0)
    state_names = ("x", "v")
    state_scale = (1e-4, 1e-3)
    output_names = ("x", "v")
    max_substep = 2.5e-5

    @classmethod
    def default_friction(cls):
        return make_model("lugre", sigma0=1e5, sigma1=300.0, sigma2=0.4, Fc=1.0, Fs=1.5, vs=1e-3)

    def drive(self, t):
        return self.params.F0 * np.sin(2 * np.pi * self.params.f * t)

    def initial_state(self):
        return np.zeros(2)

    def derivatives(self, t, s, d, F, u):
        p = self.params
        if "parts" not in self.cache:
            self.cache["parts"] = Spring(c=p.c, preload=p.preload), Mass(m=p.m)
        spring, body = self.cache["parts"]
        return np.array([s[1], body.acceleration(self.drive(t) + spring.reaction_on_b(s[0], s[1])
                                                 - F)])

    def contact(self, t, s, d, u):
        return s[0], s[1], None

    def output(self, t, s, d, F, u):
        return {"x": s[0], "v": s[1]}


@pytest.fixture(scope="module")
def osc():
    return Oscillator()


@pytest.fixture(scope="module")
def ref(osc):
    return osc.simulate(method="reference", rtol=1e-9)


def test_result_layout(osc, ref):
    assert ref.dtype.names == ("time", "x", "v", "F")
    t = Experiment(0.0, 0.4, 1 / 2000.0).times()
    np.testing.assert_allclose(ref["time"], t)


def test_reference_matches_simulate_mass(osc, ref):
    # same ODE through friction.reference with the spring folded into the drive
    law = osc.friction
    p = osc.params
    n = 161  # first 0.08 s: stick, break-away, sliding
    t, xr = ref["time"][:n], ref["x"][:n]
    # spring force uses x(t): feed the plant reference's x, then compare the whole state
    out = simulate_mass(law, p.m, t, lambda tq: osc.drive(tq) - p.c * np.interp(tq, t, xr),
                        rtol=1e-10)
    # the spring sees linearly interpolated samples of x here: O(dt^2) apart, not exact
    assert nrmse(xr, out["x"]) < 3e-4
    assert nrmse(ref["F"][:n], out["F"]) < 2e-3


def test_reference_no_spring_equals_simulate_mass():
    osc = Oscillator(c=0.0)
    r = osc.simulate(0.1, method="reference", rtol=1e-9)
    out = simulate_mass(osc.friction, osc.params.m, r["time"], osc.drive, rtol=1e-10)
    assert np.max(np.abs(r["x"] - out["x"])) < 1e-6 * np.ptp(out["x"])
    assert np.max(np.abs(r["F"] - out["F"])) < 1e-5 * np.ptp(out["F"])


def test_fast_matches_reference(osc, ref):
    fast = osc.simulate(method="fast")
    # the force sweeps through stick, break-away and sliding: position and force agree
    assert nrmse(ref["x"], fast["x"]) < 1e-4
    assert nrmse(ref["v"], fast["v"]) < 1e-3
    assert nrmse(ref["F"], fast["F"]) < 2e-3


def test_fast_converges_second_order(osc, ref):
    errs = [nrmse(ref["v"], osc.simulate(method="fast", substep=h)["v"])
            for h in (1e-4, 5e-5)]
    assert errs[1] < errs[0] / 3.0, errs  # Heun: ~4x per halving


def test_reference_converges_to_tighter_run(osc, ref):
    loose = osc.simulate(method="reference", rtol=1e-6)
    assert nrmse(ref["x"], loose["x"]) < 1e-4
    assert nrmse(ref["F"], loose["F"]) < 1e-3


def test_stick_holds_below_breakaway():
    # a constant force below Fc with no spring: the mass only deflects the bristles
    class Push(Oscillator):
        def drive(self, t):
            return 0.8  # N, below Fc = 1 N

    p = Push(c=0.0)
    r = p.simulate(0.3)
    law = p.friction
    # sticks within the bristle range (some plastic creep during the step), friction
    # balancing the push, as the reference integrator says
    assert 0.8 / law.params.sigma0 < r["x"][-1] < 2 * law.params.Fs / law.params.sigma0
    assert r["F"][-1] == pytest.approx(0.8, rel=1e-4)
    assert abs(r["v"][-1]) < 1e-7
    rr = p.simulate(0.3, method="reference")
    assert rr["x"][-1] == pytest.approx(r["x"][-1], rel=1e-3)


def test_stepper_contract(osc):
    st = osc.stepper()
    assert st.input_names == ()
    assert st.output_names == ("x", "v", "F")
    assert "m" in st.parameter_names
    h = 1 / 2000.0
    xs = []
    for k in range(200):
        st.do_step(k * h, h)
        xs.append(st.outputs()["x"])
    fast = osc.simulate(0.1)
    np.testing.assert_allclose(xs, fast["x"][1:201], rtol=0, atol=1e-12)
    st.reset()
    assert st.outputs()["x"] == 0.0 and st.time == 0.0
    with pytest.raises(KeyError, match="F_friction"):
        st.set_inputs({"F_friction": 1.0})
    with pytest.raises(ValueError, match="stepper is at time"):
        st.do_step(1.0, h)


def test_external_friction_mode_matches_internal_with_small_steps(osc):
    # co-simulation style: a separate friction law fed with the plant's velocity, force held
    ext = Oscillator(external_friction=True)
    st = ext.stepper()
    assert st.input_names == ("F_friction",)
    law = osc.friction
    from plants.base import FrictionStep
    fs = FrictionStep(law)
    z = law.initial_state()
    h = 2e-5
    v_prev, x_prev = 0.0, 0.0
    xs = []
    for k in range(int(0.1 / h)):
        o = st.outputs()
        if k > 0:
            z, _ = fs.advance(z, h, (x_prev, v_prev, 0.0, None), (o["x"], o["v"], 0.0, None))
        st.set_inputs({"F_friction": fs.force(z, o["x"], o["v"])})
        v_prev, x_prev = o["v"], o["x"]
        st.do_step(k * h, h)
        xs.append(st.outputs()["x"])
    ref = osc.simulate(0.1, method="reference")
    x_ext = np.interp(ref["time"], h * np.arange(1, len(xs) + 1), xs)
    assert nrmse(ref["x"][1:], x_ext[1:]) < 2e-3


def test_bad_input_names_the_problem():
    with pytest.raises(ParameterError, match="m = -1"):
        Oscillator(m=-1.0)
    with pytest.raises(TypeError, match="unknown experiment option"):
        Oscillator().simulate(bogus=1)
    with pytest.raises(ValueError, match="method must be"):
        Oscillator().simulate(method="rk4")
    with pytest.raises(ValueError, match="stop"):
        Oscillator().simulate(stop_time=-1.0)
    with pytest.raises(ValueError, match="reference integrator needs"):
        Oscillator(external_friction=True).simulate(method="reference")
    with pytest.raises(ValueError, match="do not pass a friction law"):
        Oscillator(make_model("lugre"), external_friction=True)


# -- components -----------------------------------------------------------------------------
def test_spring_preload_and_action_reaction():
    sp = Spring(c=1e3, preload=6e-3)
    f = sp.force(2e-3, 0.1)
    assert f == pytest.approx(8.0)            # c (S + 6 mm)
    # massless: the reactions on the bodies at both flanges balance
    assert sp.reaction_on_a(2e-3, 0.1) == -sp.reaction_on_b(2e-3, 0.1)
    assert sp.reaction_on_b(2e-3, 0.0) == pytest.approx(-8.0)  # pushes the body back


def test_damper_and_mass():
    assert Damper(d=5.0).force(0.0, 0.2) == pytest.approx(1.0)
    assert Mass(m=2.0, g=-9.81).acceleration(19.62) == pytest.approx(0.0)
    with pytest.raises(ParameterError, match="m = 0"):
        Mass(m=0.0)


# -- every registered machine ------------------------------------------------------------------
def _registered():
    from plants import PLANTS
    return sorted(PLANTS)


@pytest.mark.parametrize("name", _registered())
def test_every_registered_plant_converges_to_a_finer_run(name):
    # the fast path at its default substep against 4x finer substeps, on the main output,
    # over the first 200 output samples of the default experiment
    from plants import PLANTS
    plant = PLANTS[name]()
    exp = plant.default_experiment
    stop = min(exp.stop, exp.start + 200 * exp.step)
    coarse = plant.simulate(stop)
    fine = plant.simulate(stop, substep=plant.max_substep / 4)
    y = plant.main_output
    assert coarse.dtype.names[0] == "time" and y in coarse.dtype.names
    assert np.ptp(fine[y]) > 0
    assert nrmse(fine[y], coarse[y]) < 1e-3


def test_public_names_are_documented_and_exported():
    import importlib
    for mod in ("base", "stepper", "reference", "law_stepper", "interfaces", "components",
                "sources", "sensors", "controllers", "motor", "xml350", "experiments",
                "studies.xml350", "studies.demo"):
        m = importlib.import_module(f"plants.{mod}")
        assert m.__doc__ and len(m.__doc__) > 80, mod
        for name in m.__all__:
            obj = getattr(m, name)   # every exported name exists
            if callable(obj) and not isinstance(obj, dict):
                assert obj.__doc__, f"plants.{mod}.{name} has no docstring"


@pytest.mark.parametrize("package,module", [("friction", "friction.gms"),
                                            ("plants", "plants.valve")])
def test_a_broken_law_or_machine_module_fails_the_import(package, module):
    # the registries import every law and machine plainly: no warning, no silent gap
    import pathlib
    import subprocess
    import sys
    code = (
        "import importlib.abc, sys\n"
        "class Broken(importlib.abc.MetaPathFinder):\n"
        "    def find_spec(self, name, path, target=None):\n"
        f"        if name == {module!r}:\n"
        "            raise RuntimeError('broken on purpose')\n"
        "sys.meta_path.insert(0, Broken())\n"
        f"import {package}\n")
    run = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                         cwd=pathlib.Path(__file__).resolve().parents[1])
    assert run.returncode != 0
    assert "RuntimeError: broken on purpose" in run.stderr, run.stderr[-500:]
