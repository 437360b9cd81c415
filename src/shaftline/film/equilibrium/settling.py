"""A rigid rough bore's equilibrium where Newton stalls: the stall and crawl rules, and the
pseudo-transient settling that follows the net force past the contact zone's force peak
(docs/theory.md, "Boundary lubrication", "Settling", "The stall rule and crawling Newton steps")."""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

from shaftline.film.cavitation import CavitationConvergenceError
from shaftline.film.equilibrium.steps import moved, predicted_cavitation
from shaftline.film.solver import FilmSolution, FilmSolver, NegativeFilm

__all__ = ["StallRule", "settle"]

Progress = Callable[[int, float], None]


@dataclass
class StallRule:
    """The Newton iterations in a row that stalled (each left more than ``stalled_reduction`` of
    the residual) and that crawled (each a step the line search's residual test shortened, leaving
    more than ``crawl_reduction``: the NTUA rigid rough bore at 12.4 rpm took Newton steps cut to
    1/16, 1-3 % each, for 45 iterations); steps cut only by the fraction to the boundary (a film
    approaching its floor) do not count (``NewtonOptions``)."""

    stalled: int = 0
    crawled: int = 0

    def update(self, solver: FilmSolver, left: float, shortened: bool) -> bool:
        """Count an iteration that left ``left`` of the residual; True when the rule stops Newton."""
        options = solver.options.newton
        self.stalled = self.stalled + 1 if left > options.stalled_reduction else 0
        self.crawled = self.crawled + 1 if left > options.crawl_reduction and shortened else 0
        return self.stalled >= options.stalled_iterations or self.crawled >= options.crawl_iterations


def resolves_contact_zone(solver: FilmSolver, solution: FilmSolution) -> bool:
    """Whether the grid resolves the rough contact zone of ``solution``'s film well enough for
    the settling (``SettleOptions.zone_nodes``)."""
    return solver.surfaces.zone_nodes(solution.film) >= solver.options.settling.zone_nodes


def newton_trial(
    solver: FilmSolver,
    solution: FilmSolution,
    jacobian: np.ndarray,
    response: tuple[np.ndarray, np.ndarray],
    load: np.ndarray,
    norm: float,
) -> FilmSolution | None:
    """The full Newton step from ``solution`` if it stays above the film floor, moves the journal
    at most ``SettleOptions.max_move`` sigma and halves the force residual, else None."""
    residual = solution.force + load
    try:
        step = np.linalg.solve(jacobian, -residual)
    except np.linalg.LinAlgError:
        return None
    sigma = solver.surfaces.sigma
    if float(np.hypot(*step)) > solver.options.settling.max_move * sigma:
        return None
    there = moved(solution.position, step)
    if solver.min_film(there) < solver.surfaces.floor:
        return None
    try:
        start, guess = predicted_cavitation(solver, solution, response, step)
        trial = solver.evaluate(there, start, guess=guess)
    except (NegativeFilm, CavitationConvergenceError):
        return None
    return trial if np.hypot(*(trial.force + load)) < 0.5 * norm else None


def _limited_step(solver: FilmSolver, solution: FilmSolution, step: np.ndarray) -> np.ndarray | None:
    """``step`` (m) cut to at most ``max_move`` sigma and to where the film stops a margin above
    the boundary limit; None when the film is at that margin already and the step presses it
    further (contact)."""
    sigma = solver.surfaces.sigma
    options = solver.options.settling
    margin = solver.options.newton.floor_margin
    floor = solver.surfaces.floor
    length = float(np.hypot(*step))
    if length > options.max_move * sigma:
        step = step * (options.max_move * sigma / length)
    hmin_now = solver.min_film(solution.position)
    hmin_next = solver.min_film(moved(solution.position, step))
    if hmin_next < floor + margin * sigma:
        if hmin_now <= floor + margin * sigma:
            return None  # at the limit and pressed further down
        # Stop at the limit: the share of the step that leaves the margin above it.
        share = (hmin_now - floor - margin * sigma) / max(hmin_now - hmin_next, 1e-300)
        step = step * max(min(share, 1.0), 0.0)
    return step


def settle(
    solver: FilmSolver,
    solution: FilmSolution,
    load: np.ndarray,
    tolerance: float,
    iterations: int,
    progress: Progress | None,
) -> tuple[FilmSolution, int, bool]:
    """Pseudo-transient continuation of a rigid rough bore's equilibrium where Newton stalls:
    the journal moves with the net force, ``dx/dt = force + load``, by implicit Euler steps
    ``(I/delta - J) dx = force + load`` whose pseudo-time step ``delta`` grows as the residual
    falls (switched evolution relaxation), so the iteration becomes Newton's near the
    equilibrium (Kelley & Keyes, SIAM J. Numer. Anal. 35 (1998) 508-523). Newton's line search
    asks the residual to fall; the film force of a contact zone one or two cells wide is not
    monotone in the journal's position (it peaks near the mean plane and dips below it), so
    Newton stops at a local minimum of the residual on the wrong side of the peak, where the
    force rises as the journal lifts. The net force there still pushes the journal down, and
    following it passes the peak, as the journal itself would.

    Returns the last solution, the iterations counted on, and whether it ended in contact (the
    film at the boundary limit with the force still pressing it down)."""
    sigma = solver.surfaces.sigma
    options = solver.options.settling
    residual = solution.force + load
    norm = float(np.hypot(*residual))
    magnitude = float(np.hypot(*load))
    delta = options.first_move * sigma / norm
    used = 0
    while used < solver.options.max_iterations:
        if norm <= tolerance:
            return solution, iterations, False
        jacobian, d_residual, d_pressure = solver.position_response(solution)
        newton = newton_trial(solver, solution, jacobian, (d_residual, d_pressure), load, norm)
        used += 1
        if newton is not None:
            # Near the equilibrium a full Newton step that halves the residual is taken: the
            # settling's own steps converge only linearly along the soft (attitude) direction.
            solution, residual = newton, newton.force + load
        else:
            try:
                step = np.linalg.solve(np.eye(2) / delta - jacobian, residual)
            except np.linalg.LinAlgError:
                delta *= 0.25
                continue
            limited = _limited_step(solver, solution, step)
            if limited is None:
                return solution, iterations, True
            try:
                start, guess = predicted_cavitation(solver, solution, (d_residual, d_pressure), limited)
                trial = solver.evaluate(moved(solution.position, limited), start, guess=guess)
            except (NegativeFilm, CavitationConvergenceError):
                delta *= 0.25
                continue
            new_norm = float(np.hypot(*(trial.force + load)))
            if new_norm > options.growth * norm:
                delta *= 0.25  # a step too long for the local force: shorter pseudo-time
                continue
            # Switched evolution relaxation: the pseudo-time step grows as the residual falls.
            # At least doubled after a step that lowers it: a journal sliding slowly along a valley
            # of the residual (its force nearly carrying the load) must not crawl.
            ratio = norm / new_norm if new_norm > 0.0 else 10.0
            delta *= min(max(ratio, 2.0), 10.0) if ratio > 1.0 else max(ratio, 0.1)
            solution, residual = trial, trial.force + load
        norm = float(np.hypot(*residual))
        iterations += 1
        if progress is not None:
            progress(iterations, norm / magnitude)
    margin = solver.options.newton.floor_margin
    return solution, iterations, solver.surfaces.at_floor(solver.min_film(solution.position), margin)
