"""Compare a code change against the code before it, on one machine, to 1e-12 relative.

The snapshot test holds every example to what two machines' floating-point kernels leave of the
same arithmetic (1e-8). A reorganisation of the code (a refactor, a faster kernel that should
round the same) is checked more closely on one machine, before and after::

    git switch --detach BASE && python -m tests.regression.snapshot_check write /tmp/before
    git switch -             && python -m tests.regression.snapshot_check compare /tmp/before

``write`` refuses a folder that already holds documents, so an earlier run is not overwritten.
``compare`` prints each number that differs beyond 1e-12 (an entry of a list: 1e-12 of the list's
largest magnitude; the residual-level numbers within their absolute bounds) and exits 1 if any do.
"""

from __future__ import annotations

import argparse
import json
import os
import sys
from collections.abc import Iterator
from pathlib import Path
from typing import Any

from tests.regression.compare import compare

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"
RTOL = 1e-12
NAMES = [path.stem for path in sorted((Path(__file__).parent / "snapshots").glob("*.json"))]


def documents() -> Iterator[tuple[str, dict[str, Any]]]:
    """Each snapshot's name and the current code's results document for it."""
    from typer.testing import CliRunner

    from shaftline.cases import load_case
    from shaftline.cli import make_app
    from shaftline.pipeline import dumps, results_document, run_case

    os.chdir(EXAMPLES)
    for name in NAMES:
        if name.startswith("stribeck-"):
            outcome = CliRunner().invoke(make_app(), ["bearing", "stribeck", f"{name[9:]}.toml", "--json", "-"])
            text = outcome.stdout
        else:
            text = dumps(results_document(run_case(load_case(Path(f"{name}.toml")))))
        document = json.loads(text)
        document.pop("shaftline_version", None)
        yield name, document


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("action", choices=["write", "compare"])
    parser.add_argument("folder", type=Path)
    arguments = parser.parse_args(argv)
    folder: Path = arguments.folder.resolve()
    if arguments.action == "write":
        if folder.exists() and any(folder.glob("*.json")):
            print(f"{folder} already holds documents; give an empty or new folder", file=sys.stderr)
            return 2
        folder.mkdir(parents=True, exist_ok=True)
        for name, document in documents():
            (folder / f"{name}.json").write_text(json.dumps(document, indent=1))
            print(f"wrote {name}")
        return 0
    differing = 0
    for name, document in documents():
        lines = compare(document, json.loads((folder / f"{name}.json").read_text()), RTOL, RTOL)
        differing += bool(lines)
        print(f"{name}: {'same' if not lines else f'{len(lines)} numbers differ'}")
        for line in lines:
            print(f"  {line}")
    return 1 if differing else 0


if __name__ == "__main__":
    raise SystemExit(main())
