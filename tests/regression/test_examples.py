"""Every example gives the numbers it gave before the pipeline refactor (issue 8).

Reference: ``baseline/*.json``, written by shaftline at commit b95902c (see README.md here).
The case files have since moved to the one-table-per-capability layout and the bearing
film's results moved from the top level of the JSON to ``bearing.cases``; the comparison
maps the old layout onto the new one and then compares every number.

Tolerance: relative 1e-7, or 1e-9 of the largest magnitude in the same list for entries
near zero. The film and wear numerics are unchanged and agree to the last digit; the
tolerance leaves room for the alignment's contact QP, whose converged results may differ
in the last digits if its linear algebra is reorganised — far below any engineering
meaning (1e-7 of a reaction of 1 MN is 0.1 N). The blade-carrier motion is held to 1e-6:
the old compiled kernel's Jacobian left out the Stribeck slope, and its Newton loop
accepted thousands of unconverged backward-Euler steps in the example (Newton tolerance
1e-9); the one model of both integrators converges them, which moves the fretting
amplitude by 1.2e-7 and the study by up to 2.7e-7 relative. With the Newton tolerance
tightened to 1e-14 the old and the new code give the new numbers to 1e-13.

Issue 10 replaced the carrier-motion numbers of ``cpp_blade_bearing.json`` (``cpp.motion``
fretting amplitude, sliding and pressure fluctuation, ``cpp.study.fretting_amplitude``): the
second-order TR-BDF2 integrator took the place of backward Euler, whose 7200 steps a
revolution were 1.5-3 % from the converged amplitude; see README.md here for the evidence.
The new keys on the periodic state are in :data:`ADDED`.
"""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

import pytest

from tests.conftest import invoke
from tests.regression.compare import compare as compare_documents

HERE = Path(__file__).parent
EXAMPLES = HERE.parents[1] / "examples"
#: Results added since the baseline (new information, not changed numbers), left out of the comparison.
ADDED = (
    "findings",
    "cpp.motion.fretting_amplitude_settled",
    "cpp.study.fretting_amplitude_settled_max",
    "cpp.study.revolutions",
    # issue 10: the integrator and the periodic state of the carrier motion
    "cpp.motion.revolutions_requested",
    "cpp.motion.method",
    "cpp.motion.periodic",
    "cpp.motion.period",
    "cpp.motion.periodic_change",
    "cpp.motion.periodic_tolerance",
    "cpp.study.revolutions_integrated",
    "cpp.study.periodic",
    "cpp.study.period",
    # issue 11: the film's 4 x 4 stiffness and damping with the tilt terms, in every bearing case
    "bearing.cases.stiffness_4x4",
    "bearing.cases.damping_4x4",
    "bearing.units.stiffness_4x4",
    "bearing.units.damping_4x4",
    # which influence matrix is shown, and how the offset optimisation ran
    "alignment.influence_matrix.kind",
    "alignment.influence_matrix.label",
    "alignment.influence_matrix.condition",
    "alignment.optimised_offsets.rounds",
    "alignment.optimised_offsets.settled",
    "alignment.optimised_offsets.note",
    "alignment.optimised_offsets.influence",
)
RTOL = 1e-7
RTOL_CARRIER = 1e-6
ATOL_SHARE = 1e-9


def baseline(name: str) -> dict[str, Any]:
    return json.loads((HERE / "baseline" / f"{name}.json").read_text())


def new_layout(old: dict[str, Any]) -> dict[str, Any]:
    """The version-0.1 document in today's layout: the film's base case and variants under
    ``bearing.cases``, its units under ``bearing.units``."""
    if "case" not in old:  # a tool's document (the Weibull verb), not a case's
        return old
    capability_keys = {"alignment", "wear", "cpp"}
    head = {"shaftline_version", "case"}
    out = {key: value for key, value in old.items() if key in capability_keys | head}
    if "variants" in old:
        base = {k: v for k, v in old.items() if k not in capability_keys | head | {"variants", "units"}}
        out["bearing"] = {"units": old["units"], "cases": [base, *old["variants"]]}
    return out


def without_added(document: dict[str, Any]) -> dict[str, Any]:
    """``document`` without the entries of :data:`ADDED` (a list on the path: from each item)."""
    for dotted in ADDED:
        *parents, last = dotted.split(".")
        nodes: list[Any] = [document]
        for part in parents:
            nodes = [node.get(part, {}) for node in nodes if isinstance(node, dict)]
            nodes = [item for node in nodes for item in (node if isinstance(node, list) else [node])]
        for node in nodes:
            if isinstance(node, dict):
                node.pop(last, None)
    return document


def compare(actual: Any, expected: Any, rtol: float = RTOL) -> list[str]:
    """Differences between two JSON values beyond the tolerance, as readable lines."""
    return compare_documents(actual, expected, rtol, ATOL_SHARE)


def test_compare_sees_a_change():
    """The comparison itself: a relative change of 1e-6 in one number of a list is caught."""
    reference = {"a": [1.0, 2.0, {"b": 3.0}]}
    assert compare({"a": [1.0, 2.0, {"b": 3.0}]}, reference) == []
    assert compare({"a": [1.0, 2.000002, {"b": 3.0}]}, reference) == ["a[1]: 2.000002 != 2.0"]
    assert compare({"a": [1.0, 2.0, {"b": 3.0, "c": 1}]}, reference) != []
    # A residual-level number may round differently, a real change of it is still seen.
    assert compare({"c": {"force_z": 3e-9}}, {"c": {"force_z": -2e-9}}) == []
    assert compare({"c": {"force_z": 1e-2}}, {"c": {"force_z": -2e-9}}) == ["c.force_z: 0.01 != -2e-09"]


@pytest.mark.parametrize(
    "name",
    [
        "ntua_stern_tube",
        "single_screw_alignment",
        "ferry_wear",
        pytest.param("cpp_blade_bearing", marks=pytest.mark.slow),
    ],
)
def test_run_matches_baseline(name, example_document):
    expected = new_layout(baseline(name))
    actual = example_document(name)
    actual["shaftline_version"] = expected["shaftline_version"]
    actual = without_added(actual)
    assert compare(actual, expected, rtol=RTOL_CARRIER if name == "cpp_blade_bearing" else RTOL) == []


@pytest.mark.parametrize(
    "name, args",
    [
        ("ferry_wear_pitchlog", ["wear", "pitchlog", "ferry_pitch_log.csv", "--case", "ferry_wear.toml"]),
        ("cpp_blade_bearing_fretting", ["cpp", "fretting", "cpp_blade_bearing.toml"]),
        ("wear_test_6_weibull", ["wear", "weibull", "wear_test_6_depths.csv", "--threshold", "0.12"]),
    ],
)
def test_verbs_match_baseline(name, args, monkeypatch):
    monkeypatch.chdir(EXAMPLES)
    outcome = invoke(*args, "--json", "-")
    assert outcome.exit_code == 0, outcome.output
    expected = new_layout(baseline(name))
    actual = json.loads(outcome.stdout)
    if "shaftline_version" in expected:
        actual["shaftline_version"] = expected["shaftline_version"]
    actual = without_added(actual)
    assert compare(actual, expected) == []
