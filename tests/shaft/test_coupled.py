"""Checks of the elastohydrodynamic alignment (shaftline.shaft.coupled, issue 11 "Checks").

The line of most checks is a 14 m shaft of seed 004's stern-tube bearing (L = 1.05 m,
D = 0.52 m, c = 0.45 mm, 90 rpm, 0.07 Pa s; Table 5-1) with the propeller end force of
Table 4-5 and a nose-down end moment (with the seed's nose-up sign the film reaches its
floor and the solver falls back to contact, which the last checks use). Film grids are
coarse (40 x 36) unless a check needs more: the checks are about the coupling, and the
film's own accuracy has its validation tests in tests/film.

References and tolerances are given check by check. Docs: docs/theory.md,
"Elastohydrodynamic alignment"; docs/validation.md, "Coupled alignment".
"""

from __future__ import annotations

import math
import time
from dataclasses import replace

import numpy as np
import pytest

from shaftline.errors import InputError
from shaftline.film import BearingProblem, JournalBearing, OperatingPoint, SolverOptions
from shaftline.film.geometry import BearingGeometry, BentJournal, BoreSegment, JournalPosition
from shaftline.shaft import AlignmentModel, Bearing, Condition, ShaftLine, ShaftSegment
from shaftline.shaft.coupled import CoupledAlignment, CouplingOptions, FilmSupport
from shaftline.shaft.model import PointLoad

CLEARANCE = 0.45e-3
AFT_X = 0.407 + 0.525  # aft stern-tube bearing centre: the seed's 0.407 m overhang
END_MOMENT = -409948.0  # N m, Table 4-5's magnitude, nose-down


def ntua_line(moment: float = END_MOMENT, **changes) -> ShaftLine:
    line = ShaftLine(
        segments=(ShaftSegment(length=14.0, outer_diameter=0.52),),
        bearings=(
            Bearing("aft", AFT_X, 1.05, support="multi_point", points=6),
            Bearing("fwd", 6.0, 0.6),
            Bearing("int", 13.0, 0.5, offset_y=-0.5e-3),
        ),
        point_loads=(PointLoad(0.0, force_y=-202598.2, moment_vertical=moment),),
        element_length=0.25,
    )
    return replace(line, **changes)


def ntua_film(
    axial: int = 40, circumferential: int = 36, viscosity: float = 0.07, length: float = 1.05
) -> BearingProblem:
    return BearingProblem(
        BearingGeometry(length, 0.52, CLEARANCE),
        OperatingPoint(speed=9.4248, viscosity=viscosity),
        SolverOptions(axial_nodes=axial, circumferential_nodes=circumferential),
    )


def film_row_forces(film) -> np.ndarray:
    """Film force per grid row, (2, nz), N, from the reported line load (trapezoid rows)."""
    weights = np.full(film.z.size, film.z[1] - film.z[0])
    weights[[0, -1]] *= 0.5
    return film.line_load * weights[None, :]


# -- 1. global equilibrium ------------------------------------------------------------------
def test_global_equilibrium_of_forces_and_moments_in_both_planes():
    """Statics of the free shaft (Timoshenko, Strength of Materials I, ch. 1): the film
    forces and every other reaction balance the applied loads, forces and moments about
    x = 0, in both planes. A horizontal end load and moment make the horizontal plane carry
    something of its own. The only imbalance the method leaves is the auxiliary springs'
    force k0 (s - G(s)) (docs/theory.md), at convergence below 2 x the final film mismatch
    (2.6e-8 here) times the film force; 1e-7 of the applied load allows it with room."""
    line = ntua_line(
        point_loads=(
            PointLoad(0.0, force_y=-202598.2, moment_vertical=END_MOMENT),
            PointLoad(10.0, force_z=15e3, moment_horizontal=-8e3),
        )
    )
    result = CoupledAlignment(line, [FilmSupport("aft", ntua_film())]).solve()
    assert result.converged, result.message
    segment = line.segments[0]
    weight = segment.density * line.gravity * math.pi / 4 * segment.outer_diameter**2 * 14.0
    applied_y = -weight - 202598.2
    applied_z = 15e3
    applied_moment_y = -weight * 7.0 + END_MOMENT  # about x = 0, + nose-up
    applied_moment_z = 15e3 * 10.0 - 8e3

    film = result.film("aft")
    rows = film_row_forces(film)
    x_rows = AFT_X - 0.525 + film.z
    reactions = {b.name: b for b in result.condition.bearings}
    assert reactions["aft"].contact == "film"
    assert reactions["aft"].reaction_y == pytest.approx(film.force_y, rel=1e-12)
    assert rows.sum(axis=1) == pytest.approx([film.force_y, film.force_z], rel=1e-9)
    sum_y = film.force_y + reactions["fwd"].reaction_y + reactions["int"].reaction_y
    sum_z = film.force_z + reactions["fwd"].reaction_z + reactions["int"].reaction_z
    moment_y = x_rows @ rows[0] + 6.0 * reactions["fwd"].reaction_y + 13.0 * reactions["int"].reaction_y
    moment_z = x_rows @ rows[1] + 6.0 * reactions["fwd"].reaction_z + 13.0 * reactions["int"].reaction_z
    scale = abs(applied_y)
    assert abs(sum_y + applied_y) < 1e-7 * scale, (sum_y, applied_y)
    assert abs(sum_z + applied_z) < 1e-7 * scale, (sum_z, applied_z)
    assert abs(moment_y + applied_moment_y) < 1e-7 * scale * 14.0, (moment_y, applied_moment_y)
    assert abs(moment_z + applied_moment_z) < 1e-7 * scale * 14.0, (moment_z, applied_moment_z)
    # Each plane's resultant: the force and the first moment of the rows about mid-length; the
    # support point is its place from mid-length, + forward (the sign convention of
    # FilmBearingResult), in each plane on its own.
    arm = film.z - 0.525
    assert film.moment_y == pytest.approx(arm @ rows[0], rel=1e-9)
    assert film.moment_z == pytest.approx(arm @ rows[1], rel=1e-9, abs=1e-9 * abs(film.force_y))
    assert film.support_point_y == pytest.approx(film.moment_y / film.force_y, rel=1e-9)
    assert film.support_point_y > 0.0  # nose-down end moment: the film load moves forward


