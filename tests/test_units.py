"""Quantities at the case-file boundary."""

from __future__ import annotations

import math

import pytest

from shaftline.errors import InputError
from shaftline.units import to_si


@pytest.mark.parametrize(
    "value, kind, expected",
    [
        ("0.45 mm", "length", 0.45e-3),
        (0.52, "length", 0.52),
        ("90 rpm", "speed", 3 * math.pi),
        ("1.5 Hz", "speed", 3 * math.pi),
        ("9.42 rad/s", "speed", 9.42),
        ("40 degC", "temperature", 40.0),
        ("313.15 K", "temperature", 40.0),
        ("70 cP", "viscosity", 0.07),
        ("68 cSt", "kinematic_viscosity", 68e-6),
        ("309.86 kN", "force", 309860.0),
        ("0.3 mrad", "angle", 3e-4),
        ("2 bar", "pressure", 2e5),
    ],
)
def test_conversion(value, kind, expected):
    assert to_si(value, kind, "x") == pytest.approx(expected, rel=1e-12)


@pytest.mark.parametrize(
    "value, kind, fragment",
    [
        ("0.5 kg", "length", "quantity of length"),
        ("3 furlongz", "length", "known unit"),
        ("nan mm", "length", "finite"),
        (float("nan"), "length", "finite"),
        (True, "length", "number"),
    ],
)
def test_bad_quantities(value, kind, fragment):
    with pytest.raises(InputError) as error:
        to_si(value, kind, "bearing.length")
    assert error.value.field == "bearing.length"
    assert fragment in str(error.value)
