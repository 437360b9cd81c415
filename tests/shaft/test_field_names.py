"""Bad input to the alignment procedures names the field relative to the function or object
that checks it (a parameter name, or an attribute path of the dataclass), never a path of
the case file: the domain cannot know where a value came from, the case layer prefixes it."""

from __future__ import annotations

import numpy as np
import pytest

from shaftline.errors import InputError
from shaftline.shaft import AlignmentModel, Bearing, PointLoad, PointMass, Propeller, ShaftLine, ShaftSegment
from shaftline.shaft.jackup import jack_up, reaction_from_jack_curve
from shaftline.shaft.local import LocalShaftModel
from shaftline.shaft.offsets import offsets_from_reactions, optimise_offsets
from shaftline.shaft.rules import Rule, load_rules
from shaftline.shaft.sag_gap import sag_and_gap

# No offsets within +/- 1 mm make a bearing of a 12 m shaft carry 1 GN.
IMPOSSIBLE = Rule("impossible", "", "", "", quantity="reaction", comparison=">=", limit=1e9)


def line(**changes):
    base = {
        "segments": (ShaftSegment(6.0, 0.5), ShaftSegment(6.0, 0.45)),
        "bearings": (Bearing("a", 1.0, 0.5), Bearing("b", 6.5, 0.5), Bearing("c", 11.5, 0.5)),
        "propeller": Propeller(x=0.3, mass=5000.0),
    }
    return ShaftLine(**{**base, **changes})


@pytest.mark.parametrize(
    "call, field",
    [
        (lambda: jack_up(line(), "nope", 6.5), "bearing"),
        (lambda: jack_up(line(), "b", 40.0), "jack_x"),
        (lambda: sag_and_gap(line(), 20.0), "flange_x"),
        (lambda: sag_and_gap(line(), 6.0), "temporary_supports"),
        (lambda: optimise_offsets(AlignmentModel(line()), [], ["nope"]), "adjustable"),
        (lambda: optimise_offsets(AlignmentModel(line()), [], []), "adjustable"),
        (lambda: optimise_offsets(AlignmentModel(line()), [], objective="nope"), "objective"),
        (lambda: optimise_offsets(AlignmentModel(line()), [IMPOSSIBLE], bound=1e-3), "bound"),
        (lambda: offsets_from_reactions(AlignmentModel(line()), {"nope": 1.0}), "measured"),
        (lambda: reaction_from_jack_curve(np.arange(3.0), np.arange(3.0)), "loads"),
        (lambda: reaction_from_jack_curve(np.arange(8.0), np.arange(7.0)), "lifts"),
        (lambda: reaction_from_jack_curve(np.arange(8.0), np.full(8, np.nan)), "lifts"),
        (lambda: reaction_from_jack_curve(np.arange(8.0)[::-1], np.arange(8.0)), "loads"),
        (lambda: reaction_from_jack_curve(np.arange(8.0), np.arange(8.0), 20.0), "correction_factor"),
        (lambda: load_rules("/no/such/rules.toml"), "path"),
        (lambda: line(point_loads=(PointLoad(30.0),)), "point_loads[0].x"),
        (lambda: line(masses=(PointMass(-1.0, 10.0),)), "masses[0].x"),
        (lambda: line(propeller=Propeller(x=0.3, mass=-1.0)), "propeller.mass"),
        (lambda: line(element_length=0.0), "element_length"),
        (lambda: line(beam_theory="plate"), "beam_theory"),
    ],
)
def test_procedures_name_their_own_parameters(call, field):
    with pytest.raises(InputError) as error:
        call()
    assert error.value.field == field


def test_local_model_names_its_attribute():
    values = dict(
        bearing_length=1.0,
        shaft_diameter=0.5,
        aft_overhang=0.5,
        fore_length=2.0,
        aft_force=-1e5,
        aft_moment=0.0,
        fore_force=0.0,
        fore_rotation=0.0,
        weight_per_length=1e4,
    )
    with pytest.raises(InputError) as error:
        LocalShaftModel(**{**values, "shaft_diameter": -0.5})
    assert error.value.field == "shaft_diameter"
