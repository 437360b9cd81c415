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

The tables are defined by family, each in its own module: the line's geometry in
:mod:`~shaftline.shaft.case_line`, the bearings in :mod:`~shaftline.shaft.case_supports`,
loads and conditions in :mod:`~shaftline.shaft.case_loads`, rules and procedures in
:mod:`~shaftline.shaft.case_procedures`, the film tables in :mod:`~shaftline.shaft.case_film`
and the ranges they share in :mod:`~shaftline.shaft.case_ranges`. This module holds the
``[alignment]`` table itself, its cross-table checks and the build of the study, and
re-exports the tables' names.
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING, Annotated

from pydantic import Field, model_validator

from shaftline.cases.types import PlausibleRatio, Section, field_error
from shaftline.errors import located
from shaftline.registry import BuildContext

if TYPE_CHECKING:
    from shaftline.shaft.study import AlignmentStudy
from shaftline.shaft.case_film import CouplingSection, FilmSection, MinimumSpeedSection, film_support
from shaftline.shaft.case_line import BeamTheory, PropellerSection, SegmentSection, ShaftSection, shaft_diameter_at
from shaftline.shaft.case_loads import (
    DISTRIBUTED_LOAD,
    ConditionSection,
    DistributedLoadSection,
    MassSection,
    PointLoadSection,
    point_load,
)
from shaftline.shaft.case_procedures import (
    Comparison,
    JackUpSection,
    MeasuredReactionsSection,
    Objective,
    OptimiseSection,
    RuleQuantity,
    RuleSection,
    SagGapSection,
    TemporarySupportSection,
    read_jack_curve,
)
from shaftline.shaft.case_ranges import (
    BORE,
    EXAMPLE_CASE,
    LINE_FORCE,
    LINE_MOMENT,
    OFFSET,
    SHAFT_DENSITY,
    SHAFT_DIAMETER,
    STEEL,
    YOUNGS_MODULUS,
    X,
)
from shaftline.shaft.case_supports import Material, SupportModel, SupportPosition, SupportSection
from shaftline.shaft.film_supports import CouplingOptions
from shaftline.shaft.lift_off import FilmLimit
from shaftline.shaft.model import Bearing, Condition, DistributedLoad, PointMass, Propeller, ShaftLine, ShaftSegment

__all__ = [
    "BORE",
    "DISTRIBUTED_LOAD",
    "LINE_FIELDS",
    "LINE_FORCE",
    "LINE_MOMENT",
    "OFFSET",
    "SHAFT_DENSITY",
    "SHAFT_DIAMETER",
    "STEEL",
    "YOUNGS_MODULUS",
    "AlignmentSection",
    "BeamTheory",
    "Comparison",
    "ConditionSection",
    "CouplingSection",
    "DistributedLoadSection",
    "FilmSection",
    "JackUpSection",
    "MassSection",
    "Material",
    "MeasuredReactionsSection",
    "MinimumSpeedSection",
    "Objective",
    "OptimiseSection",
    "PointLoadSection",
    "PropellerSection",
    "RuleQuantity",
    "RuleSection",
    "SagGapSection",
    "SegmentSection",
    "ShaftSection",
    "SupportModel",
    "SupportPosition",
    "SupportSection",
    "TemporarySupportSection",
    "X",
    "build_line",
    "build_study",
    "read_jack_curve",
]


class AlignmentSection(Section):
    """A shaft alignment: the shaft line on its bearings in every load condition."""

    plausible_ratios = (
        PlausibleRatio(
            "propeller.mass",
            "m/(rho d^3)",
            lambda s, mass: mass / (STEEL * shaft_diameter_at(s.shaft, s.propeller.x) ** 3),
            2.0,
            200.0,
            "propeller mass grows with the cube of the shaft diameter: about 20-40 from small craft (a 0.4 m, 5 kg "
            f"propeller on a 25 mm shaft) to the largest ships (130 t on about 1 m; {EXAMPLE_CASE}: 24); 2 and 200 are "
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
            loads=tuple(point_load(p) for p in c.loads),
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
            point_loads=tuple(point_load(p) for p in section.loads),
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
        film_support(section, k, line, context.warnings)
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
