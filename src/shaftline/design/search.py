"""The multi-objective search for a bore: a pymoo algorithm, batches of designs through
:func:`shaftline.parallel.map`, every evaluation kept, the non-dominated set and its knee.

Seed 004 used MATLAB's ``gamultiobj`` (a controlled-elitist NSGA-II) with 40 generations of 40
designs (Sect. 4.5.5) and sorted the dominant designs by hand in a spreadsheet. Here pymoo's
NSGA-II is the default (Deb et al. 2002; Blank & Deb 2020, pymoo), driven by its ask-and-tell
interface so that each generation is one batch for a process pool or a Dask cluster; the
non-dominated set is pymoo's non-dominated sorting of the feasible designs, and the knee is
pymoo's high trade-off point where it finds one, else the design of the front farthest from
the line through its extremes (normalised objectives; Das 1999).

A fixed ``seed`` gives the same designs in the same order on every backend: an evaluation is
a pure function of its design. With a ``store`` folder every evaluation is written after each
generation (``evaluations.parquet`` and ``evaluations.csv``, replaced atomically); a search
started again on the same folder with the same settings takes the designs it already has from
it instead of solving them, so an interrupted run resumes where it stopped.
"""

from __future__ import annotations

import json
import math
import os
import time
from collections.abc import Callable
from dataclasses import dataclass
from functools import partial
from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np

from shaftline import parallel
from shaftline.design.problem import OBJECTIVES, DesignEvaluation, SlopeDesignProblem, evaluate_design
from shaftline.errors import InputError

if TYPE_CHECKING:
    from distributed import Client

__all__ = ["ALGORITHMS", "SearchProgress", "SearchResult", "knee_point", "non_dominated", "search"]


def _nsga2(population: int) -> Any:
    from pymoo.algorithms.moo.nsga2 import NSGA2

    return NSGA2(pop_size=population)


def _spea2(population: int) -> Any:
    from pymoo.algorithms.moo.spea2 import SPEA2

    return SPEA2(pop_size=population)


def _smsemoa(population: int) -> Any:
    from pymoo.algorithms.moo.sms import SMSEMOA

    return SMSEMOA(pop_size=population)


def _agemoea(population: int) -> Any:
    from pymoo.algorithms.moo.age import AGEMOEA

    return AGEMOEA(pop_size=population)


#: pymoo algorithms by name (``algorithm=`` of :func:`search`): ``factory(population)``.
ALGORITHMS: dict[str, Callable[[int], Any]] = {
    "nsga2": _nsga2,
    "spea2": _spea2,
    "smsemoa": _smsemoa,
    "agemoea": _agemoea,
}

#: What a store folder records of the search that wrote it (a resumed search must match it).
_SETTINGS_FILE = "search.json"


@dataclass(frozen=True)
class SearchProgress:
    """What a search tells its ``progress`` callback after each generation."""

    generation: int
    generations: int
    evaluations: int
    best_min_film: float  # m, the largest h_min of an acceptable design so far (NaN: none)
    elapsed: float  # s
    remaining: float  # s, estimated from the mean time per generation


@dataclass(frozen=True, eq=False)
class SearchResult:
    """Every design a search evaluated, its non-dominated set and knee.

    Attributes
    ----------
    problem : SlopeDesignProblem
    evaluations : list of DesignEvaluation
        In the order they were proposed.
    generation : ndarray of int
        The generation of each evaluation (0 the initial population).
    pareto : ndarray of int
        Indices into ``evaluations`` of the non-dominated feasible designs, by the first objective.
    knee : int or None
        Index of the knee design of the front (None with fewer than three designs on it).
    algorithm : str
    seed : int
    completed : bool
        False when the run was stopped early (the evaluations so far are kept).
    """

    problem: SlopeDesignProblem
    evaluations: list[DesignEvaluation]
    generation: np.ndarray
    pareto: np.ndarray
    knee: int | None
    algorithm: str
    seed: int
    completed: bool

    def table(self) -> Any:
        """The evaluations as a pandas DataFrame: generation, variables, quantities, status,
        and whether each is on the front or the knee."""
        import pandas as pd

        names = self.problem.parametrisation.names
        frame = pd.DataFrame([e.record(names) for e in self.evaluations])
        frame.insert(0, "generation", self.generation)
        frame["pareto"] = False
        frame.loc[self.pareto, "pareto"] = True
        frame["knee"] = False
        if self.knee is not None:
            frame.loc[self.knee, "knee"] = True
        return frame


