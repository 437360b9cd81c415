"""The examples' results documents, each solved once for both regression tests (the version-0.1
baseline and the snapshots): a run of an example takes seconds, and both compare the same run."""

from __future__ import annotations

import json
import os
from pathlib import Path
from typing import Any

import pytest

from shaftline.cases import load_case
from shaftline.pipeline import dumps, results_document, run_case

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"


@pytest.fixture(scope="session")
def example_document():
    """``example_document(name)``: the results JSON of ``examples/<name>.toml`` as ``shaftline run``
    writes it (solved in the examples folder, whose data files the cases name relative to it)."""
    solved: dict[str, str] = {}

    def document(name: str) -> dict[str, Any]:
        if name not in solved:
            here = Path.cwd()
            os.chdir(EXAMPLES)
            try:
                solved[name] = dumps(results_document(run_case(load_case(Path(f"{name}.toml")))))
            finally:
                os.chdir(here)
        return json.loads(solved[name])

    return document
