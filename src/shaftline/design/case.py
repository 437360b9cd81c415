"""The ``[design]`` table of a case file: the search for a slope-bored bore of the case's
``[bearing]`` (its base case is the operating point held during the search) or of a film
bearing of its ``[alignment]`` (the coupled solution is the operating point), its robustness
scenarios and the misalignment sweep.

Layout::

    [design]                          segments, bounds, objectives, shaft model
    [[design.constraints]]            quantity, comparison, limit
    [design.search]                   algorithm, population, generations, seed
    [design.robustness]               which designs, h_min limit, scenarios
    [[design.robustness.scenarios]]   name, speed_factor, load_factor, temperature_change
    [design.sweep]                    misalignment ratios
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING, Annotated, Literal

from pydantic import Field, model_validator

from shaftline.cases.types import (
    Number,
    Plausible,
    PositiveNumber,
    Quantity,
    Section,
    field_error,
)
from shaftline.errors import InputError, located
from shaftline.registry import BuildContext

if TYPE_CHECKING:
    from shaftline.design.problem import SlopeDesignProblem
    from shaftline.design.robustness import Scenario
    from shaftline.design.study import CoupledSource, DesignStudy
    from shaftline.film.problem import BearingProblem
    from shaftline.lubricants import Lubricant

ObjectiveName = Literal["min_film_thickness", "max_pressure", "power_loss", "side_leakage", "support_offset"]
ShaftModel = Literal["linear", "bent", "coupled"]
RobustDesigns = Literal["knee", "pareto", "named", "none"]
SLOPE_SHARE = Plausible(
    -3.0,
    3.0,
    "seed 004 bounds slopes to 0-0.6 of 2c/L (Table 4-8); 1 is a bore rising a full clearance over the "
    "bearing, 3 three times that (engineering judgement); a share written in % (30 for 0.3) is far outside",
)
_FILM_LIMIT = (
    "class values of the smallest film are some tens of µm (seed 004 quotes Bureau Veritas' 30 µm); 0.5 mm is "
    "beyond any stern-tube clearance, a limit in µm written as m is far above (engineering judgement)"
)


class ConstraintSection(Section):
    """A limit a design must meet to count (e.g. h_min >= 30 µm)."""

    quantity: ObjectiveName
    """The quantity: min_film_thickness (m), max_pressure (Pa), power_loss (W), side_leakage (m^3/s) or
    support_offset (m)."""
    comparison: Literal[">=", "<="]
    """value <comparison> limit is met."""
    limit: Number
    """Limit in SI units (m, Pa, W, m^3/s)."""


class SearchSection(Section):
    """The multi-objective search (pymoo)."""

    algorithm: Literal["nsga2", "spea2", "smsemoa", "agemoea"] = "nsga2"
    """pymoo algorithm (seed 004: MATLAB's gamultiobj, a controlled-elitist NSGA-II)."""
    population: Annotated[int, Field(ge=4, le=10000)] = 40
    """Designs per generation (seed 004: 40)."""
    generations: Annotated[int, Field(ge=1, le=10000)] = 40
    """Generations (seed 004: 40)."""
    seed: Annotated[int, Field(ge=0)] = 1
    """Random seed: the same seed gives the same designs."""
    store: str | None = None
    """Folder (relative to the case file) that keeps every evaluation as it is made, in Parquet and CSV; the same
    search started again on it resumes where it stopped (a folder of another search is refused)."""


class ScenarioSection(Section):
    """A deviation from the operating point."""

    name: str
    """Label."""
    speed_factor: PositiveNumber = 1.0
    """Multiplier of the shaft speed."""
    load_factor: PositiveNumber = 1.0
    """Multiplier of the load."""
    temperature_change: Annotated[float, Quantity("temperature_difference", ge=-100, le=100)] = 0.0
    """Change of the oil's effective temperature (viscosity from the lubricant)."""


class NamedDesignSection(Section):
    """A bore given by its design variables (e.g. the seed's double slope), for the robustness."""

    name: str
    """Label."""
    slopes: Annotated[list[Annotated[Number, SLOPE_SHARE]], Field(min_length=1)]
    """Slope of each segment aft to forward, shares of 2c/L."""
    knuckles: list[Number] = []
    """Knuckle positions aft to forward, shares of L from the aft edge (one fewer than the slopes)."""


class RobustnessSection(Section):
    """The chosen designs under speed, load and oil-temperature deviations."""

    designs: RobustDesigns = "knee"
    """Which designs: the knee of the front, the whole front (both need the search), the named designs below (no
    search), or none."""
    named: list[NamedDesignSection] = []
    """Designs given by their variables: marked on the front and compared along the bearing beside the knee, and
    with designs = "named" the ones whose robustness is checked (`design robustness --designs FILE` reads them
    from a CSV with a name column and the variable columns, e.g. a search's design_evaluations.csv)."""
    min_film: Annotated[float, Quantity("length", gt=0), Plausible(1e-7, 5e-4, _FILM_LIMIT)] = 30e-6
    """Smallest film a design must keep in every scenario (Bureau Veritas' 30 µm, quoted by seed 004)."""
    scenarios: list[ScenarioSection] | None = None
    """Scenarios (default: seed 004's, +20 %/-30 % speed, +50 %/-50 %/+20 % load, +10/+20 degC)."""


class SweepSection(Section):
    """One search per misalignment ratio (seed 004 Sect. 5.2), with the [design] shaft model; on an [alignment]
    case, of the linear shaft (a straight journal) at the film bearing's coupled film force, speed and lubricant."""

    ratios: Annotated[
        list[Annotated[Number, Plausible(-3.0, 3.0, "psi_x of seed 004: 0.1-0.6")]], Field(min_length=1)
    ] = [0.1, 0.2, 0.3, 0.4, 0.5, 0.6]
    """psi_x values (journal tilt over 2c/L); seed 004 Sect. 5.2's by default (`design sweep` on a case without
    [design.sweep] sweeps these too)."""


class DesignSection(Section):
    """A slope-bored bore for the case's bearing, searched for the best film (seed 004 Sect. 4.4-4.5)."""

    segments: Annotated[int, Field(ge=1, le=10)] = 2
    """Slope segments of the bore (1: a single slope, 2: the seed's double slope)."""
    slope_bounds: list[tuple[Annotated[Number, SLOPE_SHARE], Annotated[Number, SLOPE_SHARE]]] | None = None
    """[lower, upper] slope of each segment aft to forward, shares of 2c/L (default: seed 004 Table 4-8 for two
    segments, [0, 0.6] otherwise)."""
    knuckle_bounds: list[tuple[Number, Number]] | None = None
    """[lower, upper] position of each knuckle aft to forward, shares of L (default [0.1, 0.9]; the seed's 0-0.5
    is broken by its own optima)."""
    objectives: Annotated[list[ObjectiveName], Field(min_length=1)] = ["min_film_thickness", "max_pressure"]
    """What to rank by: h_min is maximised, the others minimised (seed 004: h_min and p_max)."""
    shaft: ShaftModel | None = None
    """The journal held during the search: linear (tilted by the bearing's misalignment), bent (seed 004's local
    shaft model, Table 4-5, with the same chord) or coupled (the journal and load of the film bearing in the
    coupled [alignment]); default linear on [bearing], coupled on [alignment]."""
    bearing: str | None = None
    """With [alignment]: the film bearing whose bore is designed (default: the first)."""
    condition: str | None = None
    """With [alignment]: the condition whose coupled solution is the operating point (default: the first)."""
    constraints: list[ConstraintSection] = []
    """Limits a design must meet."""
    search: SearchSection = SearchSection()
    """The search."""
    robustness: RobustnessSection = RobustnessSection()
    """Robustness of the chosen designs."""
    sweep: SweepSection | None = None
    """A search per misalignment ratio; on an [alignment] case, of a straight journal (the linear shaft) at the
    bearing's coupled film force, speed and lubricant."""

    @model_validator(mode="after")
    def _bounds(self) -> DesignSection:
        if self.slope_bounds is not None and len(self.slope_bounds) != self.segments:
            raise field_error("slope_bounds", len(self.slope_bounds), f"{self.segments} [lower, upper] pairs")
        if self.knuckle_bounds is not None and len(self.knuckle_bounds) != self.segments - 1:
            raise field_error("knuckle_bounds", len(self.knuckle_bounds), f"{self.segments - 1} [lower, upper] pairs")
        if self.robustness.designs == "named" and not self.robustness.named:
            raise field_error("robustness.named", [], "at least one design with designs = 'named'")
        for k, design in enumerate(self.robustness.named):
            if len(design.slopes) != self.segments or len(design.knuckles) != self.segments - 1:
                raise field_error(
                    f"robustness.named[{k}].slopes",
                    f"{len(design.slopes)} slopes, {len(design.knuckles)} knuckles",
                    f"{self.segments} slopes and {self.segments - 1} knuckles ([design] segments)",
                )
            knuckles = list(design.knuckles)
            for j, position in enumerate(knuckles):
                # the bore would clip a knuckle to the bearing's ends and sort them: say so instead
                if not 0.0 < position < 1.0 or (j and position < knuckles[j - 1]):
                    raise field_error(
                        f"robustness.named[{k}].knuckles[{j}]",
                        position,
                        "within (0, 1) of the length, aft to forward (not below the previous knuckle)",
                    )
        names = [s.name for s in self.robustness.scenarios or []]
        for k, name in enumerate(names):
            if name in names[:k]:
                raise field_error(f"robustness.scenarios[{k}].name", name, "a name not used by another scenario")
        for k, name in enumerate(self.objectives):
            if name in self.objectives[:k]:
                raise field_error(f"objectives[{k}]", name, "an objective not given twice")
        return self


def build_study(section: DesignSection, context: BuildContext) -> DesignStudy:
    """The design study in SI domain objects, on the base case of the case's ``[bearing]`` or on a
    film bearing of its ``[alignment]``."""
    from shaftline.design.study import DesignStudy

    if "bearing" in context.studies:  # [bearing] first: its base case is the operating point
        base = _designed_from_bearing(section, context)
    else:
        base = _designed_from_alignment(section, context)
    problem = _slope_design_problem(section, base)
    where = "[bearing]" if base.coupled is None else f"the film bearing {base.coupled.bearing!r} of [alignment]"
    scenarios, left_out = _robustness_scenarios(section, context, base.lubricant, base.temperature, where)
    search = section.search
    return DesignStudy(
        problem=problem,
        shaft=base.shaft,
        algorithm=search.algorithm,
        population=search.population,
        generations=search.generations,
        seed=search.seed,
        robust_designs=section.robustness.designs,
        named=tuple((d.name, (*d.slopes, *d.knuckles)) for d in section.robustness.named),
        left_out=tuple(left_out),
        min_film=section.robustness.min_film,
        scenarios=scenarios,
        lubricant=base.lubricant,
        temperature=base.temperature,
        ratios=tuple(section.sweep.ratios) if section.sweep is not None else (),
        store=None if search.store is None else str(context.base_dir / Path(search.store).expanduser()),
        coupled=base.coupled,
    )


@dataclass(frozen=True, eq=False)
class _DesignedBearing:
    """The film whose bore the design searches and what it is searched at.

    Attributes
    ----------
    film : BearingProblem
        The bearing without a bore.
    load_y, load_z : float
        Load on the journal, N (placeholders when ``coupled`` gives it).
    tilt_y, tilt_z : float
        Journal tilts, rad.
    lubricant : Lubricant or None
        The lubricant, for the temperature scenarios.
    temperature : float or None
        Its film temperature, degC, where given.
    shaft : ShaftModel
        The shaft model of the search.
    coupled : CoupledSource or None
        The coupled alignment that gives the load and the journal (an ``[alignment]`` case).
    """

    film: BearingProblem
    load_y: float
    load_z: float
    tilt_y: float
    tilt_z: float
    lubricant: Lubricant | None
    temperature: float | None
    shaft: ShaftModel
    coupled: CoupledSource | None = None


def _designed_from_bearing(section: DesignSection, context: BuildContext) -> _DesignedBearing:
    """The operating point of a ``[bearing]`` case: its base case.

    Raises
    ------
    InputError
        A bore in ``[bearing]``, or a field of ``[design]`` that only an ``[alignment]`` case takes.
    """
    from shaftline.film.problem import BearingProblem

    bearing = context.studies["bearing"].cases[0]
    if bearing.geometry.bore:
        raise InputError("bearing.bore", "given", "", "no bore in [bearing]: [design] searches the bore", in_file=True)
    if section.shaft == "coupled" or section.bearing is not None or section.condition is not None:
        field = "shaft" if section.shaft == "coupled" else ("bearing" if section.bearing else "condition")
        raise InputError(field, getattr(section, field), "", "only with an [alignment] case (no [bearing] table)")
    film = BearingProblem(bearing.geometry, bearing.operating, bearing.options)
    return _DesignedBearing(
        film,
        bearing.load_y,
        bearing.load_z,
        bearing.tilt_y,
        bearing.tilt_z,
        bearing.lubricant,
        bearing.temperature,
        section.shaft or "linear",
    )


def _designed_from_alignment(section: DesignSection, context: BuildContext) -> _DesignedBearing:
    """The operating point of an ``[alignment]`` case: the coupled solution of its film bearing
    ``section.bearing`` (default the first) in ``section.condition`` (default the first).

    Raises
    ------
    InputError
        No such film bearing or condition, a bore on it, or a shaft model other than coupled.
    """
    from shaftline.design.study import CoupledSource

    alignment = context.studies["alignment"]
    names = [f.bearing for f in alignment.films]
    if not names:
        raise InputError(
            "alignment.bearings", "no film bearing", "", "a bearing with a film (film = true or a film table)",
            in_file=True,
        )  # fmt: skip
    name = section.bearing or names[0]
    if name not in names:
        raise InputError("bearing", name, "", "a film bearing of [alignment]: " + ", ".join(names))
    conditions = [c.name for c in alignment.line.all_conditions()]
    if section.condition is not None and section.condition not in conditions:
        raise InputError("condition", section.condition, "", "a condition of [alignment]: " + ", ".join(conditions))
    index = names.index(name)
    support = alignment.films[index]
    if support.problem.geometry.bore:
        raise InputError(
            "alignment.bearings.film.bore", "given", "", f"no bore on {name}: [design] searches it", in_file=True
        )
    film = support.problem
    lubricant, temperature = alignment.film_lubricants[index] if alignment.film_lubricants else (None, None)
    shaft = section.shaft or "coupled"
    condition = next(c for c in alignment.line.all_conditions() if c.name == (section.condition or conditions[0]))
    coupled = CoupledSource(alignment.line, alignment.films, alignment.coupling, condition, name)
    if shaft != "coupled":
        raise InputError("shaft", shaft, "", "coupled with an [alignment] case (its journal is the coupled one)")
    # [design.sweep] here sweeps the linear shaft at the coupled operating point (DesignStudy.sweep_at)
    # the load and the journal come from the coupled solution when the study is solved
    return _DesignedBearing(film, -1.0, 0.0, 0.0, 0.0, lubricant, temperature, shaft, coupled)


def _slope_design_problem(section: DesignSection, base: _DesignedBearing) -> SlopeDesignProblem:
    """The search's problem: the bore's parametrisation, objectives and constraints of
    ``section`` on the film and operating point ``base`` (errors placed under ``[design]``)."""
    from shaftline.design.bore import SlopeParametrisation
    from shaftline.design.problem import Constraint, SlopeDesignProblem

    with located(""):
        parametrisation = SlopeParametrisation(
            section.segments,
            tuple(tuple(b) for b in section.slope_bounds) if section.slope_bounds is not None else None,  # type: ignore[misc]
            tuple(tuple(b) for b in section.knuckle_bounds) if section.knuckle_bounds is not None else None,  # type: ignore[misc]
        )
    constraints = []
    for k, c in enumerate(section.constraints):
        with located(f"constraints[{k}]"):
            constraints.append(Constraint(c.quantity, c.comparison, c.limit))
    return SlopeDesignProblem(
        base.film,
        load_y=base.load_y,
        load_z=base.load_z,
        tilt_y=base.tilt_y,
        tilt_z=base.tilt_z,
        parametrisation=parametrisation,
        objectives=tuple(section.objectives),
        constraints=tuple(constraints),
    )


def _robustness_scenarios(
    section: DesignSection,
    context: BuildContext,
    lubricant: Lubricant | None,
    temperature: float | None,
    where: str,
) -> tuple[tuple[Scenario, ...], list[tuple[str, str]]]:
    """The robustness scenarios (the seed's by default) and (name, reason) of the defaults left
    out; ``temperature``: the film temperature of ``lubricant``, degC; ``where``: the table of
    the lubricant, for the messages. A default left out is a warning in ``context``.

    Raises
    ------
    InputError
        A listed temperature scenario the lubricant cannot take.
    """
    from shaftline.design.robustness import SEED_SCENARIOS, VALID_TEMPERATURES, Scenario, outside_range

    why = _fixed_viscosity(lubricant, temperature, where)
    if section.robustness.scenarios is None:
        scenarios, left_out = _default_scenarios(SEED_SCENARIOS, lubricant, temperature, why)
        if left_out and section.robustness.designs != "none":
            dropped = " and ".join(name for name, _ in left_out)
            reasons = "; ".join(dict.fromkeys(reason for _, reason in left_out))
            several = len(left_out) > 1
            context.warnings.append(
                f"[design.robustness]: the seed's default scenario{'s' if several else ''} {dropped} "
                f"{'were' if several else 'was'} left out ({reasons}); to have {'them' if several else 'it'}, give "
                "the lubricant as a preset or a two-point oil at its temperature, or list the scenarios in "
                "[[design.robustness.scenarios]]."
            )
        return scenarios, left_out
    scenarios = tuple(
        Scenario(s.name, s.speed_factor, s.load_factor, s.temperature_change) for s in section.robustness.scenarios
    )
    for k, scenario in enumerate(scenarios):
        if not scenario.temperature_change or section.robustness.designs == "none":
            continue
        field = f"robustness.scenarios[{k}].temperature_change"
        if why:
            raise InputError(
                field,
                scenario.temperature_change,
                "K",
                f"0 here: {why} (give the lubricant as a preset or a two-point oil at its temperature for a "
                "temperature scenario)",
            )
        assert lubricant is not None and temperature is not None
        low, high = VALID_TEMPERATURES[lubricant.model]
        change = scenario.temperature_change
        if not low <= temperature + change <= high:  # told now, not after the search
            raise InputError(field, change, "K", outside_range(lubricant, temperature, change))
    return scenarios, []


def _fixed_viscosity(lubricant: Lubricant | None, temperature: float | None, where: str) -> str:
    """Why the lubricant of ``where`` cannot take a temperature scenario ("" when it can)."""
    if lubricant is None or temperature is None or lubricant.model == "constant":
        return f"the lubricant of {where} is a constant viscosity, which does not follow temperature"
    return ""


def _default_scenarios(
    scenarios: tuple[Scenario, ...], lubricant: Lubricant | None, temperature: float | None, why: str
) -> tuple[tuple[Scenario, ...], list[tuple[str, str]]]:
    """The default scenarios this lubricant can take, and (name, reason) of those left out: the
    temperature scenarios of a constant viscosity, or those that take the oil outside the range of
    its viscosity model."""
    from shaftline.design.robustness import VALID_TEMPERATURES

    kept, left_out = [], []
    for scenario in scenarios:
        reason = ""
        if scenario.temperature_change and why:
            reason = why
        elif scenario.temperature_change and lubricant is not None and temperature is not None:
            low, high = VALID_TEMPERATURES[lubricant.model]
            hot = temperature + scenario.temperature_change
            if not low <= hot <= high:
                reason = (
                    f"{temperature:g} + {scenario.temperature_change:g} = {hot:g} degC is outside the {low:g} to "
                    f"{high:g} degC where the viscosity of {lubricant.name} is known"
                )
        if reason:
            left_out.append((scenario.name, reason))
        else:
            kept.append(scenario)
    return tuple(kept), left_out
