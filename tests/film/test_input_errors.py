"""Bad input to the film model names the field relative to the object or call that checks it.

The domain cannot know whether a value came from a case file, a notebook or a sweep, so
it names the attribute path (``"grooves[0].angle"``) or the parameter (``"load_y"``);
the case layer places that under its own path with ``InputError.within``.
"""

from __future__ import annotations

import pytest

from shaftline.errors import InputError
from shaftline.film import BearingGeometry, JournalBearing, OperatingPoint, SolverOptions
from shaftline.film.bearing import SupplyGroove
from tests.conftest import make_bearing

GEOMETRY = BearingGeometry(length=0.1, diameter=0.1, radial_clearance=1e-4)


@pytest.mark.parametrize(
    "kwargs, field",
    [
        ({"speed": 0.0}, "speed"),
        ({"viscosity": -0.02}, "viscosity"),
        ({"density": float("nan")}, "density"),
        ({"aft_pressure": float("inf")}, "aft_pressure"),
        ({"cavitation_pressure": 1e3}, "cavitation_pressure"),
        ({"grooves": (SupplyGroove(0.0), SupplyGroove(float("nan")))}, "grooves[1].angle"),
        ({"grooves": (SupplyGroove(0.0, float("nan")),)}, "grooves[0].pressure"),
        ({"grooves": (SupplyGroove(0.0, 0.0, 1.5),)}, "grooves[0].length_fraction"),
    ],
)
def test_bad_operating_point_names_the_attribute(kwargs, field):
    values = {"speed": 100.0, "viscosity": 0.02} | kwargs
    with pytest.raises(InputError) as error:
        OperatingPoint(**values)
    assert error.value.field == field


@pytest.mark.parametrize(
    "kwargs, field",
    [
        ({"cavitation": "magic"}, "cavitation"),
        ({"film_start": "anywhere"}, "film_start"),
        ({"cavitated_shear": "none"}, "cavitated_shear"),
        ({"min_film_floor": 0.7}, "min_film_floor"),
        ({"tolerance": 0.1}, "tolerance"),
    ],
)
def test_bad_solver_options_name_the_attribute(kwargs, field):
    with pytest.raises(InputError) as error:
        SolverOptions(**kwargs)
    assert error.value.field == field


def test_jfo_without_feed_names_the_operating_attribute():
    """The check needs both the options and the operating point, so it names the path from the bearing."""
    with pytest.raises(InputError) as error:
        JournalBearing(GEOMETRY, OperatingPoint(speed=100.0, viscosity=0.02), SolverOptions(cavitation="jfo"))
    assert error.value.field == "operating.cavitation_pressure"


@pytest.mark.parametrize(
    "kwargs, field",
    [
        ({"load_y": float("nan")}, "load_y"),
        ({"load_y": -1e3, "load_z": float("inf")}, "load_z"),
        ({"load_y": -1e3, "tilt_y": float("nan")}, "tilt_y"),
        ({"load_y": -1e3, "tilt_z": float("inf")}, "tilt_z"),
        ({"load_y": 0.0, "load_z": 0.0}, "load_y"),
        ({"load_y": -1e3, "tilt_z": 0.1}, "tilt_z"),
    ],
)
def test_bad_equilibrium_arguments_name_the_parameter(kwargs, field):
    bearing = make_bearing(1.0, axial_nodes=11, circumferential_nodes=36)
    with pytest.raises(InputError) as error:
        bearing.equilibrium(**kwargs)
    assert error.value.field == field


def test_within_places_a_field_under_a_case_path():
    error = InputError("radial_clearance", -1e-4, "m", "> 0")
    placed = error.within("bearing")
    assert placed.field == "bearing.radial_clearance"
    assert (placed.value, placed.unit, placed.allowed) == (-1e-4, "m", "> 0")
    assert str(placed) == "bearing.radial_clearance = -0.0001 m: allowed > 0"
    assert InputError("[1].slope", 0.0).within("bearing.bore").field == "bearing.bore[1].slope"
