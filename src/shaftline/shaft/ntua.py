"""The seed 004 (NTUA) shaft line: the local model's end conditions as one alignment case.

Seed 004 (Rossopoulos 2018, Table 4-5 / 5-1) gives only the local model around the aft
stern-tube bearing (:mod:`shaftline.shaft.local`): a 0.52 m solid shaft with the propeller
force and moment at its aft end, the 1.05 m bearing, a forward length whose end carries a
force and an imposed rotation. :func:`ntua_shaft_line` builds a whole line around it that
the coupled alignment (:mod:`shaftline.shaft.coupled`) and the fast path
(:mod:`shaftline.shaft.fast_path`) can both solve.

What the line reproduces (docs/validation.md, "The seed 004 shaft line"):

* exactly: the shaft (D, E, weight 16343 N/m, Timoshenko with shear area = section area,
  the reading that reproduces the seed's Tables 5-29/5-30), the propeller force and
  moment at x = 0, the aft bearing (L, clearance, 10 shaft elements across it) and the film
  (100 x 60 grid, 90 rpm, 0.07 Pa s);
* by the offsets of the two other bearings (solved here): the point-support reaction at
  the aft bearing, 309.86 kN (the seed's W = F_Yaft + F_Yfore, the load behind its
  Sommerfeld number), and the chord slope of the shaft across it, ``psi_x * 2c/L``;
* not: the seed's fore-end rotation, +0.465 mrad at x = 1.9982 m. With the propeller's
  force and hogging moment and a reaction of 309.86 kN, statics fixes the bending moment
  from the propeller to that station (-410 to -606 kN m, hogging throughout), so the
  rotation there is the chord slope less about 0.8 mrad: -0.55 mrad for psi_x = 0.3 with
  the support at mid-length. The seed's local model reaches +0.465 mrad only through its
  forward edge support pulling the shaft down (-746 kN at psi_x = 0): a line on real
  bearings cannot. Nor the seed's F_Yfore (-107.26 kN = reaction less propeller force,
  the shaft's own weight left out): here the shear at that station is -74.6 kN.

The other bearings are not in the seed; they are a plausible layout (engineering choice):
a forward stern-tube bearing 0.6 m long at 6.0 m and an intermediate bearing 0.5 m long at
13.0 m on a 14.5 m shaft, both point supports.
"""

from __future__ import annotations

import math
from dataclasses import replace

import numpy as np

from shaftline.errors import InputError, require_finite, require_positive
from shaftline.film.geometry import BearingGeometry, BoreAnchor, BoreSegment
from shaftline.film.problem import BearingProblem, OperatingPoint, SolverOptions
from shaftline.shaft.alignment import AlignmentModel
from shaftline.shaft.film_supports import FilmSupport
from shaftline.shaft.model import GRAVITY, Bearing, Condition, PointLoad, ShaftLine, ShaftSegment

__all__ = [
    "AFT_OVERHANG",
    "BEARING_LENGTH",
    "FORE_FORCE",
    "FORE_LENGTH",
    "FORE_ROTATION",
    "LOCAL_SPAN_END",
    "PROPELLER_FORCE",
    "PROPELLER_MOMENT",
    "RADIAL_CLEARANCE",
    "REACTION",
    "SHAFT_DIAMETER",
    "SPEED",
    "VISCOSITY",
    "WEIGHT_PER_LENGTH",
    "ntua_shaft_line",
]

# Seed 004 Table 4-5 / 5-1 (see ../shared/reference/seed004-chapter5.md, Sect. 0).
BEARING_LENGTH = 1.05  # m
SHAFT_DIAMETER = 0.52  # m, solid
RADIAL_CLEARANCE = 0.45e-3  # m (the seed's "c" 0.9 mm is diametral)
AFT_OVERHANG = 0.407  # m, propeller end to the aft bearing edge
FORE_LENGTH = 0.5412  # m, forward bearing edge to the end of the local model
LOCAL_SPAN_END = AFT_OVERHANG + BEARING_LENGTH + FORE_LENGTH  # 1.9982 m from the aft end
PROPELLER_FORCE = -202598.2  # N (+ up)
PROPELLER_MOMENT = 409948.0  # N m, nose-up in shaftline's sign: hogging at the propeller end
FORE_FORCE = -107261.7  # N, the seed's force at the end of the local model
FORE_ROTATION = 0.465e-3  # rad, the seed's imposed rotation there
WEIGHT_PER_LENGTH = 16343.0  # N/m
YOUNGS_MODULUS = 206e9  # Pa
SPEED = 90.0 * math.pi / 30.0  # rad/s (90 rpm)
VISCOSITY = 0.07  # Pa s (the seed prints "0.07 mPa s"; only Pa s gives its S = 0.0618)
#: The seed's bearing load W = -(F_Yaft + F_Yfore), N: the aft-bearing reaction of its alignment.
REACTION = -(PROPELLER_FORCE + FORE_FORCE)

