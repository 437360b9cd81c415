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

The tables are defined by family, each in its own module: the bearing's shape (bore, bent
journal, film profile, rotation) in :mod:`~shaftline.film.case_geometry`, the running
condition (operation and its grooves, lubricant, thermal) in
:mod:`~shaftline.film.case_operation`, the bore's surfaces (roughness, liner) in
:mod:`~shaftline.film.case_surface` and the solution's settings (solver, Stribeck speeds) in
:mod:`~shaftline.film.case_solver`. This module holds the ``[bearing]`` table itself with its
variants and the build of the study, and re-exports the tables' names.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import replace
from typing import TYPE_CHECKING, Annotated, Literal

import numpy as np
from pydantic import BeforeValidator, model_validator

from shaftline.cases.types import (
    Angle,
    Number,
    Plausible,
    PlausibleRatio,
    PositiveLength,
    Section,
    default_of,
    field_error,
)
from shaftline.errors import InputError, located
from shaftline.film.case_geometry import (
    CLEARANCE_SHARE,
    JOURNAL_OFFSET,
    ROTATION_ALIASES,
    SLOPE,
    BentJournalSection,
    BoreSegmentSection,
    FilmProfileSection,
    _bore,
    _rotation_alias,
    _tilt,
    read_film_profile,
)
from shaftline.film.case_operation import (
    BEARING_LOAD,
    EDGE_PRESSURE,
    KINEMATIC_VISCOSITY,
    PRESET_TEXT,
    REFERENCE_TEMPERATURE,
    GrooveSection,
    LubricantSection,
    OperationSection,
    ThermalSection,
    lubricant_properties,
    operating_point,
    thermal_options,
)
from shaftline.film.case_solver import (
    FAR_BELOW_TRANSITION,
    LAYER_RESOLUTION,
    SolverSection,
    StribeckSection,
    layer_note,
    solver_options,
    stribeck_speeds,
    turbulence_note,
    turbulence_notes,
)
from shaftline.film.case_surface import LinerSection, SurfaceSection, checked_surface, liner_of, surface_roughness
from shaftline.film.geometry import BearingGeometry, BentJournal, BoreAnchor, BoreSegment
from shaftline.film.problem import BearingProblem, OperatingPoint, SolverOptions
from shaftline.film.study import BearingCase
from shaftline.registry import BuildContext

if TYPE_CHECKING:
    from shaftline.film.study import BearingStudy
    from shaftline.film.thermal import ThermalOptions
    from shaftline.lubricants import Lubricant

__all__ = [
    "BEARING_LOAD",
    "CLEARANCE_SHARE",
    "EDGE_PRESSURE",
    "FAR_BELOW_TRANSITION",
    "JOURNAL_OFFSET",
    "KINEMATIC_VISCOSITY",
    "LAYER_RESOLUTION",
    "PRESET_TEXT",
    "REFERENCE_TEMPERATURE",
    "ROTATION_ALIASES",
    "SLOPE",
    "BearingSection",
    "BentJournalSection",
    "BoreSegmentSection",
    "FilmProfileSection",
    "GrooveSection",
    "LinerSection",
    "LubricantSection",
    "OperationSection",
    "SolverSection",
    "StribeckSection",
    "SurfaceSection",
    "ThermalSection",
    "VariantSection",
    "build_study",
    "checked_surface",
    "layer_note",
    "liner_of",
    "lubricant_properties",
    "operating_point",
    "read_film_profile",
    "solver_options",
    "stribeck_speeds",
    "surface_roughness",
    "thermal_options",
    "turbulence_note",
    "turbulence_notes",
]

_SEEDS = "seed 004 Table 5-1 (L = 1.05 m, D = 0.52 m, c = 0.45 mm), seed 001 Table 1 (L = 1.2 m, D = 0.324 m)"


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


#: The bearing's geometry for a bore: its segments, and the field they come from (for errors).
GeometryOf = Callable[[tuple[BoreSegment, ...], str], BearingGeometry]


