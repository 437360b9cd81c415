"""The ``[alignment]`` table of a case file: a shaft line on its bearings, its load
conditions, class rules and the alignment procedures asked for.

Layout (x runs from the aft end of the shaft model forward; offsets + up)::

    [alignment]                       rules_file
    [alignment.shaft]                 model and default material
    [[alignment.shaft.segments]]      aft to forward
    [alignment.propeller]
    [[alignment.bearings]]
    [[alignment.loads]], [[alignment.masses]], [[alignment.distributed_loads]]
    [[alignment.conditions]]          load cases solved together
    [[alignment.rules]]               rules added to the bundled class rules
    [alignment.optimise], [alignment.sag_gap], [alignment.jack_up], [alignment.measured_reactions]
    [alignment.film]                  film of the bearings marked ``film = true``
    [alignment.bearings.film]         a bearing's own film (elastohydrodynamic alignment)
    [alignment.coupling]              tolerances of the coupled solution
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING, Annotated, Any, Literal

from pydantic import BeforeValidator, Field, StrictBool, model_validator

from shaftline.cases.types import (
    SHAFT_SPEED,
    Angle,
    Force,
    ForcePerLength,
    Fraction,
    Length,
    Moment,
    NonNegativeLength,
    Number,
    Plausible,
    PlausibleRatio,
    PositiveAcceleration,
    PositiveDensity,
    PositiveFraction,
    PositiveLength,
    PositiveMass,
    PositivePressure,
    PositiveStiffness,
    Pressure,
    Quantity,
    Section,
    default_of,
    field_error,
)
from shaftline.errors import located
from shaftline.film.case import (
    _CLEARANCE,
    EDGE_PRESSURE,
    BoreSegmentSection,
    LinerSection,
    LubricantSection,
    SolverSection,
    SurfaceSection,
    _rotation_alias,
)
from shaftline.film.geometry import BearingGeometry, BoreAnchor
from shaftline.film.problem import OperatingPoint
from shaftline.registry import BuildContext

if TYPE_CHECKING:
    from shaftline.lubricants import Lubricant
    from shaftline.shaft.study import AlignmentStudy
from shaftline.shaft.coupled import CouplingOptions, FilmSupport
from shaftline.shaft.lift_off import FilmLimit
from shaftline.shaft.model import (
    Bearing,
    Condition,
    DistributedLoad,
    PointLoad,
    PointMass,
    Propeller,
    ShaftLine,
    ShaftSegment,
)

BeamTheory = Literal["timoshenko", "euler_bernoulli"]
SupportModel = Literal["point", "spring", "multi_point"]
SupportPosition = Literal["centre", "aft_third"]
Material = Literal["white_metal", "synthetic", "rubber", "bronze", "composite", "lignum_vitae", "engine", "roller"]
RuleQuantity = Literal["reaction", "reaction_share", "mean_pressure", "relative_slope"]
Comparison = Literal[">", ">=", "<", "<="]
Objective = Literal["aft_slope", "load_spread"]


# Plausible ranges of a ship's shaft line (the README's table of plausible ranges is made
# from them): generous, to catch a unit slip (a bare number is SI: 2200 meant in mm is 2.2 km),
# not an unusual line, which a case lists in [case] unusual.
_EXAMPLE = "examples/single_screw_alignment.toml"
X = Annotated[
    Length,
    Plausible(
        -30.0,
        300.0,
        "stations from the aft end of the model: the propeller overhangs a few m aft, the longest lines (engine "
        f"room amidships) are about 100 m; {_EXAMPLE}: 0.55-28.8 m (engineering judgement); mm written as m is "
        "beyond 300 m",
    ),
]
SHAFT_DIAMETER = Plausible(
    0.02,
    3.0,
    "propeller shafts from about 25 mm (small craft) to about 1.2 m (the largest ships), flanges up to about "
    f"2 m; {_EXAMPLE}: 0.62-1.25 m (engineering judgement)",
)
BORE = Plausible(0.0, 2.5, "a hollow shaft's bore is smaller than its outer diameter (the larger range above)")
YOUNGS_MODULUS = Plausible(
    1e9,
    1e12,
    "shaft steels about 206 GPa, composite shafts 20-150 GPa (engineering judgement); GPa or MPa written as a "
    "bare number (Pa) is far below",
)
SHAFT_DENSITY = Plausible(
    1000.0,
    30000.0,
    "steel 7850 kg/m^3, composite shafts about 1600; an equivalent crankshaft may take a modified density "
    "(engineering judgement); g/cm^3 as a bare number is far below",
)
OFFSET = Annotated[
    Length,
    Plausible(
        -0.05,
        0.05,
        f"bearing offsets from the reference line are a few mm ({_EXAMPLE}: up to 1.6 mm plus 0.9 mm of hull and "
        "thermal change); 50 mm is ten times the largest (engineering judgement), an offset in mm written as a "
        "bare number (m) is above it",
    ),
]
LINE_FORCE = Plausible(
    -3e7,
    3e7,
    "forces on a shaft line are at most a few MN (the largest propellers weigh 1.3 MN); 30 MN is ten times "
    "that (engineering judgement)",
)
LINE_MOMENT = Plausible(
    -1e8,
    1e8,
    f"eccentric-thrust moments of the largest propellers are a few MN m ({_EXAMPLE}: 0.35 MN m); 100 MN m is "
    "ten times beyond (engineering judgement)",
)
_FILM_LIMIT = (
    "class values of the smallest film are some tens of µm (seed 004 quotes Bureau Veritas' 30 µm); 0.5 mm is "
    "beyond any stern-tube clearance, a limit in µm written as m is far above (engineering judgement)"
)
_ROUGHNESS = (
    "ground journals and bored liners are Ra 0.2-3.2 µm (seed 001: 0.8 µm sleeve, 1.6 µm liner); 20 µm is a "
    "rough casting, µm written as m is far above (engineering judgement)"
)
#: Density of shaft steel, kg/m^3: the scale of the propeller-mass check (not the model's density).
STEEL = 7850.0


def _shaft_diameter_at(section: AlignmentSection, x: float) -> float:
    """Outer diameter of the shaft model at station ``x`` (clamped to the model)."""
    start = 0.0
    for segment in section.shaft.segments:
        if x <= start + segment.length or segment is section.shaft.segments[-1]:
            share = min(max((x - start) / segment.length, 0.0), 1.0)
            end = segment.outer_diameter_end if segment.outer_diameter_end is not None else segment.outer_diameter
            return segment.outer_diameter + share * (end - segment.outer_diameter)
        start += segment.length
    raise AssertionError("a shaft has at least one segment")  # checked by the schema


class SegmentSection(Section):
    """A length of shaft, straight or conical, solid or hollow; flanges as short thick segments."""

    length: Annotated[
        PositiveLength,
        Plausible(
            0.005,
            60.0,
            "flanges and steps from a few mm, intermediate and propeller shafts up to about 15-25 m in one piece "
            f"(engineering judgement; {_EXAMPLE}: 0.14-12 m); mm written as m is above 60 m",
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


class SupportSection(Section):
    """A bearing of the line: its position, offsets and support model."""

    name: str
    """Name (conditions, rules and procedures refer to it)."""
    x: X
    """Centre of the bearing."""
    length: Annotated[
        PositiveLength,
        Plausible(
            0.02,
            4.0,
            "aft stern-tube bearings up to about 2-2.5 m (L/D about 2 on the largest shafts), engine and "
            f"intermediate bearings 0.2-0.6 m ({_EXAMPLE}: 0.45-1.5 m); 20 mm covers small craft "
            "(engineering judgement)",
        ),
    ]
    """Bearing length."""
    offset_y: OFFSET = default_of(Bearing, "offset_y")
    """Vertical offset of the bearing from the reference line (+ up)."""
    offset_z: OFFSET = default_of(Bearing, "offset_z")
    """Horizontal offset (+ starboard)."""
    vertical_clearance: (
        Annotated[
            PositiveLength,
            Plausible(
                2e-5,
                0.04,
                f"diametral clearances are about 1e-3 to 2e-3 of the diameter ({_EXAMPLE}: 0.6-1.2 mm; seed 004: "
                "0.9 mm), several mm in worn water-lubricated bearings (engineering judgement); mm written as m is "
                "far above",
            ),
        ]
        | None
    ) = None
    """Diametral clearance: the shaft touches the top of the bore after it (none: no top)."""
    material: Material = default_of(Bearing, "material")
    """Lining material (selects the class rules that apply); engine: limits of the engine maker."""
    support: SupportModel = default_of(Bearing, "support")
    """Rigid point, spring, or several points along a long bearing."""
    stiffness: (
        Annotated[
            PositiveStiffness,
            Plausible(
                1e6,
                1e12,
                f"bearing and foundation stiffnesses of ship lines are about 1e8 to 1e10 N/m ({_EXAMPLE}: 2.5e9) "
                "(engineering judgement); kN/mm written as a bare number (N/m) is far below",
            ),
        ]
        | None
    ) = None
    """Support stiffness of a spring support."""
    points: Annotated[int, Field(ge=1, le=50)] = default_of(Bearing, "points")
    """Support points of a multi-point support."""
    position: SupportPosition = default_of(Bearing, "position")
    """Where a point support acts: the centre or a third of the length from the aft end."""
    one_sided: StrictBool = default_of(Bearing, "one_sided")
    """The shaft can lift off (the bearing only pushes up)."""
    slope: Annotated[
        Angle,
        Plausible(
            -0.01,
            0.01,
            "slope-bored stern-tube bearings are inclined by about 0.1-1 mrad (class limit of the relative slope "
            "about 0.3 mrad, rules.toml); 10 mrad (0.57 deg) is ten times that, mrad or deg written as a bare "
            "number (rad) is far above (engineering judgement)",
        ),
    ] = default_of(Bearing, "slope")
    """The bearing's own slope (slope boring)."""
    film: FilmSection | StrictBool = False
    """true: supported by the film of [alignment.film]; a table: its own film; false: the support above."""


