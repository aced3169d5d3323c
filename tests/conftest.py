import os
import pathlib

# one BLAS thread per test process: the suite runs in two processes on two cores, and
# OpenBLAS threads spinning beside the other process's slow both (set before numpy loads;
# a value the user exports wins)
for _var in ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ.setdefault(_var, "1")

import numpy as np  # noqa: E402
import pytest

REPO = pathlib.Path(__file__).resolve().parents[1]
SHARED = pathlib.Path(os.environ.get("FRICTIONLAB_SHARED", REPO.parent / "shared"))
REAL = SHARED / "data" / "real"


@pytest.fixture
def rng():
    return np.random.default_rng(12345)


@pytest.fixture(scope="session")
def real_data():
    if not REAL.exists():
        pytest.skip(f"shared real data not found at {REAL}")
    return REAL