# -- 2. each film reproduces its own force --------------------------------------------------
def test_each_film_reproduces_its_force_when_solved_again_on_its_journal_line():
    """The Reynolds solution for a given film is unique (the cavitated set found by the
    active-set solver does not depend on its start), so the film solved again from a cold
    start on the reported journal line, once through film_load and once through the
    classical bent-journal geometry and solve_at (another code path: the way the fast path
    and the seed give the journal), gives the reported force to round-off: 1e-9."""
    result = CoupledAlignment(ntua_line(), [FilmSupport("aft", ntua_film())]).solve()
    assert result.converged, result.message
    film = result.film("aft")
    fresh = JournalBearing.from_problem(ntua_film())
    again = fresh.film_load(film.centre_y, film.centre_z, warm_start=False)
    assert again.row_force.sum(axis=1) == pytest.approx([film.force_y, film.force_z], rel=1e-9)
    assert again.row_force == pytest.approx(film_row_forces(film), rel=1e-9, abs=1e-9 * abs(film.force_y))

    z, length = film.z, 1.05
    mid_y, mid_z = np.interp(0.5 * length, z, film.centre_y), np.interp(0.5 * length, z, film.centre_z)
    tilt_y = (film.centre_y[-1] - film.centre_y[0]) / length
    tilt_z = (film.centre_z[-1] - film.centre_z[0]) / length
    arm = z - 0.5 * length
    bent = BentJournal(z=z, dy=film.centre_y - mid_y - tilt_y * arm, dz=film.centre_z - mid_z - tilt_z * arm)
    problem = ntua_film()
    classical = JournalBearing(replace(problem.geometry, bent_journal=bent), problem.operating, problem.options)
    state = classical.solve_at(JournalPosition(ey=mid_y, ez=mid_z, tilt_y=tilt_y, tilt_z=tilt_z), warm_start=False)
    assert [state.force_y, state.force_z] == pytest.approx([film.force_y, film.force_z], rel=1e-9)
    assert state.min_film_thickness == pytest.approx(film.state.min_film_thickness, rel=1e-9)


def test_the_film_journal_line_is_the_shafts_elastic_line():
    """The journal the film was solved for lies on the shaft's converged elastic line: at the
    shaft nodes inside the bearing, deflection less the bore centre line (offset + c,
    docs/theory.md) equals the journal centre line, linearly interpolated on the film grid.
    Tolerance: the film mismatch allowed (1e-5 c) plus the interpolation error h^2 kappa / 8
    of the 27 mm film rows (curvature M/EI <= 1e-3 /m: 1e-7 m); 0.05 % of c."""
    result = CoupledAlignment(ntua_line(), [FilmSupport("aft", ntua_film())]).solve()
    film = result.film("aft")
    x = result.condition.x
    inside = (x >= AFT_X - 0.525 - 1e-9) & (x <= AFT_X + 0.525 + 1e-9)
    journal_y = np.interp(x[inside] - (AFT_X - 0.525), film.z, film.centre_y) + CLEARANCE
    journal_z = np.interp(x[inside] - (AFT_X - 0.525), film.z, film.centre_z)
    assert np.abs(result.condition.deflection_y[inside] - journal_y).max() < 5e-4 * CLEARANCE
    assert np.abs(result.condition.deflection_z[inside] - journal_z).max() < 5e-4 * CLEARANCE
    assert film.relative_slope == pytest.approx(
        result.condition.bearing("aft").relative_slope, abs=1e-3 * 2 * CLEARANCE
    )


