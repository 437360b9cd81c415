"""The ``[bearing]`` table of a case file: a stern-tube bearing film under load.

Layout::

    [bearing]                    geometry of the bearing and bore
    [[bearing.bore]]             slope-bored segments, aft to forward
    [bearing.bent_journal]       journal centre line along the bearing
    [bearing.film_profile]       additive film change from a CSV
    [bearing.operation]          speed, load, misalignment, edge pressures
    [[bearing.operation.grooves]]
    [bearing.lubricant]
    [bearing.solver]             grid and cavitation model
    [[bearing.variants]]         other bores or tilts solved beside the base case
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Annotated, Any, Literal

import numpy as np
from pydantic import BeforeValidator, Field, model_validator

from shaftline.cases.types import (
    Angle,
    Force,
    Length,
    Number,
    PositiveDensity,
    PositiveFraction,
    PositiveKinematicViscosity,
    PositiveLength,
    PositiveViscosity,
    Pressure,
    Quantity,
    Section,
    Temperature,
    default_of,
    field_error,
)
from shaftline.errors import InputError, located
from shaftline.film.geometry import (
    MIN_AXIAL_NODES,
    MIN_CIRCUMFERENTIAL_NODES,
    BearingGeometry,
    BentJournal,
    BoreAnchor,
    BoreSegment,
    FilmProfile,
)
from shaftline.film.problem import (
    BearingProblem,
    CavitatedShear,
    Cavitation,
    FilmStart,
    OperatingPoint,
    SolverOptions,
    SupplyGroove,
)
from shaftline.registry import BuildContext

if TYPE_CHECKING:
    from shaftline.film.study import BearingStudy

ROTATION_ALIASES = {
    "clockwise_from_aft": "clockwise",
    "cw": "clockwise",
    "counterclockwise": "anticlockwise",
    "anticlockwise_from_aft": "anticlockwise",
    "ccw": "anticlockwise",
}


def _rotation_alias(value: Any) -> Any:
    if isinstance(value, str):
        key = value.strip().lower()
        return ROTATION_ALIASES.get(key, key)
    return value


class BoreSegmentSection(Section):
    """A slope-bored segment of the bore (aft to forward)."""

    length_fraction: PositiveFraction
    """Share of the bearing length; the shares of all segments sum to 1."""
    slope: Angle | None = None
    """Slope of the bore axis in the vertical plane (+ rising forward); or give slope_ratio."""
    slope_ratio: Number | None = None
    """Slope as a share of 2c/L (the dimensionless slope of seed 004)."""
    slope_horizontal: Angle = default_of(BoreSegment, "slope_horizontal")
    """Slope in the horizontal plane (+ towards starboard going forward)."""

    @model_validator(mode="after")
    def _one_slope(self) -> BoreSegmentSection:
        if (self.slope is None) == (self.slope_ratio is None):
            raise field_error("slope", "missing" if self.slope is None else self.slope, "either slope or slope_ratio")
        return self


class BentJournalSection(Section):
    """Journal centre line along the bearing (from a shaft model), linearly interpolated."""

    z: list[Length]
    """Stations from the aft edge."""
    dy: list[Length]
    """Vertical offsets of the journal centre at the stations."""
    dz: list[Length] | None = None
    """Horizontal offsets (default zero)."""


class FilmProfileSection(Section):
    """Additive film change delta(theta, z) from a CSV (wear, bore errors)."""

    file: str
    """CSV with columns theta_deg, z, delta on a full grid; path relative to the case file."""
    length_unit: str = "m"
    """Unit of z and delta in the file."""


class GrooveSection(Section):
    """An axial supply groove."""

    angle: Angle
    """Angle of the groove centre from the top, in the sense of rotation."""
    pressure: Pressure = default_of(SupplyGroove, "pressure")
    """Supply pressure above ambient."""
    length_fraction: PositiveFraction = default_of(SupplyGroove, "length_fraction")
    """Axial length of the groove, share of the bearing length (centred)."""


class OperationSection(Section):
    """Running condition, load and misalignment."""

    speed: Annotated[float, Quantity("speed", ge=0)]
    """Shaft speed."""
    load: Annotated[float, Quantity("force", ge=0)]
    """Magnitude of the downward load on the journal."""
    load_horizontal: Force = 0.0
    """Horizontal load on the journal (+ starboard)."""
    tilt_vertical: Angle | None = None
    """Journal tilt relative to the bore, vertical plane (+ journal rising forward); or misalignment_ratio_vertical."""
    tilt_horizontal: Angle | None = None
    """Journal tilt, horizontal plane; or misalignment_ratio_horizontal."""
    misalignment_ratio_vertical: Number | None = None
    """Tilt as a share of 2c/L (psi of seed 004)."""
    misalignment_ratio_horizontal: Number | None = None
    """Horizontal tilt as a share of 2c/L."""
    aft_pressure: Pressure = default_of(OperatingPoint, "aft_pressure")
    """Pressure at the aft edge above ambient."""
    fore_pressure: Pressure = default_of(OperatingPoint, "fore_pressure")
    """Pressure at the forward edge above ambient."""
    cavitation_pressure: Pressure = default_of(OperatingPoint, "cavitation_pressure")
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


class LubricantSection(Section):
    """The lubricant: a constant viscosity, a preset at a temperature, or an oil given by
    two kinematic viscosities (ASTM D341) at a temperature."""

    viscosity: PositiveViscosity | None = None
    """Effective dynamic viscosity of the film."""
    preset: str | None = None
    """Named lubricant: ISO VG 68, ISO VG 100, ISO VG 150, SAE 30, water, sea water."""
    temperature: Temperature | None = None
    """Effective film temperature (with a preset or two-point oil)."""
    density: PositiveDensity | None = None
    """Density (with viscosity; density at 15 degC of a two-point oil); default 880 kg/m^3."""
    kinematic_viscosity_1: PositiveKinematicViscosity | None = None
    """Kinematic viscosity at temperature_1 of a two-point oil."""
    temperature_1: Temperature | None = None
    """First reference temperature (e.g. 40 degC)."""
    kinematic_viscosity_2: PositiveKinematicViscosity | None = None
    """Kinematic viscosity at temperature_2."""
    temperature_2: Temperature | None = None
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


class SolverSection(Section):
    """Grid and models of the film solution."""

    axial_nodes: Annotated[int, Field(ge=MIN_AXIAL_NODES)] = default_of(SolverOptions, "axial_nodes")
    """Grid nodes along the bearing, edges included."""
    circumferential_nodes: Annotated[int, Field(ge=MIN_CIRCUMFERENTIAL_NODES)] = default_of(
        SolverOptions, "circumferential_nodes"
    )
    """Grid nodes around the bore."""
    cavitation: Cavitation = default_of(SolverOptions, "cavitation")
    """Reynolds (Swift-Stieber), jfo (mass-conserving; needs an edge or groove pressure above the cavitation
    pressure) or half_sommerfeld (comparison only)."""
    film_start: FilmStart = default_of(SolverOptions, "film_start")
    """periodic (the film is continuous all round) or max_film (ambient pressure at the thickest film, as the
    classical design charts)."""
    cavitated_shear: CavitatedShear = default_of(SolverOptions, "cavitated_shear")
    """Shear in the cavitated zone: film_fraction (liquid streamers only) or full_film (design-chart friction)."""
    min_film_floor: Annotated[float, Quantity("dimensionless", gt=0, lt=0.5)] = default_of(
        SolverOptions, "min_film_floor"
    )
    """Smallest film, share of the radial clearance, the equilibrium may approach before reporting contact."""
    tolerance: Annotated[float, Quantity("dimensionless", gt=0, lt=0.01)] = default_of(SolverOptions, "tolerance")
    """Relative force residual at which the equilibrium is accepted."""
    max_iterations: Annotated[int, Field(ge=1, le=1000)] = default_of(SolverOptions, "max_iterations")
    """Newton iterations allowed for the equilibrium."""


class VariantSection(Section):
    """A further bore or tilt solved beside the base case."""

    name: str
    """Label of the variant."""
    bore: list[BoreSegmentSection] | None = None
    """Slope-bored segments replacing the base case's bore."""
    misalignment_ratio_vertical: Number | None = None
    """Vertical tilt as a share of 2c/L, replacing the base case's."""
    tilt_vertical: Angle | None = None
    """Vertical tilt replacing the base case's."""

    @model_validator(mode="after")
    def _one_tilt(self) -> VariantSection:
        if self.tilt_vertical is not None and self.misalignment_ratio_vertical is not None:
            raise field_error(
                "tilt_vertical", self.tilt_vertical, "either tilt_vertical or misalignment_ratio_vertical"
            )
        return self