class FilmSection(Section):
    """The film of a hydrodynamic bearing: it supports the shaft instead of points, and the
    shaft's elastic line across the bearing is its journal (elastohydrodynamic alignment)."""

    speed: Annotated[float, Quantity("speed", gt=0), SHAFT_SPEED]
    """Shaft speed."""
    lubricant: LubricantSection
    """The lubricant (a viscosity, a preset at a temperature or a two-point oil)."""
    radial_clearance: Annotated[PositiveLength, Plausible(1e-5, 0.02, _CLEARANCE)] | None = None
    """Radial clearance c (default: half the bearing's vertical_clearance; if both are given they must agree)."""
    diametral_clearance: Annotated[PositiveLength, Plausible(2e-5, 0.04, _CLEARANCE)] | None = None
    """Diametral clearance 2c (or radial_clearance)."""
    rotation: Annotated[Literal["clockwise", "anticlockwise"], BeforeValidator(_rotation_alias)] = "clockwise"
    """Sense of rotation seen from aft."""
    bore: list[BoreSegmentSection] = []
    """Slope-bored segments of the bore, aft to forward, relative to the bearing's axis (none: straight)."""
    bore_anchor: BoreAnchor = default_of(BearingGeometry, "bore_anchor")
    """Where a slope-bored bore keeps the bearing's axis."""
    aft_pressure: Annotated[Pressure, EDGE_PRESSURE] = default_of(OperatingPoint, "aft_pressure")
    """Pressure at the aft edge above ambient."""
    fore_pressure: Annotated[Pressure, EDGE_PRESSURE] = default_of(OperatingPoint, "fore_pressure")
    """Pressure at the forward edge above ambient."""
    cavitation_pressure: Annotated[Pressure, EDGE_PRESSURE] = default_of(OperatingPoint, "cavitation_pressure")
    """Pressure at which the film ruptures, above ambient."""
    solver: SolverSection = SolverSection()
    """Film grid and models."""
    surface: SurfaceSection | None = None
    """Rough journal and bore (mixed lubrication), as [bearing.surface]: the same fields and checks."""
    liner: LinerSection | None = None
    """Elastic liner of the bore (column or layer model solved with the film), as [bearing.liner]: the same
    fields and checks; a water-lubricated stern tube is aligned with its soft liner."""
    elements: Annotated[int, Field(ge=2, le=50)] = 10
    """Shaft elements across the bearing (at least; seed 004 uses 10)."""