def test_condition_offsets_act_as_the_bearings_own_offsets():
    """The bore centre line (offset + condition offset + c + slope) enters the film, the
    auxiliary springs and the start separately (docs/theory.md (H2)); a condition's offsets
    must give exactly what the same offsets written into the bearings give (the same
    arithmetic: identical to round-off, 1e-9). A slope-bored bearing's relative slope is the
    journal's less the bore's, in the film result and the bearing result alike."""
    line = ntua_line(
        conditions=(Condition("hot", offsets_y={"aft": 0.2e-3, "int": -0.1e-3}, offsets_z={"aft": 0.1e-3}),)
    )
    by_condition = CoupledAlignment(line, [FilmSupport("aft", ntua_film())]).solve(line.conditions[0])
    aft, fwd, intermediate = line.bearings
    moved = ntua_line(
        bearings=(
            replace(aft, offset_y=0.2e-3, offset_z=0.1e-3),
            fwd,
            replace(intermediate, offset_y=intermediate.offset_y - 0.1e-3),
        )
    )
    by_line = CoupledAlignment(moved, [FilmSupport("aft", ntua_film())]).solve()
    assert by_condition.converged and by_line.converged
    for a, b in zip(by_condition.condition.bearings, by_line.condition.bearings, strict=True):
        assert (a.reaction_y, a.reaction_z) == pytest.approx((b.reaction_y, b.reaction_z), rel=1e-9, abs=1e-6)
    assert by_condition.film("aft").centre_y == pytest.approx(by_line.film("aft").centre_y, abs=1e-9 * CLEARANCE)
    # ... and they do move the film: without them the aft film carries 1 % less.
    unmoved = CoupledAlignment(ntua_line(), [FilmSupport("aft", ntua_film())]).solve()
    assert by_condition.film("aft").force_y != pytest.approx(unmoved.film("aft").force_y, rel=1e-3)

    sloped = ntua_line(bearings=(replace(aft, slope=-0.2e-3), fwd, intermediate))
    result = CoupledAlignment(sloped, [FilmSupport("aft", ntua_film())]).solve()
    assert result.converged, result.message
    film, bearing = result.film("aft"), result.condition.bearing("aft")
    assert film.relative_slope == pytest.approx(bearing.relative_slope, abs=1e-3 * 2 * CLEARANCE / 1.05)
    assert bearing.shaft_slope - (-0.2e-3) == pytest.approx(bearing.relative_slope, abs=1e-12)


def test_progress_reports_every_newton_iteration():
    """The progress callback (long runs) sees each iteration's number and film mismatch: the
    residual history after the start."""
    seen = []
    result = CoupledAlignment(ntua_line(), [FilmSupport("aft", ntua_film())]).solve(
        progress=lambda k, r: seen.append((k, r))
    )
    assert [k for k, _ in seen] == list(range(1, result.iterations + 1))
    assert [r for _, r in seen] == result.residual_history[1:]


# -- 3. limits -------------------------------------------------------------------------------
def test_very_high_speed_times_viscosity_clamps_the_shaft_at_the_bore_centre_line():
    """Limit (a). As eta*omega grows the film stiffness grows with it, the journal centres in
    the bore (e -> 0) and the film holds the shaft's deflection at every grid row to the bore
    centre line: a shaft clamped (built in) over the bearing length at offset + c. The rigid
    model of that limit is the AlignmentModel with the bearing as N two-sided rigid points at
    offset + c, N -> infinity; its reactions converge as 1/N (checked: the difference ratio
    for N = 10, 25, 50 is 3, as 1/N predicts), so the limit is the Richardson value
    2 R(50) - R(25). The film's approach is slow because its pressure vanishes at the bearing
    edges, where the clamping couples of the rigid limit sit: the largest reaction gap, as a
    share of the line's load, falls by under 2x per decade of eta*omega (0.38 % at 1e4,
    0.22 % at 1e5 x the seed's value); we require it to fall at every step, the journal to
    centre and the gap at 1e5 below 0.3 %."""
    line = ntua_line()
    rigid = {}
    for n in (10, 25, 50):
        clamped = replace(
            line,
            bearings=(replace(line.bearings[0], points=n, one_sided=False, offset_y=CLEARANCE), *line.bearings[1:]),
        )
        result = AlignmentModel(clamped).solve_condition(clamped.all_conditions()[0])
        rigid[n] = np.array([b.reaction_y for b in result.bearings])
    ratio = (rigid[25] - rigid[10]) / (rigid[50] - rigid[25])
    assert ratio == pytest.approx(3.0, rel=0.05), ratio
    limit = 2 * rigid[50] - rigid[25]

    gaps, eccentricities, slopes = [], [], []
    for factor in (1.0, 1e2, 1e4, 1e5):
        result = CoupledAlignment(line, [FilmSupport("aft", ntua_film(viscosity=0.07 * factor))]).solve()
        assert result.converged, (factor, result.message)
        reactions = np.array([b.reaction_y for b in result.condition.bearings])
        gaps.append(np.max(np.abs(reactions - limit)) / limit.sum())
        film = result.film("aft")
        eccentricities.append(film.state.eccentricity_ratio)
        slopes.append(abs(film.relative_slope) / (2 * CLEARANCE / 1.05))
        # Horizontally the rigid limit carries nothing: the films' side force goes too.
        assert abs(film.force_z) < 0.1 * abs(film.force_y)
    assert np.all(np.diff(gaps) < 0), gaps
    assert np.all(np.diff(eccentricities) < 0), eccentricities
    assert np.all(np.diff(slopes) < 0), slopes
    assert gaps[-1] < 3e-3, gaps
    assert eccentricities[-1] < 1e-3 and slopes[-1] < 0.02, (eccentricities, slopes)


