"""The film tables of ``[alignment]``: a bearing's film (``[alignment.film]``,
``[alignment.bearings.film]``), the minimum speed of the film bearings and the coupled
solution's tolerances, and the film bearings built from them."""

from __future__ import annotations

from typing import TYPE_CHECKING, Annotated, Literal

from pydantic import BeforeValidator, Field

from shaftline.cases.types import (
    SHAFT_SPEED,
    NonNegativeLength,
    Plausible,
    PositiveLength,
    Pressure,
    Quantity,
    Section,
    default_of,
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
)
from shaftline.film.case_geometry import _rotation_alias
from shaftline.film.geometry import BearingGeometry, BoreAnchor
from shaftline.film.problem import OperatingPoint
from shaftline.shaft.film_supports import CouplingOptions, FilmSupport
from shaftline.shaft.lift_off import FilmLimit
from shaftline.shaft.model import ShaftLine

if TYPE_CHECKING:
    from shaftline.lubricants import Lubricant
    from shaftline.shaft.case import AlignmentSection


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


_FILM_LIMIT = (
    "class values of the smallest film are some tens of µm (seed 004 quotes Bureau Veritas' 30 µm); 0.5 mm is "
    "beyond any stern-tube clearance, a limit in µm written as m is far above (engineering judgement)"
)
_ROUGHNESS = (
    "ground journals and bored liners are Ra 0.2-3.2 µm (seed 001: 0.8 µm sleeve, 1.6 µm liner); 20 µm is a "
    "rough casting, µm written as m is far above (engineering judgement)"
)


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


def film_support(
    section: AlignmentSection, k: int, line: ShaftLine, notes: list[str] | None = None
) -> tuple[FilmSupport, tuple[Lubricant, float | None]]:
    """The film of ``bearings[k]`` as a domain object (errors placed under its table), with its
    lubricant and film temperature (None for a viscosity given as such). ``notes``: where the
    film's notes go (the layer liner's resolution and the turbulence notes, as for [bearing])."""
    from shaftline.film.case import (
        checked_surface,
        layer_note,
        liner_of,
        lubricant_properties,
        solver_options,
        turbulence_notes,
    )
    from shaftline.film.case_geometry import _bore
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
        # The layer liner's under-resolution note, as [bearing.liner] gives it (film/case_solver.py).
        layer = layer_note(geometry, options.axial_nodes, f"alignment.{where}.")
        fresh = ([] if layer is None else [layer]) + fresh
        notes.extend(note for note in fresh if note not in notes)
    return FilmSupport(bearing.name, problem, film.elements), (lubricant, film.lubricant.temperature)
