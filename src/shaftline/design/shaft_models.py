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
from shaftline.shaft.local import LocalShaftModel, solve_local_model

__all__ = ["bent_shaft", "linear_shaft", "seed004_local_model"]


def seed004_local_model() -> LocalShaftModel:
    """The local shaft model of seed 004 Table 4-5 / 5-1 (its edge offsets set per psi_x by
    :func:`bent_shaft`): L = 1.05 m, D = 0.52 m, overhangs 0.407 and 0.5412 m, M_aft = 409948 N m
    (nose-up in shaftline's sign), F_aft = -202598.2 N, F_fore = -107261.7 N, fore slope
    0.465 mrad, 16343 N/m, E = 206 GPa, shear area = section area (the seed's tables are
    reproduced so, tests/shaft/test_local_seed004.py)."""
    return LocalShaftModel(
        bearing_length=1.05,
        shaft_diameter=0.52,
        aft_overhang=0.407,
        fore_length=0.5412,
        aft_force=-202598.2,
        aft_moment=409948.0,
        fore_force=-107261.7,
        fore_rotation=0.000465,
        weight_per_length=16343.0,
        beam_theory="timoshenko",
        shear_area_factor=1.0,
    )


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
