"""Units and formats (issue 16, item 4): the unit check names the measured column that is off
and the --scale that fixes it; separators, decimal commas and byte-order marks are read;
hints reach CLI users in CLI syntax; --max-evals <= 0 is refused by name."""
import re

import numpy as np
import pytest

import friction.dataset
from friction.dataset import Dataset, load_csv, load_dataset
from frictionlab.cli import main

# (a plain ValueError before DataError existed, so each test fails on its own there)
DataError = getattr(friction.dataset, "DataError", ValueError)


def _motion(T=2.0, dt=1e-3):
    """A small friction experiment in SI: speeds of about 1 cm/s, a 3 mm stroke."""
    t = np.arange(0, T, dt)
    v = 0.01 * np.sin(2 * np.pi * 1.0 * t) + 0.002 * np.sin(2 * np.pi * 6 * t)
    x = np.concatenate(([0.0], np.cumsum(0.5 * (v[1:] + v[:-1]) * np.diff(t))))
    F = np.tanh(v / 1e-3) + 0.3 * v / 0.01
    return t, x, v, F


def _write(path, header, cols, sep=",", decimal=".", bom=b"", encoding="utf-8"):
    def cell(val):
        s = repr(float(val))
        return s.replace(".", decimal) if decimal != "." else s
    lines = [sep.join(header)] + [sep.join(cell(c) for c in row) for row in zip(*cols)]
    path.write_bytes(bom + ("\n".join(lines) + "\n").encode(encoding))
    return path


def _cli_error(args, capsys):
    capsys.readouterr()
    assert main(args) == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1 and "Traceback" not in err
    return err


# ---- the unit check names the column that is off ---------------------------------------

def test_x_in_mm_without_v_column_is_caught_and_blames_x(tmp_path, capsys):
    t, x, v, F = _motion()
    with pytest.raises(DataError) as exc:
        Dataset.from_arrays(t, F, x=x * 1e3)  # no v: it is differentiated from x
    e = exc.value
    assert "x looks like millimetres" in str(e)
    assert "scale={'x': 1e-3}" in str(e) and "--scale x=1e-3" in e.cli
    assert "v=" not in e.cli.split("Rescale")[1].split(";")[0]  # v was derived: not blamed
    # following the hint gives the SI data
    p = _write(tmp_path / "mm.csv", ["t", "x", "F"], [t, x * 1e3, F])
    ds = load_csv(p, scale={"x": 1e-3})
    np.testing.assert_allclose(ds.x, x, rtol=1e-12, atol=1e-15)
    err = _cli_error(["identify", str(p), "--model", "lugre"], capsys)
    assert "--scale x=1e-3" in err and "scale={" not in err


def test_v_in_mm_per_s_with_x_in_m_blames_v(tmp_path, capsys):
    t, x, v, F = _motion()
    with pytest.raises(DataError) as exc:
        Dataset.from_arrays(t, F, x=x, v=v * 1e3)
    e = exc.value
    assert "v looks like mm/s" in str(e)
    fix = e.cli.split("Rescale with ")[1]
    assert fix.startswith("--scale v=1e-3")  # today's hint said x=1e-3: wrong
    p = _write(tmp_path / "v_mm.csv", ["t", "x", "v", "F"], [t, x, v * 1e3, F])
    ds = load_csv(p, scale={"v": 1e-3})  # following the hint: SI data, no error
    np.testing.assert_allclose(ds.v, v, rtol=1e-12)
    err = _cli_error(["identify", str(p), "--model", "lugre"], capsys)
    assert "--scale v=1e-3" in err


def test_x_in_mm_with_v_in_m_per_s_blames_x():
    t, x, v, F = _motion()
    with pytest.raises(DataError) as exc:
        Dataset.from_arrays(t, F, x=x * 1e3, v=v)
    assert exc.value.cli.split("Rescale with ")[1].startswith("--scale x=1e-3")


def test_degrees_against_rad_per_s_blame_the_degrees():
    t, x, v, F = _motion()
    with pytest.raises(DataError, match="x looks like degrees") as exc:
        Dataset.from_arrays(t, F, x=np.degrees(x), v=v)
    assert "--scale x=0.017453292519943" in exc.value.cli
    with pytest.raises(DataError, match="v looks like deg/s"):
        Dataset.from_arrays(t, F, x=x, v=np.degrees(v))


def test_a_position_derived_from_v_is_never_blamed():
    # a long run at a steady 0.3 m/s: the integrated position spans 300 m, legitimately
    t = np.arange(0, 1000, 0.01)
    v = 0.3 + 0.05 * np.sin(2 * np.pi * 0.5 * t)
    F = 1.0 + 0.5 * v
    ds = Dataset.from_arrays(t, F, v=v)
    assert ds.derived[0] == "x" and np.ptp(ds.x) > 250
    # the same speeds in mm/s: v is blamed, the derived x never is
    with pytest.raises(DataError) as exc:
        Dataset.from_arrays(t, F, v=v * 1e3)
    e = exc.value
    fix = e.cli.split("Rescale with ")[1].split(";")[0]
    assert fix.startswith("--scale v=1e-3 ") and "x=" not in fix, e.cli
    assert "x spans" not in str(e)


