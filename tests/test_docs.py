"""The README's generated parts are what the code says: the case-file tables come from the
schema, the bearing JSON fields from the list the JSON is written from."""

from __future__ import annotations

from pathlib import Path

import pytest

from shaftline.cases.docs import GENERATED, readme_part

README = Path(__file__).resolve().parents[1] / "README.md"


@pytest.mark.parametrize("name", list(GENERATED))
def test_readme_part_is_generated(name):
    assert readme_part(README.read_text(encoding="utf-8"), name) == GENERATED[name](), (
        f"README part '{name}' is stale: run python -m shaftline.cases.docs README.md"
    )


def test_every_schema_field_has_a_description():
    from pydantic import BaseModel

    from shaftline.cases.loader import case_model
    from shaftline.cases.types import nested_model

    missing = []

    def walk(model: type[BaseModel], path: str) -> None:
        for name, info in model.model_fields.items():
            if not info.description:
                missing.append(f"{path}.{name}")
            nested = nested_model(info.annotation)
            if nested is not None:
                walk(nested[0], f"{path}.{name}")

    walk(case_model(), "")
    assert missing == []


def test_every_schema_field_type_is_resolved():
    """A field whose annotation is still a ForwardRef (a table named before it is defined,
    e.g. a bearing's own ``film`` table) prints as ``ForwardRef(...)`` in the README, drops
    out of the ranges table and loses the "did you mean" of a misspelt key."""
    from typing import ForwardRef

    from pydantic import BaseModel

    from shaftline.cases.loader import case_model
    from shaftline.cases.types import nested_model

    unresolved = []

    def walk(model: type[BaseModel], path: str) -> None:
        for name, info in model.model_fields.items():
            if isinstance(info.annotation, (ForwardRef, str)):
                unresolved.append(f"{path}.{name}")
            nested = nested_model(info.annotation)
            if nested is not None:
                walk(nested[0], f"{path}.{name}")

    walk(case_model(), "")
    assert unresolved == []
