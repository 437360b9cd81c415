"""No tracebacks: every malformed input (tests/data/malformed) through every verb that reads
it gives exit status 2, one line on standard error, nothing on standard output and no output
written. The same for output places that cannot be used."""

from __future__ import annotations

from pathlib import Path

import pytest

from tests.conftest import MINIMAL_CASE, invoke

ROOT = Path(__file__).resolve().parents[1]
CORPUS = Path(__file__).parent / "data" / "malformed"
CASES = sorted(CORPUS.glob("*.toml"))
TABLES = sorted(CORPUS.glob("*.csv"))
EXAMPLES = ROOT / "examples"


def assert_refused(result, out: Path, json_file: Path) -> None:
    lines = [line for line in result.stderr.splitlines() if line.strip()]
    assert result.exit_code == 2, result.output
    assert len(lines) == 1 and lines[0].startswith("error: "), result.stderr
    assert "Traceback" not in result.output and result.stdout == ""
    assert not out.exists() and not json_file.exists()


@pytest.mark.parametrize("case", CASES, ids=lambda p: p.name)
@pytest.mark.parametrize(
    "verb", [["run"], ["bearing", "solve"], ["align"], ["cpp", "fretting"], ["cpp", "motion"]], ids=" ".join
)
def test_malformed_case_files(verb, case, tmp_path):
    out, json_file = tmp_path / "out", tmp_path / "r.json"
    assert_refused(invoke(*verb, str(case), "--out", str(out), "--json", str(json_file)), out, json_file)


@pytest.mark.parametrize("case", CASES, ids=lambda p: p.name)
def test_malformed_case_files_with_a_pitch_log(case, tmp_path):
    out, json_file = tmp_path / "out", tmp_path / "r.json"
    log = str(EXAMPLES / "ferry_pitch_log.csv")
    result = invoke("wear", "pitchlog", log, "--case", str(case), "--out", str(out), "--json", str(json_file))
    assert_refused(result, out, json_file)


@pytest.mark.parametrize("table", TABLES, ids=lambda p: p.name)
def test_malformed_data_files(table, tmp_path):
    out, json_file = tmp_path / "out", tmp_path / "r.json"
    wear_case = str(EXAMPLES / "ferry_wear.toml")
    for verb in (["wear", "pitchlog", str(table), "--case", wear_case], ["wear", "weibull", str(table)]):
        assert_refused(invoke(*verb, "--out", str(out), "--json", str(json_file)), out, json_file)


@pytest.mark.parametrize(
    "options",
    [
        ["--out", "."],
        ["--out", ".."],
        ["--out", "/proc/shaftline"],
        ["--out", "{file}"],
        ["--json", "{folder}"],
        ["--json", "/proc/shaftline.json"],
        ["--json", "{case}"],
    ],
    ids=lambda o: " ".join(o),
)
def test_unusable_output_places(options, tmp_path, monkeypatch):
    work = tmp_path / "work"
    work.mkdir()
    monkeypatch.chdir(work)
    case = work / "case.toml"
    case.write_text(MINIMAL_CASE)
    existing = work / "existing.txt"
    existing.write_text("keep")
    places = {"{file}": str(existing), "{folder}": str(work), "{case}": str(case)}
    options = [places.get(o, o) for o in options]
    before = sorted(p.name for p in work.iterdir())
    result = invoke("run", str(case), *options)
    lines = [line for line in result.stderr.splitlines() if line.strip()]
    assert result.exit_code == 2 and len(lines) == 1 and lines[0].startswith("error: --"), result.output
    assert sorted(p.name for p in work.iterdir()) == before
    assert existing.read_text() == "keep" and case.read_text() == MINIMAL_CASE


def test_weibull_threshold_below_zero_is_one_line(tmp_path):
    data = tmp_path / "d.csv"
    data.write_text("x\n0.1\n0.2\n0.15\n")
    result = invoke("wear", "weibull", str(data), "--threshold", "-1")
    assert result.exit_code == 2 and result.stderr.startswith("error: --threshold") and result.stdout == ""
