"""The bearing state of a film solution: forces and moments, the located extremes, friction and
flows, with the parts its surfaces, liner and turbulence model add (docs/theory.md Sect. 5).

Flows come from the discrete face fluxes, consistent with the solver's mass balance; the film
and pressure extremes are located between nodes (:mod:`shaftline.film.extremes`).
"""

from __future__ import annotations

import math

import numpy as np

from shaftline.film.extremes import local_extreme
from shaftline.film.results import BearingState, LinerState, TurbulenceState
from shaftline.film.solver import FilmSolution, FilmSolver
from shaftline.film.turbulence import couette_shear_factor

__all__ = ["bearing_state"]


def _attitude_angle(
    rotation: int, eccentricity: float, angle: float, force: tuple[float, float], load: np.ndarray | None
) -> float:
    """Angle (rad) from the load line to the line of centres at ``angle``, in the sense of
    rotation; the load line is ``load``'s, or without a load the line opposite the film
    ``force`` (what the film carries). Zero for a centred journal."""
    fy, fz = force
    if load is None:
        load_angle = float(np.arctan2(-rotation * fz, -fy))
    else:
        load_angle = float(np.arctan2(rotation * load[1], load[0]))
    return float((angle - load_angle + np.pi) % (2 * np.pi) - np.pi) if eccentricity > 0 else 0.0


def _sommerfeld_number(radius_ratio: float, viscosity: float, speed: float, mean_pressure: float) -> float:
    """``(R/c)^2 eta N / P`` with ``N`` in rev/s (``speed`` in rad/s); infinite without load."""
    return radius_ratio**2 * viscosity * (speed / (2 * np.pi)) / mean_pressure if mean_pressure > 0 else math.inf


def bearing_state(solver: FilmSolver, solution: FilmSolution, load: np.ndarray | None = None) -> BearingState:
    """The :class:`BearingState` of ``solution``; ``load`` (2,), N, is the applied load whose
    line the attitude angle is measured from (without it: the line opposite the film force)."""
    g = solver.geometry
    grid = solution.grid
    theta, z = grid.theta.copy(), grid.z.copy()  # the state's own (the grid's are shared, read-only)
    film = solution.film
    pressure = solver.gauge(solution.relative_pressure)
    fy, fz = (float(v) for v in solution.force)
    capacity = float(np.hypot(fy, fz))
    e, angle = solver.local_polar(solution.position)
    attitude = _attitude_angle(g.rotation, e, angle, (fy, fz), load)
    # Extremes between nodes (docs/theory.md): the film is smooth everywhere; the pressure
    # only on free nodes (fixed-pressure and cavitated values are not samples of it).
    thinnest = local_extreme(film)
    free = ~(solver.nodes.fixed | solution.cavitated)
    peak = local_extreme(pressure, usable=free, maximum=True)
    moment_y, moment_z = _moments(solver, solution, pressure, theta, z)
    offset = (moment_y * fy + moment_z * fz) / capacity**2 if capacity > 0 else 0.0
    local_reynolds = solver.reynolds_number * np.maximum(film, 0.0) / g.radial_clearance
    fluid, boundary = _friction(solver, solution, pressure, local_reynolds)
    friction = fluid + boundary
    torque = friction * g.radius
    circumferential, edge, inlet = _flows(solver, solution)
    mean_pressure = capacity / (g.length * g.diameter)
    op = solver.problem.operating
    sommerfeld = _sommerfeld_number(g.radius / g.radial_clearance, op.viscosity, op.speed, mean_pressure)
    hmin = float(thinnest.value)
    area = 2.0 * math.pi * g.radius * g.length
    rough = solver.surfaces.contact_part(
        film, solution.contact, solver.area_weights, theta, g.rotation, area, (fy, fz), hmin, (fluid, boundary)
    )
    return BearingState(
        eccentricity_ratio=e / g.radial_clearance,
        attitude_angle=attitude,
        position_angle=angle,
        position=solution.position,
        min_film_thickness=hmin,
        min_film_theta=float((theta[0] + thinnest.column * grid.d_theta) % (2 * np.pi)),
        min_film_z=float(thinnest.row * grid.dz),
        max_pressure=float(peak.value),
        max_pressure_theta=float((theta[0] + peak.column * grid.d_theta) % (2 * np.pi)),
        max_pressure_z=float(peak.row * grid.dz),
        mean_pressure=mean_pressure,
        load_capacity=capacity,
        force_y=fy,
        force_z=fz,
        moment_y=moment_y,
        moment_z=moment_z,
        load_centre_offset=float(offset),
        friction_force=friction,
        friction_torque=torque,
        friction_coefficient=friction / capacity if capacity > 0 else math.inf,
        power_loss=torque * op.speed,
        inlet_flow=inlet,
        side_leakage=float(edge.sum()),
        sommerfeld_number=sommerfeld,
        contact=bool(hmin <= solver.surfaces.floor),
        theta=theta,
        z=z,
        film=film,
        pressure=pressure,
        film_fraction=solution.cavitation.film_fraction,
        circumferential_flow=circumferential,
        edge_leakage=edge,
        cavitation=solver.cavitation.name,
        cavitated=solution.cavitated,
        iterations=solution.cavitation.iterations,
        rough=rough,
        liner=_liner_part(solution),
        turbulence=_turbulence_part(solver, local_reynolds),
    )


