"""The steps of the equilibrium's Newton iteration: the candidate steps, the line search that
keeps the film above its floor, and each trial's start (docs/theory.md Sect. 4.1 and 6)."""

from __future__ import annotations

from collections.abc import Iterator
from dataclasses import replace

import numpy as np

from shaftline.film.cavitation import CavitationConvergenceError
from shaftline.film.geometry import JournalPosition
from shaftline.film.lined import LinerConvergenceError
from shaftline.film.solver import FilmSolution, FilmSolver, NegativeFilm

__all__ = ["candidate_steps", "line_search", "moved", "predicted_cavitation"]


def moved(position: JournalPosition, step: np.ndarray) -> JournalPosition:
    """``position`` with its offsets moved by ``step`` (m, (2,))."""
    return replace(position, ey=position.ey + float(step[0]), ez=position.ez + float(step[1]))


def limit_step(step: np.ndarray, c: float) -> np.ndarray:
    """``step`` shortened to at most half the radial clearance ``c``."""
    length = float(np.hypot(*step))
    limit = 0.5 * c
    return step if length <= limit else step * (limit / length)


def candidate_steps(
    jacobian: np.ndarray, residual: np.ndarray, load: np.ndarray, c: float
) -> Iterator[tuple[np.ndarray, float]]:
    """Newton step first, with its Armijo share; then the damped fallbacks: steepest descent of
    ``|r|^2/2`` and a push along the load (which walks a load that is too large down to the film
    floor), each to be accepted where it lowers the residual at all."""
    try:
        yield limit_step(np.linalg.solve(jacobian, -residual), c), 1e-4
    except np.linalg.LinAlgError:
        pass
    gradient = -jacobian.T @ residual
    if np.any(gradient):
        yield 0.1 * c * gradient / float(np.hypot(*gradient)), 0.0
    yield 0.1 * c * load / float(np.hypot(*load)), 0.0


def predicted_cavitation(
    solver: FilmSolver, solution: FilmSolution, response: tuple[np.ndarray, np.ndarray], step: np.ndarray
) -> tuple[np.ndarray | None, np.ndarray | None]:
    """Start of the active set after the journal moves by ``step`` (m): a set, or a pressure
    guess from which the model predicts it (its ``trial_guess``: the Reynolds condition's
    ``P + dP`` with the set frozen, whose set a few sweeps on the new film sharpen); (None, None)
    for a model whose solver predicts a warm start's set itself (the mass-conserving model's
    chord step) or that has no set."""
    return None, solver.cavitation.trial_guess(solution.relative_pressure, step, response[1])


def _boundary_share(
    solver: FilmSolver,
    solution: FilmSolution,
    response: tuple[np.ndarray, np.ndarray],
    step: np.ndarray,
    floor: float,
) -> float:
    """The share of ``step`` that the fraction to the boundary allows: never close more than 80 %
    of the film left above the floor (with a liner the film predicted with its deformation)."""
    position = solution.position
    lined = solution.deformation is not None
    hmin_now = float(solution.film.min())  # rigid: the film at ``position``; lined: with its liner
    alpha = 1.0
    while alpha > 1e-8:
        there = moved(position, alpha * step)
        if lined:
            predicted = solver.predicted_deformation(solution, response, alpha * step)
            assert predicted is not None
            hmin_next = float((solver.film(there) + predicted).min())
        else:
            hmin_next = solver.min_film(there)
        if hmin_next - floor >= 0.2 * (hmin_now - floor):
            break
        alpha *= 0.5
    return alpha


def line_search(
    solver: FilmSolver,
    solution: FilmSolution,
    response: tuple[np.ndarray, np.ndarray],
    step: np.ndarray,
    load: np.ndarray,
    norm: float,
    sufficient: float,
    liner_tolerance: float,
    refine: bool = False,
    loose: bool = False,
) -> FilmSolution | None:
    """Backtracking that keeps the film above the floor and lowers the force residual
    (by the Armijo share ``sufficient * alpha`` for a Newton step, at all for a fallback).

    Each trial starts its active set from the one predicted by the step from the solution's
    ``response`` (the residual and pressure changes per metre of ey and ez of
    :meth:`~shaftline.film.solver.FilmSolver.position_response`; see :func:`predicted_cavitation`);
    with ``refine`` each trial starts from the solution's set and iterates its pressure from that
    guess, otherwise with ``loose`` its set may stop short of settling. None when no share of the
    step lowers the residual enough."""
    floor = solver.surfaces.floor
    approach = solver.surfaces.approach_floor
    if approach > floor and float(solution.film.min()) > 2.0 * approach:
        # A rough film approaches the mean plane as it did when that was its floor, and passes
        # it only from there: a long step through it from a thick film lands in the contact
        # zone's one-node pressure spikes and ends in a spurious equilibrium (docs/theory.md,
        # "Boundary lubrication").
        floor = approach
    alpha = _boundary_share(solver, solution, response, step, floor)
    boundary = alpha  # the step the fraction to the boundary allows
    while alpha > 1e-8:
        there = moved(solution.position, alpha * step)
        try:
            start, guess = predicted_cavitation(solver, solution, response, alpha * step)
            if refine and guess is not None:
                trial = solver.evaluate(there, solution.cavitated, refine_from=guess)
            else:
                trial = solver.evaluate(
                    there,
                    start,
                    guess=guess,
                    deformation=solver.predicted_deformation(solution, response, alpha * step),
                    chord=solution.liner_system,
                    liner_tolerance=liner_tolerance,
                    settle=not loose,
                )
        except (NegativeFilm, LinerConvergenceError):
            alpha *= 0.5
            continue
        except CavitationConvergenceError:
            if not solver.surfaces.rough:
                raise
            # A rough trial far past the mean plane: the closing mean gap's pressure spike
            # can keep the active set from settling; a shorter step (docs/theory.md,
            # "Boundary lubrication").
            alpha *= 0.5
            continue
        if np.hypot(*(trial.force + load)) < (1.0 - sufficient * alpha) * norm:
            trial.shortened = alpha < boundary
            return trial
        alpha *= 0.5
    return None
