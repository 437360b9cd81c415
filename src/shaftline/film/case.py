"""The ``[bearing]`` table of a case file: a stern-tube bearing film under load.

Layout::

    [bearing]                    geometry of the bearing and bore
    [[bearing.bore]]             slope-bored segments, aft to forward
    [bearing.bent_journal]       journal centre line along the bearing
    [bearing.film_profile]       additive film change from a CSV
    [bearing.operation]          speed, load, misalignment, edge pressures
    [[bearing.operation.grooves]]
    [bearing.lubricant]
    [bearing.surface]            rough journal and bore: mixed lubrication
    [bearing.liner]              elastic liner on the bore (column or bonded-layer model)
    [bearing.thermal]            film temperature from the heat balance
    [bearing.solver]             grid and cavitation model
    [[bearing.variants]]         other bores or tilts solved beside the base case
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING, Annotated, Any, Literal

import numpy as np
from pydantic import BeforeValidator, Field, model_validator

from shaftline.cases.types import (
    SHAFT_SPEED,
    Angle,
    Force,
    Length,
    NonNegativeLength,
    Number,
    Plausible,
    PlausibleRatio,
    PositiveDensity,
    PositiveFraction,
    PositiveKinematicViscosity,
    PositiveLength,
    PositivePressure,
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
from shaftline.film.liner import Liner
from shaftline.film.problem import (
    BearingProblem,
    CavitatedShear,
    Cavitation,
    FilmStart,
    OperatingPoint,
    SolverOptions,
    SupplyGroove,
)
from shaftline.film.roughness import SurfaceRoughness
from shaftline.film.study import BearingCase
from shaftline.film.turbulence import TurbulenceMode, TurbulenceModel
from shaftline.registry import BuildContext

if TYPE_CHECKING:
    from shaftline.film.study import BearingStudy
    from shaftline.lubricants import Lubricant

ROTATION_ALIASES = {
    "clockwise_from_aft": "clockwise",
    "cw": "clockwise",
    "counterclockwise": "anticlockwise",
    "anticlockwise_from_aft": "anticlockwise",
    "ccw": "anticlockwise",
}


# Plausible ranges of a marine stern-tube bearing (the README's table of plausible ranges is
# made from them). They are generous: they catch a unit slip (a factor of 25.4 or 1000, a
# bare number read as SI), not an unusual bearing, which a case lists in [case] unusual.
_SEEDS = "seed 004 Table 5-1 (L = 1.05 m, D = 0.52 m, c = 0.45 mm), seed 001 Table 1 (L = 1.2 m, D = 0.324 m)"
SLOPE = Plausible(
    -0.01,
    0.01,
    "relative slopes in stern-tube bearings are about 0.1-0.5 mrad (class limit about 0.3 mrad, rules.toml; "
    "seed 004 tilts 0.3-0.6 x 2c/L, 0.26-0.51 mrad); 10 mrad (0.57 deg) is 20 times that, a slope in mrad or "
    "deg written as a bare number (rad) is far above it",
)
CLEARANCE_SHARE = Plausible(
    -3.0,
    3.0,
    "seed 004 optimises slopes and tilts of 0.1-0.6 x 2c/L; 1 brings the journal edge onto the bore, 3 is "
    "three times that (engineering judgement); a share written in % (30 for 0.3) is far outside",
)
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


def _rotation_alias(value: Any) -> Any:
    if isinstance(value, str):
        key = value.strip().lower()
        return ROTATION_ALIASES.get(key, key)
    return value


class BoreSegmentSection(Section):
    """A slope-bored segment of the bore (aft to forward)."""

    length_fraction: PositiveFraction
    """Share of the bearing length; the shares of all segments sum to 1."""
    slope: Annotated[Angle, SLOPE] | None = None
    """Slope of the bore axis in the vertical plane (+ rising forward); or give slope_ratio."""
    slope_ratio: Annotated[Number, CLEARANCE_SHARE] | None = None
    """Slope as a share of 2c/L (the dimensionless slope of seed 004)."""
    slope_horizontal: Annotated[Angle, SLOPE] = default_of(BoreSegment, "slope_horizontal")
    """Slope in the horizontal plane (+ towards starboard going forward)."""

    @model_validator(mode="after")
    def _one_slope(self) -> BoreSegmentSection:
        if (self.slope is None) == (self.slope_ratio is None):
            raise field_error("slope", "missing" if self.slope is None else self.slope, "either slope or slope_ratio")
        return self


JOURNAL_OFFSET = Plausible(
    -0.01,
    0.01,
    "the journal's bend within a bearing is of the order of its clearance (seed 004 Table 5-29: up to 0.7 mm); "
    "10 mm is ten times the largest clearances (engineering judgement); mm written as m is above it",
)


class BentJournalSection(Section):
    """Journal centre line along the bearing (from a shaft model), linearly interpolated."""

    z: list[Annotated[Length, Plausible(0.0, 4.0, "stations within the bearing: as its length")]]
    """Stations from the aft edge."""
    dy: list[Annotated[Length, JOURNAL_OFFSET]]
    """Vertical offsets of the journal centre at the stations."""
    dz: list[Annotated[Length, JOURNAL_OFFSET]] | None = None
    """Horizontal offsets (default zero)."""


class FilmProfileSection(Section):
    """Additive film change delta(theta, z) from a CSV (wear, bore errors)."""

    file: str
    """CSV with columns theta_deg, z, delta on a full grid; path relative to the case file."""
    length_unit: str = "m"
    """Unit of z and delta in the file."""


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
    memory_limit: Annotated[float, Quantity("memory", gt=0)] | None = None
    """Largest memory a film solution may take (e.g. "8 GiB"); a finer grid is refused before
    anything is allocated. Default: half the machine's memory."""
    turbulence: TurbulenceMode = default_of(SolverOptions, "turbulence")
    """Turbulent film (large, fast, low-viscosity films such as water): off (laminar), on (the turbulence
    coefficients at every node), or auto (on above the Taylor-vortex onset, 2 rho omega R c / mu > 41.3 sqrt(R/c));
    the local Reynolds number is reported unless off."""
    turbulence_model: TurbulenceModel = default_of(SolverOptions, "turbulence_model")
    """Coefficients of the turbulent film: ng_pan (Ng & Pan 1965) or constantinescu (Constantinescu 1962)."""


