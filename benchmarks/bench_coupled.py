"""Elastohydrodynamic alignment timing (issue 11 targets) against seed 004's fast path.

Run: ``.venv/bin/python benchmarks/bench_coupled.py [--repeat N]``. Prints medians and ratios.

Coupled: a 14 m line on seed 004's aft stern-tube bearing as a film (L = 1.05 m, D = 0.52 m,
c = 0.45 mm, 90 rpm, 0.07 Pa s; Table 5-1) on a 100 x 60 grid, a forward stern-tube and an
intermediate bearing as points, the propeller end force of Table 4-5 and its end moment
nose-down (with the seed's nose-up sign this line's film reaches its floor and the solver
falls back to contact); ``CoupledAlignment(line, films).solve()`` from scratch (model built,
film solver state cold) <= 1 s median on the 2-core machine.

Fast path (seed 004 Sect. 4.5.2-4.5.4): the local shaft model (``shaftline.shaft.local``,
Table 4-5, psi_x = 0.3) gives the bent journal, then one film load equilibrium with that
journal and the chord tilt, same bearing and grid: <= 0.2 s median.

Also printed: Newton iterations and film solutions of the coupled solve, and where its time
goes (film solutions with their frozen-set derivatives, the inner alignment solves, the
alignment's response to unit loads, the set-up), from instrumented runs (means).
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
from shaftline.shaft import AlignmentModel, Bearing, ShaftLine, ShaftSegment
from shaftline.shaft.coupled import CoupledAlignment, CoupledResult, FilmSupport
from shaftline.shaft.local import LocalShaftModel, solve_local_model
from shaftline.shaft.model import PointLoad

CLEARANCE = 0.45e-3
TARGET_COUPLED = 1.0  # s
TARGET_FAST = 0.2  # s


def film_problem() -> BearingProblem:
    return BearingProblem(
        BearingGeometry(1.05, 0.52, CLEARANCE),
        OperatingPoint(speed=9.4248, viscosity=0.07),
        SolverOptions(axial_nodes=100, circumferential_nodes=60),
    )


def line() -> ShaftLine:
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
    return CoupledAlignment(line(), [FilmSupport("aft", film_problem())]).solve()


def fast_path():
    """Seed 004's bypass: local shaft model, bent journal, one film equilibrium."""
    local = LocalShaftModel.from_misalignment(
        0.3,
        radial_clearance=CLEARANCE,
        bearing_length=1.05,
        shaft_diameter=0.52,
        aft_overhang=0.407,
        fore_length=0.5412,
        aft_force=-202598.2,
        aft_moment=409948.0,
        fore_force=-107261.7,
        fore_rotation=0.000465,
        weight_per_length=16343.0,
        shear_area_factor=1.0,
    )
    shaft = solve_local_model(local)
    slope, bent = shaft.bent_journal()
    problem = film_problem()
    geometry = problem.geometry.__class__(**{**problem.geometry.__dict__, "bent_journal": bent})
    bearing = JournalBearing(geometry, problem.operating, problem.options)
    return bearing.equilibrium(load_y=-float(shaft.edge_reactions.sum()), tilt_y=slope)


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

    wrap(JournalBearing, "_pressure_derivatives", "film derivatives (frozen set)")
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
    fast_path()
    # Pairs in one process, alternating, so that load from other jobs hits both alike.
    t_coupled, result = median_time(coupled, repeat)
    t_fast, fast = median_time(fast_path, repeat)
    film = result.film("aft")
    print(f"Coupled alignment, NTUA-like 14 m line, aft stern tube as a 100 x 60 film ({repeat} repeats)")
    print(
        f"  converged {result.converged} in {result.iterations} Newton iterations, "
        f"{result.film_solutions} film solutions; residuals " + ", ".join(f"{r:.2g}" for r in result.residual_history)
    )
    print(
        f"  hmin {film.state.min_film_thickness * 1e6:.1f} um, pmax {film.state.max_pressure / 1e6:.2f} MPa, "
        f"support point {film.support_point * 1e3:+.1f} mm from L/2 (+ forward), e {film.state.eccentricity_ratio:.3f}"
    )
    print(
        f"  coupled solve (model built, cold film): {t_coupled:.3f} s median "
        f"(target <= {TARGET_COUPLED} s, ratio {t_coupled / TARGET_COUPLED:.2f})"
    )
    state = fast.state
    print(
        f"  fast path (local model + one film equilibrium): {t_fast:.3f} s median "
        f"(target <= {TARGET_FAST} s, ratio {t_fast / TARGET_FAST:.2f}); "
        f"hmin {state.min_film_thickness * 1e6:.1f} um, pmax {state.max_pressure / 1e6:.2f} MPa "
        "(Table 4-5's loading and psi_x = 0.3, not the coupled line's)"
    )
    print(f"  coupled / fast path: {t_coupled / t_fast:.1f}")
    spent = instrumented(repeat)
    total = spent.pop("total")
    print(f"  instrumented coupled solve, mean of {repeat}: {total:.3f} s")
    for label, seconds in sorted(spent.items(), key=lambda item: -item[1]):
        print(f"    {label:36s} {seconds:.3f} s ({seconds / total:.0%})")


if __name__ == "__main__":
    main()
