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


def test_the_case_file_sets_the_integration_and_the_periodic_stop(tmp_path):
    """[cpp.motion] method, stop_when_periodic and periodic_tolerance reach the integration,
    and the JSON and the report say how many revolutions were integrated and whether the
    periodic state was reached. Without backlash the example's carrier settles (the change
    falls by about 2.5 a revolution, to 1e-6 after 19), so 40 revolutions stop early;
    with the stop off all 40 run and the motion is still found periodic. A tolerance outside
    (0, 1) is an input error naming the field."""
    text = (
        EXAMPLE.read_text()
        .replace('backlash = "0.05 mm"', 'backlash = "0 mm"')
        .replace("revolutions = 20", "revolutions = 40")
    )
    text = text[: text.index("[cpp.study]")]
    case = tmp_path / "settling.toml"
    case.write_text(text)
    out = tmp_path / "out"
    result = shaftline("cpp", "motion", str(case), "--out", str(out), "--json", str(tmp_path / "r.json"))
    assert result.exit_code == 0, result.stderr
    motion = json.loads((tmp_path / "r.json").read_text())["cpp"]["motion"]
    assert motion["periodic"] is True and motion["period"] == 1 and motion["method"] == "trbdf2"
    assert 5 < motion["revolutions"] < 40 == motion["revolutions_requested"]
    assert motion["periodic_change"] <= motion["periodic_tolerance"] == 1e-6
    assert "reached: repeats every revolution" in (out / "report.html").read_text()

    case.write_text(text.replace("revolutions = 40", "revolutions = 40\nstop_when_periodic = false"))
    motion = json.loads(shaftline("cpp", "motion", str(case), "--json", "-").stdout)["cpp"]["motion"]
    assert motion["revolutions"] == 40 and motion["periodic"] is True

    case.write_text(text.replace("revolutions = 40", 'revolutions = 3\nmethod = "backward_euler"'))
    motion = json.loads(shaftline("cpp", "motion", str(case), "--json", "-").stdout)["cpp"]["motion"]
    assert motion["method"] == "backward_euler" and motion["revolutions"] == 3 and motion["periodic"] is False

    for value in ("0.0", "1.5"):
        case.write_text(text.replace("revolutions = 40", f"revolutions = 40\nperiodic_tolerance = {value}"))
        result = shaftline("cpp", "motion", str(case))
        assert result.exit_code == 2 and "cpp.motion.periodic_tolerance" in result.stderr


def test_a_motion_that_never_repeats_is_said_above_the_results(tmp_path):
    """The example's backlash keeps the motion from repeating (the change from one cycle to
    the next stays near 0.3): the summary and the report open the section with a warning that
    the settled amplitude is not that of a cycle; the settled motion without backlash has none.
    The periodic stop is a true/false switch: "yes" is refused, not read as true."""
    out = tmp_path / "out"
    result = shaftline("cpp", "motion", str(EXAMPLE), "--out", str(out))
    assert result.exit_code == 0, result.stderr
    assert "did not become periodic in 20 revolutions" in " ".join(result.stdout.split())
    assert "did not become periodic" in (out / "report.html").read_text()

    settled = EXAMPLE.read_text().replace('backlash = "0.05 mm"', 'backlash = "0 mm"')
    settled = settled.replace("revolutions = 20", "revolutions = 40")
    case = tmp_path / "settled.toml"
    case.write_text(settled[: settled.index("[cpp.study]")])
    result = shaftline("cpp", "motion", str(case))
    assert result.exit_code == 0 and "did not become periodic" not in result.stdout

    case.write_text(EXAMPLE.read_text().replace("revolutions = 20", 'revolutions = 20\nstop_when_periodic = "yes"'))
    result = shaftline("cpp", "motion", str(case))
    assert result.exit_code == 2 and "cpp.motion.stop_when_periodic = 'yes'" in result.stderr