def non_dominated(objectives: np.ndarray) -> np.ndarray:
    """Indices of the non-dominated rows of ``objectives`` (minimisation), pymoo's sorting."""
    from pymoo.util.nds.non_dominated_sorting import NonDominatedSorting

    if objectives.shape[0] == 0:
        return np.zeros(0, dtype=int)
    return np.asarray(NonDominatedSorting().do(objectives, only_non_dominated_front=True), dtype=int)


def knee_point(front: np.ndarray) -> int | None:
    """Index (into ``front``, minimisation form) of the knee of a non-dominated set.

    pymoo's high trade-off point (Rachmawati & Srinivasan 2009) where it finds one; otherwise,
    and for two objectives always as a check, the point farthest from the hyperplane through
    the extreme points of the normalised front (Das 1999). None for fewer than three points.
    """
    n = front.shape[0]
    if n < 3:
        return None
    low, high = front.min(axis=0), front.max(axis=0)
    span = np.where(high > low, high - low, 1.0)
    normal = (front - low) / span
    m = front.shape[1]
    if m == 2:
        # distance below the line from (0, 1) to (1, 0) in the normalised plane
        distance = 1.0 - normal.sum(axis=1)
        return int(np.argmax(distance))
    from pymoo.mcdm.high_tradeoff import HighTradeoffPoints

    found = HighTradeoffPoints().do(normal)
    if found is not None and np.size(found):
        return int(np.atleast_1d(found)[0])
    return int(np.argmin(normal.sum(axis=1)))


def _settings(problem: SlopeDesignProblem, algorithm: str, population: int, seed: int) -> dict[str, Any]:
    return {
        "algorithm": algorithm,
        "population": population,
        "seed": seed,
        "variables": problem.parametrisation.names,
        "lower": problem.parametrisation.lower.tolist(),
        "upper": problem.parametrisation.upper.tolist(),
        "objectives": list(problem.objectives),
        "constraints": [[c.quantity, c.comparison, c.limit] for c in problem.constraints],
        "load": [problem.load_y, problem.load_z],
        "tilt": [problem.tilt_y, problem.tilt_z],
        "film": repr(problem.film),
    }


class _Store:
    """The folder of one search: its settings and every evaluation so far."""

    def __init__(self, folder: Path, settings: dict[str, Any], names: list[str]) -> None:
        self.folder = folder
        self.names = names
        self.known: dict[bytes, DesignEvaluation] = {}
        folder.mkdir(parents=True, exist_ok=True)
        path = folder / _SETTINGS_FILE
        if path.exists():
            found = json.loads(path.read_text())
            if found != json.loads(json.dumps(settings)):
                changed = sorted(k for k in settings if found.get(k) != json.loads(json.dumps(settings[k])))
                raise InputError(
                    "store",
                    str(folder),
                    "",
                    "a new folder, or the folder of the same search to resume it (this one differs in "
                    + ", ".join(changed)
                    + ")",
                )
            self._load()
        else:
            path.write_text(json.dumps(settings, indent=1))

    def _load(self) -> None:
        import pandas as pd

        table = self.folder / "evaluations.parquet"
        if not table.exists():
            return
        frame = pd.read_parquet(table)
        for row in frame.to_dict("records"):
            x = np.array([row[name] for name in self.names], dtype=float)
            values = {
                name: float(row[name])
                for name in [*OBJECTIVES, "eccentricity_ratio", "attitude_angle", "load_centre_offset"]
            }
            self.known[x.tobytes()] = DesignEvaluation(x, values, str(row["status"]), int(row["iterations"]))

    def write(self, result: SearchResult) -> None:
        frame = result.table()
        for name, write in (("evaluations.parquet", frame.to_parquet), ("evaluations.csv", frame.to_csv)):
            partial_path = self.folder / (name + ".partial")
            write(partial_path, index=False)
            os.replace(partial_path, self.folder / name)


