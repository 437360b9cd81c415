"""``[bearing.thermal]``: the heat balance of docs/theory.md Sect. 8.1 around the equilibrium of a
case, in the terminal, the JSON and the report; a balance that does not close is a finding
(exit 3); bad input is one line, exit 2, nothing written.

Reference: the balance's own equation (T1), T_eff = T_in + beta P_f / (2 rho c_p Q), checked
with the reported equilibrium's friction power and side leakage at the reported effective
temperature; its tolerance is the balance's 0.05 K (Brent's xtol).
"""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from shaftline.lubricants import Lubricant
from tests.conftest import invoke

ROOT = Path(__file__).resolve().parents[2]


def _ntua(tmp_path: Path, grid: tuple[int, int] = (40, 24)) -> Path:
    # The example on a coarse grid (the balance, not the grid, is under test).
    text = (ROOT / "examples" / "ntua_stern_tube_thermal.toml").read_text()
    text = text.replace("axial_nodes = 100", f"axial_nodes = {grid[0]}").replace(
        "circumferential_nodes = 60", f"circumferential_nodes = {grid[1]}"
    )
    path = tmp_path / "ntua.toml"
    path.write_text(text)
    return path


def test_ntua_with_sae_30_closes_the_heat_balance(tmp_path: Path) -> None:
    out = tmp_path / "out"
    result = invoke("bearing", "solve", str(_ntua(tmp_path)), "--out", str(out), "--workers", "1")
    assert result.exit_code == 0, result.output
    assert "effective" in result.stdout and "outlet" in result.stdout  # the table wraps its labels
    bearing = json.loads((out / "results.json").read_text())["bearing"]
    assert bearing["units"]["thermal.effective_temperature"] == "degC"
    oil = Lubricant.preset("SAE 30")
    for case in bearing["cases"]:
        thermal = case["thermal"]
        assert thermal["converged"] and thermal["inlet_temperature"] == 40.0
        t_eff = thermal["effective_temperature"]
        assert thermal["viscosity"] == pytest.approx(float(oil.dynamic_viscosity(t_eff)), rel=1e-12)
        # (T1) with the reported film at T_eff (the film the equilibrium reports is that one).
        from shaftline.film.thermal import specific_heat

        heat = float(oil.density(t_eff)) * specific_heat(oil, t_eff)
        rise = 0.8 * case["power_loss"] / (heat * case["side_leakage"])
        assert t_eff == pytest.approx(40.0 + 0.5 * rise, abs=0.05)
        assert thermal["outlet_temperature"] == pytest.approx(40.0 + rise, abs=0.1)
        assert 40.5 < t_eff < 45.0  # a warm, not a hot, stern tube at 90 rpm
    assert "effective temperature" in (out / "report.html").read_text()


def test_heat_balance_that_does_not_close_is_a_finding_exit_3(tmp_path: Path) -> None:
    # A 100 mm bearing at 1400 rpm in 12 um clearance: in 20 um it closes at 124 degC, heating the
    # oil by 167 K; the rise goes as 1/c^2 (Petroff power over leakage): beyond ISO VG 68's 150 degC.
    case = tmp_path / "hot.toml"
    case.write_text(
        """
[case]
name = "hot"

[bearing]
length = "0.1 m"
diameter = "0.1 m"
radial_clearance = "12 um"

[bearing.operation]
speed = "1400 rpm"
load = "5 kN"

[bearing.lubricant]
preset = "ISO VG 68"
temperature = "40 degC"

[bearing.thermal]
inlet_temperature = "40 degC"

[bearing.solver]
axial_nodes = 11
circumferential_nodes = 24
"""
    )
    result = invoke("bearing", "solve", str(case), "--json", str(tmp_path / "r.json"), "--workers", "1")
    assert result.exit_code == 3, result.output
    assert "heat balance does not close" in result.stdout
    thermal = json.loads((tmp_path / "r.json").read_text())["bearing"]["cases"][0]["thermal"]
    assert thermal["converged"] is False and thermal["effective_temperature"] == 150.0


@pytest.mark.parametrize(
    ("old", "new", "field"),
    [
        ('inlet_temperature = "40 degC"', 'inlet_temperature = "160 degC"', "bearing.thermal.inlet_temperature"),
        ("heat_to_lubricant = 0.8", "heat_to_lubricant = 0", "bearing.thermal.heat_to_lubricant"),
        ("heat_to_lubricant = 0.8", "heat_to_lubricant = 1.2", "bearing.thermal.heat_to_lubricant"),
        ('preset = "SAE 30"', 'viscosity = "0.07 Pa*s"', "bearing.lubricant.viscosity"),
    ],
)
def test_bad_thermal_input_is_one_line_exit_2(tmp_path: Path, old: str, new: str, field: str) -> None:
    path = _ntua(tmp_path)
    text = path.read_text()
    assert old in text
    text = text.replace(old, new, 1)
    if "viscosity =" in new:
        text = text.replace('temperature = "40 degC"       #', "#", 1)
    path.write_text(text)
    result = invoke("bearing", "solve", str(path), "--json", str(tmp_path / "r.json"))
    assert result.exit_code == 2, result.output
    lines = [line for line in result.stderr.splitlines() if line.strip()]
    assert len(lines) == 1 and lines[0].startswith(f"error: {field} = "), lines
    assert not (tmp_path / "r.json").exists()
