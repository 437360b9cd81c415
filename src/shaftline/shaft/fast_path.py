"""Seed 004's fast path: point-support alignment, local shaft model, one film equilibrium.

Before the shaft and its film are solved together (:mod:`shaftline.shaft.coupled`), seed 004
(Sect. 4.5.2-4.5.4) analyses the stern-tube bearing in three uncoupled steps:

1. the alignment with the bearing as a point support at mid-length gives the reaction and
   the chord slope of the shaft across the bearing (psi_x);
2. the local shaft model (:mod:`shaftline.shaft.local`: overhang, bearing, a forward length
   with its end rotation imposed, pinned at both bearing edges at the chord) gives the bent
   journal inside the bearing;
3. one film equilibrium carries the reaction with the journal held at that chord slope and
   bent shape (only the mid-plane offsets are free).

Its "problem bisection" (Sect. 4.5.2, L1538-1552) feeds the film's support point back into
the alignment as the point support's position and repeats; the seed states no tolerance.
:func:`bisection` stops when the support point moves less than ``tolerance``.

What the fast path leaves out, and the coupled solution keeps (docs/validation.md): the
journal rides on the film, so its chord across the bearing is not the point-support chord;
the film load is distributed, not a point at the support point; and the film's side force
(the attitude angle) bends the line horizontally, which the seed's psi_y = 0 ignores.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field, replace

import numpy as np

from shaftline.errors import InputError, require_positive
from shaftline.film.bearing import BearingState, JournalBearing
from shaftline.shaft.alignment import AlignmentModel, ConditionResult
from shaftline.shaft.coupled import FilmSupport
from shaftline.shaft.local import LocalShaftLine, LocalShaftModel, solve_local_model
from shaftline.shaft.model import Bearing, Condition, PointLoad, ShaftLine, ShaftSegment

__all__ = ["FastPathResult", "bisection", "fast_path"]

#: Forward length of the local model when none is given: seed 004 Table 4-5, m.
SEED_FORE_LENGTH = 0.5412


@dataclass(frozen=True, eq=False)
class FastPathResult:
    """The fast path at one support-point position (SI units).

    Attributes
    ----------
    name : str
        The film bearing.
    state : BearingState
        The film at its equilibrium (hmin, pmax and their places, support point, friction);
        ``state.contact`` is True when the film cannot carry the reaction above its floor.
    reaction : float
        Point-support reaction the film carries, N (+ up, on the shaft).
    relative_slope : float
        Chord slope of the shaft across the bearing relative to the bore axis, rad: the
        film's imposed tilt (psi_x times 2c/L).
    support_point : float
        Axial position of the film resultant from mid-length, m, + forward: seed 004's load
        centre, the iteration variable of its bisection (in the vertical plane where the film
        is loaded vertically; :attr:`~shaftline.shaft.coupled.FilmBearingResult.support_point_y`
        of the coupled line is the vertical plane's alone).
    support_x : float
        Where the alignment's point support was, m from the aft end of the line.
    local : LocalShaftLine
        The local model's elastic line (the bent journal).
    alignment : ConditionResult
        The point-support alignment it started from.
    iterations : int
        Alignment-film passes (1 without :func:`bisection`).
    history : list of float
        Support point after each pass, m from mid-length.
    converged : bool
        False when :func:`bisection` ran out of iterations.
    """

    name: str
    state: BearingState
    reaction: float
    relative_slope: float
    support_point: float
    support_x: float
    local: LocalShaftLine = field(repr=False)
    alignment: ConditionResult = field(repr=False)
    iterations: int = 1
    history: list[float] = field(default_factory=list)
    converged: bool = True


def _point_line(line: ShaftLine, index: int, support_x: float, lift: float, marks: list[float]) -> ShaftLine:
    """The line with bearing ``index`` as one short point support at ``support_x`` (bore bottom
    there, raised by ``lift``), and mesh nodes at ``marks`` (zero loads)."""
    bearing = line.bearings[index]
    aft = bearing.x - 0.5 * bearing.length
    if not aft <= support_x <= aft + bearing.length:
        raise InputError("support_x", support_x, "m", f"within the bearing, [{aft:.4g}, {aft + bearing.length:.4g}]")
    # Short, so that its edges stay inside the shaft wherever the point is, and long enough
    # that the mesh does not merge its edge nodes into the point (NODE_MERGE_DISTANCE).
    short = 0.1 * bearing.length
    point = replace(
        bearing,
        x=support_x,
        length=short,
        support="point",
        position="centre",
        offset_y=bearing.offset_y + bearing.slope * (support_x - bearing.x) + lift,
        stiffness=math.inf,
    )
    bearings = list(line.bearings)
    bearings[index] = point
    loads = tuple(PointLoad(x) for x in marks)
    return replace(line, bearings=tuple(bearings), point_loads=(*line.point_loads, *loads))


def fast_path(
    line: ShaftLine,
    film: FilmSupport,
    condition: Condition | None = None,
    *,
    support_x: float | None = None,
    lift: float = 0.0,
    fore_length: float = SEED_FORE_LENGTH,
) -> FastPathResult:
    """Seed 004's uncoupled analysis of one film bearing: point-support alignment, local shaft
    model, film equilibrium.

    Parameters
    ----------
    line : ShaftLine
        The line; the film bearing must be its aft-most bearing on a solid shaft of uniform
        section from the aft end to ``fore_length`` forward of the bearing (the local model's
        span), as seed 004's stern tube.
    film : FilmSupport
        The bearing and its film (a straight journal; the bent one comes from the local model).
    condition : Condition, optional
        Default: the line's first.
    support_x : float, optional
        Position of the point support, m from the aft end; default the bearing's mid-length
        (the seed's ``l_cp = L/2``).
    lift : float
        Raise the point support by this much, m (:func:`bisection` with ``lift=True``).
    fore_length : float
        Length of the local model forward of the bearing, m (seed 004: 0.5412).

    Returns
    -------
    FastPathResult

    Raises
    ------
    InputError
        ``film.bearing`` not a bearing of the line or not its aft-most one; ``fore_length``
        not positive or beyond the shaft; a hollow or conical shaft over the local span.
    """
    require_positive("fore_length", fore_length, "m")
    span = _local_span(line, film, fore_length)
    bearing = span.bearing
    condition = condition or line.all_conditions()[0]
    position = bearing.x if support_x is None else float(support_x)
    model, alignment = _point_support_alignment(line, span, condition, position, lift)
    point = alignment.bearings[span.index]
    v_aft, v_fore = (float(np.interp(s, alignment.x, alignment.deflection_y)) for s in (span.aft, span.fore))
    chord = (v_fore - v_aft) / bearing.length
    local = solve_local_model(_local_model(line, span, model, alignment, v_aft, v_fore))
    local_chord, journal = local.bent_journal()
    problem = film.problem
    bent = replace(problem, geometry=replace(problem.geometry, bent_journal=journal))
    tilt = local_chord - bearing.slope
    found = JournalBearing.from_problem(bent).equilibrium(-point.reaction_y, -point.reaction_z, tilt_y=tilt)
    state = found.state
    return FastPathResult(
        name=bearing.name,
        state=state,
        reaction=point.reaction_y,
        relative_slope=chord - bearing.slope,
        support_point=state.load_centre_offset,
        support_x=position,
        local=local,
        alignment=alignment,
        history=[state.load_centre_offset],
    )


@dataclass(frozen=True)
class _LocalSpan:
    """Where the local model of the film bearing lies on the line (m from the aft end).

    Attributes
    ----------
    index : int
        The film bearing's place in ``line.bearings``.
    bearing : Bearing
        The film bearing.
    segment : ShaftSegment
        The one uniform, solid segment over the span.
    aft, fore : float
        The bearing's aft and forward edges, m.
    end : float
        The forward end of the local model, m.
    fore_length : float
        Length of the local model forward of the bearing, m.
    """

    index: int
    bearing: Bearing
    segment: ShaftSegment
    aft: float
    fore: float
    end: float
    fore_length: float


def _local_span(line: ShaftLine, film: FilmSupport, fore_length: float) -> _LocalSpan:
    """The local model's span on ``line``: the film bearing, its edges and the model's
    forward end ``fore_length`` (m) beyond it, checked as :func:`fast_path` documents."""
    names = [b.name for b in line.bearings]
    if film.bearing not in names:
        raise InputError("film.bearing", film.bearing, "", "the name of a bearing: " + ", ".join(names))
    index = names.index(film.bearing)
    bearing = line.bearings[index]
    if any(b.x < bearing.x for b in line.bearings):
        raise InputError("film.bearing", film.bearing, "", "the aft-most bearing (the local model's overhang)")
    aft = bearing.x - 0.5 * bearing.length
    fore = aft + bearing.length
    end = fore + fore_length
    if end > line.length:
        raise InputError("fore_length", fore_length, "m", f"at most {line.length - fore:.4g} (the shaft's end)")
    edges = line.segment_edges()
    first, last = (
        int(np.clip(np.searchsorted(edges, x, side="right") - 1, 0, len(line.segments) - 1)) for x in (0.0, end)
    )
    segment = line.segments[first]
    if (
        last != first
        or segment.inner_diameter > 0.0
        or (segment.outer_diameter_end not in (None, segment.outer_diameter))
    ):
        raise InputError(
            "line.segments", "hollow, conical or stepped", "", "one solid, uniform segment over the local model's span"
        )
    return _LocalSpan(index, bearing, segment, aft, fore, end, fore_length)


def _point_support_alignment(
    line: ShaftLine, span: _LocalSpan, condition: Condition, position: float, lift: float
) -> tuple[AlignmentModel, ConditionResult]:
    """The alignment in ``condition`` with the film bearing as a point support at
    ``position`` (m from the aft end) raised by ``lift`` (m), mesh nodes at the span's
    edges and end; the model and its solution."""
    bearing = span.bearing
    lift_total = lift + condition.offsets_y.get(bearing.name, 0.0)
    point_line = _point_line(line, span.index, position, lift_total, [span.aft, span.fore, span.end])
    # The condition's own offset of this bearing is in lift_total: drop it from the condition.
    offsets_y = {k: v for k, v in condition.offsets_y.items() if k != bearing.name}
    model = AlignmentModel(point_line)
    alignment = model.solve_condition(replace(condition, offsets_y=offsets_y))
    return model, alignment


def _local_model(
    line: ShaftLine,
    span: _LocalSpan,
    model: AlignmentModel,
    alignment: ConditionResult,
    v_aft: float,
    v_fore: float,
) -> LocalShaftModel:
    """The local shaft model over ``span``, loaded as the point-support ``alignment`` loads
    it there; ``v_aft``, ``v_fore``: the alignment's deflections at the bearing's edges, m."""
    x = alignment.x
    bearing, segment, aft, end = span.bearing, span.segment, span.aft, span.end
    # The local model's end loads reproduce the alignment's shear and moment at the aft edge
    # (shear_y: net upward force aft of the cut; moment_y: + sagging) with the weight of the
    # overhang: F x - M0 - w x^2 / 2 = M(x), F - w x = S(x).
    element = int(np.clip(np.searchsorted(x, bearing.x) - 1, 0, x.size - 2))
    weight = float(model.mesh.weight_per_length[element])
    shear_aft, moment_aft = (float(np.interp(aft, x, values)) for values in (alignment.shear_y, alignment.moment_y))
    aft_force = shear_aft + weight * aft
    aft_moment = aft_force * aft - 0.5 * weight * aft**2 - moment_aft
    return LocalShaftModel(
        bearing_length=bearing.length,
        shaft_diameter=segment.outer_diameter,
        aft_overhang=aft,
        fore_length=span.fore_length,
        aft_force=aft_force,
        aft_moment=aft_moment,
        fore_force=-float(np.interp(end, x, alignment.shear_y)),
        fore_rotation=float(np.interp(end, x, alignment.rotation_y)),
        weight_per_length=weight,
        youngs_modulus=segment.youngs_modulus,
        # The alignment's edge deflections: the same chord (seed: offsets giving psi_x).
        aft_edge_offset=v_aft,
        fore_edge_offset=v_fore,
        beam_theory=line.beam_theory,
        shear_area_factor=segment.shear_area_factor,
    )


def bisection(
    line: ShaftLine,
    film: FilmSupport,
    condition: Condition | None = None,
    *,
    tolerance: float = 1e-3,
    max_iterations: int = 10,
    lift: bool = False,
    fore_length: float = SEED_FORE_LENGTH,
) -> FastPathResult:
    """Seed 004's "problem bisection": the film's support point back into the alignment as the
    point support's position, until it moves less than ``tolerance``.

    Parameters
    ----------
    line, film, condition, fore_length
        As :func:`fast_path`.
    tolerance : float
        Change of the support point between passes at which to stop, m (the seed gives
        none; 1 mm is 0.1 % of its bearing length).
    max_iterations : int
        Passes allowed (the seed: "a few iterations ... should be sufficient").
    lift : bool
        Also raise the point support to the journal's height above the bore bottom at the
        support point (its centre line plus the clearance), which the seed does not do
        ("the vertical contact offsets do not affect the bore geometry"): it lets the
        alignment see that the journal rides on the film.

    Returns
    -------
    FastPathResult
        The last pass, with ``iterations``, ``history`` and ``converged``.
    """
    tolerance = require_positive("tolerance", tolerance, "m")
    if not 1 <= int(max_iterations) <= 100:
        raise InputError("max_iterations", max_iterations, "", "an integer in [1, 100]")
    result = fast_path(line, film, condition, fore_length=fore_length)
    history = [result.support_point]
    bearing = next(b for b in line.bearings if b.name == film.bearing)
    c = film.problem.geometry.radial_clearance
    converged = False
    for _ in range(int(max_iterations) - 1):
        state = result.state
        z = 0.5 * bearing.length + state.load_centre_offset
        raise_by = 0.0
        if lift:
            journal = result.local.bent_journal()[1]
            centre = state.position.ey + state.position.tilt_y * (z - 0.5 * bearing.length)
            raise_by = c + centre + float(np.interp(z, journal.z, journal.dy))
        support_x = bearing.x - 0.5 * bearing.length + z
        result = fast_path(line, film, condition, support_x=support_x, lift=raise_by, fore_length=fore_length)
        history.append(result.support_point)
        if abs(history[-1] - history[-2]) <= tolerance:
            converged = True
            break
    return replace(result, iterations=len(history), history=history, converged=converged)
