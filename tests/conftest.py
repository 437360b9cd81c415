"""Shared fixtures: small bearings that solve in milliseconds."""

from __future__ import annotations

import os
import tempfile
from pathlib import Path

import numpy as np
import pytest
from typer.testing import CliRunner, Result

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


#: A small bearing case that solves in a fraction of a second.
MINIMAL_CASE = """
[case]
name = "small bearing"

[bearing]
length = "0.1 m"
diameter = "0.1 m"
radial_clearance = "0.1 mm"

[bearing.operation]
speed = "600 rpm"
load = "5 kN"

[bearing.lubricant]
viscosity = "0.02 Pa*s"

[bearing.solver]
axial_nodes = 21
circumferential_nodes = 72
"""


def invoke(*args: str) -> Result:
    """Run the command line in this process (standard output and error kept apart)."""
    from shaftline.cli import make_app

    return CliRunner().invoke(make_app(), list(args))


def assert_refused(result: Result, message: str, out: Path) -> None:
    """The project's rule for bad input: exit 2, one line on standard error holding
    ``message``, and nothing written to ``out``."""
    assert result.exit_code == 2, result.stdout
    assert message in result.stderr
    assert len(result.stderr.strip().splitlines()) == 1
    assert not out.exists()


# Unit conversions remembered by the tests go to a folder of the test run, not the user's.
os.environ.setdefault("SHAFTLINE_CACHE_DIR", tempfile.mkdtemp(prefix="shaftline-test-cache-"))
