"""Command line: ``shaftline run CASE.toml`` and one verb per capability.

A thin layer over the registry and the pipeline: the verbs are made from each
capability's :attr:`~shaftline.registry.Capability.verbs` and
:meth:`~shaftline.registry.Capability.commands`. Bad input is reported in one line on
standard error with exit status 2, without a traceback and without output files.
Only what a verb needs is imported when it runs, so ``--version`` and input errors are quick.
"""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path
from typing import Annotated, Any, Literal

import typer

import shaftline
from shaftline import registry
from shaftline.commandline import (
    CaseArgument,
    JsonOption,
    OutOption,
    SchedulerOption,
    StrictOption,
    WorkersOption,
    compare_cases,
    input_errors,
    parallel_options,
    run_cases,
)
from shaftline.registry import Capability, Verb


def _version(value: bool) -> None:
    if value:
        print(f"shaftline {shaftline.__version__}")
        raise typer.Exit()


def main_callback(
    version: Annotated[
        bool, typer.Option("--version", callback=_version, is_eager=True, help="Print the version and exit.")
    ] = False,
) -> None:
    """shaftline: stern-tube bearings, shaft alignment, CPP blade bearings and more."""


def run(
    case_file: CaseArgument,
    out: Annotated[Path | None, typer.Option("--out", help="Output folder (default results/<case file name>).")] = None,
    json_path: JsonOption = None,
    strict: StrictOption = False,
    workers: WorkersOption = None,
    scheduler: SchedulerOption = None,
) -> None:
    """The main job: every analysis the case file asks for, with the HTML report."""
    with input_errors():
        options = parallel_options(list(registry.capabilities()), workers, scheduler)
    run_cases(case_file, json_path, out or Path("results") / case_file.stem, options=options, strict=strict)


def schema(
    format: Annotated[
        Literal["json", "markdown"], typer.Option("--format", help="JSON Schema, or the Markdown tables of the README.")
    ] = "json",
) -> None:
    """The case-file schema: every table and field with its unit, default and meaning."""
    from shaftline.cases.docs import json_schema_text, markdown_tables

    typer.echo(json_schema_text() if format == "json" else markdown_tables())


def _case_verb(capability: Capability[Any, Any, Any], verb: Verb) -> Callable[..., None]:
    """The typer command of ``verb``, its ``--strict`` help the verb's own."""
    command = _case_command(capability, verb)
    if verb.strict:
        # The three shapes below share one signature; the help is the verb's.
        command.__annotations__["strict"] = Annotated[bool, typer.Option("--strict", help=verb.strict)]
    return command


def _case_command(capability: Capability[Any, Any, Any], verb: Verb) -> Callable[..., None]:
    key = capability.key
    options = {key: dict(verb.options)}
    if not verb.many and capability.parallel:

        def spread(
            case_file: CaseArgument,
            json_path: JsonOption = None,
            out: OutOption = None,
            strict: StrictOption = False,
            workers: WorkersOption = None,
            scheduler: SchedulerOption = None,
        ) -> None:
            with input_errors():
                where = parallel_options([key], workers, scheduler)[key]
            run_cases(case_file, json_path, out, only=[key], options={key: {**options[key], **where}}, strict=strict)

        spread.__doc__ = verb.help
        return spread
    if not verb.many:

        def one(
            case_file: CaseArgument, json_path: JsonOption = None, out: OutOption = None, strict: StrictOption = False
        ) -> None:
            run_cases(case_file, json_path, out, only=[key], options=options, strict=strict)

        one.__doc__ = verb.help
        return one

    def many(
        case_files: Annotated[list[Path], typer.Argument(help="Case file(s) (TOML); several are compared.")],
        json_path: JsonOption = None,
        out: OutOption = None,
        strict: StrictOption = False,
    ) -> None:
        if len(case_files) == 1:
            run_cases(case_files[0], json_path, out, only=[key], options=options, strict=strict)
            return
        compare_cases(key, case_files, options[key], json_path, out, strict)

    many.__doc__ = verb.help
    return many


def make_app() -> typer.Typer:
    """The command line of the capabilities registered now: ``run``, ``schema`` and each
    capability's verbs (built afresh, so a capability registered later has its verbs)."""
    app = typer.Typer(
        add_completion=False,
        no_args_is_help=True,
        help="Tribology of a ship's propulsion shaft line.",
        pretty_exceptions_enable=False,
        rich_markup_mode=None,
    )
    app.callback()(main_callback)
    app.command("run")(run)
    app.command("schema")(schema)
    groups: dict[str, typer.Typer] = {}

    def group(path: tuple[str, ...], title: str) -> typer.Typer:
        if len(path) == 1:
            return app
        if path[0] not in groups:
            groups[path[0]] = typer.Typer(no_args_is_help=True, help=title, rich_markup_mode=None)
            app.add_typer(groups[path[0]], name=path[0])
        return groups[path[0]]

    taken: dict[tuple[str, ...], str] = {("run",): "shaftline", ("schema",): "shaftline"}

    def claim(path: tuple[str, ...], key: str) -> None:
        # A capability must not shadow another's verb (or run, schema) without anyone noticing.
        clash = taken.get(path) or (taken.get(path[:1]) if len(path) > 1 else None)
        if clash is not None or (len(path) == 1 and any(p[:1] == path for p in taken if len(p) > 1)):
            raise ValueError(f"the verb '{' '.join(path)}' of capability {key!r} is taken already")
        taken[path] = key

    for capability in registry.capabilities().values():
        for verb in capability.verbs:
            claim(verb.path, capability.key)
            group(verb.path, capability.title).command(verb.path[-1])(_case_verb(capability, verb))
        for command in capability.commands():
            claim(command.path, capability.key)
            group(command.path, capability.title).command(command.path[-1])(command.function)
    return app


def main() -> None:
    """Console entry point."""
    make_app()()


if __name__ == "__main__":
    main()
