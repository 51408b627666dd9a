# The arbor module under test is the one CTest points PYTHONPATH at (build/python); run by hand as
#   PYTHONPATH=build/python /usr/bin/python3 -m pytest tests/python
import pathlib

import pytest

arbor = pytest.importorskip("arbor", reason="the arbor module is not on PYTHONPATH (build it: cmake --build build --target arbor_python)")


@pytest.fixture(scope="session")
def data_dir():
    return pathlib.Path(__file__).resolve().parent.parent / "data"


@pytest.fixture(scope="session")
def small_tree():
    # Two levels of the tupelo: about 600 nodes, 2600 quads and 240 leaves, grown in milliseconds.
    return arbor.grow("black-tupelo", seed=1, levels=2)
