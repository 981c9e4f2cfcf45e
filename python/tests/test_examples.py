# The example scripts in examples/python/ run at small resolution and write their plots.
import subprocess
import sys

import pytest

PNG_SIGNATURE = b"\x89PNG\r\n\x1a\n"


def run_example(source_dir, tmp_path, script, *args):
    out = subprocess.run([sys.executable, str(source_dir / "examples" / "python" / script), "--out", str(tmp_path),
                          "--no-progress", *args], check=True, capture_output=True, text=True, timeout=300).stdout
    return out


def check_png(path):
    data = path.read_bytes()
    assert data[:8] == PNG_SIGNATURE
    assert len(data) > 20000  # axes, labels, two curves: not an empty canvas


def test_dam_break_surge_front_example(source_dir, tmp_path):
    out = run_example(source_dir, tmp_path, "dam_break_surge.py", "--resolution", "8")
    check_png(tmp_path / "surge_front.png")
    table = [line.split() for line in out.splitlines() if line[:1] == " " and "%" in line]
    assert len(table) == 9  # every experimental point compared
    # the column starts where it stands, and the front runs out along the floor
    assert float(table[0][2]) == pytest.approx(1.0, abs=0.01)
    assert float(table[-1][2]) > 2.5


def test_wave_tank_gauge_example(source_dir, tmp_path):
    out = run_example(source_dir, tmp_path, "wave_tank_gauge.py", "--spacing", "0.06", "--duration", "1")
    check_png(tmp_path / "wave_gauges.png")
    assert "gauge 1 m from the paddle" in out and "gauge 2 m from the paddle" in out
