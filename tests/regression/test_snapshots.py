"""Every example gives the numbers the film solver gave before its split into one module per job.

Reference: ``snapshots/*.json``, the results JSON of each example (``shaftline run CASE --json``)
and of the Stribeck verb on the film examples (``shaftline bearing stribeck CASE --json``), as
written by shaftline before the split (README.md here says how they were made). The split is a
reorganisation of the same arithmetic in the same order, so the numbers agree to the last digits:
the tolerance is 1e-12 relative, with entries of a list compared to 1e-12 of the list's largest
magnitude (an entry that is rounding next to its neighbours, e.g. a pressure at a cavitated
node). That is ten thousand times below the 1e-8 force tolerance of the film's Newton
iteration, so a change of the solver's path (another start, step or set) is seen, while a
reordering of a floating-point sum by numpy would not be (none is made).

The examples whose run takes longest are marked slow; they still run in the suite.
"""

from __future__ import annotations

import json
import math
from pathlib import Path
from typing import Any

import pytest

from tests.conftest import invoke

HERE = Path(__file__).parent
EXAMPLES = HERE.parents[1] / "examples"
RTOL = 1e-12

RUNS = [
    "ntua_stern_tube",
    "ntua_stern_tube_thermal",
    "seed001_water_rig",
    "seed001_water_rig_layer",
    "seed001_water_rig_liner",
    pytest.param("seed001_rig_alignment_liner", marks=pytest.mark.slow),
    "single_screw_alignment",
    pytest.param("ntua_shaft_line", marks=pytest.mark.slow),
    "monitor_rig",
    "contact_ehl",
    "gears_fzg_a",
    "gears_scuffing",
    "cpp_blade_bearing",
    "ferry_wear",
]
STRIBECK = ["ntua_stern_tube", "seed001_water_rig", "seed001_water_rig_liner"]


def snapshot(name: str) -> dict[str, Any]:
    document = json.loads((HERE / "snapshots" / f"{name}.json").read_text())
    document.pop("shaftline_version", None)
    return document


def differences(actual: Any, expected: Any, path: str = "", scale: float = 0.0) -> list[str]:
    """Where two JSON values differ beyond :data:`RTOL`, as readable lines."""
    if isinstance(expected, dict):
        if not isinstance(actual, dict) or set(actual) != set(expected):
            return [f"{path}: keys {sorted(actual) if isinstance(actual, dict) else actual!r} != {sorted(expected)}"]
        return [line for key in expected for line in differences(actual[key], expected[key], f"{path}.{key}")]
    if isinstance(expected, list):
        if not isinstance(actual, list) or len(actual) != len(expected):
            return [f"{path}: length {len(actual) if isinstance(actual, list) else actual!r} != {len(expected)}"]
        numbers = [abs(v) for v in expected if isinstance(v, (int, float)) and not isinstance(v, bool)]
        largest = max(numbers, default=0.0)
        return [
            line
            for k, (a, e) in enumerate(zip(actual, expected, strict=True))
            for line in differences(a, e, f"{path}[{k}]", largest)
        ]
    if isinstance(expected, (bool, str)) or expected is None or isinstance(actual, (bool, str)) or actual is None:
        return [] if actual == expected else [f"{path}: {actual!r} != {expected!r}"]
    close = math.isclose(actual, expected, rel_tol=RTOL, abs_tol=RTOL * scale)
    return [] if close else [f"{path}: {actual!r} != {expected!r}"]


def test_differences_see_a_change_of_one_part_in_a_hundred_billion():
    reference = {"a": [1.0, 2.0, {"b": 3.0}], "c": "film"}
    assert differences({"a": [1.0, 2.0, {"b": 3.0}], "c": "film"}, reference) == []
    assert differences({"a": [1.0, 2.0 * (1 + 1e-11), {"b": 3.0}], "c": "film"}, reference) != []
    assert differences({"a": [1.0, 2.0, {"b": 3.0}], "c": "contact"}, reference) != []
    assert differences({"a": [1.0, 2.0, {"b": 3.0, "d": 1}], "c": "film"}, reference) != []
    # An entry that is rounding beside its list's largest one is held to 1e-12 of that one.
    assert differences({"a": [1e-17, 2.0]}, {"a": [-1e-17, 2.0]}) == []
    assert differences({"a": [1e-11, 2.0]}, {"a": [-1e-17, 2.0]}) != []


@pytest.mark.parametrize("name", RUNS)
def test_run_gives_the_snapshot(name, example_document):
    actual = example_document(name)
    actual.pop("shaftline_version", None)
    assert differences(actual, snapshot(name)) == []


@pytest.mark.parametrize("name", STRIBECK)
def test_stribeck_verb_gives_the_snapshot(name, monkeypatch):
    monkeypatch.chdir(EXAMPLES)
    outcome = invoke("bearing", "stribeck", f"{name}.toml", "--json", "-")
    assert outcome.exit_code == 0, outcome.output
    actual = json.loads(outcome.stdout)
    actual.pop("shaftline_version", None)
    assert differences(actual, snapshot(f"stribeck-{name}")) == []