def build_study(section: BearingSection, context: BuildContext) -> BearingStudy:
    """The base case and its variants in SI domain objects (raises :class:`InputError` with
    the field's path inside ``[bearing]``)."""
    from shaftline.film.study import BearingStudy

    clearance = (
        section.radial_clearance if section.radial_clearance is not None else 0.5 * (section.diametral_clearance or 0.0)
    )
    geometry = _geometry_of(section, context, clearance)
    base_geometry = geometry(_bore(section.bore, section.length, clearance), "bore")
    lubricant, viscosity, density = lubricant_properties(section.lubricant)
    operating = operating_point(section.operation, viscosity, density)
    thermal = None if section.thermal is None else thermal_options(section.thermal, section.lubricant, lubricant)
    options = _checked_options(section, base_geometry, operating, context)
    base = _base_case(section, context.case.name, base_geometry, operating, options, lubricant, thermal, clearance)
    cases = [base, *_variants(section, context.case.name, base, geometry, clearance)]
    return BearingStudy(tuple(cases), stribeck_speeds(section.stribeck, section.operation.speed))


def _geometry_of(section: BearingSection, context: BuildContext, clearance: float) -> GeometryOf:
    """The bearing's geometry for a given bore, with the bent journal, film profile, surface and
    liner of ``[bearing]`` read once for the base case and all its variants."""
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
                length=section.length,
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

    return geometry


def _checked_options(
    section: BearingSection, geometry: BearingGeometry, operating: OperatingPoint, context: BuildContext
) -> SolverOptions:
    """The solver options of ``[bearing.solver]``, checked as a problem with the base case's
    geometry and operating point; the notes on them go to ``context.warnings``."""
    with located("solver"):
        options = solver_options(section.solver)
    with located("", {"operating": "operation", "options": "solver"}):
        BearingProblem(geometry, operating, options)
    layer = layer_note(geometry, options.axial_nodes)
    if layer is not None:
        context.warnings.append(layer)
    context.warnings.extend(turbulence_notes(section.solver, options, geometry, operating, "bearing.solver"))
    return options


def _error_fields(section: BearingSection, tilt_field: str) -> dict[str, str]:
    """Where the case file gives a case's tilts and loads (``tilt_field``: its vertical tilt),
    for an error found only while solving."""
    # A journal that does not fit in the bore is the tilt's fault, or the bent journal's.
    bent = section.bent_journal is not None
    return {
        "tilt_y": "bent_journal" if bent else tilt_field,
        "tilt_z": "bent_journal" if bent else "operation.tilt_horizontal",
        "load_y": "operation.load",
        "load_z": "operation.load_horizontal",
    }


def _base_case(
    section: BearingSection,
    name: str,
    geometry: BearingGeometry,
    operating: OperatingPoint,
    options: SolverOptions,
    lubricant: Lubricant,
    thermal: ThermalOptions | None,
    clearance: float,
) -> BearingCase:
    """The base case of ``[bearing]``, named ``name``, under the load and tilts of its operation."""
    op = section.operation
    return BearingCase(
        name=name,
        geometry=geometry,
        operating=operating,
        options=options,
        load_y=-op.load,
        load_z=op.load_horizontal,
        tilt_y=_tilt(op.tilt_vertical, op.misalignment_ratio_vertical, section.length, clearance),
        tilt_z=_tilt(op.tilt_horizontal, op.misalignment_ratio_horizontal, section.length, clearance),
        lubricant=lubricant,
        temperature=section.lubricant.temperature,
        surface_roughness=section.surface_roughness if geometry.surface is None else geometry.surface.sigma,
        error_fields=_error_fields(section, "operation.tilt_vertical"),
        thermal=thermal,
    )


def _variants(
    section: BearingSection, name: str, base: BearingCase, geometry: GeometryOf, clearance: float
) -> list[BearingCase]:
    """The cases of ``[[bearing.variants]]``: the base case (named ``name``) with a variant's own
    bore or vertical tilt."""
    cases = []
    for k, variant in enumerate(section.variants):
        if variant.name == name:
            raise InputError(f"variants[{k}].name", variant.name, "", "a name other than the case's ([case] name)")
        variant_geometry = base.geometry
        if variant.bore is not None:
            variant_geometry = geometry(_bore(variant.bore, section.length, clearance), f"variants[{k}].bore")
        variant_tilt, tilt_field = base.tilt_y, "operation.tilt_vertical"
        if variant.misalignment_ratio_vertical is not None or variant.tilt_vertical is not None:
            variant_tilt = _tilt(variant.tilt_vertical, variant.misalignment_ratio_vertical, section.length, clearance)
            tilt_field = f"variants[{k}].tilt_vertical"
        variant_fields = _error_fields(section, tilt_field)
        cases.append(
            replace(
                base, name=variant.name, geometry=variant_geometry, tilt_y=variant_tilt, error_fields=variant_fields
            )
        )
    return cases
