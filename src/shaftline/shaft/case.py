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
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING, Annotated, Any, Literal

from pydantic import Field, model_validator

from shaftline.cases.types import (
    Angle,
    Force,
    ForcePerLength,
    Fraction,
    Length,
    Moment,
    NonNegativeLength,
    Number,
    PositiveAcceleration,
    PositiveDensity,
    PositiveFraction,
    PositiveLength,
    PositiveMass,
    PositivePressure,
    PositiveStiffness,
    Section,
    default_of,
    field_error,
)
from shaftline.errors import located
from shaftline.registry import BuildContext

if TYPE_CHECKING:
    from shaftline.shaft.study import AlignmentStudy
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


class SegmentSection(Section):
    """A length of shaft, straight or conical, solid or hollow; flanges as short thick segments."""

    length: PositiveLength
    """Segment length."""
    outer_diameter: PositiveLength
    """Outer diameter at the aft end."""
    inner_diameter: NonNegativeLength = default_of(ShaftSegment, "inner_diameter")
    """Bore at the aft end (0: solid)."""
    outer_diameter_end: PositiveLength | None = None
    """Outer diameter at the forward end of a conical segment."""
    inner_diameter_end: NonNegativeLength | None = None
    """Bore at the forward end of a conical segment."""
    youngs_modulus: PositivePressure | None = None
    """Young's modulus (default: the shaft's)."""
    shear_modulus: PositivePressure | None = None
    """Shear modulus (default: from Young's modulus and Poisson's ratio)."""
    poisson_ratio: Annotated[float, Field(gt=-1, lt=0.5)] | None = None
    """Poisson's ratio (default: the shaft's)."""
    density: PositiveDensity | None = None
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
    element_length: PositiveLength = default_of(ShaftLine, "element_length")
    """Largest element length of the mesh."""
    self_weight: bool = default_of(ShaftLine, "self_weight")
    """Include the shaft's own weight."""
    gravity: PositiveAcceleration = default_of(ShaftLine, "gravity")
    """Acceleration of gravity."""
    youngs_modulus: PositivePressure = default_of(ShaftSegment, "youngs_modulus")
    """Young's modulus of segments that give none."""
    poisson_ratio: Annotated[float, Field(gt=-1, lt=0.5)] = default_of(ShaftSegment, "poisson_ratio")
    """Poisson's ratio of segments that give none."""
    density: PositiveDensity = default_of(ShaftSegment, "density")
    """Density of segments that give none."""


class PropellerSection(Section):
    """The propeller: its weight less buoyancy acts at its centre of gravity."""

    x: Length
    """Centre of gravity (x < 0 beyond the aft end of the shaft)."""
    mass: PositiveMass
    """Mass in air."""
    material_density: PositiveDensity = default_of(Propeller, "material_density")
    """Density of the propeller material (buoyancy)."""
    water_density: PositiveDensity = default_of(Propeller, "water_density")
    """Density of the water."""
    immersed_fraction: Fraction = default_of(Propeller, "immersed_fraction")
    """Share of the propeller under water (conditions may change it)."""


class SupportSection(Section):
    """A bearing of the line: its position, offsets and support model."""

    name: str
    """Name (conditions, rules and procedures refer to it)."""
    x: Length
    """Centre of the bearing."""
    length: PositiveLength
    """Bearing length."""
    offset_y: Length = default_of(Bearing, "offset_y")
    """Vertical offset of the bearing from the reference line (+ up)."""
    offset_z: Length = default_of(Bearing, "offset_z")
    """Horizontal offset (+ starboard)."""
    vertical_clearance: PositiveLength | None = None
    """Diametral clearance: the shaft touches the top of the bore after it (none: no top)."""
    material: Material = default_of(Bearing, "material")
    """Lining material (selects the class rules that apply); engine: limits of the engine maker."""
    support: SupportModel = default_of(Bearing, "support")
    """Rigid point, spring, or several points along a long bearing."""
    stiffness: PositiveStiffness | None = None
    """Support stiffness of a spring support."""
    points: Annotated[int, Field(ge=1, le=50)] = default_of(Bearing, "points")
    """Support points of a multi-point support."""
    position: SupportPosition = default_of(Bearing, "position")
    """Where a point support acts: the centre or a third of the length from the aft end."""
    one_sided: bool = default_of(Bearing, "one_sided")
    """The shaft can lift off (the bearing only pushes up)."""
    slope: Angle = default_of(Bearing, "slope")
    """The bearing's own slope (slope boring)."""


