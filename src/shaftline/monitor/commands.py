"""The command line of film-thickness monitoring: ``shaftline monitor identify`` and
``shaftline monitor trend`` (``monitor simulate`` is a verb of the capability, made by
:mod:`shaftline.cli`).

The typer commands of :meth:`FilmMonitor.commands <shaftline.monitor.capability.FilmMonitor.commands>`,
apart from the capability so that importing it imports no typer: ``identify`` is a run of the
case with the recordings and the database as overrides, ``trend`` reads the database alone
(:mod:`shaftline.monitor.trend_report`).
"""

from __future__ import annotations

from pathlib import Path
from typing import TYPE_CHECKING, Annotated, Any

import typer

from shaftline.commandline import (
    JsonOption,
    OutOption,
    check_outputs,
    console,
    deliver,
    error_console,
    fail,
    input_errors,
    interruptible,
    read_and_build,
    run_cases,
    strict_help,
)
from shaftline.errors import InputError
from shaftline.report.blocks import Paragraph, Section, Table
from shaftline.report.terminal import print_blocks

if TYPE_CHECKING:
    from shaftline.monitor.study import MonitorStudy

#: ``--strict`` of ``monitor identify``: what FilmMonitor.findings judges of recordings.
IdentifyStrict = Annotated[
    bool,
    typer.Option(
        "--strict",
        help=strict_help(
            "a lambda alarm is raised (the film parameter below [monitor.identify] lambda_threshold for "
            "alarm_duration or longer)",
            "a window that could not be identified (rejected)",
        ),
    ),
]


def identify_command(
    case_file: Annotated[Path, typer.Argument(help="Case file (TOML) with the [monitor] probes.")],
    recordings: Annotated[
        list[Path] | None,
        typer.Argument(help="Recordings (CSV, Parquet, HDF5, TDMS); default: [monitor.identify] recordings."),
    ] = None,
    db: Annotated[
        str | None,
        typer.Option(
            "--db",
            help="Trend database: a SQLAlchemy URL (postgresql+psycopg://user@host/name) or a SQLite file; default: "
            "[monitor.identify] database, monitor.sqlite beside the case file.",
        ),
    ] = None,
    slow_roll: Annotated[
        Path | None,
        typer.Option(
            "--slow-roll",
            help="Slow-roll recording whose runout of each probe is subtracted from every window; default: "
            "[monitor.identify] slow_roll, else none.",
        ),
    ] = None,
    replace: Annotated[
        bool,
        typer.Option(
            "--replace",
            help="Identify again a recording stored with other settings (slow roll, runout, window, layout...): its "
            "stored windows are replaced, other recordings kept; without it such a recording is refused.",
        ),
    ] = False,
    json_path: JsonOption = None,
    out: OutOption = None,
    strict: IdentifyStrict = False,
) -> None:
    """Identify probe recordings window by window (orbits, film, regimes) into the trend database;
    Ctrl-C keeps every window stored and the same command resumes."""
    if db is not None and "://" not in db and out is not None:
        if out.expanduser().resolve() in Path(db).expanduser().resolve().parents:
            # a file in the report folder would stop that folder being written (refused as foreign)
            fail(InputError("--db", db, "", "a database outside the --out folder"))
    overrides: dict[str, Any] = {}
    if recordings:
        overrides["monitor.identify.recordings"] = [str(path.expanduser().resolve()) for path in recordings]
    if db is not None:
        overrides["monitor.identify.database"] = db if "://" in db else str(Path(db).expanduser().resolve())
    if slow_roll is not None:
        overrides["monitor.identify.slow_roll"] = str(slow_roll.expanduser().resolve())
    run_cases(
        Path(case_file),
        json_path,
        out,
        only=["monitor"],
        options={"monitor": {"task": "identify", "replace": replace}},
        overrides=overrides,
        strict=strict,
    )


def trend_command(
    case_file: Annotated[
        Path | None,
        typer.Argument(
            help="Optional case file: its [monitor] regime thresholds and [monitor.identify] database, "
            "alarm threshold and duration."
        ),
    ] = None,
    db: Annotated[
        str | None,
        typer.Option(
            "--db",
            help="Trend database (SQLAlchemy URL or SQLite file); default: the case's, else "
            "monitor.sqlite in the working folder.",
        ),
    ] = None,
    limit: Annotated[
        str | None,
        typer.Option(
            "--limit",
            help="Film limit the trend is projected to (e.g. '3 um'); default: the film at lambda = the threshold.",
        ),
    ] = None,
    lambda_threshold: Annotated[
        float | None, typer.Option("--lambda-threshold", help="Film parameter of an alarm (default 1).")
    ] = None,
    min_duration: Annotated[
        str | None, typer.Option("--min-duration", help="Shortest alarm stretch (e.g. '10 min'; default 10 min).")
    ] = None,
    json_path: JsonOption = None,
    out: OutOption = None,
) -> None:
    """Trends of the smallest film per section from the trend database: lambda alarms, the fitted
    trend and its projected crossing of a limit, the averaged shaft centre line against speed."""
    from shaftline.monitor.trend_report import trend_report

    with interruptible(), input_errors():
        study: MonitorStudy | None = None
        inputs: list[Path] = []
        if case_file is not None:
            case = read_and_build(Path(case_file), ["monitor"])
            study, inputs = case.studies["monitor"], [*case.inputs, Path(case_file)]
        document, blocks, url = trend_report(
            study,
            db,
            limit,
            lambda_threshold,
            min_duration,
            lambda files: check_outputs(out, json_path, [*inputs, *files]),
        )
        quiet = json_path == "-"
        print_blocks(error_console if quiet else console, [b for b in blocks if isinstance(b, Paragraph | Table)])
        section = Section("monitor", "Film-thickness trends", blocks)
        deliver({"monitor_trend": document}, json_path, out, [section], "Film-thickness trends", "", url, "database")
    if out is not None and json_path != "-":
        console.print(f"report: {out / 'report.html'}", markup=False, highlight=False)
