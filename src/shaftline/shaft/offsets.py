"""Bearing offsets: an alignment that meets the rules in every condition, and the offsets
behind measured reactions ("reverse engineering").

Optimisation: reactions and the aft-bearing slope are linear in the offsets while the
contact state holds, so the design is a linear programme (scipy's HiGHS): minimise the
largest aft-bearing relative slope over the conditions (or the largest
departure of a load ratio from 1), subject to every reaction above its minimum and every mean pressure below
its limit in every condition, offsets within bounds. The linearisation is taken at the
current contact state (the first round on the two-sided model, so that lifted bearings
count); the plan is re-solved with the full one-sided model and re-linearised until the
contact state settles. Its coefficients are the influence matrix of that contact state
(:meth:`AlignmentModel.influence_matrix`), exact for it; a finite difference would cross
a change of contact state whenever one lies within its step (a multi-point bearing with a
point about to lift, as in the example) and mix two linear pieces.

A line whose bearings sit on their films (``films=``, a
:class:`~shaftline.shaft.coupled.CoupledAlignment`) is solved coupled in every round and
linearised with the coupled line's tangent influence coefficients
(:func:`~shaftline.shaft.film_tangent.tangent_influence`): the film's stiffness makes the
reactions non-linear in the offsets, so the rounds are Newton steps, repeated until the offsets
settle. The first round, which must bring lifted bearings back, is taken on the declared
supports' two-sided model.
"""

from __future__ import annotations

from dataclasses import dataclass, replace
from typing import TYPE_CHECKING

import numpy as np
from scipy.optimize import linprog

from shaftline.errors import InputError, SolverFailure
from shaftline.shaft.alignment import AlignmentModel, ConditionResult, InfluenceMatrix
from shaftline.shaft.model import Bearing, Condition
from shaftline.shaft.rules import Rule, weight_shares

if TYPE_CHECKING:
    from shaftline.shaft.coupled import CoupledAlignment

#: Largest offset change (m) of a round at which the plan of a line on its films has settled: the
#: film makes the reactions non-linear in the offsets, so the rounds are Newton steps and stop
#: when a step no longer moves a bearing by more than 0.1 um, a hundredth of what a yard sets
#: (0.01 mm) and above the offsets the coupled solution's own tolerance leaves uncertain.
FILM_OFFSET_TOLERANCE = 1e-7
#: Halvings of a round's offset change on films before a film that grounds at every one of them
#: is reported: 2^-10 of a millimetre step is a micrometre, below which no plan is meaningful.
FILM_STEP_HALVINGS = 10

#: ``aft_slope``: the largest relative slope in the aft stern-tube bearing over the conditions;
#: ``load_spread``: the largest departure of a load ratio (reaction / straight-line weight
#: share of the bearing) from 1.
OBJECTIVES = ("aft_slope", "load_spread")


@dataclass(frozen=True)
class OffsetPlan:
    """Offsets found by :func:`optimise_offsets`.

    Attributes
    ----------
    offsets : dict
        Added vertical offset per bearing, m.
    results : list of ConditionResult
        The conditions solved with these offsets (full one-sided model).
    objective : float
        Largest aft-bearing relative slope (rad) or load-ratio departure (-).
    iterations : int
        Linearise-and-solve rounds.
    settled : bool
        Whether the rounds settled (the contact states, and on films the offsets, unchanged
        by the last round); False when the rounds ran out first.
    influence : str
        Which influence coefficients the rounds used (:attr:`InfluenceMatrix.label`).
    note : str
        Why the rounds stopped unsettled (empty otherwise or when they ran out).
    """

    offsets: dict[str, float]
    results: list[ConditionResult]
    objective: float
    iterations: int
    settled: bool = True
    influence: str = "point supports"
    note: str = ""


def _with_offsets(condition: Condition, offsets: dict[str, float]) -> Condition:
    merged = dict(condition.offsets_y)
    for name, value in offsets.items():
        merged[name] = merged.get(name, 0.0) + value
    return replace(condition, offsets_y=merged)


