"""The 4 x 4 film stiffness and damping with the tilt (moment) coefficients (issue 11).

Reference: central differences of the nonlinear film solution (force and moment re-solved,
cold, at positions moved in ey, ez, tilt_y, tilt_z and, for the damping, at journal
velocities and tilt rates). Entries are compared scaled to one unit: columns per clearance
of edge displacement (offsets by c, tilts by c / (L/2)), moment rows over L/2; the error is
taken against the largest scaled entry.

Tolerances. The linearisation is that of the discrete film with its cavitated set frozen, so
central differences approach it as O(step^2) until a set switch or round-off intervenes:
measured 2.9e-5, 2.9e-7, 2.9e-9 (Reynolds condition) at steps 1e-3, 1e-4, 1e-5 c; the film
is linear in the squeeze term on a fixed set, so the damping agrees to 1e-13. A wrong term
(a missing lever arm, a sign, the rotation sense) shows at order 1.
"""

from __future__ import annotations

from dataclasses import replace

import numpy as np
import pytest

from shaftline.film import JournalPosition, TiltLinearisation, dynamic_coefficients
from shaftline.film.state import bearing_state
from tests.conftest import CLEARANCE, make_bearing

NAMES = ("ey", "ez", "tilt_y", "tilt_z")


def _loads(bearing, position, rates=(0.0, 0.0)) -> np.ndarray:
    """(F_y, F_z, M_y, M_z) of the film solution at ``position`` with tilt ``rates``, started cold."""
    state = bearing_state(bearing.solver, bearing.solver.evaluate(position, warm=False, tilt_rates=rates))
    return np.array([state.force_y, state.force_z, state.moment_y, state.moment_z])


def _differences(bearing, position: JournalPosition, relative_step: float) -> tuple[np.ndarray, np.ndarray]:
    """Central differences of the loads by (ey, ez, tilt_y, tilt_z) and by their rates."""
    half = 0.5 * bearing.geometry.length
    speed = bearing.operating.speed
    offsets, rates = np.zeros((4, 4)), np.zeros((4, 4))
    for k, name in enumerate(NAMES):
        step = relative_step * CLEARANCE / (1.0 if k < 2 else half)
        value = getattr(position, name)
        up = _loads(bearing, replace(position, **{name: value + step}))
        down = _loads(bearing, replace(position, **{name: value - step}))
        offsets[:, k] = (up - down) / (2 * step)
        rate = step * speed
        if k < 2:
            velocity = ("vy", "vz")[k]
            up = _loads(bearing, replace(position, **{velocity: rate}))
            down = _loads(bearing, replace(position, **{velocity: -rate}))
        else:
            up = _loads(bearing, position, (rate, 0.0) if k == 2 else (0.0, rate))
            down = _loads(bearing, position, (-rate, 0.0) if k == 2 else (0.0, -rate))
        rates[:, k] = (up - down) / (2 * rate)
    return offsets, rates


def _scaled(bearing, matrix: np.ndarray) -> np.ndarray:
    half = 0.5 * bearing.geometry.length
    column = np.array([CLEARANCE, CLEARANCE, CLEARANCE / half, CLEARANCE / half])
    row = np.array([1.0, 1.0, 1.0 / half, 1.0 / half])
    return matrix * row[:, None] * column[None, :]


def _error(bearing, exact: np.ndarray, numeric: np.ndarray) -> float:
    a, b = _scaled(bearing, exact), _scaled(bearing, numeric)
    return float(np.abs(a - b).max() / np.abs(b).max())


def _misaligned(bearing) -> JournalPosition:
    half = 0.5 * bearing.geometry.length
    tilt_y, tilt_z = 0.3 * CLEARANCE / half, -0.15 * CLEARANCE / half
    return JournalPosition.from_polar(0.6 * CLEARANCE, 2.5, tilt_y=tilt_y, tilt_z=tilt_z)


@pytest.fixture(scope="module")
def reynolds_bearing():
    return make_bearing(1.0, axial_nodes=31, circumferential_nodes=96)


