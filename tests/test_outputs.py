"""Outputs never lose a user's data: foreign folders are refused and left untouched, result
folders are updated file by file, no output replaces an input, places are checked before
solving, permissions follow the umask, and an interrupt leaves nothing behind."""

from __future__ import annotations

import json
import os
import stat
from pathlib import Path

import pytest

from shaftline.outputs import MANIFEST, result_folder
from tests.conftest import MINIMAL_CASE, invoke

EXAMPLES = Path(__file__).resolve().parents[1] / "examples"


@pytest.fixture
def case(tmp_path: Path) -> Path:
    path = tmp_path / "case.toml"
    path.write_text(MINIMAL_CASE)
    return path


def every_verb(case: Path, tmp_path: Path) -> dict[str, list[str]]:
    """Each verb that writes a report folder, with inputs it accepts."""
    depths = tmp_path / "depths.csv"
    depths.write_text("x\n0.09\n0.10\n0.06\n0.08\n0.097\n")
    cpp = str(EXAMPLES / "cpp_blade_bearing.toml")
    return {
        "run": ["run", str(case)],
        "bearing solve": ["bearing", "solve", str(case)],
        "align": ["align", str(EXAMPLES / "single_screw_alignment.toml")],
        "cpp fretting": ["cpp", "fretting", cpp],
        "cpp fretting, two cases": ["cpp", "fretting", cpp, cpp],
        "cpp motion": ["cpp", "motion", cpp],
        "wear pitchlog": [
            "wear",
            "pitchlog",
            str(EXAMPLES / "ferry_pitch_log.csv"),
            "--case",
            str(EXAMPLES / "ferry_wear.toml"),
        ],
        "wear weibull": ["wear", "weibull", str(depths)],
    }


def test_every_verb_refuses_a_folder_of_other_files_and_leaves_it_untouched(case, tmp_path):
    """The issue's check: --out at a folder holding a foreign file is refused (exit 2, one
    line) and the file is untouched; refused before solving, so even cpp motion is quick."""
    precious = tmp_path / "precious"
    precious.mkdir()
    (precious / "notes.txt").write_text("keep me")
    for verb, args in every_verb(case, tmp_path).items():
        result = invoke(*args, "--out", str(precious))
        assert result.exit_code == 2, (verb, result.output)
        assert result.stderr.startswith("error: --out = ") and MANIFEST in result.stderr, verb
        assert sorted(p.name for p in precious.iterdir()) == ["notes.txt"], verb
        assert (precious / "notes.txt").read_text() == "keep me", verb


def test_a_result_folder_is_updated_file_by_file(case, tmp_path):
    out = tmp_path / "out"
    assert invoke("run", str(case), "--out", str(out)).exit_code == 0
    manifest = json.loads((out / MANIFEST).read_text())
    assert "results.json" in manifest["files"] and "report.html" in manifest["files"]
    (out / "my notes.txt").write_text("added by the engineer")
    first = (out / "results.json").stat().st_mtime_ns
    assert invoke("run", str(case), "--out", str(out)).exit_code == 0
    assert (out / "my notes.txt").read_text() == "added by the engineer"
    assert (out / "results.json").stat().st_mtime_ns >= first
    assert not [p for p in out.iterdir() if p.name.startswith(".shaftline-staging")]


@pytest.mark.parametrize("target", ["file", "case", "data"])
def test_outputs_may_not_replace_a_file_or_an_input(case, tmp_path, target):
    existing = tmp_path / "existing.txt"
    existing.write_text("a file")
    log = EXAMPLES / "ferry_pitch_log.csv"
    before = log.read_bytes()
    if target == "file":
        result = invoke("run", str(case), "--out", str(existing))
        assert result.exit_code == 2 and "a folder (this is a file)" in result.stderr
        assert existing.read_text() == "a file"
    elif target == "case":
        result = invoke("run", str(case), "--json", str(case))
        assert result.exit_code == 2 and "other than the run's inputs" in result.stderr
        assert case.read_text() == MINIMAL_CASE
    else:
        result = invoke("wear", "pitchlog", str(log), "--case", str(EXAMPLES / "ferry_wear.toml"), "--json", str(log))
        assert result.exit_code == 2 and "other than the run's inputs" in result.stderr
        assert log.read_bytes() == before


