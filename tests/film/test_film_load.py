"""The film of a journal centre line of any shape (``JournalBearing.film_load``) and the 4 x 4
film coefficients with tilt at such a line (``shaftline.shaft.coupled.film_coefficients``).

References: the film's own solution at a rigid position (``solve_at``, ``linearise``) and central
finite differences of the nonlinear film solution. The NTUA bearing of seed 004 (L = 1.05 m,
D = 0.52 m, c = 0.45 mm, 90 rpm, 0.07 Pa s) at its psi_x = 0.3 equilibrium, on a 60 x 48 grid.
"""

from __future__ import annotations

import numpy as np
import pytest

from shaftline.errors import InputError
from shaftline.film import BearingProblem, JournalBearing, OperatingPoint, SolverOptions
from shaftline.film.geometry import BearingGeometry
from shaftline.shaft.coupled import film_coefficients

LOAD = 309859.9
TILT = 0.3 * 0.9e-3 / 1.05


@pytest.fixture(scope="module")
def bearing():
    geometry = BearingGeometry(length=1.05, diameter=0.52, radial_clearance=0.45e-3)
    problem = BearingProblem(
        geometry, OperatingPoint(speed=9.4248, viscosity=0.07), SolverOptions(axial_nodes=60, circumferential_nodes=48)
    )
    film = JournalBearing.from_problem(problem)
    position = film.equilibrium(-LOAD, tilt_y=TILT).state.position
    arm = film.axial_stations - 0.525
    return film, position, position.ey + position.tilt_y * arm, position.ez + position.tilt_z * arm


def test_straight_line_reproduces_the_rigid_solution(bearing):
    """A straight centre line is the rigid journal: same force to round-off, rows summing to it."""
    film, position, cy, cz = bearing
    load = film.film_load(cy, cz, warm_start=False)
    state = film.solve_at(position, warm_start=False)
    assert load.row_force.sum(axis=1) == pytest.approx([state.force_y, state.force_z], rel=1e-9, abs=1e-6 * LOAD)
    assert load.state.min_film_thickness == pytest.approx(state.min_film_thickness, rel=1e-12)


def test_row_force_derivatives_match_finite_differences(bearing):
    """d(row forces)/d(bend) for a half-sine bend of the journal against a central difference of
    the nonlinear solution; step 0.05 um (1e-4 of c): the truncation error is second order in the
    step and the set change it may cause is first order in it, both far below the 1 % tolerance."""
    film, _, cy, cz = bearing
    bend = np.sin(np.pi * film.axial_stations / 1.05)
    direction = np.array([[bend, np.zeros_like(bend)]])
    analytic = film.film_load(cy, cz, direction, warm_start=False).derivative[..., 0]
    step = 0.05e-6
    plus = film.film_load(cy + step * bend, cz, warm_start=False).row_force
    minus = film.film_load(cy - step * bend, cz, warm_start=False).row_force
    numeric = (plus - minus) / (2 * step)
    assert np.abs(numeric - analytic).max() <= 0.01 * np.abs(analytic).max()


def test_four_by_four_coefficients(bearing):
    """The top-left 2 x 2 blocks equal ``linearise`` (the same frozen-set solves, round-off); the
    whole stiffness matches central differences of force and moment for offsets and tilts
    (steps 0.1 um and 0.2 urad, 2e-3 relative: set changes across the step)."""
    film, position, cy, cz = bearing
    stiffness, damping = film_coefficients(film, cy, cz)
    linear = film.linearise(position)
    assert stiffness[:2, :2] == pytest.approx(linear.stiffness, rel=1e-9, abs=1e-9 * np.abs(linear.stiffness).max())
    assert damping[:2, :2] == pytest.approx(linear.damping, rel=1e-9, abs=1e-9 * np.abs(linear.damping).max())
    arm = film.axial_stations - 0.525
    zero, one = np.zeros_like(arm), np.ones_like(arm)

    def force_and_moment(y: np.ndarray, z: np.ndarray) -> np.ndarray:
        rows = film.film_load(y, z, warm_start=False).row_force
        return np.concatenate([rows.sum(axis=1), rows @ arm])

    numeric = np.zeros((4, 4))
    for j, ((my, mz), step) in enumerate(
        [((one, zero), 1e-7), ((zero, one), 1e-7), ((arm, zero), 2e-7), ((zero, arm), 2e-7)]
    ):
        plus = force_and_moment(cy + step * my, cz + step * mz)
        minus = force_and_moment(cy - step * my, cz - step * mz)
        numeric[:, j] = -(plus - minus) / (2 * step)
    scale = np.abs(stiffness).max(axis=0)
    assert np.all(np.abs(numeric - stiffness).max(axis=0) <= 2e-3 * scale)
    # a long misaligned film resists tilt: the moment-tilt terms are of the order K L^2 / 12
    assert stiffness[2, 2] > 0.02 * stiffness[0, 0] * 1.05**2


def test_bad_centre_line(bearing):
    film, _, cy, cz = bearing
    with pytest.raises(InputError) as error:
        film.film_load(cy[:-1], cz)
    assert error.value.field == "centre_y"
    with pytest.raises(InputError) as error:
        film.film_load(cy - 1e-3, cz)  # 1 mm down: through the bore
    assert error.value.field == "centre_y"
