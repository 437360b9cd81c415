"""Invariants of the alignment model on random shaft lines (hypothesis).

- The influence matrix is symmetric (Maxwell-Betti), its columns sum to zero (a uniform
  rise of all bearings is a rigid motion) and their first moments vanish (so is a rigid
  rotation). Tolerance 1e-7 of the largest entry: a dense solve of a small KKT system.
- Superposition: with every support in contact, reactions(offsets) = reactions(0) +
  influence @ offsets, to 1e-6 of the largest reaction.
- Equilibrium in every condition, with lift-off or not: sum of reactions = weight and
  moments balance, to 1e-8 relative.
"""

from __future__ import annotations

import numpy as np
from hypothesis import HealthCheck, assume, given, settings
from hypothesis import strategies as st

from shaftline.errors import InputError
from shaftline.shaft import AlignmentModel, Bearing, Condition, Propeller, ShaftLine, ShaftSegment


def solve_or_skip(model, condition=None):
    """Solve, discarding draws whose propeller tips the line over its aft bearing (refused)."""
    try:
        return model.solve_condition(condition) if condition is not None else model.solve()[0]
    except InputError as error:
        assert "tips over" in str(error)
        assume(False)


@st.composite
def shaft_lines(draw):
    segments = tuple(
        ShaftSegment(draw(st.floats(2.0, 8.0)), draw(st.floats(0.25, 0.9))) for _ in range(draw(st.integers(1, 4)))
    )
    length = sum(s.length for s in segments)
    count = draw(st.integers(3, 7))
    # Evenly spread stations, each moved by up to a quarter of the spacing; bearings of 0.4
    # spacing never overlap (neighbours stay at least half a spacing apart).
    spacing = (length - 0.4) / (count - 1)
    jitter = draw(st.lists(st.floats(-0.25, 0.25), min_size=count, max_size=count))
    x = 0.2 + spacing * (np.arange(count) + np.array(jitter) * [0, *([1] * (count - 2)), 0])
    bearings = tuple(Bearing(f"B{k}", float(xk), min(0.2, 0.4 * spacing)) for k, xk in enumerate(x))
    propeller = Propeller(x=-draw(st.floats(0.0, min(1.5, 0.4 * length))), mass=draw(st.floats(1e3, 5e4)))
    return ShaftLine(segments=segments, bearings=bearings, propeller=propeller, element_length=0.5)


@settings(max_examples=25, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(shaft_lines())
def test_influence_matrix_invariants(line):
    model = AlignmentModel(line)
    matrix = model.influence_matrix().matrix
    scale = np.abs(matrix).max()
    x = np.array([b.x for b in line.bearings])
    assert np.allclose(matrix, matrix.T, atol=1e-7 * scale)
    assert np.allclose(matrix.sum(axis=0), 0.0, atol=1e-7 * scale)
    assert np.allclose(x @ matrix, 0.0, atol=1e-7 * scale * x.max())
    assert np.all(np.diag(matrix) > 0)  # raising a bearing loads it


@settings(max_examples=25, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(shaft_lines(), st.data())
def test_superposition_while_in_contact(line, data):
    model = AlignmentModel(line)
    base = solve_or_skip(model)
    assume(all(b.contact == "bottom" for b in base.bearings))
    offsets = np.array(
        data.draw(st.lists(st.floats(-2e-5, 2e-5), min_size=len(line.bearings), max_size=len(line.bearings)))
    )
    condition = Condition("offset", offsets_y={b.name: float(o) for b, o in zip(line.bearings, offsets, strict=True)})
    moved = solve_or_skip(model, condition)
    assume(all(b.contact == "bottom" for b in moved.bearings))
    r0 = np.array([b.reaction_y for b in base.bearings])
    r1 = np.array([b.reaction_y for b in moved.bearings])
    predicted = r0 + model.influence_matrix().matrix @ offsets
    assert np.allclose(r1, predicted, atol=1e-6 * np.abs(r0).max())


@settings(max_examples=25, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(shaft_lines(), st.data())
def test_equilibrium_with_lift_off(line, data):
    offsets = data.draw(st.lists(st.floats(-2e-3, 2e-3), min_size=len(line.bearings), max_size=len(line.bearings)))
    condition = Condition("rough", offsets_y={b.name: o for b, o in zip(line.bearings, offsets, strict=True)})
    model = AlignmentModel(line)
    result = solve_or_skip(model, condition)
    reactions = np.array([b.reaction_y for b in result.bearings])
    assert np.all(reactions >= -1e-6 * np.abs(reactions).max())  # one-sided, no top contact set
    weight = float(np.sum(model.mesh.weight_per_length * model.mesh.length)) + line.propeller.weight()
    assert reactions.sum() == pytest_approx(weight)
    for bearing in result.bearings:
        if bearing.contact == "lifted":
            assert bearing.reaction_y == 0.0


def pytest_approx(value):
    import pytest

    return pytest.approx(value, rel=1e-8)
