"""The command line: results, JSON fields, report folder, and bad input (exit 2, no output)."""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
MINIMAL = """
[bearing]
length = "0.1 m"
diameter = "0.1 m"
radial_clearance = "0.1 mm"
[operation]
speed = "600 rpm"
load = "5 kN"
[lubricant]
viscosity = "0.02 Pa*s"
[solver]
axial_nodes = 21
circumferential_nodes = 72
"""


def shaftline(*args: str, cwd: Path | None = None) -> subprocess.CompletedProcess:
    return subprocess.run(
        [sys.executable, "-m", "shaftline.cli", *args], capture_output=True, text=True, cwd=cwd, timeout=120
    )


def test_version():
    result = shaftline("--version")
    assert result.returncode == 0
    assert result.stdout.startswith("shaftline ")


def test_bearing_solve_json_to_stdout(tmp_path):
    case = tmp_path / "case.toml"
    case.write_text(MINIMAL)
    result = shaftline("bearing", "solve", str(case), "--json", "-")
    assert result.returncode == 0, result.stderr
    document = json.loads(result.stdout)
    for key in (
        "eccentricity_ratio",
        "attitude_angle_deg",
        "min_film_thickness",
        "max_pressure",
        "friction_coefficient",
        "power_loss",
        "sommerfeld_number",
        "side_leakage",
    ):
        assert isinstance(document[key], float), key
    assert document["units"]["min_film_thickness"] == "m"
    assert document["converged"] is True
    assert len(document["stiffness"]) == 2


def test_bearing_solve_writes_report(tmp_path):
    case = tmp_path / "case.toml"
    case.write_text(MINIMAL)
    out = tmp_path / "out"
    result = shaftline("bearing", "solve", str(case), "--out", str(out), "--json", str(tmp_path / "r.json"))
    assert result.returncode == 0, result.stderr
    assert "Bearing film at equilibrium" in result.stdout
    assert (out / "report.html").read_text().count("<img") >= 3
    assert (out / "figures" / "bearing_0_maps.png").stat().st_size > 10_000
    assert json.loads((tmp_path / "r.json").read_text())["min_film_thickness"] > 0


@pytest.mark.parametrize(
    "replace, field",
    [
        (('radial_clearance = "0.1 mm"', 'radial_clearance = "-0.1 mm"'), "bearing.radial_clearance"),
        (('speed = "600 rpm"', 'speed = "0 rpm"'), "operation.speed"),
        (('length = "0.1 m"', 'length = "0.1 kg"'), "bearing.length"),
        (("axial_nodes = 21", "axial_nodes = 2"), "solver.axial_nodes"),
        (('viscosity = "0.02 Pa*s"', "viscosity = nan"), "lubricant.viscosity"),
    ],
)
def test_bad_input_exit_2_one_line_no_output(tmp_path, replace, field):
    case = tmp_path / "case.toml"
    case.write_text(MINIMAL.replace(*replace))
    out = tmp_path / "out"
    result = shaftline("run", str(case), "--out", str(out), "--json", str(tmp_path / "r.json"))
    assert result.returncode == 2
    assert "Traceback" not in result.stderr
    lines = [line for line in result.stderr.splitlines() if line.strip()]
    assert len(lines) == 1 and field in lines[0]
    assert not out.exists() and not (tmp_path / "r.json").exists()


def test_missing_file_and_bad_toml(tmp_path):
    result = shaftline("bearing", "solve", str(tmp_path / "nope.toml"))
    assert result.returncode == 2 and "case file" in result.stderr
    bad = tmp_path / "bad.toml"
    bad.write_text("[bearing\nlength = 1")
    result = shaftline("bearing", "solve", str(bad))
    assert result.returncode == 2 and "valid TOML" in result.stderr