def _interpolation_weights(nodes: np.ndarray, x: float) -> np.ndarray:
    """Weights w with w @ values = np.interp(x, nodes, values) for any nodal values."""
    weights = np.zeros(nodes.size)
    if x <= nodes[0]:
        weights[0] = 1.0
    elif x >= nodes[-1]:
        weights[-1] = 1.0
    else:
        k = int(np.searchsorted(nodes, x, side="right")) - 1
        t = (x - nodes[k]) / (nodes[k + 1] - nodes[k])
        weights[k], weights[k + 1] = 1.0 - t, t
    return weights


def _slope_weights(nodes: np.ndarray, aft: Bearing) -> np.ndarray:
    """Weights of the nodal deflections (at ``nodes``, m) in the chord slope of bearing ``aft``,
    1/m: relative slope = (v(fore edge) - v(aft edge)) / L - bore slope, linear in the nodal v."""
    fore_edge = _interpolation_weights(nodes, aft.x + 0.5 * aft.length)
    return (fore_edge - _interpolation_weights(nodes, aft.x - 0.5 * aft.length)) / aft.length


def _limits(model: AlignmentModel, rules: list[Rule]) -> tuple[np.ndarray, np.ndarray]:
    """Smallest and largest admissible reaction per bearing, N, from the rules."""
    line = model.line
    shares = weight_shares(model)
    low = np.zeros(len(line.bearings))
    high = np.full(len(line.bearings), np.inf)
    for k, bearing in enumerate(line.bearings):
        area = bearing.length * line.outer_diameter_at(bearing.x)
        for rule in rules:
            if rule.applies_to not in ("all", bearing.material):
                continue
            if rule.quantity == "reaction" and rule.comparison in (">", ">="):
                low[k] = max(low[k], rule.limit)
            elif rule.quantity == "reaction_share" and rule.comparison in (">", ">="):
                low[k] = max(low[k], rule.limit * shares[k])
            elif rule.quantity == "mean_pressure" and rule.comparison in ("<", "<="):
                high[k] = min(high[k], rule.limit * area)
    return low, high


def optimise_offsets(
    model: AlignmentModel,
    rules: list[Rule],
    adjustable: list[str] | None = None,
    objective: str = "aft_slope",
    bound: float = 5e-3,
    max_rounds: int = 6,
    films: CoupledAlignment | None = None,
) -> OffsetPlan:
    """Offsets of the ``adjustable`` bearings (default: all but the aft- and forward-most).

    Parameters
    ----------
    model : AlignmentModel
        The line on its declared supports.
    rules : list of Rule
        The limits every condition must meet.
    adjustable : list of str, optional
        The bearings whose offsets change.
    objective : str
        One of :data:`OBJECTIVES`.
    bound : float
        Largest added offset either way, m.
    max_rounds : int
        Linearise-and-solve rounds allowed (twice as many on films).
    films : CoupledAlignment, optional
        The same line with its film bearings on their films: every condition is then solved
        coupled and linearised with the tangent influence coefficients (module docstring).

    Raises
    ------
    InputError
        An unknown objective or bearing, or no offsets within the bound that meet the limits.
    SolverFailure
        On films, when a round's offsets leave a film-supported condition without an
        equilibrium (a film grounds).
    """
    problem = _offset_problem(model, rules, adjustable, objective, bound)
    offsets = np.zeros(len(problem.adjustable))
    starts: dict[str, object] = {}
    rounds = 0
    settled = False
    note = ""
    results: list[ConditionResult] | None = None
    while rounds < (max_rounds if films is None else 2 * max_rounds):
        rounds += 1
        # First round on the two-sided model: a lifted bearing has no sensitivity to a small
        # offset in the one-sided model, but the plan must bring it back into contact.
        two_sided = rounds == 1
        linearised = _linearise(problem, offsets, two_sided, films, starts)
        change = _offset_change(problem, linearised, offsets)
        try:
            results, change = _solved(problem, offsets, change, films, starts)
        except SolverFailure as failure:
            if results is None:
                raise
            # The linear programme keeps asking for offsets at which a film grounds (its floor is
            # no constraint of the programme): the last round's offsets are the plan, unsettled.
            note = (
                f"round {rounds} stopped: the step towards the linear programme's offsets, halved "
                f"{FILM_STEP_HALVINGS} times, leaves a film without equilibrium ({failure})"
            )
            break
        offsets = offsets + change
        new_states = [[b.contact for b in r.bearings] for r in results]
        moved = films is not None and float(np.max(np.abs(change))) > FILM_OFFSET_TOLERANCE
        if new_states == linearised.states and not two_sided and not moved:
            settled = True
            break
    if results is None:  # max_rounds < 1
        raise InputError("max_rounds", max_rounds, "", "at least 1")
    aft_index, shares = problem.aft_index, problem.shares
    if objective == "aft_slope":
        value = max(abs(r.bearings[aft_index].relative_slope) for r in results)
    else:
        value = max(abs(b.reaction_y / shares[k] - 1.0) for r in results for k, b in enumerate(r.bearings))
    used = "point supports" if films is None else "film supports: tangent at each round's coupled equilibrium"
    return OffsetPlan(
        dict(zip(problem.adjustable, map(float, offsets), strict=True)),
        results,
        float(value),
        rounds,
        settled,
        used,
        note,
    )


