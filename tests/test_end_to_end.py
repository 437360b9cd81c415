"""A few runs of the installed command line in a separate process (the rest of the CLI
tests run in process): the console entry point, exit codes and standard streams as a
shell sees them."""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

from tests.conftest import MINIMAL_CASE


def shaftline(*args: str, cwd: Path | None = None) -> subprocess.CompletedProcess[str]:
    return subprocess.run(
        [sys.executable, "-m", "shaftline.cli", *args], capture_output=True, text=True, cwd=cwd, timeout=120
    )


def test_version():
    result = shaftline("--version")
    assert result.returncode == 0 and result.stdout.startswith("shaftline ")


def test_python_dash_m_shaftline_is_the_command_line():
    # for an environment whose scripts folder is not on the PATH
    result = subprocess.run(
        [sys.executable, "-m", "shaftline", "--version"], capture_output=True, text=True, timeout=120
    )
    assert result.returncode == 0 and result.stdout.startswith("shaftline ")


def test_run_writes_json_and_report(tmp_path):
    (tmp_path / "case.toml").write_text(MINIMAL_CASE)
    result = shaftline("run", "case.toml", "--json", "-", cwd=tmp_path)
    assert result.returncode == 0, result.stderr
    assert json.loads(result.stdout)["bearing"]["cases"][0]["converged"] is True
    assert (tmp_path / "results" / "case" / "report.html").exists()


def test_bad_input_is_one_line_on_stderr_with_exit_2(tmp_path):
    (tmp_path / "case.toml").write_text(MINIMAL_CASE.replace('length = "0.1 m"', 'length = "0.1 kg"'))
    result = shaftline("bearing", "solve", "case.toml", "--out", "out", cwd=tmp_path)
    assert result.returncode == 2
    assert result.stderr.strip().count("\n") == 0 and "Traceback" not in result.stderr
    assert result.stderr.startswith("error: bearing.length = '0.1 kg': allowed a quantity of length")
    assert not (tmp_path / "out").exists()