_SURFACE_ROUGHNESS = (
    "machined journals and bores: Ra 0.1 um (lapped) to 6.3 um (rough turned); seed 001: polymer liner Ra 1.6 um, "
    "sleeve Ra 0.8 um; 20 um keeps a value in um written as mm out (engineering judgement)"
)
_ASPERITY_RADIUS = (
    "asperity tip radii from profiles of machined surfaces, about 1 um to 1 mm (Greenwood & Williamson 1966: "
    "tens of um; sigma/beta = 0.001 on Ra 1 um is about 1 mm); mm written as m is above (engineering judgement)"
)
_ASPERITY_DENSITY = (
    "asperities per m^2 from profiles of machined surfaces, about 1e8 to 1e12 (Greenwood & Williamson 1966: "
    "1e9-1e11; sigma beta eta 0.04 with sigma 1 um and beta 1 mm is 4e7); per mm^2 written as per m^2 is "
    "below (engineering judgement)"
)
_MODULUS = (
    "nitrile rubber liners about 3-10 MPa, polymer composites 1-10 GPa (seed 001: 2320 MPa), white metal about "
    "50 GPa, steel 206 GPa; 3 MPa to 500 GPa keeps GPa written as MPa and MPa as kPa out (engineering judgement)"
)


class SurfaceSection(Section):
    """Rough journal and bore: Patir-Cheng flow factors in the film and Greenwood-Tripp asperity
    contact (mixed lubrication, docs/theory.md). A preset gives every field; fields given
    beside it replace the preset's."""

    preset: Literal["steel_polymer", "turned_steel_white_metal", "ground_steel_white_metal"] | None = None
    """Named surface pair (docs/theory.md lists the sources): steel_polymer (seed 001's rig),
    turned_steel_white_metal, ground_steel_white_metal."""
    journal_roughness: Annotated[NonNegativeLength, Plausible(0.0, 2e-5, _SURFACE_ROUGHNESS)] | None = None
    """Roughness of the journal (sleeve)."""
    bore_roughness: Annotated[NonNegativeLength, Plausible(0.0, 2e-5, _SURFACE_ROUGHNESS)] | None = None
    """Roughness of the bore (liner)."""
    roughness_parameter: Literal["Rq", "Ra"] = "Ra"
    """Rq (root mean square) or Ra (arithmetic mean; Rq = 1.25 Ra, seed 001 Eq. 10)."""
    journal_modulus: Annotated[PositivePressure, Plausible(3e6, 5e11, _MODULUS)] | None = None
    """Young's modulus of the journal (default steel, 206 GPa)."""
    journal_poisson: Annotated[float, Quantity("dimensionless", gt=0, lt=0.5)] | None = None
    """Poisson's ratio of the journal (default 0.3)."""
    bore_modulus: Annotated[PositivePressure, Plausible(3e6, 5e11, _MODULUS)] | None = None
    """Young's modulus of the bore surface (liner)."""
    bore_poisson: Annotated[float, Quantity("dimensionless", gt=0, lt=0.5)] | None = None
    """Poisson's ratio of the bore surface."""
    sigma_beta_eta: Annotated[float, Quantity("dimensionless", gt=0, lt=1)] | None = None
    """Roughness parameter sigma beta eta (default 0.04)."""
    sigma_over_beta: Annotated[float, Quantity("dimensionless", gt=0, lt=1)] | None = None
    """RMS roughness over asperity tip radius (default 0.001)."""
    asperity_radius: Annotated[PositiveLength, Plausible(1e-7, 0.01, _ASPERITY_RADIUS)] | None = None
    """Mean asperity tip radius beta, measured (in place of sigma_over_beta: sigma / beta with
    sigma the composite Rq)."""
    asperity_density: (
        Annotated[float, Quantity("areal_density", gt=0), Plausible(1e6, 1e14, _ASPERITY_DENSITY)] | None
    ) = None
    """Asperities per unit area eta, measured (with asperity_radius, in place of sigma_beta_eta:
    sigma beta eta with sigma the composite Rq)."""
    boundary_friction: Annotated[float, Quantity("dimensionless", ge=0, lt=1)] | None = None
    """Coefficient of friction on the asperity load (default 0.1)."""

    @model_validator(mode="after")
    def _complete(self) -> SurfaceSection:
        if self.preset is None:
            for name in ("journal_roughness", "bore_roughness", "bore_modulus", "bore_poisson"):
                if getattr(self, name) is None:
                    raise field_error(name, "missing", "a value, or a preset")
        journal, bore = self.journal_roughness, self.bore_roughness
        if journal == 0 and bore == 0:
            raise field_error("bore_roughness", 0.0, "> 0 where journal_roughness is 0 (a rough surface)", "m")
        return self


