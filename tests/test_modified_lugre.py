"""Modified LuGre of seed 000: Gamma switch, acceleration part F_d, stability, reference."""
import numpy as np
import pytest

from friction import ParameterError, make_model
from friction.numerics import euler_critical_velocity
from friction.reference import simulate_mass, simulate_prescribed

H = 5e-5  # seed 000 sampling interval (20 kHz)
ASYM = dict(Fc_neg=5.0, Fs_neg=5.8, vs_neg=8e-3, sigma2_neg=25.0, f_a_neg=1.5, a_s_neg=30.0,
            v_c_neg=0.08, b=0.1)


@pytest.mark.parametrize("gamma_form", ["logistic", "cosine"])
@pytest.mark.parametrize("fd_form", ["lag", "filtered_acceleration"])
def test_constant_velocity_reaches_eq5(gamma_form, fd_form):
    m = make_model("modified_lugre", gamma_form=gamma_form, fd_form=fd_form, **ASYM)
    for vc in (-0.12, -0.02, -1e-3, 1e-3, 0.02, 0.12):
        G = float(m.gamma_switch(vc))
        # 40 time constants of the bristle (g / (Gamma sigma0 |v|)) and of the lag
        T = 40 * max(6.5 / (G * m.params.sigma0 * abs(vc)), m.params.tau)
        t = np.linspace(0, T, 4000)
        q0 = 1.0 if fd_form == "lag" else 10.0  # start off equilibrium: F_d != 0
        F = m.simulate(t, np.full(t.size, vc), a=np.zeros(t.size), state0=[0.0, q0])
        Fss = m.steady_state(np.array([vc]))[0]
        assert abs(F[-1] - Fss) <= 1e-9 * abs(Fss), (vc, F[-1], Fss)
        # derived acceleration of a constant speed is zero too
        F2 = m.simulate(t, np.full(t.size, vc))
        assert abs(F2[-1] - Fss) <= 1e-9 * abs(Fss)


def test_steady_state_is_eq5_written_out():
    m = make_model("modified_lugre", **ASYM)
    p = m.params
    for vc in (-0.3, -4e-3, 4e-3, 0.3):
        d = "_neg" if vc < 0 else ""
        Fc, Fs, vs, s2 = (getattr(p, n + d) for n in ("Fc", "Fs", "vs", "sigma2"))
        g = Fc + (Fs - Fc) * np.exp(-(abs(vc) / vs) ** p.alpha)
        assert m.steady_state([vc])[0] == pytest.approx(g * np.sign(vc) + s2 * vc + p.b,
                                                        rel=1e-13)


@pytest.mark.parametrize("gamma_form", ["logistic", "cosine"])
def test_switch_properties(gamma_form):
    m = make_model("modified_lugre", gamma_form=gamma_form, v1=0.05, v2=0.15)
    for s in (1.0, -1.0):
        assert m.gamma_switch(s * 0.05) >= 0.99
        assert m.gamma_switch(s * 0.15) <= 0.01 + 1e-15  # = 0.01 up to rounding
        assert m.gamma_switch(s * 0.01) >= 0.99
        assert m.gamma_switch(s * 0.5) <= 0.01
    v = np.linspace(0, 0.4, 4001)
    G = m.gamma_switch(v)
    assert np.all(np.diff(G) <= 1e-15) and np.all((G >= 0) & (G <= 1))
    np.testing.assert_array_equal(G, m.gamma_switch(-v))
    assert np.max(np.abs(np.diff(G))) < 0.01  # continuous (no jump on a fine grid)
    if gamma_form == "logistic":
        assert m.gamma_switch(0.05) == pytest.approx(0.99, rel=1e-12)
        assert m.gamma_switch(0.15) == pytest.approx(0.01, rel=1e-10)
    else:
        assert m.gamma_switch(0.05) == 1.0 and m.gamma_switch(0.15) == 0.0


