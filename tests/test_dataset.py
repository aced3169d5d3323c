"""Measurement CSV/.mat loading: contract columns, mapping, and bad files that must fail loudly."""
import numpy as np
import pytest
from scipy.io import savemat

from friction.dataset import Dataset, load_csv, load_dataset, parse_mapping


def _write(path, header, rows):
    path.write_text(",".join(header) + "\n" + "\n".join(",".join(map(str, r)) for r in rows) + "\n")


def _signal(n=500):
    t = np.arange(n) * 1e-3
    x = 0.01 * np.sin(2 * np.pi * 2 * t)
    v = 0.01 * 2 * np.pi * 2 * np.cos(2 * np.pi * 2 * t)
    F = np.tanh(v / 1e-3)
    return t, x, v, F


def test_roundtrip_and_derived_columns(tmp_path):
    t, x, v, F = _signal()
    ds = Dataset.from_arrays(t, F, x=x, v=v)
    assert ds.derived == ("a",)
    np.testing.assert_allclose(ds.a[5:-5], np.gradient(v, t)[5:-5])
    p = tmp_path / "run.csv"
    ds.to_csv(p)
    back = load_csv(p)
    np.testing.assert_array_equal(back.t, t)
    np.testing.assert_array_equal(back.F, F)
    s = back.to_structured()
    assert s.dtype.names[0] == "time"


def test_extra_columns_kept_and_mapping(tmp_path):
    t, x, v, F = _signal()
    p = tmp_path / "raw.csv"
    _write(p, ["time", "pos_mm", "force", "temperature"],
           [(a, b * 1e3, c, 20.0) for a, b, c in zip(t, x, F)])
    ds = load_csv(p, mapping=parse_mapping("t=time,x=pos_mm,F=force"), scale={"x": 1e-3})
    np.testing.assert_allclose(ds.x, x)
    np.testing.assert_allclose(ds.v[5:-5], v[5:-5], rtol=0, atol=1e-3 * np.max(np.abs(v)))
    assert "temperature" in ds.extra


def test_mat_with_mapping(tmp_path):
    t, x, v, F = _signal()
    p = tmp_path / "run.mat"
    savemat(p, {"time": t[:, None], "q": x[:, None], "f": F[:, None]})
    ds = load_dataset(p, mapping={"t": "time", "x": "q", "F": "f"})
    assert len(ds) == t.size and "v" in ds.derived


def test_nan_names_the_sample(tmp_path):
    t, x, v, F = _signal()
    F[17] = np.nan
    with pytest.raises(ValueError, match=r"F\[17\]"):
        Dataset.from_arrays(t, F, x=x, v=v)


def test_unsorted_time_and_wrong_length():
    t, x, v, F = _signal()
    t2 = t.copy()
    t2[10], t2[11] = t2[11], t2[10]
    with pytest.raises(ValueError, match="strictly increasing"):
        Dataset.from_arrays(t2, F, x=x, v=v)
    with pytest.raises(ValueError, match="length mismatch"):
        Dataset.from_arrays(t, F[:-1], x=x, v=v)


def test_units_off_by_1000():
    t, x, v, F = _signal()
    with pytest.raises(ValueError, match="units off by 1000"):
        Dataset.from_arrays(t, F, x=x * 1e3, v=v)  # x in mm, v in m/s
    with pytest.raises(ValueError, match="millimetres"):
        Dataset.from_arrays(t, F, x=(x + 0.05) * 1e3)  # only x, in mm: spans > 20 "m"


def test_missing_columns(tmp_path):
    p = tmp_path / "bad.csv"
    _write(p, ["t", "x"], [(0.0, 0.0), (0.001, 0.0)])
    with pytest.raises(ValueError, match="friction-force column 'F'"):
        load_csv(p)
    _write(p, ["t", "F"], [(0.0, 0.0), (0.001, 0.0)])
    with pytest.raises(ValueError, match="position column 'x'"):
        load_csv(p)
    with pytest.raises(FileNotFoundError):
        load_csv(tmp_path / "nope.csv")


def test_split_is_chronological():
    t, x, v, F = _signal()
    a, b = Dataset.from_arrays(t, F, x=x, v=v).split(0.7)
    assert a.t[-1] < b.t[0] and len(a) + len(b) == t.size


def test_constructor_checks_like_from_arrays():
    # a Dataset built directly (as the Python API allows) is checked too, naming the problem
    t = np.linspace(0.0, 1.0, 11)
    z = np.zeros(11)
    F = np.ones(11)
    bad = F.copy()
    bad[4] = np.nan
    with pytest.raises(ValueError, match=r"F\[4\] = nan is not finite"):
        Dataset(t=t, x=z, v=z, a=z, F=bad)
    with pytest.raises(ValueError, match="strictly increasing"):
        Dataset(t=t[::-1], x=z, v=z, a=z, F=F)
    with pytest.raises(ValueError, match="length mismatch: F has 10 samples but t has 11"):
        Dataset(t=t, x=z, v=z, a=z, F=F[:-1])
    with pytest.raises(ValueError, match=r"load\[0\]"):
        Dataset(t=t, x=z, v=z, a=z, F=F, load=np.full(11, np.inf))