def _solved(
    problem: _OffsetProblem,
    offsets: np.ndarray,
    change: np.ndarray,
    films: CoupledAlignment | None,
    starts: dict[str, object],
) -> tuple[list[ConditionResult], np.ndarray]:
    """Every condition solved with the added ``offsets + change`` (m), on the films if given, and
    the change taken. On films a change that grounds a film (a linear step too far for the
    film) is halved until every condition has its equilibrium, up to :data:`FILM_STEP_HALVINGS`
    times; then the full step's failure is raised."""
    if films is None:
        conditions = [_with_offsets(c, problem.offsets(offsets + change)) for c in problem.conditions]
        return [problem.model.solve_condition(c) for c in conditions], change
    first: SolverFailure | None = None
    for _ in range(FILM_STEP_HALVINGS + 1):
        try:
            trial = offsets + change
            return [
                _film_solution(films, _with_offsets(c, problem.offsets(trial)), starts)[0] for c in problem.conditions
            ], change
        except SolverFailure as failure:
            first = first or failure  # the full step's: the one that says what went wrong
            change = 0.5 * change
    assert first is not None
    raise first


@dataclass(frozen=True, eq=False)
class _OffsetProblem:
    """What the offset optimisation's linear programmes share, round after round.

    Attributes
    ----------
    model : AlignmentModel
    conditions : tuple of Condition
        The line's conditions, all met at once.
    adjustable : list of str
        The bearings whose offsets change.
    columns : list of int
        Their places in ``model.line.bearings``.
    aft_index : int
        Place of the aft-most bearing (the slope objective's).
    low, high : ndarray
        Smallest and largest reaction per bearing the plan aims within, N (the rules' limits
        with a margin).
    slope_weights : ndarray
        Weights of the nodal deflections in the aft bearing's chord slope, 1/m.
    shares : ndarray
        Each bearing's straight-line share of the line's weight, N.
    objective : str
        One of :data:`OBJECTIVES`.
    bound : float
        Largest added offset either way, m.
    """

    model: AlignmentModel
    conditions: tuple[Condition, ...]
    adjustable: list[str]
    columns: list[int]
    aft_index: int
    low: np.ndarray
    high: np.ndarray
    slope_weights: np.ndarray
    shares: np.ndarray
    objective: str
    bound: float

    def offsets(self, values: np.ndarray) -> dict[str, float]:
        """The added offsets ``values`` (m) by bearing name."""
        return dict(zip(self.adjustable, values, strict=True))


