"""The inertia candidate's coupled part (:func:`diagnosis.effects_inertia.coupled_part`) against
a fine reference integration and its analytic limits, and the candidate's fit of a part
whose coupling slips."""
import numpy as np
import pytest
from scipy.integrate import solve_ivp

from diagnosis.effects_inertia import coupled_part


def _reference(t, v, tau, g_up, g_dn):
    """The part's acceleration from solve_ivp on the axis speed held over each sample."""
    def rhs(tt, y):
        k = min(int(np.searchsorted(t, tt, side="right")), t.size - 1)
        return [np.clip((v[k] - y[0]) / tau, -g_dn, g_up)]
    vp = [v[0]]
    y = v[0]
    for k in range(1, t.size):
        sol = solve_ivp(rhs, (t[k - 1], t[k]), [y], method="LSODA", rtol=1e-10, atol=1e-12,
                        max_step=(t[k] - t[k - 1]) / 20)
        y = sol.y[0, -1]
        vp.append(y)
    vp = np.asarray(vp)
    return np.concatenate([[0.0], np.diff(vp) / np.diff(t)])


def test_a_stiff_unslipping_coupling_is_a_rigid_mass():
    t = np.arange(4000) * 1e-3
    v = 0.1 * np.sin(2 * np.pi * 0.5 * t)
    a = 0.1 * 2 * np.pi * 0.5 * np.cos(2 * np.pi * 0.5 * t)
    ap = coupled_part(v, 1e-3, 1e-4, np.inf, np.inf)
    assert np.max(np.abs(ap[10:] - a[10:])) < 0.01 * np.max(np.abs(a))


def test_a_ramp_is_followed_at_its_acceleration_or_at_the_grip():
    t = np.arange(3000) * 1e-3
    v = 0.5 * t  # 0.5 m/s^2
    lag = coupled_part(v, 1e-3, 0.05, np.inf, np.inf)
    assert lag[0] == 0.0 and abs(lag[-1] - 0.5) < 1e-6  # settled after 60 time constants
    assert 0.0 < lag[20] < 0.5  # it lags while the coupling takes up the speed difference
    slip = coupled_part(v, 1e-3, 0.05, 0.2, np.inf)
    assert np.max(slip) <= 0.2 + 1e-12 and abs(slip[-1] - 0.2) < 1e-12


def test_a_one_way_coupling_never_brakes_the_part():
    t = np.arange(4000) * 1e-3
    v = 0.1 * np.sin(2 * np.pi * 1.0 * t)
    ap = coupled_part(v, 1e-3, 0.01, np.inf, 0.0)
    assert np.min(ap) >= 0.0 and np.max(ap) > 0.1


@pytest.mark.parametrize("tau, g_up, g_dn", [(0.02, np.inf, np.inf), (0.02, 0.3, 0.1),
                                             (0.3, 1.0, 0.0)])
def test_matches_a_fine_reference_integration(tau, g_up, g_dn):
    t = np.arange(400) * 5e-3
    v = 0.2 * np.sin(2 * np.pi * 0.8 * t) + 0.05 * np.sin(2 * np.pi * 3.1 * t)
    ours = coupled_part(v, 5e-3, tau, g_up, g_dn)
    ref = _reference(t, v, tau, g_up, g_dn)
    np.testing.assert_allclose(ours[1:], ref[1:], atol=2e-3 * np.max(np.abs(ref)))


def test_any_step_is_stable():
    t = np.arange(200) * 0.5  # steps 1000 x the coupling's time constant
    v = np.sin(0.3 * t)
    ap = coupled_part(v, 0.5, 5e-4, np.inf, np.inf)
    assert np.all(np.isfinite(ap))
    np.testing.assert_allclose(ap[1:], np.diff(v) / 0.5, rtol=1e-9, atol=1e-12)


@pytest.mark.parametrize("kw, name", [({"tau": 0.0}, "tau"), ({"dt": -1.0}, "dt"),
                                      ({"g_up": -1.0}, "g_up"), ({"g_dn": np.nan}, "g_dn")])
def test_bad_parameters_are_refused_by_name(kw, name):
    args = {"dt": 1e-3, "tau": 0.01, "g_up": 1.0, "g_dn": 1.0, **kw}
    with pytest.raises(ValueError, match=f"^{name} = "):
        coupled_part(np.zeros(10), **args)


def test_a_velocity_that_is_not_a_number_is_refused_at_its_sample():
    v = np.zeros(10)
    v[4] = np.nan
    with pytest.raises(ValueError, match=r"^v\[4\] = nan is not finite"):
        coupled_part(v, 1e-3, 0.01, 1.0, 1.0)


