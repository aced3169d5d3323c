"""The ``drift`` and ``acceleration`` candidates' levels inside a classic LuGre's bristle
dynamics (:class:`diagnosis.effects_drift.DriftInside`,
:class:`diagnosis.effects_acceleration.AccelerationInside`), each fitted beside its output
form: which laws get them, that they are the output forms' levels, and that on a level
acting through the bristle (integrated by Radau, 8 x finer than sampled) the inside form is
kept and forecasts the held-out part where the output form cannot; on a level of the
output the output form is kept."""
import numpy as np
import pytest
from scipy.integrate import solve_ivp

from diagnosis.candidates import Fixed, law_variants, make_context
from diagnosis.composite import fit_composite
from diagnosis.effects import CANDIDATES
from diagnosis.effects_acceleration import Acceleration, AccelerationInside
from diagnosis.effects_drift import Drift, DriftInside
from friction import make_model
from friction.dataset import Dataset

NAMES = ["sigma0", "sigma1", "sigma2", "Fc", "Fs", "vs"]


def _law():
    return make_model("lugre", sigma0=1e5, sigma1=300.0, sigma2=40.0, Fc=10.0, Fs=15.0,
                      vs=5e-3)


def _motion(n, T=4.0):
    """Reversals every 0.1 s over +-0.4 mm (a few presliding distances) on a slower sweep
    of +-1 mm: the presliding carries much of the record."""
    t = np.linspace(0.0, T, n)
    v = (2 * np.pi * 5 * 4e-4 * np.sin(2 * np.pi * 5 * t)
         + 2 * np.pi * 1.3 * 1e-3 * np.sin(2 * np.pi * 1.3 * t))
    return t, v


def _warm_up(t, T=4.0):
    # the levels rise by half, levelling off with a time constant of a third of the record
    return 1.0 + 0.5 * (1.0 - np.exp(-t / (T / 3.0)))


def _radau(law, t, v, lev):
    """The bristle with its levels times ``lev`` by Radau on the continuous problem (v and
    the level interpolated linearly): another integrator than the candidate's."""
    p = law.params

    def rhs(s, z):
        vv = np.interp(s, t, v)
        return [vv - p.sigma0 * abs(vv) / (np.interp(s, t, lev) * float(law.g(vv))) * z[0]]
    sol = solve_ivp(rhs, (t[0], t[-1]), [0.0], method="Radau", t_eval=t, rtol=1e-8,
                    atol=1e-12, max_step=2 * (t[1] - t[0]))
    z = sol.y[0]
    zd = np.array([rhs(s, [zz])[0] for s, zz in zip(t, z)])
    return p.sigma0 * z + p.sigma1 * zd + lev * p.sigma2 * v


def _acceleration(t):
    w1, w2 = 2 * np.pi * 5, 2 * np.pi * 1.3
    return w1 * w1 * 4e-4 * np.cos(w1 * t) + w2 * w2 * 1e-3 * np.cos(w2 * t)


def _load_transfer(t):
    # the levels up to 40 % above and below the base's with the signed acceleration (a
    # pitching carriage moving its load between supports of other friction)
    a = _acceleration(t)
    return 1.0 + 0.4 * a / np.max(np.abs(a))


def _record(inside, step=8, n_fine=8001, noise=0.005, level=_warm_up):
    law = _law()
    tf, vf = _motion(n_fine)
    lev = level(tf)
    Ff = _radau(law, tf, vf, lev) if inside else law.simulate(tf, vf) * lev
    rng = np.random.default_rng(4)
    F = Ff[::step] + noise * np.std(Ff) * rng.standard_normal(Ff[::step].size)
    return law, Dataset.from_arrays(tf[::step], F, v=vf[::step], a=_acceleration(tf)[::step])


@pytest.mark.parametrize("name,out,ins", [("drift", Drift, DriftInside),
                                          ("acceleration", Acceleration, AccelerationInside)])
def test_the_inside_form_is_offered_on_a_classic_lugre_only(name, out, ins):
    law = _law()
    ctx = make_context(_record(False, n_fine=801)[1])
    forms = [f for _, _, f in law_variants(CANDIDATES[name], law, NAMES, ctx)]
    assert [type(f) for f in forms] == [out, ins]
    assert all(f.name == name for f in forms)
    gms = make_model("gms")
    forms = [f for _, _, f in law_variants(CANDIDATES[name], gms, ["Fc"], ctx)]
    assert [type(f) for f in forms] == [out]


