"""Unit handling at the case-file boundary.

Quantities in a case file are plain numbers (taken as SI) or strings with a
unit, such as ``"0.45 mm"``, ``"90 rpm"`` or ``"40 degC"``. They are converted
once, here, to SI floats; the models never see units.

pint does every conversion, but importing it costs about 0.15 s, more than the rest of
a short command. So the conversion of each unit pint has converted once, an affine map
``si = scale * number + offset``, is kept in a small cache file (:func:`cache_path`) and
used for later strings of the form ``"<number> <unit>"`` with the same unit, as is a unit
pint has refused for a kind (``"0.1 kg"`` for a length), so that the same message comes back
without pint; pint is imported only for a unit not seen before, or for text of any other
form. A missing, unreadable or unwritable cache only means pint is imported.
"""

from __future__ import annotations

import json
import math
import os
import re
import tempfile
from functools import lru_cache
from pathlib import Path
from typing import TYPE_CHECKING, Any

from shaftline.errors import InputError

if TYPE_CHECKING:
    import pint

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
    # a change of temperature: "10 K" or "10 delta_degC" (a bare number is K; "10 degC" is a
    # temperature, 283.15 K, and fails the range of a change)
    "temperature_difference": "K",
    "density": "kg/m**3",
    "dimensionless": "",
    "percent": "percent",
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
    "memory": "byte",
    # surface speed of a contact; "speed" is a shaft's angular speed
    "velocity": "m/s",
    # output of a displacement probe per unit gap (shaftline.monitor): "8 mV/um"
    "sensitivity": "V/m",
    # C of the scuffing parameter of Ciulli et al. (2010)
    "thermal_conductivity": "W/(m*K)",
    # asperities per unit area of a rough surface (Greenwood-Williamson's eta)
    "areal_density": "1/m**2",
}

#: How an SI unit is written in messages and tables.
UNIT_TEXT: dict[str, str] = {
    "percent": "%",
    "byte": "B",
    "W/(m*K)": "W/(m K)",
    "m**2/s": "m^2/s",
    "kg/m**3": "kg/m^3",
    "m**3/s": "m^3/s",
    "m/s**2": "m/s^2",
    "m**3/(N*m)": "m^3/(N m)",
    "m**3": "m^3",
    "m**2": "m^2",
    "1/m**2": "1/m^2",
    "kg*m**2": "kg m^2",
    "N*m": "N m",
    "N*m*s": "N m s",
    "Pa*s": "Pa s",
}


def si_unit(kind: str) -> str:
    """The SI unit of a kind of quantity as written in messages (``"m"``, ``"Pa s"``, ``""``)."""
    unit = SI_UNITS[kind]
    return UNIT_TEXT.get(unit, unit)


@lru_cache(maxsize=1)
def registry() -> pint.UnitRegistry:
    """The shared unit registry (offset units such as degC allowed as plain input).

    Its parsed definitions are cached on disk by pint (user cache folder), which cuts
    the registry's start from about 0.2 s to 0.02 s; without a writable cache it is
    built from the definitions file as before.
    """
    import pint

    ureg: pint.UnitRegistry
    try:
        ureg = pint.UnitRegistry(autoconvert_offset_to_baseunit=True, cache_folder=":auto:")
    except OSError:
        ureg = pint.UnitRegistry(autoconvert_offset_to_baseunit=True)
    # Marine engineers write "cSt" for kinematic viscosity and "mrad" for slopes.
    ureg.define("centistokes = 1e-6 m**2/s = cSt")
    return ureg


