"""The equilibrium's Newton iteration: the journal's mid-plane offsets at which the film carries
the load, with the tilts held (docs/theory.md Sect. 6).

Newton's method on ``force(ey, ez) + load = 0`` with the Jacobian from the reused factorisation
(frozen active set), a fraction-to-boundary rule that keeps the film above its floor and a
backtracking line search on the residual (:mod:`~shaftline.film.equilibrium.steps`), from a
start of :mod:`~shaftline.film.equilibrium.starts`; a rigid rough bore whose steps stall or crawl
is settled (:mod:`~shaftline.film.equilibrium.settling`). With a liner, each trial's liner is
solved only as far as the force residual needs (an inexact Newton method).
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, replace

import numpy as np

from shaftline.film.equilibrium.settling import StallRule, resolves_contact_zone, settle
from shaftline.film.equilibrium.starts import (
    coarse_start,
    initial_position,
    pull_inside,
    rigid_start,
    smooth_rigid_active_set,
    start_solution,
)
from shaftline.film.equilibrium.steps import candidate_steps, line_search
from shaftline.film.geometry import JournalPosition
from shaftline.film.lined import LinerConvergenceError
from shaftline.film.solver import FilmSolution, FilmSolver

__all__ = ["Found", "find_equilibrium"]

Progress = Callable[[int, float], None]


@dataclass
class Found:
    """Where :func:`find_equilibrium` ended: its last film solution, whether it converged or met
    the film floor, its Newton iterations on this grid and force residual (N), whether its start
    was solved (False: a lined start whose film-liner iteration did not settle at any position
    tried, reported as it is), and the Newton iterations of every equilibrium it took, its
    starts' included."""

    solution: FilmSolution
    converged: bool
    contact: bool
    iterations: int
    residual: float
    started: bool = True
    newton_iterations: int = 0


def find_equilibrium(
    solver: FilmSolver,
    load: np.ndarray,
    tilt_y: float,
    tilt_z: float,
    initial: JournalPosition | None = None,
    progress: Progress | None = None,
    start_set: np.ndarray | None = None,
    deformation: np.ndarray | None = None,
) -> Found:
    """The equilibrium of ``solver``'s film under ``load`` (N, (2,), not zero) with the tilts held
    (rad), up to its last film solution, without the state: the coarse grid's and the rigid
    bore's equilibria, which only start another, need no more (the state's extremes, flows and
    friction cost a film solution's worth on a small grid).

    ``initial`` starts Newton there (else the coarse grid's equilibrium, a lined bearing's rigid
    bore's or the closed form); ``start_set`` the first film solution's cavitated set (checked
    against the grid); ``deformation`` its liner's. ``progress`` is told each Newton iteration
    and its force residual over the load. The result depends only on the problem and these
    arguments, never on earlier calls."""
    solution, started, start_iterations = _first_solution(solver, load, tilt_y, tilt_z, initial, start_set, deformation)
    if not started:
        # No position of the retreat settles the film-liner iteration: the start itself,
        # its liner as the iteration left it, reported as not converged.
        norm = float(np.hypot(*(solution.force + load)))
        return Found(solution, False, False, 0, norm, started=False, newton_iterations=start_iterations)
    found = _Newton(solver, load, progress).run(solution)
    found.newton_iterations = start_iterations + found.iterations
    return found


