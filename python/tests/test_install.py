# `cmake --install build --prefix P` puts the package in P/lib/python3.X/dist-packages/tide, where
# Debian's python3 imports it (with /usr/local, without PYTHONPATH).
import os
import subprocess
import sys

import pytest


def test_the_installed_package_imports_and_runs(tmp_path):
    build = os.environ.get("TIDE_BUILD_DIR")
    if not build:
        pytest.skip("TIDE_BUILD_DIR not set (run through ctest)")
    cmake = os.environ.get("CMAKE_COMMAND", "cmake")
    prefix = tmp_path / "prefix"
    subprocess.run([cmake, "--install", build, "--prefix", str(prefix)], check=True, capture_output=True)
    version = f"python{sys.version_info.major}.{sys.version_info.minor}"
    site = prefix / "lib" / version / "dist-packages"
    assert (site / "tide" / "__init__.py").exists()
    # The same layout under /usr/local is on Debian python3's own path: no PYTHONPATH needed there.
    assert f"/usr/local/lib/{version}/dist-packages" in sys.path
    code = ("import tide; w = tide.World({'domain': {'min': [0,0,0], 'max': [0.4,0.4,0.4]}, 'particle_spacing': 0.04,"
            " 'end_time': 0.1, 'materials': [{'name': 'water', 'density': 1000}],"
            " 'blocks': [{'min': [0,0,0], 'max': [0.2,0.2,0.2], 'material': 'water'}]}); w.step();"
            " print(tide.__file__, w.particle_count)")
    env = {k: v for k, v in os.environ.items() if k != "PYTHONPATH"}
    env["PYTHONPATH"] = str(site)
    out = subprocess.run([sys.executable, "-c", code], check=True, capture_output=True, text=True, env=env,
                         cwd=tmp_path).stdout
    assert out.startswith(str(site / "tide")) and out.split()[-1] == "125"