def test_a_stiff_short_film_bearing_acts_as_a_point_support_at_the_bore_centre():
    """Limit (b). A short film bearing (L/D = 0.1) made stiff by eta*omega: the film's
    translational stiffness grows as eta*omega while its tilt stiffness (~ k L^2 / 12) stays
    small against the shaft's bending stiffness, so the shaft passes through the bore centre
    with its own slope: the point-support alignment with that bearing as a rigid two-sided
    point at offset + c. The remaining gap is the vertical journal travel (e c cos(attitude),
    mostly sideways at small e) times the line's influence coefficients plus the tilt
    restraint; 1e-4 of the reaction at 1e5 x the seed's eta*omega (observed 2e-5), and the
    gap must shrink at every step. The shaft slope passes the bearing unrestrained: its
    relative slope is the point model's to 2 % (what the tilt stiffness takes)."""
    base = ntua_line()
    length = 0.05
    short = replace(base, bearings=(base.bearings[0], replace(base.bearings[1], length=length), base.bearings[2]))
    point = replace(
        short,
        bearings=(
            short.bearings[0],
            replace(short.bearings[1], offset_y=CLEARANCE, one_sided=False),
            short.bearings[2],
        ),
    )
    reference = AlignmentModel(point).solve_condition(point.all_conditions()[0])
    expected = np.array([b.reaction_y for b in reference.bearings])
    gaps = []
    for factor in (1e2, 1e3, 1e4, 1e5):
        problem = ntua_film(axial=24, viscosity=0.07 * factor, length=length)
        result = CoupledAlignment(short, [FilmSupport("fwd", problem, elements=4)]).solve()
        assert result.converged, (factor, result.message)
        reactions = np.array([b.reaction_y for b in result.condition.bearings])
        gaps.append(np.max(np.abs(reactions - expected) / expected))
    assert np.all(np.diff(gaps) < 0), gaps
    assert gaps[-1] < 1e-4, gaps
    film = result.film("fwd")
    assert film.relative_slope == pytest.approx(reference.bearing("fwd").relative_slope, rel=0.02)
    assert abs(film.force_z) < 5e-3 * film.force_y


def symmetric_problem() -> BearingProblem:
    return BearingProblem(
        BearingGeometry(0.4, 0.4, 0.3e-3),
        OperatingPoint(speed=10.0, viscosity=0.05),
        SolverOptions(axial_nodes=40, circumferential_nodes=36),
    )


def test_a_symmetric_line_on_two_identical_films_is_symmetric():
    """Limit (c). An 8 m shaft on two identical film bearings at 2 and 6 m, loads mirror
    symmetric about x = 4 m (a middle load and two equal end loads). Mirroring x about 4 m
    maps the line and each film onto the other (the rotation about the shaft axis is
    unchanged by that mirror), so the reactions, the horizontal film forces, hmin and e are
    equal, the relative slopes and support points opposite, the elastic line symmetric and
    level at mid-span. Nothing in the solver imposes that, so it holds to the solver's
    tolerances: 1e-6 of the force (force_tolerance) and 1e-5 c of the line
    (film_tolerance). With no horizontal support but the films, each horizontal film force
    is zero: the journals move sideways until the film force is vertical."""
    line = ShaftLine(
        segments=(ShaftSegment(8.0, 0.4),),
        bearings=(Bearing("a", 2.0, 0.4), Bearing("b", 6.0, 0.4)),
        point_loads=(
            PointLoad(4.0, force_y=-150e3),
            PointLoad(0.0, force_y=-30e3),
            PointLoad(8.0, force_y=-30e3),
        ),
        element_length=0.2,
    )
    result = CoupledAlignment(
        line, [FilmSupport("a", symmetric_problem()), FilmSupport("b", symmetric_problem())]
    ).solve()
    assert result.converged, result.message
    a, b = result.film("a"), result.film("b")
    assert not a.contact and not b.contact
    assert a.force_y == pytest.approx(b.force_y, rel=1e-6)
    assert a.force_z == pytest.approx(b.force_z, abs=1e-6 * a.force_y)
    assert abs(a.force_z) < 1e-6 * a.force_y
    assert a.state.eccentricity_ratio == pytest.approx(b.state.eccentricity_ratio, abs=1e-5)
    assert a.state.min_film_thickness == pytest.approx(b.state.min_film_thickness, abs=1e-5 * 0.3e-3)
    assert a.relative_slope == pytest.approx(-b.relative_slope, abs=1e-5 * 0.3e-3 / 0.4)
    assert a.support_point_y == pytest.approx(-b.support_point_y, abs=1e-6 * 0.4)
    condition = result.condition
    assert np.allclose(condition.x, 8.0 - condition.x[::-1])
    assert np.abs(condition.deflection_y - condition.deflection_y[::-1]).max() < 1e-5 * 0.3e-3
    assert np.abs(condition.deflection_z - condition.deflection_z[::-1]).max() < 1e-5 * 0.3e-3
    middle = int(np.argmin(np.abs(condition.x - 4.0)))
    assert abs(condition.rotation_y[middle]) < 1e-5 * 0.3e-3 / 0.4


