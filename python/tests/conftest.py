# Shared by the Python module's tests: where the sources and the built programs are.
import os
import pathlib

import pytest

SOURCE_DIR = pathlib.Path(os.environ.get("TIDE_SOURCE_DIR", pathlib.Path(__file__).resolve().parents[2]))
BIN_DIR = pathlib.Path(os.environ.get("TIDE_BIN_DIR", SOURCE_DIR / "build" / "bin"))


@pytest.fixture
def source_dir():
    return SOURCE_DIR


@pytest.fixture
def bin_dir():
    return BIN_DIR


def small_tank(**extra):
    """A 0.4 m tank with a 0.2 m block of water at 0.04 m spacing (125 particles): quick scenes."""
    scene = {
        "name": "small tank",
        "domain": {"min": [0, 0, 0], "max": [0.4, 0.4, 0.4]},
        "particle_spacing": 0.04,
        "end_time": 0.1,
        "solver": {"method": "dfsph"},
        "materials": [{"name": "water", "density": 1000, "viscosity": 0.001}],
        "blocks": [{"min": [0, 0, 0], "max": [0.2, 0.2, 0.2], "material": "water"}],
        "output": {"fps": 50},
    }
    scene.update(extra)
    return scene