# SupportSection.film names FilmSection before it is defined: pydantic validates it lazily but
# keeps the field's annotation a ForwardRef until rebuilt, and the README tables, the ranges
# table and the "did you mean" of a misspelt key in [alignment.bearings.film] read it.
SupportSection.model_rebuild(force=True)


class MinimumSpeedSection(Section):
    """The lowest speed at which every film bearing keeps a film above a limit: the lift-off
    curve h_min against speed (needs film bearings)."""

    class_value: Annotated[NonNegativeLength, Plausible(0.0, 5e-4, _FILM_LIMIT)] = default_of(FilmLimit, "class_value")
    """Smallest film a class rule or the designer asks for (seed 004 quotes Bureau Veritas' 30 µm; 0: none)."""
    journal_roughness: Annotated[NonNegativeLength, Plausible(0.0, 2e-5, _ROUGHNESS)] = default_of(
        FilmLimit, "journal_roughness"
    )
    """Roughness of the journal (sleeve)."""
    bore_roughness: Annotated[NonNegativeLength, Plausible(0.0, 2e-5, _ROUGHNESS)] = default_of(
        FilmLimit, "bore_roughness"
    )
    """Roughness of the bore (liner)."""
    roughness_parameter: Literal["Rq", "Ra"] = default_of(FilmLimit, "roughness_parameter")
    """Rq (root mean square) or Ra (arithmetic mean; Rq = 1.25 Ra)."""
    film_parameter: Annotated[float, Quantity("dimensionless", gt=0, le=20)] = default_of(FilmLimit, "film_parameter")
    """The limit is at least this many composite roughnesses (3: full film)."""
    lowest: Annotated[float, Quantity("dimensionless", gt=0, lt=1)] = 0.05
    """Lowest speed tried, share of the operating speed."""
    points: Annotated[int, Field(ge=2, le=200)] = 8
    """Speeds of the sweep before the bisection."""
    tolerance: Annotated[float, Quantity("dimensionless", gt=1e-6, lt=0.5)] = 0.01
    """Relative width of the final speed bracket."""
    condition: str | None = None
    """Condition (default: the first)."""