def test_a_film_bearing_at_the_centre_of_a_symmetric_line_keeps_its_journal_level():
    """Limit (c), the level journal: a film bearing at the middle of a symmetric line (point
    bearings at both ends, self-weight only) lies on the mirror plane, so its journal is
    level in both planes (relative slope 0, support point at mid-length) and the two point
    bearings carry equal shares; tolerances as in the two-film check."""
    line = ShaftLine(
        segments=(ShaftSegment(8.0, 0.4),),
        bearings=(Bearing("a", 0.5, 0.4), Bearing("m", 4.0, 0.4), Bearing("b", 7.5, 0.4)),
        element_length=0.2,
    )
    result = CoupledAlignment(line, [FilmSupport("m", symmetric_problem())]).solve()
    assert result.converged, result.message
    film = result.film("m")
    assert abs(film.relative_slope) < 1e-5 * 0.3e-3 / 0.4
    assert abs((film.centre_z[-1] - film.centre_z[0]) / 0.4) < 1e-5 * 0.3e-3 / 0.4
    assert abs(film.support_point_y) < 1e-6 * 0.4
    a, b = result.condition.bearing("a"), result.condition.bearing("b")
    assert a.reaction_y == pytest.approx(b.reaction_y, rel=1e-6)
    assert a.reaction_z == pytest.approx(b.reaction_z, abs=1e-6 * a.reaction_y)
    assert film.force_y > a.reaction_y > 0


# -- 4. convergence with the film grid and the shaft elements -------------------------------
def observed_order(coarse: float, middle: float, fine: float, ratio: float = 2.0) -> float:
    return math.log(abs(coarse - middle) / abs(middle - fine)) / math.log(ratio)


def test_the_film_load_converges_with_the_film_grid():
    """Film grids 20 x 18, 40 x 36, 80 x 72 (both steps halved): the film resultant, its
    support point and the forward reaction converge with a positive observed order (the
    Reynolds discretisation is second order; about 2 is observed) and the last change is
    small: below 2e-4 of the force and 1 mm of support point (0.1 % of L)."""
    values = []
    for axial, circumferential in ((20, 18), (40, 36), (80, 72)):
        result = CoupledAlignment(ntua_line(), [FilmSupport("aft", ntua_film(axial, circumferential))]).solve()
        assert result.converged, result.message
        film = result.film("aft")
        values.append((film.force_y, film.support_point_y, result.condition.bearing("fwd").reaction_y))
    for k, name in enumerate(("film force", "support point", "forward reaction")):
        coarse, middle, fine = (v[k] for v in values)
        order = observed_order(coarse, middle, fine)
        assert order > 1.0, f"{name}: observed order {order:.2f} ({coarse}, {middle}, {fine})"
    force_change = abs(values[2][0] - values[1][0]) / abs(values[2][0])
    assert force_change < 2e-4, force_change
    assert abs(values[2][1] - values[1][1]) < 1e-3


def test_the_film_load_converges_with_the_shaft_elements_across_the_bearing():
    """FilmSupport.elements 8, 16, 32 (the largest element across the bearing halves; the
    film grid is fixed at 80 rows and the solver tolerances tightened to 1e-9 so that they
    do not mask the differences). The resultant, support point and line load converge with a
    positive observed order; the changes are already tiny (Hermite elements with consistent
    loads are nearly exact for a smooth load): the last below 1e-5 of the force and 10 um of
    support point."""
    options = CouplingOptions(force_tolerance=1e-9, film_tolerance=1e-8)
    values, loads, sizes = [], [], []
    for elements in (8, 16, 32):
        model = CoupledAlignment(ntua_line(), [FilmSupport("aft", ntua_film(80, 36), elements=elements)], options)
        result = model.solve()
        assert result.converged, result.message
        film = result.film("aft")
        x = model.model.mesh.x
        inside = x[(x >= AFT_X - 0.525 - 1e-9) & (x <= AFT_X + 0.525 + 1e-9)]
        sizes.append(np.diff(inside).max())
        values.append((film.force_y, film.support_point_y))
        loads.append(film.line_load[0])
    assert sizes[0] / sizes[1] == pytest.approx(2.0, rel=0.05) and sizes[1] / sizes[2] == pytest.approx(2.0, rel=0.05)
    for k, name in enumerate(("film force", "support point")):
        coarse, middle, fine = (v[k] for v in values)
        order = observed_order(coarse, middle, fine)
        assert order > 0.5, f"{name}: observed order {order:.2f} ({coarse}, {middle}, {fine})"
    first, second = np.abs(loads[1] - loads[0]).max(), np.abs(loads[2] - loads[1]).max()
    assert second < first, f"line load changes {first:.4g} then {second:.4g} N/m"
    assert abs(values[2][0] - values[1][0]) < 1e-5 * abs(values[2][0])
    assert abs(values[2][1] - values[1][1]) < 1e-5


