"""What the command line imports before it answers: ``--version`` and an input error load no
solver, and a capability module loads no command-line library.

Each check runs in a fresh interpreter, as a user starts the command: in this process the
other tests have imported everything already.
"""

from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

import pytest

import shaftline
from shaftline.registry import CAPABILITY_MODULES

#: Packages and modules that solve (or draw) and that a quick answer must not wait for.
SOLVER_MODULES = (
    "scipy.optimize",
    "scipy.sparse.linalg",
    "scipy.integrate",
    "scipy.interpolate",
    "pymoo",
    "numba",
    "matplotlib",
    "pandas",
    "sqlalchemy",
    "shaftline.film.bearing",
    "shaftline.film.solver",
    "shaftline.film.cavitation.reynolds",
    "shaftline.film.cavitation.jfo",
    "shaftline.film.elastic",
    "shaftline.film.relaxation",
    "shaftline.shaft.alignment",
    "shaftline.shaft.coupled",
    "shaftline.design.problem",
    "shaftline.design.search",
    "shaftline.monitor.processing",
    "shaftline.monitor.study",
)

#: The case of benchmarks/bench_startup.py with a clearance that is refused.
BAD_CASE = """
[bearing]
length = "0.1 m"
diameter = "0.1 m"
radial_clearance = "-0.1 mm"
[bearing.operation]
speed = "600 rpm"
load = "5 kN"
[bearing.lubricant]
viscosity = "20 cP"
"""

#: Runs the command line's entry point with the given arguments and writes the exit status
#: and the modules then loaded as JSON to the file named first.
RUN_MAIN = """
import json, sys
import shaftline.cli
report, *arguments = sys.argv[1:]
sys.argv = ["shaftline", *arguments]
try:
    shaftline.cli.main()
    code = 0
except SystemExit as stop:
    code = stop.code or 0
with open(report, "w") as file:
    json.dump({"code": code, "modules": sorted(sys.modules)}, file)
"""

#: Imports the module named first and writes the modules then loaded as JSON to the second.
IMPORT_MODULE = """
import importlib, json, sys
importlib.import_module(sys.argv[1])
with open(sys.argv[2], "w") as file:
    json.dump(sorted(sys.modules), file)
"""


def _environment(tmp_path: Path) -> dict[str, str]:
    source = str(Path(shaftline.__file__).resolve().parents[1])
    paths = [source, *filter(None, os.environ.get("PYTHONPATH", "").split(os.pathsep))]
    return {**os.environ, "PYTHONPATH": os.pathsep.join(paths), "SHAFTLINE_CACHE_DIR": str(tmp_path / "cache")}


def _loaded(modules: list[str], names: tuple[str, ...]) -> list[str]:
    """The entries of ``names`` that are loaded (a package or any of its submodules)."""
    return [name for name in names if any(m == name or m.startswith(name + ".") for m in modules)]


def _command(tmp_path: Path, *arguments: str) -> tuple[int, list[str], str]:
    report = tmp_path / "report.json"
    done = subprocess.run(
        [sys.executable, "-c", RUN_MAIN, str(report), *arguments],
        capture_output=True,
        text=True,
        env=_environment(tmp_path),
        timeout=120,
    )
    assert done.returncode == 0, done.stderr
    found = json.loads(report.read_text())
    return found["code"], found["modules"], done.stdout + done.stderr


def test_version_imports_no_solver_and_no_numpy(tmp_path):
    code, modules, output = _command(tmp_path, "--version")
    assert code == 0
    assert output.strip() == f"shaftline {shaftline.__version__}"
    assert _loaded(modules, (*SOLVER_MODULES, "numpy", "scipy")) == []


def test_an_input_error_imports_no_solver(tmp_path):
    case = tmp_path / "bad_value.toml"
    case.write_text(BAD_CASE)
    code, modules, output = _command(tmp_path, "run", str(case))
    assert code == 2
    assert "bearing.radial_clearance" in output
    assert _loaded(modules, SOLVER_MODULES) == []


def test_a_missing_case_file_imports_no_solver_and_no_schema(tmp_path):
    code, modules, output = _command(tmp_path, "run", str(tmp_path / "missing.toml"))
    assert code == 2
    assert "missing.toml" in output
    assert _loaded(modules, (*SOLVER_MODULES, "numpy", "shaftline.cases.loader")) == []


@pytest.mark.parametrize("module", CAPABILITY_MODULES)
def test_a_capability_module_imports_no_command_line_and_no_solver(module, tmp_path):
    report = tmp_path / "modules.json"
    subprocess.run(
        [sys.executable, "-c", IMPORT_MODULE, module, str(report)],
        check=True,
        env=_environment(tmp_path),
        timeout=120,
    )
    modules = json.loads(report.read_text())
    assert _loaded(modules, ("typer", "click", "shaftline.commandline", "shaftline.cli")) == []
    assert _loaded(modules, (*SOLVER_MODULES, "numpy", "scipy")) == []