def _first_solution(
    solver: FilmSolver,
    load: np.ndarray,
    tilt_y: float,
    tilt_z: float,
    initial: JournalPosition | None,
    start_set: np.ndarray | None,
    deformation: np.ndarray | None,
) -> tuple[FilmSolution, bool, int]:
    """The film solution Newton starts from, whether it was solved, and the Newton iterations of
    the equilibria that placed it."""
    floor = solver.surfaces.floor
    guess = None
    iterations = 0
    if initial is None:
        coarse = coarse_start(solver, load, tilt_y, tilt_z, find_equilibrium)
        if coarse is not None:
            initial, guess, iterations = coarse
    if initial is None and solver.lined:
        rigid = rigid_start(solver, load, tilt_y, tilt_z, find_equilibrium)
        if rigid is not None:
            initial, spent = rigid
            iterations += spent
            if solver.min_film(initial) < solver.surfaces.approach_floor:
                # A rigid rough bore in boundary lubrication (its film below the mean plane) is no
                # start for the liner (seed 001's rig at 15 rpm: the lined Newton stalls from it at
                # 12 % of the load): the default start instead.
                initial = None
    position = initial or initial_position(solver, load, tilt_y, tilt_z)
    position = replace(position, tilt_y=tilt_y, tilt_z=tilt_z, vy=0.0, vz=0.0)
    if solver.min_film(position) <= floor:
        position = pull_inside(solver, position, floor)
    # Start the active set from the coarse grid, never from an earlier call: the
    # equilibrium then depends only on the problem and its arguments.
    solver.clear_history()
    start = solver.start_set(start_set)
    if start is not None:
        guess = None  # the caller's set comes first
    # A smooth rigid bore's Newton iterates far from the equilibrium leave their active sets a
    # few nodes short of settling (docs/theory.md Sect. 4.1): the converged one is settled.
    loose = smooth_rigid_active_set(solver)
    solution, started = start_solution(solver, position, start, guess, settle=not loose, deformation=deformation)
    return solution, started, iterations