def surface_roughness(section: SurfaceSection) -> SurfaceRoughness:
    """The :class:`SurfaceRoughness` of a ``surface`` table (fields beside a preset replace it)."""
    from shaftline.film.roughness import PRESETS, RA_TO_RQ, contact_modulus

    base = PRESETS[section.preset] if section.preset is not None else None
    factor = RA_TO_RQ if section.roughness_parameter == "Ra" else 1.0
    journal = section.journal_roughness
    bore = section.bore_roughness
    if base is not None:
        # Preset roughnesses are Ra; a value given beside them is in the table's parameter.
        journal_rq = RA_TO_RQ * base[0] if journal is None else factor * journal
        bore_rq = RA_TO_RQ * base[1] if bore is None else factor * bore
        bore_e = base[2] if section.bore_modulus is None else section.bore_modulus
        bore_nu = base[3] if section.bore_poisson is None else section.bore_poisson
    else:
        assert journal is not None and bore is not None and section.bore_modulus is not None
        assert section.bore_poisson is not None
        journal_rq, bore_rq = factor * journal, factor * bore
        bore_e, bore_nu = section.bore_modulus, section.bore_poisson
    journal_e = 206e9 if section.journal_modulus is None else section.journal_modulus
    journal_nu = 0.3 if section.journal_poisson is None else section.journal_poisson
    sigma_beta_eta, sigma_over_beta = _asperity_parameters(section, math.hypot(journal_rq, bore_rq))
    names = {"journal_rq": "journal_roughness", "bore_rq": "bore_roughness", "contact_modulus": "bore_modulus"}
    with located("", names):
        defaults = SurfaceRoughness(journal_rq=1.0, bore_rq=1.0)
        return SurfaceRoughness(
            journal_rq=journal_rq,
            bore_rq=bore_rq,
            sigma_beta_eta=sigma_beta_eta or defaults.sigma_beta_eta,
            sigma_over_beta=sigma_over_beta or defaults.sigma_over_beta,
            contact_modulus=contact_modulus(journal_e, journal_nu, bore_e, bore_nu),
            boundary_friction=defaults.boundary_friction
            if section.boundary_friction is None
            else section.boundary_friction,
        )


