"""An alignment study: the shaft line in all its conditions, the class-rule checks and
the procedures asked for (offset optimisation, sag and gap, jack-up, offsets from
measured reactions).

This is what ``[alignment]`` in a case file becomes; notebooks can build one directly
from a :class:`~shaftline.shaft.model.ShaftLine` and :func:`solve_alignment` it.
"""

from __future__ import annotations

import math
import re
from collections.abc import Callable
from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np

from shaftline.errors import InputError
from shaftline.lubricants import Lubricant
from shaftline.shaft.film_supports import CouplingOptions, FilmSupport
from shaftline.shaft.lift_off import FilmLimit
from shaftline.shaft.model import Bearing, Condition, ShaftLine

if TYPE_CHECKING:
    from shaftline.shaft.alignment import AlignmentModel, ConditionResult, InfluenceMatrix
    from shaftline.shaft.coupled import CoupledAlignment
    from shaftline.shaft.film_supports import CoupledResult
    from shaftline.shaft.jackup import JackUpCurve, JackUpFit
    from shaftline.shaft.lift_off import LiftOffResult
    from shaftline.shaft.offsets import OffsetPlan
    from shaftline.shaft.rules import Rule, RuleCheck
    from shaftline.shaft.sag_gap import SagGap


@dataclass(frozen=True)
class OffsetOptimisation:
    """Offsets of the ``adjustable`` bearings (None: all but the end ones) that meet the
    rules in every condition, minimising ``objective`` within +/- ``bound`` (m)."""

    objective: str = "aft_slope"
    adjustable: tuple[str, ...] | None = None
    bound: float = 5e-3


@dataclass(frozen=True)
class SagGapRequest:
    """Sag and gap at the flange at ``flange_x`` (m) in ``condition``, with temporary supports."""

    flange_x: float
    condition: Condition
    flange_diameter: float | None = None
    temporary_supports: tuple[Bearing, ...] = ()


@dataclass(frozen=True, eq=False)
class JackUpRequest:
    """A jack-up test of ``bearing`` with the jack at ``jack_x`` (m); ``measured`` is the
    test's (loads N, lifts m) where there is one."""

    bearing: str
    jack_x: float
    condition: Condition
    measured: tuple[np.ndarray, np.ndarray] | None = None


@dataclass(frozen=True)
class MeasuredReactions:
    """Measured reactions (N per bearing) in ``condition``; ``reference`` holds two bearings
    whose offsets stay as they are."""

    values: dict[str, float]
    condition: Condition
    reference: tuple[str, str] | None = None


@dataclass(frozen=True, eq=False)
class MinimumSpeedRequest:
    """The minimum speed of the film bearings for ``limit`` in ``condition``
    (:func:`shaftline.shaft.lift_off.minimum_speed` with these settings)."""

    limit: FilmLimit
    condition: Condition
    lowest: float = 0.05
    points: int = 8
    tolerance: float = 0.01


@dataclass(frozen=True, eq=False)
class AlignmentStudy:
    """An alignment problem in SI units and the procedures asked for.

    ``films`` are the hydrodynamic bearings, supported by their film in every condition
    (:mod:`shaftline.shaft.coupled`); the procedures (offsets, sag and gap, jack-up) use the
    line's declared supports. ``film_fields`` are the case-file tables the films came from
    (for error messages; empty from a notebook), ``film_lubricants`` their lubricants and film
    temperatures (for a design's temperature scenarios).
    """

    line: ShaftLine
    rules: tuple[Rule, ...]
    optimise: OffsetOptimisation | None = None
    sag_gap: SagGapRequest | None = None
    jack_up: JackUpRequest | None = None
    measured_reactions: MeasuredReactions | None = None
    films: tuple[FilmSupport, ...] = ()
    coupling: CouplingOptions = CouplingOptions()
    film_fields: tuple[str, ...] = ()
    minimum_speed: MinimumSpeedRequest | None = None
    film_lubricants: tuple[tuple[Lubricant, float | None], ...] = ()


@dataclass(frozen=True, eq=False)
class AlignmentResult:
    """Everything an alignment study asked for.

    Attributes
    ----------
    study : AlignmentStudy
    model : AlignmentModel
    conditions : list of ConditionResult
        One per condition, in the order of the study (with film bearings: the coupled
        solution, whose film bearings report their film force).
    influence : InfluenceMatrix
        The reactions' sensitivity to the offsets: on films the tangent at the first
        condition's coupled equilibrium (``kind = "film_tangent"``), else the declared
        supports' (``"point"``); :attr:`InfluenceMatrix.label` says which.
    checks : list of RuleCheck
    plan, plan_checks :
        Optimised offsets and the rule checks with them (when asked).
    sag_gap : SagGap or None
    jack, jack_fit :
        Modelled jack-up curve and the fit of the measured one (when asked).
    reverse : (dict, float) or None
        Offsets from measured reactions (m per bearing) and the RMS reaction misfit (N).
    coupled : list of CoupledResult or None
        With film bearings, the coupled solution of each condition (films, point-support
        comparison, convergence).
    lift_off : LiftOffResult or None
        The minimum speed and lift-off curve (when asked).
    point_influence : InfluenceMatrix or None
        With the film tangent shown as :attr:`influence`, the declared supports' matrix beside it
        (the comparison "point supports vs film supports").
    """

    study: AlignmentStudy
    model: AlignmentModel
    conditions: list[ConditionResult]
    influence: InfluenceMatrix
    checks: list[RuleCheck]
    plan: OffsetPlan | None = None
    plan_checks: list[RuleCheck] | None = None
    sag_gap: SagGap | None = None
    jack: JackUpCurve | None = None
    jack_fit: JackUpFit | None = None
    reverse: tuple[dict[str, float], float] | None = None
    coupled: list[CoupledResult] | None = None
    lift_off: LiftOffResult | None = None
    point_influence: InfluenceMatrix | None = None

    def slope_boring_angle(self) -> dict[str, float]:
        """Per condition, the bore slope that would make the aft stern-tube bearing parallel
        to the shaft, rad."""
        aft = min(self.model.line.bearings, key=lambda b: b.x).name
        return {r.name: r.bearing(aft).shaft_slope for r in self.conditions}


