"""The benchmark oracle's practical size of a ``delay`` truth (issue 15: a shift below a
sample is no delay, so such a case is not counted among the detectable ones)."""
import numpy as np
import pytest

from diagnosis.benchmark.scoring import practical_size, truth_shift
from diagnosis.effects_delay import Delay


def _record(n=2000, dt=1e-3):
    t = np.arange(n) * dt
    # a friction-like force: smooth, with sharp sign changes at the reversals
    v = np.sin(2 * np.pi * 1.3 * t) + 0.3 * np.sin(2 * np.pi * 4.1 * t)
    return t, 2.0 * np.tanh(v / 0.05) + 8.0 * v


@pytest.mark.parametrize("d", [3.3, -7.25, 0.4])
def test_truth_shift_recovers_a_transport_delay(d):
    t, F = _record()
    dt = t[1] - t[0]
    late = np.interp(t - d * dt, t, F)
    # linear interpolation of the truth against the oracle's spline: a few hundredths
    assert truth_shift(t, F, late) == pytest.approx(d, abs=0.05)


def test_a_filter_reads_as_its_group_delay():
    from scipy.signal import lfilter
    t, F = _record()
    # a 5-tap moving average: group delay of 2 samples
    avg = lfilter(np.ones(5) / 5, [1.0], F)
    avg[:5] = F[:5]
    # (the average also rounds the reversals' corners, which no shift undoes: 1.89)
    assert truth_shift(t, F, avg) == pytest.approx(2.0, abs=0.15)


def test_practical_size_names_the_rule_only_for_small_delays():
    assert practical_size("delay", {"truth_shift": 0.6}).startswith(
        "the truth shifts the force by 0.60 samples")
    assert practical_size("delay", {"truth_shift": -0.6}) != ""
    assert practical_size("delay", {"truth_shift": Delay.MIN_SAMPLES + 0.01}) == ""
    # no shift measured, or another effect: no rule
    assert practical_size("delay", {}) == ""
    assert practical_size("position", {"truth_shift": 0.1}) == ""


def test_truth_shift_refuses_bad_records_by_name():
    t, F = _record(200)
    with pytest.raises(ValueError, match="one length"):
        truth_shift(t, F, F[:-1])
    bad = F.copy()
    bad[7] = np.nan
    with pytest.raises(ValueError, match=r"F\[7\] is not finite"):
        truth_shift(t, F, bad)
    with pytest.raises(ValueError, match="increase"):
        truth_shift(t[::-1], F, F)


def test_the_rule_speaks_only_of_truths_a_shift_draws():
    from scipy.signal import lfilter
    t, F = _record()
    dt = t[1] - t[0]
    # a transport delay of half a sample: the shift leaves (almost) nothing of it
    d, left = truth_shift(t, F, np.interp(t - 0.5 * dt, t, F), left=True)
    assert d == pytest.approx(0.5, abs=0.05) and left < 0.01
    # a charge amplifier's leak (time constant 10 s, 5 x the record): the force leads by
    # less than a sample, and its reading droops, which no shift draws; so its small best
    # shift is no verdict's rule
    e = np.exp(-dt / 10.0)
    hp = F - lfilter([1.0 - e], [1.0, -e], F - F[0])
    d, left = truth_shift(t, F, hp, left=True)
    assert -Delay.MIN_SAMPLES < d < 0.0 and left > 0.8
    assert practical_size("delay", {"truth_shift": d, "shift_left": left}) == ""
    assert practical_size("delay", {"truth_shift": 0.5, "shift_left": 0.01}) != ""


@pytest.mark.parametrize("imp, floor, before, why", [
    (0.004, 0.01, 0.012, "noise floor"),     # below half the noise floor
    (0.02, 0.01, 0.1, "held-out gap"),        # above the noise, below a quarter of the gap
    (0.03, 0.01, 0.1, ""),                    # a name may be given
])
def test_a_truth_below_the_imprint_a_name_needs_is_below_practical_size(imp, floor, before, why):
    from diagnosis.verdict import practical_size as verdict_size
    info = {"truth_imprint": imp, "floor": floor, "before": before}
    reason = practical_size("stribeck_shape", info)
    assert (why in reason) if why else reason == ""
    # the same rule the verdict applies to a named candidate of that imprint
    entry = {"name": "stribeck_shape", "imprint": imp, "significance_z": 50.0}
    assert bool(verdict_size(entry, before, floor, 10)) == bool(reason)


def test_truth_imprint_is_the_rms_of_truth_minus_base_over_the_held_out_spread():
    from diagnosis.benchmark.scoring import truth_imprint
    rng = np.random.default_rng(3)
    F = rng.normal(0.0, 2.0, 4000)
    base = np.zeros(4000)
    truth = np.full(4000, 0.1)
    assert truth_imprint(F, truth, base) == pytest.approx(0.1 / np.std(F), rel=1e-12)
    # a truth the base fit draws exactly has no imprint
    assert truth_imprint(F, base, base) == 0.0
