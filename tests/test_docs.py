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


def test_numbered_references_to_the_theory_name_sections_that_exist():
    """ "docs/theory.md 19.3", "theory Sect. 10.1", "theory 17" in the README, the docs and the
    code name a numbered heading of docs/theory.md. The gear sections moved from 17 to 19 and
    the README still sent the FZG example's reader to 17.3 and 17.5 (mixed lubrication, which
    has no such subsections)."""
    import re

    root = README.parent
    theory = (root / "docs" / "theory.md").read_text(encoding="utf-8")
    numbered = set(re.findall(r"^#{2,4} (\d+(?:\.\d+)?)\.? ", theory, flags=re.MULTILINE))
    reference = re.compile(r"theory(?:\.md)?,? (?:Sect\. )?(\d+(?:\.\d+)?)(?![\d.]*\d)")
    files = [README, *(root / "docs").glob("*.md"), *(root / "src" / "shaftline").rglob("*.py")]
    stale = []
    for path in files:
        for number in reference.findall(path.read_text(encoding="utf-8")):
            if number not in numbered:
                stale.append(f"{path.relative_to(root)}: theory {number}")
    assert len(numbered) > 30 and stale == []


def test_the_readme_command_lines_name_every_option():
    """Each verb's line under README "Command line" names every option the verb has (`align`,
    `bearing stribeck` and others left out `--strict`, `--scheduler`, `--store`, `--json`, which
    `--help` lists)."""
    import typer

    from shaftline.cli import make_app

    text = README.read_text(encoding="utf-8")
    block = text[text.index("## Command line") : text.index("`--json -` writes")].splitlines()

    def verbs(command, path):
        subcommands = getattr(command, "commands", None)
        if subcommands:
            for name, sub in subcommands.items():
                yield from verbs(sub, [*path, name])
        else:
            yield path, command

    missing = []
    checked = 0
    for path, command in verbs(typer.main.get_command(make_app()), []):
        head = "shaftline " + " ".join(path)
        lines = [line for line in block if line == head or line.startswith(head + " ")]
        synopsis = lines[0].split("  #")[0] if lines else ""
        for parameter in command.params:
            if parameter.param_type_name != "option":
                continue
            checked += 1
            if not any(f"{name} " in synopsis + " " or f"{name}]" in synopsis for name in parameter.opts):
                missing.append(f"{head}: {'/'.join(parameter.opts)}")
    assert checked > 40 and missing == []
