"""The alignment's contact solver (ContactQP) against the original active-set solver (the oracle).

Both solve the same convex QP exactly (finite active-set methods); the solution is unique for
a line that stands, so the reactions must agree to round-off and the contact states must be
identical. Tolerance 1e-9 of the largest point reaction (and for the elastic line, of the
deflection that reaction causes at the most flexible support): each solver's answer is a dense
solve of a KKT system of at most ~60 unknowns with condition numbers up to ~1e7 here, and the
original accumulates its iterate over up to ~25 steps (1e-10 seen on the example).
The lines have lift-off (random offsets of +/- 2 mm), top-of-bore contact (clearances of
0.3-1 mm), multi-point and spring supports, and several conditions solved one after another
on one model, so the warm start from the previous contact set is exercised too.
"""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import HealthCheck, assume, given, settings
from hypothesis import strategies as st

from shaftline.errors import InputError
from shaftline.shaft import AlignmentModel, Bearing, Condition, Propeller, ShaftLine, ShaftSegment
from shaftline.shaft.contact_qp import ContactQP, active_set_qp


@st.composite
def lines_and_conditions(draw):
    segments = tuple(
        ShaftSegment(draw(st.floats(3.0, 8.0)), draw(st.floats(0.3, 0.8))) for _ in range(draw(st.integers(2, 3)))
    )
    length = sum(s.length for s in segments)
    count = draw(st.integers(4, 7))
    spacing = (length - 1.0) / (count - 1)
    x = 0.5 + spacing * np.arange(count)
    bearings = []
    for k, xk in enumerate(x):
        kind = (
            draw(st.sampled_from(["point", "spring", "multi_point"]))
            if k == 0
            else draw(st.sampled_from(["point", "point", "spring"]))
        )
        clearance = draw(st.one_of(st.just(np.inf), st.floats(0.3e-3, 1e-3)))
        extra = {"support": kind, "vertical_clearance": clearance}
        if kind == "spring":
            extra["stiffness"] = draw(st.floats(5e8, 5e9))
        if kind == "multi_point":
            extra["points"] = draw(st.integers(2, 6))
        bearings.append(Bearing(f"B{k}", float(xk), min(0.8, 0.4 * spacing), **extra))
    line = ShaftLine(
        segments=segments,
        bearings=tuple(bearings),
        propeller=Propeller(x=-draw(st.floats(0.0, 1.0)), mass=draw(st.floats(1e3, 3e4))),
        element_length=0.4,
    )
    conditions = []
    for c in range(3):
        offsets = draw(st.lists(st.floats(-2e-3, 2e-3), min_size=count, max_size=count))
        conditions.append(Condition(f"c{c}", offsets_y={b.name: o for b, o in zip(bearings, offsets, strict=True)}))
    return line, conditions


def solve_all(model, conditions):
    try:
        return [model.solve_condition(c) for c in conditions]
    except InputError as error:  # a heavy overhanging propeller may tip the line over: refused alike
        assert "tips over" in str(error)
        assume(False)


@settings(max_examples=40, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(lines_and_conditions())
def test_contact_solver_matches_the_original(data):
    line, conditions = data
    model = AlignmentModel(line)
    fast = solve_all(model, conditions)
    oracle = solve_all(AlignmentModel(line, reference_qp=True), conditions)
    for a, b in zip(fast, oracle, strict=True):
        reactions_a = np.concatenate([r.point_reactions for r in a.bearings])
        reactions_b = np.concatenate([r.point_reactions for r in b.bearings])
        scale = np.abs(reactions_b).max()
        assert np.abs(reactions_a - reactions_b).max() <= 1e-9 * scale
        assert [r.contact for r in a.bearings] == [r.contact for r in b.bearings]
        # zero reaction exactly where the oracle has a lifted point
        assert np.array_equal(reactions_a == 0.0, reactions_b == 0.0)
        # The deflection a reaction of the largest size causes sets the scale of its round-off.
        deflection = model.flexibility.max() * scale
        assert np.abs(a.deflection_y - b.deflection_y).max() <= 1e-9 * deflection


def test_warm_start_from_a_stale_contact_set_still_finds_the_optimum():
    """A model first solved with a bearing lifted, then with it loaded again: the remembered
    working set is wrong for the second condition and must not survive into its answer."""
    line = ShaftLine(
        segments=(ShaftSegment(7.0, 0.7), ShaftSegment(11.5, 0.55)),
        bearings=(
            Bearing("aft", 1.0, 1.2, support="multi_point", points=5),
            Bearing("fwd", 6.0, 0.6),
            Bearing("mid", 12.0, 0.4),
            Bearing("engine", 17.5, 0.4, vertical_clearance=0.4e-3),
        ),
        propeller=Propeller(x=-0.8, mass=30000.0),
    )
    conditions = [
        Condition("low", offsets_y={"mid": -5e-3}),
        Condition("high", offsets_y={"mid": 6e-3}),
        Condition("straight"),
    ]
    model = AlignmentModel(line)
    fast = [model.solve_condition(c) for c in conditions]
    oracle = [AlignmentModel(line, reference_qp=True).solve_condition(c) for c in conditions]
    assert [r.bearing("mid").contact for r in fast] == ["lifted", "bottom", "bottom"]
    assert fast[1].bearing("engine").contact == "top"
    for a, b in zip(fast, oracle, strict=True):
        assert [r.contact for r in a.bearings] == [r.contact for r in b.bearings]
        for ra, rb in zip(a.bearings, b.bearings, strict=True):
            assert ra.reaction_y == pytest.approx(rb.reaction_y, rel=1e-9, abs=1e-9 * 3e5)


def test_degenerate_start_needs_the_lp():
    """Both columns at one station: every pair of columns is singular (no two-column vertex)
    and every KKT matrix rank-deficient, so the LP start and the least-squares steps are
    used; an infeasible problem (a load the supports cannot carry) is refused like the
    original does."""
    hessian = np.array([[2.0, 0.5], [0.5, 1.0]])
    equality = np.array([[1.0, 1.0], [0.0, 0.0]])  # both columns at station 0: no vertex of two
    bounded = np.array([True, True])
    linear = np.array([-1.0, 0.3])
    target = np.array([1.0, 0.0])
    x, mu, _ = ContactQP(hessian, equality, bounded).solve(linear, target)
    x_ref, mu_ref, _ = active_set_qp(hessian, linear, equality, target, bounded)
    assert x == pytest.approx(x_ref, abs=1e-12)
    assert x.sum() == pytest.approx(1.0)
    with pytest.raises(InputError, match="tips over"):
        ContactQP(hessian, equality, bounded).solve(linear, np.array([-1.0, 0.0]))
