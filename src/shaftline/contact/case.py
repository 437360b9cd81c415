"""The ``[contact]`` table of a case file: one lubricated non-conformal contact (issue 14,
part A).

Layout::

    [contact]           geometry, load, radii, surface speeds, temperature, lubricant, methods
    [contact.body_1]    elastic constants and roughness of each body
    [contact.body_2]
    [contact.sweep]     ranges of the speed and load sweeps (optional)
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING, Annotated, Literal

from pydantic import Field, StrictBool, model_validator

from shaftline.cases.types import (
    Plausible,
    PositiveLength,
    PositivePressure,
    Quantity,
    Section,
    field_error,
)
from shaftline.errors import InputError
from shaftline.registry import BuildContext

if TYPE_CHECKING:
    from shaftline.contact.study import ContactStudy

_EXAMPLE = "examples/contact_ehl.toml"
_SEED = "seed 002"
CURVATURE_RADIUS = Plausible(
    1e-4,
    10.0,
    "radii of curvature of gear flanks, rollers, cams and balls: from about 1 mm (small rolling elements) to "
    f"some 100 mm ({_EXAMPLE}: 23.9 mm); 10 m allows a large rail wheel (engineering judgement); mm written as m is "
    "above",
)
SURFACE_SPEED = Plausible(
    0.0,
    200.0,
    "surface speeds of gears and bearings (a flank rolls over the contact at omega x its radius of curvature: "
    f"{_SEED}'s gears at 18000 rpm, 45 m/s at the pitch point, 68 m/s at a tip; pitch-line speeds of "
    "aerospace gears reach about 150 m/s) (engineering judgement); mm/s written as m/s is above",
)
ROUGHNESS = Plausible(
    1e-9,
    2e-5,
    f"finishes from superfinished (Ra 0.01 um) to rough machined (Ra about 6 um) ({_SEED} Table 1: Ra 0.4 and "
    "0.1 um); um written as m is far above (engineering judgement)",
)
MODULUS = Plausible(
    1e6,
    1e12,
    "from elastomers (MPa) to ceramics and carbides (300-700 GPa); GPa written as a bare number (Pa) is far below",
)


class BodySection(Section):
    """One of the two bodies in contact."""

    radius: Annotated[PositiveLength, CURVATURE_RADIUS] | None = None
    """Radius of curvature in the rolling direction (convex; omit for a plane)."""
    radius_y: Annotated[PositiveLength, CURVATURE_RADIUS] | None = None
    """Radius of curvature across the rolling direction (point contacts; omit for straight)."""
    speed: Annotated[float, Quantity("velocity", ge=0), SURFACE_SPEED]
    """Surface speed in the rolling direction."""
    youngs_modulus: Annotated[PositivePressure, MODULUS] = 206e9
    """Young's modulus (default: steel)."""
    poisson_ratio: Annotated[float, Quantity("dimensionless", ge=0, lt=0.5)] = 0.3
    """Poisson's ratio."""
    roughness_ra: Annotated[PositiveLength, ROUGHNESS] | None = None
    """Arithmetic mean roughness Ra (Rq = 1.25 Ra, Gaussian heights); or roughness_rq."""
    roughness_rq: Annotated[PositiveLength, ROUGHNESS] | None = None
    """Root-mean-square roughness Rq."""

    @model_validator(mode="after")
    def _one_roughness(self) -> BodySection:
        if (self.roughness_ra is None) == (self.roughness_rq is None):
            raise field_error(
                "roughness_ra",
                "missing" if self.roughness_ra is None else self.roughness_ra,
                "one of roughness_ra and roughness_rq",
            )
        return self

    @property
    def rq(self) -> float:
        if self.roughness_rq is not None:
            return self.roughness_rq
        assert self.roughness_ra is not None  # checked by the validator
        return math.sqrt(math.pi / 2.0) * self.roughness_ra


class SweepSection(Section):
    """Ranges of the sweeps around the operating point (factors on it)."""

    speed_factors: Annotated[
        list[Annotated[float, Quantity("dimensionless", gt=0)]], Field(min_length=2, max_length=2)
    ] = [
        0.01,
        3.0,
    ]
    """Smallest and largest factor on both surface speeds (slide-to-roll ratio kept): the f-Lambda curve."""
    load_factors: Annotated[
        list[Annotated[float, Quantity("dimensionless", gt=0)]], Field(min_length=2, max_length=2)
    ] = [
        0.1,
        2.0,
    ]
    """Smallest and largest factor on the load: pressure and film against load."""
    points: Annotated[int, Field(ge=5, le=2000)] = 60
    """Points of each sweep."""


