"""The command line of slope-boring design: ``shaftline design slopes | robustness | sweep``.

The typer commands of :meth:`SlopeDesign.commands <shaftline.design.capability.SlopeDesign.commands>`,
apart from the capability so that importing it (for the schema, the registry or a notebook)
imports no typer; each command turns its options into overrides of the case's ``[design]``
and runs the case through :func:`shaftline.commandline.run_cases`.
"""

from __future__ import annotations

from collections.abc import Sequence
from pathlib import Path
from typing import Annotated, Any

import typer

from shaftline.commandline import (
    CaseArgument,
    JsonOption,
    OutOption,
    SchedulerOption,
    WorkersOption,
    strict_help,
)

GenerationsOption = Annotated[int | None, typer.Option("--generations", help="Generations of the search.")]
PopulationOption = Annotated[int | None, typer.Option("--population", help="Designs per generation.")]
AlgorithmOption = Annotated[str | None, typer.Option("--algorithm", help="nsga2, spea2, smsemoa or agemoea.")]
SeedOption = Annotated[int | None, typer.Option("--seed", help="Random seed of the search.")]
StoreOption = Annotated[
    Path | None,
    typer.Option("--store", help="Folder keeping every evaluation as it is made; run again on it to resume."),
]


#: ``--strict`` of the design verbs: what SlopeDesign.findings judges of each task's result
#: (the search's front for slopes and an unnamed robustness run, the robustness of the chosen
#: designs; a sweep's fronts are shown, not judged).
_BOUND = "the design front sits on a variable's bound (half its designs within 2 % of it)"
_NONE_ACCEPTABLE = "a search that finds no acceptable design"
SlopesStrict = Annotated[bool, typer.Option("--strict", help=strict_help(_BOUND, _NONE_ACCEPTABLE))]
RobustnessStrict = Annotated[
    bool,
    typer.Option(
        "--strict",
        help=strict_help(
            "no chosen design keeps h_min at or above the limit in every scenario, or (designs found by a search) "
            + _BOUND.replace("the design front", "the front"),
            _NONE_ACCEPTABLE,
        ),
    ),
]
SweepStrict = Annotated[
    bool,
    typer.Option(
        "--strict",
        help="No effect here: a sweep's fronts are shown, not judged (--strict of design slopes and design "
        "robustness judges a front and its robustness).",
    ),
]


def _search_run(
    task: str,
    case_file: Path,
    search: dict[str, Any],
    json_path: str | None,
    out: Path | None,
    strict: bool,
    workers: int | None,
    scheduler: str | None,
) -> None:
    """Run ``task`` of the case's [design] with the search settings given on the command line."""
    from shaftline.commandline import input_errors, parallel_options, run_cases

    store = search.pop("store", None)
    overrides = {f"design.search.{name}": value for name, value in search.items() if value is not None}
    if store is not None:
        overrides["design.search.store"] = str(Path(store).resolve())
    with input_errors():
        options = parallel_options(["design"], workers, scheduler)
    options.setdefault("design", {})["task"] = task
    run_cases(Path(case_file), json_path, out, only=["design"], options=options, overrides=overrides, strict=strict)


def slopes(
    case_file: CaseArgument,
    generations: GenerationsOption = None,
    population: PopulationOption = None,
    algorithm: AlgorithmOption = None,
    seed: SeedOption = None,
    store: StoreOption = None,
    json_path: JsonOption = None,
    out: OutOption = None,
    strict: SlopesStrict = False,
    workers: WorkersOption = None,
    scheduler: SchedulerOption = None,
) -> None:
    """Search the slope-bored bore of the case's bearing (pymoo): every design, the non-dominated set and
    its knee (the robustness of the knee: `design robustness` or `run`)."""
    search = {"generations": generations, "population": population, "algorithm": algorithm, "seed": seed}
    _search_run("slopes", case_file, {**search, "store": store}, json_path, out, strict, workers, scheduler)


def sweep_command(
    case_file: CaseArgument,
    generations: GenerationsOption = None,
    population: PopulationOption = None,
    algorithm: AlgorithmOption = None,
    seed: SeedOption = None,
    store: StoreOption = None,
    json_path: JsonOption = None,
    out: OutOption = None,
    strict: SweepStrict = False,
    workers: WorkersOption = None,
    scheduler: SchedulerOption = None,
) -> None:
    """One search per misalignment ratio of [design.sweep] (default psi_x 0.1 ... 0.6), each with the
    search settings of [design.search] or of these options; the non-dominated designs of each."""
    search = {"generations": generations, "population": population, "algorithm": algorithm, "seed": seed}
    _search_run("sweep", case_file, {**search, "store": store}, json_path, out, strict, workers, scheduler)


def read_designs(path: Path, names: Sequence[str]) -> list[dict[str, Any]]:
    """Named designs from a CSV: the variable columns (``slope_1`` … ``knuckle_1`` …) and optionally
    ``name``; a search's ``design_evaluations.csv`` gives its front (the rows marked ``pareto``),
    named by their data row in the file (``row 17``) and the knee as ``knee``."""
    import pandas as pd

    from shaftline.errors import InputError

    try:
        table = pd.read_csv(path)
    except (OSError, ValueError) as error:
        raise InputError("--designs", str(path), "", f"a readable CSV file ({error})") from None
    missing = [name for name in names if name not in table.columns]
    if missing:
        raise InputError("--designs", str(path), "", "a CSV with the columns " + ", ".join(names))
    if "pareto" in table.columns:
        table = table[table["pareto"].astype(bool)]
    if table.empty:
        raise InputError("--designs", str(path), "", "at least one design")
    slopes = [n for n in names if n.startswith("slope_")]
    knuckles = [n for n in names if n.startswith("knuckle_")]
    if "name" in table.columns:
        labels = table["name"].astype(str).tolist()
    else:
        # traceable to the file: its knee by name, the others by their data row (1 = the first)
        knee = table["knee"].astype(bool) if "knee" in table.columns else [False] * len(table)
        labels = ["knee" if is_knee else f"row {row + 1}" for row, is_knee in zip(table.index, knee, strict=True)]
    return [
        {"name": label, "slopes": [float(row[n]) for n in slopes], "knuckles": [float(row[n]) for n in knuckles]}
        for label, (_, row) in zip(labels, table.iterrows(), strict=True)
    ]


def robustness_command(
    case_file: CaseArgument,
    designs: Annotated[
        Path | None,
        typer.Option(
            "--designs",
            help="CSV of designs (name, slope_1 …, knuckle_1 …; a search's design_evaluations.csv gives its front). "
            "Default: the case's [design.robustness].",
        ),
    ] = None,
    json_path: JsonOption = None,
    out: OutOption = None,
    strict: RobustnessStrict = False,
    workers: WorkersOption = None,
    scheduler: SchedulerOption = None,
) -> None:
    """The chosen designs (the knee or front of a search, named ones, or those of --designs) under the
    speed, load and temperature scenarios."""
    from shaftline.commandline import input_errors, parallel_options, read_and_build, run_cases

    overrides: dict[str, Any] = {}
    with input_errors():
        options = parallel_options(["design"], workers, scheduler)
        if designs is not None:
            case = read_and_build(Path(case_file), ["design"])
            names = case.studies["design"].problem.parametrisation.names
            overrides = {"design.robustness.designs": "named", "design.robustness.named": read_designs(designs, names)}
    options.setdefault("design", {})["task"] = "robustness"
    run_cases(Path(case_file), json_path, out, only=["design"], options=options, overrides=overrides, strict=strict)
