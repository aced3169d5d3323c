"""The generalisation grid's cases keep their noise seeds and measurement protocols when a
family is added (diagnosis.benchmark.runner.grid_jobs): paired comparisons across sessions."""
import pytest

from diagnosis.benchmark.runner import MEASURED, grid_jobs
from diagnosis.effects import EFFECTS

EFFECTS_WITH_TRUTHS = [n for n, e in EFFECTS.items() if e.truths]


def _grid(effects, forms="all", plants=("valve", "forging_press")):
    # two plants (each plant's motion is simulated once to see which forms apply)
    return grid_jobs(list(plants), effects, forms, (0.5, 1.0), (0.01, 0.03), 1, True, True, 0)


@pytest.mark.slow  # 10 s (every form's reach on two plants); protocols and seeds below
def test_a_case_is_the_same_job_whatever_else_is_in_the_grid():
    full = {(j[0], j[1], j[7], j[2], j[3]): j for j in _grid(EFFECTS_WITH_TRUTHS)}
    alone = _grid(["drift"])
    assert alone
    for j in alone:
        assert full[(j[0], j[1], j[7], j[2], j[3])] == j


def test_each_form_meets_distinct_protocols_and_seeds_differ():
    # one plant and one effect (was: two of each, 18 s of the default run's 10 minutes)
    jobs = _grid(["delay"], plants=("valve",))
    by_form = {}
    for j in jobs:
        by_form.setdefault((j[0], j[1], j[7]), []).append(j)
    for cases in by_form.values():
        protocols = [j[8] for j in cases]
        assert len(set(protocols)) == min(len(cases), len(MEASURED))
    seeds = [j[4] for j in jobs]
    assert len(set(seeds)) == len(seeds)


def test_the_generic_cases_keep_their_numbered_seeds():
    jobs = grid_jobs([None], ["drift", "delay"], "first", (1.0,), (0.02,), 1, False, False, 7)
    assert [j[4] for j in jobs] == [8, 9]
    assert all(j[8] is None for j in jobs)


def test_a_sample_of_the_grid_is_the_same_cases_for_the_same_seed():
    from diagnosis.benchmark.runner import sample_jobs
    jobs = _grid(["delay"], plants=("valve",))
    a, b = sample_jobs(jobs, 5, seed=3), sample_jobs(jobs, 5, seed=3)
    assert a == b and len(a) == 5 and len(set(a)) == 5
    # in the grid's order, drawn from it
    idx = [jobs.index(j) for j in a]
    assert idx == sorted(idx)
    assert sample_jobs(jobs, 5, seed=4) != a
    assert sample_jobs(jobs, len(jobs) + 3) == jobs
    for bad in (0, -2, 2.5, True):
        with pytest.raises(ValueError, match="sample"):
            sample_jobs(jobs, bad)


def test_a_checkpoints_keys_select_the_same_cases(tmp_path):
    import json
    from diagnosis.benchmark.runner import _job_key, read_keys, select_jobs
    jobs = _grid(["delay"], plants=("valve",))
    picked = [jobs[1], jobs[4]]
    ck = tmp_path / "run.jsonl"
    ck.write_text("".join(json.dumps({"key": _job_key(j), "verdict": "x"}) + "\n"
                          for j in picked) + '{"key": "cut wh')   # a killed run's last line
    keys = read_keys(ck)
    assert keys == [_job_key(j) for j in picked]
    assert select_jobs(jobs, keys) == picked
    plain = tmp_path / "keys.txt"
    plain.write_text("\n".join(reversed(keys)) + "\n\n")
    assert select_jobs(jobs, read_keys(plain)) == picked       # the grid's order
    with pytest.raises(ValueError, match="1 of 2 keys name no case"):
        select_jobs(jobs, [keys[0], "valve|delay|9.0|0.01|1|1|0|nope|0"])
    with pytest.raises(ValueError, match="no case key"):
        select_jobs(jobs, [])
