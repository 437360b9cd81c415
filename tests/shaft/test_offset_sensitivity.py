"""Sensitivities of reactions, elastic line and slopes to bearing offsets, from the influence
matrix of the solution's contact set, against finite differences of the full one-sided model.

For a fixed contact set the response is affine in the offsets, so a central difference has
no truncation error: the only difference is round-off, about (relative accuracy of a solve,
~1e-13 to 1e-12) x (largest reaction, 5e5 N) / (2 x step, 2e-6 m), i.e. 0.03-0.3 N/m against
largest entries of ~1e9 N/m, or 1e-11 to 1e-10 relative (1e-11 is what these lines show). The
tolerance, 1e-8 of the largest entry, leaves a margin of ~100 over that and is still far
below what a wrong contact set or sign gives (a whole entry).
The premise, no change of contact set within +/- the step, is asserted, not assumed.
"""

from __future__ import annotations

import numpy as np
import pytest

from shaftline.shaft import AlignmentModel, Bearing, Condition, Propeller, ShaftLine, ShaftSegment

STEP = 1e-6  # m


def line() -> ShaftLine:
    return ShaftLine(
        segments=(ShaftSegment(7.0, 0.7), ShaftSegment(11.5, 0.55)),
        bearings=(
            Bearing("aft", 1.0, 1.2, support="multi_point", points=5),
            Bearing("fwd", 6.0, 0.6, vertical_clearance=0.8e-3),
            Bearing("mid", 12.0, 0.4, support="spring", stiffness=3e9),
            Bearing("engine", 17.5, 0.4, vertical_clearance=0.4e-3),
        ),
        propeller=Propeller(x=-0.8, mass=30000.0),
    )


CONDITIONS = {
    "straight": Condition("straight"),
    "mid lifted": Condition("mid lifted", offsets_y={"mid": -5e-3}),
    "engine at the top": Condition("engine at the top", offsets_y={"mid": 6e-3}),
}


def states(result):
    return [tuple(b.point_contact) for b in result.bearings]


def finite_differences(model, condition, base):
    """Central differences of reactions, deflection and aft relative slope per bearing offset."""
    names = [b.name for b in model.line.bearings]
    reactions, deflection, slope = [], [], []
    for name in names:
        moved = []
        for sign in (1.0, -1.0):
            offsets = dict(condition.offsets_y)
            offsets[name] = offsets.get(name, 0.0) + sign * STEP
            result = model.solve_condition(Condition(condition.name, offsets_y=offsets))
            assert states(result) == states(base), "a contact change within the step: move the condition"
            moved.append(result)
        up, down = moved
        reactions.append(
            [(u.reaction_y - d.reaction_y) / (2 * STEP) for u, d in zip(up.bearings, down.bearings, strict=True)]
        )
        deflection.append((up.deflection_y - down.deflection_y) / (2 * STEP))
        slope.append((up.bearings[0].relative_slope - down.bearings[0].relative_slope) / (2 * STEP))
    return np.array(reactions).T, np.array(deflection).T, np.array(slope)


@pytest.mark.parametrize("name", list(CONDITIONS))
def test_influence_of_the_contact_set_matches_finite_differences(name):
    model = AlignmentModel(line())
    condition = CONDITIONS[name]
    base = model.solve_condition(condition)
    influence = model.influence_matrix(base)
    reactions, deflection, slope = finite_differences(model, condition, base)
    scale = np.abs(influence.matrix).max()
    assert np.abs(influence.matrix - reactions).max() <= 1e-8 * scale
    assert np.abs(influence.deflection - deflection).max() <= 1e-8 * np.abs(influence.deflection).max()
    # The aft relative slope is linear in the nodal deflections (interpolation at the edges).
    aft = model.line.bearings[0]
    x = model.mesh.x
    predicted = [
        (np.interp(aft.x + aft.length / 2, x, col) - np.interp(aft.x - aft.length / 2, x, col)) / aft.length
        for col in influence.deflection.T
    ]
    assert np.abs(np.array(predicted) - slope).max() <= 1e-8 * np.abs(slope).max()


def test_contact_sets_are_what_the_conditions_claim():
    """The premise of the parametrised test: the three conditions do cover lift-off, top contact
    and partial contact of the multi-point bearing."""
    model = AlignmentModel(line())
    contact = {n: [b.contact for b in model.solve_condition(c).bearings] for n, c in CONDITIONS.items()}
    assert contact["mid lifted"][2] == "lifted"
    assert contact["engine at the top"][3] == "top"
    assert "partial" in {contact[n][0] for n in CONDITIONS}


def test_lifted_bearing_has_no_influence_and_the_default_is_all_in_contact():
    """A lifted bearing's reaction stays zero for small offsets, and its own offset changes no
    reaction: its row and column vanish. Without a result the matrix is the two-sided one,
    whose diagonal is positive everywhere (raising a bearing loads it)."""
    model = AlignmentModel(line())
    lifted = model.influence_matrix(model.solve_condition(CONDITIONS["mid lifted"]))
    assert np.all(lifted.matrix[2] == 0.0) and np.all(lifted.matrix[:, 2] == 0.0)
    default = model.influence_matrix()
    assert np.all(np.diag(default.matrix) > 0.0)
    two_sided = model.influence_matrix(model.solve_condition(CONDITIONS["mid lifted"], two_sided=True))
    assert np.array_equal(two_sided.matrix, default.matrix)


def test_a_result_of_another_model_is_refused():
    other = ShaftLine(segments=(ShaftSegment(10.0, 0.5),), bearings=(Bearing("a", 1.0, 0.5), Bearing("b", 9.0, 0.5)))
    result = AlignmentModel(other).solve()[0]
    with pytest.raises(ValueError, match="another model"):
        AlignmentModel(line()).influence_matrix(result)
