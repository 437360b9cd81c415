"""An equilibrium from its inputs to its result: the load and the start checked, the Newton
driver run (:func:`~shaftline.film.equilibrium.newton.find_equilibrium`), its last film
solution turned into the state, with the work it took."""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import replace

import numpy as np

from shaftline.errors import InputError, require_finite
from shaftline.film.equilibrium.newton import Found, find_equilibrium
from shaftline.film.geometry import JournalPosition
from shaftline.film.results import Equilibrium
from shaftline.film.solver import FilmSolver

__all__ = ["solve_equilibrium"]


def solve_equilibrium(
    solver: FilmSolver,
    load_y: float,
    load_z: float,
    tilt_y: float,
    tilt_z: float,
    initial: JournalPosition | None = None,
    progress: Callable[[int, float], None] | None = None,
    initial_cavitated: np.ndarray | None = None,
    initial_deformation: np.ndarray | None = None,
) -> Equilibrium:
    """The equilibrium of ``solver``'s film under the load (N) with the tilts held (rad), as
    :meth:`shaftline.film.bearing.JournalBearing.equilibrium` documents it (its arguments, the
    errors it raises and the result)."""
    load = _checked_load(load_y, load_z, tilt_y, tilt_z)
    deformation = _checked_deformation(solver, initial_deformation)
    before = solver.counts.copy()
    found = find_equilibrium(solver, load, tilt_y, tilt_z, initial, progress, initial_cavitated, deformation)
    return _result(solver, found, load, before.film_solutions, before.factorisations)


def _result(solver: FilmSolver, found: Found, load: np.ndarray, solutions: int, factorisations: int) -> Equilibrium:
    """The result of the Newton driver's ``found`` under ``load`` (N), with the work it took
    since the solver's counters stood at ``solutions`` and ``factorisations``: a start that did
    not converge with the film at its floor is contact."""
    from shaftline.film.state import bearing_state

    state = bearing_state(solver, found.solution, load=load)
    contact = found.contact
    margin = solver.options.newton.floor_margin
    if found.started and not found.converged and solver.surfaces.at_floor(state.min_film_thickness, margin):
        contact = True
    if contact:
        state = replace(state, contact=True)
    return Equilibrium(
        state,
        float(load[0]),
        float(load[1]),
        found.converged,
        contact,
        found.iterations,
        found.residual,
        newton_iterations=found.newton_iterations,
        film_solutions=solver.counts.film_solutions - solutions,
        factorisations=solver.counts.factorisations - factorisations,
    )


def _checked_load(load_y: float, load_z: float, tilt_y: float, tilt_z: float) -> np.ndarray:
    """The load (N, (2,)) of an equilibrium, its four inputs checked finite and the load not zero."""
    load = np.array([require_finite("load_y", load_y, "N"), require_finite("load_z", load_z, "N")])
    require_finite("tilt_y", tilt_y, "rad")
    require_finite("tilt_z", tilt_z, "rad")
    if float(np.hypot(*load)) == 0.0:
        raise InputError("load_y", 0.0, "N", "a non-zero load (load_y, load_z): a loaded bearing")
    return load


def _checked_deformation(solver: FilmSolver, initial_deformation: np.ndarray | None) -> np.ndarray | None:
    """A caller's start deformation (m), checked against the grid (None without a liner)."""
    if solver.geometry.liner is None or initial_deformation is None:
        return None
    deformation = np.array(initial_deformation, dtype=float)
    shape = (solver.options.axial_nodes, solver.options.circumferential_nodes)
    if deformation.shape != shape or not np.all(np.isfinite(deformation)):
        raise InputError(
            "initial_deformation",
            f"an array of shape {deformation.shape}",
            "m",
            f"finite values on the bearing's grid, shape {shape}",
        )
    return deformation