class BearingSection(Section):
    """A stern-tube journal bearing film at equilibrium under its load."""

    length: PositiveLength
    """Bearing length L."""
    diameter: PositiveLength
    """Journal diameter D."""
    radial_clearance: PositiveLength | None = None
    """Radial clearance c; or diametral_clearance."""
    diametral_clearance: PositiveLength | None = None
    """Diametral clearance 2c."""
    rotation: Annotated[Literal["clockwise", "anticlockwise"], BeforeValidator(_rotation_alias)] = "clockwise"
    """Sense of rotation seen from aft."""
    bore_anchor: BoreAnchor = default_of(BearingGeometry, "bore_anchor")
    """Where a slope-bored bore keeps the nominal axis."""
    bore: list[BoreSegmentSection] = []
    """Slope-bored segments, aft to forward (none: a straight bore)."""
    bent_journal: BentJournalSection | None = None
    """Journal centre line along the bearing."""
    film_profile: FilmProfileSection | None = None
    """Additive film change from a CSV."""
    operation: OperationSection
    """Speed, load and misalignment."""
    lubricant: LubricantSection
    """The lubricant."""
    solver: SolverSection = SolverSection()
    """Grid and models."""
    variants: list[VariantSection] = []
    """Further bores or tilts solved beside the base case."""

    @model_validator(mode="after")
    def _one_clearance(self) -> BearingSection:
        if (self.radial_clearance is None) == (self.diametral_clearance is None):
            raise field_error(
                "radial_clearance",
                "missing" if self.radial_clearance is None else self.radial_clearance,
                "exactly one of radial_clearance or diametral_clearance",
                "m",
            )
        names = [variant.name for variant in self.variants]
        for k, name in enumerate(names):
            if name in names[:k]:
                raise field_error(f"variants[{k}].name", name, "a name not used by another variant")
        return self


