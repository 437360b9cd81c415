"""What every command-line verb shares: running case files through the pipeline, printing
the summary, writing JSON and the report folder, and the one-line error with exit 2.

Kept apart from :mod:`shaftline.cli` so that a capability's own commands
(:meth:`shaftline.registry.Capability.commands`) can use it without an import cycle.
"""

from __future__ import annotations

import sys
from collections.abc import Iterator, Mapping, Sequence
from contextlib import contextmanager
from pathlib import Path
from typing import Annotated, Any, NoReturn

import typer
from rich.console import Console

from shaftline.errors import InputError

console = Console()
error_console = Console(stderr=True)

JsonOption = Annotated[
    str | None, typer.Option("--json", help="Write results as JSON to PATH, or '-' for standard output.")
]
OutOption = Annotated[Path | None, typer.Option("--out", help="Folder for results.json, figures and report.html.")]
CaseArgument = Annotated[Path, typer.Argument(help="Case file (TOML).")]


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


def check_out(out: Path | None) -> None:
    """Refuse an output folder that is the working folder, the case's own folder or one
    of their parents: the report folder is replaced as a whole when it is written.

    (Issue 9 makes updating an existing folder safe in general; until then this keeps a
    ``--out .`` from replacing the folder the user works in.)
    """
    if out is None:
        return
    target = out.resolve()
    here = Path.cwd().resolve()
    if not out.name or target == here or target in here.parents or target == Path(target.anchor):
        raise InputError("--out", str(out), "", "a folder of its own (not the working folder or one above it)")


def emit_json(document: Mapping[str, Any], json_path: str | None) -> None:
    """Write ``document`` to ``json_path`` (``-``: standard output; None: nowhere)."""
    from shaftline.pipeline import dumps, write_text_atomic

    if json_path is None:
        return
    text = dumps(document) + "\n"
    if json_path == "-":
        sys.stdout.write(text)
    else:
        write_text_atomic(Path(json_path), text)


def run_cases(
    case_file: Path,
    json_path: str | None,
    out: Path | None,
    only: Sequence[str] | None = None,
    options: Mapping[str, Mapping[str, Any]] | None = None,
    overrides: Mapping[str, Any] | None = None,
) -> None:
    """Load ``case_file``, solve what it asks for (or the capabilities in ``only``), print
    the summaries, write the report folder and the JSON."""
    from shaftline.pipeline import results_document, run_case, write_outputs
    from shaftline.report.terminal import print_blocks

    quiet = json_path == "-"
    with input_errors():
        check_out(out)
        holder = case_file.resolve().parent
        if out is not None and out.resolve() in (holder, *holder.parents):
            raise InputError("--out", str(out), "", "a folder that does not hold the case file")
        case = read_and_build(case_file, only, overrides)
        with error_console.status("solving") as status:
            result = run_case(case, only, options, progress=lambda text: status.update(text))
    if not quiet:
        for capability, value in result.capabilities():
            print_blocks(console, capability.summary(value))
    # The folder first: a JSON file inside it, or beside it, is not lost when it is written.
    if out is not None:
        write_outputs(result, out, str(case_file))
    emit_json(results_document(result), json_path)
    if out is not None and not quiet:
        console.print(f"report: {out / 'report.html'}", markup=False, highlight=False)


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
    key: str, case_files: Sequence[Path], options: Mapping[str, Any], json_path: str | None, out: Path | None
) -> None:
    """Solve capability ``key`` for each case file and show the capability's comparison;
    cases are named by their [case] name, made unique with the file name where needed."""
    from shaftline.pipeline import run_case, write_folder
    from shaftline.registry import capabilities
    from shaftline.report.blocks import Section
    from shaftline.report.terminal import print_blocks

    capability = capabilities()[key]
    results: list[tuple[str, Any]] = []
    with input_errors():
        check_out(out)
        for path in case_files:
            case = read_and_build(path, [key])
            result = run_case(case, [key], {key: options})
            names = [name for name, _ in results]
            name = case.name if case.name not in names else f"{case.name} ({path.name})"
            while name in names:
                name += "'"
            results.append((name, result[key]))
    comparison = capability.compare(results)
    if json_path != "-":
        print_blocks(console, comparison.blocks)
    if out is not None:
        section = Section(key, capability.title, comparison.blocks)
        title = f"{capability.title}: {len(results)} cases compared"
        write_folder(out, comparison.document, [section], title, "", ", ".join(map(str, case_files)), "case files")
    emit_json(comparison.document, json_path)
