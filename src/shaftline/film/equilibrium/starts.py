"""Where an equilibrium's Newton iteration starts: the closed-form estimate, the equilibrium on
the grid halved both ways (grid continuation), a lined bearing's rigid bore, and the retreat of
a lined start whose film-liner iteration does not settle (docs/theory.md Sect. 4.1 and 17).

The starts that are equilibria themselves take the finder as an argument (``find``: the
equilibrium of :mod:`shaftline.film.equilibrium.newton`), so this module does not import it.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Iterator
from dataclasses import replace
from typing import TYPE_CHECKING

import numpy as np

from shaftline.errors import InputError, SolverFailure
from shaftline.film.analytic import eccentricity_guess
from shaftline.film.geometry import (
    MIN_AXIAL_NODES,
    MIN_CIRCUMFERENTIAL_NODES,
    BearingGeometry,
    JournalPosition,
    coarse_shape,
)
from shaftline.film.lined import LinerConvergenceError, film_solver
from shaftline.film.problem import BearingProblem, OperatingPoint
from shaftline.film.solver import FilmSolution, FilmSolver

if TYPE_CHECKING:
    from shaftline.film.equilibrium.newton import Found

__all__ = [
    "closed_form_offsets",
    "coarse_start",
    "initial_position",
    "pull_inside",
    "retreat",
    "rigid_start",
    "smooth_rigid_active_set",
    "start_solution",
]

#: The equilibrium of a solver under a load (N, (2,)) with tilts (rad):
#: :func:`~shaftline.film.equilibrium.newton.find_equilibrium`.
Finder = Callable[[FilmSolver, np.ndarray, float, float], "Found"]


def closed_form_offsets(
    geometry: BearingGeometry, operating: OperatingPoint, load_y: float, load_z: float, max_eccentricity: float = 1.0
) -> tuple[float, float]:
    """Journal offsets (ey, ez) from the bore centre that carry the load by the closed-form
    finite-bearing estimate (:func:`shaftline.film.analytic.eccentricity_guess`), m.

    The cold start of an equilibrium (with the eccentricity ratio capped at
    ``max_eccentricity``) and, uncapped and so smooth in the load, the part of a swept position
    that :func:`shaftline.film.sweep` does not extrapolate. The load must not be zero.
    """
    g = geometry
    mean_pressure = math.hypot(load_y, load_z) / (g.length * g.diameter)
    sommerfeld = (g.radius / g.radial_clearance) ** 2 * operating.viscosity * (operating.speed / (2 * math.pi))
    epsilon, attitude = eccentricity_guess(sommerfeld / mean_pressure, g.length / g.diameter)
    epsilon = min(epsilon, max_eccentricity)
    load_angle = math.atan2(g.rotation * load_z, load_y)
    local = JournalPosition.from_polar(epsilon * g.radial_clearance, load_angle + attitude, g.rotation)
    return local.ey, local.ez


def initial_position(solver: FilmSolver, load: np.ndarray, tilt_y: float, tilt_z: float) -> JournalPosition:
    """The closed-form start (:func:`closed_form_offsets`, eccentricity ratio at most 0.95) about the
    bore's centre at the mid-plane, with the tilts."""
    g = solver.geometry
    ey, ez = closed_form_offsets(g, solver.problem.operating, float(load[0]), float(load[1]), max_eccentricity=0.95)
    bore_y, bore_z = g.bore_centre_line(np.array([0.5 * g.length]))
    return JournalPosition(ey=ey + float(bore_y[0]), ez=ez + float(bore_z[0]), tilt_y=tilt_y, tilt_z=tilt_z)


def pull_inside(solver: FilmSolver, position: JournalPosition, floor: float) -> JournalPosition:
    """``position`` drawn towards the bore's axis until the film is well above ``floor`` (m).

    Raises
    ------
    InputError
        Naming the larger tilt, when both tilts together do not fit in the clearance.
    """
    for _ in range(200):
        if solver.min_film(position) > 2.0 * max(floor, 0.0) + 0.05 * solver.geometry.radial_clearance:
            return position
        position = replace(position, ey=0.8 * position.ey, ez=0.8 * position.ez)
    # Both tilts together do not fit; name the larger, which is the one to reduce first.
    name = "tilt_y" if abs(position.tilt_y) >= abs(position.tilt_z) else "tilt_z"
    raise InputError(
        name,
        getattr(position, name),
        "rad",
        "a misalignment that fits in the clearance with the journal centred "
        f"(tilt_y, tilt_z = {position.tilt_y:.4g}, {position.tilt_z:.4g} rad)",
    )


def smooth_rigid_active_set(solver: FilmSolver) -> bool:
    """A smooth rigid bore with an active-set cavitation model (Reynolds condition or JFO): the
    film whose equilibrium continues from ``ContinuationOptions.nodes`` and leaves its far
    iterates unsettled."""
    return not solver.lined and not solver.surfaces.rough and solver.cavitation.active_set