def test_the_inside_level_is_the_output_forms_level_and_leaves_the_output_alone():
    law, data = _record(False, n_fine=801)
    ctx = make_context(data)
    out, ins = Drift("drift", ""), DriftInside("drift", "")
    p = {e.name: e.x0 for e in out.force_extras(ctx)}
    p.update(k_sat=0.4, k_drift=-0.2, k_step=0.1)
    F = np.linspace(-3.0, 5.0, data.t.size)
    np.testing.assert_allclose(out.apply(F, p, data, ctx), F * out.level(p, data, ctx))
    np.testing.assert_allclose(ins.inside(p, data, ctx), out.level(p, data, ctx))
    assert np.array_equal(ins.apply(F, p, data, ctx), F)
    # a level that would reverse the friction is held at 5 % inside the bristle
    p.update(k_drift=-2.0, k_sat=-2.0)
    assert ins.inside(p, data, ctx).min() == pytest.approx(0.05)


def _fits(inside, name="drift", level=_warm_up):
    law, data = _record(inside, level=level)
    fit, held = data.split(0.7)
    ctx = make_context(fit)

    def held_nrmse(comp):
        return np.sqrt(np.mean((comp.predict(held) - held.F) ** 2)) / np.std(held.F)
    base, _ = fit_composite(law, NAMES, [], fit, ctx)
    out = {}
    for lv, nv, form in law_variants(CANDIDATES[name].specialise(law), law, NAMES, ctx):
        comp, cost = fit_composite(lv, nv, [form], fit, ctx)
        out[type(form).__name__] = (cost, held_nrmse(comp))
    return held_nrmse(base), out


def test_a_warm_up_through_the_bristle_is_kept_inside_and_forecast():
    base, fits = _fits(inside=True)
    (c_out, h_out), (c_in, h_in) = fits["Drift"], fits["DriftInside"]
    assert c_in < 0.5 * c_out, fits          # the better fit: the form the diagnosis keeps
    assert h_in < 0.3 * h_out, (base, fits)  # and it forecasts the held-out warm-up
    assert h_in < 0.2 * base, (base, fits)


def test_a_warm_up_on_the_output_keeps_the_output_form():
    base, fits = _fits(inside=False)
    (c_out, h_out), (c_in, _) = fits["Drift"], fits["DriftInside"]
    assert c_out < 0.5 * c_in, fits         # kept: the better fit by far
    assert h_out < 0.7 * base, (base, fits)


def test_the_acceleration_level_inside_is_the_output_forms_and_its_start_frees_it():
    law, data = _record(True, n_fine=801, level=_load_transfer)
    ctx = make_context(data)
    out, ins = Acceleration("acceleration", ""), AccelerationInside("acceleration", "")
    p = {e.name: e.x0 for e in out.force_extras(ctx)}
    p.update(f_a=2.0, f_e=0.3, f_o=-0.2)
    F = np.linspace(-3.0, 5.0, data.t.size)
    np.testing.assert_allclose(out.apply(F, p, data, ctx),
                               F * out.level(p, data) + out.additive(p, data))
    np.testing.assert_allclose(ins.inside(p, data, ctx), np.clip(out.level(p, data), 0.05, None))
    np.testing.assert_allclose(ins.apply(F, p, data, ctx), F + out.additive(p, data))
    # the output form's start pins a level part the output residual does not ask for; the
    # inside form's start leaves both free (they act through the bristle)
    base = law.simulate(data.t, data.v)
    r = 0.01 * np.std(base) * np.random.default_rng(5).standard_normal(base.size)
    assert isinstance(out.start(data, base, r, ctx)["f_e"], Fixed)
    started = ins.start(data, base, r, ctx)
    assert not isinstance(started["f_e"], Fixed) and not isinstance(started["f_o"], Fixed)


def test_a_load_transfer_through_the_bristle_is_kept_inside_and_forecast():
    base, fits = _fits(True, "acceleration", _load_transfer)
    (c_out, h_out), (c_in, h_in) = fits["Acceleration"], fits["AccelerationInside"]
    assert c_in < 0.2 * c_out, fits
    assert h_in < 0.3 * h_out and h_in < 0.1 * base, (base, fits)


def test_a_load_transfer_on_the_output_keeps_the_output_form():
    base, fits = _fits(False, "acceleration", _load_transfer)
    (c_out, h_out), (c_in, _) = fits["Acceleration"], fits["AccelerationInside"]
    assert c_out < 0.2 * c_in, fits
    assert h_out < 0.5 * base, (base, fits)