class CouplingSection(Section):
    """Tolerances of the coupled solution of the shaft and its films."""

    force_tolerance: Annotated[float, Quantity("dimensionless", gt=0, lt=0.1)] = default_of(
        CouplingOptions, "force_tolerance"
    )
    """Film force mismatch left, as a share of each film's force."""
    film_tolerance: Annotated[float, Quantity("dimensionless", gt=0, lt=0.1)] = default_of(
        CouplingOptions, "film_tolerance"
    )
    """Journal-line mismatch between shaft and film left, as a share of the radial clearance."""
    max_iterations: Annotated[int, Field(ge=1, le=1000)] = default_of(CouplingOptions, "max_iterations")
    """Newton iterations allowed."""


class PointLoadSection(Section):
    """A point force and moment on the shaft."""

    x: X
    """Station."""
    force_y: Annotated[Force, LINE_FORCE] = default_of(PointLoad, "force_y")
    """Vertical force (+ up)."""
    force_z: Annotated[Force, LINE_FORCE] = default_of(PointLoad, "force_z")
    """Horizontal force (+ starboard)."""
    moment_vertical: Annotated[Moment, LINE_MOMENT] = default_of(PointLoad, "moment_vertical")
    """Moment in the vertical plane (+ turning +x towards +y)."""
    moment_horizontal: Annotated[Moment, LINE_MOMENT] = default_of(PointLoad, "moment_horizontal")
    """Moment in the horizontal plane (+ turning +x towards +z)."""
    name: str = ""
    """Label."""


class MassSection(Section):
    """A point mass (flywheel, coupling): its weight acts at x."""

    x: X
    """Station."""
    mass: Annotated[
        PositiveMass,
        Plausible(
            0.1,
            5e5,
            "couplings, flywheels, gears and rotors from kg to some tens of t (the example's flywheel: 14 t); "
            "500 t is beyond any shaft-line mass (engineering judgement)",
        ),
    ]
    """Mass."""
    name: str = ""
    """Label."""


DISTRIBUTED_LOAD = Plausible(
    -1e6,
    1e6,
    "the weight of a 1.2 m steel shaft is about 87 kN/m; 1 MN/m is ten times any line's (engineering judgement)",
)


class DistributedLoadSection(Section):
    """A load spread uniformly over a length of shaft."""

    x_start: X
    """Aft end of the loaded length."""
    x_end: X
    """Forward end."""
    load_y: Annotated[ForcePerLength, DISTRIBUTED_LOAD] = default_of(DistributedLoad, "load_y")
    """Vertical load per length (+ up)."""
    load_z: Annotated[ForcePerLength, DISTRIBUTED_LOAD] = default_of(DistributedLoad, "load_z")
    """Horizontal load per length (+ starboard)."""
    name: str = ""
    """Label."""


class ConditionSection(Section):
    """A load condition: offsets added to the bearings' and loads added to the line's."""

    name: str
    """Name (cold/hot, ballast/laden, static/running, ...)."""
    offsets_y: dict[str, OFFSET] = {}
    """Vertical offsets added per bearing name, e.g. { "intermediate" = "0.2 mm" }."""
    offsets_z: dict[str, OFFSET] = {}
    """Horizontal offsets added per bearing name."""
    propeller_immersion: Fraction | None = None
    """Immersed share of the propeller in this condition."""
    loads: list[PointLoadSection] = []
    """Point loads of this condition only."""


class RuleSection(Section):
    """A class rule (or yard limit) checked at every bearing it applies to, in every condition."""

    id: str
    """Identifier shown with the check."""
    quantity: RuleQuantity
    """The checked quantity (SI: N, -, Pa, rad)."""
    comparison: Comparison
    """value <comparison> limit passes."""
    limit: Number
    """Limit in SI units."""
    applies_to: str = "all"
    """all, aft_stern_tube or a bearing material."""
    society: str = ""
    """Source of the rule."""
    clause: str = ""
    """Clause of the source."""
    edition: str = ""
    """Edition of the source."""
    confidence: Literal["high", "medium", "low"] = "medium"
    """How sure the value is."""
    note: str = ""
    """Remark."""


