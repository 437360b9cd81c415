"""The journal a design search holds fixed: the seed's linear shaft (a straight journal tilted
by psi_x 2c/L) or its bent shaft (the elastic line of the local shaft model across the bearing,
seed 004 Sect. 4.5.2-4.5.4, whose chord has the same tilt).
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import replace

from shaftline.design.problem import SlopeDesignProblem
from shaftline.design.sweep import linear_shaft
from shaftline.errors import InputError
from shaftline.shaft.local import LocalShaftModel, seed004_local_model, solve_local_model

__all__ = ["bent_shaft", "linear_shaft", "seed004_local_model"]


def bent_shaft(
    problem: SlopeDesignProblem, local: LocalShaftModel, aft_share: float = 0.25
) -> Callable[[float], SlopeDesignProblem]:
    """``psi_x -> problem`` whose journal is the local model's elastic line across the bearing.

    The bearing edges of ``local`` are offset so that the chord across the bearing rises
    ``psi_x 2c`` over L, ``aft_share`` of it below the reference (seed 004 Table 5-29 puts a
    quarter below); the journal is that line (its chord as the tilt, the rest as the bent
    journal).

    Raises
    ------
    InputError
        ``"local.bearing_length"`` differing from the film's length.
    """
    geometry = problem.film.geometry
    if abs(local.bearing_length - geometry.length) > 1e-9 * geometry.length:
        raise InputError("local.bearing_length", local.bearing_length, "m", f"the film's length {geometry.length}")
    c = geometry.radial_clearance

    def at(ratio: float) -> SlopeDesignProblem:
        rise = ratio * 2.0 * c
        model = replace(local, aft_edge_offset=-aft_share * rise, fore_edge_offset=(1.0 - aft_share) * rise)
        slope, bent = solve_local_model(model).bent_journal()
        film = replace(problem.film, geometry=replace(geometry, bent_journal=bent))
        return replace(problem, film=film, tilt_y=slope)

    return at
