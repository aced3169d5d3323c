"""The user's own plant FMU (issue 14 section 1): connection files (fmus.connect), the master's
connection factors and measured inputs, identification and trajectory-level diagnosis
through plant FMUs the plant library did not build (a C FMU compiled here, a pythonfmu FMU
written here; tests/user_plants.py)."""
from __future__ import annotations

import json
import math

import numpy as np
import pytest

pytest.importorskip("fmpy")

from friction import make_model  # noqa: E402
from fmus.connect import (ConnectError, MeasuredRecord, PlantLoop, PlantRunError,  # noqa: E402
                          builtin_connection, load_connection, parse_connection)
from fmus.master import Master, fmu_file, law_parameters  # noqa: E402

LAWS = ("friction_effects", "lugre", "mass")


@pytest.fixture(scope="module")
def native_dir():
    from fmus.testing import built_native_fmus
    return built_native_fmus(LAWS)


@pytest.fixture(scope="module")
def cart(tmp_path_factory):
    from user_plants import build_c_cart
    return build_c_cart(tmp_path_factory.mktemp("c_cart"))


@pytest.fixture(scope="module")
def py_cart(tmp_path_factory):
    pytest.importorskip("pythonfmu")
    from user_plants import build_python_cart
    return build_python_cart(tmp_path_factory.mktemp("py_cart"), "PyCartPlantFmuTests")


def _record(T=1.0, dt=1e-3, **cols):
    t = np.arange(0.0, T + 1e-9, dt)
    return MeasuredRecord(t, {k: f(t) for k, f in cols.items()}, "rec")


CART = {  # the C cart: the law's force enters F_c, which the cart *adds* (sign -1)
    "step": 1e-4,
    "friction": {"input": "F_c", "sign": -1, "v": "vel", "x": "pos", "a": "acc"},
    "inputs": {"u": "u"},
    "compare": {"pos": {"column": "x", "unit": "m"}},
    "parameters": {"k_u": 2.0, "m": 1.5},
    "identify": {"m": [0.5, 3.0]},
}


# -- the master: connection factors, measured inputs ------------------------------------------
def test_master_connection_factor_and_external_inputs_c_loop_equals_python(native_dir):
    """friction.F -> mass.F_ext with factor -1 is the plain connection into F_friction; an
    external input table drives F_ext; the compiled loop equals the Python loop bit for bit
    and a step's recorded input is the table's row held over it."""
    mass, law = fmu_file(native_dir, "mass", True), fmu_file(native_dir, "lugre", True)
    par = {"mass": {"m": 1.0, "u_amp": 2.0, "u_freq": 1.0}}
    plain = Master({"mass": mass, "friction": law}, [("mass.v", "friction.v"),
                                                    ("friction.F", "mass.F_friction")],
                   parameters=par, record=["mass.x"])
    neg = Master({"mass": mass, "friction": law}, [("mass.v", "friction.v"),
                                                  ("friction.F", "mass.F_ext", -1.0)],
                 parameters=par, record=["mass.x"])
    with plain, neg:
        a = plain.simulate(stop_time=0.5, step_size=1e-4)
        b = neg.simulate(stop_time=0.5, step_size=1e-4)
    assert np.array_equal(a["mass.x"], b["mass.x"])

    n = 5000
    u = 1.5 * np.sin(2 * np.pi * 2.0 * 1e-4 * np.arange(n + 1))
    out = {}
    for loop in ("c", "python"):
        with Master({"mass": mass, "friction": law},
                    [("mass.v", "friction.v"), ("friction.F", "mass.F_friction")],
                    parameters={"mass": {"m": 1.0, "u_amp": 0.0}}, inputs=["mass.F_ext"],
                    record=["mass.x", "mass.F_ext"], loop=loop) as m:
            out[loop] = m.simulate(stop_time=0.5, step_size=1e-4, inputs={"mass.F_ext": u})
    assert np.array_equal(out["c"]["mass.x"], out["python"]["mass.x"])
    assert np.array_equal(out["c"]["mass.F_ext"][1:], u[:n])
    assert np.ptp(out["c"]["mass.x"]) > 1e-3
    with Master({"mass": mass}, [], inputs=["mass.F_ext"]) as m:
        with pytest.raises(ValueError, match="F_ext: 3 values for 10 steps"):
            m.simulate(stop_time=1e-3, step_size=1e-4, inputs={"mass.F_ext": [0, 1, 2]})
        with pytest.raises(ValueError, match="no values given"):
            m.simulate(stop_time=1e-3, step_size=1e-4)
    with pytest.raises(ValueError, match="mass.x is a output, not an input"):
        Master({"mass": mass}, [], inputs=["mass.x"])