def to_si(value: Any, kind: str, field: str = "") -> float:
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

    Raises
    ------
    InputError
        For text that is not a number with a unit of ``kind``, and for NaN or infinities.
    """
    target = si_unit(kind)
    if isinstance(value, bool):
        raise InputError(field, value, target, "a number or a string with a unit")
    if isinstance(value, (int, float)):
        number = float(value)
        if not math.isfinite(number):
            raise InputError(field, value, target, "a finite number")
        return number
    if not isinstance(value, str):
        raise InputError(field, value, target, "a number or a string with a unit")
    text = value.strip()
    if "nan" in text.lower().split() or "inf" in text.lower().split():
        raise InputError(field, value, target, "a finite number")
    try:
        number = float(text)
    except ValueError:
        number = _convert(text, kind, field)
    if not math.isfinite(number):
        raise InputError(field, value, target, "a finite number")
    return number


#: "<number> <unit>" where the unit starts with a letter: pint reads it as the number
#: times the unit (or, for an offset unit such as degC, the number in that unit), so its
#: conversion is the same affine map for every number.
# The unit may not start with an exponent: "5e9 /m^2" is 5e9 per square metre, not 5 "e9 /m^2".
_NUMBER_AND_UNIT = re.compile(
    r"^([+-]?(?:\d+\.?\d*|\.\d+)(?:[eE][+-]?\d+)?)\s*(?![eE][+-]?\d)([A-Za-zµμ°Ω%][\w\s*/^().µμ°Ω%-]*)$"
)


def cache_path() -> Path | None:
    """The file of remembered unit conversions: ``$SHAFTLINE_CACHE_DIR`` or the user's cache
    folder (``$XDG_CACHE_HOME/shaftline`` or ``~/.cache/shaftline``); None if no home."""
    folder = os.environ.get("SHAFTLINE_CACHE_DIR")
    if not folder:
        base = os.environ.get("XDG_CACHE_HOME") or os.path.join(os.path.expanduser("~"), ".cache")
        if base.startswith("~"):
            return None
        folder = os.path.join(base, "shaftline")
    return Path(folder) / "unit-conversions-1.json"


class _WrongDimension(InputError):
    """A unit of another dimension than its field's kind: ``unit`` as pint abbreviates it."""

    def __init__(self, field: str, text: str, kind: str, unit: str) -> None:
        super().__init__(field, text, "", f"a quantity of {kind.replace('_', ' ')} (got unit {unit})")
        self.unit = unit


@lru_cache(maxsize=1)
def _remembered() -> dict[str, list[float] | str]:
    path = cache_path()
    try:
        data = json.loads(path.read_text(encoding="utf-8")) if path is not None else {}
    except (OSError, ValueError):
        return {}
    if not isinstance(data, dict):
        return {}
    return {
        key: value
        for key, value in data.items()
        if isinstance(value, str)
        or (isinstance(value, list) and len(value) == 2 and all(isinstance(v, float) for v in value))
    }


def _remember(key: str, conversion: list[float] | str) -> None:
    """Keep ``conversion`` of ``key`` (``kind|unit``): ``[scale, offset]``, or the unit pint
    refused for the kind, as pint wrote it."""
    remembered = _remembered()
    remembered[key] = conversion
    path = cache_path()
    if path is None:
        return
    try:
        path.parent.mkdir(parents=True, exist_ok=True)
        fd, temporary = tempfile.mkstemp(dir=path.parent, prefix=".units.", suffix=".tmp")
        with os.fdopen(fd, "w", encoding="utf-8") as handle:
            json.dump(remembered, handle)
        os.replace(temporary, path)
    except OSError:  # a read-only home: convert with pint next time too
        return


def _convert(text: str, kind: str, field: str) -> float:
    """``text`` in SI through a remembered unit conversion, or through pint (remembering it)."""
    match = _NUMBER_AND_UNIT.match(text)
    if match is None:
        return _parse_with_unit(text, kind, field)
    number, unit = float(match.group(1)), " ".join(match.group(2).split())
    key = f"{kind}|{unit}"
    known = _remembered().get(key)
    if isinstance(known, str):
        raise _WrongDimension(field, text, kind, known)
    if known is not None:
        return known[0] * number + known[1]
    try:
        value = _parse_with_unit(text, kind, field)
    except _WrongDimension as refused:
        _remember(key, refused.unit)
        raise
    offset = _parse_with_unit(f"0 {unit}", kind, field)
    scale = _parse_with_unit(f"1 {unit}", kind, field) - offset
    # Keep the map only if it reproduces pint for this number (an affine unit, as expected).
    if math.isclose(scale * number + offset, value, rel_tol=1e-12, abs_tol=1e-300):
        _remember(key, [scale, offset])
    return value


def _parse_with_unit(text: str, kind: str, field: str) -> float:
    import pint

    ureg = registry()
    try:
        parsed: Any = ureg.Quantity(text)
    except (pint.errors.UndefinedUnitError, pint.errors.DefinitionSyntaxError) as exc:
        raise InputError(field, text, "", f"a number with a known unit ({exc})") from None
    except Exception:  # pint raises a variety of parser errors for garbage text
        raise InputError(field, text, "", f"a number with a unit of {kind}") from None
    quantity: Any = parsed if isinstance(parsed, pint.Quantity) else ureg.Quantity(float(parsed), "")
    try:
        if kind == "speed":
            # pint reads rpm as 2*pi rad/min, so "1/s" gives rad/s; a shaft speed in Hz
            # means revolutions per second, which pint would take as rad/s.
            number = float(quantity.to("1/s").magnitude)
            if "hz" in text.lower():
                number *= 2.0 * math.pi
        else:
            number = float(quantity.to(SI_UNITS[kind]).magnitude)
    except pint.errors.DimensionalityError:
        unit = f"{quantity.units:~}" if str(quantity.units) else "(no unit)"
        raise _WrongDimension(field, text, kind, unit) from None
    return number
