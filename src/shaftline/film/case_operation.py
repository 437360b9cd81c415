"""The running condition in ``[bearing]``: speed, load and misalignment
(``[bearing.operation]`` with its ``[[bearing.operation.grooves]]``), the lubricant
(``[bearing.lubricant]``) and the film temperature from the heat balance
(``[bearing.thermal]``), and the domain objects built from them."""

from __future__ import annotations

import math
from typing import TYPE_CHECKING, Annotated

from pydantic import model_validator

from shaftline.cases.types import (
    SHAFT_SPEED,
    Angle,
    Force,
    Number,
    Plausible,
    PositiveDensity,
    PositiveFraction,
    PositiveKinematicViscosity,
    PositiveViscosity,
    Pressure,
    Quantity,
    Section,
    Temperature,
    default_of,
    field_error,
)
from shaftline.errors import InputError, located
from shaftline.film.case_geometry import CLEARANCE_SHARE, SLOPE
from shaftline.film.problem import OperatingPoint, SupplyGroove

if TYPE_CHECKING:
    from shaftline.film.thermal import ThermalOptions
    from shaftline.lubricants import Lubricant

EDGE_PRESSURE = Plausible(
    -1.1e5,
    1e6,
    "sea-water head at the stern (draught up to about 25 m: 2.5 bar), header tanks and feed pumps are a few bar; "
    "seed 001 feeds water at 1.3 bar; below -1 bar gauge is vacuum (engineering judgement); a pressure in "
    "bar written as MPa is above 10 bar",
)
BEARING_LOAD = Plausible(
    0.0,
    3e7,
    "the heaviest aft stern-tube bearings carry a few MN (a 130 t propeller is 1.3 MN; seed 004: 0.31 MN); "
    "30 MN is ten times that (engineering judgement)",
)


class GrooveSection(Section):
    """An axial supply groove."""

    angle: Annotated[
        Angle,
        Plausible(
            -2 * math.pi,
            2 * math.pi,
            "a place around the bore: a turn either way; deg as a bare number (rad) is beyond from 7 deg on",
        ),
    ]
    """Angle of the groove centre from the top, in the sense of rotation."""
    pressure: Annotated[Pressure, EDGE_PRESSURE] = default_of(SupplyGroove, "pressure")
    """Supply pressure above ambient."""
    length_fraction: PositiveFraction = default_of(SupplyGroove, "length_fraction")
    """Axial length of the groove, share of the bearing length (centred)."""


class OperationSection(Section):
    """Running condition, load and misalignment."""

    speed: Annotated[float, Quantity("speed", ge=0), SHAFT_SPEED]
    """Shaft speed."""
    load: Annotated[float, Quantity("force", ge=0), BEARING_LOAD]
    """Magnitude of the downward load on the journal."""
    load_horizontal: Annotated[Force, Plausible(-BEARING_LOAD.high, BEARING_LOAD.high, BEARING_LOAD.source)] = 0.0
    """Horizontal load on the journal (+ starboard)."""
    tilt_vertical: Annotated[Angle, SLOPE] | None = None
    """Journal tilt relative to the bore, vertical plane (+ journal rising forward); or misalignment_ratio_vertical."""
    tilt_horizontal: Annotated[Angle, SLOPE] | None = None
    """Journal tilt, horizontal plane; or misalignment_ratio_horizontal."""
    misalignment_ratio_vertical: Annotated[Number, CLEARANCE_SHARE] | None = None
    """Tilt as a share of 2c/L (psi of seed 004)."""
    misalignment_ratio_horizontal: Annotated[Number, CLEARANCE_SHARE] | None = None
    """Horizontal tilt as a share of 2c/L."""
    aft_pressure: Annotated[Pressure, EDGE_PRESSURE] = default_of(OperatingPoint, "aft_pressure")
    """Pressure at the aft edge above ambient."""
    fore_pressure: Annotated[Pressure, EDGE_PRESSURE] = default_of(OperatingPoint, "fore_pressure")
    """Pressure at the forward edge above ambient."""
    cavitation_pressure: Annotated[Pressure, EDGE_PRESSURE] = default_of(OperatingPoint, "cavitation_pressure")
    """Pressure at which the film ruptures, above ambient."""
    grooves: list[GrooveSection] = []
    """Axial supply grooves."""

    @model_validator(mode="after")
    def _consistent(self) -> OperationSection:
        if self.tilt_vertical is not None and self.misalignment_ratio_vertical is not None:
            raise field_error(
                "tilt_vertical", self.tilt_vertical, "either tilt_vertical or misalignment_ratio_vertical"
            )
        if self.tilt_horizontal is not None and self.misalignment_ratio_horizontal is not None:
            raise field_error(
                "tilt_horizontal", self.tilt_horizontal, "either tilt_horizontal or misalignment_ratio_horizontal"
            )
        if self.load == 0 and self.load_horizontal == 0:
            raise field_error("load", 0.0, "> 0", "N")
        if self.speed == 0:
            raise field_error("speed", 0.0, "> 0 when the bearing carries a load", "rad/s")
        return self