def _asperity_parameters(section: SurfaceSection, sigma: float) -> tuple[float | None, float | None]:
    """Greenwood-Tripp's sigma beta eta and sigma / beta of a ``surface`` table: as given, or
    from a measured asperity radius beta and density eta with sigma the composite Rq (m; the
    spread of the asperity heights taken as the surfaces', docs/theory.md Sect. 17)."""
    sigma_beta_eta, sigma_over_beta = section.sigma_beta_eta, section.sigma_over_beta
    radius, density = section.asperity_radius, section.asperity_density
    if radius is not None:
        if sigma_over_beta is not None:
            raise InputError("asperity_radius", radius, "m", "sigma_over_beta or asperity_radius, not both")
        sigma_over_beta = sigma / radius
        if not sigma_over_beta < 1.0:
            raise InputError(
                "asperity_radius", radius, "m", f"above the composite roughness {sigma:.3g} m (sigma / beta < 1)"
            )
    if density is not None:
        if radius is None:
            raise InputError("asperity_density", density, "1/m^2", "with asperity_radius (sigma beta eta needs both)")
        if sigma_beta_eta is not None:
            raise InputError("asperity_density", density, "1/m^2", "sigma_beta_eta or asperity_density, not both")
        sigma_beta_eta = sigma * radius * density
        if not sigma_beta_eta < 1.0:
            raise InputError(
                "asperity_density",
                density,
                "1/m^2",
                f"below {1.0 / (sigma * radius):.3g} 1/m^2 (sigma beta eta < 1 with sigma {sigma:.3g} m and beta "
                f"{radius:.3g} m)",
            )
    return sigma_beta_eta, sigma_over_beta


def checked_surface(section: SurfaceSection, clearance: float) -> SurfaceRoughness:
    """:func:`surface_roughness` of a ``surface`` table, its composite roughness checked against
    the radial clearance ``clearance`` (m): below half of it (errors placed under ``surface``)."""
    with located("surface"):
        surface = surface_roughness(section)
    if surface.sigma >= 0.5 * clearance:
        name = "bore_roughness" if surface.bore_rq >= surface.journal_rq else "journal_roughness"
        raise InputError(
            f"surface.{name}",
            getattr(section, name),
            "m",
            f"a composite roughness (now {surface.sigma:.3g} m Rq) below half the radial clearance "
            f"({0.5 * clearance:.3g} m)",
        )
    return surface