def read_film_profile(path: Any, length_unit: str = "m") -> FilmProfile:
    """Read an additive film profile from CSV: columns ``theta_deg, z, delta``, one row per
    point of a full regular grid (any order); z and delta in ``length_unit``."""
    from shaftline.csvio import read_columns
    from shaftline.units import to_si

    scale = to_si(f"1 {length_unit}", "length", "length_unit")
    table = read_columns(path, ["theta_deg", "z", "delta"], "file")
    theta = np.unique(table["theta_deg"])
    z = np.unique(table["z"])
    if theta.size * z.size != table["z"].size:
        raise InputError("file", str(path), "", f"a full grid of {theta.size} angles x {z.size} stations")
    delta = np.full((z.size, theta.size), np.nan)
    delta[np.searchsorted(z, table["z"]), np.searchsorted(theta, table["theta_deg"])] = table["delta"]
    if np.isnan(delta).any():
        raise InputError("file", str(path), "", "each (theta_deg, z) pair exactly once")
    return FilmProfile(theta=np.radians(theta), z=z * scale, delta=delta * scale)


def _bore(segments: list[BoreSegmentSection], length: float, clearance: float) -> tuple[BoreSegment, ...]:
    return tuple(
        BoreSegment(
            length_fraction=segment.length_fraction,
            slope=segment.slope_ratio * 2.0 * clearance / length
            if segment.slope_ratio is not None
            else segment.slope or 0.0,
            slope_horizontal=segment.slope_horizontal,
        )
        for segment in segments
    )


def _tilt(angle: float | None, ratio: float | None, length: float, clearance: float) -> float:
    if ratio is not None:
        return ratio * 2.0 * clearance / length
    return 0.0 if angle is None else angle