def _offset_problem(
    model: AlignmentModel, rules: list[Rule], adjustable: list[str] | None, objective: str, bound: float
) -> _OffsetProblem:
    """The arguments of :func:`optimise_offsets` checked, and the parts of its linear
    programmes that do not change between rounds."""
    line = model.line
    names = [b.name for b in line.bearings]
    if objective not in OBJECTIVES:
        raise InputError("objective", objective, "", "one of " + ", ".join(OBJECTIVES))
    if adjustable is None:
        ordered = sorted(line.bearings, key=lambda b: b.x)
        adjustable = [b.name for b in ordered[1:-1]]
    for name in adjustable:
        if name not in names:
            raise InputError("adjustable", name, "", "bearing names: " + ", ".join(names))
    if not adjustable:
        raise InputError("adjustable", "[]", "", "at least one adjustable bearing")
    conditions = line.all_conditions()
    low, high = _limits(model, rules)
    # Plan with a small margin inside the limits so round-off cannot fail the checks.
    low = low + 1e-6 * np.abs(low) + 1.0
    limited = np.isfinite(high)
    high[limited] -= 1e-6 * np.abs(high[limited])
    aft_index = names.index(min(line.bearings, key=lambda b: b.x).name)
    columns = [names.index(name) for name in adjustable]
    slope_weights = _slope_weights(model.mesh.x, line.bearings[aft_index])
    shares = weight_shares(model)
    if objective == "load_spread" and not np.all(shares > 0.0):
        # The spread is each reaction over its weight share: undefined where the share is zero.
        bare = names[int(np.flatnonzero(~(shares > 0.0))[0])]
        raise InputError(
            "objective",
            objective,
            "",
            f"aft_slope here: bearing {bare!r} carries no share of the line's weight (a shaft without "
            "self weight and no mass near it), so the load spread is not defined",
        )
    return _OffsetProblem(
        model, conditions, adjustable, columns, aft_index, low, high, slope_weights, shares, objective, bound
    )


@dataclass(frozen=True, eq=False)
class _Linearisation:
    """The reactions, aft slope and load ratios of every condition linearised in the offset
    change ``d`` (m) at the current offsets, one entry per condition.

    Attributes
    ----------
    rows_a, rows_b : list of ndarray
        The reaction limits as ``rows_a @ d <= rows_b`` (N/m, N), lower and upper in turn.
    slope_rows, slope_rhs : list
        The aft bearing's relative slope ``slope_rhs + slope_rows @ d``, rad.
    ratio_rows, ratio_rhs : list of ndarray
        The load ratios' departures from 1, ``ratio_rhs + ratio_rows @ d`` (load_spread only).
    states : list of list of str
        The contact state of each bearing (its :attr:`BearingResult.contact`) the linearisation holds for.
    """

    rows_a: list[np.ndarray]
    rows_b: list[np.ndarray]
    slope_rows: list[np.ndarray]
    slope_rhs: list[float]
    ratio_rows: list[np.ndarray]
    ratio_rhs: list[np.ndarray]
    states: list[list[str]]


def _film_solution(
    films: CoupledAlignment, condition: Condition, starts: dict[str, object]
) -> tuple[ConditionResult, InfluenceMatrix]:
    """``condition`` solved on the films (from the last solution of the same condition in
    ``starts``, which it updates) and the tangent influence coefficients there.

    Raises
    ------
    SolverFailure
        When the coupled solution does not converge or a film grounds: the offsets then have
        no tangent on the films.
    """
    from shaftline.shaft.coupled import CoupledResult

    start = starts.get(condition.name)
    result = films.solve(condition, initial=start if isinstance(start, CoupledResult) else None)
    if result.influence is None:
        raise SolverFailure(
            f"offsets on the bearing films, condition {condition.name}: the film-supported line has no "
            f"equilibrium to linearise at these offsets ({result.message or 'not converged'}); narrow the "
            "offsets' bound, or optimise on the declared supports"
        )
    starts[condition.name] = result
    return result.condition, result.influence


