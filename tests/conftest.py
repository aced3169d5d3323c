import os
import pathlib

import numpy as np
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
