"""One-sided supports: lift-off, top-of-bore contact and multi-point bearings."""

from __future__ import annotations

import numpy as np
import pytest

from shaftline.errors import InputError
from shaftline.shaft import AlignmentModel, Bearing, Condition, Propeller, ShaftLine, ShaftSegment


def line(**bearing_changes):
    bearings = [
        Bearing("aft", 1.0, 1.2, support="multi_point", points=5),
        Bearing("fwd stern tube", 6.0, 0.6),
        Bearing("intermediate", 12.0, 0.4),
        Bearing("engine", 17.5, 0.4),
    ]
    bearings = [Bearing(**{**b.__dict__, **bearing_changes.get(b.name, {})}) for b in bearings]
    return ShaftLine(
        segments=(ShaftSegment(7.0, 0.7), ShaftSegment(11.5, 0.55)),
        bearings=tuple(bearings),
        propeller=Propeller(x=-0.8, mass=30000.0),
    )


def test_lowered_bearing_lifts_off_and_the_others_carry():
    model = AlignmentModel(line())
    result = model.solve_condition(Condition("low", offsets_y={"intermediate": -5e-3}))
    assert result.bearing("intermediate").contact == "lifted"
    assert result.bearing("intermediate").reaction_y == 0.0
    base = model.solve()[0]
    assert sum(b.reaction_y for b in result.bearings) == pytest.approx(sum(b.reaction_y for b in base.bearings))
    # the shaft hangs above the lowered bearing: positive gap
    x = model.line.bearings[2].x
    assert np.interp(x, result.x, result.deflection_y) > -5e-3


def test_shaft_pressed_against_the_top_of_a_bearing():
    """Raise the intermediate bearing far: the engine bearing, with 0.4 mm clearance, must hold
    the shaft down from the top of its bore (a downward reaction)."""
    model = AlignmentModel(line(engine={"vertical_clearance": 0.4e-3}))
    result = model.solve_condition(Condition("high", offsets_y={"intermediate": 6e-3}))
    engine = result.bearing("engine")
    assert engine.contact == "top"
    assert engine.reaction_y < 0
    deflection = np.interp(17.5, result.x, result.deflection_y)
    assert deflection == pytest.approx(0.4e-3, abs=1e-9)


def test_multi_point_aft_bearing_carries_at_its_aft_end_under_the_propeller():
    result = AlignmentModel(line()).solve()[0]
    aft = result.bearing("aft")
    assert aft.point_reactions.size == 5
    assert aft.point_reactions[0] == aft.point_reactions.max()  # edge loading at the aft end
    assert aft.reaction_y == pytest.approx(aft.point_reactions.sum())
    assert aft.shaft_slope > 0  # shaft rising forward through the aft bearing


def test_aft_third_support_point():
    shaft = line(aft={"support": "point", "position": "aft_third"})
    model = AlignmentModel(shaft)
    assert model.supports.x[0] == pytest.approx(1.0 - 0.6 + 0.7 / 3, abs=1e-3)


@pytest.mark.parametrize(
    "change, field",
    [
        ({"segments": (ShaftSegment(10.0, 0.5, inner_diameter=0.6),)}, "segments[0].inner_diameter"),
        ({"segments": (ShaftSegment(-1.0, 0.5),)}, "segments[0].length"),
        ({"bearings": (Bearing("a", 1.0, 0.5), Bearing("b", 30.0, 0.5))}, "bearings[1].x"),
        ({"bearings": (Bearing("a", 1.0, 0.5), Bearing("b", 1.2, 0.5))}, "bearings[1].x"),
        ({"bearings": (Bearing("a", 1.0, 0.5),)}, "bearings"),
        ({"conditions": (Condition("c", offsets_y={"nope": 1e-3}),)}, "conditions[0].offsets_y"),
        ({"bearings": (Bearing("a", 1.0, 0.5, material="cheese"), Bearing("b", 9.0, 0.5))}, "bearings[0].material"),
    ],
)
def test_bad_shaft_input_names_the_field(change, field):
    base = {
        "segments": (ShaftSegment(10.0, 0.5),),
        "bearings": (Bearing("a", 1.0, 0.5), Bearing("b", 9.0, 0.5)),
    }
    with pytest.raises(InputError) as error:
        ShaftLine(**{**base, **change})
    assert error.value.field == field
