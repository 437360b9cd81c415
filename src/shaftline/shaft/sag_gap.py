"""Sag and gap at an uncoupled flange (the yard's check of an alignment during erection).

The line is cut at the flange; each piece rests on its own bearings and any temporary
supports. Sag is the vertical offset of the forward flange face relative to the aft
one; gap is the opening of the faces at the top less at the bottom.
"""

from __future__ import annotations

from dataclasses import dataclass, replace

import numpy as np

from shaftline.errors import InputError
from shaftline.shaft.alignment import AlignmentModel, ConditionResult
from shaftline.shaft.model import Bearing, Condition, ShaftLine, ShaftSegment


@dataclass(frozen=True)
class SagGap:
    """Prescribed sag and gap at a flange.

    Attributes
    ----------
    flange_x : float
        Station of the flange, m.
    sag : float
        Forward face above the aft face, m (+ when the forward piece sits higher).
    gap : float
        Opening at the top less opening at the bottom, m (+ open at the top).
    flange_diameter : float
        m (the gap is the relative face rotation times this diameter).
    aft, fore : ConditionResult
        Elastic lines of the two pieces (fore piece stations from the flange).
    """

    flange_x: float
    sag: float
    gap: float
    flange_diameter: float
    aft: ConditionResult
    fore: ConditionResult


def _split_segments(segments: tuple[ShaftSegment, ...], cut: float) -> tuple[list, list]:
    aft, fore, start = [], [], 0.0
    for segment in segments:
        end = start + segment.length
        if end <= cut + 1e-9:
            aft.append(segment)
        elif start >= cut - 1e-9:
            fore.append(segment)
        else:  # the cut falls inside this segment
            fraction = (cut - start) / segment.length
            outer, inner = segment.diameters_at(np.array(fraction))
            aft.append(
                replace(segment, length=cut - start, outer_diameter_end=float(outer), inner_diameter_end=float(inner))
            )
            fore.append(replace(segment, length=end - cut, outer_diameter=float(outer), inner_diameter=float(inner)))
        start = end
    return aft, fore


def sag_and_gap(
    line: ShaftLine,
    flange_x: float,
    temporary_supports: tuple[Bearing, ...] = (),
    condition: Condition | None = None,
    flange_diameter: float | None = None,
) -> SagGap:
    """Sag and gap at the flange at ``flange_x`` with the line uncoupled there."""
    if not 0.0 < flange_x < line.length:
        raise InputError("flange_x", flange_x, "m", f"inside the shaft, (0, {line.length:.4g})")
    condition = condition or Condition("erection")
    aft_segments, fore_segments = _split_segments(line.segments, flange_x)
    supports = tuple(line.bearings) + tuple(temporary_supports)
    aft_bearings = tuple(b for b in supports if b.x < flange_x)
    fore_bearings = tuple(replace(b, x=b.x - flange_x) for b in supports if b.x > flange_x)
    pieces = []
    for name, segments, bearings, shift in (
        ("aft", aft_segments, aft_bearings, 0.0),
        ("fore", fore_segments, fore_bearings, flange_x),
    ):
        if sum(b.points if b.support == "multi_point" else 1 for b in bearings) < 2:
            raise InputError(
                "temporary_supports",
                len(temporary_supports),
                "",
                f"supports enough for the {name} piece to stand (at least two under it)",
            )
        start, end = shift, shift + sum(s.length for s in segments)

        def inside(x: float, lo: float = start, hi: float = end) -> bool:
            return lo <= x <= hi

        piece = ShaftLine(
            segments=tuple(segments),
            bearings=bearings,
            point_loads=tuple(replace(p, x=p.x - shift) for p in line.point_loads if inside(p.x)),
            masses=tuple(replace(m, x=m.x - shift) for m in line.masses if inside(m.x)),
            distributed_loads=tuple(
                replace(
                    d,
                    x_start=max(d.x_start, shift) - shift,
                    x_end=min(d.x_end, shift + sum(s.length for s in segments)) - shift,
                )
                for d in line.distributed_loads
                if d.x_end > shift and d.x_start < shift + sum(s.length for s in segments)
            ),
            propeller=line.propeller if name == "aft" else None,
            self_weight=line.self_weight,
            gravity=line.gravity,
            element_length=line.element_length,
            beam_theory=line.beam_theory,
        )
        names = {b.name for b in bearings}
        local = Condition(
            condition.name,
            offsets_y={k: v for k, v in condition.offsets_y.items() if k in names},
            offsets_z={k: v for k, v in condition.offsets_z.items() if k in names},
            propeller_immersion=condition.propeller_immersion,
        )
        pieces.append(AlignmentModel(piece).solve_condition(local))
    aft, fore = pieces
    diameter = flange_diameter if flange_diameter is not None else line.outer_diameter_at(flange_x)
    sag = float(fore.deflection_y[0] - aft.deflection_y[-1])
    gap = float((aft.rotation_y[-1] - fore.rotation_y[0]) * diameter)
    return SagGap(flange_x, sag, gap, diameter, aft, fore)