class LinerSection(Section):
    """Thin elastic liner bonded to the bore: deforms under the film and asperity pressure by
    the column (Winkler) model or as a bonded elastic layer, solved together with the film
    (docs/theory.md, "Elastic liner", "Elastic layer"). A preset gives every field; fields given
    beside it replace the preset's."""

    model: Literal["column", "layer"] = "column"
    """column: each point of the liner moves under its own pressure (Winkler); layer: the
    surface compliance of an elastic layer bonded to the shell (spreads a load over a few
    thicknesses; takes a rubber liner up to poisson 0.5; slower, docs/theory.md "Elastic layer")."""

    preset: Literal["polymer_composite", "rubber", "white_metal"] | None = None
    """Named liner (docs/theory.md lists the sources): polymer_composite (seed 001's rig, 20 mm,
    2320 MPa, 0.327), rubber (10 mm nitrile, 7 MPa, 0.49: the column model's lower bound of its
    deformation), white_metal (2 mm tin-based, ASTM B23 grade 2, 53 GPa, 0.35)."""
    thickness: PositiveLength | None = None
    """Liner thickness (at most a quarter of the bore radius)."""
    modulus: Annotated[PositivePressure, Plausible(3e6, 5e11, _MODULUS)] | None = None
    """Young's modulus of the liner."""
    poisson: Annotated[float, Quantity("dimensionless", gt=0, le=0.5)] | None = None
    """Poisson's ratio of the liner, in (0, 0.5); the layer model also takes 0.5."""

    @model_validator(mode="after")
    def _complete(self) -> LinerSection:
        if self.preset is None:
            for name in ("thickness", "modulus", "poisson"):
                if getattr(self, name) is None:
                    raise field_error(name, "missing", "a value, or a preset")
        if self.model == "column" and self.poisson == 0.5:
            raise field_error("poisson", self.poisson, "in (0, 0.5) for the column model (model = 'layer' takes 0.5)")
        return self


def liner_of(section: LinerSection) -> Liner:
    """The :class:`Liner` of a ``liner`` table (fields beside a preset replace it)."""
    from shaftline.film.liner import LINER_PRESETS

    base = LINER_PRESETS[section.preset] if section.preset is not None else (None, None, None)
    values = [
        given if given is not None else preset
        for given, preset in zip((section.thickness, section.modulus, section.poisson), base, strict=True)
    ]
    return Liner(thickness=values[0], modulus=values[1], poisson=values[2], model=section.model)  # type: ignore[arg-type]


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


class StribeckSection(Section):
    """Speeds of ``shaftline bearing stribeck``: geometric steps from lowest to highest."""

    lowest: Annotated[float, Quantity("speed", gt=0), SHAFT_SPEED] | None = None
    """Lowest speed (default a tenth of the case's)."""
    highest: Annotated[float, Quantity("speed", gt=0), SHAFT_SPEED] | None = None
    """Highest speed (default ten times the case's)."""
    points: Annotated[int, Field(ge=2, le=500)] = 30
    """Number of speeds."""


def stribeck_speeds(section: StribeckSection | None, speed: float) -> tuple[float, ...]:
    """The speeds (rad/s) of a ``stribeck`` table for a case running at ``speed``."""
    table = section or StribeckSection()
    lowest = table.lowest if table.lowest is not None else 0.1 * speed
    highest = table.highest if table.highest is not None else 10.0 * speed
    if highest <= lowest:
        raise InputError("stribeck.highest", highest, "rad/s", f"above the lowest speed ({lowest:.4g} rad/s)")
    return tuple(float(v) for v in np.geomspace(lowest, highest, table.points))


class VariantSection(Section):
    """A further bore or tilt solved beside the base case."""

    name: str
    """Label of the variant."""
    bore: list[BoreSegmentSection] | None = None
    """Slope-bored segments replacing the base case's bore."""
    misalignment_ratio_vertical: Annotated[Number, CLEARANCE_SHARE] | None = None
    """Vertical tilt as a share of 2c/L, replacing the base case's."""
    tilt_vertical: Annotated[Angle, SLOPE] | None = None
    """Vertical tilt replacing the base case's."""

    @model_validator(mode="after")
    def _one_tilt(self) -> VariantSection:
        if self.tilt_vertical is not None and self.misalignment_ratio_vertical is not None:
            raise field_error(
                "tilt_vertical", self.tilt_vertical, "either tilt_vertical or misalignment_ratio_vertical"
            )
        return self