def coarse_start(
    solver: FilmSolver, load: np.ndarray, tilt_y: float, tilt_z: float, find: Finder
) -> tuple[JournalPosition, np.ndarray, int] | None:
    """Equilibrium position on the grid halved in both directions (grid continuation), its
    solution's start field (the model's ``start_field``) brought onto this grid (the start of the
    first film solution's active set) and the Newton iterations it took; None on a grid below
    ``ContinuationOptions.nodes`` (``other_nodes`` with a liner or a rough surface) or where it does
    not converge. A film whose model ``starts_from_coarse_contact`` (the Reynolds condition, on a
    smooth rigid bore) whose coarse equilibrium's line search ends at the film floor starts from
    where it ended: the fine film is then at or near its floor too, and its own iteration decides
    (NTUA at twice the load and the tilt, 100 x 60: 24 fine iterations crawling from the
    closed-form start to contact, 2 from the coarse end, 121 -> 37 ms).

    Depends only on the problem and the arguments, as the equilibrium does."""
    options, continuation = solver.options, solver.options.continuation
    shape = coarse_shape((options.axial_nodes, options.circumferential_nodes))
    # The mass-conserving film on a smooth rigid bore continues from the same grids and to the
    # same force tolerance (its fine start then comes from the coarse JFO unknown).
    smooth = smooth_rigid_active_set(solver)
    plain = smooth and solver.cavitation.starts_from_coarse_contact
    threshold = continuation.nodes if smooth else continuation.other_nodes
    coarse_tolerance = continuation.tolerance if smooth else continuation.other_tolerance
    if options.axial_nodes * options.circumferential_nodes < threshold or shape is None:
        return None
    if shape[0] < MIN_AXIAL_NODES or shape[1] < MIN_CIRCUMFERENTIAL_NODES:
        return None  # a grid too coarse to resolve the film is no start (e.g. 200 x 30)
    if solver.coarse is None:
        coarse_options = replace(
            options,
            axial_nodes=shape[0],
            circumferential_nodes=shape[1],
            tolerance=max(options.tolerance, coarse_tolerance),
        )
        problem = solver.problem
        solver.coarse = film_solver(BearingProblem(problem.geometry, problem.operating, coarse_options), solver.counts)
    coarse = find(solver.coarse, load, tilt_y, tilt_z)
    if not ((coarse.converged and not coarse.contact) or (plain and coarse.contact)):
        return None
    field = solver.coarse.cavitation.start_field(coarse.solution.cavitation, coarse.solution.relative_pressure)
    # Both grids start at the same angle at the same position, so the coarse rows and
    # columns are the fine model's coarse grid's (CoarseGrid: every other column, rows
    # evenly from edge to edge).
    grid = solver.cavitation.coarse_grid()
    assert grid is not None and grid.model.nodes.shape == field.shape  # both coarse_shape's
    return coarse.solution.position, grid.prolong(field), coarse.newton_iterations


def rigid_start(
    solver: FilmSolver, load: np.ndarray, tilt_y: float, tilt_z: float, find: Finder
) -> tuple[JournalPosition, int] | None:
    """Equilibrium position of the same bearing with a rigid bore (the liner left out) and its
    Newton iterations, or None where it does not converge or ends in contact: the start of a
    lined equilibrium.

    A rigid film solution costs one factorisation of the film operator, a film-liner one
    several of the coupled matrix; far from the equilibrium, where the journal's steps are
    cut by the fraction-to-the-boundary rule, the rigid bearing takes them at that price
    (NTUA 100 x 60 polymer liner at 1 rpm: 9 lined Newton iterations from the default start,
    6 from the rigid equilibrium). Depends only on the problem and the arguments."""
    if solver.rigid is None:
        # Its force tolerance is the coarse start's: it only places the start.
        options = solver.options
        options = replace(options, tolerance=max(options.tolerance, options.continuation.other_tolerance))
        problem = solver.problem
        solver.rigid = film_solver(
            BearingProblem(replace(problem.geometry, liner=None), problem.operating, options), solver.counts
        )
    try:
        rigid = find(solver.rigid, load, tilt_y, tilt_z)
    except SolverFailure:
        return None
    if not rigid.converged or rigid.contact:
        return None
    return rigid.solution.position, rigid.newton_iterations


def retreat(solver: FilmSolver, position: JournalPosition) -> Iterator[JournalPosition]:
    """Positions on the way from ``position`` to the bore's centre at the mid-plane (tilts
    kept): the offset shortened by the surfaces' start lift times 1, 2, 4, ... (the rigid film's
    minimum rises by about that much), the centre last."""
    g = solver.geometry
    bore_y, bore_z = (float(v[0]) for v in g.bore_centre_line(np.array([0.5 * g.length])))
    dy, dz = position.ey - bore_y, position.ez - bore_z
    offset = float(np.hypot(dy, dz))
    lift = solver.surfaces.start_lift(solver.options.newton.start_lift)
    while lift < offset:
        share = 1.0 - lift / offset
        yield replace(position, ey=bore_y + share * dy, ez=bore_z + share * dz)
        lift *= 2.0
    yield replace(position, ey=bore_y, ez=bore_z)


def start_solution(
    solver: FilmSolver,
    position: JournalPosition,
    start: np.ndarray | None,
    guess: np.ndarray | None = None,
    settle: bool = True,
    deformation: np.ndarray | None = None,
) -> tuple[FilmSolution, bool]:
    """The equilibrium's first film solution, at ``position`` or, where an elastic liner's
    film-liner iteration does not settle there, at the first position of :func:`retreat`
    where it does; and whether one settled. None settling: the solution the iteration left
    at ``position`` (its liner unsettled) and False.

    A journal started far into a soft liner (a misaligned or bent journal whose closed-form
    start puts its edge below the mean plane: seed 001's rig at 15 and 35 rpm, psi 5e-5 rad)
    can leave the film-liner Newton iteration without a descent; a journal lifted off the
    liner by a few roughness heights settles, and the equilibrium's Newton iteration then
    takes it down to the equilibrium, with its line search rejecting trials that do not
    settle (docs/theory.md, "Starting a lined equilibrium")."""
    try:
        return solver.evaluate(position, start, guess=guess, settle=settle, deformation=deformation), True
    except LinerConvergenceError as failure:
        first = failure
    for lifted in retreat(solver, position):
        try:
            return solver.evaluate(lifted, start), True
        except LinerConvergenceError:
            continue
    solution = first.evaluation
    assert solution is not None  # raised by the film-liner iteration, which attaches its iterate
    solution.liner_residual = first.residual
    return solution, False
