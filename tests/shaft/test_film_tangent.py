"""Influence coefficients of a line on its bearing films (shaftline.shaft.film_tangent), and the
offset optimisation and reverse engineering that use them.

Reference: central differences of re-solved coupled equilibria (a bearing raised and lowered by
2 um, each solved to force and film tolerances of 1e-10 so that the difference carries no
iteration noise). The tangent is the derivative of the same discrete equations (frozen cavitated
set, held contact set), so the two agree to the difference's truncation error, O((2 um / c)^2)
of the film's curvature: observed 9e-9 of the largest entry for the reactions, 2.5e-9 m/m for the
deflections. The tolerance, 1e-6 of the largest entry (1e-6 m/m), is a factor 100 above that and
far below the 57 % by which the point-support matrix misses the aft film's own coefficient (the
quantity at stake).
The line is seed 004's (Rossopoulos 2018, Table 4-5) at psi = 0.3 on a 41 x 30 film grid.
"""

from __future__ import annotations

from dataclasses import replace

import numpy as np
import pytest

from shaftline.shaft.coupled import CoupledAlignment, CouplingOptions
from shaftline.shaft.ntua import ntua_shaft_line
from shaftline.shaft.offsets import FILM_OFFSET_TOLERANCE, offsets_from_reactions, optimise_offsets
from shaftline.shaft.rules import Rule

GRID = (41, 30)
TIGHT = CouplingOptions(force_tolerance=1e-10, film_tolerance=1e-10, max_iterations=60)
STEP = 2e-6  # m


@pytest.fixture(scope="module")
def line_on_film():
    line, film = ntua_shaft_line(0.3, grid=GRID)
    solver = CoupledAlignment(line, [film], TIGHT)
    return line, solver, solver.solve()


def _raised(condition, name, by):
    return replace(condition, offsets_y={**condition.offsets_y, name: condition.offsets_y.get(name, 0.0) + by})


def test_the_tangent_is_the_derivative_of_the_coupled_reactions(line_on_film):
    line, solver, base = line_on_film
    influence = base.influence
    assert base.converged and influence is not None and influence.kind == "film_tangent"
    assert influence.condition == base.condition.name and "film stiffness" in influence.label
    condition = line.all_conditions()[0]
    difference = np.empty_like(influence.matrix)
    for j, name in enumerate(influence.names):
        sides = []
        for sign in (1.0, -1.0):
            raised = solver.solve(_raised(condition, name, sign * STEP), initial=base)
            assert raised.converged and [b.contact for b in raised.condition.bearings] == [
                b.contact for b in base.condition.bearings
            ]
            sides.append(np.array([b.reaction_y for b in raised.condition.bearings]))
        difference[:, j] = (sides[0] - sides[1]) / (2 * STEP)
    scale = np.abs(difference).max()
    assert np.abs(influence.matrix - difference).max() <= 1e-6 * scale
    # A rigid rise of the whole line changes no reaction, on films as on points.
    assert np.abs(influence.matrix.sum(axis=1)).max() <= 1e-12 * scale
    # What the point-support matrix misses: the aft film's own stiffness in series with the shaft.
    point = solver.point_model.influence_matrix().matrix
    assert influence.matrix[0, 0] > 1.3 * point[0, 0]


def test_the_deflection_response_is_the_derivative_of_the_elastic_line(line_on_film):
    line, solver, base = line_on_film
    condition = line.all_conditions()[0]
    name = base.influence.names[1]
    up = solver.solve(_raised(condition, name, STEP), initial=base)
    down = solver.solve(_raised(condition, name, -STEP), initial=base)
    difference = (up.condition.deflection_y - down.condition.deflection_y) / (2 * STEP)
    assert np.abs(base.influence.deflection[:, 1] - difference).max() <= 1e-6


def test_offsets_from_reactions_on_the_films_recover_the_offsets(line_on_film):
    """Reactions of the film line with the forward stern tube 0.2 mm up: on the films the offset is
    found to FILM_OFFSET_TOLERANCE and the reactions to a newton; the point-support matrix puts it
    30 % off and leaves over a kilonewton unexplained."""
    line, solver, _ = line_on_film
    condition = line.all_conditions()[0]
    truth = solver.solve(_raised(condition, "forward stern tube", 0.2e-3))
    measured = {b.name: b.reaction_y for b in truth.condition.bearings}
    reference = ("aft stern tube", "intermediate")
    found, misfit = offsets_from_reactions(solver.point_model, measured, condition, reference, films=solver)
    assert found["forward stern tube"] == pytest.approx(0.2e-3, abs=FILM_OFFSET_TOLERANCE)
    assert misfit < 1.0
    on_points, point_misfit = offsets_from_reactions(solver.point_model, measured, condition, reference)
    assert abs(on_points["forward stern tube"] - 0.2e-3) > 0.2 * 0.2e-3 and point_misfit > 1e3


def test_offset_optimisation_on_the_films_meets_its_objective_there(line_on_film):
    """The aft bearing's relative slope minimised with the forward stern tube's offset: on the
    films the plan makes the journal parallel to its bore (to 1e-9 rad); the point-support plan,
    solved on the films, leaves tens of microradians."""
    line, solver, _ = line_on_film
    rules = [Rule("min-load", "test", "", "", "reaction", ">=", 1e4)]
    model = solver.point_model
    on_films = optimise_offsets(model, rules, ["forward stern tube"], "aft_slope", 1e-3, films=solver)
    assert on_films.settled and on_films.influence.startswith("film supports")
    assert on_films.objective < 1e-9
    check = solver.solve(replace(line.all_conditions()[0], offsets_y=on_films.offsets))
    assert abs(check.condition.bearings[0].relative_slope) < 1e-9
    on_points = optimise_offsets(model, rules, ["forward stern tube"], "aft_slope", 1e-3)
    solved = solver.solve(replace(line.all_conditions()[0], offsets_y=on_points.offsets))
    assert abs(solved.condition.bearings[0].relative_slope) > 1e-5


def test_a_plan_the_films_cannot_reach_stops_unsettled_and_says_why(line_on_film):
    """The load spread minimised with the forward stern tube within 3 mm: the linear programme asks
    for offsets at which the aft film grounds (its floor is not one of the programme's limits), so
    each step is halved back to an equilibrium; when every step grounds a film the plan is the last
    round's, flagged unsettled with the reason, with the aft bearing on its film."""
    line, solver, _ = line_on_film
    rules = [Rule("min-load", "test", "", "", "reaction", ">=", 0.0)]
    plan = optimise_offsets(solver.point_model, rules, ["forward stern tube"], "load_spread", 3e-3, films=solver)
    assert not plan.settled and "without equilibrium" in plan.note
    assert "film at its floor in aft stern tube" in plan.note
    assert 0.5e-3 < plan.offsets["forward stern tube"] < 3e-3
    assert plan.results[0].bearings[0].contact == "film"  # the aft bearing on its film, not grounded
