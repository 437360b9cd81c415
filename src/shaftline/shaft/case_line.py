"""The line's geometry in ``[alignment]``: ``[alignment.shaft]`` with its segments and
``[alignment.propeller]``."""

from __future__ import annotations

from typing import Annotated, Literal

from pydantic import Field, StrictBool

from shaftline.cases.types import (
    Fraction,
    NonNegativeLength,
    Plausible,
    PositiveAcceleration,
    PositiveDensity,
    PositiveFraction,
    PositiveLength,
    PositiveMass,
    PositivePressure,
    Section,
    default_of,
)
from shaftline.shaft.case_ranges import BORE, EXAMPLE_CASE, SHAFT_DENSITY, SHAFT_DIAMETER, YOUNGS_MODULUS, X
from shaftline.shaft.model import Propeller, ShaftLine, ShaftSegment

BeamTheory = Literal["timoshenko", "euler_bernoulli"]


class SegmentSection(Section):
    """A length of shaft, straight or conical, solid or hollow; flanges as short thick segments."""

    length: Annotated[
        PositiveLength,
        Plausible(
            0.005,
            60.0,
            "flanges and steps from a few mm, intermediate and propeller shafts up to about 15-25 m in one piece "
            f"(engineering judgement; {EXAMPLE_CASE}: 0.14-12 m); mm written as m is above 60 m",
        ),
    ]
    """Segment length."""
    outer_diameter: Annotated[PositiveLength, SHAFT_DIAMETER]
    """Outer diameter at the aft end."""
    inner_diameter: Annotated[NonNegativeLength, BORE] = default_of(ShaftSegment, "inner_diameter")
    """Bore at the aft end (0: solid)."""
    outer_diameter_end: Annotated[PositiveLength, SHAFT_DIAMETER] | None = None
    """Outer diameter at the forward end of a conical segment."""
    inner_diameter_end: Annotated[NonNegativeLength, BORE] | None = None
    """Bore at the forward end of a conical segment."""
    youngs_modulus: Annotated[PositivePressure, YOUNGS_MODULUS] | None = None
    """Young's modulus (default: the shaft's)."""
    shear_modulus: (
        Annotated[
            PositivePressure,
            Plausible(4e8, 4e11, "steel about 80 GPa; as Young's modulus above, divided by 2(1 + nu)"),
        ]
        | None
    ) = None
    """Shear modulus (default: from Young's modulus and Poisson's ratio)."""
    poisson_ratio: Annotated[float, Field(gt=-1, lt=0.5)] | None = None
    """Poisson's ratio (default: the shaft's)."""
    density: Annotated[PositiveDensity, SHAFT_DENSITY] | None = None
    """Density (default: the shaft's)."""
    shear_area_factor: PositiveFraction | None = None
    """Shear area / area of the Timoshenko element (default: Cowper's value for a hollow circle)."""
    name: str = ""
    """Label (tail shaft, flange, ...)."""


class ShaftSection(Section):
    """The beam model of the shaft line and its default material."""

    segments: Annotated[list[SegmentSection], Field(min_length=1)]
    """Segments aft to forward."""
    beam_theory: BeamTheory = default_of(ShaftLine, "beam_theory")
    """Beam elements."""
    element_length: Annotated[
        PositiveLength,
        Plausible(0.001, 10.0, "a mesh of mm to m elements (default 0.25 m); mm written as m is above 10 m"),
    ] = default_of(ShaftLine, "element_length")
    """Largest element length of the mesh."""
    self_weight: StrictBool = default_of(ShaftLine, "self_weight")
    """Include the shaft's own weight."""
    gravity: Annotated[
        PositiveAcceleration,
        Plausible(5.0, 20.0, "9.81 m/s^2 (standard gravity 9.80665); up to twice that for a ship's motion"),
    ] = default_of(ShaftLine, "gravity")
    """Acceleration of gravity."""
    youngs_modulus: Annotated[PositivePressure, YOUNGS_MODULUS] = default_of(ShaftSegment, "youngs_modulus")
    """Young's modulus of segments that give none."""
    poisson_ratio: Annotated[float, Field(gt=-1, lt=0.5)] = default_of(ShaftSegment, "poisson_ratio")
    """Poisson's ratio of segments that give none."""
    density: Annotated[PositiveDensity, SHAFT_DENSITY] = default_of(ShaftSegment, "density")
    """Density of segments that give none."""


class PropellerSection(Section):
    """The propeller: its weight less buoyancy acts at its centre of gravity."""

    x: X
    """Centre of gravity (x < 0 beyond the aft end of the shaft)."""
    mass: Annotated[
        PositiveMass,
        Plausible(
            5.0,
            3e5,
            "from a few kg (small craft) to about 130 t (the largest container-ship propellers; the example: 62 t) "
            "(engineering judgement); the cross-field check below catches a mass in t written in kg",
        ),
    ]
    """Mass in air."""
    material_density: Annotated[
        PositiveDensity,
        Plausible(
            1000.0,
            12000.0,
            "nickel-aluminium and manganese bronzes about 7600 kg/m^3, stainless steel 7800, composite propellers "
            "about 1500-2000 (engineering judgement)",
        ),
    ] = default_of(Propeller, "material_density")
    """Density of the propeller material (buoyancy)."""
    water_density: Annotated[
        PositiveDensity,
        Plausible(950.0, 1100.0, "fresh water 1000 kg/m^3, sea water about 1025 (default)"),
    ] = default_of(Propeller, "water_density")
    """Density of the water."""
    immersed_fraction: Fraction = default_of(Propeller, "immersed_fraction")
    """Share of the propeller under water (conditions may change it)."""


def shaft_diameter_at(shaft: ShaftSection, x: float) -> float:
    """Outer diameter of the shaft model at station ``x`` (clamped to the model)."""
    start = 0.0
    for segment in shaft.segments:
        if x <= start + segment.length or segment is shaft.segments[-1]:
            share = min(max((x - start) / segment.length, 0.0), 1.0)
            end = segment.outer_diameter_end if segment.outer_diameter_end is not None else segment.outer_diameter
            return segment.outer_diameter + share * (end - segment.outer_diameter)
        start += segment.length
    raise AssertionError("a shaft has at least one segment")  # checked by the schema