def test_the_candidate_fits_a_payload_that_slips():
    """A payload held by its friction up to 0.3 of the top acceleration: the candidate's
    start finds the part, and its form leaves far less of the force than a rigid mass."""
    from friction.dataset import Dataset
    from diagnosis.candidates import Fixed
    from diagnosis.effects import CANDIDATES, make_context
    dt = 1e-3
    t = np.arange(6000) * dt
    v = 0.05 * np.sin(2 * np.pi * 0.7 * t) + 0.02 * np.sin(2 * np.pi * 2.3 * t)
    a = np.gradient(v, dt)
    sa = np.percentile(np.abs(a), 99)
    # the truth on a grid ten times finer than the data, linear between samples
    tf = np.arange(60000) * dt / 10
    vf = np.interp(tf, t, v)
    apf = coupled_part(vf, dt / 10, dt, 0.3 * sa, 0.3 * sa)
    part = 2.0 * apf.reshape(-1, 10).mean(axis=1)
    rng = np.random.default_rng(3)
    F = part + 0.01 * np.std(part) * rng.standard_normal(t.size)
    data = Dataset(t=t, x=np.cumsum(v) * dt, v=v, a=a, F=F)
    ctx = make_context(data)
    inertia = CANDIDATES["inertia"]
    p, rigid_start = inertia.start(data, np.zeros_like(F), F, ctx)
    assert rigid_start["m_p"] == 0.0 and isinstance(rigid_start["m_p"], Fixed)
    assert p["m_p"] > 0 and 0.1 * sa < min(p["g_up"], p["g_dn"]) < 0.7 * sa
    assert "dm" not in p  # the rigid mass starts at its x0
    left = F - inertia.apply(np.zeros_like(F), {"dm": 0.0, **p}, data, ctx)
    rigid = np.linalg.lstsq(a[:, None], F, rcond=None)[1][0]
    assert left @ left < 0.2 * rigid


def _lugre_with_mass(n, seed):
    """A LuGre law and a record of its force plus a 0.2 kg mass error, 1 % noise (n samples
    at 1 kHz)."""
    from friction import make_model
    from friction.dataset import Dataset
    dt = 1e-3
    t = np.arange(n) * dt
    v = 0.02 * np.sin(2 * np.pi * 0.8 * t) + 0.004 * np.sin(2 * np.pi * 3.3 * t)
    a = np.gradient(v, dt)
    law = make_model("lugre", sigma0=1e5, sigma1=300.0, sigma2=5.0, Fc=1.0, Fs=1.5,
                     vs=2e-3)
    F = law.simulate(t, v) + 0.2 * a
    F = F + 0.01 * np.std(F) * np.random.default_rng(seed).standard_normal(t.size)
    return law, Dataset.from_arrays(t, F, x=np.cumsum(v) * dt, v=v, a=a, check_units=False)


def test_parts_a_start_pins_do_not_move_the_joint_fit():
    """A joint fit with extras a data start pinned (the coupled part off) ends where the
    fit without those extras ends, to the last bit: pinned columns stay out of the solved
    vector (in scipy's trust region their zero columns still shaped the steps)."""
    from diagnosis.candidates import Candidate, Extra, Fixed
    from diagnosis.composite import fit_composite
    from diagnosis.effects import make_context

    class Mass(Candidate):
        def force_extras(self, ctx):
            return [Extra("dm", 0.0, -1.0, 1.0, "kg")]

        def apply(self, F, p, data, ctx):
            return F + p["dm"] * data.a

    class MassAndDeadPart(Mass):
        def force_extras(self, ctx):
            return super().force_extras(ctx) + [Extra("m_x", 0.0, 0.0, 1.0, "kg"),
                                                Extra("tau_x", 1e-3, 1e-4, 1.0, "s")]

        def start(self, fit, Ff, r, ctx, basis=None):
            return {"m_x": Fixed(0.0), "tau_x": Fixed(1e-3)}

    law, data = _lugre_with_mass(5000, seed=4)
    ctx = make_context(data)
    start = law.with_values(Fc=1.3, Fs=1.2, sigma2=2.0)
    names = ["Fc", "Fs", "sigma2"]
    plain, nr0 = fit_composite(start, names, [Mass("m", "")], data, ctx)
    pinned, nr1 = fit_composite(start, names, [MassAndDeadPart("m", "")], data, ctx)
    assert nr1 == nr0
    assert pinned.extras["dm"] == plain.extras["dm"]
    assert pinned.extras["m_x"] == 0.0 and pinned.extras["tau_x"] == 1e-3
    assert abs(plain.extras["dm"] - 0.2) < 0.02


