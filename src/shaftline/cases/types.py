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
from collections.abc import Callable
from dataclasses import dataclass
from typing import Annotated, Any, ClassVar

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

    def inside(self, number: float) -> bool:
        """Whether ``number`` (SI) lies in the allowed range."""
        return (
            (self.gt is None or number > self.gt)
            and (self.ge is None or number >= self.ge)
            and (self.lt is None or number < self.lt)
            and (self.le is None or number <= self.le)
        )

    def convert(self, value: Any) -> float:
        try:
            number = to_si(value, self.kind)
        except InputError as error:
            raise PydanticCustomError(
                "quantity", "{allowed}", {"unit": error.unit, "allowed": error.allowed, "value": error.value}
            ) from None
        if not self.inside(number):
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


@dataclass(frozen=True)
class Plausible:
    """The plausible range of a quantity field, in SI units, and where it comes from.

    Declared beside the field's :class:`Quantity`, for the domain of marine propulsion
    shaft lines::

        length: Annotated[PositiveLength, Plausible(0.02, 4.0, "seed 004 Table 5-1 ...")]

    The allowed range of the :class:`Quantity` is what the model can compute; the plausible
    range is what a real machine has. A value outside it is most likely a unit slip (a bare
    number is SI: ``length = 1050`` is a 1050 m bearing) and is refused, with the unit that
    would bring it into range, unless the case lists the field in ``[case] unusual``
    (:mod:`shaftline.cases.plausibility`). The range must catch slips of a factor of 25.4
    or 1000, not legitimate unusual machines: it is generous, and ``source`` says why.
    """

    low: float
    high: float
    source: str
    #: Unit the message shows the value and the range in, with its size in SI (degrees for
    #: angles a user writes in degrees); none: the SI unit.
    shown_unit: str = ""
    shown_factor: float = 1.0
    #: The range is also the model's limit: the message says "allowed" and does not offer
    #: ``[case] unusual``, which could not let the value through.
    limit: bool = False
    #: Brackets of a limit whose ends are excluded, written as the model's own message writes
    #: them ("()", "[)"); none: "low to high".
    ends: str = ""

    def __post_init__(self) -> None:
        if not self.low < self.high:
            raise ValueError(f"a plausible range needs low < high, got {self.low} and {self.high}")

    def contains(self, value: float) -> bool:
        return self.low <= value <= self.high

    def sizeable(self, value: float) -> bool:
        """Whether ``value`` is not negligible in a range that holds zero (offsets, forces):
        in such a range every small unit fits, and a value a thousandth of the range's size is
        no likely meaning of a number written."""
        return not self.low <= 0.0 <= self.high or abs(value) >= 1e-3 * max(-self.low, self.high)

    def text(self, unit: str) -> str:
        """The range in words, ``"0.02 to 4 m"`` (in ``shown_unit`` where one is set)."""
        if self.shown_unit:
            low, high, unit = self.low / self.shown_factor, self.high / self.shown_factor, self.shown_unit
            low_text, high_text = f"{float(f'{low:.6g}'):g}", f"{float(f'{high:.6g}'):g}"
            if self.ends:
                return f"in {self.ends[0]}{low_text}, {high_text}{self.ends[1]} {unit}"
            return f"{low_text} to {high_text} {unit}"
        return f"{_number(self.low)} to {_number(self.high)}{' ' + unit if unit else ''}"

    def shown(self, value: float, unit: str) -> tuple[float, str]:
        """``value`` (SI, of ``unit``) as the message shows it."""
        if self.shown_unit:
            return float(f"{value / self.shown_factor:.10g}"), self.shown_unit
        return value, unit

    def __get_pydantic_json_schema__(
        self, schema: core_schema.CoreSchema, handler: GetJsonSchemaHandler
    ) -> JsonSchemaValue:
        out = handler(schema)
        out["x-plausible"] = [self.low, self.high]
        out["x-plausible-source"] = self.source
        return out


@dataclass(frozen=True)
class PlausibleRatio:
    """A cross-field plausibility check of a table: a ratio of its fields in a plausible range.

    Declared in the table's model as ``plausible_ratios`` (a class variable); the check names
    ``field``, the field most likely to hold a unit slip, and tries the usual units of that
    field for the suggestion. Listing ``field`` in ``[case] unusual`` lowers this check too.

    Attributes
    ----------
    field : str
        Path of the named field relative to the table (``"radial_clearance"``,
        ``"operation.load"``); the check is skipped when it is not given.
    name : str
        The ratio as written in the message (``"c/R"``).
    ratio : callable
        ``ratio(table, value)``: the ratio with ``value`` in place of the named field (SI).
    low, high : float
        Plausible range of the ratio.
    source : str
        Where the range comes from.
    meaning : str
        What the ratio is, in words, for the README.
    uses : tuple of str
        The other fields of the ratio (relative paths), shown in the message.
    unit : str
        SI unit of the ratio (``"Pa"``), ``""`` for a number.
    """

    field: str
    name: str
    ratio: Callable[[Any, float], float]
    low: float
    high: float
    source: str
    meaning: str
    uses: tuple[str, ...] = ()
    unit: str = ""

    def text(self) -> str:
        return Plausible(self.low, self.high, self.source).text(self.unit)


#: The plausible shaft speed of a marine propulsion line, shared by the capabilities.
SHAFT_SPEED = Plausible(
    0.1 * math.pi / 30,
    1500 * math.pi / 30,
    "0.1 to 1500 rpm: turning gear (about 1 rpm), slow-speed two-stroke (50-120 rpm, seed 004: 90 rpm), geared "
    "medium-speed (up to about 300 rpm), fast ferries and naval craft (up to about 1500 rpm); seed 001 runs "
    "15-215 rpm (engineering judgement); rpm written as a bare number (rad/s) is above from 157 rpm on",
)


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

    #: Cross-field plausibility checks of the table (see :class:`PlausibleRatio`).
    plausible_ratios: ClassVar[tuple[PlausibleRatio, ...]] = ()


class CaseInfo(Section):
    """Labels of the case."""

    name: str = "unnamed case"
    """Name of the case (report title; the base case of a bearing study)."""
    description: str = ""
    """What the case is, for the report."""
    unusual: list[str] = []
    """Fields whose plausible range is lowered, for a genuinely unusual machine: dotted case-file paths, one
    field each (e.g. "bearing.length", "alignment.bearings[3].x"); the report lists them."""


def nested_model(annotation: Any) -> tuple[type[BaseModel], bool] | None:
    """The model of a sub-table inside a field's annotation (through ``Annotated``, ``| None``,
    ``list[...]``) and whether the field is an array of such tables; None for a plain field."""
    from typing import get_args, get_origin

    if isinstance(annotation, type) and issubclass(annotation, BaseModel):
        return annotation, False
    origin = get_origin(annotation)
    for arg in get_args(annotation):
        found = nested_model(arg)
        if found is not None:
            return found[0], found[1] or origin is list
    return None


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


__all__ = [
    "SHAFT_SPEED",
    "CaseInfo",
    "Field",
    "Plausible",
    "PlausibleRatio",
    "Quantity",
    "Section",
    "default_of",
    "field_error",
    "nested_model",
]