class PointLoadSection(Section):
    """A point force and moment on the shaft."""

    x: Length
    """Station."""
    force_y: Force = default_of(PointLoad, "force_y")
    """Vertical force (+ up)."""
    force_z: Force = default_of(PointLoad, "force_z")
    """Horizontal force (+ starboard)."""
    moment_vertical: Moment = default_of(PointLoad, "moment_vertical")
    """Moment in the vertical plane (+ turning +x towards +y)."""
    moment_horizontal: Moment = default_of(PointLoad, "moment_horizontal")
    """Moment in the horizontal plane (+ turning +x towards +z)."""
    name: str = ""
    """Label."""


class MassSection(Section):
    """A point mass (flywheel, coupling): its weight acts at x."""

    x: Length
    """Station."""
    mass: PositiveMass
    """Mass."""
    name: str = ""
    """Label."""


class DistributedLoadSection(Section):
    """A load spread uniformly over a length of shaft."""

    x_start: Length
    """Aft end of the loaded length."""
    x_end: Length
    """Forward end."""
    load_y: ForcePerLength = default_of(DistributedLoad, "load_y")
    """Vertical load per length (+ up)."""
    load_z: ForcePerLength = default_of(DistributedLoad, "load_z")
    """Horizontal load per length (+ starboard)."""
    name: str = ""
    """Label."""


class ConditionSection(Section):
    """A load condition: offsets added to the bearings' and loads added to the line's."""

    name: str
    """Name (cold/hot, ballast/laden, static/running, ...)."""
    offsets_y: dict[str, Length] = {}
    """Vertical offsets added per bearing name, e.g. { "intermediate" = "0.2 mm" }."""
    offsets_z: dict[str, Length] = {}
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
    bound: PositiveLength = 5e-3
    """Largest added offset either way."""


class TemporarySupportSection(Section):
    """A temporary support of the uncoupled shaft."""

    name: str
    """Label."""
    x: Length
    """Station."""
    offset_y: Length = 0.0
    """Vertical offset (+ up)."""


class SagGapSection(Section):
    """Sag and gap at an uncoupled flange."""

    flange_x: Length
    """Station of the flange."""
    flange_diameter: PositiveLength | None = None
    """Flange diameter (default: the larger shaft diameter at the flange)."""
    condition: str | None = None
    """Condition (default: the first)."""
    temporary_supports: list[TemporarySupportSection] = []
    """Supports added while the line is uncoupled."""


class JackUpSection(Section):
    """A jack-up test of one bearing, modelled and, with a measured curve, evaluated."""

    bearing: str
    """The bearing jacked."""
    jack_x: Length
    """Station of the jack."""
    condition: str | None = None
    """Condition (default: the first)."""
    measured_curve: str | None = None
    """CSV with columns load (N) and lift (m) from the test; path relative to the case file."""


class MeasuredReactionsSection(Section):
    """Offsets that explain measured reactions (reverse engineering of the alignment)."""

    values: dict[str, Force]
    """Measured reaction per bearing name."""
    condition: str | None = None
    """Condition of the measurement (default: the first)."""
    reference: Annotated[list[str], Field(min_length=2, max_length=2)] | None = None
    """Two bearings whose offsets are held (default: the aft- and forward-most)."""


class AlignmentSection(Section):
    """A shaft alignment: the shaft line on its bearings in every load condition."""

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
    return AlignmentStudy(line, tuple(rules), optimise, sag_gap, jack, reactions)
