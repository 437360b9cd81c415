"""The command line, in process: results, JSON fields, report folder, bad input (exit 2,
one line, no output), the schema verb."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from tests.conftest import MINIMAL_CASE, invoke


@pytest.fixture
def case(tmp_path: Path) -> Path:
    path = tmp_path / "case.toml"
    path.write_text(MINIMAL_CASE)
    return path


def test_version():
    result = invoke("--version")
    assert result.exit_code == 0
    assert result.stdout.startswith("shaftline ")


def test_bearing_solve_json_to_stdout(case):
    result = invoke("bearing", "solve", str(case), "--json", "-")
    assert result.exit_code == 0, result.output
    document = json.loads(result.stdout)  # nothing but the JSON on standard output
    bearing = document["bearing"]
    base = bearing["cases"][0]
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
        assert isinstance(base[key], float), key
    assert bearing["units"]["min_film_thickness"] == "m"
    assert base["converged"] is True
    assert len(base["stiffness"]) == 2
    assert document["case"] == "small bearing"


def test_bearing_solve_writes_report(case, tmp_path):
    out = tmp_path / "out"
    result = invoke("bearing", "solve", str(case), "--out", str(out), "--json", str(tmp_path / "r.json"))
    assert result.exit_code == 0, result.output
    assert "Bearing film at equilibrium" in result.stdout
    assert (out / "report.html").read_text().count("<img") >= 3
    assert (out / "figures" / "bearing_0_maps.png").stat().st_size > 10_000
    assert json.loads((tmp_path / "r.json").read_text())["bearing"]["cases"][0]["min_film_thickness"] > 0
    assert json.loads((out / "results.json").read_text()) == json.loads((tmp_path / "r.json").read_text())


@pytest.mark.parametrize(
    "replace, field",
    [
        (('radial_clearance = "0.1 mm"', 'radial_clearance = "-0.1 mm"'), "bearing.radial_clearance"),
        (('speed = "600 rpm"', 'speed = "0 rpm"'), "bearing.operation.speed"),
        (('length = "0.1 m"', 'length = "0.1 kg"'), "bearing.length"),
        (("axial_nodes = 21", "axial_nodes = 2"), "bearing.solver.axial_nodes"),
        (('viscosity = "0.02 Pa*s"', "viscosity = nan"), "bearing.lubricant.viscosity"),
        (("[bearing.operation]", "[operation]"), "operation"),
    ],
)
def test_bad_input_exit_2_one_line_no_output(case, tmp_path, replace, field):
    case.write_text(MINIMAL_CASE.replace(*replace))
    out = tmp_path / "out"
    result = invoke("run", str(case), "--out", str(out), "--json", str(tmp_path / "r.json"))
    assert result.exit_code == 2
    lines = [line for line in result.stderr.splitlines() if line.strip()]
    assert len(lines) == 1 and lines[0].startswith(f"error: {field} = ")
    assert result.stdout == ""
    assert not out.exists() and not (tmp_path / "r.json").exists()


def test_missing_file_and_bad_toml(tmp_path):
    result = invoke("bearing", "solve", str(tmp_path / "nope.toml"))
    assert result.exit_code == 2 and "case file" in result.stderr and "an existing file" in result.stderr
    bad = tmp_path / "bad.toml"
    bad.write_text("[bearing\nlength = 1")
    result = invoke("bearing", "solve", str(bad))
    assert result.exit_code == 2 and "valid TOML" in result.stderr


def test_verb_refuses_a_case_without_its_table(case):
    result = invoke("align", str(case))
    assert result.exit_code == 2 and "[alignment]" in result.stderr


def test_run_writes_to_results_by_default(case, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    result = invoke("run", str(case))
    assert result.exit_code == 0, result.output
    assert (tmp_path / "results" / "case" / "report.html").exists()


def test_schema_verb_prints_the_json_schema():
    result = invoke("schema")
    assert result.exit_code == 0
    schema = json.loads(result.stdout)
    length = schema["$defs"]["BearingSection"]["properties"]["length"]
    assert length["x-unit"] == "m" and length["exclusiveMinimum"] == 0
    markdown = invoke("schema", "--format", "markdown").stdout
    assert "#### `[bearing.operation]`" in markdown


def test_json_inside_the_report_folder_is_kept(case, tmp_path):
    out = tmp_path / "out"
    result = invoke("bearing", "solve", str(case), "--out", str(out), "--json", str(out / "summary.json"))
    assert result.exit_code == 0, result.output
    assert json.loads((out / "summary.json").read_text())["case"] == "small bearing"
    assert (out / "report.html").exists()


def test_pitchlog_needs_a_wear_table(case, tmp_path):
    log = tmp_path / "log.csv"
    log.write_text("time,pitch\n0,0\n0.1,1\n")
    result = invoke("wear", "pitchlog", str(log), "--case", str(case))
    assert result.exit_code == 2 and "[wear]" in result.stderr


@pytest.mark.parametrize("threshold", ["nan", "inf", "-1"])
def test_weibull_threshold_must_be_a_positive_number(tmp_path, threshold):
    data = tmp_path / "d.csv"
    data.write_text("x\n0.1\n0.2\n0.15\n0.12\n")
    result = invoke("wear", "weibull", str(data), "--threshold", threshold, "--json", "-")
    assert result.exit_code == 2 and result.stderr.startswith("error: --threshold")


def test_non_utf8_files_are_input_errors(tmp_path):
    data = tmp_path / "d.csv"
    data.write_bytes(b"x\n0.1\n\xff\n")
    result = invoke("wear", "weibull", str(data))
    assert result.exit_code == 2 and "UTF-8" in result.stderr
    case = tmp_path / "c.toml"
    case.write_bytes(b'[bearing]\nlength = "\xff"\n')
    result = invoke("run", str(case))
    assert result.exit_code == 2 and "UTF-8" in result.stderr


def test_run_case_refuses_unknown_capabilities():
    from shaftline.cases import parse_case
    from shaftline.pipeline import run_case

    with pytest.raises(ValueError, match="nonsense"):
        run_case(parse_case({"wear": {}}, only=[]), only=["nonsense"])


def test_out_may_not_be_the_working_folder_or_hold_the_case(case, tmp_path, monkeypatch):
    """Until issue 9 makes updating a folder safe, a report folder that would replace the
    working folder or the case's own folder is refused, and nothing is touched."""
    monkeypatch.chdir(tmp_path)
    (tmp_path / "notes.txt").write_text("keep me")
    for out in (".", str(tmp_path), str(tmp_path.parent)):
        result = invoke("run", str(case), "--out", out)
        assert result.exit_code == 2 and result.stderr.startswith("error: --out"), out
    assert (tmp_path / "notes.txt").read_text() == "keep me" and case.exists()
