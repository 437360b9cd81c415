"""Solving bearing studies: one case at equilibrium with its stiffness and damping, a study's
cases and its Stribeck curve, and many cases at once, grouped by film problem, warm-started and
spread over cores.

A load x speed map, a robustness table or the variants of a case file are many
:class:`~shaftline.film.study.BearingCase` s of which most share their film problem
(geometry, operating point, solver options: a :class:`~shaftline.film.problem.BearingProblem`)
and differ in load and tilt. :func:`sweep` solves them as follows:

1. **Group** the cases by their problem (compared by value). Each group is solved with one
   :class:`~shaftline.film.JournalBearing`, which keeps its sparsity pattern and coarse
   grids from one case to the next.
2. **Order** each group by tilt, then load magnitude and direction, and cut it into
   contiguous chunks of at most ``chunk_size`` cases. The chunks depend on the cases only,
   never on the number of workers, so the results do not either.
3. **Warm-start** each case from the nearest solved case of its chunk (distance in load
   over the chunk's largest load and tilt over ``2c/L``): Newton starts at a position
   extrapolated along the line of solved neighbours (constant, linear or quadratic in the
   distance, as many collinear neighbours as there are), which leaves one or two Newton
   iterations where a cold start takes four to six. A warm start that ends in contact or
   without convergence is solved again from the cold start, so a difficult case gets the
   answer it gets alone.
4. **Spread** the chunks over workers with :func:`shaftline.parallel.map`; this process
   solves chunks from the end of the list while the workers start (``work_here``).

The equilibrium of each case is the same problem whatever its start (Newton to
``SolverOptions.tolerance`` on the force), so a sweep agrees with the cases solved one by
one within that tolerance, and is bit for bit the same on any backend and worker count:
each chunk is the same sequence of operations on a fresh bearing wherever it runs.
"""

from __future__ import annotations

import functools
import math
import pickle
from collections.abc import Callable, Sequence
from dataclasses import dataclass, replace
from typing import TYPE_CHECKING

import numpy as np

from shaftline.film.bearing import JournalBearing
from shaftline.film.equilibrium import closed_form_offsets
from shaftline.film.geometry import JournalPosition
from shaftline.film.problem import BearingProblem
from shaftline.film.study import BearingCase, BearingResult, BearingStudy, BearingStudyResult

if TYPE_CHECKING:
    from shaftline.film.thermal import ThermalResult

__all__ = ["DEFAULT_CHUNK_SIZE", "solve_case", "solve_study", "sweep"]

#: Largest number of cases solved one after the other by one worker (one cold start each):
#: large enough that the cold start is rare, small enough to share a large group of cases
#: among a few workers.
DEFAULT_CHUNK_SIZE = 32

#: Points further than this share of the step from the line through the nearest solved
#: case and the new one are not on it (the extrapolation then uses fewer points).
_COLLINEAR = 1e-6
#: Neighbours on the line used by the extrapolation: quadratic. A cubic one (4) saved no
#: Newton iteration on the benchmark's load lines, a quartic one cost some (noise amplified).
_MAX_POINTS = 3


@dataclass(frozen=True, eq=False)
class _Chunk:
    """What a worker receives: cases of one problem in the order to solve them."""

    problem: BearingProblem
    cases: tuple[BearingCase, ...]
    coefficients: bool


def _parameters(cases: Sequence[BearingCase], problem: BearingProblem) -> np.ndarray:
    """(load_y, load_z, tilt_y, tilt_z) of each case, scaled to order one, shape (n, 4)."""
    loads = np.array([[case.load_y, case.load_z] for case in cases], dtype=float)
    tilts = np.array([[case.tilt_y, case.tilt_z] for case in cases], dtype=float)
    load_scale = float(np.max(np.hypot(loads[:, 0], loads[:, 1]))) or 1.0
    tilt_scale = 2.0 * problem.geometry.radial_clearance / problem.geometry.length
    return np.hstack([loads / load_scale, tilts / tilt_scale])


def _analytic_offsets(problem: BearingProblem, load_y: float, load_z: float) -> np.ndarray:
    """The closed-form offsets of :func:`~shaftline.film.equilibrium.closed_form_offsets` (not
    capped: smooth in the load), m; NaN for no load."""
    magnitude = math.hypot(load_y, load_z)
    if not magnitude or not math.isfinite(magnitude):
        return np.full(2, np.nan)
    return np.array(closed_form_offsets(problem.geometry, problem.operating, load_y, load_z), dtype=float)


