"""Cost of the 4 x 4 film coefficients with the tilt terms (issue 11) against the 2 x 2 ones.

Run ``PYTHONPATH=src .venv/bin/python benchmarks/bench_tilt.py``. On the NTUA stern tube
(``examples/ntua_stern_tube.toml``, 100 x 60, psi_x = 0.3) at its equilibrium, prints the
medians of ``linearise`` (four derivatives) and ``linearise_with_tilt`` (eight), both started
from the equilibrium's cavitated set as ``dynamic_coefficients`` does, their ratio, and the
equilibrium's own time for scale; three rounds, each measured pair by pair in one process.
"""

from __future__ import annotations

import statistics
import time
from collections.abc import Callable
from pathlib import Path

from shaftline.cases import load_case
from shaftline.film.bearing import JournalBearing

EXAMPLE = Path(__file__).resolve().parents[1] / "examples" / "ntua_stern_tube.toml"


def median_time(function: Callable[[], object], repeats: int) -> float:
    times = []
    for _ in range(repeats):
        start = time.perf_counter()
        function()
        times.append(time.perf_counter() - start)
    return statistics.median(times)


def main() -> None:
    case = load_case(EXAMPLE)["bearing"].cases[0]
    bearing = JournalBearing(case.geometry, case.operating, case.options)
    state = bearing.equilibrium(case.load_y, tilt_y=case.tilt_y).state
    for _ in range(3):
        two = median_time(lambda: bearing.linearise(state.position, initial_cavitated=state.cavitated), 30)
        four = median_time(lambda: bearing.linearise_with_tilt(state.position, initial_cavitated=state.cavitated), 30)
        equilibrium = median_time(lambda: bearing.equilibrium(case.load_y, tilt_y=case.tilt_y), 10)
        print(
            f"linearise {two * 1e3:.2f} ms, linearise_with_tilt {four * 1e3:.2f} ms, ratio {four / two:.2f}; "
            f"equilibrium {equilibrium * 1e3:.1f} ms"
        )


if __name__ == "__main__":
    main()