def test_acceleration_part_properties():
    m = make_model("modified_lugre", **ASYM)
    v = np.r_[-np.geomspace(1e-4, 1.0, 40)[::-1], np.geomspace(1e-4, 1.0, 40)]
    np.testing.assert_array_equal(m.fd_steady(v, np.zeros_like(v)), 0.0)
    a = np.geomspace(1e-2, 1e3, 60)
    below = a[1:] < 100.0  # strictly increasing until 1 - exp(-|a|/a_s) rounds to 1
    for vk in v:
        Fp = m.fd_steady(np.full(a.size, vk), a)
        Fm = m.fd_steady(np.full(a.size, vk), -a)
        assert np.all(Fp > 0) and np.all(Fm < 0)      # sign of a: clockwise vertical loop
        for Fd in (np.abs(Fp), np.abs(Fm)):           # |F_d| increasing in |a|
            assert np.all(np.diff(Fd) >= 0) and np.all(np.diff(Fd)[below] > 0)
    for ak in (-50.0, -1.0, 1.0, 50.0):
        for side in (v[v > 0], -v[v > 0]):
            Fd = np.abs(m.fd_steady(side, np.full(side.size, ak)))
            assert np.all(np.diff(Fd) < 0)            # |F_d| decreasing in |v|
    # direction-dependent levels: |F_d| -> f_a for |a| >> a_s, |v| << v_c
    assert m.fd_steady(1e-9, 1e6) == pytest.approx(2.0, rel=1e-6)
    assert m.fd_steady(-1e-9, -1e6) == pytest.approx(-1.5, rel=1e-6)


def test_static_fd_is_eq11_and_lag_is_exact_at_any_step():
    t = np.linspace(0, 0.02, 401)
    v = 0.3 * np.sin(2 * np.pi * 20 * t)
    a = 0.3 * 2 * np.pi * 20 * np.cos(2 * np.pi * 20 * t)
    m0 = make_model("modified_lugre", tau=0.0, **ASYM)
    _, S = m0.simulate(t, v, a=a, return_state=True)
    np.testing.assert_allclose(S[:, 1], m0.fd_steady(v, a), rtol=1e-12, atol=1e-14)
    # an acceleration step at (frozen, Gamma ~ 0) high speed: F_d = F_d^ss (1 - e^{-t/tau}),
    # exact even with a step h = 3 tau
    tau = 1e-3
    m = make_model("modified_lugre", tau=tau)
    for h in (1e-5, 3e-3):
        t = np.arange(0, 0.03, h)
        acc = np.full(t.size, 40.0)
        _, S = m.simulate(t, np.full(t.size, 0.5), a=acc, return_state=True)
        target = float(m.fd_steady(0.5, 40.0))
        # first-order hold of a step-like input that is constant from sample 0 on: exact
        np.testing.assert_allclose(S[:, 1], target * (1 - np.exp(-t / tau)), rtol=1e-12,
                                   atol=1e-14)


def test_vertical_loop_is_clockwise():
    """Acceleration phase above deceleration phase at the same speed (seed 000 Fig. 5d)."""
    m = make_model("modified_lugre")
    t = np.arange(0, 0.3, H)
    f = 10.0
    v = 0.2 * np.sin(2 * np.pi * f * t)
    a = 0.2 * 2 * np.pi * f * np.cos(2 * np.pi * f * t)
    F = m.simulate(t, v, a=a)
    last = t >= 0.2
    up = last & (v > 0.05) & (a > 0)
    down = last & (v > 0.05) & (a < 0)
    grid = np.linspace(0.06, 0.19, 20)
    order_up = np.argsort(v[up])
    order_dn = np.argsort(v[down])
    F_up = np.interp(grid, v[up][order_up], F[up][order_up])
    F_dn = np.interp(grid, v[down][order_dn], F[down][order_dn])
    assert np.all(F_up > F_dn)


@pytest.mark.parametrize("fd_form", ["lag", "filtered_acceleration"])
def test_converges_to_reference_second_order(fd_form):
    m = make_model("modified_lugre", fd_form=fd_form, **ASYM)
    T, f = 0.06, 10.0  # includes the reversal at t = 0.05 s (F_d switches +/- set)

    def motion(t):
        return 0.25 * np.sin(2 * np.pi * f * t), 0.25 * 2 * np.pi * f * np.cos(2 * np.pi * f * t)

    tf = np.linspace(0, T, 4801)
    vf, af = motion(tf)
    Fr = simulate_prescribed(m, tf, vf, a=af)
    errs = []
    for n in (151, 301, 601):
        t = np.linspace(0, T, n)
        v, a = motion(t)
        errs.append(np.sqrt(np.mean((m.simulate(t, v, a=a) - np.interp(t, tf, Fr)) ** 2)))
    order = np.log2(np.array(errs[:-1]) / np.array(errs[1:]))
    print(f"modified_lugre ({fd_form}) RMS error vs reference {errs}, observed order {order}")
    assert np.min(order) > 1.8, (errs, order)