def test_point_and_film_relative_slopes_are_against_the_same_machined_bore():
    """A single-slope bore of 0.2 mrad on the film bearing: the point-support comparison's
    relative slope is the point model's shaft slope less that bore's chord, as the film's is
    (docs/theory.md 10.1, sign conventions), so the two columns differ by the support model
    only. Reference: the point model solved on its own; the chord is exact (one straight
    segment), so the agreement is to round-off."""
    slope = 2e-4
    problem = ntua_film()
    bored = replace(problem, geometry=replace(problem.geometry, bore=(BoreSegment(1.0, slope=slope),)))
    result = CoupledAlignment(ntua_line(), [FilmSupport("aft", bored)]).solve()
    assert result.converged, result.message
    alone = AlignmentModel(ntua_line()).solve_condition(ntua_line().all_conditions()[0]).bearing("aft")
    point = result.point_supports.bearing("aft")
    # Converged, the film table's relative slope (the journal's chord against the bore's) is the
    # alignment table's (the shaft's chord less the bearing's and the bore's slopes): one chord.
    assert result.film("aft").relative_slope == pytest.approx(result.condition.bearing("aft").relative_slope, rel=1e-6)
    assert point.shaft_slope == pytest.approx(alone.shaft_slope, rel=1e-12)
    assert point.relative_slope == pytest.approx(alone.shaft_slope - slope, rel=1e-9)
    # the bearings without a film keep the point model's own relative slope
    assert result.point_supports.bearing("fwd").relative_slope == pytest.approx(
        AlignmentModel(ntua_line()).solve_condition(ntua_line().all_conditions()[0]).bearing("fwd").relative_slope,
        rel=1e-12,
    )


# -- 5. Newton and input errors --------------------------------------------------------------
def test_newton_converges_quadratically_on_the_demo_line():
    """With the exact Jacobian (frozen cavitated set; exact once the set settles) Newton's
    error obeys r_{k+1} <= C r_k^2. A linearly converging scheme of rate q would show
    r_{k+1} / r_k^2 = q / r_k, growing without bound (about 1e3 at r = 1e-4 for q = 0.1);
    a bound of 10 over every step, with at least three steps, separates the two."""
    result = CoupledAlignment(ntua_line(), [FilmSupport("aft", ntua_film())]).solve()
    assert result.converged, result.message
    history = result.residual_history
    assert len(history) >= 4, history
    assert result.iterations == len(history) - 1
    ratios = [b / a**2 for a, b in zip(history[:-1], history[1:], strict=False)]
    assert max(ratios) < 10.0, (history, ratios)
    assert history[-1] < CouplingOptions().film_tolerance
    assert result.force_residual < CouplingOptions().force_tolerance
    # One film solution per accepted step here: no line-search trials were needed.
    assert result.film_solutions == len(history)


def test_a_warm_start_from_a_nearby_solution_gives_the_same_root():
    """solve(initial=) starts from a neighbouring solution (here 5 % more speed); Newton's
    root does not depend on its start, so the warm and the cold solve agree to the solver's
    tolerances (1e-6 of the force, 1e-5 c of the journal line; observed 3e-7 and 1e-7 c), in no more
    iterations."""
    line = ntua_line()
    first = CoupledAlignment(line, [FilmSupport("aft", ntua_film())]).solve()
    assert first.converged and not first.contact
    faster = replace(ntua_film(), operating=replace(ntua_film().operating, speed=1.05 * 9.4248))
    model = CoupledAlignment(line, [FilmSupport("aft", faster)])
    cold = model.solve()
    warm = model.solve(initial=first)
    assert cold.converged and warm.converged
    assert warm.iterations <= cold.iterations
    for a, b in zip(cold.condition.bearings, warm.condition.bearings, strict=True):
        assert a.reaction_y == pytest.approx(b.reaction_y, rel=1e-6)
        assert a.reaction_z == pytest.approx(b.reaction_z, abs=1e-6 * abs(a.reaction_y))
    assert np.abs(cold.film("aft").centre_y - warm.film("aft").centre_y).max() < 1e-5 * CLEARANCE
    # The faster film carries the same line with a thicker film.
    assert cold.film("aft").state.min_film_thickness > first.film("aft").state.min_film_thickness


