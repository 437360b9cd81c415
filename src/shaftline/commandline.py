"""What every command-line verb shares: running case files through the pipeline, printing
the summary, writing JSON and the report folder, and the one-line error with exit 2.

Kept apart from :mod:`shaftline.cli` so that a capability's own commands (its ``commands.py``,
:meth:`shaftline.registry.Capability.commands`) can use it without an import cycle.
:func:`~shaftline.helptext.strict_help` is importable from here too.
"""

from __future__ import annotations

import sys
from collections.abc import Iterator, Mapping, Sequence
from contextlib import contextmanager
from pathlib import Path
from typing import Annotated, Any, NoReturn

import typer
from rich.console import Console

from shaftline.errors import InputError, Interrupted
from shaftline.helptext import strict_help as strict_help  # the verbs' own commands build their help with it

console = Console()
error_console = Console(stderr=True)

JsonOption = Annotated[
    str | None, typer.Option("--json", help="Write results as JSON to PATH, or '-' for standard output.")
]
OutOption = Annotated[Path | None, typer.Option("--out", help="Folder for results.json, figures and report.html.")]
CaseArgument = Annotated[Path, typer.Argument(help="Case file (TOML).")]


#: ``--strict`` of ``run`` (every analysis of the case): each verb's own help names its criteria.
StrictOption = Annotated[
    bool,
    typer.Option(
        "--strict",
        help=strict_help(
            "a design criterion of any analysis fails (a class-rule check, a film limit, an allowable wear depth, a "
            "scuffing limit, gross fretting, a lambda alarm...: each verb's --strict help names its own)",
            "a result that is not acceptable (no convergence, a film at its floor, a rejected recording window...)",
        ),
    ),
]

WorkersOption = Annotated[
    int | None,
    typer.Option(
        "--workers",
        help=(
            "Worker processes for the analyses that spread their cases (default: one per core, or none "
            "where a command finds its work too small for a pool; 1: none)."
        ),
    ),
]
SchedulerOption = Annotated[
    str | None,
    typer.Option(
        "--scheduler",
        help="Address of a Dask scheduler (tcp://HOST:8786) to run on instead of this machine's cores.",
    ),
]

#: Exit status of a run that was solved but whose result is not acceptable.
NOT_ACCEPTABLE = 3


def fail(error: InputError) -> NoReturn:
    """Print ``error`` on one line of standard error and exit with status 2."""
    error_console.print(f"error: {error}", markup=False, highlight=False, soft_wrap=True)
    raise typer.Exit(code=2)


@contextmanager
def input_errors() -> Iterator[None]:
    """Turn an :class:`InputError` of the block into the one-line message and exit 2."""
    try:
        yield
    except InputError as error:
        fail(error)


@contextmanager
def interruptible() -> Iterator[None]:
    """Ctrl-C ends the command with exit status 130 and one line (and the note of an
    :class:`~shaftline.errors.Interrupted`: where a search keeps what it evaluated), a solver
    that fails on accepted inputs with 3 and one line; outputs are written all at once at the
    end (:mod:`shaftline.outputs`), so nothing half-written is left."""
    from shaftline.errors import SolverFailure, interrupted_by_user

    try:
        yield
    except (KeyboardInterrupt, SystemError) as stop:
        # Ctrl-C inside a compiled (numba) call arrives as a SystemError caused by it; any other
        # SystemError is a defect and keeps its traceback
        if not interrupted_by_user(stop):
            raise
        # an Interrupted run kept something elsewhere (a search's store): its note says where
        text = f"interrupted: no results were written; {stop.note}" if isinstance(stop, Interrupted) else ""
        error_console.print(text or "interrupted: nothing was written", markup=False, highlight=False, soft_wrap=True)
        raise typer.Exit(code=130) from None
    except SolverFailure as failure:
        error_console.print(f"not solved: {failure}; nothing was written", markup=False, highlight=False)
        raise typer.Exit(code=NOT_ACCEPTABLE) from None


def parallel_options(keys: Sequence[str], workers: int | None, scheduler: str | None) -> dict[str, dict[str, Any]]:
    """The ``--workers`` and ``--scheduler`` of a verb as ``solve`` options of the capabilities
    ``keys`` that spread their work (:attr:`~shaftline.registry.Capability.parallel`); raises
    :class:`InputError` for a value that cannot work, before anything is read."""
    from shaftline.registry import capabilities

    if workers is not None and workers < 1:
        raise InputError("--workers", workers, "", "an integer >= 1")
    if scheduler is not None:
        if workers is not None:
            raise InputError("--workers", workers, "", "no --workers with --scheduler (the cluster has its workers)")
        from shaftline.parallel import check_scheduler

        check_scheduler(scheduler, "--scheduler")
    given = {name: value for name, value in (("workers", workers), ("scheduler", scheduler)) if value is not None}
    registry = capabilities()
    return {key: dict(given) for key in keys if key in registry and registry[key].parallel}


def check_outputs(out: Path | None, json_path: str | None, inputs: Sequence[Path]) -> None:
    """Refuse output places that cannot be written or would replace an input or a foreign
    folder, before anything is solved (raises :class:`InputError`)."""
    from shaftline.outputs import check_file, check_folder

    if out is not None:
        check_folder(out, inputs)
    if json_path not in (None, "-"):
        json_file = Path(str(json_path))
        check_file(json_file, inputs)
        inside = out is not None and json_file.resolve().parent == out.resolve()
        if inside and json_file.name in ("results.json", "report.html"):
            raise InputError("--json", str(json_file), "", "a name other than the report folder's own files")


