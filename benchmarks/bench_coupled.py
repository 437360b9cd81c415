"""Elastohydrodynamic alignment timing (issue 11 targets) against seed 004's fast path.

Run: ``PYTHONPATH=src .venv/bin/python benchmarks/bench_coupled.py [--repeat N]``. Prints
medians and ratios.

Coupled: the seed 004 shaft line (``shaftline.shaft.ntua.ntua_shaft_line``, psi_x = 0.3: the
aft stern-tube bearing of Table 5-1 as a film on the seed's 100 x 60 grid, L = 1.05 m,
D = 0.52 m, c = 0.45 mm, 90 rpm, 0.07 Pa s; the propeller force and moment of Table 4-5);
``CoupledAlignment(line, [film]).solve()`` from scratch (model built, film solver state
cold) <= 1 s median on the 2-core machine.

Fast path (seed 004 Sect. 4.5.2-4.5.4, ``shaftline.shaft.fast_path.fast_path``): the
point-support alignment, the local shaft model (``shaftline.shaft.local``) with its end
conditions, and one film load equilibrium with that bent journal, same line and grid:
<= 0.2 s median.

Also printed: Newton iterations and film solutions of the coupled solve, where its time goes
(film solutions with their frozen-set derivatives, the start's uncoupled film equilibrium,
the inner alignment solves, the alignment's response to unit loads, the set-up) from
instrumented runs (means), and the same coupled solve on the 14 m test line of
``tests/shaft/test_coupled.py`` (nose-down end moment) for comparison.
"""

from __future__ import annotations

import sys
import time
from collections import defaultdict
from collections.abc import Callable
from typing import Any

from timing import median_time

from shaftline.film import BearingProblem, JournalBearing, OperatingPoint, SolverOptions
from shaftline.film.geometry import BearingGeometry
from shaftline.film.solver import FilmSolver
from shaftline.shaft import AlignmentModel, Bearing, ShaftLine, ShaftSegment
from shaftline.shaft.coupled import CoupledAlignment, CoupledResult, FilmSupport
from shaftline.shaft.fast_path import FastPathResult, fast_path
from shaftline.shaft.model import PointLoad
from shaftline.shaft.ntua import ntua_shaft_line

CLEARANCE = 0.45e-3
TARGET_COUPLED = 1.0  # s
TARGET_FAST = 0.2  # s


SEED_LINE, SEED_FILM = ntua_shaft_line(0.3)


def film_problem() -> BearingProblem:
    return BearingProblem(
        BearingGeometry(1.05, 0.52, CLEARANCE),
        OperatingPoint(speed=9.4248, viscosity=0.07),
        SolverOptions(axial_nodes=100, circumferential_nodes=60),
    )


def test_line() -> ShaftLine:
    """The 14 m line of tests/shaft/test_coupled.py (its end moment nose-down)."""
    return ShaftLine(
        segments=(ShaftSegment(length=14.0, outer_diameter=0.52),),
        bearings=(
            Bearing("aft", 0.407 + 0.525, 1.05, support="multi_point", points=6),
            Bearing("fwd", 6.0, 0.6),
            Bearing("int", 13.0, 0.5, offset_y=-0.5e-3),
        ),
        point_loads=(PointLoad(0.0, force_y=-202598.2, moment_vertical=-409948.0),),
        element_length=0.25,
    )


def coupled() -> CoupledResult:
    return CoupledAlignment(SEED_LINE, [SEED_FILM]).solve()


def coupled_test_line() -> CoupledResult:
    return CoupledAlignment(test_line(), [FilmSupport("aft", film_problem())]).solve()


def seed_fast_path() -> FastPathResult:
    """Seed 004's bypass on the same line: point-support alignment, local shaft model, bent
    journal, one film equilibrium."""
    return fast_path(SEED_LINE, SEED_FILM)


def instrumented(repeat: int) -> dict[str, float]:
    """Mean wall time inside the main pieces of a coupled solve over ``repeat`` runs, s (nested: the film derivatives
    are part of the film solutions; the start's equilibrium makes film solutions of its own,
    not counted with them)."""
    spent: dict[str, float] = defaultdict(float)
    patched: list[tuple[type, str, Callable[..., Any]]] = []

    def wrap(owner: type, name: str, label: str) -> None:
        original = getattr(owner, name)

        def timed(*args: Any, **kwargs: Any) -> Any:
            start = time.perf_counter()
            try:
                return original(*args, **kwargs)
            finally:
                spent[label] += time.perf_counter() - start

        patched.append((owner, name, original))
        setattr(owner, name, timed)

    wrap(FilmSolver, "load_changes", "film derivatives (frozen set)")
    wrap(JournalBearing, "film_load", "film solutions incl. derivatives")
    wrap(AlignmentModel, "solve_condition", "inner alignment solves")
    wrap(AlignmentModel, "displacement_response", "alignment unit-load response")
    wrap(JournalBearing, "equilibrium", "start: uncoupled film equilibrium")
    wrap(CoupledAlignment, "__init__", "model set-up")
    try:
        for _ in range(repeat):
            start = time.perf_counter()
            coupled()
            spent["total"] += time.perf_counter() - start
    finally:
        for owner, name, original in reversed(patched):
            setattr(owner, name, original)
    return {label: seconds / repeat for label, seconds in spent.items()}


def main() -> None:
    repeat = int(sys.argv[sys.argv.index("--repeat") + 1]) if "--repeat" in sys.argv else 7
    coupled()  # imports, numba caches
    seed_fast_path()
    t_coupled, result = median_time(coupled, repeat)
    t_fast, fast = median_time(seed_fast_path, repeat)
    film = result.film(SEED_FILM.bearing)
    print(f"Coupled alignment, seed 004 shaft line (psi_x = 0.3), aft stern tube as a 100 x 60 film ({repeat} repeats)")
    print(
        f"  converged {result.converged} in {result.iterations} Newton iterations, "
        f"{result.film_solutions} film solutions; residuals " + ", ".join(f"{r:.2g}" for r in result.residual_history)
    )
    state = fast.state
    print(
        f"  coupled: hmin {film.state.min_film_thickness * 1e6:.1f} um, pmax {film.state.max_pressure / 1e6:.2f} MPa, "
        f"support point {film.support_point_y * 1e3:+.1f} mm from L/2 (+ forward, vertical); fast path: hmin "
        f"{state.min_film_thickness * 1e6:.1f} um, pmax {state.max_pressure / 1e6:.2f} MPa, "
        f"support point {fast.support_point * 1e3:+.1f} mm"
    )
    print(
        f"  coupled solve (model built, cold film): {t_coupled:.3f} s median "
        f"(target <= {TARGET_COUPLED} s, ratio {t_coupled / TARGET_COUPLED:.2f})"
    )
    print(
        f"  fast path (alignment, local model, one film equilibrium): {t_fast:.3f} s median "
        f"(target <= {TARGET_FAST} s, ratio {t_fast / TARGET_FAST:.2f})"
    )
    print(f"  coupled / fast path: {t_coupled / t_fast:.1f}")
    spent = instrumented(repeat)
    total = spent.pop("total")
    print(f"  instrumented coupled solve, mean of {repeat}: {total:.3f} s")
    for label, seconds in sorted(spent.items(), key=lambda item: -item[1]):
        print(f"    {label:36s} {seconds:.3f} s ({seconds / total:.0%})")
    t_test, other = median_time(coupled_test_line, repeat)
    print(
        f"  the 14 m test line (nose-down end moment), same film: {t_test:.3f} s median, "
        f"{other.iterations} iterations, {other.film_solutions} film solutions"
    )


if __name__ == "__main__":
    main()
