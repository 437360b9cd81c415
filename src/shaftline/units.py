"""Unit handling at the case-file boundary.

Quantities in a case file are plain numbers (taken as SI) or strings with a
unit, such as ``"0.45 mm"``, ``"90 rpm"`` or ``"40 degC"``. They are converted
once, here, to SI floats; the models never see units.
"""

from __future__ import annotations

import math
from functools import lru_cache
from typing import Any

import pint

from shaftline.errors import InputError

#: SI unit each physical kind is converted to, and the dimensionality pint checks.
SI_UNITS: dict[str, str] = {
    "length": "m",
    "angle": "rad",
    "speed": "rad/s",
    "force": "N",
    "moment": "N*m",
    "pressure": "Pa",
    "viscosity": "Pa*s",
    "kinematic_viscosity": "m**2/s",
    "temperature": "degC",
    "density": "kg/m**3",
    "dimensionless": "",
    "stiffness": "N/m",
    "volume_flow": "m**3/s",
    "mass": "kg",
    "force_per_length": "N/m",
    "acceleration": "m/s**2",
    "wear_rate": "m**3/(N*m)",
    "time": "s",
    "frequency": "Hz",
    "volume": "m**3",
    "area": "m**2",
    "inertia": "kg*m**2",
    "rotational_stiffness": "N*m",
    "rotational_damping": "N*m*s",
}


@lru_cache(maxsize=1)
def registry() -> pint.UnitRegistry:
    """The shared unit registry (offset units such as degC allowed as plain input)."""
    ureg = pint.UnitRegistry(autoconvert_offset_to_baseunit=True)
    # Marine engineers write "cSt" for kinematic viscosity and "mrad" for slopes.
    ureg.define("centistokes = 1e-6 m**2/s = cSt")
    return ureg


def to_si(value: Any, kind: str, field: str) -> float:
    """Convert a case-file value to an SI float.

    Parameters
    ----------
    value : float, int or str
        A number (already SI) or a string ``"<number> <unit>"``.
    kind : str
        Physical kind, a key of :data:`SI_UNITS`.
    field : str
        Dotted field name, used in error messages.

    Returns
    -------
    float
        The value in the SI unit of ``kind`` (temperatures in degC).
    """
    target = SI_UNITS[kind]
    if isinstance(value, bool):
        raise InputError(field, value, target, "a number or a string with a unit")
    if isinstance(value, (int, float)):
        number = float(value)
        if not math.isfinite(number):
            raise InputError(field, value, target, "a finite number")
        return number
    if not isinstance(value, str):
        raise InputError(field, value, target, "a number or a string with a unit")
    ureg = registry()
    text = value.strip()
    if text.lower() == "nan" or "nan" in text.lower().split():
        raise InputError(field, value, target, "a finite number")
    try:
        quantity = ureg.Quantity(text)
    except (pint.errors.UndefinedUnitError, pint.errors.DefinitionSyntaxError) as exc:
        raise InputError(field, value, "", f"a number with a known unit ({exc})") from None
    except Exception:  # pint raises a variety of parser errors for garbage text
        raise InputError(field, value, "", f"a number with a unit of {kind}") from None
    if not isinstance(quantity, pint.Quantity):
        quantity = ureg.Quantity(float(quantity), "")
    try:
        if kind == "speed":
            # pint reads rpm as 2*pi rad/min, so "1/s" gives rad/s; a shaft speed in Hz
            # means revolutions per second, which pint would take as rad/s.
            number = float(quantity.to("1/s").magnitude)
            if "hz" in text.lower():
                number *= 2.0 * math.pi
        else:
            number = float(quantity.to(target).magnitude)
    except pint.errors.DimensionalityError:
        unit = f"{quantity.units:~}" if str(quantity.units) else "(no unit)"
        raise InputError(field, value, "", f"a quantity of {kind} (got unit {unit})") from None
    if not math.isfinite(number):
        raise InputError(field, value, target, "a finite number")
    return number
