"""The film linearised about a solution: stiffness and damping (2 x 2 and the 4 x 4 set with the
tilt terms) and the film load along a journal centre line of any shape.

Every derivative here is that of the discrete film force with the cavitated set frozen
(:meth:`~shaftline.film.solver.FilmSolver.load_changes`): one back-substitution of the converged
factor per direction (docs/theory.md Sect. 7). The 4 x 4 coefficients of a journal at a position
and of a journal along a bent centre line (the elastohydrodynamic alignment's) are the same
computation, :func:`tilt_linearisation`, of the film solved there.
"""

from __future__ import annotations

from dataclasses import replace

import numpy as np

from shaftline.errors import InputError
from shaftline.film.geometry import BearingGeometry, BentJournal, JournalPosition
from shaftline.film.results import FilmLinearisation, FilmLoad, TiltLinearisation
from shaftline.film.solver import Direction, FilmSolution, FilmSolver, NegativeFilm
from shaftline.film.state import bearing_state

__all__ = ["centre_line", "film_load", "linearise", "line_solution", "tilt_linearisation"]


def linearise(solver: FilmSolver, position: JournalPosition, start: np.ndarray | None = None) -> FilmLinearisation:
    """Film force at ``position`` and its derivatives by journal offset and velocity
    (:meth:`shaftline.film.JournalBearing.linearise`), solved from ``start`` or the coarse grids,
    never from an earlier call."""
    solution = solver.evaluate_inside(position, warm=False, start=start)
    d_ey, d_ez = solver.offset_directions(solution)
    # A velocity changes the squeeze term (2/omega) dH/dt, not the film itself.
    rate = 2.0 / solver.problem.operating.speed
    zero = np.zeros(solution.film.shape)
    directions: list[Direction] = [(d_ey, None), (d_ez, None), (zero, rate * d_ey), (zero, rate * d_ez)]
    _, d_pressure, d_contact = solver.load_changes(solution, directions)
    dfy, dfz, dfvy, dfvz = (
        solver.force(solution.grid, dp, gauge=False, contact=dc) for dp, dc in zip(d_pressure, d_contact, strict=True)
    )
    return FilmLinearisation(
        position=solution.position,
        force=solution.force,
        offset_derivative=np.column_stack([dfy, dfz]),
        velocity_derivative=np.column_stack([dfvy, dfvz]),
    )


def tilt_linearisation(solver: FilmSolver, solution: FilmSolution) -> TiltLinearisation:
    """Film force and moment of ``solution`` and their derivatives by journal offset, tilt and
    their rates, the journal moving as a rigid body about its mid-plane: the 4 x 4 stiffness
    and damping (docs/theory.md Sect. 7.1).

    A tilt changes the film by ``dh = -(z - L/2)(d tilt_y cos(theta) + s d tilt_z sin(theta))``, a
    tilt rate gives that as a squeeze ``dh/dt`` varying along the bearing; the eight derivatives
    reuse the factorisation of the converged active set, one triangular solve each. The top-left
    2 x 2 blocks are those of :func:`linearise`.
    """
    d_ey, d_ez = solver.offset_directions(solution)
    arm = (solution.grid.z - 0.5 * solver.geometry.length)[:, None]
    # dH per radian of tilt: the offset direction times the lever arm from the mid-plane.
    shapes = [d_ey, d_ez, arm * d_ey, arm * d_ez]
    rate = 2.0 / solver.problem.operating.speed
    zero = np.zeros(solution.film.shape)
    directions: list[Direction] = [(d, None) for d in shapes]
    directions += [(zero, rate * d) for d in shapes]
    _, d_pressure, d_contact = solver.load_changes(solution, directions)
    grid = solution.grid
    columns = [
        np.concatenate(
            [
                solver.force(grid, dp, gauge=False, contact=dc),
                solver.moment(grid, dp, gauge=False, contact=dc),
            ]
        )
        for dp, dc in zip(d_pressure, d_contact, strict=True)
    ]
    return TiltLinearisation(
        position=solution.position,
        force=solution.force,
        moment=solver.moment(grid, solution.relative_pressure, contact=solution.contact),
        offset_derivative=np.column_stack(columns[:4]),
        velocity_derivative=np.column_stack(columns[4:]),
    )


