"""One slope-boring design problem and the evaluation of one design.

A design is a bore (:class:`~shaftline.design.bore.SlopeParametrisation`); its evaluation is
the film at equilibrium under the fixed operating point (seed 004 holds the Sommerfeld number
constant during a search, Sect. 4.5.1: load, speed, viscosity and the journal's misalignment,
linear or bent, do not change). Every evaluation reports all the quantities a designer ranks by,
whichever are objectives: h_min, p_max, friction power, side leakage and the support point's
distance from L/2.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass, field, replace
from typing import Any, Literal

import numpy as np

from shaftline.design.bore import SlopeParametrisation
from shaftline.errors import InputError, SolverFailure, require_finite
from shaftline.film.bearing import BearingState, JournalBearing
from shaftline.film.geometry import BoreSegment
from shaftline.film.problem import BearingProblem

__all__ = [
    "CONSTRAINT_COMPARISONS",
    "OBJECTIVES",
    "Constraint",
    "DesignEvaluation",
    "Objective",
    "SlopeDesignProblem",
    "evaluate_design",
    "film_state",
]


@dataclass(frozen=True)
class Objective:
    """A quantity of a design's film that a search can rank by.

    Attributes
    ----------
    sense : "max" or "min"
    unit : str
    value : callable
        ``value(state) -> float`` from the film at equilibrium.
    description : str
    """

    sense: Literal["max", "min"]
    unit: str
    value: Callable[[BearingState], float]
    description: str


def _min_film(state: BearingState) -> float:
    return state.min_film_thickness


def _max_pressure(state: BearingState) -> float:
    return state.max_pressure


def _power(state: BearingState) -> float:
    return state.power_loss


def _leakage(state: BearingState) -> float:
    return state.side_leakage


def _support(state: BearingState) -> float:
    return abs(state.load_centre_offset)


#: The quantities a search may take as objectives or constraints (SciPy-style registry).
OBJECTIVES: dict[str, Objective] = {
    "min_film_thickness": Objective("max", "m", _min_film, "smallest film h_min (seed 004: maximised)"),
    "max_pressure": Objective("min", "Pa", _max_pressure, "largest pressure p_max (seed 004: minimised)"),
    "power_loss": Objective("min", "W", _power, "friction power"),
    "side_leakage": Objective("min", "m^3/s", _leakage, "net flow out through both edges"),
    "support_offset": Objective("min", "m", _support, "distance of the film resultant from L/2"),
}
CONSTRAINT_COMPARISONS = (">=", "<=")


@dataclass(frozen=True)
class Constraint:
    """``quantity comparison limit`` that a design must meet (e.g. h_min >= 30 µm, BV's value
    quoted by seed 004 Sect. 2.2.1; p_max <= a lining's limit).

    Raises
    ------
    InputError
        ``"quantity"`` not in :data:`OBJECTIVES`, ``"comparison"`` not ``>=``/``<=``,
        ``"limit"`` not finite.
    """

    quantity: str
    comparison: str
    limit: float

    def __post_init__(self) -> None:
        if self.quantity not in OBJECTIVES:
            raise InputError("quantity", self.quantity, "", "one of " + ", ".join(OBJECTIVES))
        if self.comparison not in CONSTRAINT_COMPARISONS:
            raise InputError("comparison", self.comparison, "", ">= or <=")
        require_finite("limit", self.limit, OBJECTIVES[self.quantity].unit)

    def violation(self, value: float) -> float:
        """How far ``value`` is on the wrong side of the limit (<= 0 when met), in the quantity's unit."""
        return self.limit - value if self.comparison == ">=" else value - self.limit


@dataclass(frozen=True, eq=False)
class SlopeDesignProblem:
    """The search for a bore: the film problem, its fixed operating point, and what to rank by.

    Attributes
    ----------
    film : BearingProblem
        The bearing without slope boring (any ``bore`` of its geometry is replaced by each
        design's); a ``bent_journal`` in its geometry is the bent-shaft model.
    load_y, load_z : float
        Load on the journal, N (``load_y = -W`` for a downward load).
    tilt_y, tilt_z : float
        Journal tilt (chord slope) relative to the unbored axis, rad (psi_x 2c/L of seed 004).
    parametrisation : SlopeParametrisation
    objectives : tuple of str
        Keys of :data:`OBJECTIVES`; default the seed's pair (max h_min, min p_max).
    constraints : tuple of Constraint

    Raises
    ------
    InputError
        ``"objectives"`` empty, repeated or unknown; ``"load_y"`` for no load.
    """

    film: BearingProblem
    load_y: float
    load_z: float = 0.0
    tilt_y: float = 0.0
    tilt_z: float = 0.0
    parametrisation: SlopeParametrisation = field(default_factory=SlopeParametrisation)
    objectives: tuple[str, ...] = ("min_film_thickness", "max_pressure")
    constraints: tuple[Constraint, ...] = ()

    def __post_init__(self) -> None:
        if not self.objectives:
            raise InputError("objectives", [], "", "at least one of " + ", ".join(OBJECTIVES))
        for k, name in enumerate(self.objectives):
            if name not in OBJECTIVES:
                raise InputError(f"objectives[{k}]", name, "", "one of " + ", ".join(OBJECTIVES))
            if name in self.objectives[:k]:
                raise InputError(f"objectives[{k}]", name, "", "an objective not given twice")
        for name in ("load_y", "load_z", "tilt_y", "tilt_z"):
            require_finite(name, getattr(self, name), "rad" if name.startswith("tilt") else "N")
        if self.load_y == 0.0 and self.load_z == 0.0:
            raise InputError("load_y", 0.0, "N", "a non-zero load")

    def minimised(self, evaluation: DesignEvaluation) -> np.ndarray:
        """The objectives of an evaluation in pymoo's minimisation form (maxima negated)."""
        return np.array(
            [
                -evaluation.values[name] if OBJECTIVES[name].sense == "max" else evaluation.values[name]
                for name in self.objectives
            ]
        )

    def violations(self, evaluation: DesignEvaluation) -> np.ndarray:
        """Constraint violations (<= 0 when met), with a failed evaluation infeasible (1)."""
        out = [c.violation(evaluation.values[c.quantity]) for c in self.constraints]
        return np.array([0.0 if evaluation.ok else 1.0, *out])


@dataclass(frozen=True, eq=False)
class DesignEvaluation:
    """One design and its film.

    Attributes
    ----------
    x : ndarray
        Design variables (slopes as shares of 2c/L, knuckles as shares of L).
    values : dict
        Every quantity of :data:`OBJECTIVES` (SI), plus ``eccentricity_ratio``,
        ``attitude_angle`` (rad) and ``load_centre_offset`` (m, + forward); NaN when failed.
    status : str
        ``"ok"``, ``"contact"`` (the film reached its floor), ``"not converged"`` or
        ``"failed: <reason>"``.
    iterations : int
        Newton iterations of the equilibrium.
    """

    x: np.ndarray
    values: dict[str, float]
    status: str
    iterations: int = 0

    @property
    def ok(self) -> bool:
        return self.status == "ok"

    def record(self, names: list[str]) -> dict[str, Any]:
        """A flat row for a table: variables by ``names``, quantities, status."""
        row: dict[str, Any] = {name: float(v) for name, v in zip(names, self.x, strict=True)}
        row.update(self.values)
        row["status"] = self.status
        row["iterations"] = self.iterations
        return row


#: Bearings built in this process, by what their solver depends on (a worker reuses its
#: factorisations from one design to the next: only the bore changes).
_BEARINGS: dict[tuple[Any, ...], JournalBearing] = {}


def _bearing(film: BearingProblem) -> JournalBearing:
    g = film.geometry
    key = (g.length, g.diameter, g.radial_clearance, g.rotation, film.operating, film.options)
    bearing = _BEARINGS.get(key)
    if bearing is None:
        if len(_BEARINGS) > 8:
            _BEARINGS.clear()
        bearing = JournalBearing.from_problem(film)
        _BEARINGS[key] = bearing
    return bearing


def film_state(problem: SlopeDesignProblem, bore: tuple[BoreSegment, ...]) -> BearingState | None:
    """The film at equilibrium with ``bore`` (any bore, e.g. none or a single slope to compare
    a design with), or None where there is none (the journal cuts the bore)."""
    geometry = replace(problem.film.geometry, bore=bore)
    try:
        found = (
            _bearing(problem.film)
            .with_geometry(geometry)
            .equilibrium(problem.load_y, problem.load_z, tilt_y=problem.tilt_y, tilt_z=problem.tilt_z)
        )
    except (InputError, SolverFailure):
        return None
    return found.state


def evaluate_design(problem: SlopeDesignProblem, x: np.ndarray) -> DesignEvaluation:
    """The film at equilibrium with the bore of design ``x`` (a pure function of its inputs;
    module-level so that it pickles for a process pool or a Dask cluster)."""
    x = np.asarray(x, dtype=float)
    film = problem.film
    nan = dict.fromkeys([*OBJECTIVES, "eccentricity_ratio", "attitude_angle", "load_centre_offset"], math.nan)
    try:
        bore = problem.parametrisation.bore(x, film.geometry.length, film.geometry.radial_clearance)
        geometry = replace(film.geometry, bore=bore)
        bearing = _bearing(film).with_geometry(geometry)
        found = bearing.equilibrium(problem.load_y, problem.load_z, tilt_y=problem.tilt_y, tilt_z=problem.tilt_z)
    except (InputError, SolverFailure) as error:
        return DesignEvaluation(x, nan, f"failed: {error}")
    state = found.state
    values = {name: float(objective.value(state)) for name, objective in OBJECTIVES.items()}
    values.update(
        eccentricity_ratio=state.eccentricity_ratio,
        attitude_angle=state.attitude_angle,
        load_centre_offset=state.load_centre_offset,
    )
    return DesignEvaluation(x, values, found.status, found.iterations)