def _linearise(
    problem: _OffsetProblem,
    offsets: np.ndarray,
    two_sided: bool,
    films: CoupledAlignment | None = None,
    starts: dict[str, object] | None = None,
) -> _Linearisation:
    """Every condition solved at the added ``offsets`` (m), on the two-sided model if
    ``two_sided``, on the ``films`` if given (and not ``two_sided``), and linearised there."""
    model, low, high, columns, shares = problem.model, problem.low, problem.high, problem.columns, problem.shares
    rows_a, rows_b, slope_rows, slope_rhs, use_rows, use_rhs = [], [], [], [], [], []
    states = []
    for condition in problem.conditions:
        current = _with_offsets(condition, problem.offsets(offsets))
        slope_weights = problem.slope_weights
        if films is not None and not two_sided:
            base, influence = _film_solution(films, current, {} if starts is None else starts)
            slope_weights = _slope_weights(base.x, model.line.bearings[problem.aft_index])
        else:
            base = model.solve_condition(current, two_sided)
            # Exact derivatives for the contact set of this solution (see influence_matrix);
            # a change of contact set is met by re-solving and re-linearising in the next round.
            influence = model.influence_matrix(None if two_sided else base)
        states.append([b.contact for b in base.bearings])
        reactions = np.array([b.reaction_y for b in base.bearings])
        slope = base.bearings[problem.aft_index].relative_slope
        jac_r = influence.matrix[:, columns]
        jac_s = slope_weights @ influence.deflection[:, columns]
        # low <= R + J d <= high  ->  -J d <= R - low ;  J d <= high - R   (d = change from current)
        rows_a.append(-jac_r)
        rows_b.append(reactions - low)
        finite = np.isfinite(high)
        rows_a.append(jac_r[finite])
        rows_b.append(high[finite] - reactions[finite])
        slope_rows.append(jac_s)
        slope_rhs.append(slope)
        if problem.objective == "load_spread":
            use_rows.append(jac_r / shares[:, None])
            use_rhs.append(reactions / shares - 1.0)
    return _Linearisation(rows_a, rows_b, slope_rows, slope_rhs, use_rows, use_rhs, states)


def _offset_change(problem: _OffsetProblem, linearised: _Linearisation, offsets: np.ndarray) -> np.ndarray:
    """The change of the added ``offsets`` (m) that minimises the objective of the
    ``linearised`` conditions within the limits and the bound, m (HiGHS).

    Raises
    ------
    InputError
        No offsets within the bound meet the limits.
    """
    bound = problem.bound
    n = len(problem.adjustable)
    # variables: d (n), t
    c = np.zeros(n + 1)
    c[-1] = 1.0
    rows_b = linearised.rows_b
    a_ub = [np.hstack([np.vstack(linearised.rows_a), np.zeros((sum(len(r) for r in rows_b), 1))])]
    b_ub = [np.concatenate(rows_b)]
    if problem.objective == "aft_slope":
        for row, value in zip(linearised.slope_rows, linearised.slope_rhs, strict=True):
            a_ub.append(np.concatenate([row, [-1.0]])[None, :])
            b_ub.append(np.array([-value]))
            a_ub.append(np.concatenate([-row, [-1.0]])[None, :])
            b_ub.append(np.array([value]))
    else:  # -t <= ratio - 1 + J d / share <= t
        for rows, values in zip(linearised.ratio_rows, linearised.ratio_rhs, strict=True):
            a_ub.append(np.hstack([rows, -np.ones((rows.shape[0], 1))]))
            b_ub.append(-values)
            a_ub.append(np.hstack([-rows, -np.ones((rows.shape[0], 1))]))
            b_ub.append(values)
    bounds = [(-bound - o, bound - o) for o in offsets] + [(0.0, None)]
    solution = linprog(c, A_ub=np.vstack(a_ub), b_ub=np.concatenate(b_ub), bounds=bounds, method="highs")
    if solution.status != 0:
        raise InputError(
            "bound",
            bound,
            "m",
            "a bound within which some offsets meet the rule limits in every condition (none found)",
        )
    return solution.x[:n]


