"""The cpp verbs of the command line on the example case."""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
EXAMPLE = ROOT / "examples" / "cpp_blade_bearing.toml"


def shaftline(*args: str) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, "-m", "shaftline.cli", *args], capture_output=True, text=True, timeout=300)


def test_cpp_fretting_and_motion(tmp_path):
    result = shaftline("cpp", "fretting", str(EXAMPLE), "--json", "-")
    assert result.returncode == 0, result.stderr
    cpp = json.loads(result.stdout)["cpp"]
    assert cpp["gross_fretting_both_ways"] is True
    assert cpp["k_fret_max"] > 1 > -1 > cpp["k_fret_min"]
    assert "motion" not in cpp
    out = tmp_path / "out"
    result = shaftline("cpp", "motion", str(EXAMPLE), "--out", str(out), "--json", str(tmp_path / "r.json"))
    assert result.returncode == 0, result.stderr
    motion = json.loads((tmp_path / "r.json").read_text())["cpp"]["motion"]
    assert 20e-6 < motion["fretting_amplitude"] < 1e-3
    assert motion["pressure_fluctuation"] > 0
    for name in ("cpp_torques", "cpp_motion"):
        assert (out / "figures" / f"{name}.png").stat().st_size > 10_000


def test_cpp_bad_input(tmp_path):
    case = tmp_path / "case.toml"
    case.write_text(EXAMPLE.read_text().replace("friction_coefficient = 0.1", "friction_coefficient = 1.5"))
    result = shaftline("cpp", "fretting", str(case))
    assert result.returncode == 2 and "cpp.bearing.friction_coefficient" in result.stderr
    assert "Traceback" not in result.stderr