@pytest.mark.parametrize(
    ("changes", "field"),
    [
        ({"force_tolerance": 0.0}, "force_tolerance"),
        ({"force_tolerance": 0.1}, "force_tolerance"),
        ({"film_tolerance": -1e-6}, "film_tolerance"),
        ({"film_tolerance": float("nan")}, "film_tolerance"),
        ({"max_iterations": 0}, "max_iterations"),
        ({"max_iterations": 1001}, "max_iterations"),
    ],
)
def test_coupling_options_refuse_bad_values(changes, field):
    with pytest.raises(InputError) as error:
        CouplingOptions(**changes)
    assert error.value.field == field


def test_coupled_alignment_refuses_bad_films():
    line = ntua_line()
    film = ntua_film()
    cases = [
        ([FilmSupport("stern", film)], "films[0].bearing", "the name of a bearing"),
        ([FilmSupport("aft", film), FilmSupport("aft", film)], "films[1].bearing", "twice"),
        ([FilmSupport("aft", ntua_film(length=1.0))], "films[0].problem.geometry.length", "1.05"),
        ([FilmSupport("aft", film, elements=1)], "films[0].elements", "[2, 50]"),
        ([FilmSupport("aft", film, elements=51)], "films[0].elements", "[2, 50]"),
        # 10 elements across 1.05 m (the shortest 0.0525 m next to the edges of a six-point
        # bearing's mesh, the largest 0.105 m) need film rows at least every 0.105 m.
        ([FilmSupport("aft", ntua_film(axial=6))], "films[0].problem.options.axial_nodes", ">= 11 nodes"),
    ]
    bent = BentJournal(z=np.array([0.0, 1.05]), dy=np.zeros(2), dz=np.zeros(2))
    cases.append(
        (
            [FilmSupport("aft", replace(film, geometry=replace(film.geometry, bent_journal=bent)))],
            "films[0].problem.geometry.bent_journal",
            "elastic line",
        )
    )
    spring = replace(line, bearings=(replace(line.bearings[0], support="spring", stiffness=5e9), *line.bearings[1:]))
    for films, field, words in cases:
        with pytest.raises(InputError) as error:
            CoupledAlignment(line, films)
        assert error.value.field == field, (field, str(error.value))
        assert words in str(error.value)
        assert "\n" not in str(error.value)
    with pytest.raises(InputError) as error:
        CoupledAlignment(spring, [FilmSupport("aft", film)])
    assert error.value.field == "films[0].bearing" and "spring" in str(error.value)
    # As fine as the elements is enough.
    CoupledAlignment(line, [FilmSupport("aft", ntua_film(axial=11))])


# -- 6. fall-back to contact -----------------------------------------------------------------
def test_a_film_that_cannot_carry_falls_back_to_contact_at_the_bore():
    """With the seed's nose-up end moment the line bears on the aft edge so hard that the
    film reaches its floor: the solver says so, flags the film as contact, solves the bearing
    as contact at the bore (edge loading) and returns promptly (well under 10 s on a 40 x 36
    grid; a hang would be a timeout here). The contact solution is in equilibrium like any
    alignment (1e-7 of the load, as in the first check)."""
    line = ntua_line(moment=-END_MOMENT)
    start = time.perf_counter()
    result = CoupledAlignment(line, [FilmSupport("aft", ntua_film())]).solve()
    assert time.perf_counter() - start < 10.0
    assert result.message and "aft" in result.message and "contact" in result.message
    film = result.film("aft")
    assert film.contact and result.contact
    aft = result.condition.bearing("aft")
    assert aft.contact != "film" and aft.contact in ("bottom", "partial", "top")
    # The edge loading: the aft-most contact point carries the most.
    assert np.argmax(aft.point_reactions) == 0
    c = film.state.min_film_thickness / CLEARANCE
    assert c <= 2.0 * ntua_film().options.min_film_floor + 1e-12
    segment = line.segments[0]
    weight = segment.density * line.gravity * math.pi / 4 * segment.outer_diameter**2 * 14.0
    total = sum(b.reaction_y for b in result.condition.bearings)
    assert abs(total - weight - 202598.2) < 1e-7 * (weight + 202598.2)
    # The work before the film grounded is counted: at least the first film evaluation and the
    # Newton iteration whose step found no better film (the count read 0 and 0 before).
    assert result.iterations >= 1 and result.film_solutions >= 1
    # Why it grounds: the film is far out of equilibrium with the shaft (its force would change
    # by more than GROUNDED_FORCE_MISMATCH, 1 %, to follow the shaft's line), quoted.
    assert "force mismatch" in result.message
    # The journal figure says the film grounded and gives its h_min to 3 significant digits
    # (a film at its floor read "h_min 0.0 µm").
    from matplotlib.figure import Figure

    from shaftline.shaft import figures

    ax = Figure().subplots(2, 1)
    figures.journal_in_bore(film, ax=ax)
    title = ax[0].get_title()
    assert "(at its floor: solved as contact)" in title
    assert f"h_min {film.state.min_film_thickness * 1e6:.3g} µm" in title
    # The point-vs-film figure draws the grounded bearing as contact, not as a film support
    # (its bar is the contact solution's); the other bearings stay "film supports".
    ax = Figure().subplots(1, 2)
    figures.point_vs_film(result, ax=ax)
    for axes in ax:
        labels = [bars.get_label() for bars in axes.containers]
        assert labels == ["point supports", "film supports", "film at its floor: contact at the bore"]
        (grounded,) = axes.containers[2]  # one bar: the aft bearing's
        assert grounded.get_x() + 0.5 * grounded.get_width() == pytest.approx(0.2)
    assert ax[1].containers[2][0].get_height() == pytest.approx(aft.relative_slope * 1e3)
    # The film's relative slope (at its last journal line) is not the contact solution's: the
    # notes under the film table give both and say which table has which.
    assert abs(film.relative_slope - aft.relative_slope) > 1e-5
    from shaftline.shaft.capability import _film_notes

    notes = _film_notes(result)
    assert notes is not None
    assert (
        f"relative slope {film.relative_slope * 1e3:.4g} mrad at that line (the film table's); "
        f"{aft.relative_slope * 1e3:.4g} mrad with the bearing in contact at the bore (the alignment table's"
    ) in notes.text