def _predict(
    parameters: np.ndarray, new: int, solved: list[int], positions: dict[int, np.ndarray], parents: dict[int, int]
) -> tuple[int, np.ndarray] | None:
    """Start of case ``new``: nearest usable solved case and its position extrapolated along
    the line of that case's own warm-start ancestors where they lie on the line to ``new``.

    ``positions`` hold what is extrapolated: the solved offsets less their closed-form
    estimate, which carries most of the change with the load, so that the remainder is
    smooth and small (the closed form is then added back by the caller)."""
    usable = [k for k in solved if k in positions]
    if not usable:
        return None
    distances = np.linalg.norm(parameters[usable] - parameters[new], axis=1)
    nearest = usable[int(np.argmin(distances))]  # first of equals: a fixed choice
    step = parameters[new] - parameters[nearest]
    length = float(np.linalg.norm(step))
    points = [(0.0, positions[nearest])]
    k = nearest
    while len(points) < _MAX_POINTS and k in parents and parents[k] in positions and length > 0.0:
        k = parents[k]
        offset = parameters[k] - parameters[nearest]
        s = float(offset @ step) / length
        if s >= -1e-12 * length or np.linalg.norm(offset - s * step / length) > _COLLINEAR * length:
            break
        points.append((s, positions[k]))
    # Lagrange extrapolation to s = length through the collinear points.
    prediction = np.zeros(2)
    for i, (si, qi) in enumerate(points):
        weight = 1.0
        for j, (sj, _) in enumerate(points):
            if j != i:
                weight *= (length - sj) / (si - sj)
        prediction += weight * qi
    return nearest, prediction


def _solve_chunk(chunk: _Chunk, progress: Callable[[str], None] | None = None) -> list[BearingResult]:
    """Solve a chunk's cases in order on one bearing, each warm-started from its nearest
    solved neighbour (run in a worker process, or here for the serial backend)."""
    bearing = JournalBearing.from_problem(chunk.problem)
    parameters = _parameters(chunk.cases, chunk.problem)
    analytic = [_analytic_offsets(chunk.problem, case.load_y, case.load_z) for case in chunk.cases]
    positions: dict[int, np.ndarray] = {}
    parents: dict[int, int] = {}
    cavitated: dict[int, np.ndarray] = {}
    results: list[BearingResult] = []
    for index, case in enumerate(chunk.cases):
        if progress is not None:
            progress(case.name)
        guess = _predict(parameters, index, list(range(index)), positions, parents)
        initial = None
        start_set = None
        if guess is not None:
            parents[index] = guess[0]
            ey, ez = (float(v) for v in guess[1] + analytic[index])
            initial = JournalPosition(ey=ey, ez=ez, tilt_y=case.tilt_y, tilt_z=case.tilt_z)
            # The neighbour's cavitated set spares the first film solution its cold start
            # (coarse grids and several fine factorisations); the result does not depend on it.
            start_set = cavitated.get(guess[0])
        result = solve_case(
            case,
            progress,
            bearing=bearing,
            initial=initial,
            coefficients=chunk.coefficients,
            initial_cavitated=start_set,
        )
        if initial is not None and (result.equilibrium.contact or not result.equilibrium.converged):
            # A hard case (at the film floor, or not settling): its answer is the cold start's,
            # as when it is solved alone.
            result = solve_case(case, progress, bearing=bearing, coefficients=chunk.coefficients)
        equilibrium = result.equilibrium
        if equilibrium.converged and not equilibrium.contact:
            position = equilibrium.state.position
            offsets = np.array([position.ey, position.ez], dtype=float) - analytic[index]
            if np.all(np.isfinite(offsets)):
                positions[index] = offsets
                cavitated[index] = equilibrium.state.cavitated
        results.append(result)
    return results


def _problem_key(problem: BearingProblem) -> bytes:
    """Equal problems, equal keys: the pickle of the problem (arrays of a bent journal or
    film profile compare by value here, where the dataclasses compare them by identity)."""
    return pickle.dumps(problem, protocol=pickle.HIGHEST_PROTOCOL)


def _order_key(case: BearingCase, index: int) -> tuple[float, ...]:
    return (
        case.tilt_y,
        case.tilt_z,
        math.hypot(case.load_y, case.load_z),
        math.atan2(case.load_z, case.load_y),
        float(index),
    )