_CLEARANCE = (
    "seed 004: c = 0.45 mm, seed 001: 0.5 mm; from about 10 um on a small journal to several mm in worn "
    "water-lubricated bearings (engineering judgement); the clearance ratio c/R below is the sharper check"
)
_ROUGHNESS = (
    "machined journals and bores: Ra 0.1 um (lapped) to 6.3 um (rough turned), Rq about 1.25 Ra (ISO 4287 "
    "for a Gaussian profile); 0.05 to 50 um keeps a value in um written as m out"
)
_CLEARANCE_RATIO = (
    "oil-lubricated white metal typically 0.5e-3 to 2e-3 (seed 004: 1.7e-3); water-lubricated polymer and rubber "
    "bearings more, seed 001: 3.1e-3, small-craft rubber bearings 1e-3 to 2e-3 new and about 5e-3 at the wear "
    "limit (ABYC practice); 1e-4 and 2e-2 are four times beyond, a clearance in mm written as m or um, or in "
    "inches written as mm, is outside"
)


class BearingSection(Section):
    """A stern-tube journal bearing film at equilibrium under its load."""

    plausible_ratios = (
        PlausibleRatio(
            "radial_clearance",
            "c/R",
            lambda s, c: 2.0 * c / s.diameter,
            1e-4,
            2e-2,
            _CLEARANCE_RATIO,
            "radial clearance / journal radius",
            uses=("diameter",),
        ),
        PlausibleRatio(
            "diametral_clearance",
            "c/R",
            lambda s, clearance: clearance / s.diameter,
            1e-4,
            2e-2,
            _CLEARANCE_RATIO,
            "diametral clearance / journal diameter",
            uses=("diameter",),
        ),
        PlausibleRatio(
            "length",
            "L/D",
            lambda s, length: length / s.diameter,
            0.2,
            6.0,
            "class rules ask L >= 2 D of oil-lubricated white-metal (down to about 1.5 D) and >= 4 D of "
            "water-lubricated aft stern-tube bearings (e.g. LR Rules for Ships Pt 5 Ch 6; seed 004 Ch. 2: L/D about 2, "
            "seed 001: 3.7; Nielsen 1978 found 1-1.5 optimal); intermediate bearings down to about 0.5 "
            "(engineering judgement)",
            "bearing length / journal diameter",
            uses=("diameter",),
        ),
        PlausibleRatio(
            "operation.load",
            "W/(L D)",
            lambda s, load: math.hypot(load, s.operation.load_horizontal) / (s.length * s.diameter),
            1e3,
            5e6,
            "class limits of the nominal pressure: 0.8 MPa white metal (some societies accept 1.0-1.2 MPa), 0.6 MPa "
            "synthetic (seed 004 Ch. 2; rules.toml); seed 004: 0.57 MPa. 5 MPa is six times the limit, 1 kPa a "
            "nearly unloaded forward bearing (engineering judgement); a load in N written as kN, or kN as N, is "
            "outside",
            "load magnitude / projected area",
            uses=("length", "diameter"),
            unit="Pa",
        ),
    )

    length: Annotated[
        PositiveLength,
        Plausible(
            0.02,
            4.0,
            f"{_SEEDS}; the largest aft stern-tube bearings are about 2-2.5 m (shafts up to about 1.2 m, L/D about 2); "
            "20 mm covers small-craft bearings (engineering judgement)",
        ),
    ]
    """Bearing length L."""
    diameter: Annotated[
        PositiveLength,
        Plausible(
            0.02,
            2.0,
            f"{_SEEDS}; propeller shafts of the largest ships are about 1-1.2 m, of small craft 25 mm "
            "(engineering judgement); mm written as a bare number (m) is far above",
        ),
    ]
    """Journal diameter D."""
    radial_clearance: Annotated[PositiveLength, Plausible(1e-5, 0.02, _CLEARANCE)] | None = None
    """Radial clearance c; or diametral_clearance."""
    diametral_clearance: Annotated[PositiveLength, Plausible(2e-5, 0.04, _CLEARANCE)] | None = None
    """Diametral clearance 2c."""
    rotation: Annotated[Literal["clockwise", "anticlockwise"], BeforeValidator(_rotation_alias)] = "clockwise"
    """Sense of rotation seen from aft."""
    surface_roughness: Annotated[PositiveLength, Plausible(5e-8, 5e-5, _ROUGHNESS)] = default_of(
        BearingCase, "surface_roughness"
    )
    """Composite roughness sqrt(Rq_journal^2 + Rq_bore^2): a film below three times it is mixed lubrication,
    outside the smooth-film model (reported as not acceptable)."""
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
    surface: SurfaceSection | None = None
    """Rough journal and bore (mixed lubrication); none: smooth surfaces."""
    liner: LinerSection | None = None
    """Elastic liner on the bore (column or bonded-layer model); none: a rigid bore."""
    thermal: ThermalSection | None = None
    """Film temperature from the heat balance; none: the lubricant table's temperature."""
    stribeck: StribeckSection | None = None
    """Speeds of the Stribeck curve (``shaftline bearing stribeck``)."""
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
        if self.surface is not None and "surface_roughness" in self.model_fields_set:
            raise field_error(
                "surface_roughness",
                self.surface_roughness,
                "either surface_roughness or a [bearing.surface] table (which gives the roughness)",
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


#: ``turbulence = "on"`` with a largest local Reynolds number below this share of the transition
#: is noted (not refused): the coefficients are fits to turbulent films, and a film this far
#: below transition is laminar (issue 15, "Bad input").
FAR_BELOW_TRANSITION = 0.1


def turbulence_note(
    geometry: BearingGeometry, operating: OperatingPoint, speed: float, field: str = "bearing.solver"
) -> str | None:
    """A note when turbulence is asked for with a film whose largest local Reynolds number
    (``2 Re_c``, a film of at most 2c) is far below the Taylor-vortex onset; None otherwise.
    ``field``: the case-file path of the solver table, for the note's text."""
    from shaftline.film.turbulence import clearance_reynolds, pressure_flow_coefficients, transition_reynolds

    radius, clearance = geometry.radius, geometry.radial_clearance
    largest = 2.0 * clearance_reynolds(operating.density, speed, radius, clearance, operating.viscosity)
    transition = transition_reynolds(radius, clearance)
    if largest >= FAR_BELOW_TRANSITION * transition:
        return None
    kx, _ = pressure_flow_coefficients(largest)
    return (
        f"{field}.turbulence = on with a film whose largest local Reynolds number is {largest:.3g}, far below the "
        f"transition at {transition:.3g} (41.3 sqrt(R/c)): the film is laminar; the turbulence coefficients change "
        f"its pressure flow by at most {100 * (1 - 12 / float(kx)):.2g} % (set turbulence = off or auto)."
    )


#: The layer model's end rows are resolved only with an axial step of at most this share of the
#: liner thickness (docs/validation.md "Elastic layer": seed 001's rig at 135 rpm, end film
#: 0.58, 0.96, 1.50, 1.94 um at dz = 1.5, 0.75, 0.375, 0.19 t; the interior within 1 %).
LAYER_RESOLUTION = 0.5


def layer_note(geometry: BearingGeometry, axial_nodes: int, table: str = "") -> str | None:
    """A note when the layer model's liner is thin against the axial step (its deformation
    near the bearing ends is not resolved); None otherwise. ``table``: the case-file path of the
    film's table with its dot (``"alignment.bearings[0].film."``; empty for ``[bearing]``), for
    the fields the note names."""
    liner = geometry.liner
    if liner is None or liner.model != "layer":
        return None
    dz = geometry.length / (axial_nodes - 1)
    if dz <= LAYER_RESOLUTION * liner.thickness:
        return None
    needed = math.ceil(geometry.length / (LAYER_RESOLUTION * liner.thickness)) + 1
    return (
        f"{table}liner.model = layer with an axial step of {dz * 1e3:.3g} mm, more than half the liner's "
        f"{liner.thickness * 1e3:.3g} mm: the layer's deformation near the bearing ends is not resolved and the "
        f"film there comes out too thin (set {table}solver.axial_nodes to {needed} or more; docs/validation.md, "
        '"Elastic layer").'
    )


def turbulence_notes(
    solver: SolverSection,
    options: SolverOptions,
    geometry: BearingGeometry,
    operating: OperatingPoint,
    field: str = "bearing.solver",
) -> list[str]:
    """The notes (not errors) on a film's turbulence settings, the same for ``[bearing.solver]``
    and ``[alignment.bearings.film.solver]``: turbulence on for a film far below transition
    (:func:`turbulence_note`), and a ``turbulence_model`` named with turbulence left off.
    ``field``: the case-file path of the solver table, for the notes' text."""
    notes = []
    if options.turbulence == "on":
        note = turbulence_note(geometry, operating, operating.speed, field)
        if note is not None:
            notes.append(note)
    if options.turbulence == "off" and "turbulence_model" in solver.model_fields_set:
        # a model named with turbulence left at its default: the user likely meant it to apply
        notes.append(
            f"{field}.turbulence_model = {options.turbulence_model} has no effect with turbulence = off (the "
            "default): the film is laminar (set turbulence = on or auto)."
        )
    return notes


def solver_options(s: SolverSection) -> SolverOptions:
    """The film's :class:`SolverOptions` of a ``solver`` table."""
    return SolverOptions(
        axial_nodes=s.axial_nodes,
        circumferential_nodes=s.circumferential_nodes,
        cavitation=s.cavitation,
        film_start=s.film_start,
        cavitated_shear=s.cavitated_shear,
        min_film_floor=s.min_film_floor,
        tolerance=s.tolerance,
        max_iterations=s.max_iterations,
        memory_limit=s.memory_limit,
        turbulence=s.turbulence,
        turbulence_model=s.turbulence_model,
    )


def build_study(section: BearingSection, context: BuildContext) -> BearingStudy:
    """The base case and its variants in SI domain objects (raises :class:`InputError` with
    the field's path inside ``[bearing]``)."""
    from shaftline.film.study import BearingCase, BearingStudy

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

    surface = None if section.surface is None else checked_surface(section.surface, clearance)

    liner = None
    if section.liner is not None:
        with located("liner"):
            liner = liner_of(section.liner)

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
                surface=surface,
                liner=liner,
            )

    base_geometry = geometry(_bore(section.bore, length, clearance), "bore")
    lubricant, viscosity, density = lubricant_properties(section.lubricant)
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
    thermal = None
    if section.thermal is not None:
        from shaftline.film.thermal import TEMPERATURE_RANGES, ThermalOptions

        if lubricant.model == "constant":
            raise InputError(
                "lubricant.viscosity",
                section.lubricant.viscosity,
                "Pa s",
                "a lubricant whose viscosity follows temperature (a preset or a two-point oil) with [bearing.thermal]",
            )
        low, high = TEMPERATURE_RANGES[lubricant.model]
        inlet = section.thermal.inlet_temperature
        if not low <= inlet < high:
            raise InputError(
                "thermal.inlet_temperature", inlet, "degC", f"{low:g} to {high:g} degC, the range of {lubricant.name}"
            )
        with located("thermal"):
            thermal = ThermalOptions(inlet, section.thermal.heat_to_lubricant)
    with located("solver"):
        options = solver_options(section.solver)
    with located("", {"operating": "operation", "options": "solver"}):
        BearingProblem(base_geometry, operating, options)
    layer = layer_note(base_geometry, options.axial_nodes)
    if layer is not None:
        context.warnings.append(layer)
    context.warnings.extend(turbulence_notes(section.solver, options, base_geometry, operating, "bearing.solver"))
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
            temperature=section.lubricant.temperature,
            surface_roughness=section.surface_roughness if surface is None else surface.sigma,
            error_fields=fields,
            thermal=thermal,
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
    return BearingStudy(tuple(cases), stribeck_speeds(section.stribeck, op.speed))
