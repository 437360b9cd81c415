"""Start-up of the command line: the time until a user sees ``--version`` or an input error.

Each command runs as a new process of the console script, as a user starts it (``python -m
shaftline.cli`` with ``--module``, or where no console script is installed beside this
Python). Medians of N runs (default 15), wall time, with the ratio to the 0.5 s target and to
the start-up of ``python -c "import numpy"`` measured alongside: each run of a command is
followed by one of the numpy import, so that a machine that slows down slows both. The
targets against numpy: ``--version`` at most 2.5 times its start-up (the command line's own
libraries, no numpy, no solver), an input error at most 4 times (the case schema, which
needs numpy and pydantic, and no solver).

The unit cache (shaftline.units) and the compiled bytecode are warmed by one run of each
command first, as they are after a user's first run; where bytecode is not written
(``PYTHONDONTWRITEBYTECODE``) it goes to a temporary folder for the benchmark, as a user's
installed package has it.

Run: python benchmarks/bench_startup.py [N] [--module]
"""

from __future__ import annotations

import argparse
import os
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

TARGET = 0.5
#: Largest start-up of each command as a multiple of ``python -c "import numpy"``'s.
NUMPY_TARGETS = {"--version": 2.5, "input error": 4.0}
CASE = """
[bearing]
length = "0.1 m"
diameter = "0.1 m"
radial_clearance = "{clearance}"
[bearing.operation]
speed = "600 rpm"
load = "5 kN"
[bearing.lubricant]
viscosity = "20 cP"
"""
NUMPY = [sys.executable, "-c", "import numpy"]


def command(module: bool = False) -> list[str]:
    """The installed console script, as a user runs it (``python -m shaftline.cli`` without one,
    or with ``module``)."""
    script = Path(sys.executable).with_name("shaftline")
    return [str(script)] if script.exists() and not module else [sys.executable, "-m", "shaftline.cli"]


def environment(folder: Path) -> dict[str, str]:
    """The children's environment: a unit cache of the benchmark's own, and bytecode kept (in
    the benchmark's folder when the caller writes none, so nothing lands in the source tree)."""
    env = {**os.environ, "SHAFTLINE_CACHE_DIR": str(folder / "cache")}
    if env.pop("PYTHONDONTWRITEBYTECODE", None) and "PYTHONPYCACHEPREFIX" not in env:
        env["PYTHONPYCACHEPREFIX"] = str(folder / "pycache")
    return env


def elapsed(args: list[str], env: dict[str, str]) -> tuple[float, int]:
    """Wall time of one process and its exit status."""
    start = time.perf_counter()
    code = subprocess.run(args, capture_output=True, env=env).returncode
    return time.perf_counter() - start, code


def alternating(args: list[str], runs: int, env: dict[str, str]) -> tuple[float, float, int]:
    """Medians of ``runs`` runs of ``args`` and of the numpy import, one after the other."""
    times, numpy_times, code = [], [], 0
    for _ in range(runs):
        took, code = elapsed(args, env)
        times.append(took)
        numpy_times.append(elapsed(NUMPY, env)[0])
    return statistics.median(times), statistics.median(numpy_times), code


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("runs", nargs="?", type=int, default=15, help="runs of each command (median)")
    parser.add_argument("--module", action="store_true", help="run python -m shaftline.cli, not the console script")
    options = parser.parse_args()
    folder = Path(tempfile.mkdtemp(prefix="shaftline-startup-"))
    env = environment(folder)
    (folder / "bad_value.toml").write_text(CASE.format(clearance="-0.1 mm"))
    (folder / "bad_unit.toml").write_text(CASE.format(clearance="0.1 kg"))
    shaftline = command(options.module)
    cases = {
        "--version": (["--version"], "--version"),
        "missing case file": (["run", str(folder / "missing.toml")], "input error"),
        "value out of range (bearing.radial_clearance = -0.1 mm)": (
            ["run", str(folder / "bad_value.toml")],
            "input error",
        ),
        "wrong unit (bearing.radial_clearance = 0.1 kg, pint explains)": (
            ["run", str(folder / "bad_unit.toml")],
            "input error",
        ),
    }
    for args, _ in cases.values():  # remembers the units, writes the bytecode
        elapsed([*shaftline, *args], env)
    elapsed(NUMPY, env)
    print(f"Command-line start-up ({' '.join(shaftline)}), median of {options.runs} runs (target < {TARGET} s)")
    targets = ", ".join(f"{kind} <= {limit:g}x" for kind, limit in NUMPY_TARGETS.items())
    print(f'each against python -c "import numpy", run alternately (targets: {targets})')
    for label, (args, kind) in cases.items():
        median, numpy_median, code = alternating([*shaftline, *args], options.runs, env)
        times = median / numpy_median
        verdict = "ok" if times <= NUMPY_TARGETS[kind] else "ABOVE"
        print(
            f"  {label:62s} {median:6.3f} s  ratio {median / TARGET:5.2f}  exit {code}  "
            f"numpy {numpy_median:5.3f} s  x{times:4.2f} ({verdict}, target <= {NUMPY_TARGETS[kind]:g}x)"
        )


if __name__ == "__main__":
    main()
