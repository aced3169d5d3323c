"""The inertia candidate's mass behind a compliant mode
(:func:`diagnosis.effects_inertia.compliant_mode`) against a fine reference integration and
its analytic limits, and the candidate's start on a frame that recoils on soft mounts,
integrated by Radau ten times finer than sampled, positions quantised and differentiated."""
import numpy as np
import pytest
from scipy.integrate import solve_ivp

from diagnosis.effects_inertia import compliant_mode


def _reference(t, a_of_t, w, zeta):
    """The mode's high-pass a - 2 zeta w y' - w^2 y, with y'' + 2 zeta w y' + w^2 y = a,
    from solve_ivp (LSODA, tight tolerances) on the continuous a, settled at a(0)."""
    def rhs(tt, s):
        return [s[1], a_of_t(tt) - 2 * zeta * w * s[1] - w * w * s[0]]
    sol = solve_ivp(rhs, (t[0], t[-1]), [a_of_t(t[0]) / w ** 2, 0.0], t_eval=t,
                    method="LSODA", rtol=1e-10, atol=1e-12)
    return a_of_t(t) - 2 * zeta * w * sol.y[1] - w * w * sol.y[0]


@pytest.mark.parametrize("w, zeta", [(2 * np.pi * 3.0, 0.05), (2 * np.pi * 12.0, 0.3),
                                     (2 * np.pi * 0.8, 1.0)])
def test_matches_a_fine_reference_integration(w, zeta):
    dt = 1e-3
    t = np.arange(3000) * dt
    def a_of_t(tt):
        return np.cos(2 * np.pi * 1.1 * tt) + 0.4 * np.sin(2 * np.pi * 4.7 * tt)
    ours = compliant_mode(a_of_t(t), dt, w, zeta)
    ref = _reference(t, a_of_t, w, zeta)
    assert np.max(np.abs(ours - ref)) < 5e-3 * np.max(np.abs(ref))


@pytest.mark.parametrize("f_in, gain", [(0.2, (0.2 / 10.0) ** 2), (100.0, 1.0),
                                        (10.0, 1.0 / (2 * 0.1))])