#: Layout of the bearings the seed does not give (engineering choice): (x, length), m.
FORWARD_STERN_TUBE = (6.0, 0.6)
INTERMEDIATE = (13.0, 0.5)
SHAFT_LENGTH = 14.5


def _line(
    offsets: np.ndarray,
    forward: tuple[float, float],
    intermediate: tuple[float, float],
    length: float,
) -> ShaftLine:
    area = math.pi * SHAFT_DIAMETER**2 / 4.0
    density = WEIGHT_PER_LENGTH / (GRAVITY * area)  # 7847 kg/m^3: the seed's 16343 N/m exactly
    aft_x = AFT_OVERHANG + 0.5 * BEARING_LENGTH
    return ShaftLine(
        segments=(
            ShaftSegment(length, SHAFT_DIAMETER, youngs_modulus=YOUNGS_MODULUS, density=density, shear_area_factor=1.0),
        ),
        bearings=(
            Bearing("aft stern tube", aft_x, BEARING_LENGTH, vertical_clearance=2.0 * RADIAL_CLEARANCE),
            Bearing("forward stern tube", forward[0], forward[1], offset_y=float(offsets[0])),
            Bearing("intermediate", intermediate[0], intermediate[1], offset_y=float(offsets[1])),
        ),
        point_loads=(
            PointLoad(0.0, force_y=PROPELLER_FORCE, moment_vertical=PROPELLER_MOMENT, name="propeller"),
            # No load: a node at the end of the seed's local model, where its rotation is read.
            PointLoad(LOCAL_SPAN_END, name="end of the seed's local model"),
        ),
        # Ten elements across the aft bearing, as the seed (Table 5-1).
        element_length=BEARING_LENGTH / 10,
    )


def ntua_shaft_line(
    psi_x: float = 0.3,
    *,
    reaction: float = REACTION,
    bore: tuple[BoreSegment, ...] = (),
    bore_anchor: BoreAnchor = "fore",
    grid: tuple[int, int] = (100, 60),
    options: SolverOptions | None = None,
    speed: float = SPEED,
    viscosity: float = VISCOSITY,
    forward_bearing: tuple[float, float] = FORWARD_STERN_TUBE,
    intermediate_bearing: tuple[float, float] = INTERMEDIATE,
    shaft_length: float = SHAFT_LENGTH,
) -> tuple[ShaftLine, FilmSupport]:
    """The seed 004 shaft line and the film of its aft stern-tube bearing.

    The offsets of the forward stern-tube and intermediate bearings (the aft bearing at
    offset 0) are solved so that the point-support alignment gives the aft bearing the
    reaction ``reaction`` and the chord slope ``psi_x * 2c/L`` across it. While every
    bearing is in contact the alignment is affine in the offsets, so one linear solve is
    exact; the result is checked with lift-off allowed.

    Parameters
    ----------
    psi_x : float
        Misalignment ratio of the aft bearing in the point-support alignment: chord slope of
        the shaft across the bearing over ``2c/L`` (positive: shaft rising forward, aft end
        low). Seed 004 Table 5-3 uses 0.3.
    reaction : float
        Point-support reaction at the aft bearing, N (default the seed's 309 859.9 N).
    bore : tuple of BoreSegment
        Slope boring of the aft bearing (film geometry), e.g. the seed's single slope
        ``(BoreSegment(1.0, 0.3 * 2c/L),)``.
    bore_anchor : BoreAnchor
        Where the slope-bored bore meets the nominal line (:class:`BearingGeometry`).
    grid : (int, int)
        Film nodes (axial, circumferential); the seed's 100 x 60 by default.
    options : SolverOptions, optional
        Film options; ``grid`` sets their node counts.
    speed : float
        Shaft speed, rad/s (90 rpm).
    viscosity : float
        Pa s.
    forward_bearing, intermediate_bearing : (float, float)
        Position of the bearing centre and length, m.
    shaft_length : float
        m.

    Returns
    -------
    (ShaftLine, FilmSupport)
        The line with the aft bearing as a point support at mid-length (the seed's
        alignment, ``l_cp = L/2``), and the film that replaces it in
        :class:`~shaftline.shaft.coupled.CoupledAlignment`.

    Raises
    ------
    InputError
        ``psi_x`` or ``reaction`` that the layout cannot give with every bearing loaded.

    Examples
    --------
    >>> from shaftline.shaft import AlignmentModel
    >>> line, film = ntua_shaft_line(0.3, grid=(41, 30))
    >>> aft = AlignmentModel(line).solve()[0].bearing("aft stern tube")
    >>> round(aft.reaction_y / 1e3, 2), round(aft.relative_slope / (2 * 0.45e-3 / 1.05), 4)
    (309.86, 0.3)
    """
    psi_x = require_finite("psi_x", psi_x)
    require_positive("reaction", reaction, "N")
    require_positive("speed", speed, "rad/s")
    require_positive("viscosity", viscosity, "Pa*s")
    offsets = _offsets_for_aft_bearing(psi_x, reaction, forward_bearing, intermediate_bearing, shaft_length)
    line = _line(offsets, forward_bearing, intermediate_bearing, shaft_length)
    problem = _aft_film_problem(bore, bore_anchor, grid, options, speed, viscosity)
    return line, FilmSupport(line.bearings[0].name, problem, elements=10)


