"""Mass-conserving (JFO) film solver timings (issue 10, item 3). Prints medians and ratios.

Run ``.venv/bin/python benchmarks/bench_jfo.py`` (add ``--large`` for the 400 x 240 grid).

Targets:
  NTUA stern tube (examples/ntua_stern_tube.toml, psi_x = 0.3) with cavitation = "jfo" and the
  cavitation pressure 30 kPa below ambient (the edges feed the film): one JFO load
  equilibrium within 3x the Reynolds-condition equilibrium on the same grid, measured pair
  by pair in one process; the Newton residual history falling quadratically; a 400 x 240
  JFO equilibrium in under 60 s.
"""

from __future__ import annotations

import statistics
import sys
import time
from dataclasses import replace
from pathlib import Path

from shaftline.cases import load_case
from shaftline.film import JournalBearing

ROOT = Path(__file__).resolve().parents[1]
#: Cavitation pressure below ambient, Pa: the edges then feed the JFO film.
CAVITATION_PRESSURE = -3e4


def ntua(cavitation: str, nz: int, nt: int) -> tuple[JournalBearing, object]:
    case = load_case(ROOT / "examples" / "ntua_stern_tube.toml")["bearing"].cases[0]
    operating = replace(case.operating, cavitation_pressure=CAVITATION_PRESSURE)
    options = replace(case.options, cavitation=cavitation, axial_nodes=nz, circumferential_nodes=nt)
    return JournalBearing(case.geometry, operating, options), case


def equilibrium(bearing: JournalBearing, case, history: list[float] | None = None):
    return bearing.equilibrium(
        case.load_y,
        case.load_z,
        tilt_y=case.tilt_y,
        progress=None if history is None else (lambda k, r: history.append(r)),
    )


def pairwise(nz: int, nt: int, repeat: int) -> None:
    reynolds, case = ntua("reynolds", nz, nt)
    jfo, _ = ntua("jfo", nz, nt)
    equilibrium(reynolds, case)  # first calls build patterns and coarse grids
    history: list[float] = []
    eq = equilibrium(jfo, case, history)
    times_r, times_j, ratios = [], [], []
    for _ in range(repeat):
        start = time.perf_counter()
        equilibrium(reynolds, case)
        middle = time.perf_counter()
        equilibrium(jfo, case)
        end = time.perf_counter()
        times_r.append(middle - start)
        times_j.append(end - middle)
        ratios.append((end - middle) / (middle - start))
    print(f"NTUA stern tube, {nz} x {nt} nodes, psi_x = 0.3, cavitation pressure {CAVITATION_PRESSURE:.0f} Pa")
    print(f"  Reynolds-condition equilibrium : {statistics.median(times_r) * 1e3:8.1f} ms median")
    print(
        f"  JFO equilibrium                : {statistics.median(times_j) * 1e3:8.1f} ms median "
        f"({eq.iterations} Newton iterations)"
    )
    print(f"  ratio JFO / Reynolds           : {statistics.median(ratios):8.2f} median of pairs (target <= 3)")
    print("  JFO residual |F + W| / |W| per Newton iteration: " + ", ".join(f"{r:.1e}" for r in history))
    print(f"  eps = {eq.state.eccentricity_ratio:.4f}, p_max = {eq.state.max_pressure / 1e6:.3f} MPa")
    # One film solution at a position near the equilibrium: cold (nested coarse-grid start) and
    # warm (from the solution at the equilibrium, through the set predictor).
    here = eq.state.position
    near = replace(here, ey=here.ey + 0.01 * jfo.geometry.radial_clearance)
    cold, warm = [], []
    for _ in range(repeat):
        start = time.perf_counter()
        jfo.solve_at(near, warm_start=False)
        cold.append(time.perf_counter() - start)
        jfo.solve_at(here, warm_start=False)  # the solution the warm start starts from
        start = time.perf_counter()
        jfo.solve_at(near, warm_start=True)
        warm.append(time.perf_counter() - start)
    print(
        f"  JFO film solution at a position : cold {statistics.median(cold) * 1e3:.1f} ms, "
        f"warm from 0.01 c away {statistics.median(warm) * 1e3:.1f} ms (medians)"
    )


def large() -> None:
    jfo, case = ntua("jfo", 400, 240)
    history: list[float] = []
    start = time.perf_counter()
    eq = equilibrium(jfo, case, history)
    elapsed = time.perf_counter() - start
    print(
        f"NTUA stern tube, 400 x 240 nodes, JFO equilibrium: {elapsed:.1f} s (target < 60 s), "
        f"{eq.iterations} iterations"
    )
    print("  residual history: " + ", ".join(f"{r:.1e}" for r in history))


if __name__ == "__main__":
    pairwise(100, 60, 11)
    print()
    pairwise(200, 120, 3)
    if "--large" in sys.argv:
        print()
        large()