def build_study(section: BearingSection, context: BuildContext) -> BearingStudy:
    """The base case and its variants in SI domain objects (raises :class:`InputError` with
    the field's path inside ``[bearing]``)."""
    from shaftline.film.study import BearingCase, BearingStudy
    from shaftline.lubricants import Lubricant

    clearance = (
        section.radial_clearance if section.radial_clearance is not None else 0.5 * (section.diametral_clearance or 0.0)
    )
    length = section.length
    bent = None
    if section.bent_journal is not None:
        journal = section.bent_journal
        with located("bent_journal"):
            bent = BentJournal(
                z=np.asarray(journal.z),
                dy=np.asarray(journal.dy),
                dz=np.asarray(journal.dz if journal.dz is not None else [0.0] * len(journal.z)),
            )
    profile = None
    if section.film_profile is not None:
        with located("film_profile"):
            profile = read_film_profile(context.path(section.film_profile.file), section.film_profile.length_unit)

    def geometry(bore: tuple[BoreSegment, ...], where: str) -> BearingGeometry:
        with located("", {"bore": where}):
            return BearingGeometry(
                length=length,
                diameter=section.diameter,
                radial_clearance=clearance,
                bore=bore,
                bore_anchor=section.bore_anchor,
                bent_journal=bent,
                film_profile=profile,
                rotation=1 if section.rotation == "clockwise" else -1,
            )

    base_geometry = geometry(_bore(section.bore, length, clearance), "bore")
    lube = section.lubricant
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
    op = section.operation
    # OperatingPoint carries the lubricant's viscosity and density: their errors belong there.
    with located("operation", {"viscosity": "lubricant.viscosity", "density": "lubricant.density"}):
        operating = OperatingPoint(
            speed=op.speed,
            viscosity=viscosity,
            density=density,
            aft_pressure=op.aft_pressure,
            fore_pressure=op.fore_pressure,
            cavitation_pressure=op.cavitation_pressure,
            grooves=tuple(SupplyGroove(g.angle, g.pressure, g.length_fraction) for g in op.grooves),
        )
    s = section.solver
    with located("solver"):
        options = SolverOptions(
            axial_nodes=s.axial_nodes,
            circumferential_nodes=s.circumferential_nodes,
            cavitation=s.cavitation,
            film_start=s.film_start,
            cavitated_shear=s.cavitated_shear,
            min_film_floor=s.min_film_floor,
            tolerance=s.tolerance,
            max_iterations=s.max_iterations,
        )
    with located("", {"operating": "operation", "options": "solver"}):
        BearingProblem(base_geometry, operating, options)
    tilt_y = _tilt(op.tilt_vertical, op.misalignment_ratio_vertical, length, clearance)
    tilt_z = _tilt(op.tilt_horizontal, op.misalignment_ratio_horizontal, length, clearance)

    def case(name: str, geometry: BearingGeometry, tilt: float, tilt_field: str) -> BearingCase:
        # A journal that does not fit in the bore is the tilt's fault, or the bent journal's.
        fields = {
            "tilt_y": "bent_journal" if bent is not None else tilt_field,
            "tilt_z": "bent_journal" if bent is not None else "operation.tilt_horizontal",
            "load_y": "operation.load",
            "load_z": "operation.load_horizontal",
        }
        return BearingCase(
            name=name,
            geometry=geometry,
            operating=operating,
            options=options,
            load_y=-op.load,
            load_z=op.load_horizontal,
            tilt_y=tilt,
            tilt_z=tilt_z,
            lubricant=lubricant,
            temperature=lube.temperature,
            error_fields=fields,
        )

    cases = [case(context.case.name, base_geometry, tilt_y, "operation.tilt_vertical")]
    for k, variant in enumerate(section.variants):
        if variant.name == context.case.name:
            raise InputError(f"variants[{k}].name", variant.name, "", "a name other than the case's ([case] name)")
        variant_geometry = base_geometry
        if variant.bore is not None:
            variant_geometry = geometry(_bore(variant.bore, length, clearance), f"variants[{k}].bore")
        variant_tilt, tilt_field = tilt_y, "operation.tilt_vertical"
        if variant.misalignment_ratio_vertical is not None or variant.tilt_vertical is not None:
            variant_tilt = _tilt(variant.tilt_vertical, variant.misalignment_ratio_vertical, length, clearance)
            tilt_field = f"variants[{k}].tilt_vertical"
        cases.append(case(variant.name, variant_geometry, variant_tilt, tilt_field))
    return BearingStudy(tuple(cases))
