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
from collections.abc import Iterable, Iterator, Mapping
from dataclasses import dataclass, field
from functools import cached_property
from pathlib import Path
from typing import Any

import shaftline
from shaftline.registry import Capability, Finding, Progress, capabilities, no_progress


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
    inputs : tuple of Path
        Every file the case was read from: the case file and the data files it names (no
        output may be one of them).
    kept : tuple of Path
        Files the run writes in place and keeps (:attr:`~shaftline.registry.BuildContext.kept`,
        a trend database): no output may be one of them or a result folder hold one.
    tables : mapping
        The case's tables as validated, in SI with every default filled in (the record of
        what was solved).
    fingerprints : tuple
        (path, SHA-256, bytes) of every input file as read.
    unusual : tuple of str
        Fields whose plausibility guard the case lowered (``[case] unusual``: dotted
        case-file paths such as ``"bearing.length"``), in the order given; the report should
        say so, as their values were accepted outside the plausible range.
    warnings : tuple of str
        What building the case left out of its defaults (:attr:`BuildContext.warnings`): the
        command line shows them before solving, the report at its top, the JSON under
        ``warnings`` (only when there are some).
    """

    name: str
    description: str
    studies: Mapping[str, Any] = field(default_factory=dict)
    source: Path | None = None
    inputs: tuple[Path, ...] = ()
    kept: tuple[Path, ...] = ()
    tables: Mapping[str, Any] = field(default_factory=dict)
    fingerprints: tuple[tuple[str, str, int], ...] = ()
    unusual: tuple[str, ...] = ()
    warnings: tuple[str, ...] = ()

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

    @cached_property
    def findings(self) -> list[tuple[str, Finding]]:
        """(capability key, finding) of every capability, in report order (found once)."""
        return [
            (capability.key, item) for capability, value in self.capabilities() for item in capability.findings(value)
        ]


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


def acceptable(result: CaseResult, strict: bool = False) -> bool:
    """No finding that makes the result unacceptable (with ``strict``, no finding at all)."""
    return not any(strict or not item.criterion for _, item in result.findings)


def finding_line(subject: str, item: Finding) -> str:
    """A finding as one line of the terminal or the report, naming what it is about."""
    return f"{'' if item.criterion else 'NOT ACCEPTABLE: '}{subject}: {item.text}"


def results_document(result: CaseResult) -> dict[str, Any]:
    """The JSON document of a run: version, case name, the findings and one entry per capability."""
    document: dict[str, Any] = {
        "shaftline_version": shaftline.__version__,
        "case": result.case.name,
        "findings": [
            {"capability": key, "text": item.text, "criterion": item.criterion} for key, item in result.findings
        ],
    }
    if result.case.warnings:
        document["warnings"] = list(result.case.warnings)
    for capability, value in result.capabilities():
        document[capability.key] = capability.to_json(value)
    return document


def dumps(document: Mapping[str, Any]) -> str:
    """JSON text; NaN and infinities are refused (they are not JSON)."""
    return json.dumps(document, indent=2, allow_nan=False)


def findings_blocks(result: CaseResult) -> list[Any]:
    """The findings as warnings, for the top of the terminal output and of the report."""
    from shaftline.report.blocks import Paragraph

    titles = {capability.key: capability.title for capability, _ in result.capabilities()}
    return [Paragraph(finding_line(titles[key], item), "warn") for key, item in result.findings]


def report_sections(result: CaseResult) -> list[Any]:
    """The lowered plausibility guards and the findings first (if any), then one report
    section per capability of the run, then the record of its inputs."""
    from shaftline.report.blocks import Paragraph, Section

    sections = []
    if result.case.unusual:
        text = (
            "These values lie outside the range a ship's shaft line has and were accepted because the case "
            "lists them under [case] unusual: " + ", ".join(result.case.unusual) + "."
        )
        sections.append(Section("unusual", "Values accepted outside the plausible range", [Paragraph(text, "warn")]))
    if result.case.warnings:
        blocks = [Paragraph(text, "warn") for text in result.case.warnings]
        sections.append(Section("warnings", "Left out of the defaults", blocks))
    blocks = findings_blocks(result)
    if blocks:
        unacceptable = not acceptable(result)
        title = "The result is not acceptable" if unacceptable else "Design criteria not met"
        sections.append(Section("findings", title, blocks))
    sections += [
        Section(capability.key, capability.title, capability.report(value))
        for capability, value in result.capabilities()
    ]
    return sections + [inputs_section(result.case)]


def inputs_section(case: Case) -> Any:
    """The record of what was solved: the input files with their SHA-256, the case file as
    written and the case as read (SI, every default and solver setting filled in)."""
    import platform

    from shaftline.report.blocks import Details, Paragraph, Preformatted, Section, Table

    blocks: list[Any] = [
        Paragraph(
            f"shaftline {shaftline.__version__}, Python {platform.python_version()}, {platform.system()}. "
            "The SHA-256 of a file identifies its content: the same hash, the same input."
        )
    ]
    if case.fingerprints:
        blocks.append(Table(["file", "SHA-256", "bytes"], [[p, h, str(n)] for p, h, n in case.fingerprints], "Inputs"))
    if case.source is not None:
        try:
            blocks.append(Details("the case file as written", [Preformatted(case.source.read_text(encoding="utf-8"))]))
        except (OSError, UnicodeDecodeError):
            pass
    if case.tables:
        text = json.dumps(case.tables, indent=2, default=str)
        blocks.append(Details("the case as read: SI units, every default and solver setting", [Preformatted(text)]))
    return Section("inputs", "Inputs of this run", blocks)


def write_folder(
    out: str | Path,
    document: Mapping[str, Any],
    sections: list[Any],
    title: str,
    description: str = "",
    source: str = "",
    source_label: str = "case file",
    progress: Progress = no_progress,
) -> Path:
    """Write ``results.json`` (``document``), the figures of ``sections`` and ``report.html``
    into the result folder ``out`` (:mod:`shaftline.outputs`): all files or none, files of
    others left alone. The command line checks ``out`` with
    :func:`shaftline.outputs.check_folder` before solving; this function checks it again."""
    from shaftline.outputs import check_folder, result_folder
    from shaftline.report.html import write_report

    out = Path(out)
    check_folder(out, field="out")
    with result_folder(out) as folder:
        (folder / "results.json").write_text(dumps(document) + "\n", encoding="utf-8")
        write_report(folder, title, description, source, sections, shaftline.__version__, source_label, progress)
    return out


def write_outputs(result: CaseResult, out: str | Path, case_file: str = "") -> Path:
    """Write ``results.json``, the figures and ``report.html`` of a run into ``out`` (atomically)."""
    case = result.case
    source = case_file or (str(case.source) if case.source else "")
    return write_folder(out, results_document(result), report_sections(result), case.name, case.description, source)