def _film_error(error: InputError, fields: tuple[str, ...]) -> InputError:
    """An error of :class:`~shaftline.shaft.coupled.CoupledAlignment` (``films[k]...``) under
    the case-file table of that film."""
    match = re.fullmatch(r"films\[(\d+)\]\.(.*)", error.field)
    if not match or int(match.group(1)) >= len(fields):
        return error
    rest = match.group(2).replace("problem.options.", "solver.").replace("problem.geometry.", "")
    return InputError(f"{fields[int(match.group(1))]}.{rest}", error.value, error.unit, error.allowed)


def _solve_on_films(
    study: AlignmentStudy, step: Callable[[str], None]
) -> tuple[CoupledAlignment | None, list[CoupledResult] | None]:
    """With film bearings, the coupled solver and every condition solved on the films."""
    if not study.films:
        return None, None
    from shaftline.shaft.coupled import CoupledAlignment

    try:
        solver = CoupledAlignment(study.line, study.films, study.coupling)
    except InputError as error:
        raise _film_error(error, study.film_fields) from None
    coupled = []
    for condition in study.line.all_conditions():
        name = condition.name
        step(f"film-supported alignment, {name}")

        def iteration(k: int, mismatch: float, name: str = name) -> None:
            step(f"film-supported alignment, {name}: iteration {k}, mismatch {mismatch:.2g} of the clearance")

        coupled.append(solver.solve(condition, iteration))
    return solver, coupled


def solve_alignment(study: AlignmentStudy, progress: Callable[[str], None] | None = None) -> AlignmentResult:
    """All conditions, the influence matrix, rule checks and the procedures the study asks for."""
    from shaftline.errors import located
    from shaftline.shaft.alignment import AlignmentModel
    from shaftline.shaft.jackup import jack_up, reaction_from_jack_curve
    from shaftline.shaft.offsets import offsets_from_reactions, optimise_offsets
    from shaftline.shaft.rules import check_rules
    from shaftline.shaft.sag_gap import sag_and_gap

    step = progress or (lambda _: None)
    step("alignment conditions")
    model = AlignmentModel(study.line)
    results = model.solve()
    solver, coupled = _solve_on_films(study, step)
    if coupled is not None:
        results = [c.condition for c in coupled]
    lift_off = None
    if study.minimum_speed is not None and study.films:
        from shaftline.shaft.lift_off import minimum_speed

        request = study.minimum_speed

        def speed_step(k: int, speed: float, smallest: float) -> None:
            step(f"minimum speed: solution {k}, {speed * 30 / math.pi:.1f} rpm, h_min {smallest * 1e6:.1f} µm")

        with located("minimum_speed"):
            lift_off = minimum_speed(
                study.line,
                study.films,
                request.limit,
                condition=request.condition,
                options=study.coupling,
                lowest=request.lowest,
                points=request.points,
                tolerance=request.tolerance,
                progress=speed_step,
            )
    influence = point_influence = model.influence_matrix()
    if coupled and coupled[0].influence is not None:
        # On films the reactions' sensitivity includes the films' stiffness: the tangent at the
        # first condition's coupled equilibrium is the matrix shown (each condition's is kept
        # with its coupled result).
        influence = coupled[0].influence
    rules = list(study.rules)
    checks = check_rules(model, results, rules)
    plan = plan_checks = sag = jack = fit = reverse = None
    if study.optimise is not None:
        step("offset optimisation")
        o = study.optimise
        with located("optimise"):
            plan = optimise_offsets(
                model, rules, list(o.adjustable) if o.adjustable else None, o.objective, o.bound, films=solver
            )
        plan_checks = check_rules(model, plan.results, rules)
    if study.sag_gap is not None:
        step("sag and gap")
        sg = study.sag_gap
        with located("sag_gap"):
            sag = sag_and_gap(study.line, sg.flange_x, sg.temporary_supports, sg.condition, sg.flange_diameter)
    if study.jack_up is not None:
        step("jack-up")
        ju = study.jack_up
        with located("jack_up"):
            jack = jack_up(study.line, ju.bearing, ju.jack_x, ju.condition)
        if ju.measured is not None:
            with located("jack_up.measured_curve"):
                fit = reaction_from_jack_curve(*ju.measured, jack.correction_factor)
    if study.measured_reactions is not None:
        mr = study.measured_reactions
        with located("measured_reactions"):
            reverse = offsets_from_reactions(model, mr.values, mr.condition, mr.reference, films=solver)
    return AlignmentResult(
        study,
        model,
        results,
        influence,
        checks,
        plan,
        plan_checks,
        sag,
        jack,
        fit,
        reverse,
        coupled,
        lift_off,
        point_influence if influence is not point_influence else None,
    )
