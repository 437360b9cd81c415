"""The cpp verbs of the command line on the example case."""

from __future__ import annotations

import json
from pathlib import Path

import pytest
from typer.testing import Result

from tests.conftest import invoke

ROOT = Path(__file__).resolve().parents[1]
EXAMPLE = ROOT / "examples" / "cpp_blade_bearing.toml"


def shaftline(*args: str) -> Result:
    return invoke(*args)


def test_cpp_fretting_and_motion(tmp_path):
    result = shaftline("cpp", "fretting", str(EXAMPLE), "--json", "-")
    assert result.exit_code == 0, result.stderr
    cpp = json.loads(result.stdout)["cpp"]
    assert cpp["gross_fretting_both_ways"] is True
    assert cpp["k_fret_max"] > 1 > -1 > cpp["k_fret_min"]
    assert "motion" not in cpp
    out = tmp_path / "out"
    result = shaftline("cpp", "motion", str(EXAMPLE), "--out", str(out), "--json", str(tmp_path / "r.json"))
    assert result.exit_code == 0, result.stderr
    motion = json.loads((tmp_path / "r.json").read_text())["cpp"]["motion"]
    assert 20e-6 < motion["fretting_amplitude"] < 1e-3
    assert motion["pressure_fluctuation"] > 0
    for name in ("cpp_torques", "cpp_motion"):
        assert (out / "figures" / f"{name}.png").stat().st_size > 10_000


def test_cpp_bad_input(tmp_path):
    case = tmp_path / "case.toml"
    case.write_text(EXAMPLE.read_text().replace("friction_coefficient = 0.1", "friction_coefficient = 1.5"))
    result = shaftline("cpp", "fretting", str(case))
    assert result.exit_code == 2 and "cpp.bearing.friction_coefficient = 1.5" in result.stderr


def test_load_table_ranking_and_study(tmp_path):
    """Blade loads from a CSV table (as from a propeller code) give the same coefficient as the
    harmonics they were sampled from; two propellers are ranked; the study grows with backlash."""
    import numpy as np

    from shaftline.cases import load_case

    case = load_case(EXAMPLE)["cpp"]
    loads = case.loads
    rows = ["angle_deg,force_x,force_y,force_z,moment_x,moment_y,moment_z"]
    for k in range(loads.angle.size):
        values = [np.degrees(loads.angle[k]), *loads.hydro_force[k], *loads.hydro_moment[k]]
        rows.append(",".join(f"{v:.6f}" for v in values))
    (tmp_path / "loads.csv").write_text("\n".join(rows))
    text = EXAMPLE.read_text()
    start, end = text.index("[cpp.loads]"), text.index("[cpp.hydraulics]")
    table_case = (
        text[:start] + '[cpp.loads]\ntable = "loads.csv"\nblade_mass = "2.6 t"\n'
        'centre_of_gravity = ["0.12 m", "-0.06 m", "0.55 m"]\n\n' + text[end:]
    )
    (tmp_path / "table.toml").write_text(
        table_case.replace('name = "CPP blade bearing, fretting check"', 'name = "from a table"')
    )
    harmonic = json.loads(shaftline("cpp", "fretting", str(EXAMPLE), "--json", "-").stdout)["cpp"]
    tabled = json.loads(shaftline("cpp", "fretting", str(tmp_path / "table.toml"), "--json", "-").stdout)["cpp"]
    assert tabled["k_fret_max"] == pytest.approx(harmonic["k_fret_max"], rel=1e-6)
    calmer = text.replace('amplitude = "30 kN*m"', 'amplitude = "12 kN*m"').replace(
        'name = "CPP blade bearing, fretting check"', 'name = "calmer wake"'
    )
    (tmp_path / "calm.toml").write_text(calmer)
    compared = shaftline(
        "cpp",
        "fretting",
        str(EXAMPLE),
        str(tmp_path / "calm.toml"),
        str(EXAMPLE),
        "--json",
        "-",
        "--out",
        str(tmp_path / "rank"),
    )
    ranking = json.loads(compared.stdout)
    # the same case twice is ranked twice, told apart by its file name
    assert [r["case"] for r in ranking["ranking"]] == [
        "CPP blade bearing, fretting check",
        "CPP blade bearing, fretting check (cpp_blade_bearing.toml)",
        "calmer wake",
    ]
    assert "Fretting risk" in (tmp_path / "rank" / "report.html").read_text()
    assert json.loads((tmp_path / "rank" / "results.json").read_text()) == ranking
    study = json.loads(shaftline("cpp", "motion", str(EXAMPLE), "--json", "-").stdout)["cpp"]["study"]
    amplitudes = study["fretting_amplitude"]
    assert study["parameter"] == "backlash" and all(a < b for a, b in zip(amplitudes, amplitudes[1:], strict=False))
    (tmp_path / "loads.csv").write_text("\n".join(rows[:3] + ["nan" + rows[3][rows[3].index(",") :]] + rows[4:]))
    result = shaftline("cpp", "fretting", str(tmp_path / "table.toml"))
    assert result.exit_code == 2 and "row 4" in result.stderr