def test_the_joint_fit_keeps_the_best_of_alternative_starts():
    """A start hook that returns a list offers alternative starts: the joint fit runs from
    each and keeps the best on the fit record, whichever comes first."""
    from diagnosis.candidates import Candidate, Extra, Fixed
    from diagnosis.composite import fit_composite
    from diagnosis.effects import make_context

    class Mass(Candidate):
        order = 0

        def force_extras(self, ctx):
            return [Extra("dm", 0.0, -1.0, 1.0, "kg")]

        def apply(self, F, p, data, ctx):
            return F + p["dm"] * data.a

        def start(self, fit, Ff, r, ctx, basis=None):
            alts = [{"dm": Fixed(0.0)}, {"dm": 0.1}]  # the first pins the mass off
            return alts[::-1] if self.order else alts

    law, data = _lugre_with_mass(4000, seed=5)
    ctx = make_context(data)
    fits = []
    for order in (0, 1):
        cand = Mass("m", "")
        cand.order = order
        fits.append(fit_composite(law, ["Fc"], [cand], data, ctx))
    for comp, nr in fits:
        assert abs(comp.extras["dm"] - 0.2) < 0.01
    assert fits[0][1] == fits[1][1]
    # the pinned alternative alone ends far worse

    class MassOff(Mass):
        def start(self, fit, Ff, r, ctx, basis=None):
            return {"dm": Fixed(0.0)}
    off, nr_off = fit_composite(law, ["Fc"], [MassOff("m", "")], data, ctx)
    assert off.extras["dm"] == 0.0 and nr_off > 1.5 * fits[0][1]


def _mass_record(m_of, seed=6):
    """A record whose force is only a mass term m(x, v) a (1 % noise, 1 kHz, 6 s)."""
    from friction.dataset import Dataset
    dt = 1e-3
    t = np.arange(6000) * dt
    v = 0.05 * np.sin(2 * np.pi * 0.7 * t) + 0.02 * np.sin(2 * np.pi * 2.3 * t)
    x = np.concatenate([[0.0], np.cumsum(0.5 * (v[1:] + v[:-1])) * dt])
    a = np.gradient(v, dt)
    F = m_of(x, v) * a
    F = F + 0.01 * np.std(F) * np.random.default_rng(seed).standard_normal(t.size)
    return Dataset(t=t, x=x, v=v, a=a, F=F)


@pytest.mark.parametrize("kind", ["position", "speed"])
def test_the_start_keeps_a_mass_that_varies_along_the_stroke_or_with_the_speed(kind):
    """A mass growing along the stroke (a cable chain: 1 -> 2 kg) or with the squared speed
    (flyweights: 0.5 kg at rest, 3 kg at the top speed): the start keeps that variation,
    pins the others off, and the candidate's form leaves far less of the force than a
    rigid mass; the variation's mass comes out near the truth's."""
    from diagnosis.candidates import Fixed
    from diagnosis.effects import CANDIDATES, make_context
    if kind == "position":
        def m_of(x, v):
            return 1.0 + (x - x.min()) / np.ptp(x)
        name, other = "dm_x", "dm_v"
    else:
        def m_of(x, v):
            return 0.5 + 2.5 * (v / np.abs(v).max()) ** 2
        name, other = "dm_v", "dm_x"
    data = _mass_record(m_of)
    ctx = make_context(data)
    inertia = CANDIDATES["inertia"]
    p = inertia.start(data, np.zeros(len(data)), data.F, ctx)
    p = p[0] if isinstance(p, list) else p
    assert p[name] == 0.0 and not isinstance(p[name], Fixed)  # kept, started at 0
    assert isinstance(p[other], Fixed) and isinstance(p["dm_t"], Fixed)
    # the kept form, solved by least squares, leaves < 5 % of the rigid mass's residual
    a, var = inertia._columns(data, {"tau_af": 0.0}, ctx)
    A = np.column_stack([a, var[name]])
    c, res = np.linalg.lstsq(A, data.F, rcond=None)[:2]
    rigid = np.linalg.lstsq(a[:, None], data.F, rcond=None)[1][0]
    assert res[0] < 0.05 * rigid
    span = 1.0 if kind == "position" else 2.5 * (ctx.sv / np.abs(data.v).max()) ** 2
    assert abs(c[1] - span) < 0.1 * span
    # and apply() draws that form
    out = inertia.apply(np.zeros(len(data)), {"dm": c[0], name: c[1]}, data, ctx)
    np.testing.assert_allclose(out, A @ c, rtol=1e-12, atol=1e-12)


def test_a_rigid_mass_keeps_every_variation_off():
    """A constant 0.7 kg: no variation is kept (each would follow only the noise)."""
    from diagnosis.candidates import Fixed
    from diagnosis.effects import CANDIDATES, make_context
    data = _mass_record(lambda x, v: np.full_like(x, 0.7))
    ctx = make_context(data)
    p = CANDIDATES["inertia"].start(data, np.zeros(len(data)), data.F, ctx)
    p = p[0] if isinstance(p, list) else p
    assert all(isinstance(p[n], Fixed) and p[n] == 0.0 for n in ("dm_t", "dm_x", "dm_v"))