PRESET_TEXT = "ISO VG 68, ISO VG 100, ISO VG 150, SAE 30, water, sea water"


REFERENCE_TEMPERATURE = Plausible(
    -20.0,
    150.0,
    "the reference temperatures of oil data are 40 and 100 degC (ISO 3448, ASTM D341); degF written as degC "
    "(212 for 100 degC) is above 150",
)
KINEMATIC_VISCOSITY = Plausible(
    2e-7,
    5e-3,
    "0.2 to 5000 cSt: water at 100 degC is 0.3 cSt, ISO VG 68-150 oils are about 10-150 cSt at 40-100 degC "
    "(ISO 3448) and a few thousand at 0 degC (engineering judgement); cSt written as a bare number (m^2/s) is "
    "far above",
)


class LubricantSection(Section):
    """The lubricant: a constant viscosity, a preset at a temperature, or an oil given by
    two kinematic viscosities (ASTM D341) at a temperature."""

    viscosity: (
        Annotated[
            PositiveViscosity,
            Plausible(
                1e-4,
                5.0,
                "0.1 mPa s to 5 Pa s: water at 100 degC is 0.28 mPa s, sea water at 0 degC 1.9 mPa s, seed 004's "
                "SAE 30 at 40 degC 0.07 Pa s, ISO VG 150 at 0 degC about 2 Pa s (engineering judgement); Pa s "
                "written as mPa s (the seed's own slip: 0.07 mPa s) or cP of an oil as a bare number is outside",
            ),
        ]
        | None
    ) = None
    """Effective dynamic viscosity of the film."""
    preset: str | None = None
    """Named lubricant: ISO VG 68, ISO VG 100, ISO VG 150, SAE 30, water, sea water."""
    temperature: (
        Annotated[
            Temperature,
            Plausible(
                -5.0,
                120.0,
                "sea water from -2 degC; stern-tube oil runs at about 30-70 degC (seed 004: 40 degC, robustness test "
                "hotter) with alarms near 65-80 degC (engineering judgement); degF written as degC (140 for 60 degC) "
                "is above 120",
            ),
        ]
        | None
    ) = None
    """Effective film temperature (with a preset or two-point oil)."""
    density: (
        Annotated[
            PositiveDensity,
            Plausible(
                600.0,
                1400.0,
                "mineral and synthetic oils 820-1000 kg/m^3, water 1000-1030 (seed 004: 890); g/cm^3 as a bare number "
                "is far below",
            ),
        ]
        | None
    ) = None
    """Density (with viscosity; density at 15 degC of a two-point oil); default 880 kg/m^3."""
    kinematic_viscosity_1: Annotated[PositiveKinematicViscosity, KINEMATIC_VISCOSITY] | None = None
    """Kinematic viscosity at temperature_1 of a two-point oil."""
    temperature_1: Annotated[Temperature, REFERENCE_TEMPERATURE] | None = None
    """First reference temperature (e.g. 40 degC)."""
    kinematic_viscosity_2: Annotated[PositiveKinematicViscosity, KINEMATIC_VISCOSITY] | None = None
    """Kinematic viscosity at temperature_2."""
    temperature_2: Annotated[Temperature, REFERENCE_TEMPERATURE] | None = None
    """Second reference temperature (e.g. 100 degC)."""
    name: str | None = None
    """Label of the lubricant."""

    @model_validator(mode="after")
    def _one_source(self) -> LubricantSection:
        two_points = [self.kinematic_viscosity_1, self.temperature_1, self.kinematic_viscosity_2, self.temperature_2]
        sources = sum([self.viscosity is not None, self.preset is not None, any(v is not None for v in two_points)])
        if sources != 1:
            raise field_error(
                "viscosity",
                "given twice" if sources else "missing",
                "exactly one of: viscosity; preset with temperature; kinematic_viscosity_1, temperature_1, "
                "kinematic_viscosity_2, temperature_2 with temperature",
            )
        if any(v is not None for v in two_points):
            names = ("kinematic_viscosity_1", "temperature_1", "kinematic_viscosity_2", "temperature_2")
            for name, value in zip(names, two_points, strict=True):
                if value is None:
                    raise field_error(name, "missing", "all four two-point fields")
        if self.preset is not None and self.density is not None:
            raise field_error("density", self.density, "no density with a preset (the preset has its own)", "kg/m^3")
        if self.viscosity is None and self.temperature is None:
            raise field_error("temperature", "missing", "a film temperature with a preset or a two-point oil", "degC")
        return self


