"""A 200-case load x speed sweep of the NTUA stern-tube bearing (issue 10, item 5).

Run ``.venv/bin/python benchmarks/bench_sweep.py [repeats]``. Prints medians and ratios.

The cases: examples/ntua_stern_tube.toml (100 x 60 nodes, psi_x = 0.3), 20 loads from 0.5 to
1.5 times the design load (309.86 kN) at each of 10 speeds from 60 to 120 rpm (design 90):
200 equilibria, without stiffness and damping (a second table adds them).

  naive          : each case alone with a new bearing and a cold start, one core (what
                   solve_study did per variant before)
  sweep, serial  : shaftline.film.sweep on one core (one bearing per speed, warm starts)
  sweep, 2 procs : the same on a process pool of two workers (pool start-up included; the
                   first pool of the process, which also starts the fork server, is timed
                   on its own before the medians)

Targets: sweep serial >= 3x faster than naive; the pool of two >= 1.8x faster than serial.
The issue measured the naive loop with the solver before it ("today's naive loop"); with
``--before SRC`` (the ``src`` folder of a checkout of that solver, e.g. a worktree at 9f6e95a)
the same naive loop also runs on it in a subprocess, and the sweep is compared with both.
The machine has 2 cores; run it on a quiet machine (the ratios are taken pair by pair in one
process, each timing a median of ``repeats`` runs).
"""

from __future__ import annotations

import subprocess
import sys
from dataclasses import replace
from pathlib import Path

import numpy as np
from timing import median_time

from shaftline.cases import load_case
from shaftline.film import sweep
from shaftline.film.solve import solve_case
from shaftline.film.study import BearingCase

ROOT = Path(__file__).resolve().parents[1]
_POOL_STARTED: list[bool] = []


def sweep_cases() -> list[BearingCase]:
    base = load_case(ROOT / "examples" / "ntua_stern_tube.toml")["bearing"].cases[0]
    return [
        replace(
            base,
            name=f"{speed:.0f} rpm, {share:.3f} W",
            load_y=base.load_y * share,
            operating=replace(base.operating, speed=speed * np.pi / 30.0),
        )
        for speed in np.linspace(60.0, 120.0, 10)
        for share in np.linspace(0.5, 1.5, 20)
    ]


_NAIVE_BEFORE = """
import statistics, sys, time
from dataclasses import replace
from pathlib import Path
import numpy as np
from shaftline.cases import load_case
from shaftline.film import JournalBearing
base = load_case(Path(sys.argv[1]))["bearing"].cases[0]
cases = [
    replace(base, load_y=base.load_y * share, operating=replace(base.operating, speed=speed * np.pi / 30.0))
    for speed in np.linspace(60.0, 120.0, 10)
    for share in np.linspace(0.5, 1.5, 20)
]
JournalBearing(base.geometry, base.operating, base.options).equilibrium(base.load_y, tilt_y=base.tilt_y)
times = []
for _ in range(int(sys.argv[2])):
    start = time.perf_counter()
    for c in cases:
        JournalBearing(c.geometry, c.operating, c.options).equilibrium(
            c.load_y, c.load_z, tilt_y=c.tilt_y, tilt_z=c.tilt_z
        )
    times.append(time.perf_counter() - start)
print(statistics.median(times))
"""


def naive_before(source: str, repeat: int) -> float:
    """The naive loop (new bearing and cold start per case, no stiffness) on the solver in
    ``source``, timed in a subprocess that imports it; seconds, median of ``repeat``."""
    example = str(ROOT / "examples" / "ntua_stern_tube.toml")
    done = subprocess.run(
        [sys.executable, "-c", _NAIVE_BEFORE, example, str(repeat)],
        env={"PYTHONPATH": source, "PATH": "/usr/bin:/bin"},
        capture_output=True,
        text=True,
        check=True,
    )
    return float(done.stdout.split()[-1])


def run(coefficients: bool, repeat: int, before: float | None = None) -> None:
    cases = sweep_cases()
    what = "equilibria with stiffness and damping" if coefficients else "equilibria"
    naive_time, naive = median_time(lambda: [solve_case(case, coefficients=coefficients) for case in cases], repeat)
    serial_time, serial = median_time(lambda: sweep(cases, coefficients=coefficients, backend="serial"), repeat)
    first_pool = None
    if not _POOL_STARTED:
        # The first pool of a process also starts the fork server (a new interpreter importing
        # the solver): timed on its own, then the medians of pools that find it running.
        first_pool, _ = median_time(lambda: sweep(cases, coefficients=coefficients, workers=2), 1)
        _POOL_STARTED.append(True)
    pool_time, pool = median_time(lambda: sweep(cases, coefficients=coefficients, workers=2), repeat)
    iterations = [sum(r.equilibrium.iterations for r in results) for results in (naive, serial, pool)]
    same = all(a.equilibrium.state.position == b.equilibrium.state.position for a, b in zip(serial, pool, strict=True))
    shift = max(
        abs(a.equilibrium.state.eccentricity_ratio - b.equilibrium.state.eccentricity_ratio)
        for a, b in zip(naive, serial, strict=True)
    )
    n = len(cases)
    print(f"NTUA stern tube, 100 x 60 nodes: {n} {what} (10 speeds x 20 loads), medians of {repeat}")
    print(f"  naive loop, one core : {naive_time:7.2f} s  ({n / naive_time:5.1f} /s, {iterations[0]} Newton)")
    print(
        f"  sweep, serial        : {serial_time:7.2f} s  ({n / serial_time:5.1f} /s, {iterations[1]} Newton)"
        f"  {naive_time / serial_time:.2f}x the naive loop on this solver"
    )
    print(
        f"  sweep, 2 processes   : {pool_time:7.2f} s  ({n / pool_time:5.1f} /s)"
        f"  {serial_time / pool_time:.2f}x the serial sweep (target >= 1.8), {naive_time / pool_time:.2f}x naive"
    )
    if first_pool is not None:
        print(
            f"  first pool of the process (fork server started): {first_pool:7.2f} s, "
            f"{serial_time / first_pool:.2f}x the serial sweep (this process solves chunks while it starts)"
        )
    if before is not None:
        print(
            f"  naive loop, solver before issue 10: {before:7.2f} s  ({n / before:5.1f} /s): sweep serial "
            f"{before / serial_time:.2f}x (target >= 3), 2 processes {before / pool_time:.2f}x"
        )
    else:
        # The 3x is against its "today's naive loop", the solver before issue 10.
        print("  (target: serial sweep >= 3x the naive loop before issue 10; run with --before SRC)")
    print(f"  pool = serial bit for bit: {same}; largest |d eps| sweep vs naive: {shift:.1e}")


if __name__ == "__main__":
    arguments = sys.argv[1:]
    old_source = None
    if "--before" in arguments:
        at = arguments.index("--before")
        old_source = arguments[at + 1]
        del arguments[at : at + 2]
    repeats = int(arguments[0]) if arguments else 3
    sweep(sweep_cases()[:2], backend="serial")  # imports and first-call set-up out of the timings
    run(False, repeats, None if old_source is None else naive_before(old_source, repeats))
    print()
    run(True, repeats)