class ContactSection(Section):
    """A lubricated non-conformal contact: Hertz pressure, EHL film, Lambda and seed 002's friction."""

    geometry: Literal["line", "point"] = "line"
    """Line contact (parallel cylinders, load per unit length) or point contact (elliptical, load)."""
    load_per_length: (
        Annotated[
            float,
            Quantity("force_per_length", gt=0),
            Plausible(
                1e3, 1e7, f"gear and roller loads of 1 N/mm to 10 kN/mm ({_EXAMPLE}: 300 N/mm); engineering judgement"
            ),
        ]
        | None
    ) = None
    """Normal load per unit length (line contacts)."""
    load: (
        Annotated[
            float, Quantity("force", gt=0), Plausible(1e-2, 1e7, "from instrument bearings to large rolling elements")
        ]
        | None
    ) = None
    """Normal load (point contacts)."""
    temperature: Annotated[float, Quantity("temperature", ge=-40, le=250)]
    """Inlet (bulk) oil temperature."""
    lubricant: str
    """Lubricant: MIL-PRF-23699, ISO VG 100 or FVA 3 (docs/theory.md Sect. 15.3: where their data come from)."""
    film_method: Literal["default", "dowson_toyoda", "moes", "hamrock_dowson", "hamrock_dowson_soft"] = "default"
    """Film formula: dowson_toyoda (default) or moes for line contacts, hamrock_dowson (default) or
    hamrock_dowson_soft (isoviscous-elastic) for point contacts."""
    thermal_method: Literal["gupta", "murch_wilson", "none"] = "gupta"
    """Inlet shear-heating reduction of the film."""
    pressure_viscosity_model: Literal["roelands", "barus"] = "roelands"
    """Viscosity at the mean Hertz pressure for the Bair-Winer stress."""
    ellipticity_method: Literal["exact", "hamrock_brewe", "brewe_hamrock"] = "exact"
    """Ellipticity and elliptic integrals of point contacts."""
    boundary_friction: Annotated[
        float,
        Quantity("dimensionless", gt=0, lt=1),
        Plausible(
            0.02, 0.3, f"{_SEED}: usually constant, 0.08-0.1 typical; 0.02-0.3 covers additive films to dry steel"
        ),
    ] = 0.1
    """Boundary friction coefficient f_b (seed 002 Eq. 1)."""
    extrapolate: StrictBool = False
    """Evaluate correlations outside their validity ranges with a warning instead of an error."""
    body_1: BodySection
    """Body 1."""
    body_2: BodySection
    """Body 2."""
    sweep: SweepSection = SweepSection()
    """Sweep ranges."""

    @model_validator(mode="after")
    def _geometry(self) -> ContactSection:
        line = self.geometry == "line"
        if line and self.load_per_length is None:
            raise field_error("load_per_length", "missing", "a load per unit length for a line contact")
        if not line and self.load is None:
            raise field_error("load", "missing", "a load for a point contact")
        if line and self.load is not None:
            raise field_error("load", self.load, "load_per_length for a line contact", "N")
        if not line and self.load_per_length is not None:
            raise field_error("load_per_length", self.load_per_length, "load for a point contact", "N/m")
        for name, body in (("body_1", self.body_1), ("body_2", self.body_2)):
            if line and body.radius_y is not None:
                raise field_error(
                    f"{name}.radius_y", body.radius_y, "none for a line contact (use geometry = 'point')", "m"
                )
        if self.body_1.radius is None and self.body_2.radius is None:
            raise field_error("body_1.radius", "missing", "a radius of curvature on one body at least")
        if self.body_1.speed + self.body_2.speed <= 0.0:
            raise field_error(
                "body_1.speed", self.body_1.speed, "a mean surface speed > 0 (a film needs entrainment)", "m/s"
            )
        point_methods = ("hamrock_dowson", "hamrock_dowson_soft")
        if self.film_method != "default" and (self.film_method in point_methods) == line:
            allowed = "default, dowson_toyoda or moes" if line else "default, hamrock_dowson or hamrock_dowson_soft"
            raise field_error("film_method", self.film_method, f"{allowed} for a {self.geometry} contact")
        return self


def _reduced(r1: float | None, r2: float | None) -> float:
    curvature = (0.0 if r1 is None else 1.0 / r1) + (0.0 if r2 is None else 1.0 / r2)
    return math.inf if curvature == 0.0 else 1.0 / curvature


def build_study(section: ContactSection, context: BuildContext) -> ContactStudy:
    """The contact study in SI domain objects."""
    import numpy as np

    from shaftline.contact.lubricated import ContactModel, Surfaces
    from shaftline.contact.rheology import contact_lubricant
    from shaftline.contact.study import ContactStudy

    b1, b2 = section.body_1, section.body_2
    lubricant = contact_lubricant(section.lubricant)  # its error names "lubricant"
    surfaces = Surfaces(b1.youngs_modulus, b1.poisson_ratio, b2.youngs_modulus, b2.poisson_ratio, b1.rq, b2.rq)
    model = ContactModel(
        lubricant=lubricant,
        geometry=section.geometry,
        film_method=section.film_method,
        thermal_method=section.thermal_method,
        pressure_viscosity_model=section.pressure_viscosity_model,
        boundary_friction=section.boundary_friction,
        ellipticity_method=section.ellipticity_method,
        extrapolate=section.extrapolate,
    )
    radius_x = _reduced(b1.radius, b2.radius)
    radius_y = math.inf
    if section.geometry == "point":
        radius_y = _reduced(b1.radius_y, b2.radius_y)
        if radius_y < radius_x:
            raise InputError(
                "body_1.radius_y",
                b1.radius_y,
                "m",
                f"a reduced transverse radius >= the rolling one ({radius_x:.6g} m): x is the direction of the "
                "smaller radius",
            )
        if math.isinf(radius_y):
            raise InputError(
                "body_1.radius_y", "missing", "", "a transverse radius on one body at least for a point contact"
            )
    load = section.load_per_length if section.geometry == "line" else section.load
    assert load is not None  # checked by the schema
    sw = section.sweep
    for name, pair in (("sweep.speed_factors", sw.speed_factors), ("sweep.load_factors", sw.load_factors)):
        if not pair[0] < pair[1]:
            raise InputError(name, list(pair), "", "[smallest, largest] with smallest < largest")
    return ContactStudy(
        model=model,
        surfaces=surfaces,
        load=load,
        speed_1=b1.speed,
        speed_2=b2.speed,
        temperature=section.temperature,
        radius_x=radius_x,
        radius_y=radius_y,
        speed_factors=np.geomspace(sw.speed_factors[0], sw.speed_factors[1], sw.points),
        load_factors=np.linspace(sw.load_factors[0], sw.load_factors[1], sw.points),
    )