def search(
    problem: SlopeDesignProblem,
    algorithm: str = "nsga2",
    population: int = 40,
    generations: int = 40,
    seed: int = 1,
    *,
    backend: str | None = None,
    workers: int | None = None,
    scheduler: str | Client | None = None,
    store: str | os.PathLike[str] | None = None,
    progress: Callable[[SearchProgress], None] | None = None,
) -> SearchResult:
    """Search the bores of ``problem`` with a pymoo algorithm.

    Parameters
    ----------
    problem : SlopeDesignProblem
    algorithm : str
        A key of :data:`ALGORITHMS` (default NSGA-II, as the seed's gamultiobj).
    population, generations : int
        Designs per generation and generations (the seed: 40 and 40, 1600 evaluations).
    seed : int
        Random seed: the same seed gives the same designs on every backend.
    backend, workers, scheduler
        Where the designs of a generation are evaluated (:func:`shaftline.parallel.map`; ``scheduler`` a
        scheduler's address or the caller's ``dask.distributed.Client``).
    store : path, optional
        Folder for ``evaluations.parquet``/``.csv`` (written after each generation) and the
        search's settings; an existing folder of the same search resumes it.
    progress : callable, optional
        Called with a :class:`SearchProgress` after each generation.

    Returns
    -------
    SearchResult
        Also when interrupted (Ctrl-C): the evaluations so far are kept, in the store too,
        and the interruption is raised again after the store is written.

    Raises
    ------
    InputError
        ``"algorithm"`` unknown, ``"population"`` below 4, ``"generations"`` below 1,
        ``"store"`` a folder of another search.
    """
    _check_search(algorithm, population, generations)
    names = problem.parametrisation.names
    saved = None if store is None else _Store(Path(store), _settings(problem, algorithm, population, seed), names)
    pymoo_problem, engine = _pymoo_search(problem, algorithm, population, generations, seed)
    evaluations: list[DesignEvaluation] = []
    generation_of: list[int] = []
    start = time.perf_counter()
    evaluate = partial(evaluate_design, problem)
    completed = False
    generation = 0
    # One pool for the whole search: the workers keep their bearings and factorisations.
    pool = parallel.Pool(backend=backend, workers=workers, scheduler=scheduler)
    try:
        while engine.has_next():
            offspring = engine.ask()
            designs = np.asarray(offspring.get("X"), dtype=float)
            known = saved.known if saved is not None else {}
            batch = _evaluate_generation(designs, known, pool, evaluate)
            _tell(engine, pymoo_problem, problem, offspring, batch)
            evaluations.extend(batch)
            generation_of.extend([generation] * len(batch))
            generation += 1
            if saved is not None:
                saved.write(_result(problem, evaluations, generation_of, algorithm, seed, False))
            if progress is not None:
                progress(_search_progress(evaluations, generation, generations, start))
        completed = True
    finally:
        pool.close()
        result = _result(problem, evaluations, generation_of, algorithm, seed, completed)
        if saved is not None and evaluations:
            saved.write(result)
    return result


def _check_search(algorithm: str, population: int, generations: int) -> None:
    """Refuse an unknown ``algorithm``, a ``population`` below 4 or ``generations`` below 1.

    Raises
    ------
    InputError
        Naming the argument.
    """
    if algorithm not in ALGORITHMS:
        raise InputError("algorithm", algorithm, "", "one of " + ", ".join(ALGORITHMS))
    for name, value, least in (("population", population, 4), ("generations", generations, 1)):
        if isinstance(value, bool) or not isinstance(value, int) or value < least:
            raise InputError(name, value, "", f"an integer >= {least}")


def _pymoo_search(
    problem: SlopeDesignProblem, algorithm: str, population: int, generations: int, seed: int
) -> tuple[Any, Any]:
    """The pymoo problem of ``problem``'s bore variables, objectives and constraints (the
    first constraint: the film's own), and the ``algorithm`` set up on it to be asked and told."""
    from pymoo.core.problem import Problem

    parametrisation = problem.parametrisation
    n_constraints = 1 + len(problem.constraints)
    pymoo_problem = Problem(
        n_var=parametrisation.variables,
        n_obj=len(problem.objectives),
        n_ieq_constr=n_constraints,
        xl=parametrisation.lower,
        xu=parametrisation.upper,
    )
    engine = ALGORITHMS[algorithm](population)
    engine.setup(pymoo_problem, termination=("n_gen", generations), seed=seed, verbose=False)
    return pymoo_problem, engine


