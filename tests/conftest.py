"""Shared fixtures: small bearings that solve in milliseconds."""

from __future__ import annotations

import numpy as np
import pytest

from shaftline.film import BearingGeometry, JournalBearing, OperatingPoint, SolverOptions

RADIUS = 0.05
CLEARANCE = 1e-4
SPEED_REV_S = 10.0


def make_bearing(length_to_diameter: float = 1.0, cavitation_pressure: float = 0.0, **options) -> JournalBearing:
    """A plain bearing of D = 0.1 m, c = 0.1 mm at 10 rev/s with eta = 0.02 Pa s."""
    geometry = BearingGeometry(length=2 * RADIUS * length_to_diameter, diameter=2 * RADIUS, radial_clearance=CLEARANCE)
    operating = OperatingPoint(speed=2 * np.pi * SPEED_REV_S, viscosity=0.02, cavitation_pressure=cavitation_pressure)
    return JournalBearing(geometry, operating, SolverOptions(**options))


@pytest.fixture
def square_bearing() -> JournalBearing:
    return make_bearing(1.0, axial_nodes=31, circumferential_nodes=96)
