"""The seed 004 shaft line (``shaftline.shaft.ntua``), 100 x 60 film grid: the seed's fast path
(issue 11 target <= 0.2 s), its problem bisection, the coupled alignment and the minimum
speed (lift-off curve), medians over repeats in one process, with the ratio of each to
the coupled solution.

Run: ``PYTHONPATH=src .venv/bin/python benchmarks/bench_ntua_line.py [repeats]``.
"""

from __future__ import annotations

import math
import sys

from timing import median_time

from shaftline.shaft.coupled import CoupledAlignment
from shaftline.shaft.fast_path import bisection, fast_path
from shaftline.shaft.lift_off import FilmLimit, minimum_speed
from shaftline.shaft.ntua import ntua_shaft_line


def main() -> None:
    repeats = int(sys.argv[1]) if len(sys.argv) > 1 else 5
    line, film = ntua_shaft_line(0.3)
    fast_path(line, film)  # imports and first-use set-up out of the timings
    coupled_time, coupled = median_time(lambda: CoupledAlignment(line, [film]).solve(), repeats)
    rows = [
        ("fast path (one film equilibrium)", *median_time(lambda: fast_path(line, film), repeats)),
        ("problem bisection (seed, 1 mm)", *median_time(lambda: bisection(line, film), repeats)),
        ("bisection with the film's lift", *median_time(lambda: bisection(line, film, lift=True), repeats)),
        ("coupled alignment", coupled_time, coupled),
    ]
    print(f"seed 004 line, film 100 x 60, {repeats} repeats (median)")
    for name, seconds, result in rows:
        extra = ""
        if hasattr(result, "iterations") and hasattr(result, "film_solutions"):
            extra = f"  Newton iterations {result.iterations}, film solutions {result.film_solutions}"
        elif hasattr(result, "iterations"):
            extra = f"  passes {result.iterations}"
        print(f"  {name:34s} {seconds * 1e3:8.1f} ms  ratio to coupled {seconds / coupled_time:5.2f}{extra}")
    limit = FilmLimit(class_value=30e-6)
    lift_time, lift = median_time(lambda: minimum_speed(line, [film], limit), max(1, repeats // 2))
    print(
        f"  minimum speed (30 um, 1 %)         {lift_time * 1e3:8.1f} ms  ratio to coupled "
        f"{lift_time / coupled_time:5.2f}  coupled solutions {lift.solutions}, "
        f"speed {lift.speed * 30 / math.pi:.2f} rpm"
    )


if __name__ == "__main__":
    main()
