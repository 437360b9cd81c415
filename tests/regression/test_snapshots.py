"""Every example gives the numbers it gave when the snapshots were written.

Reference: ``snapshots/*.json``, the results JSON of each example (``shaftline run CASE --json``)
and of the Stribeck verb on the film examples (``shaftline bearing stribeck CASE --json``), as
written by shaftline before the film solver was split into one module per job (README.md here
says how they were made). On the machine that wrote them the split gave the same numbers to
1e-12; this test runs on any machine, so its tolerance is what two machines' floating-point
kernels leave of the same arithmetic:

* 1e-8 relative for every number (an entry of a list also within 1e-12 of the list's largest
  magnitude). Between the machine that wrote the snapshots and an AMD EPYC with the same numpy
  2.4 and scipy 1.17 the film examples differ by at most 3e-11, the alignment, design-search
  and coupled examples by at most 8e-10 (the offset plan's objective: the plan is the vertex
  of a linear programme, whose coordinates amplify the rounding of the influence
  coefficients), the contact, gear, wear and CPP examples by at most 1e-15. 1e-8 leaves a
  factor of ten above that and is the film equilibrium's own force tolerance, so a change of
  any physics moves some number by more.
* the residual-level numbers of ``compare.RESIDUAL_ATOL`` (a vertical load's horizontal film
  force, the moments of an aligned film, the monitor's fit residual) within absolute bounds far
  below anything physical: they are rounding of a converged iteration and differ between
  machines by orders of magnitude relative (1e-16 to 1e-3 N).
* strings, flags and counts (Newton iterations) exactly, so a change of the solver's path shows
  there even where its numbers stay inside the tolerance.

``snapshot_check.py`` here compares a code change on one machine to 1e-12.

Changes since the snapshots were written are listed, each with its reason, in :data:`ADDED`
(new entries, left out of the comparison), :data:`REMOVED` (entries no longer written) and
:data:`MOVED` (an entry that now stands under another name, compared there).

The examples whose run takes longest are marked slow; they still run in the suite.
"""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

import pytest

from tests.conftest import invoke
from tests.regression.compare import compare

HERE = Path(__file__).parent
EXAMPLES = HERE.parents[1] / "examples"
RTOL = 1e-8
SHARE = 1e-12

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

#: Entries added since the snapshots, left out of the run's document before the comparison (on a
#: list, from each item), each with its reason.
ADDED = {
    "alignment.influence_matrix.kind": "which matrix is shown: the declared supports' or the film tangent",
    "alignment.influence_matrix.label": "the same in words",
    "alignment.influence_matrix.condition": "the condition a film tangent was taken in",
    "alignment.film_supports.influence_matrix": "each condition's film tangent (new numbers, see MOVED)",
    "alignment.optimised_offsets.rounds": "the optimisation's linearise-and-solve rounds",
    "alignment.optimised_offsets.settled": "whether the rounds settled",
    "alignment.optimised_offsets.note": "why they stopped unsettled",
    "alignment.optimised_offsets.influence": "which influence coefficients the rounds used",
    **{
        f"alignment.{where}.{key}": "a film's resultant in each plane and its support point there (see REMOVED)"
        for where in ("film_supports.films", "units")
        for key in ("moment_y", "moment_z", "support_point_y", "support_point_z", "couple_planes")
    },
}

#: Entries of the snapshots no longer written, left out of the snapshot before the comparison, each
#: with its reason.
REMOVED = {
    "alignment.film_supports.films.support_point": "one position projected on the resultant's direction, "
    "mixing both planes and outside the bearing when the film carries a couple; now per plane",
    "alignment.units.support_point": "its unit",
}

#: Entries that stand under another name since the snapshots: the snapshot's entry (key) is
#: compared with the run's (value), and the run's entry under the old name is left out. On film
#: supports ``influence_matrix`` was the declared supports' matrix and did not say so; it is now
#: the film-supported line's tangent (new numbers, checked against central differences of
#: re-solved coupled equilibria in tests/shaft/test_film_tangent.py), and the declared supports'
#: matrix, unchanged, stands beside it.
MOVED = {"alignment.influence_matrix.matrix": "alignment.point_supports_influence_matrix.matrix"}


def snapshot(name: str) -> dict[str, Any]:
    """The snapshot of ``name`` without :data:`REMOVED`."""
    document = json.loads((HERE / "snapshots" / f"{name}.json").read_text())
    document.pop("shaftline_version", None)
    if not name.startswith("stribeck-"):
        for dotted in REMOVED:
            _drop(document, dotted)
    return document