class OptimiseSection(Section):
    """Offsets of the adjustable bearings that meet the rules in every condition."""

    objective: Objective = "aft_slope"
    """Minimise the aft bearing's relative slope, or the spread of the load ratios."""
    adjustable: list[str] | None = None
    """Bearings whose offsets may change (default: all but the aft- and forward-most)."""
    bound: Annotated[
        PositiveLength,
        Plausible(1e-5, 0.05, "offsets are a few mm (the offsets above); the default bound is 5 mm"),
    ] = 5e-3
    """Largest added offset either way."""


class TemporarySupportSection(Section):
    """A temporary support of the uncoupled shaft."""

    name: str
    """Label."""
    x: X
    """Station."""
    offset_y: OFFSET = 0.0
    """Vertical offset (+ up)."""


class SagGapSection(Section):
    """Sag and gap at an uncoupled flange."""

    flange_x: X
    """Station of the flange."""
    flange_diameter: Annotated[PositiveLength, SHAFT_DIAMETER] | None = None
    """Flange diameter (default: the larger shaft diameter at the flange)."""
    condition: str | None = None
    """Condition (default: the first)."""
    temporary_supports: list[TemporarySupportSection] = []
    """Supports added while the line is uncoupled."""


class JackUpSection(Section):
    """A jack-up test of one bearing, modelled and, with a measured curve, evaluated."""

    bearing: str
    """The bearing jacked."""
    jack_x: X
    """Station of the jack."""
    condition: str | None = None
    """Condition (default: the first)."""
    measured_curve: str | None = None
    """CSV with columns load (N) and lift (m) from the test; path relative to the case file."""


class MeasuredReactionsSection(Section):
    """Offsets that explain measured reactions (reverse engineering of the alignment)."""

    values: dict[str, Annotated[Force, LINE_FORCE]]
    """Measured reaction per bearing name."""
    condition: str | None = None
    """Condition of the measurement (default: the first)."""
    reference: Annotated[list[str], Field(min_length=2, max_length=2)] | None = None
    """Two bearings whose offsets are held (default: the aft- and forward-most)."""


