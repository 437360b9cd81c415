"""Start-up of the command line: the time until a user sees ``--version`` or an input error.

Issue 8's target: well under 0.5 s for ``--version`` and for an input error (it was 1.5 s
and 3.9 s). Each command runs as a new process of the console script, as a user starts
it; medians of N runs
(default 15), wall time, with the ratio to the 0.5 s target. The unit cache
(shaftline.units) is warmed by one run first, as it is after a user's first run.

Run: python benchmarks/bench_startup.py [N]
"""

from __future__ import annotations

import os
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

TARGET = 0.5
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


def command() -> list[str]:
    """The installed console script, as a user runs it (``python -m shaftline.cli`` without one)."""
    script = Path(sys.executable).with_name("shaftline")
    return [str(script)] if script.exists() else [sys.executable, "-m", "shaftline.cli"]


def median_time(args: list[str], runs: int, env: dict[str, str]) -> tuple[float, int]:
    times, code = [], 0
    for _ in range(runs):
        start = time.perf_counter()
        code = subprocess.run([*command(), *args], capture_output=True, env=env).returncode
        times.append(time.perf_counter() - start)
    return statistics.median(times), code


def main() -> None:
    runs = int(sys.argv[1]) if len(sys.argv) > 1 else 15
    folder = Path(tempfile.mkdtemp(prefix="shaftline-startup-"))
    env = {**os.environ, "SHAFTLINE_CACHE_DIR": str(folder / "cache")}
    (folder / "bad_value.toml").write_text(CASE.format(clearance="-0.1 mm"))
    (folder / "bad_unit.toml").write_text(CASE.format(clearance="0.1 kg"))
    median_time(["run", str(folder / "bad_value.toml")], 1, env)  # remembers the units
    cases = {
        "--version": ["--version"],
        "missing case file": ["run", str(folder / "missing.toml")],
        "value out of range (bearing.radial_clearance = -0.1 mm)": ["run", str(folder / "bad_value.toml")],
        "wrong unit (bearing.radial_clearance = 0.1 kg, pint explains)": ["run", str(folder / "bad_unit.toml")],
    }
    print(f"Command-line start-up, median of {runs} runs (target < {TARGET} s)")
    for label, args in cases.items():
        median, code = median_time(args, runs, env)
        print(f"  {label:62s} {median:6.3f} s  ratio {median / TARGET:5.2f}  exit {code}")


if __name__ == "__main__":
    main()
