"""Command line: ``shaftline <domain> <verb> CASE.toml`` and ``shaftline run CASE.toml``.

A thin layer over :mod:`shaftline.jobs`. Bad input is reported in one line on
standard error with exit status 2, without a traceback and without output files.
"""

from __future__ import annotations

import sys
from pathlib import Path
from typing import Annotated

import typer
from rich.console import Console
from rich.table import Table

import shaftline
from shaftline.cases import load_case
from shaftline.errors import InputError

app = typer.Typer(
    add_completion=False,
    no_args_is_help=True,
    help="Tribology of a ship's propulsion shaft line.",
    pretty_exceptions_enable=False,
)
bearing_app = typer.Typer(no_args_is_help=True, help="Stern-tube journal bearing film.")
app.add_typer(bearing_app, name="bearing")

console = Console()
error_console = Console(stderr=True)


def _version(value: bool) -> None:
    if value:
        print(f"shaftline {shaftline.__version__}")
        raise typer.Exit()


@app.callback()
def main_callback(
    version: Annotated[
        bool, typer.Option("--version", callback=_version, is_eager=True, help="Print the version and exit.")
    ] = False,
) -> None:
    """shaftline: stern-tube bearings, shaft alignment and more."""


def _fail(error: InputError) -> None:
    error_console.print(f"error: {error}", markup=False, highlight=False, soft_wrap=True)
    raise typer.Exit(code=2)


def _print_table(runs) -> None:
    from shaftline.jobs import bearing_table_rows

    headers, rows = bearing_table_rows(runs)
    table = Table(title="Bearing film at equilibrium")
    for header in headers:
        table.add_column(header, justify="right" if header != "quantity" else "left")
    for row in rows:
        table.add_row(*row)
    console.print(table)


def _solve(case_file: Path):
    from shaftline.jobs import solve_bearings

    case = load_case(case_file)
    with console.status("solving") as status:
        runs = solve_bearings(case, progress=lambda name: status.update(f"solving {name}"))
    return case, runs


def _emit_json(case, runs, json_path: str | None) -> None:
    from shaftline.jobs import dumps, results_document, write_text_atomic

    if json_path is None:
        return
    text = dumps(results_document(case, runs))
    if json_path == "-":
        sys.stdout.write(text + "\n")
    else:
        write_text_atomic(Path(json_path), text + "\n")


@bearing_app.command("solve")
def bearing_solve(
    case_file: Annotated[Path, typer.Argument(help="Case file (TOML).")],
    json_path: Annotated[
        str | None, typer.Option("--json", help="Write results as JSON to PATH, or '-' for standard output.")
    ] = None,
    out: Annotated[Path | None, typer.Option("--out", help="Folder for figures and the HTML report.")] = None,
) -> None:
    """Solve the bearing film at equilibrium under the case load."""
    from shaftline.jobs import write_bearing_outputs

    try:
        case, runs = _solve(case_file)
    except InputError as error:
        _fail(error)
    if json_path != "-":
        _print_table(runs)
    _emit_json(case, runs, json_path)
    if out is not None:
        write_bearing_outputs(case, runs, out, str(case_file))
        if json_path != "-":
            console.print(f"report: {out / 'report.html'}")


@app.command("run")
def run(
    case_file: Annotated[Path, typer.Argument(help="Case file (TOML).")],
    out: Annotated[Path | None, typer.Option("--out", help="Output folder (default results/<case name>).")] = None,
    json_path: Annotated[str | None, typer.Option("--json", help="Also write results as JSON to PATH, or '-'.")] = None,
) -> None:
    """The main job: every analysis the case file asks for, with the HTML report."""
    from shaftline.jobs import write_bearing_outputs

    try:
        case, runs = _solve(case_file)
    except InputError as error:
        _fail(error)
    out = out or Path("results") / case_file.stem
    if json_path != "-":
        _print_table(runs)
    _emit_json(case, runs, json_path)
    write_bearing_outputs(case, runs, out, str(case_file))
    if json_path != "-":
        console.print(f"report: {out / 'report.html'}")


def main() -> None:
    """Console entry point."""
    app()


if __name__ == "__main__":
    main()