def _nodes(document: Any, parents: list[str]) -> list[Any]:
    """The values at the dotted path ``parents`` (through every item of a list on the way)."""
    nodes = [document]
    for part in parents:
        nodes = [node.get(part, {}) for node in nodes if isinstance(node, dict)]
        nodes = [item for node in nodes for item in (node if isinstance(node, list) else [node])]
    return nodes


def _drop(document: Any, dotted: str) -> None:
    *parents, last = dotted.split(".")
    for node in _nodes(document, parents):
        if isinstance(node, dict):
            node.pop(last, None)


def explained(actual: dict[str, Any]) -> dict[str, Any]:
    """The run's document with :data:`ADDED` left out and :data:`MOVED` put back under its old name."""
    for old, new in MOVED.items():
        *new_parents, new_last = new.split(".")
        moved = [node[new_last] for node in _nodes(actual, new_parents) if isinstance(node, dict) and new_last in node]
        if moved:
            *old_parents, old_last = old.split(".")
            (target,) = _nodes(actual, old_parents)
            target[old_last] = moved[0]
            (holder,) = _nodes(actual, new_parents[:-1])
            holder.pop(new_parents[-1])
    for dotted in ADDED:
        _drop(actual, dotted)
    return actual


def differences(actual: Any, expected: Any) -> list[str]:
    """Where two results documents differ beyond the tolerance of this test, as readable lines."""
    return compare(actual, expected, RTOL, SHARE)


def test_differences_see_a_change_of_one_part_in_ten_million():
    reference = {"a": [1.0, 2.0, {"b": 3.0}], "c": "film", "iterations": 9}
    assert differences({"a": [1.0, 2.0 * (1 + 5e-9), {"b": 3.0}], "c": "film", "iterations": 9}, reference) == []
    assert differences({"a": [1.0, 2.0 * (1 + 1e-7), {"b": 3.0}], "c": "film", "iterations": 9}, reference) != []
    assert differences({"a": [1.0, 2.0, {"b": 3.0}], "c": "contact", "iterations": 9}, reference) != []
    assert differences({"a": [1.0, 2.0, {"b": 3.0, "d": 1}], "c": "film", "iterations": 9}, reference) != []
    # A count is exact: another Newton path is seen even where every number agrees.
    assert differences({"a": [1.0, 2.0, {"b": 3.0}], "c": "film", "iterations": 8}, reference) != []
    # An entry that is rounding beside its list's largest one is held to 1e-12 of that one.
    assert differences({"a": [1e-17, 2.0]}, {"a": [-1e-17, 2.0]}) == []
    assert differences({"a": [1e-11, 2.0]}, {"a": [-1e-17, 2.0]}) != []
    # A residual-level number may round differently; a real change of it is still seen.
    assert differences({"c": {"force_z": 4.67e-6}}, {"c": {"force_z": -4.9e-5}}) == []
    assert differences({"c": {"force_z": 1e-2}}, {"c": {"force_z": -4.9e-5}}) != []


@pytest.mark.parametrize("name", RUNS)
def test_run_gives_the_snapshot(name, example_document):
    actual = explained(example_document(name))
    actual.pop("shaftline_version", None)
    assert differences(actual, snapshot(name)) == []


def test_a_moved_entry_is_compared_under_its_old_name():
    run = {
        "alignment": {
            "influence_matrix": {"matrix": [2.0], "kind": "film_tangent"},
            "point_supports_influence_matrix": {"matrix": [1.0], "kind": "point"},
        }
    }
    assert explained(run) == {"alignment": {"influence_matrix": {"matrix": [1.0]}}}
    point_only = {"alignment": {"influence_matrix": {"matrix": [1.0], "kind": "point", "label": "point supports"}}}
    assert explained(point_only) == {"alignment": {"influence_matrix": {"matrix": [1.0]}}}


@pytest.mark.parametrize("name", STRIBECK)
def test_stribeck_verb_gives_the_snapshot(name, monkeypatch):
    monkeypatch.chdir(EXAMPLES)
    outcome = invoke("bearing", "stribeck", f"{name}.toml", "--json", "-")
    assert outcome.exit_code == 0, outcome.output
    actual = json.loads(outcome.stdout)
    actual.pop("shaftline_version", None)
    assert differences(actual, snapshot(f"stribeck-{name}")) == []