def _offsets_for_aft_bearing(
    psi_x: float,
    reaction: float,
    forward_bearing: tuple[float, float],
    intermediate_bearing: tuple[float, float],
    shaft_length: float,
) -> np.ndarray:
    """Offsets of the forward stern-tube and intermediate bearings, m, that give the aft
    bearing the point-support ``reaction`` (N) and the misalignment ratio ``psi_x``
    (arguments as :func:`ntua_shaft_line`).

    Raises
    ------
    InputError
        No such offsets with every bearing loaded.
    """
    target = np.array([reaction, psi_x * 2.0 * RADIAL_CLEARANCE / BEARING_LENGTH])
    condition = Condition("base")

    def aft_result(offsets: np.ndarray, two_sided: bool) -> tuple[np.ndarray, list[str]]:
        line = _line(offsets, forward_bearing, intermediate_bearing, shaft_length)
        result = AlignmentModel(line).solve_condition(condition, two_sided=two_sided)
        aft = result.bearings[0]
        return np.array([aft.reaction_y, aft.relative_slope]), [b.contact for b in result.bearings]

    # Affine in the offsets with every support held: three evaluations give it exactly.
    step = 1e-3
    base, _ = aft_result(np.zeros(2), True)
    jacobian = np.column_stack([(aft_result(step * np.eye(2)[k], True)[0] - base) / step for k in range(2)])
    offsets = np.linalg.solve(jacobian, target - base)
    try:
        reached, contacts = aft_result(offsets, False)
    except InputError:
        reached, contacts = np.full(2, np.nan), ["lifted"]
    if any(state != "bottom" for state in contacts) or not np.allclose(reached, target, rtol=1e-6, atol=1e-12):
        raise InputError(
            "psi_x",
            psi_x,
            "",
            f"a misalignment the layout gives with every bearing loaded at a reaction of {reaction:.6g} N "
            f"(offsets {offsets[0] * 1e3:.3g}, {offsets[1] * 1e3:.3g} mm lift a bearing)",
        )
    return offsets


def _aft_film_problem(
    bore: tuple[BoreSegment, ...],
    bore_anchor: BoreAnchor,
    grid: tuple[int, int],
    options: SolverOptions | None,
    speed: float,
    viscosity: float,
) -> BearingProblem:
    """The film of the aft stern-tube bearing at ``speed`` (rad/s) with an oil of
    ``viscosity`` (Pa s) and the seed's density (arguments as :func:`ntua_shaft_line`)."""
    solver = replace(options or SolverOptions(), axial_nodes=int(grid[0]), circumferential_nodes=int(grid[1]))
    return BearingProblem(
        BearingGeometry(
            BEARING_LENGTH, SHAFT_DIAMETER, RADIAL_CLEARANCE, bore=tuple(bore), bore_anchor=bore_anchor, rotation=1
        ),
        OperatingPoint(speed=speed, viscosity=viscosity, density=890.0),
        solver,
    )
