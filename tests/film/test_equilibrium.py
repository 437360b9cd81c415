"""Load equilibrium: range of eccentricity, warm starts, and loads that cannot be carried."""

from __future__ import annotations

import numpy as np
import pytest

from shaftline.film import JournalPosition
from tests.conftest import CLEARANCE, make_bearing


@pytest.fixture(scope="module")
def bearing():
    return make_bearing(1.0, axial_nodes=31, circumferential_nodes=120)


@pytest.mark.parametrize("epsilon", [0.01, 0.1, 0.5, 0.9, 0.97, 0.99])
def test_equilibrium_recovers_the_position_that_made_the_load(bearing, epsilon):
    """Solve at a known position, apply the film force as the load, and find the position again."""
    position = JournalPosition.from_polar(epsilon * CLEARANCE, np.radians(200.0))
    state = bearing.solve_at(position)
    eq = bearing.equilibrium(load_y=-state.force_y, load_z=-state.force_z)
    assert eq.converged and not eq.contact
    assert eq.residual <= 1e-8 * state.load_capacity
    assert eq.state.eccentricity_ratio == pytest.approx(epsilon, rel=1e-5, abs=1e-7)
    assert eq.state.position_angle == pytest.approx(state.position_angle, abs=1e-5)
    assert eq.iterations <= 25


def test_eccentricity_rises_with_load(bearing):
    eccentricities = [bearing.equilibrium(load_y=-w).state.eccentricity_ratio for w in (2e2, 2e3, 2e4, 2e5)]
    assert all(a < b for a, b in zip(eccentricities, eccentricities[1:], strict=False))


def test_warm_start_from_previous_equilibrium_is_faster(bearing):
    first = bearing.equilibrium(load_y=-5e3)
    again = bearing.equilibrium(load_y=-5.2e3, initial=first.state.position)
    assert again.converged
    assert again.iterations <= first.iterations


def test_horizontal_load_component(bearing):
    eq = bearing.equilibrium(load_y=-4e3, load_z=3e3)
    assert eq.converged
    assert eq.state.force_y == pytest.approx(4e3, rel=1e-7)
    assert eq.state.force_z == pytest.approx(-3e3, rel=1e-7)


def test_load_beyond_the_film_floor_reports_contact(bearing):
    """A load the film could only carry below the film floor stops with a contact flag, not a hang."""
    eq = bearing.equilibrium(load_y=-5e9)
    assert eq.contact and not eq.converged
    assert eq.state.contact
    assert eq.state.min_film_thickness <= 1.5 * bearing.options.min_film_floor * CLEARANCE
    assert eq.iterations <= bearing.options.max_iterations


def test_misaligned_equilibrium_keeps_the_tilt(bearing):
    tilt = 0.5 * 2 * CLEARANCE / bearing.geometry.length
    eq = bearing.equilibrium(load_y=-5e3, tilt_y=tilt)
    assert eq.converged
    assert eq.state.position.tilt_y == tilt
    assert eq.state.min_film_z in (0.0, bearing.geometry.length)


def test_jfo_equilibrium():
    bearing = make_bearing(1.0, cavitation_pressure=-3e4, axial_nodes=31, circumferential_nodes=120, cavitation="jfo")
    eq = bearing.equilibrium(load_y=-5e3)
    assert eq.converged
    assert eq.state.force_y == pytest.approx(5e3, rel=1e-6)


def test_newton_iterations_are_reported_without_changing_the_result(bearing):
    """Issue 9: a fine grid takes minutes per equilibrium; ``progress`` hears each Newton
    iteration (its number and the force residual as a share of the load) and the answer is
    the same bits as without it."""
    told: list[tuple[int, float]] = []
    quiet = bearing.equilibrium(load_y=-2e4)
    heard = bearing.equilibrium(load_y=-2e4, progress=lambda k, r: told.append((k, r)))
    assert [k for k, _ in told] == list(range(1, heard.iterations + 1)) and heard.iterations > 1
    assert told[-1][1] == pytest.approx(heard.residual / 2e4, rel=1e-12)
    assert told[-1][1] < told[0][1]
    assert heard.state.position == quiet.state.position


def test_the_film_study_reports_iterations_and_coefficients():
    from shaftline.film.solve import solve_study
    from shaftline.film.study import BearingCase, BearingStudy

    b = make_bearing(1.0, axial_nodes=21, circumferential_nodes=60)
    case = BearingCase("base", b.geometry, b.operating, b.options, load_y=-2e4)
    told: list[str] = []
    solve_study(BearingStudy((case,)), told.append)
    assert told[0] == "base" and told[-1] == "base: stiffness and damping"
    assert told[1].startswith("base: Newton iteration 1, force residual ")
    assert all("Newton iteration" in t for t in told[1:-1])