def centre_line(
    geometry: BearingGeometry, z: np.ndarray, centre_y: np.ndarray, centre_z: np.ndarray
) -> tuple[JournalPosition, BearingGeometry]:
    """The mid-plane position and chord tilt of a journal centre line at the axial stations ``z``
    (m), and the geometry whose bent journal is the rest of it (see :func:`film_load`).

    Raises
    ------
    InputError
        ``"centre_y"`` (or ``"centre_z"``) for a line of the wrong length or not finite.
    """
    line_y = np.asarray(centre_y, dtype=float)
    line_z = np.asarray(centre_z, dtype=float)
    for name, line in (("centre_y", line_y), ("centre_z", line_z)):
        if line.shape != z.shape or not np.all(np.isfinite(line)):
            raise InputError(name, f"shape {line.shape}", "m", f"{z.size} finite offsets, one per axial station")
    length = geometry.length
    mid_y, mid_z = float(np.interp(0.5 * length, z, line_y)), float(np.interp(0.5 * length, z, line_z))
    tilt_y, tilt_z = (line_y[-1] - line_y[0]) / length, (line_z[-1] - line_z[0]) / length
    arm = z - 0.5 * length
    bent = BentJournal(z=z, dy=line_y - mid_y - tilt_y * arm, dz=line_z - mid_z - tilt_z * arm)
    position = JournalPosition(ey=mid_y, ez=mid_z, tilt_y=float(tilt_y), tilt_z=float(tilt_z))
    return position, replace(geometry, bent_journal=bent)


def line_solution(
    solver: FilmSolver,
    centre_y: np.ndarray,
    centre_z: np.ndarray,
    warm_start: bool = True,
    start: np.ndarray | None = None,
) -> FilmSolution:
    """The film solved with the journal along a centre line (:func:`film_load`'s arguments).

    Raises
    ------
    InputError
        ``"centre_y"`` for a line of the wrong length or one that cuts into the bore.
    """
    position, geometry = centre_line(solver.geometry, solver.grid.z, centre_y, centre_z)
    try:
        return solver.evaluate(position, start, warm=warm_start, geometry=geometry)
    except NegativeFilm as exc:
        raise InputError(
            "centre_y", f"hmin {exc.value:.3g}", "m", "a journal centre line inside the clearance"
        ) from None


def film_load(
    solver: FilmSolver,
    centre_y: np.ndarray,
    centre_z: np.ndarray,
    directions: np.ndarray | None = None,
    warm_start: bool = True,
    start: np.ndarray | None = None,
    velocity_directions: np.ndarray | None = None,
) -> FilmLoad:
    """Film solution and its load along the bearing for a journal centre line of any shape
    (:meth:`shaftline.film.JournalBearing.film_load`, where the arguments are described)."""
    solution = line_solution(solver, centre_y, centre_z, warm_start, start)
    state = bearing_state(solver, solution)
    row_force = solver.row_forces(solution.grid, solution.relative_pressure, gauge=True, contact=solution.contact)
    theta = solution.grid.theta
    c = solver.geometry.radial_clearance
    rotation = solver.geometry.rotation

    def film_change(lines: np.ndarray) -> np.ndarray:
        """dH (k, nz, nt) of centre-line changes (k, 2, nz), m per unit."""
        steps = np.asarray(lines, dtype=float)
        cos, sin = np.cos(theta)[None, None, :], np.sin(theta)[None, None, :]
        return -(steps[:, 0, :, None] * cos + rotation * steps[:, 1, :, None] * sin) / c

    requests: list[Direction] = []
    if directions is not None:
        requests += [(d, None) for d in film_change(directions)]
    moving = 0
    if velocity_directions is not None:
        # A velocity changes the squeeze term (2/omega) dH/dt, not the film (as linearise).
        rate = 2.0 / solver.problem.operating.speed
        zero = np.zeros(solution.film.shape)
        changes = film_change(velocity_directions)
        requests += [(zero, rate * d) for d in changes]
        moving = len(changes)
    if requests:
        _, d_pressure, d_contact = solver.load_changes(solution, requests)
        rows = np.stack(
            [
                solver.row_forces(solution.grid, dp, gauge=False, contact=dc)
                for dp, dc in zip(d_pressure, d_contact, strict=True)
            ],
            axis=-1,
        )
    else:
        rows = np.zeros((2, solver.grid.z.size, 0))
    split = rows.shape[-1] - moving
    return FilmLoad(
        state=state, row_force=row_force, derivative=rows[..., :split], velocity_derivative=rows[..., split:]
    )