def _chunks(cases: Sequence[BearingCase], chunk_size: int, coefficients: bool) -> list[tuple[list[int], _Chunk]]:
    """Cases grouped by problem, each group ordered and cut into near-equal contiguous chunks,
    with the indices of their cases; in the order of each group's first case."""
    groups: dict[bytes, tuple[BearingProblem, list[int]]] = {}
    for index, case in enumerate(cases):
        problem = BearingProblem(case.geometry, case.operating, case.options)
        groups.setdefault(_problem_key(problem), (problem, []))[1].append(index)
    out = []
    for problem, members in groups.values():
        members = sorted(members, key=lambda i: _order_key(cases[i], i))
        count = -(-len(members) // chunk_size)
        bounds = np.linspace(0, len(members), count + 1).round().astype(int)
        for start, stop in zip(bounds[:-1], bounds[1:], strict=True):
            part = members[start:stop]
            out.append((part, _Chunk(problem, tuple(cases[i] for i in part), coefficients)))
    return out


def sweep(
    cases: Sequence[BearingCase],
    *,
    coefficients: bool = True,
    backend: str | None = None,
    workers: int | None = None,
    scheduler: str | None = None,
    chunk_size: int = DEFAULT_CHUNK_SIZE,
    progress: Callable[[str], None] | None = None,
) -> list[BearingResult]:
    """Equilibrium (and stiffness and damping) of many bearing cases, reusing work between them.

    Parameters
    ----------
    cases : sequence of BearingCase
        Any mix of problems, loads and tilts.
    coefficients : bool
        Also the stiffness and damping at each equilibrium that the film carries (as
        :func:`solve_case`).
    backend, workers, scheduler :
        Where to run: :func:`shaftline.parallel.map` (default a process pool with one worker
        per core; ``"serial"``; or ``"dask"`` with the address of a scheduler). A sweep of a
        single chunk runs here.
    chunk_size : int
        Largest number of cases one worker solves in a row (>= 1).
    progress : callable, optional
        Told each case's name and its Newton iterations when the cases are solved in this
        process; from a pool, how many cases are done as chunks finish.

    Returns
    -------
    list of BearingResult
        In the order of ``cases``.

    Raises
    ------
    InputError
        From a case (named as in the case file where the case says so), or ``"chunk_size"``.

    Examples
    --------
    >>> from shaftline.film import BearingGeometry, OperatingPoint, SolverOptions
    >>> from shaftline.film.study import BearingCase
    >>> geometry = BearingGeometry(length=0.1, diameter=0.1, radial_clearance=1e-4)
    >>> cases = [
    ...     BearingCase(f"{w} N", geometry, OperatingPoint(speed=100.0, viscosity=0.02), SolverOptions(), load_y=-w)
    ...     for w in (4e3, 5e3, 6e3)
    ... ]
    >>> [round(r.equilibrium.state.eccentricity_ratio, 2) for r in sweep(cases, backend="serial")]
    [0.47, 0.53, 0.58]
    """
    from shaftline import parallel
    from shaftline.errors import InputError

    if isinstance(chunk_size, bool) or not isinstance(chunk_size, int) or chunk_size < 1:
        raise InputError("chunk_size", chunk_size, "", "an integer >= 1")
    cases = list(cases)
    chunks = _chunks(cases, chunk_size, coefficients)
    name = parallel.backend_name(backend, workers, scheduler)  # checked even when it runs here
    local = name == "serial" or (scheduler is None and (workers == 1 or len(chunks) <= 1))
    function = functools.partial(_solve_chunk, progress=progress if local else None)
    single = all(len(part) == 1 for part, _ in chunks)

    def told(finished: int, total: int) -> None:
        if progress is not None:
            what = "bearing cases" if single else f"chunks of {len(cases)} bearing cases"
            progress(f"{what}, {finished} of {total} done")

    solved = parallel.map(
        function,
        [chunk for _, chunk in chunks],
        backend="serial" if local else name,
        workers=workers,
        scheduler=scheduler,
        progress=None if local else told,
        work_here=True,  # a chunk's answer is the same wherever it is solved
    )
    return _in_case_order(cases, chunks, solved)


def _in_case_order(
    cases: list[BearingCase], chunks: list[tuple[list[int], _Chunk]], solved: Sequence[Sequence[BearingResult]]
) -> list[BearingResult]:
    """The chunks' results in the order of ``cases``, each with its own case (a chunk solved in
    another process holds a copy)."""
    results: list[BearingResult | None] = [None] * len(cases)
    for (part, _), chunk_results in zip(chunks, solved, strict=True):
        for index, result in zip(part, chunk_results, strict=True):
            results[index] = replace(result, case=cases[index])
    return [result for result in results if result is not None]


def solve_case(
    case: BearingCase,
    progress: Callable[[str], None] | None = None,
    bearing: JournalBearing | None = None,
    initial: JournalPosition | None = None,
    coefficients: bool = True,
    initial_cavitated: np.ndarray | None = None,
) -> BearingResult:
    """Equilibrium under the case load, then stiffness and damping there (not at contact).

    ``progress``, when given, is told each Newton iteration of the equilibrium
    (``"base: Newton iteration 3, force residual 2.1e-04 of the load"``) and the start of the
    stiffness and damping: on a fine grid each takes seconds to minutes.

    ``bearing`` is a :class:`~shaftline.film.JournalBearing` of the case's problem to reuse
    (its factorisation pattern and coarse grids; :func:`shaftline.film.sweep` passes one per
    group of cases), ``initial`` the start of the equilibrium's Newton iteration and
    ``initial_cavitated`` the cavitated set of its first film solution (a warm start from a
    solved neighbour). Without them the case is solved from scratch. ``coefficients``
    False leaves out the stiffness and damping.
    """
    from shaftline.errors import located
    from shaftline.film.dynamics import dynamic_coefficients

    def newton(iteration: int, residual: float) -> None:
        if progress is not None:
            progress(f"{case.name}: Newton iteration {iteration}, force residual {residual:.1e} of the load")

    balance = None
    if case.thermal is not None:
        case, balance = _at_effective_temperature(case, progress)
        # The viscosity changed: neither the given bearing nor its warm start applies.
        bearing, initial, initial_cavitated = None, None, None
    if bearing is None:
        bearing = JournalBearing(case.geometry, case.operating, case.options)
    # A tilt that does not fit in the clearance is found only here; name it as the case file does.
    with located("", case.error_fields):
        equilibrium = bearing.equilibrium(
            case.load_y,
            case.load_z,
            tilt_y=case.tilt_y,
            tilt_z=case.tilt_z,
            initial=initial,
            progress=newton,
            initial_cavitated=initial_cavitated,
        )
    dynamics = None
    if coefficients and equilibrium.converged and not equilibrium.contact:
        if progress is not None:
            progress(f"{case.name}: stiffness and damping")
        dynamics = dynamic_coefficients(bearing, equilibrium.state)
    return BearingResult(case, equilibrium, dynamics, balance)


def _at_effective_temperature(
    case: BearingCase, progress: Callable[[str], None] | None
) -> tuple[BearingCase, ThermalResult]:
    """The heat balance of ``case`` (docs/theory.md Sect. 8.1) and the case at its effective
    temperature; a balance that does not close below the top of the viscosity model leaves
    the case at that top temperature (``converged`` False)."""
    from shaftline.errors import located
    from shaftline.film.thermal import bearing_film, thermal_balance

    assert case.thermal is not None
    if case.lubricant is None:
        raise ValueError(f"{case.name}: a heat balance needs the case's lubricant")
    if progress is not None:
        progress(f"{case.name}: heat balance")
    problem = BearingProblem(case.geometry, case.operating, case.options)
    with located("", case.error_fields):
        balance = thermal_balance(
            bearing_film(problem, case.load_y, case.load_z, case.tilt_y, case.tilt_z), case.lubricant, case.thermal
        )
    temperature = balance.effective_temperature
    operating = replace(case.operating, viscosity=balance.viscosity, density=float(case.lubricant.density(temperature)))
    return replace(case, operating=operating, temperature=temperature), balance


def solve_study(
    study: BearingStudy,
    progress: Callable[[str], None] | None = None,
    *,
    backend: str | None = None,
    workers: int | None = None,
    scheduler: str | None = None,
    stribeck: bool = False,
) -> BearingStudyResult:
    """Solve the base case and every variant with :func:`shaftline.film.sweep`: variants with
    the same film problem share one bearing and warm-start from each other, and the groups
    run on a process pool (``backend``, ``workers``, ``scheduler`` as in
    :func:`shaftline.parallel.map`).

    ``progress`` is told each case's name, then its Newton iterations (:func:`solve_case`),
    when the cases are solved in this process (serially, or one group only); from a pool it
    is told how many cases are done each time a chunk of them finishes (a chunk is the cases
    of one film problem, up to ``chunk_size`` of :func:`shaftline.film.sweep`).
    """
    results = sweep(study.cases, backend=backend, workers=workers, scheduler=scheduler, progress=progress)
    curve = None
    if stribeck:
        from shaftline.film.stribeck import stribeck_curve

        if progress is not None:
            progress(f"{study.cases[0].name}: Stribeck curve, {len(study.stribeck_speeds)} speeds")

        def chunks_done(done: int, total: int) -> None:
            if progress is not None:
                progress(f"{study.cases[0].name}: Stribeck curve, {done} of {total} groups of speeds done")

        curve = stribeck_curve(
            study.cases[0],
            study.stribeck_speeds,
            backend=backend,
            workers=workers,
            scheduler=scheduler,
            progress=chunks_done,
        )
    return BearingStudyResult(tuple(results), curve)