def test_an_explicit_scale_vouches_for_a_column():
    # a motor shaft really turning at 50 rad/s: flagged, and accepted once vouched for
    t = np.arange(0, 2, 1e-3)
    v = 50 + 5 * np.sin(2 * np.pi * t)
    F = 0.1 + 1e-3 * v
    with pytest.raises(DataError) as exc:
        Dataset.from_arrays(t, F, v=v)
    assert "--scale v=1" in exc.value.cli
    Dataset.from_arrays(t, F, v=v, asserted_units=("v",))


# ---- separators, decimal commas, byte-order marks ---------------------------------------

@pytest.mark.parametrize("sep,decimal,bom,encoding,note", [
    (";", ",", b"", "utf-8", "decimal commas"),
    ("\t", ".", b"", "utf-8", "tab-separated"),
    ("\t", ",", b"", "utf-8", "decimal commas"),
    (";", ".", b"", "utf-8", "';'-separated"),
    (",", ".", b"\xef\xbb\xbf", "utf-8", "UTF-8 byte-order mark"),
    (";", ",", b"\xef\xbb\xbf", "utf-8", "UTF-8 byte-order mark"),
    ("\t", ".", b"", "utf-16", "UTF-16 text"),
    (" ", ".", b"", "utf-8", "whitespace-separated"),
])
def test_spreadsheet_formats_are_read_correctly(sep, decimal, bom, encoding, note, tmp_path):
    t, x, v, F = _motion(T=0.5)
    p = _write(tmp_path / "d.csv", ["t", "x", "v", "F"], [t, x, v, F], sep=sep,
               decimal=decimal, bom=bom, encoding=encoding)
    ds = load_dataset(p)
    np.testing.assert_array_equal(ds.t, t)
    np.testing.assert_array_equal(ds.x, x)
    np.testing.assert_array_equal(ds.F, F)
    assert note in ds.notes


def test_decimal_commas_in_a_comma_separated_file_are_named(tmp_path, capsys):
    t, x, v, F = _motion(T=0.2)
    p = _write(tmp_path / "dc.csv", ["t", "x", "F"], [t, x, F], sep=",", decimal=",")
    with pytest.raises(DataError, match="decimal commas"):
        load_csv(p)
    err = _cli_error(["identify", str(p), "--model", "lugre"], capsys)
    assert "decimal commas" in err


def test_a_headerless_file_is_named(tmp_path):
    t, x, v, F = _motion(T=0.2)
    p = tmp_path / "nohead.txt"
    p.write_text("\n".join(f"{a} {b} {c}" for a, b, c in zip(t, x, F)) + "\n")
    with pytest.raises(DataError, match="header row"):
        load_csv(p)


# ---- hints in CLI syntax for CLI users, Python syntax for API users ---------------------

def test_mapping_hints_use_cli_syntax_on_the_command_line(tmp_path, capsys):
    t, x, v, F = _motion(T=0.2)
    p = _write(tmp_path / "names.csv", ["time", "pos", "force"], [t, x, F])
    with pytest.raises(DataError) as exc:
        load_csv(p)
    assert "mapping={'t': " in str(exc.value)
    err = _cli_error(["identify", str(p), "--model", "lugre"], capsys)
    assert "--map t=" in err and "mapping=" not in err and "{" not in err
    p2 = _write(tmp_path / "noforce.csv", ["t", "x", "force"], [t, x, F])
    err = _cli_error(["identify", str(p2), "--model", "lugre"], capsys)
    assert "--map F=" in err and "mapping=" not in err
    err = _cli_error(["identify", str(p2), "--model", "lugre", "--map", "F=force",
                      "--scale", "v=1e-3"], capsys)
    assert "--scale given for 'v', which is not in the data" in err


# ---- --max-evals -------------------------------------------------------------------------

@pytest.mark.parametrize("n", ["0", "-5"])
def test_max_evals_not_positive_is_refused_by_name(n, tmp_path, capsys):
    t, x, v, F = _motion(T=0.5)
    p = _write(tmp_path / "ok.csv", ["t", "v", "F"], [t, v, F])
    err = _cli_error(["identify", str(p), "--model", "lugre", "--max-evals", n], capsys)
    assert re.search(r"--max-evals -?\d+: the evaluation budget must be a positive", err)
    assert "data" not in err.split("error:")[1]
    from identification import identify
    with pytest.raises(ValueError, match="max_evals"):
        identify(load_csv(p), "lugre", max_evals=int(n))