def test_gamma_stays_stable_where_classic_euler_diverges():
    ml = make_model("modified_lugre")
    p = ml.params
    lg = make_model("lugre", sigma0=p.sigma0, sigma1=p.sigma1, sigma2=p.sigma2, Fc=p.Fc,
                    Fs=p.Fs, vs=p.vs, alpha=p.alpha)
    vcr = euler_critical_velocity(lg, H)
    assert vcr == pytest.approx(0.24, rel=1e-3)          # A.7: Fc/sigma0 = 1.2e-5 m
    assert euler_critical_velocity(ml, H) == pytest.approx(vcr, rel=1e-12)
    assert p.v2 < vcr                                     # switch band below it
    t = np.arange(0, 0.2, H)
    zmax = lg.z_max()
    for amp in (2.5 * vcr, 1.0):  # sinusoids peaking above the growth limit 2 v_cr
        v = amp * np.sin(2 * np.pi * 10 * t)
        a = amp * 2 * np.pi * 10 * np.cos(2 * np.pi * 10 * t)
        _, Zl = lg.simulate(t, v, method="euler", return_state=True)
        Fm, Zm = ml.simulate(t, v, a=a, method="euler", return_state=True)
        assert not np.all(np.abs(Zl[:, 0]) < 1e3 * zmax)   # classic Euler blows up
        assert np.all(np.isfinite(Fm))
        assert np.max(np.abs(Zm[:, 0])) <= zmax * (1 + 1e-12)   # bounded by g/sigma0
    # constant speed between v_cr and 2 v_cr: classic Euler zig-zags about z_ss,
    # the modified Euler update approaches monotonically
    tc = np.arange(400) * H
    for speed in (1.3 * vcr, -1.7 * vcr):
        vv = np.full(tc.size, speed)
        _, Zl = lg.simulate(tc, vv, method="euler", return_state=True)
        _, Zm = ml.simulate(tc, vv, a=np.zeros(tc.size), method="euler", return_state=True)
        zss = np.sign(speed) * p.Fc / p.sigma0
        el, em = Zl[:8, 0] - zss, Zm[:, 0] - zss
        assert np.mean(np.sign(el[1:]) != np.sign(el[:-1])) > 0.9
        assert np.all(np.sign(em) == np.sign(em[0])) and np.all(np.diff(np.abs(em)) <= 0)
    # and the modified Euler run follows the exact update closely (same model, same h)
    v = 1.0 * np.sin(2 * np.pi * 10 * t)
    a = 1.0 * 2 * np.pi * 10 * np.cos(2 * np.pi * 10 * t)
    Fe = ml.simulate(t, v, a=a, method="euler")
    Fx = ml.simulate(t, v, a=a)
    assert np.sqrt(np.mean((Fe - Fx) ** 2)) < 0.02 * p.Fc


def test_mass_reference_consistent_with_discrete_update():
    m = make_model("modified_lugre", **ASYM)
    t = np.linspace(0, 0.05, 1001)
    u = 25.0 * np.sin(2 * np.pi * 20 * t)
    out = simulate_mass(m, 0.05, t, u, rtol=1e-8)
    # the motion crosses the Gamma band (|v| up to ~0.9 m/s) and reverses
    assert np.all(np.isfinite(out["F"])) and np.max(np.abs(out["v"])) > m.params.v2
    F = m.simulate(t, out["v"], a=out["a"])
    rms = np.sqrt(np.mean((F - out["F"]) ** 2)) / np.std(out["F"])
    assert rms < 5e-4, rms
    m0 = make_model("modified_lugre", tau=0.0)
    with pytest.raises(ValueError, match="algebraic"):
        simulate_mass(m0, 0.05, t[:10], u[:10])


def test_population_matches_single_runs():
    m = make_model("modified_lugre", **ASYM)
    t = np.arange(0, 0.1, H)
    v = 0.3 * np.sin(2 * np.pi * 10 * t)
    a = 0.3 * 2 * np.pi * 10 * np.cos(2 * np.pi * 10 * t)
    X = np.array([[5e5, 2.0, 2e-3], [1e6, 0.5, 0.0], [2e5, 4.0, 1e-2]])
    P = m.simulate_population(t, v, ["sigma0", "f_a", "tau"], X, a=a)
    for i, row in enumerate(X):
        ref = m.with_values(sigma0=row[0], f_a=row[1], tau=row[2]).simulate(t, v, a=a)
        np.testing.assert_allclose(P[i], ref, rtol=0, atol=1e-12)