def _moments(
    solver: FilmSolver, solution: FilmSolution, pressure: np.ndarray, theta: np.ndarray, z: np.ndarray
) -> tuple[float, float]:
    """First moments of the vertical and horizontal film force (film and asperities) about the
    mid-plane, N m."""
    g = solver.geometry
    weights = solver.area_weights
    arm = z - 0.5 * g.length
    contact = solution.contact
    carried = pressure if contact is None else pressure + contact
    dfy = -carried * weights * np.cos(theta)[None, :]
    dfz = -g.rotation * carried * weights * np.sin(theta)[None, :]
    return float(np.sum(dfy * arm[:, None])), float(np.sum(dfz * arm[:, None]))


def _friction(
    solver: FilmSolver, solution: FilmSolution, pressure: np.ndarray, local_reynolds: np.ndarray
) -> tuple[float, float]:
    """The friction force on the journal, N: the film's shear (Couette shear on the liquid share
    plus the Poiseuille part) and the asperities' boundary friction."""
    g, op = solver.geometry, solver.problem.operating
    grid = solution.grid
    weights = solver.area_weights
    speed = op.speed * g.radius
    dp_dx = (np.roll(pressure, -1, axis=1) - np.roll(pressure, 1, axis=1)) / (2.0 * grid.d_theta * g.radius)
    fraction = solution.cavitation.film_fraction
    shearing = fraction if solver.options.cavitated_shear == "film_fraction" else np.ones_like(fraction)
    # Re_h on the nominal film, 0 where a rough film is past the mean plane (h <= 0): the
    # coefficients of the film equation take Re_h = Re_c max(H, 0) there (turbulence.py), and
    # a film a fraction of sigma thin is laminar on any gap (on the mean gap h_T <= 0.4 sigma,
    # Re_h <= 6 on seed 001's rig at 350 rpm, against the Taylor onset 708). Turbulent films:
    # the Couette shear times C_f(Re_h); the Poiseuille part as laminar (the linearised theory,
    # docs/theory.md Sect. 17 "Turbulent films").
    couette = couette_shear_factor(local_reynolds) if solver.turbulent else 1.0
    # Smooth: over the film. Rough: the Couette shear over the mean gap h_T (finite as h -> 0), the
    # Poiseuille part over h_T too (the nominal h is negative past the mean plane and would turn
    # its sign); boundary friction on the asperity pressure (docs/theory.md, "Mixed lubrication").
    gap = solver.surfaces.shear_gap(solution.film)
    shear = op.viscosity * speed * shearing * couette / gap + 0.5 * gap * dp_dx
    fluid = float(np.sum(shear * weights))
    return fluid, solver.surfaces.boundary_friction(solution.contact, weights)


def _flows(solver: FilmSolver, solution: FilmSolution) -> tuple[np.ndarray, np.ndarray, float]:
    """Circumferential flow (nt,), edge outflow (2, nt) and inlet flow, m^3/s, from the discrete
    face fluxes (consistent with the solver's mass balance)."""
    stencil = solution.stencil
    rel = solution.relative_pressure
    flow_scale = solver.problem.flow_scale
    # Couette transport carries the liquid share of the upwind node. The half cells between
    # the edge rows and the first interior faces carry half the transport of their interior
    # row; what they gain in the full film leaves through the edge. Fixed-pressure nodes
    # (supply lines) are sources, not leakage, so their half cells are left out.
    transport = stencil.couette_face * solution.cavitation.film_fraction
    theta_flux = transport - stencil.c_theta * (np.roll(rel, -1, axis=1) - rel)
    edge_transport = 0.5 * np.vstack([transport[1], transport[-2]])
    circumferential = flow_scale * (theta_flux[1:-1].sum(axis=0) + edge_transport.sum(axis=0))
    fixed = solver.nodes.fixed
    half_cells = np.roll(edge_transport, 1, axis=1) - edge_transport
    half_cells[:, fixed[1] | fixed[-2]] = 0.0
    aft = stencil.c_z[0] * (rel[1] - rel[0])
    fore = stencil.c_z[-1] * (rel[-2] - rel[-1])
    edge = flow_scale * (np.vstack([aft, fore]) + half_cells)
    return circumferential, edge, _inlet_flow(solver, solution, theta_flux, circumferential)


def _inlet_flow(
    solver: FilmSolver, solution: FilmSolution, theta_flux: np.ndarray, circumferential: np.ndarray
) -> float:
    if solver.problem.operating.grooves:
        # Net outflow of the groove nodes into the film, with the Couette inflow from a
        # cavitated upstream zone carrying only its liquid share.
        groove = solver.nodes.fixed.copy()
        groove[[0, -1]] = False
        rel = solution.relative_pressure
        stencil = solution.stencil
        net = theta_flux - np.roll(theta_flux, 1, axis=1)
        flow_north = stencil.c_z * (rel[:-1] - rel[1:])
        net[:-1] += flow_north
        net[1:] -= flow_north
        return float(solver.problem.flow_scale * net[groove].sum())
    # Without a groove: the flow entering the converging film across the line of
    # maximum film thickness at mid-plane (Raimondi & Boyd's Q).
    mid = solution.film.shape[0] // 2
    column = int(np.argmax(solution.film[mid]))
    return float(circumferential[column])


def _liner_part(solution: FilmSolution) -> LinerState | None:
    if solution.deformation is None:
        return None
    return LinerState(
        max_deformation=float(solution.deformation.max()),
        deformation=solution.deformation,
        iterations=solution.liner_iterations,
    )


def _turbulence_part(solver: FilmSolver, local_reynolds: np.ndarray) -> TurbulenceState | None:
    if solver.options.turbulence == "off":
        return None
    return TurbulenceState(
        max_reynolds_number=float(local_reynolds.max()),
        turbulent=solver.turbulent,
        reynolds_number=local_reynolds,
    )