def offsets_from_reactions(
    model: AlignmentModel,
    measured: dict[str, float],
    condition: Condition | None = None,
    reference: tuple[str, str] | None = None,
    films: CoupledAlignment | None = None,
) -> tuple[dict[str, float], float]:
    """Offsets that explain measured reactions, by least squares on the influence matrix.

    Two ``reference`` bearings (default: aft- and forward-most) stay at their offsets: a
    rigid line changes no reaction, so only offsets relative to them can be found.
    Returns the added offsets per bearing (m) and the RMS reaction misfit (N).

    With ``films`` (the line on its bearing films) the reactions are not linear in the offsets:
    the least squares is solved by Gauss-Newton steps on the tangent influence coefficients of
    the coupled line, each from a coupled solution, until a step moves no bearing by more than
    :data:`FILM_OFFSET_TOLERANCE`; the misfit is that of the last coupled solution.

    Raises
    ------
    SolverFailure
        On films, when the steps do not settle in 30, or lead to offsets where a film grounds.
    """
    line = model.line
    names = [b.name for b in line.bearings]
    for name in measured:
        if name not in names:
            raise InputError("measured", name, "", "bearing names: " + ", ".join(names))
    if reference is None:
        ordered = sorted(line.bearings, key=lambda b: b.x)
        reference = (ordered[0].name, ordered[-1].name)
    rows = [names.index(n) for n in measured]
    free = [k for k, n in enumerate(names) if n not in reference]
    if films is not None:
        return _film_offsets_from_reactions(films, measured, condition or line.all_conditions()[0], rows, free)
    base = model.solve_condition(condition or line.all_conditions()[0])
    reactions = np.array([b.reaction_y for b in base.bearings])
    matrix = model.influence_matrix().matrix
    target = np.array([measured[names[k]] for k in rows]) - reactions[rows]
    solution, *_ = np.linalg.lstsq(matrix[np.ix_(rows, free)], target, rcond=None)
    misfit = matrix[np.ix_(rows, free)] @ solution - target
    offsets = {names[k]: float(v) for k, v in zip(free, solution, strict=True)}
    return offsets, float(np.sqrt(np.mean(misfit**2)))


def _film_offsets_from_reactions(
    films: CoupledAlignment, measured: dict[str, float], condition: Condition, rows: list[int], free: list[int]
) -> tuple[dict[str, float], float]:
    """:func:`offsets_from_reactions` on the bearing films: Gauss-Newton on the coupled line."""
    names = [b.name for b in films.line.bearings]
    wanted = np.array([measured[names[k]] for k in rows])
    values = np.zeros(len(free))
    starts: dict[str, object] = {}
    for _ in range(30):
        offsets = {names[k]: float(v) for k, v in zip(free, values, strict=True)}
        solved, influence = _film_solution(films, _with_offsets(condition, offsets), starts)
        misfit = np.array([solved.bearings[k].reaction_y for k in rows]) - wanted
        step, *_ = np.linalg.lstsq(influence.matrix[np.ix_(rows, free)], -misfit, rcond=None)
        if float(np.max(np.abs(step))) <= FILM_OFFSET_TOLERANCE:
            return offsets, float(np.sqrt(np.mean(misfit**2)))
        values = values + step
    raise SolverFailure(
        "offsets from the measured reactions on the bearing films: the Gauss-Newton steps did not settle in 30; "
        "the reactions may not be reachable on the films (check the measured values and the reference bearings)"
    )