@pytest.mark.parametrize("bad, pattern", [
    ({"v1": 0.2, "v2": 0.2}, r"v2 = 0.2 must be > v1 = 0.2"),
    ({"v1": 0.3, "v2": 0.1}, r"v2 .* v1"),
    ({"v1": 0.0}, "v1"), ({"tau": -1e-3}, "tau"), ({"a_s": 0.0}, "a_s"),
    ({"v_c_neg": -0.1}, "v_c_neg"), ({"beta": 0.0}, "beta"), ({"sigma0": 0.0}, "sigma0"),
    ({"gamma_form": "step"}, "gamma_form"), ({"fd_form": "pid"}, "fd_form")])
def test_impossible_parameters_name_the_bound(bad, pattern):
    with pytest.raises(ParameterError, match=pattern):
        make_model("modified_lugre", **bad)


def test_bad_signals():
    m = make_model("modified_lugre")
    t = np.linspace(0, 1, 10)
    a = np.zeros(10)
    a[6] = np.nan
    with pytest.raises(ValueError, match=r"a\[6\]"):
        m.simulate(t, np.zeros(10), a=a)
    with pytest.raises(ValueError, match="length mismatch: a"):
        m.simulate(t, np.zeros(10), a=np.zeros(9))
    with pytest.raises(ValueError, match="length mismatch: v"):
        m.simulate(t, np.zeros(8), a=np.zeros(10))
    with pytest.raises(ValueError, match="strictly increasing"):
        m.simulate(t[::-1], np.zeros(10), a=np.zeros(10))
    with pytest.raises(ValueError, match="state0"):
        m.simulate(t, np.zeros(10), state0=[0.0])
    with pytest.raises(ValueError, match="acceleration"):
        m.derivatives(np.zeros(2), 0.1)


def test_identification_names_exclude_the_switch_presets():
    m = make_model("modified_lugre", Fc_neg=5.0)
    names = m.free_names()
    assert "v1" not in names and "v2" not in names
    assert {"sigma0", "sigma1", "beta", "gamma", "tau", "f_a", "a_s", "v_c", "alpha",
            "Fc", "Fc_neg", "Fs", "vs", "sigma2"} <= set(names)
    # every free name has a finite search range (identification builds its box from them)
    info = {i.name: i for i in m.Params.info()}
    assert all(info[n].search is not None for n in names)


def test_euler_option_is_the_paper_sketch():
    """method="euler" is EQUATIONS.md A.9 line by line (asymmetric sets, logistic Gamma).

    The sketch updates F_d before the output; the package reports the state at t_k, so
    its F_d at sample k+1 is the sketch's F_d after update k (a one-sample shift).
    """
    m = make_model("modified_lugre", **ASYM)
    p = m.params
    t = np.arange(0, 0.06, H)
    v = 0.3 * np.sin(2 * np.pi * 20 * t) + 0.02
    a = 0.3 * 2 * np.pi * 20 * np.cos(2 * np.pi * 20 * t)
    F, S = m.simulate(t, v, a=a, method="euler", return_state=True)
    kappa = 2 * np.log(99) / (p.v2 - p.v1)
    z = Fd = 0.0
    for k in range(t.size - 1):
        h = t[k + 1] - t[k]
        vk, ak = v[k], a[k]
        sfx = "" if vk >= 0 else "_neg"
        Fc, Fs, vs, s2, fa, as_, vc = (getattr(p, n + sfx) if getattr(p, n + sfx) is not None
                                       else getattr(p, n) for n in
                                       ("Fc", "Fs", "vs", "sigma2", "f_a", "a_s", "v_c"))
        g = Fc + (Fs - Fc) * np.exp(-abs(vk / vs) ** p.alpha)
        gamma = 1 / (1 + np.exp(kappa * (abs(vk) - (p.v1 + p.v2) / 2)))
        zd = gamma * (vk - p.sigma0 * abs(vk) * z / g)
        Fdss = fa * np.sign(ak) * (1 - np.exp(-(abs(ak) / as_) ** p.beta)) \
            * np.exp(-(abs(vk) / vc) ** p.gamma)
        assert F[k] == pytest.approx(p.sigma0 * z + p.sigma1 * zd + s2 * vk + Fd + p.b,
                                     rel=1e-9, abs=1e-9)
        Fd = Fd + h * (Fdss - Fd) / p.tau
        z = z + h * zd
        assert S[k + 1, 0] == pytest.approx(z, rel=1e-9, abs=1e-15)
        assert S[k + 1, 1] == pytest.approx(Fd, rel=1e-9, abs=1e-12)
