"""A case from file to results: solve, the JSON document, the report folder.

The same steps run from the command line and from a notebook::

    from shaftline import load_case, run_case
    result = run_case(load_case("examples/ntua_stern_tube.toml"))
    result["bearing"].cases[0].equilibrium.state.min_film_thickness

Each step iterates over the capabilities of the case (the registry); nothing here knows a
capability by name.
"""

from __future__ import annotations

import json
import os
import shutil
import tempfile
from collections.abc import Iterable, Iterator, Mapping
from contextlib import contextmanager
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import shaftline
from shaftline.registry import Capability, Progress, capabilities, no_progress


@dataclass(frozen=True, eq=False)
class Case:
    """A validated case: its labels and, per capability key, the study in SI domain objects.

    Attributes
    ----------
    name, description : str
        Labels for the report.
    studies : mapping
        Capability key -> what its ``build`` made of the case-file table, in registry order.
    source : Path or None
        The case file, when read from one.
    unusual : tuple of str
        Fields whose plausibility guard the case lowered (``[case] unusual``: dotted
        case-file paths such as ``"bearing.length"``), in the order given; the report should
        say so, as their values were accepted outside the plausible range.
    """

    name: str
    description: str
    studies: Mapping[str, Any] = field(default_factory=dict)
    source: Path | None = None
    unusual: tuple[str, ...] = ()

    def __getitem__(self, key: str) -> Any:
        return self.studies[key]

    def __contains__(self, key: object) -> bool:
        return key in self.studies


@dataclass(frozen=True, eq=False)
class CaseResult:
    """The results of a case, per capability key, in registry order, with the capabilities
    that made them (so that writing them does not depend on the registry of the moment)."""

    case: Case
    results: Mapping[str, Any]
    solved_by: Mapping[str, Capability[Any, Any, Any]] = field(default_factory=dict)

    def __getitem__(self, key: str) -> Any:
        return self.results[key]

    def __contains__(self, key: object) -> bool:
        return key in self.results

    def capabilities(self) -> Iterator[tuple[Capability[Any, Any, Any], Any]]:
        """(capability, result) pairs in report order."""
        for key, result in self.results.items():
            yield self.solved_by.get(key) or capabilities()[key], result


def run_case(
    case: Case,
    only: Iterable[str] | None = None,
    options: Mapping[str, Mapping[str, Any]] | None = None,
    progress: Progress = no_progress,
) -> CaseResult:
    """Solve every study of ``case`` (or those named in ``only``).

    Parameters
    ----------
    case : Case
        From :func:`shaftline.cases.load_case` or :func:`shaftline.cases.parse_case`.
    only : iterable of str, optional
        Capability keys to solve; by default all the case has.
    options : mapping, optional
        Per capability key, keyword arguments of its ``solve``.
    progress : callable, optional
        Called with a short text as the work goes on.
    """
    from shaftline.errors import located

    registry = capabilities()
    wanted = set(case.studies if only is None else only)
    unknown = wanted - set(registry)
    if unknown:
        raise ValueError(f"no capability named {sorted(unknown)[0]!r}: " + ", ".join(registry))
    results, solved_by = {}, {}
    for key, study in case.studies.items():
        if key in wanted:
            # an input found wrong only while solving is named under its table
            with located(key):
                results[key] = registry[key].solve(study, progress, **(options or {}).get(key, {}))
            solved_by[key] = registry[key]
    return CaseResult(case, results, solved_by)


def results_document(result: CaseResult) -> dict[str, Any]:
    """The JSON document of a run: version, case name and one entry per capability."""
    document: dict[str, Any] = {"shaftline_version": shaftline.__version__, "case": result.case.name}
    for capability, value in result.capabilities():
        document[capability.key] = capability.to_json(value)
    return document


def dumps(document: Mapping[str, Any]) -> str:
    """JSON text; NaN and infinities are refused (they are not JSON)."""
    return json.dumps(document, indent=2, allow_nan=False)


def write_text_atomic(path: Path, text: str) -> None:
    """Write ``text`` to ``path`` through a temporary file in the same folder."""
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    fd, temporary = tempfile.mkstemp(dir=path.parent, prefix=f".{path.name}.", suffix=".tmp")
    try:
        with os.fdopen(fd, "w", encoding="utf-8") as handle:
            handle.write(text)
        os.replace(temporary, path)
    except BaseException:
        Path(temporary).unlink(missing_ok=True)
        raise


@contextmanager
def atomic_folder(out: Path) -> Iterator[Path]:
    """Yield a temporary folder that replaces ``out`` only if the block completes."""
    out = Path(out)
    out.parent.mkdir(parents=True, exist_ok=True)
    temporary = Path(tempfile.mkdtemp(dir=out.parent, prefix=f".{out.name}."))
    try:
        yield temporary
        if out.exists():
            old = out.with_name(f".{out.name}.old")
            shutil.rmtree(old, ignore_errors=True)
            out.rename(old)
            temporary.rename(out)
            shutil.rmtree(old, ignore_errors=True)
        else:
            temporary.rename(out)
    except BaseException:
        shutil.rmtree(temporary, ignore_errors=True)
        raise


def report_sections(result: CaseResult) -> list[Any]:
    """One report section per capability of the run."""
    from shaftline.report.blocks import Section

    return [
        Section(capability.key, capability.title, capability.report(value))
        for capability, value in result.capabilities()
    ]


def write_folder(
    out: str | Path,
    document: Mapping[str, Any],
    sections: list[Any],
    title: str,
    description: str = "",
    source: str = "",
    source_label: str = "case file",
) -> Path:
    """Write ``results.json`` (``document``), the figures of ``sections`` and ``report.html``
    into the folder ``out``, atomically: a failure leaves no half-written folder."""
    from shaftline.report.html import write_report

    out = Path(out)
    with atomic_folder(out) as folder:
        (folder / "results.json").write_text(dumps(document) + "\n", encoding="utf-8")
        write_report(folder, title, description, source, sections, shaftline.__version__, source_label)
    return out


def write_outputs(result: CaseResult, out: str | Path, case_file: str = "") -> Path:
    """Write ``results.json``, the figures and ``report.html`` of a run into ``out`` (atomically)."""
    case = result.case
    source = case_file or (str(case.source) if case.source else "")
    return write_folder(out, results_document(result), report_sections(result), case.name, case.description, source)