class AlignmentSection(Section):
    """A shaft alignment: the shaft line on its bearings in every load condition."""

    plausible_ratios = (
        PlausibleRatio(
            "propeller.mass",
            "m/(rho d^3)",
            lambda s, mass: mass / (STEEL * _shaft_diameter_at(s, s.propeller.x) ** 3),
            2.0,
            200.0,
            "propeller mass grows with the cube of the shaft diameter: about 20-40 from small craft (a 0.4 m, 5 kg "
            f"propeller on a 25 mm shaft) to the largest ships (130 t on about 1 m; {_EXAMPLE}: 24); 2 and 200 are "
            "ten times beyond, a mass in t written as a bare number (kg) is far below (engineering judgement)",
            "propeller mass / (7850 kg/m^3 x cube of the shaft diameter at the propeller)",
            uses=(),
        ),
    )

    shaft: ShaftSection
    """The shaft."""
    propeller: PropellerSection | None = None
    """The propeller."""
    bearings: Annotated[list[SupportSection], Field(min_length=2)]
    """The bearings (supports) of the line."""
    loads: list[PointLoadSection] = []
    """Point loads in every condition."""
    masses: list[MassSection] = []
    """Point masses."""
    distributed_loads: list[DistributedLoadSection] = []
    """Distributed loads."""
    conditions: list[ConditionSection] = []
    """Load conditions (none: one condition with the base offsets)."""
    rules_file: str | None = None
    """TOML file of rules replacing the bundled class rules (src/shaftline/shaft/data/rules.toml)."""
    rules: list[RuleSection] = []
    """Rules added to the bundled (or the rules_file's) rules."""
    optimise: OptimiseSection | None = None
    """Offset optimisation."""
    sag_gap: SagGapSection | None = None
    """Sag and gap at a flange."""
    jack_up: JackUpSection | None = None
    """Jack-up test."""
    measured_reactions: MeasuredReactionsSection | None = None
    """Offsets from measured reactions."""
    film: FilmSection | None = None
    """The film of every bearing marked film = true."""
    coupling: CouplingSection = CouplingSection()
    """Tolerances of the coupled solution (with film bearings)."""
    minimum_speed: MinimumSpeedSection | None = None
    """Minimum speed for hydrodynamic operation of the film bearings (lift-off curve)."""

    @model_validator(mode="after")
    def _films(self) -> AlignmentSection:
        if self.minimum_speed is not None and all(b.film is False for b in self.bearings):
            raise field_error(
                "minimum_speed", "given", "a line with a film bearing (film = true or a bearings.film table)"
            )
        if self.minimum_speed is not None and self.minimum_speed.condition is not None:
            names = [c.name for c in self.conditions] or ["base"]
            if self.minimum_speed.condition not in names:
                raise field_error(
                    "minimum_speed.condition",
                    self.minimum_speed.condition,
                    "the name of a condition: " + ", ".join(names),
                )
        for k, bearing in enumerate(self.bearings):
            if bearing.film is False:
                continue
            if bearing.support == "spring":
                raise field_error(
                    f"bearings[{k}].support",
                    bearing.support,
                    "point or multi_point for a hydrodynamic bearing (the film is its support)",
                )
            film = self.film if bearing.film is True else bearing.film
            if film is None:
                raise field_error(
                    f"bearings[{k}].film",
                    True,
                    "a film with speed and lubricant: an [alignment.film] table, or the bearing's own "
                    "[alignment.bearings.film] table",
                )
            assert isinstance(film, FilmSection)
            where = f"bearings[{k}].film" if bearing.film is not True else "film"
            if film.radial_clearance is not None and film.diametral_clearance is not None:
                raise field_error(
                    f"{where}.radial_clearance", film.radial_clearance, "radial_clearance or diametral_clearance"
                )
            given = film.radial_clearance is not None or film.diametral_clearance is not None
            if not given and bearing.vertical_clearance is None:
                raise field_error(
                    f"{where}.radial_clearance",
                    "missing",
                    "the film's clearance: radial_clearance or diametral_clearance, or "
                    f"bearings[{k}].vertical_clearance",
                    "m",
                )
            if given and bearing.vertical_clearance is not None:
                # One bore, one clearance: the point supports' top contact (vertical_clearance,
                # diametral) and the film must agree; a radial value given as diametral (or the
                # reverse) is the slip this catches.
                name = "radial_clearance" if film.radial_clearance is not None else "diametral_clearance"
                value = film.radial_clearance if film.radial_clearance is not None else film.diametral_clearance
                assert value is not None
                diametral = 2.0 * value if name == "radial_clearance" else value
                if abs(diametral - bearing.vertical_clearance) > 1e-3 * bearing.vertical_clearance:
                    wanted = bearing.vertical_clearance * (0.5 if name == "radial_clearance" else 1.0)
                    raise field_error(
                        f"{where}.{name}",
                        value,
                        f"{wanted:.6g} m, as bearings[{k}].vertical_clearance = "
                        f"{bearing.vertical_clearance:.6g} m (diametral) of the same bore; or leave one of them out",
                        "m",
                    )
        return self

    @model_validator(mode="after")
    def _names(self) -> AlignmentSection:
        bearings = [b.name for b in self.bearings]
        conditions = [c.name for c in self.conditions]
        for k, name in enumerate(conditions):
            if name in conditions[:k]:
                raise field_error(f"conditions[{k}].name", name, "a name not used by another condition")
        for k, condition in enumerate(self.conditions):
            for plane in ("offsets_y", "offsets_z"):
                for name in getattr(condition, plane):
                    if name not in bearings:
                        raise field_error(
                            f"conditions[{k}].{plane}.{name}", name, "a bearing name: " + ", ".join(bearings)
                        )
        known = "a bearing name: " + ", ".join(bearings)
        if self.optimise is not None and self.optimise.adjustable is not None:
            for name in self.optimise.adjustable:
                if name not in bearings:
                    raise field_error("optimise.adjustable", name, known)
        if self.jack_up is not None and self.jack_up.bearing not in bearings:
            raise field_error("jack_up.bearing", self.jack_up.bearing, known)
        if self.measured_reactions is not None:
            for name in self.measured_reactions.values:
                if name not in bearings:
                    raise field_error(f"measured_reactions.values.{name}", name, known)
            for k, name in enumerate(self.measured_reactions.reference or []):
                if name not in bearings:
                    raise field_error(f"measured_reactions.reference[{k}]", name, known)
        for where, asked in (
            ("sag_gap.condition", self.sag_gap.condition if self.sag_gap else None),
            ("jack_up.condition", self.jack_up.condition if self.jack_up else None),
            ("measured_reactions.condition", self.measured_reactions.condition if self.measured_reactions else None),
        ):
            if asked is not None and asked not in (conditions or ["base"]):
                raise field_error(where, asked, "the name of a condition: " + ", ".join(conditions or ["base"]))
        return self


def _point_load(load: PointLoadSection) -> PointLoad:
    return PointLoad(
        x=load.x,
        force_y=load.force_y,
        force_z=load.force_z,
        moment_vertical=load.moment_vertical,
        moment_horizontal=load.moment_horizontal,
        name=load.name,
    )


def read_jack_curve(path: Any) -> tuple[Any, Any]:
    """A measured jack-up curve from CSV: columns ``load`` (N) and ``lift`` (m)."""
    from shaftline.csvio import read_columns

    table = read_columns(path, ["load", "lift"], "measured_curve")
    return table["load"], table["lift"]