class _Newton:
    """One Newton iteration of an equilibrium (:func:`find_equilibrium`) from its first solution."""

    def __init__(self, solver: FilmSolver, load: np.ndarray, progress: Progress | None) -> None:
        options = solver.options
        self.solver = solver
        self.load = load
        self.progress = progress
        self.magnitude = float(np.hypot(*load))
        self.tolerance = options.tolerance * self.magnitude
        self.final_share = 0.1 * options.tolerance  # force share the converged liner may leave
        # Below this residual an unsettled iterate is settled before its step: its force error
        # (1e-6 to 1e-5 of the load) would steer a step meant to reach the tolerance, and a line
        # search measuring progress against it can reject every step (a start at the root).
        self.settle_below = solver.cavitation.unsettled_residual(options) * self.magnitude
        self.loose = smooth_rigid_active_set(solver)
        # A liner carries any load by deforming (the journal may pass the rigid bore surface):
        # the stall rule of a rigid rough bore does not apply to it.
        self.rough = solver.surfaces.rough and not solver.lined
        self.refinable = not solver.lined and solver.cavitation.refines_trials

    def run(self, solution: FilmSolution) -> Found:
        solver, load = self.solver, self.load
        residual = solution.force + load
        contact = unsettled = False
        iterations = 0
        rule = StallRule()
        while iterations < solver.options.max_iterations:
            norm = float(np.hypot(*residual))
            required = self._liner_tolerance(solution, norm)
            if solution.liner_residual > required:
                # A liner solved more loosely than this residual needs (a trial's tolerance came
                # from its parent's larger residual): finish it, then look again.
                finished = self._finish_liner(solution, required)
                if finished is None:
                    unsettled = True
                    break
                solution, residual = finished, finished.force + load
                continue
            if not solution.settled and norm <= self.settle_below:
                solution = solver.settled(solution)
                residual = solution.force + load
                continue
            if norm <= self.tolerance:
                break
            iterations += 1
            accepted = self._step(solution, residual, norm, required)
            if accepted is None:
                solution, iterations, contact = self._stuck(solution, iterations)
                residual = solution.force + load
                break
            solution, residual = accepted, accepted.force + load
            if self.progress is not None:
                self.progress(iterations, float(np.hypot(*residual)) / self.magnitude)
            if self.rough and rule.update(solver, float(np.hypot(*residual)) / norm, solution.shortened):
                # A rigid rough bore whose steps only crawl: stopped after a few such steps instead
                # of spending max_iterations (docs/theory.md, "Boundary lubrication", "Rigid rough
                # bore at low speed").
                solution, iterations, contact = self._stalled(solution, iterations)
                residual = solution.force + load
                break
        return self._finished(solution, residual, contact, unsettled, iterations)

    def _liner_tolerance(self, solution: FilmSolution, norm: float) -> float:
        """The liner tolerance this residual needs (0 without a liner)."""
        share = self.final_share
        if norm > self.tolerance:
            share = max(self.final_share, self.solver.options.liner.inexact * norm / self.magnitude)
        return self.solver.liner_tolerance(solution, share)

    def _finish_liner(self, solution: FilmSolution, required: float) -> FilmSolution | None:
        """``solution`` with its liner solved to ``required``; None where it does not settle that
        far (seed 001's rig at 15 rpm, aligned, on 41 x 120 with min_film_floor 1e-4): reported as
        not converged, the position and liner as they are, rather than as an exception."""
        try:
            return self.solver.evaluate(
                solution.position,
                solution.cavitated,
                deformation=solution.deformation,
                chord=solution.liner_system or solution.nearby_system,
                liner_tolerance=required,
            )
        except LinerConvergenceError:
            return None

    def _step(self, solution: FilmSolution, residual: np.ndarray, norm: float, required: float) -> FilmSolution | None:
        """The next iterate: the first candidate step whose line search lowers the residual."""
        solver, magnitude = self.solver, self.magnitude
        newton = solver.options.newton
        if solution.liner_system is None and norm > newton.nearby_jacobian * magnitude:
            # Far from the equilibrium the Jacobian from the last matrix factorised in this
            # film's liner iteration (at an iterate within its residual) steers as well as the
            # exact one; none factorised there (chord steps only): the exact one.
            solution.liner_system = solution.nearby_system
        jacobian, d_residual, d_pressure = solver.position_response(solution)
        # Near the equilibrium the step barely changes the film: its trials are iterated from
        # the linear pressure guess with this film's factor (no factorisation, no set sweeps).
        refine = self.refinable and norm <= newton.refine_residual * magnitude
        loose = self.loose and norm > self.settle_below
        c = solver.geometry.radial_clearance
        for step, sufficient in candidate_steps(jacobian, residual, self.load, c):
            accepted = line_search(
                solver, solution, (d_residual, d_pressure), step, self.load, norm, sufficient, required, refine, loose
            )
            if accepted is not None:
                return accepted
        return None

    def _stuck(self, solution: FilmSolution, iterations: int) -> tuple[FilmSolution, int, bool]:
        """No step lowers the residual: contact where the film is at its floor; a rigid rough bore
        above it whose grid resolves the contact zone is settled."""
        solver = self.solver
        lined = solution.deformation is not None
        hmin = float(solution.film.min()) if lined else solver.min_film(solution.position)
        contact = solver.surfaces.at_floor(hmin, solver.options.newton.floor_margin)
        if self.rough and not contact and resolves_contact_zone(solver, solution):
            return settle(solver, solution, self.load, self.tolerance, iterations, self.progress)
        return solution, iterations, contact

    def _stalled(self, solution: FilmSolution, iterations: int) -> tuple[FilmSolution, int, bool]:
        """A stalled or crawling rigid rough bore: contact only at the boundary limit, where the
        asperities at the model's end cannot carry the rest of the load; above it the journal is
        settled along its net force where the grid resolves the contact zone, else reported as
        not converged."""
        solver = self.solver
        contact = solver.surfaces.at_floor(solver.min_film(solution.position), solver.options.newton.floor_margin)
        if not contact and resolves_contact_zone(solver, solution):
            return settle(solver, solution, self.load, self.tolerance, iterations, self.progress)
        return solution, iterations, contact

    def _finished(
        self, solution: FilmSolution, residual: np.ndarray, contact: bool, unsettled: bool, iterations: int
    ) -> Found:
        """The last iterate as the equilibrium's solution: its exact Jacobian's matrix and its
        settled set (an iterate stopped before converging may have neither)."""
        if solution.liner_system is solution.nearby_system:
            solution.liner_system = None  # the state's derivatives are the exact ones
        if not solution.settled:  # stopped before converging (contact, a stall)
            solution = self.solver.settled(solution)
            residual = solution.force + self.load
        norm = float(np.hypot(*residual))
        converged = norm <= self.tolerance and not unsettled
        return Found(solution, converged, contact, iterations, norm)
