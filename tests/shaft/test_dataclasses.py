"""Frozen dataclasses of the shaft package that hold numpy arrays compare by identity
(eq=False): the generated __eq__ would compare the arrays element-wise and raise
"truth value of an array is ambiguous" (and hash them, which fails)."""

from __future__ import annotations

import dataclasses
import importlib
import inspect

import numpy as np
import pytest

MODULES = ["alignment", "contact_qp", "fem", "jackup", "local", "model", "offsets", "rules", "sag_gap"]


def array_dataclasses():
    found = []
    for name in MODULES:
        module = importlib.import_module(f"shaftline.shaft.{name}")
        for _, cls in inspect.getmembers(module, inspect.isclass):
            if cls.__module__ != module.__name__ or not dataclasses.is_dataclass(cls):
                continue
            if any("ndarray" in str(f.type) for f in dataclasses.fields(cls)):
                found.append(cls)
    return found


def test_the_scan_finds_the_known_ones():
    names = {cls.__name__ for cls in array_dataclasses()}
    assert {"ConditionResult", "BearingResult", "InfluenceMatrix", "Mesh", "JackUpCurve", "LocalShaftLine"} <= names


@pytest.mark.parametrize("cls", array_dataclasses(), ids=lambda c: c.__name__)
def test_array_holding_dataclasses_compare_by_identity(cls):
    params = cls.__dataclass_params__
    assert params.frozen and not params.eq


def test_results_can_be_compared_and_put_in_sets():
    from shaftline.shaft import AlignmentModel, Bearing, ShaftLine, ShaftSegment

    line = ShaftLine(segments=(ShaftSegment(10.0, 0.5),), bearings=(Bearing("a", 1.0, 0.5), Bearing("b", 9.0, 0.5)))
    first, second = AlignmentModel(line).solve()[0], AlignmentModel(line).solve()[0]
    assert first != second and first == first
    assert len({first, second}) == 2
    assert isinstance(first.x, np.ndarray)