#: Domain names of ShaftLine's fields and their place in ``[alignment]``.
LINE_FIELDS = {
    "segments": "shaft.segments",
    "point_loads": "loads",
    "element_length": "shaft.element_length",
    "beam_theory": "shaft.beam_theory",
    "gravity": "shaft.gravity",
}


def build_line(section: AlignmentSection) -> ShaftLine:
    """The shaft line in SI domain objects (raises :class:`InputError` with the path in ``[alignment]``)."""
    shaft = section.shaft
    segments = tuple(
        ShaftSegment(
            length=s.length,
            outer_diameter=s.outer_diameter,
            inner_diameter=s.inner_diameter,
            outer_diameter_end=s.outer_diameter_end,
            inner_diameter_end=s.inner_diameter_end,
            youngs_modulus=s.youngs_modulus if s.youngs_modulus is not None else shaft.youngs_modulus,
            shear_modulus=s.shear_modulus,
            poisson_ratio=s.poisson_ratio if s.poisson_ratio is not None else shaft.poisson_ratio,
            density=s.density if s.density is not None else shaft.density,
            shear_area_factor=s.shear_area_factor,
            name=s.name,
        )
        for s in shaft.segments
    )
    bearings = tuple(
        Bearing(
            name=b.name,
            x=b.x,
            length=b.length,
            offset_y=b.offset_y,
            offset_z=b.offset_z,
            vertical_clearance=math.inf if b.vertical_clearance is None else b.vertical_clearance,
            material=b.material,
            support=b.support,
            stiffness=math.inf if b.stiffness is None else b.stiffness,
            points=b.points,
            position=b.position,
            one_sided=b.one_sided,
            slope=b.slope,
        )
        for b in section.bearings
    )
    conditions = tuple(
        Condition(
            name=c.name,
            offsets_y=dict(c.offsets_y),
            offsets_z=dict(c.offsets_z),
            propeller_immersion=c.propeller_immersion,
            loads=tuple(_point_load(p) for p in c.loads),
        )
        for c in section.conditions
    )
    propeller = None
    if section.propeller is not None:
        p = section.propeller
        propeller = Propeller(
            x=p.x,
            mass=p.mass,
            material_density=p.material_density,
            water_density=p.water_density,
            immersed_fraction=p.immersed_fraction,
        )
    with located("", LINE_FIELDS):
        return ShaftLine(
            segments=segments,
            bearings=bearings,
            point_loads=tuple(_point_load(p) for p in section.loads),
            masses=tuple(PointMass(m.x, m.mass, m.name) for m in section.masses),
            distributed_loads=tuple(
                DistributedLoad(d.x_start, d.x_end, d.load_y, d.load_z, d.name) for d in section.distributed_loads
            ),
            propeller=propeller,
            conditions=conditions,
            self_weight=shaft.self_weight,
            gravity=shaft.gravity,
            element_length=shaft.element_length,
            beam_theory=shaft.beam_theory,
        )


def _condition(line: ShaftLine, name: str | None) -> Condition:
    conditions = line.all_conditions()
    return conditions[0] if name is None else next(c for c in conditions if c.name == name)  # names checked


def build_study(section: AlignmentSection, context: BuildContext) -> AlignmentStudy:
    """The alignment study in SI domain objects."""
    from shaftline.shaft.rules import Rule, load_rules
    from shaftline.shaft.study import (
        AlignmentStudy,
        JackUpRequest,
        MeasuredReactions,
        MinimumSpeedRequest,
        OffsetOptimisation,
        SagGapRequest,
    )

    line = build_line(section)
    with located("", {"path": "rules_file"}):
        rules = load_rules(context.path(section.rules_file) if section.rules_file is not None else None)
    rules += [Rule(**rule.model_dump()) for rule in section.rules]
    optimise = None
    if section.optimise is not None:
        o = section.optimise
        optimise = OffsetOptimisation(o.objective, tuple(o.adjustable) if o.adjustable is not None else None, o.bound)
    sag_gap = None
    if section.sag_gap is not None:
        sg = section.sag_gap
        sag_gap = SagGapRequest(
            flange_x=sg.flange_x,
            condition=_condition(line, sg.condition),
            flange_diameter=sg.flange_diameter,
            temporary_supports=tuple(
                Bearing(name=t.name, x=t.x, length=1e-3, offset_y=t.offset_y) for t in sg.temporary_supports
            ),
        )
    jack = None
    if section.jack_up is not None:
        ju = section.jack_up
        measured = None
        if ju.measured_curve is not None:
            with located("jack_up"):
                measured = read_jack_curve(context.path(ju.measured_curve))
        jack = JackUpRequest(ju.bearing, ju.jack_x, _condition(line, ju.condition), measured)
    reactions = None
    if section.measured_reactions is not None:
        mr = section.measured_reactions
        reactions = MeasuredReactions(
            dict(mr.values),
            _condition(line, mr.condition),
            (mr.reference[0], mr.reference[1]) if mr.reference is not None else None,
        )
    built = [
        _film_support(section, k, line, context.warnings)
        for k, bearing in enumerate(section.bearings)
        if bearing.film is not False
    ]
    films = tuple(support for support, _ in built)
    lubricants = tuple(oil for _, oil in built)
    c = section.coupling
    coupling = CouplingOptions(c.force_tolerance, c.film_tolerance, c.max_iterations)
    fields = tuple(
        f"bearings[{k}].film" if isinstance(b.film, FilmSection) else "film"
        for k, b in enumerate(section.bearings)
        if b.film is not False
    )
    lift_off = None
    if section.minimum_speed is not None:
        ms = section.minimum_speed
        with located("minimum_speed"):
            limit = FilmLimit(
                journal_roughness=ms.journal_roughness,
                bore_roughness=ms.bore_roughness,
                roughness_parameter=ms.roughness_parameter,
                film_parameter=ms.film_parameter,
                class_value=ms.class_value,
            )
        lift_off = MinimumSpeedRequest(limit, _condition(line, ms.condition), ms.lowest, ms.points, ms.tolerance)
    return AlignmentStudy(
        line, tuple(rules), optimise, sag_gap, jack, reactions, films, coupling, fields, lift_off, lubricants
    )