def test_a_film_near_its_floor_that_carries_its_share_does_not_ground():
    """A stall is not contact. The demo line converges to 2.6e-8 c with h_min = 0.21 c; with the
    film floor raised to 0.6 of that (h_min within twice the floor, as a lined or rough film's
    end rows sit) and tolerances below rounding (1e-16), Newton stalls at about 1e-15 c. The
    film carries its share (force mismatch at rounding; the step does not thin it): the result
    is "not converged" with the residuals, not the fall-back to contact, which the old rule
    (a stall within twice the floor) took (docs/theory.md Sect. 10.1, "Contact fall-back")."""
    film = ntua_film()
    first = CoupledAlignment(ntua_line(), [FilmSupport("aft", film)]).solve()
    assert first.converged and not first.contact
    h = first.film("aft").state.min_film_thickness
    raised = replace(film, options=replace(film.options, min_film_floor=0.6 * h / CLEARANCE))
    options = CouplingOptions(film_tolerance=1e-16, force_tolerance=1e-16)
    result = CoupledAlignment(ntua_line(), [FilmSupport("aft", raised)], options).solve()
    assert not result.converged and not result.contact
    assert "stalled" in result.message and "force mismatch" in result.message
    assert result.condition.bearing("aft").contact == "film"
    assert result.force_residual < 1e-9 and result.residual_history[-1] < 1e-9
    # The same film as the converged solution: the stall is at rounding.
    assert result.film("aft").force_y == pytest.approx(first.film("aft").force_y, rel=1e-7)


# -- the film's resultant in each plane, and a couple ---------------------------------------
def test_a_plane_whose_resultant_lies_outside_the_bearing_carries_a_couple():
    """1 kN with 2 kN m about the mid-length of a 0.6 m bearing: the resultant would sit 2 m from
    mid-length, so there is no support point and the film carries a couple; 1 kN with 0.2 kN m
    sits 0.2 m forward, inside. A moment at rounding of the whole film force is no couple."""
    from shaftline.shaft.film_supports import carries_couple, plane_support_point

    assert carries_couple(1e3, 2e3, 0.6, 1e3) and math.isnan(plane_support_point(1e3, 2e3, 0.6, 1e3))
    assert not carries_couple(1e3, 200.0, 0.6, 1e3) and plane_support_point(1e3, 200.0, 0.6, 1e3) == 0.2
    assert not carries_couple(0.0, 1e-5, 0.6, 3e5) and math.isnan(plane_support_point(0.0, 1e-5, 0.6, 3e5))
    assert carries_couple(0.0, 100.0, 0.6, 3e5)  # a pure couple in a plane that carries no force


def test_the_ntua_film_at_four_times_its_speed_carries_a_horizontal_couple():
    """Seed 004's line at 360 rpm (41 x 30 film): the misaligned journal twists in its film, whose
    horizontal force is under 1 % of the vertical but whose horizontal moment puts that resultant
    about 5 m from mid-length, far outside the 1.05 m bearing. The film carries a couple there:
    no horizontal support point, the plane named; the vertical resultant stays inside (3.5 cm aft
    of mid-length). The one projected position reported before mixed both planes."""
    from shaftline.shaft.ntua import SPEED, ntua_shaft_line

    line, film = ntua_shaft_line(0.3, grid=(41, 30), speed=4 * SPEED)
    result = CoupledAlignment(line, [film]).solve()
    assert result.converged and not result.contact
    aft = result.films[0]
    assert abs(aft.force_z) < 0.01 * aft.force_y and abs(aft.moment_z / aft.force_z) > 2.0
    assert aft.couple_planes == ("horizontal",) and math.isnan(aft.support_point_z)
    assert -0.525 < aft.support_point_y < 0.0
