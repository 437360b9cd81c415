"""Import cost of the shaft package: the command line must start in well under 0.5 s and the
case schema reads its defaults from the ``shaftline.shaft.model`` dataclasses and rules
through ``shaftline.shaft.rules``, so none of ``shaftline.shaft``, ``shaftline.shaft.model``
and ``shaftline.shaft.rules`` may pull in scipy (about 0.4 s to import).

Each check runs in a fresh interpreter: in this one, other tests have imported scipy already.
"""

from __future__ import annotations

import json
import subprocess
import sys

import pytest

# Only what the import adds: site start-up (.pth hooks) loads modules of its own.
PROBE = """
import json, sys
before = set(sys.modules)
import {module}
print(json.dumps(sorted(set(sys.modules) - before)))
"""


def loaded_after(module: str) -> list[str]:
    run = subprocess.run(
        [sys.executable, "-c", PROBE.format(module=module)], capture_output=True, text=True, timeout=60, check=True
    )
    return json.loads(run.stdout)


def third_party(modules: list[str]) -> set[str]:
    return {m.split(".")[0] for m in modules} - set(sys.stdlib_module_names) - {"shaftline"}


def test_model_imports_only_numpy_and_the_errors_module():
    modules = loaded_after("shaftline.shaft.model")
    assert third_party(modules) <= {"numpy"}
    own = {m for m in modules if m.startswith("shaftline")}
    assert own == {"shaftline", "shaftline.errors", "shaftline.shaft", "shaftline.shaft.model"}


def test_rules_import_without_the_solver():
    """The case schema reads rules files through shaftline.shaft.rules."""
    modules = loaded_after("shaftline.shaft.rules")
    assert "scipy" not in third_party(modules)
    assert "shaftline.shaft.alignment" not in modules


def test_package_import_leaves_scipy_for_first_use():
    modules = loaded_after("shaftline.shaft")
    assert "scipy" not in third_party(modules)
    assert "shaftline.shaft.alignment" not in modules


@pytest.mark.parametrize("name", ["AlignmentModel", "BearingResult", "ConditionResult", "InfluenceMatrix"])
def test_lazy_names_resolve_to_the_alignment_module(name):
    import shaftline.shaft as shaft
    from shaftline.shaft import alignment

    assert getattr(shaft, name) is getattr(alignment, name)
    assert name in dir(shaft)


def test_unknown_name_is_an_attribute_error():
    import shaftline.shaft as shaft

    with pytest.raises(AttributeError, match="no attribute 'Nope'"):
        _ = shaft.Nope