def _film_support(
    section: AlignmentSection, k: int, line: ShaftLine, notes: list[str] | None = None
) -> tuple[FilmSupport, tuple[Lubricant, float | None]]:
    """The film of ``bearings[k]`` as a domain object (errors placed under its table), with its
    lubricant and film temperature (None for a viscosity given as such). ``notes``: where the
    film's notes go (the layer liner's resolution and the turbulence notes, as for [bearing])."""
    from shaftline.film.case import (
        _bore,
        checked_surface,
        layer_note,
        liner_of,
        lubricant_properties,
        solver_options,
        turbulence_notes,
    )
    from shaftline.film.problem import BearingProblem

    bearing = section.bearings[k]
    own = isinstance(bearing.film, FilmSection)
    film = bearing.film if isinstance(bearing.film, FilmSection) else section.film
    assert film is not None  # checked by the schema
    where = f"bearings[{k}].film" if own else "film"
    if film.radial_clearance is not None:
        clearance = film.radial_clearance
    elif film.diametral_clearance is not None:
        clearance = 0.5 * film.diametral_clearance
    else:
        assert bearing.vertical_clearance is not None  # checked by the schema
        clearance = 0.5 * bearing.vertical_clearance
    with located(where):
        lubricant, viscosity, density = lubricant_properties(film.lubricant)
    with located(where, {"viscosity": "lubricant.viscosity", "density": "lubricant.density"}):
        operating = OperatingPoint(
            speed=film.speed,
            viscosity=viscosity,
            density=density,
            aft_pressure=film.aft_pressure,
            fore_pressure=film.fore_pressure,
            cavitation_pressure=film.cavitation_pressure,
        )
    with located(f"{where}.solver"):
        options = solver_options(film.solver)
    with located(where):
        surface = None if film.surface is None else checked_surface(film.surface, clearance)
    liner = None
    if film.liner is not None:
        with located(f"{where}.liner"):
            liner = liner_of(film.liner)
    with located(where, {"length": f"bearings[{k}].length", "diameter": "shaft.segments"}):
        geometry = BearingGeometry(
            length=bearing.length,
            diameter=line.outer_diameter_at(bearing.x),
            radial_clearance=clearance,
            bore=_bore(film.bore, bearing.length, clearance),
            bore_anchor=film.bore_anchor,
            rotation=1 if film.rotation == "clockwise" else -1,
            surface=surface,
            liner=liner,
        )
    # a rename replaces the prefix too: the operating point's fields are the film table's own
    with located(where, {"operating": where, "options": f"{where}.solver"}):
        problem = BearingProblem(geometry, operating, options)
    if notes is not None:
        # a shared [alignment.film] table gives its note once, not once per bearing
        fresh = turbulence_notes(film.solver, options, geometry, operating, f"alignment.{where}.solver")
        # The layer liner's under-resolution note, as [bearing.liner] gives it (film/case.py).
        layer = layer_note(geometry, options.axial_nodes, f"alignment.{where}.")
        fresh = ([] if layer is None else [layer]) + fresh
        notes.extend(note for note in fresh if note not in notes)
    return FilmSupport(bearing.name, problem, film.elements), (lubricant, film.lubricant.temperature)
