"""A slope-boring design study: the search, the robustness of the chosen designs and the
misalignment sweep, as ``[design]`` in a case file asks (notebooks can build one directly).
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass, field, replace
from typing import TYPE_CHECKING, Literal

import numpy as np

from shaftline.design.problem import SlopeDesignProblem, film_state
from shaftline.design.robustness import RobustnessResult, Scenario, robustness
from shaftline.design.search import SearchProgress, SearchResult, search
from shaftline.design.sweep import DEFAULT_RATIOS, SweepResult, misalignment_sweep
from shaftline.errors import Interrupted, interrupted_by_user, located
from shaftline.film.bearing import BearingState
from shaftline.film.geometry import BentJournal, BoreSegment
from shaftline.lubricants import Lubricant
from shaftline.registry import Progress, Tally
from shaftline.shaft.film_supports import CoupledResult, CouplingOptions, FilmSupport
from shaftline.shaft.model import Condition, ShaftLine

if TYPE_CHECKING:
    from distributed import Client

__all__ = ["TASKS", "CoupledSource", "DesignResult", "DesignStudy", "solve_design"]

#: What a run does: the search (with the robustness of its chosen designs and the sweep, when
#: asked), or only one of the three.
TASKS = ("all", "slopes", "robustness", "sweep")


@dataclass(frozen=True, eq=False)
class CoupledSource:
    """The coupled alignment whose film bearing ``bearing`` gives the operating point: its load
    (the film force) and its journal (the coupled centre line) in ``condition``."""

    line: ShaftLine
    films: tuple[FilmSupport, ...]
    options: CouplingOptions
    condition: Condition
    bearing: str

    def problem(self, base: SlopeDesignProblem) -> tuple[SlopeDesignProblem, CoupledResult]:
        """``base`` with the load and the journal of the coupled solution (and that solution)."""
        from shaftline.shaft.coupled import CoupledAlignment

        result = CoupledAlignment(self.line, self.films, self.options).solve(self.condition)
        film = result.film(self.bearing)
        g = base.film.geometry
        z = film.z
        arm = z - 0.5 * g.length
        mid_y = float(np.interp(0.5 * g.length, z, film.centre_y))
        mid_z = float(np.interp(0.5 * g.length, z, film.centre_z))
        tilt_y = float(film.centre_y[-1] - film.centre_y[0]) / g.length
        tilt_z = float(film.centre_z[-1] - film.centre_z[0]) / g.length
        bent = BentJournal(z=z, dy=film.centre_y - mid_y - tilt_y * arm, dz=film.centre_z - mid_z - tilt_z * arm)
        geometry = replace(g, bent_journal=bent)
        problem = replace(
            base,
            film=replace(base.film, geometry=geometry),
            load_y=-film.force_y,
            load_z=-film.force_z,
            tilt_y=tilt_y,
            tilt_z=tilt_z,
        )
        return problem, result


@dataclass(frozen=True, eq=False)
class DesignStudy:
    """A design problem and what to do with it.

    Attributes
    ----------
    problem : SlopeDesignProblem
        At the case's operating point, with the linear shaft's tilt.
    shaft : "linear" or "bent"
        The journal: the problem's tilt, or seed 004's local shaft model with the same chord.
    algorithm, population, generations, seed
        The search (:func:`shaftline.design.search.search`).
    robust_designs : "knee", "pareto", "named" or "none"
    named : tuple of (str, tuple of float)
        The named designs (label, variables) of ``robust_designs = "named"``.
    min_film : float
        The h_min limit of the robustness verdict, m.
    scenarios : tuple of Scenario
    lubricant, temperature
        The case's lubricant and film temperature (degC), for temperature scenarios.
    ratios : tuple of float
        psi_x of the misalignment sweep (empty: none, but the ``"sweep"`` task then sweeps the
        seed's 0.1 ... 0.6).
    store : str or None
        Folder that keeps every evaluation of the search (and resumes it); the sweep's searches
        go into its sub-folders.
    coupled : CoupledSource or None
        With ``shaft = "coupled"``: the alignment whose coupled solution is the operating point
        (the problem's load and tilt are then replaced by it when solved).
    left_out : tuple of (str, str)
        The default scenarios left out of ``scenarios`` and why (a lubricant of constant
        viscosity has no temperature scenarios; the case's warnings say so too).
    """

    problem: SlopeDesignProblem
    shaft: Literal["linear", "bent", "coupled"]
    algorithm: str
    population: int
    generations: int
    seed: int
    robust_designs: Literal["knee", "pareto", "named", "none"]
    min_film: float
    scenarios: tuple[Scenario, ...]
    lubricant: Lubricant | None
    temperature: float | None
    ratios: tuple[float, ...] = ()
    store: str | None = None
    coupled: CoupledSource | None = None
    named: tuple[tuple[str, tuple[float, ...]], ...] = ()
    left_out: tuple[tuple[str, str], ...] = ()

    @property
    def misalignment_ratio(self) -> float:
        """psi_x of the case: the journal tilt over 2c/L."""
        g = self.problem.film.geometry
        return self.problem.tilt_y * g.length / (2.0 * g.radial_clearance)

    def sweep_at(self, problem: SlopeDesignProblem) -> Callable[[float], SlopeDesignProblem]:
        """``psi_x -> problem`` of the misalignment sweep, from the operating point ``problem``.

        On a ``[bearing]`` case, the study's shaft model (:meth:`problem_at`). On the coupled
        alignment the linear shaft at the coupled operating point: the journal straight (the
        coupled bend left out), its vertical tilt psi_x 2c/L, its horizontal tilt and the load
        (the film force), speed and lubricant the coupled solution's (docs/theory.md §14).
        """
        if self.coupled is None:
            return self.problem_at()
        from shaftline.design.sweep import linear_shaft

        g = problem.film.geometry
        straight = replace(problem, film=replace(problem.film, geometry=replace(g, bent_journal=None)))
        return linear_shaft(straight)

    def problem_at(self) -> Callable[[float], SlopeDesignProblem]:
        """``psi_x -> problem`` with the study's shaft model."""
        from shaftline.design.shaft_models import bent_shaft, linear_shaft
        from shaftline.shaft.local import seed004_local_model

        if self.shaft == "bent":
            model = replace(seed004_local_model(), bearing_length=self.problem.film.geometry.length)
            return bent_shaft(self.problem, model)
        return linear_shaft(self.problem)


@dataclass(frozen=True, eq=False)
class DesignResult:
    """What a design study found.

    Attributes
    ----------
    study : DesignStudy
    problem : SlopeDesignProblem
        The problem searched (with the shaft model's journal).
    search : SearchResult or None
    robustness : RobustnessResult or None
    sweep : SweepResult or None
    profiles : dict
        The film (:class:`BearingState`) of the knee beside the bore with no slope and the single
        slope psi_x, by label, for the comparison along the bearing.
    alignment : CoupledResult or None
        The coupled solution that gave the operating point (``shaft = "coupled"``).
    """

    study: DesignStudy
    problem: SlopeDesignProblem
    search: SearchResult | None
    robustness: RobustnessResult | None
    sweep: SweepResult | None
    profiles: dict[str, BearingState] = field(default_factory=dict)
    alignment: CoupledResult | None = None


def solve_design(
    study: DesignStudy,
    progress: Progress | None = None,
    task: str = "all",
    workers: int | None = None,
    scheduler: str | Client | None = None,
) -> DesignResult:
    """Run the search, the robustness of its chosen designs and the sweep (``task="all"``), or one.

    ``"robustness"`` of the knee or the front runs the search first as ``"all"`` does, without the
    sweep; of named designs (``robust_designs = "named"``) it runs no search. ``"sweep"`` runs only
    the sweep. ``progress`` is told each step, and a :class:`~shaftline.registry.Tally` of the
    evaluations of the search, the sweep and the robustness (the command line's bar). Ctrl-C during
    a search raises :class:`~shaftline.errors.Interrupted`, whose note says where its evaluations
    are kept (``store``) and how to resume, or how to keep them next time.
    """
    if task not in TASKS:
        raise ValueError(f"task {task!r}: one of {TASKS}")
    searches = task in ("all", "slopes", "sweep") or (task == "robustness" and study.robust_designs != "named")
    try:
        return _solve(study, progress, task, workers, scheduler)
    except (KeyboardInterrupt, SystemError) as stop:
        # Ctrl-C inside a compiled (numba) call arrives as a SystemError caused by it
        if isinstance(stop, Interrupted) or not searches or not interrupted_by_user(stop):
            raise
        if study.store is not None:
            note = (
                f"the designs evaluated so far are kept in {study.store}: run the same command again "
                "(the same case and search) to resume from them"
            )
        else:
            note = (
                "the designs evaluated so far were not kept: set [design.search] store = DIR in the case (or give "
                "design slopes --store DIR) to keep them as the search goes and to resume it"
            )
        raise Interrupted(note) from None


def _solve(
    study: DesignStudy, progress: Progress | None, task: str, workers: int | None, scheduler: str | Client | None
) -> DesignResult:
    step: Progress = progress or (lambda _: None)
    alignment = None
    if study.shaft == "coupled" and study.coupled is not None:
        step("coupled alignment: the operating point of the film bearing")
        problem, alignment = study.coupled.problem(study.problem)
    else:
        problem = study.problem_at()(study.misalignment_ratio)
    found = tuned = swept = None
    named = study.robust_designs == "named"
    if task in ("all", "slopes") or (task == "robustness" and not named):
        found = _search(study, problem, step, workers, scheduler)
    designs, names = _robustness_designs(study, problem, found)
    if task in ("all", "robustness") and names:
        tuned = _robustness(study, problem, designs, names, step, workers, scheduler)
    # `design sweep` on a case without [design.sweep]: the seed's psi_x 0.1 ... 0.6
    ratios = study.ratios or (DEFAULT_RATIOS if task == "sweep" else ())
    if ratios and task in ("all", "sweep"):
        swept = _sweep(study, problem, ratios, step, workers, scheduler)
    profiles: dict[str, BearingState] = {}
    if found is not None and found.knee is not None:
        step("films of the knee, no slope and the single slope")
        profiles = _knee_profiles(study, problem, found.evaluations[found.knee].x)
    return DesignResult(study, problem, found, tuned, swept, profiles, alignment)


def _search(
    study: DesignStudy,
    problem: SlopeDesignProblem,
    step: Progress,
    workers: int | None,
    scheduler: str | Client | None,
) -> SearchResult:
    """The study's search of ``problem``, its generations told to ``step`` as a tally."""

    def generation(state: SearchProgress) -> None:
        step(
            Tally(
                "design search",
                state.evaluations,
                study.population * study.generations,
                "evaluations",
                f"generation {state.generation}/{state.generations}, {_best(state)}",
            )
        )

    with located("search"):
        return search(
            problem,
            study.algorithm,
            study.population,
            study.generations,
            study.seed,
            progress=generation,
            workers=workers,
            scheduler=scheduler,
            store=study.store,
        )


def _robustness_designs(
    study: DesignStudy, problem: SlopeDesignProblem, found: SearchResult | None
) -> tuple[np.ndarray, list[str]]:
    """The designs whose robustness the study asks for, one per row of the bore variables,
    and their labels: the named ones, or the knee or the front of ``found``; none without."""
    designs, names = np.zeros((0, problem.parametrisation.variables)), []
    if study.robust_designs == "named":
        designs = np.array([x for _, x in study.named], dtype=float)
        names = [name for name, _ in study.named]
    elif found is not None and study.robust_designs != "none":
        chosen = _chosen(found, study.robust_designs)
        designs = np.array([found.evaluations[i].x for i in chosen]).reshape(-1, problem.parametrisation.variables)
        names = [("knee" if i == found.knee else f"front {k + 1}") for k, i in enumerate(chosen)]
    return designs, names


def _robustness(
    study: DesignStudy,
    problem: SlopeDesignProblem,
    designs: np.ndarray,
    names: list[str],
    step: Progress,
    workers: int | None,
    scheduler: str | Client | None,
) -> RobustnessResult:
    """The ``designs`` (labelled ``names``) in the study's scenarios, the evaluations told to
    ``step`` as a tally."""
    step(f"robustness of {len(names)} design(s) in {len(study.scenarios)} scenarios")
    scenarios = f"{len(names)} design(s) × {len(study.scenarios)} scenarios and the operating point"

    def solved(done: int, total: int) -> None:
        step(Tally("robustness", done, total, "evaluations", scenarios))

    with located("robustness"):
        return robustness(
            problem,
            designs,
            names=names,
            scenarios=study.scenarios,
            lubricant=study.lubricant,
            temperature=study.temperature,
            limit=study.min_film,
            workers=workers,
            scheduler=scheduler,
            progress=solved,
        )


def _sweep(
    study: DesignStudy,
    problem: SlopeDesignProblem,
    ratios: tuple[float, ...],
    step: Progress,
    workers: int | None,
    scheduler: str | Client | None,
) -> SweepResult:
    """One search per misalignment ratio psi_x of ``ratios`` at the operating point of
    ``problem``, the evaluations of all told to ``step`` as one tally."""
    each = study.population * study.generations

    def told(ratio: float, state: SearchProgress) -> None:
        k = ratios.index(ratio)
        step(
            Tally(
                "misalignment sweep",
                k * each + state.evaluations,
                len(ratios) * each,
                "evaluations",
                f"psi_x {ratio:g} ({k + 1} of {len(ratios)}), generation {state.generation}/"
                f"{state.generations}, {_best(state)}",
            )
        )

    return misalignment_sweep(
        study.sweep_at(problem),
        ratios,
        progress=told,
        algorithm=study.algorithm,
        population=study.population,
        generations=study.generations,
        seed=study.seed,
        workers=workers,
        scheduler=scheduler,
        store=None if study.store is None else f"{study.store}/sweep",
    )


def _knee_profiles(study: DesignStudy, problem: SlopeDesignProblem, knee: np.ndarray) -> dict[str, BearingState]:
    """The films of the bore with no slope, the single slope psi_x, the ``knee`` design (its
    bore variables) and the study's named designs, by label (those the film solves)."""
    g = problem.film.geometry
    ratio = problem.tilt_y * g.length / (2.0 * g.radial_clearance)
    bores = {
        "no slope": (),
        f"single slope {ratio:.3g}": (BoreSegment(1.0, ratio * 2.0 * g.radial_clearance / g.length),),
        "knee": problem.parametrisation.bore(knee, g.length, g.radial_clearance),
    }
    for name, x in study.named:  # e.g. the seed's own design, marked beside the front
        bores[name] = problem.parametrisation.bore(np.asarray(x, dtype=float), g.length, g.radial_clearance)
    profiles: dict[str, BearingState] = {}
    for label, bore in bores.items():
        state = film_state(problem, bore)
        if state is not None:
            profiles[label] = state
    return profiles


def _best(state: SearchProgress) -> str:
    """The best h_min of a search so far, for its progress bar."""
    if not math.isfinite(state.best_min_film):
        return "no acceptable design yet"
    return f"best h_min {state.best_min_film * 1e6:.1f} µm"


def _chosen(found: SearchResult, which: str) -> np.ndarray:
    if which == "pareto":
        return found.pareto
    return np.array([found.knee], dtype=int) if found.knee is not None else found.pareto[:1]
