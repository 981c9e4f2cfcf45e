# tide.Fluid: the seed's API from Python reproduces the C++ demo's summary lines exactly.
import subprocess

import numpy as np
import pytest

import tide

SECONDS, EVERY, FPS = 0.25, 0.125, 60.0


def summary(fluid):
    """demo::printSummary (examples/demo_support.hpp), from Python."""
    n = fluid.getPointCounts()
    pos = fluid.getPosData()
    material = fluid.getMaterialData()
    s = fluid.stats()
    line = "t=%6.2f s  particles=%7u  density error=%5.2f %%  max speed=%5.2f m/s  centroid y:" % (
        fluid.time(), n, 100.0 * s["density_error"], s["max_speed"])
    for m, name in enumerate(fluid.materialNames()):
        y = pos[material == m, 1].astype(np.float64)
        if len(y):
            line += "  %s=%.2f" % (name, np.cumsum(y)[-1] / len(y))  # summed in order, as C++ does
    return line


def four_jets():
    """examples/jets.cpp --four, with the same calls."""
    fluid = tide.Fluid()
    settings = tide.FluidSettings()
    settings.solver = "classic"
    fluid.init(65535, (-20, -20, -20), (20, 20, 20), (0, 0, 0), (0, 0, 0), (0, -9.81, 0), settings)
    heavy_oil = fluid.addMaterial(tide.Material(30.0, 5000.0, (0.5, 0.5, 1)))
    light_oil = fluid.addMaterial(tide.Material(30.0, 200.0, (0.5, 1, 0.5)))
    light_water = fluid.addMaterial(tide.Material(1.0, 200.0, (1, 0.5, 0.5)))
    v = (2.0, 0, 0)
    lines = [summary(fluid)]
    frames = int(SECONDS * FPS + 0.5)
    per_summary = max(1, int(EVERY * FPS + 0.5))
    dt = np.float32(1.0) / np.float32(FPS)  # 1.0f / fps in C++
    for frame in range(1, frames + 1):
        fluid.addPointTick((-20, -4, 4), (-20, 0, 8), v, light_water)
        fluid.addPointTick((-20, -4, -8), (-20, 0, -4), v, light_oil)
        fluid.addPointTick((-20, 4, -4), (-20, 8, 0), v, heavy_oil)
        fluid.addPointTick((-20, -4, -4), (-20, 0, 0), v)
        fluid.step(dt)
        if frame % per_summary == 0 or frame == frames:
            lines.append(summary(fluid))
    return lines


def test_the_seed_api_reproduces_the_cpp_demos_summary_exactly(bin_dir):
    demo = bin_dir / "jets"
    if not demo.exists():
        pytest.skip("examples not built (TIDE_BUILD_EXAMPLES=OFF)")
    out = subprocess.run([str(demo), "--four", "--solver", "classic", "--seconds", str(SECONDS), "--every", str(EVERY)], check=True,
                         capture_output=True, text=True).stdout
    expected = [line for line in out.splitlines() if line.startswith("t=")]
    assert len(expected) == 3
    assert four_jets() == expected
    assert "material 3=" in expected[-1]  # four materials flowing


def test_getposdata_is_a_read_only_view_in_world_units():
    fluid = tide.Fluid()
    fluid.init(4096, (-20, -20, -20), (20, 20, 20), (-15, -20, -15), (-5, -10, -5), (0, -9.81, 0))
    assert fluid.getPointCounts() == 1000  # 10 × 10 × 10 units at spacing 1
    pos = fluid.getPosData()
    assert pos.shape == (1000, 3) and pos.dtype == np.float32 and not pos.flags.writeable
    assert pos[:, 1].min() >= -20 and pos[:, 1].max() <= -10
    assert pos.base is fluid
    y0 = pos[:, 1].mean()
    fluid.step(1 / 60)
    assert fluid.time() == pytest.approx(1 / 60, abs=1e-6)
    assert fluid.getPosData()[:, 1].mean() < y0  # falling
    assert fluid.addPoint((100, 0, 0), (101, 1, 1), (0, 0, 0)) is False  # outside the wall box
    with pytest.raises(ValueError, match=r"min: must be 3 finite numbers, got \(1, 2\)"):
        fluid.addPoint((1, 2), (3, 4, 5), (0, 0, 0))
    fluid.reset()
    assert fluid.getPointCounts() == 0
    with pytest.raises(Exception, match="init"):
        fluid.addMaterial(tide.Material())