def test_top_left_blocks_are_the_two_by_two_linearisation(reynolds_bearing):
    """The (F_y, F_z) x (ey, ez) blocks are linearise's and dynamic_coefficients', bit for bit
    (the same solves); force and moment are the state's."""
    position = _misaligned(reynolds_bearing)
    full = reynolds_bearing.linearise_with_tilt(position)
    two = reynolds_bearing.linearise(position)
    assert isinstance(full, TiltLinearisation)
    assert full.offset_derivative.shape == full.velocity_derivative.shape == (4, 4)
    assert np.array_equal(full.offset_derivative[:2, :2], two.offset_derivative)
    assert np.array_equal(full.velocity_derivative[:2, :2], two.velocity_derivative)
    assert np.array_equal(full.stiffness, -full.offset_derivative)
    assert np.array_equal(full.damping, -full.velocity_derivative)
    state = reynolds_bearing.solve_at(position, warm_start=False)
    coefficients = dynamic_coefficients(reynolds_bearing, state)
    assert np.array_equal(full.stiffness[:2, :2], coefficients.stiffness)
    assert np.array_equal(full.damping[:2, :2], coefficients.damping)
    assert np.array_equal(full.force, two.force)
    assert full.moment == pytest.approx([state.moment_y, state.moment_z], rel=1e-12)


def test_reynolds_coefficients_match_central_differences(reynolds_bearing):
    """Reynolds condition, step 1e-4 c: stiffness to 1e-5 (measured 2.9e-7, the O(step^2) of
    the differences), damping to 1e-8 (measured 2e-13)."""
    position = _misaligned(reynolds_bearing)
    full = reynolds_bearing.linearise_with_tilt(position)
    offsets, rates = _differences(reynolds_bearing, position, 1e-4)
    assert _error(reynolds_bearing, full.offset_derivative, offsets) < 1e-5
    assert _error(reynolds_bearing, full.velocity_derivative, rates) < 1e-8
    # The tilt entries are not small: the moment rows and tilt columns are of the order of
    # the force-by-offset block (a square bearing resists tilt as much as translation).
    scaled = np.abs(_scaled(reynolds_bearing, full.stiffness))
    assert scaled[2:, 2:].max() > 0.1 * scaled[:2, :2].max()


def test_jfo_coefficients_match_central_differences():
    """JFO film (exact linearisation with the void transport), step 1e-5 c: both to 1e-6
    (measured 3e-9 and 2e-12; at 1e-4 c a set switch in the damping differences gives 9e-5)."""
    bearing = make_bearing(1.0, cavitation_pressure=-2e4, axial_nodes=31, circumferential_nodes=96, cavitation="jfo")
    position = _misaligned(bearing)
    full = bearing.linearise_with_tilt(position)
    offsets, rates = _differences(bearing, position, 1e-5)
    assert _error(bearing, full.offset_derivative, offsets) < 1e-6
    assert _error(bearing, full.velocity_derivative, rates) < 1e-6


def test_aligned_film_decouples_translation_and_tilt(reynolds_bearing):
    """An aligned journal in a straight bore gives a film symmetric about the mid-plane: an
    offset makes no moment and a tilt no force (to round-off), while the tilt stiffness and
    damping are positive on the diagonal (the film resists rotation)."""
    full = reynolds_bearing.linearise_with_tilt(JournalPosition.from_polar(0.5 * CLEARANCE, 3.0))
    k = _scaled(reynolds_bearing, full.stiffness)
    c = _scaled(reynolds_bearing, full.damping)
    for matrix in (k, c):
        size = np.abs(matrix).max()
        assert np.abs(matrix[2:, :2]).max() < 1e-9 * size
        assert np.abs(matrix[:2, 2:]).max() < 1e-9 * size
        assert matrix[2, 2] > 0 and matrix[3, 3] > 0
    assert np.abs(full.moment).max() < 1e-9 * np.abs(full.force).max() * reynolds_bearing.geometry.length
