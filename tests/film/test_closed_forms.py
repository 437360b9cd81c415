"""Analytic limits of the finite-bearing solver.

References
----------
Sommerfeld (1904) and Guembel (1914), long bearing; Ocvirk (1952), short bearing;
forms as in Hamrock, Schmid & Jacobson (2004), Fundamentals of Fluid Film Lubrication,
Ch. 10-11 (implemented in shaftline.film.analytic). Petroff (1883) for the friction of
a concentric journal.
"""

from __future__ import annotations

import numpy as np
import pytest

from shaftline.film import JournalPosition
from shaftline.film.analytic import long_bearing_load, long_bearing_pressure, short_bearing_load
from shaftline.film.cavitation import NodeGrid, ReynoldsCondition
from shaftline.film.problem import SolverOptions
from shaftline.film.stencil import build_stencil
from tests.conftest import CLEARANCE, RADIUS, make_bearing


def _dimensionless_load(state, bearing) -> tuple[float, float]:
    """(radial, tangential) film load over eta omega R L (R/c)^2, radial along the line of centres."""
    g, op = bearing.geometry, bearing.operating
    scale = op.viscosity * op.speed * g.radius * g.length * (g.radius / g.radial_clearance) ** 2
    angle = state.position_angle
    direction = np.array([np.cos(angle), np.sin(angle)])  # rotation +1: (y, z) = (cos, sin)
    normal = np.array([-np.sin(angle), np.cos(angle)])
    force = np.array([state.force_y, state.force_z])
    return -force @ direction / scale, -force @ normal / scale


@pytest.mark.parametrize("epsilon", [0.2, 0.5, 0.8])
def test_long_bearing_mid_plane_pressure_is_sommerfeld(epsilon):
    """Full-Sommerfeld (linear) film of L/D = 8: the mid-plane pressure is the long-bearing one.

    End effects decay like exp(-z/R) from each edge, 8 radii away from mid-plane: < 1e-3.
    The 240-node circumferential grid is second-order accurate: 0.5 % of the peak.
    """
    bearing = make_bearing(8.0, axial_nodes=81, circumferential_nodes=240)
    position = JournalPosition.from_polar(epsilon * CLEARANCE, 0.0)
    grid = bearing.grid(position)
    film = bearing.film(position) / CLEARANCE
    # The linear operator alone, with the edges held at ambient (= cavitation) pressure.
    edges = np.zeros(grid.shape, dtype=bool)
    edges[[0, -1]] = True
    d_theta, d_z = grid.d_theta, grid.dz / RADIUS
    solver = ReynoldsCondition(NodeGrid.of(grid.shape, d_theta, d_z, edges, np.zeros(grid.shape)), SolverOptions())
    pressure = solver.solve_linear(build_stencil(film, d_theta, d_z))
    mid = pressure[pressure.shape[0] // 2]
    # theta measured from the thickest film: h = c (1 + eps cos(theta - pi))
    expected = long_bearing_pressure(grid.theta - np.pi, epsilon)
    assert np.max(np.abs(mid - expected)) <= 0.005 * np.max(np.abs(expected))


@pytest.mark.parametrize("epsilon", [0.3, 0.6, 0.9])
def test_long_bearing_half_sommerfeld_load(epsilon):
    """Guembel (half-Sommerfeld) load per unit length at the mid-plane of an L/D = 8 bearing, 1 %."""
    bearing = make_bearing(8.0, axial_nodes=81, circumferential_nodes=240, cavitation="half_sommerfeld")
    state = bearing.solve_at(JournalPosition.from_polar(epsilon * CLEARANCE, 0.0))
    mid = state.pressure[state.pressure.shape[0] // 2]
    theta = state.theta
    d_theta = theta[1] - theta[0]
    g, op = bearing.geometry, bearing.operating
    scale = op.viscosity * op.speed * g.radius * (g.radius / g.radial_clearance) ** 2
    # Along the line of centres (towards theta = 0) and at right angles, per unit length.
    radial = np.sum(mid * np.cos(theta)) * d_theta * g.radius / scale
    tangential = np.sum(mid * np.sin(theta)) * d_theta * g.radius / scale
    expected_radial, expected_tangential = long_bearing_load(epsilon, "half_sommerfeld")
    assert abs(radial) == pytest.approx(expected_radial, rel=0.01)
    assert abs(tangential) == pytest.approx(expected_tangential, rel=0.01)


@pytest.mark.parametrize("epsilon, tolerance", [(0.2, 0.01), (0.5, 0.01), (0.8, 0.02)])
def test_short_bearing_limit_is_ocvirk(epsilon, tolerance):
    """Half-Sommerfeld film of L/D = 1/20 against Ocvirk: load and attitude (1 deg).

    The short-bearing theory drops circumferential pressure flow, whose share grows with
    the film curvature near h_min: the grid-converged gap is -0.4 % at eps = 0.2, -0.6 %
    at 0.5 and -1.2 % at 0.8 (81 x 480 nodes), so 1 % and, at eps = 0.8, 2 %.
    """
    bearing = make_bearing(0.05, axial_nodes=41, circumferential_nodes=240, cavitation="half_sommerfeld")
    state = bearing.solve_at(JournalPosition.from_polar(epsilon * CLEARANCE, np.pi))
    radial, tangential = _dimensionless_load(state, bearing)
    expected_radial, expected_tangential = short_bearing_load(epsilon, 0.05)
    assert np.hypot(radial, tangential) == pytest.approx(np.hypot(expected_radial, expected_tangential), rel=tolerance)
    expected_attitude = np.degrees(np.arctan2(expected_tangential, expected_radial))
    assert np.degrees(state.attitude_angle) == pytest.approx(expected_attitude, abs=1.0)


def test_short_bearing_error_shrinks_with_length():
    """The gap to Ocvirk closes as L/D falls (it is the theory's O((L/D)^2) error)."""
    gaps = []
    for ratio in (0.5, 0.25, 0.1):
        bearing = make_bearing(ratio, axial_nodes=21, circumferential_nodes=180, cavitation="half_sommerfeld")
        state = bearing.solve_at(JournalPosition.from_polar(0.5 * CLEARANCE, np.pi))
        load = np.hypot(*_dimensionless_load(state, bearing))
        gaps.append(abs(load / np.hypot(*short_bearing_load(0.5, ratio)) - 1.0))
    assert gaps[0] > gaps[1] > gaps[2]


@pytest.mark.parametrize("cavitation", ["reynolds", "jfo"])
def test_petroff_limit(cavitation):
    """As eps -> 0 the friction tends to Petroff's 2 pi eta omega R^3 L / c.

    The departure is O(eps) (film-fraction and Poiseuille terms), so at eps = 1e-3 it is
    below 0.1 %; JFO needs a feed, here edges 10 kPa above the cavitation pressure.
    """
    bearing = make_bearing(
        1.0, axial_nodes=31, circumferential_nodes=120, cavitation=cavitation, cavitation_pressure=-1e4
    )
    state = bearing.solve_at(JournalPosition.from_polar(0.001 * CLEARANCE, np.pi))
    g, op = bearing.geometry, bearing.operating
    petroff = 2 * np.pi * op.viscosity * op.speed * g.radius**2 * g.length / g.radial_clearance
    assert state.friction_force == pytest.approx(petroff, rel=1e-3)
    # and the friction variable tends to 2 pi^2 S
    assert state.friction_coefficient * RADIUS / CLEARANCE == pytest.approx(
        2 * np.pi**2 * state.sommerfeld_number, rel=2e-3
    )