class ThermalSection(Section):
    """Oil (or water) temperature from the bearing's heat balance (ISO 7902-1 style, docs/theory.md
    Sect. 8.1): the film runs at the effective temperature where its friction heat and the
    lubricant's viscosity agree, instead of the lubricant table's temperature. Needs a lubricant
    whose viscosity follows temperature (a preset or a two-point oil)."""

    inlet_temperature: Annotated[Temperature, Quantity("temperature", ge=-40.0, le=250.0)]
    """Temperature of the lubricant reaching the film (header tank, cooled oil, the sea)."""
    heat_to_lubricant: Annotated[float, Quantity("dimensionless", gt=0, le=1)] = 1.0
    """Share of the friction power carried away by the lubricant; 1 (default) is the adiabatic
    bound, the rest is conducted through the housing and shaft."""


def lubricant_properties(lube: LubricantSection) -> tuple[Lubricant, float, float]:
    """The lubricant of a ``lubricant`` table, and its film viscosity (Pa s) and density (kg/m^3)."""
    from shaftline.lubricants import Lubricant

    with located("lubricant", {"name": "lubricant.preset", "density_15": "lubricant.density"}):
        if lube.viscosity is not None:
            lubricant = Lubricant.constant(
                lube.viscosity, lube.density or 880.0, name=lube.name or "constant viscosity"
            )
            viscosity, density = lube.viscosity, lube.density or 880.0
        else:
            if lube.preset is not None:
                lubricant = Lubricant.preset(lube.preset)
            else:
                assert lube.temperature_1 is not None and lube.temperature_2 is not None
                assert lube.kinematic_viscosity_1 is not None and lube.kinematic_viscosity_2 is not None
                lubricant = Lubricant.from_two_points(
                    lube.name or "two-point oil",
                    lube.temperature_1,
                    lube.kinematic_viscosity_1,
                    lube.temperature_2,
                    lube.kinematic_viscosity_2,
                    lube.density or 880.0,
                )
            assert lube.temperature is not None  # checked by the schema
            viscosity = float(lubricant.dynamic_viscosity(lube.temperature))
            density = float(lubricant.density(lube.temperature))
    return lubricant, viscosity, density


def operating_point(op: OperationSection, viscosity: float, density: float) -> OperatingPoint:
    """The film's :class:`OperatingPoint` of an ``operation`` table with the lubricant's
    film viscosity (Pa s) and density (kg/m^3)."""
    # OperatingPoint carries the lubricant's viscosity and density: their errors belong there.
    with located("operation", {"viscosity": "lubricant.viscosity", "density": "lubricant.density"}):
        return OperatingPoint(
            speed=op.speed,
            viscosity=viscosity,
            density=density,
            aft_pressure=op.aft_pressure,
            fore_pressure=op.fore_pressure,
            cavitation_pressure=op.cavitation_pressure,
            grooves=tuple(SupplyGroove(g.angle, g.pressure, g.length_fraction) for g in op.grooves),
        )


def thermal_options(section: ThermalSection, lube: LubricantSection, lubricant: Lubricant) -> ThermalOptions:
    """The :class:`~shaftline.film.thermal.ThermalOptions` of a ``thermal`` table for the
    lubricant ``lubricant`` of the ``lubricant`` table ``lube``: one whose viscosity follows
    temperature, with the inlet temperature inside its data."""
    from shaftline.film.thermal import TEMPERATURE_RANGES, ThermalOptions

    if lubricant.model == "constant":
        raise InputError(
            "lubricant.viscosity",
            lube.viscosity,
            "Pa s",
            "a lubricant whose viscosity follows temperature (a preset or a two-point oil) with [bearing.thermal]",
        )
    low, high = TEMPERATURE_RANGES[lubricant.model]
    inlet = section.inlet_temperature
    if not low <= inlet < high:
        raise InputError(
            "thermal.inlet_temperature", inlet, "degC", f"{low:g} to {high:g} degC, the range of {lubricant.name}"
        )
    with located("thermal"):
        return ThermalOptions(inlet, section.heat_to_lubricant)