def test_far_below_the_mode_nothing_above_it_all_at_it_one_over_two_zeta(f_in, gain):
    """|H| = (f / f_r)^2 well below the mode, 1 well above it, 1 / (2 zeta) at it."""
    dt = 1e-4
    w, zeta = 2 * np.pi * 10.0, 0.1
    t = np.arange(int(40.0 / f_in / dt) if f_in < 1 else 40000) * dt
    a = np.sin(2 * np.pi * f_in * t)
    y = compliant_mode(a, dt, w, zeta)
    tail = y[y.size // 2:]
    amp = 0.5 * (tail.max() - tail.min())
    assert amp == pytest.approx(gain, rel=0.03)


def test_starts_settled_and_any_step_is_stable():
    a = np.full(50, 2.5)
    np.testing.assert_allclose(compliant_mode(a, 1e-3, 30.0, 0.1), 0.0, atol=1e-12)
    # steps 100 x the mode's period: finite and bounded by the input's size
    rng = np.random.default_rng(0)
    a = rng.standard_normal(500)
    y = compliant_mode(a, 10.0, 2 * np.pi * 10.0, 0.05)
    assert np.all(np.isfinite(y)) and np.max(np.abs(y)) < 3 * np.max(np.abs(a))


@pytest.mark.parametrize("kw, name", [({"dt": 0.0}, "dt"), ({"w": -1.0}, "w"),
                                      ({"zeta": np.nan}, "zeta")])
def test_bad_parameters_are_refused_by_name(kw, name):
    args = {"dt": 1e-3, "w": 10.0, "zeta": 0.1, **kw}
    with pytest.raises(ValueError, match=f"^{name} = "):
        compliant_mode(np.zeros(10), **args)


def test_an_acceleration_that_is_not_a_number_is_refused_at_its_sample():
    a = np.zeros(10)
    a[6] = np.inf
    with pytest.raises(ValueError, match=r"^a\[6\] = inf is not finite"):
        compliant_mode(a, 1e-3, 10.0, 0.1)


def _frame_record(m_frame_share=0.5, f_mode=6.0, zeta=0.05, seed=1):
    """A carriage of 2 kg read against a frame on soft mounts (mass 2 / ``m_frame_share``
    kg, mode ``f_mode`` Hz, damping ``zeta``) moving back and forth with acceleration
    pulses (a drive's point-to-point moves): the frame recoils from the drive's reaction
    and the inverse dynamics misses 2 kg times its acceleration. Integrated (DOP853) and read
    on a grid ten times finer than the 1 kHz data, positions quantised at 1 um and differentiated twice."""
    from friction.dataset import Dataset
    dt, fine = 1e-3, 10
    m = 2.0
    M = m / m_frame_share
    k = (M + m) * (2 * np.pi * f_mode) ** 2
    c = 2 * zeta * np.sqrt(k * (M + m))
    def a_rel(tt):  # the relative acceleration the drive makes [m/s^2]: smoothed pulses
        return 0.5 * (np.tanh(np.sin(2 * np.pi * 0.7 * tt) / 0.15)
                      - np.tanh(np.sin(2 * np.pi * 0.7 * tt - 1.2) / 0.15))
    def rhs(tt, s):  # the encoder's x, v and the frame's: (M + m) xf'' = -c xf' - k xf - m a
        return [s[1], a_rel(tt), s[3], (-c * s[3] - k * s[2] - m * a_rel(tt)) / (M + m)]
    n = 6000
    tf = np.arange(n * fine) * dt / fine
    # the system is not stiff (a 6 Hz mode): an adaptive 8th-order step, read on the fine
    # grid, agrees with Radau at max_step dt/10 to 1e-10 of std F in 1 % of its time (19 s)
    sol = solve_ivp(rhs, (tf[0], tf[-1]), [0.0, 0.0, 0.0, 0.0], t_eval=tf, method="DOP853",
                    rtol=1e-12, atol=1e-14)
    x_rel, _, xf, vf = sol.y
    F_fine = m * (-c * vf - k * xf - m * a_rel(tf)) / (M + m)
    t = tf[::fine]
    F = F_fine.reshape(n, fine).mean(axis=1)  # the force sensor averages over the sample
    F = F + 0.01 * np.std(F) * np.random.default_rng(seed).standard_normal(n)
    x = np.round(x_rel[::fine] / 1e-6) * 1e-6
    v = np.gradient(x, dt)
    a = np.gradient(v, dt)
    return Dataset(t=t, x=x, v=v, a=a, F=F), 2 * np.pi * f_mode, a_rel(t)


def test_the_candidate_finds_a_frame_recoiling_on_soft_mounts():
    """The start keeps a mass behind a mode near the frame's, and its form leaves under a
    fifth of what the rigid mass leaves; the coupled part stays off."""
    from diagnosis.candidates import Fixed
    from diagnosis.effects import CANDIDATES, make_context
    data, w_true, _ = _frame_record()
    F = np.asarray(data.F)
    ctx = make_context(data)
    inertia = CANDIDATES["inertia"]
    start = inertia.start(data, np.zeros_like(F), F, ctx)
    assert isinstance(start, list)
    p, rigid_start = start
    assert isinstance(rigid_start["m_r"], Fixed) and rigid_start["m_r"] == 0.0
    assert isinstance(p["m_p"], Fixed) and p["m_p"] == 0.0
    assert not isinstance(p["m_r"], Fixed) and p["m_r"] != 0.0
    assert 0.5 * w_true < p["w_r"] < 2.0 * w_true
    # the start's mode, its mass and a rigid mass beside it fitted by least squares
    a = np.asarray(data.a)
    mode = inertia.apply(np.zeros_like(F), {"dm": 0.0, **p, "m_r": 1.0}, data, ctx)
    left = np.linalg.lstsq(np.column_stack([a, mode]), F, rcond=None)[1][0]
    rigid = np.linalg.lstsq(a[:, None], F, rcond=None)[1][0]
    assert left < 0.2 * rigid


def test_a_rigid_mass_error_keeps_the_mode_off():
    """A mass error on the true acceleration (the data's a column exact here): no part."""
    from diagnosis.candidates import Fixed
    from diagnosis.effects import CANDIDATES, make_context
    from friction.dataset import Dataset
    data, _, a_true = _frame_record()
    F = 0.3 * a_true + 0.01 * np.std(0.3 * a_true) * np.random.default_rng(2).standard_normal(
        a_true.size)
    data = Dataset(t=data.t, x=data.x, v=data.v, a=a_true, F=F)
    p = CANDIDATES["inertia"].start(data, np.zeros_like(F), F, make_context(data))
    assert isinstance(p, dict)
    assert isinstance(p["m_r"], Fixed) and isinstance(p["m_p"], Fixed)


def test_a_mass_error_on_a_twice_differentiated_position_takes_the_mode_as_a_filter():
    """On positions quantised and differentiated twice, the data's a carries the counts'
    noise that the true mass error does not: a mass behind a mode well above the motion
    is then a causal low-pass of a (dm + m_r = the mass, m_r < 0), not a resonance."""
    from diagnosis.effects import CANDIDATES, make_context
    data, _, a_true = _frame_record()
    F = 0.3 * a_true + 0.01 * np.std(0.3 * a_true) * np.random.default_rng(2).standard_normal(
        a_true.size)
    ctx = make_context(data)
    start = CANDIDATES["inertia"].start(data, np.zeros_like(F), F, ctx)
    assert isinstance(start, list)  # the part, and the rigid form beside it
    p = start[0]
    assert p["m_r"] < 0 and p["w_r"] > 10 * ctx.sa / ctx.sv


def test_a_frame_recoiling_on_the_isolator_is_named_inertia():
    """Seen family 14's frame recoil on the MRE isolator (a frame on soft mounts, lightly
    damped, that the encoder reads against), strength 1, 1 % noise, positions quantised and
    differentiated: ``unexplained`` before the mode (the gap closed 0.04), now ``inertia``
    closing most of the gap above the floor."""
    from diagnosis import diagnose
    from diagnosis.benchmark.cases import make_plant_case
    from diagnosis.benchmark.runner import MEASURED
    case = make_plant_case("mre_isolator", "inertia", 1.0, 0.01, seed=339101, quick=True,
                           form="frame_recoil", measured=MEASURED[0])
    rep = diagnose(case.data, case.base, seed=0)
    assert rep["verdict"]["cause"] == "inertia"
    assert rep["verdict"]["excess_closed"] > 0.6