def _evaluate_generation(
    designs: np.ndarray,
    known: dict[bytes, DesignEvaluation],
    pool: parallel.Pool,
    evaluate: Callable[[np.ndarray], DesignEvaluation],
) -> list[DesignEvaluation]:
    """The evaluations of a generation's ``designs`` (one per row), in their order: those
    ``known`` from a resumed store as stored, the others evaluated on ``pool``."""
    todo = [x for x in designs if x.tobytes() not in known]
    chunk = max(1, math.ceil(len(todo) / (2 * parallel.available_workers()))) if todo else 1
    fresh = iter(pool.map(evaluate, todo, chunksize=chunk))
    return [known[x.tobytes()] if x.tobytes() in known else next(fresh) for x in designs]


def _tell(
    engine: Any, pymoo_problem: Any, problem: SlopeDesignProblem, offspring: Any, batch: list[DesignEvaluation]
) -> None:
    """Tell ``engine`` the objectives and constraint violations of its ``offspring``,
    evaluated as ``batch``."""
    from pymoo.core.evaluator import Evaluator
    from pymoo.problems.static import StaticProblem

    objectives = np.array([problem.minimised(e) for e in batch])
    # pymoo needs finite objectives: a failed design gets the worst seen, and is infeasible.
    objectives = _finite(objectives)
    violations = np.array([problem.violations(e) for e in batch])
    Evaluator().eval(StaticProblem(pymoo_problem, F=objectives, G=violations), offspring)
    engine.tell(infills=offspring)


def _search_progress(
    evaluations: list[DesignEvaluation], generation: int, generations: int, start: float
) -> SearchProgress:
    """Where the search is after ``generation`` of ``generations``, begun at ``start``
    (:func:`time.perf_counter`, s): evaluations, the best feasible h_min (m) and the time
    taken and left, s."""
    elapsed = time.perf_counter() - start
    feasible = [e.values["min_film_thickness"] for e in evaluations if e.ok]
    return SearchProgress(
        generation,
        generations,
        len(evaluations),
        max(feasible) if feasible else math.nan,
        elapsed,
        elapsed / generation * (generations - generation),
    )


def _finite(objectives: np.ndarray) -> np.ndarray:
    out = objectives.copy()
    for column in range(out.shape[1]):
        values = out[:, column]
        good = np.isfinite(values)
        worst = values[good].max() if good.any() else 0.0
        values[~good] = worst + abs(worst) + 1.0
    return out


def _first_of_each_row(rows: np.ndarray) -> np.ndarray:
    """Index of the first of each distinct row of ``rows`` (n, k), in lexicographic order of
    the rows: ``np.unique(rows, axis=0, return_index=True)[1]`` without its structured-array
    view, whose comparison turns a Ctrl-C arriving inside it into a TypeError (numpy
    converts any error of its common-dtype lookup), which lost a user's Ctrl-C message."""
    order = np.lexsort(rows.T[::-1])  # stable: the first of equal rows comes first
    ordered = rows[order]
    first = np.ones(order.size, dtype=bool)
    first[1:] = np.any(ordered[1:] != ordered[:-1], axis=1)
    return order[first]


def _result(
    problem: SlopeDesignProblem,
    evaluations: list[DesignEvaluation],
    generation_of: list[int],
    algorithm: str,
    seed: int,
    completed: bool,
) -> SearchResult:
    feasible = np.array(
        [i for i, e in enumerate(evaluations) if e.ok and np.all(problem.violations(e) <= 0.0)], dtype=int
    )
    pareto = np.zeros(0, dtype=int)
    knee = None
    if feasible.size:
        objectives = np.array([problem.minimised(evaluations[i]) for i in feasible], dtype=float)
        # one design per distinct objective vector: a re-proposed design is not two points
        unique = _first_of_each_row(objectives)
        front = unique[non_dominated(objectives[unique])]
        front = front[np.argsort(objectives[front, 0], kind="stable")]
        pareto = feasible[front]
        k = knee_point(objectives[front])
        knee = None if k is None else int(pareto[k])
    return SearchResult(
        problem, list(evaluations), np.array(generation_of, dtype=int), pareto, knee, algorithm, seed, completed
    )