def test_json_into_a_folder_or_an_unwritable_place_is_refused_before_solving(case, tmp_path):
    result = invoke("run", str(case), "--json", str(tmp_path))
    assert result.exit_code == 2 and "a file name (this is a folder)" in result.stderr
    result = invoke("bearing", "solve", str(case), "--out", "/proc/shaftline-results")
    assert result.exit_code == 2 and result.stderr.startswith("error: --out") and result.stdout == ""
    a_file = tmp_path / "a_file"
    a_file.write_text("x")
    result = invoke("bearing", "solve", str(case), "--json", str(a_file / "r.json"))
    assert result.exit_code == 2 and "a path below a folder" in result.stderr


def test_files_and_folders_follow_the_umask(case, tmp_path):
    old = os.umask(0o022)
    try:
        out = tmp_path / "out"
        assert invoke("run", str(case), "--out", str(out), "--json", str(tmp_path / "r.json")).exit_code == 0
    finally:
        os.umask(old)
    assert stat.S_IMODE(out.stat().st_mode) == 0o755
    assert stat.S_IMODE((out / "figures").stat().st_mode) == 0o755
    for path in (out / "report.html", out / "results.json", out / MANIFEST, tmp_path / "r.json"):
        assert stat.S_IMODE(path.stat().st_mode) == 0o644, path


def test_an_interrupt_leaves_nothing(case, tmp_path, monkeypatch):
    """Ctrl-C while the report is written: exit 130, one line, no folder, no JSON."""
    import shaftline.report.html as html

    def interrupted(*args, **kwargs):
        raise KeyboardInterrupt

    monkeypatch.setattr(html, "write_report", interrupted)
    out = tmp_path / "out"
    result = invoke("run", str(case), "--out", str(out), "--json", str(tmp_path / "r.json"))
    assert result.exit_code == 130 and result.stderr.strip() == "interrupted: nothing was written"
    assert not out.exists() and not (tmp_path / "r.json").exists()


def test_the_manifest_says_which_files_the_latest_run_wrote(tmp_path):
    # A folder reused for another verb keeps the first verb's files (not this run's to delete); the
    # manifest lists every file shaftline wrote there and, apart, those of the latest run.
    out = tmp_path / "out"
    with result_folder(out) as staging:
        (staging / "figures").mkdir()
        (staging / "figures" / "gears_path.png").write_text("first verb")
        (staging / "report.html").write_text("first")
    with result_folder(out) as staging:
        (staging / "report.html").write_text("second")
    manifest = json.loads((out / MANIFEST).read_text())
    assert manifest["files"] == ["figures/gears_path.png", "report.html"]
    assert manifest["last_run"] == ["report.html"]
    assert (out / "figures" / "gears_path.png").read_text() == "first verb"


def test_a_special_file_is_written_into_not_replaced(case, tmp_path):
    # `--json /dev/null` replaced the device with a plain file (the staged write's rename), which broke
    # every later use of /dev/null on the machine (found when PostgreSQL's initdb failed). A FIFO stands
    # for the device here: it must still be a FIFO after the run, and its reader gets the JSON.
    import stat
    import threading

    fifo = tmp_path / "results.fifo"
    os.mkfifo(fifo)
    received: list[bytes] = []
    reader = threading.Thread(target=lambda: received.append(fifo.read_bytes()), daemon=True)
    reader.start()
    result = invoke("bearing", "solve", str(case), "--json", str(fifo))
    reader.join(timeout=60)
    assert result.exit_code == 0, result.output
    assert stat.S_ISFIFO(os.stat(fifo).st_mode)
    assert json.loads(received[0])["bearing"]["cases"][0]["converged"] is True
    assert not list(tmp_path.glob(".results.fifo.*"))
