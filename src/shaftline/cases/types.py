"""Field types of the case-file schema: quantities that carry their dimension, sections.

A quantity field is declared once with its physical kind and allowed range::

    class OperationSection(Section):
        speed: Annotated[float, Quantity("speed", gt=0)]
        \"\"\"Shaft speed.\"\"\"

The value in the file may be a number (SI, temperatures in degC) or a string with a unit
(``"90 rpm"``); pydantic hands the model an SI float, and an error names the field by
pydantic's own location, with the SI unit and the allowed range. Field descriptions are the
attribute docstrings: the README's case-file tables and ``shaftline schema`` are generated
from them.
"""

from __future__ import annotations

import dataclasses
import math
from dataclasses import dataclass
from typing import Annotated, Any

from pydantic import BaseModel, ConfigDict, Field, GetCoreSchemaHandler, GetJsonSchemaHandler
from pydantic.json_schema import JsonSchemaValue
from pydantic_core import PydanticCustomError, core_schema

from shaftline.errors import InputError
from shaftline.units import si_unit, to_si


def _number(value: float) -> str:
    return f"{value:g}"


@dataclass(frozen=True)
class Quantity:
    """Metadata of a quantity field: its kind (a key of :data:`shaftline.units.SI_UNITS`)
    and bounds in SI units."""

    kind: str
    gt: float | None = None
    ge: float | None = None
    lt: float | None = None
    le: float | None = None

    @property
    def unit(self) -> str:
        return si_unit(self.kind)

    def allowed(self) -> str:
        """The allowed range in words (``"> 0"``, ``"in [0, 1]"``), or ``""``."""
        low = ("(", self.gt) if self.gt is not None else ("[", self.ge) if self.ge is not None else None
        high = (")", self.lt) if self.lt is not None else ("]", self.le) if self.le is not None else None
        if low and high:
            return f"in {low[0]}{_number(low[1])}, {_number(high[1])}{high[0]}"
        if low:
            return f"{'>' if low[0] == '(' else '>='} {_number(low[1])}"
        if high:
            return f"{'<' if high[0] == ')' else '<='} {_number(high[1])}"
        return ""

    def convert(self, value: Any) -> float:
        try:
            number = to_si(value, self.kind)
        except InputError as error:
            raise PydanticCustomError(
                "quantity", "{allowed}", {"unit": error.unit, "allowed": error.allowed, "value": error.value}
            ) from None
        inside = (
            (self.gt is None or number > self.gt)
            and (self.ge is None or number >= self.ge)
            and (self.lt is None or number < self.lt)
            and (self.le is None or number <= self.le)
        )
        if not inside:
            raise PydanticCustomError(
                "quantity", "{allowed}", {"unit": self.unit, "allowed": self.allowed(), "value": number}
            )
        return number

    def __get_pydantic_core_schema__(self, source: Any, handler: GetCoreSchemaHandler) -> core_schema.CoreSchema:
        return core_schema.no_info_plain_validator_function(self.convert)

    def __get_pydantic_json_schema__(
        self, schema: core_schema.CoreSchema, handler: GetJsonSchemaHandler
    ) -> JsonSchemaValue:
        out: dict[str, Any] = {"anyOf": [{"type": "number"}, {"type": "string"}], "x-kind": self.kind}
        if self.unit:
            out["x-unit"] = self.unit
        for key, name in (("gt", "exclusiveMinimum"), ("ge", "minimum"), ("lt", "exclusiveMaximum"), ("le", "maximum")):
            value = getattr(self, key)
            if value is not None and math.isfinite(value):
                out[name] = value
        return out


# The common kinds, unbounded and with their usual bounds.
Length = Annotated[float, Quantity("length")]
PositiveLength = Annotated[float, Quantity("length", gt=0)]
NonNegativeLength = Annotated[float, Quantity("length", ge=0)]
Angle = Annotated[float, Quantity("angle")]
Speed = Annotated[float, Quantity("speed")]
PositiveSpeed = Annotated[float, Quantity("speed", gt=0)]
Force = Annotated[float, Quantity("force")]
PositiveForce = Annotated[float, Quantity("force", gt=0)]
Moment = Annotated[float, Quantity("moment")]
Pressure = Annotated[float, Quantity("pressure")]
PositivePressure = Annotated[float, Quantity("pressure", gt=0)]
PositiveViscosity = Annotated[float, Quantity("viscosity", gt=0)]
PositiveKinematicViscosity = Annotated[float, Quantity("kinematic_viscosity", gt=0)]
Temperature = Annotated[float, Quantity("temperature", ge=-40, le=250)]
PositiveDensity = Annotated[float, Quantity("density", gt=0)]
PositiveMass = Annotated[float, Quantity("mass", gt=0)]
PositiveStiffness = Annotated[float, Quantity("stiffness", gt=0)]
ForcePerLength = Annotated[float, Quantity("force_per_length")]
PositiveAcceleration = Annotated[float, Quantity("acceleration", gt=0)]
PositiveWearRate = Annotated[float, Quantity("wear_rate", gt=0)]
Time = Annotated[float, Quantity("time")]
PositiveTime = Annotated[float, Quantity("time", gt=0)]
PositiveFrequency = Annotated[float, Quantity("frequency", gt=0)]
PositiveVolume = Annotated[float, Quantity("volume", gt=0)]
PositiveArea = Annotated[float, Quantity("area", gt=0)]
PositiveInertia = Annotated[float, Quantity("inertia", gt=0)]
NonNegativeInertia = Annotated[float, Quantity("inertia", ge=0)]
Percent = Annotated[float, Quantity("percent")]
Number = Annotated[float, Quantity("dimensionless")]
PositiveNumber = Annotated[float, Quantity("dimensionless", gt=0)]
Fraction = Annotated[float, Quantity("dimensionless", ge=0, le=1)]
PositiveFraction = Annotated[float, Quantity("dimensionless", gt=0, le=1)]


class Section(BaseModel):
    """Base of every case-file table: unknown keys are errors (a misspelt field is reported,
    not ignored), values are frozen, and field descriptions are the attribute docstrings."""

    model_config = ConfigDict(extra="forbid", frozen=True, use_attribute_docstrings=True)


class CaseInfo(Section):
    """Labels of the case."""

    name: str = "unnamed case"
    """Name of the case (report title; the base case of a bearing study)."""
    description: str = ""
    """What the case is, for the report."""


def default_of(cls: type, name: str) -> Any:
    """The default of field ``name`` of the domain dataclass ``cls``: the one source of
    defaults, so the case file and the library cannot drift apart."""
    for item in dataclasses.fields(cls):
        if item.name == name:
            if item.default is not dataclasses.MISSING:
                return item.default
            if item.default_factory is not dataclasses.MISSING:
                return item.default_factory()
            break
    raise AttributeError(f"{cls.__name__}.{name} has no default")


def field_error(field: str, value: Any, allowed: str, unit: str = "") -> PydanticCustomError:
    """An error of a cross-field check in a model validator, naming ``field`` (relative to
    the model) rather than the model as a whole."""
    return PydanticCustomError("field", "{allowed}", {"field": field, "value": value, "unit": unit, "allowed": allowed})


__all__ = ["CaseInfo", "Field", "Quantity", "Section", "default_of", "field_error"]