def deliver(
    document: Mapping[str, Any],
    json_path: str | None,
    out: Path | None,
    sections: Sequence[Any],
    title: str,
    description: str = "",
    source: str = "",
    source_label: str = "case file",
) -> None:
    """Write the report folder (showing which figure is being drawn), then the JSON file,
    then the JSON to standard output if asked.

    Both places were checked before solving (:func:`check_outputs`); the folder is written
    all at once and only then the JSON file, so a failure in the report leaves neither.
    """
    from shaftline.outputs import write_text
    from shaftline.pipeline import dumps, write_folder

    text = dumps(document) + "\n"
    if out is not None:
        with error_console.status("writing the report") as status:
            write_folder(
                out,
                document,
                list(sections),
                title,
                description,
                source,
                source_label,
                lambda text: status.update(str(text)),
            )
    if json_path not in (None, "-"):
        write_text(Path(str(json_path)), text)
    if json_path == "-":
        sys.stdout.write(text)


def run_cases(
    case_file: Path,
    json_path: str | None,
    out: Path | None,
    only: Sequence[str] | None = None,
    options: Mapping[str, Mapping[str, Any]] | None = None,
    overrides: Mapping[str, Any] | None = None,
    strict: bool = False,
) -> None:
    """Load ``case_file``, solve what it asks for (or the capabilities in ``only``), print
    the findings and summaries, write the report folder and the JSON; exit with status 3
    when the result is not acceptable (with ``strict`` also when a design criterion fails)."""
    from shaftline.pipeline import acceptable, findings_blocks, report_sections, results_document, run_case
    from shaftline.report.blocks import Paragraph
    from shaftline.report.terminal import print_blocks

    quiet = json_path == "-"
    with interruptible(), input_errors():
        case = read_and_build(case_file, only, overrides)
        check_outputs(out, json_path, [*case.inputs, *case.kept])
        # rich's progress display only once the case is accepted: an input error does not wait for it
        from shaftline.progress import ProgressDisplay

        # before solving: a long run's reader sees at once what was left out
        print_blocks(error_console if quiet else console, [Paragraph(f"warning: {w}", "warn") for w in case.warnings])
        with ProgressDisplay(error_console) as show:
            result = run_case(case, only, options, progress=show)
        # What makes the result unacceptable comes first, on standard error if the JSON goes out.
        notes = findings_blocks(result)
        if case.unusual:
            text = "accepted outside the plausible range ([case] unusual): " + ", ".join(case.unusual)
            notes.insert(0, Paragraph(text, "warn"))
        print_blocks(error_console if quiet else console, notes)
        if not quiet:
            for capability, value in result.capabilities():
                print_blocks(console, capability.summary(value))
        sections = report_sections(result) if out is not None else []
        deliver(results_document(result), json_path, out, sections, case.name, case.description, str(case_file))
    if out is not None and not quiet:
        console.print(f"report: {out / 'report.html'}", markup=False, highlight=False)
    if not acceptable(result, strict):
        raise typer.Exit(code=NOT_ACCEPTABLE)


def read_and_build(
    case_file: Path, only: Sequence[str] | None = None, overrides: Mapping[str, Any] | None = None
) -> Any:
    """The case of ``case_file`` (raises :class:`InputError`); with ``only``, it must have
    one of those tables."""
    from shaftline.cases.files import read_case_file

    data = read_case_file(case_file)  # a missing file or bad TOML fails before the heavy imports
    if only is not None and not any(key in data for key in only):
        tables = " or ".join(f"[{key}]" for key in only)
        raise InputError("case file", str(case_file), "", f"a case file with the table {tables} for this command")
    from shaftline.cases.loader import parse_case

    return parse_case(data, case_file.parent, only, overrides, source=case_file)


def compare_cases(
    key: str,
    case_files: Sequence[Path],
    options: Mapping[str, Any],
    json_path: str | None,
    out: Path | None,
    strict: bool = False,
) -> None:
    """Solve capability ``key`` for each case file and show the capability's comparison;
    cases are named by their [case] name, made unique with the file name where needed."""
    from shaftline.pipeline import finding_line, run_case
    from shaftline.registry import capabilities
    from shaftline.report.blocks import Paragraph, Section
    from shaftline.report.terminal import print_blocks

    capability = capabilities()[key]
    results: list[tuple[str, Any]] = []
    with interruptible(), input_errors():
        cases = [read_and_build(path, [key]) for path in case_files]
        check_outputs(out, json_path, [source for case in cases for source in (*case.inputs, *case.kept)])
        with error_console.status("solving") as status:
            for path, case in zip(case_files, cases, strict=True):
                status.update(f"solving {path.name}")
                result = run_case(case, [key], {key: options})
                names = [name for name, _ in results]
                name = case.name if case.name not in names else f"{case.name} ({path.name})"
                while name in names:
                    name += "'"
                results.append((name, result[key]))
        comparison = capability.compare(results)
        found = [(name, item) for name, value in results for item in capability.findings(value)]
        warnings: list[Any] = [Paragraph(finding_line(name, item), "warn") for name, item in found]
        print_blocks(error_console if json_path == "-" else console, warnings)
        if json_path != "-":
            print_blocks(console, comparison.blocks)
        section = Section(key, capability.title, [*warnings, *comparison.blocks])
        title = f"{capability.title}: {len(results)} cases compared"
        sources = ", ".join(map(str, case_files))
        deliver(comparison.document, json_path, out, [section], title, "", sources, "case files")
    if any(strict or not item.criterion for _, item in found):
        raise typer.Exit(code=NOT_ACCEPTABLE)
