"""The Python tests run against the installed package (PYTHONPATH set by ctest to the moved
prefix's dist-packages); BAIZE_PACKAGE_PREFIX names the prefix, for its assets."""
import os
import pathlib

import pytest


@pytest.fixture
def prefix():
    return pathlib.Path(os.environ["BAIZE_PACKAGE_PREFIX"])


@pytest.fixture
def scenes_dir(prefix):
    return prefix / "share" / "baize" / "scenes"
