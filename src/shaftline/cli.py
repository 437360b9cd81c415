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
wear_app = typer.Typer(no_args_is_help=True, help="Service wear of CPP blade bearings.")
app.add_typer(wear_app, name="wear")
cpp_app = typer.Typer(no_args_is_help=True, help="CPP blade bearings: friction, fretting, carrier motion.")
app.add_typer(cpp_app, name="cpp")

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


def _print(headers: list[str], rows: list[list[str]], title: str) -> None:
    table = Table(title=title)
    for k, header in enumerate(headers):
        table.add_column(header, justify="left" if k == 0 else "right")
    for row in rows:
        table.add_row(*row)
    console.print(table)


def _print_bearing(runs) -> None:
    from shaftline.jobs import bearing_table_rows

    _print(*bearing_table_rows(runs), "Bearing film at equilibrium")


def _print_alignment(run) -> None:
    from shaftline.jobs import alignment_table_rows, rule_check_rows

    headers, rows = alignment_table_rows(run)
    _print(headers, rows, "Shaft alignment")
    failed = [row for row in rule_check_rows(run.checks) if row[0] == "FAIL"]
    if failed:
        _print(
            ["result", "rule", "condition", "bearing", "value", "limit", "source", "confidence"],
            failed,
            f"Class-rule checks: {len(failed)} of {len(run.checks)} fail",
        )
    else:
        console.print(f"Class-rule checks: all {len(run.checks)} pass")


def _print_wear(run) -> None:
    from shaftline.jobs.wear import wear_table_rows

    _print(*wear_table_rows(run), "Blade-bearing wear")
    if run.weibull is not None:
        low, high = run.weibull.interval("shape")
        console.print(
            f"Weibull fit of tested wear rates: shape {run.weibull.shape:.3g} ({low:.3g}-{high:.3g}), "
            f"scale {run.weibull.scale * 1e9:.3g} mm3/Nm"
        )


def _print_cpp(run) -> None:
    from shaftline.jobs.cpp import cpp_table_rows

    _print(*cpp_table_rows(run), "CPP blade bearing")


def _solve(case_file: Path, film: bool, alignment: bool, wear: bool = False, log=None, cpp: str = ""):
    from shaftline.jobs import solve_alignment, solve_bearings
    from shaftline.jobs.cpp import solve_cpp
    from shaftline.jobs.wear import solve_wear

    case = load_case(case_file)
    if cpp and not (film or alignment or wear) and case.cpp is None:
        raise InputError("case file", str(case_file), "", "a [cpp] section")
    if cpp == "motion" and not (film or alignment or wear) and case.cpp.motion is None:
        raise InputError("case file", str(case_file), "", "a [cpp.motion] section for the carrier motion")
    if film and not alignment and not case.bearings:
        raise InputError("case file", str(case_file), "", "a bearing film: [bearing], [operation], [lubricant]")
    if alignment and not film and case.alignment is None:
        raise InputError("case file", str(case_file), "", "a shaft line: [shaft], [[shaft.segments]], [[bearings]]")
    if wear and not (film or alignment) and case.wear is None:
        raise InputError("case file", str(case_file), "", "a [wear] section")
    runs, alignment_run, wear_run, cpp_run = [], None, None, None
    with console.status("solving") as status:
        if film:
            runs = solve_bearings(case, progress=lambda name: status.update(f"solving {name}"))
        if alignment and case.alignment is not None:
            alignment_run = solve_alignment(case.alignment, progress=lambda name: status.update(f"solving {name}"))
        if wear and case.wear is not None:
            wear_run = solve_wear(case.wear, log)
        if cpp and case.cpp is not None:
            status.update("solving the blade bearing")
            cpp_run = solve_cpp(case.cpp, motion=cpp == "motion")
    return case, runs, alignment_run, wear_run, cpp_run


def _emit_json(case, runs, alignment, json_path: str | None, wear=None, cpp=None) -> None:
    from shaftline.jobs import dumps, results_document, write_text_atomic

    if json_path is None:
        return
    text = dumps(results_document(case, runs, alignment, wear, cpp))
    if json_path == "-":
        sys.stdout.write(text + "\n")
    else:
        write_text_atomic(Path(json_path), text + "\n")


JsonOption = Annotated[
    str | None, typer.Option("--json", help="Write results as JSON to PATH, or '-' for standard output.")
]


def _job(
    case_file: Path,
    json_path: str | None,
    out: Path | None,
    film: bool,
    alignment: bool,
    wear: bool = False,
    log_file: Path | None = None,
    cpp: str = "",
) -> None:
    from shaftline.jobs import write_outputs
    from shaftline.wear.service import read_pitch_log

    try:
        log = read_pitch_log(log_file) if log_file is not None else None
        case, runs, alignment_run, wear_run, cpp_run = _solve(case_file, film, alignment, wear, log, cpp)
    except InputError as error:
        _fail(error)
    if json_path != "-":
        if runs:
            _print_bearing(runs)
        if alignment_run is not None:
            _print_alignment(alignment_run)
        if wear_run is not None:
            _print_wear(wear_run)
        if cpp_run is not None:
            _print_cpp(cpp_run)
    _emit_json(case, runs, alignment_run, json_path, wear_run, cpp_run)
    if out is not None:
        write_outputs(case, runs, alignment_run, out, str(case_file), wear_run, cpp_run)
        if json_path != "-":
            console.print(f"report: {out / 'report.html'}")


@bearing_app.command("solve")
def bearing_solve(
    case_file: Annotated[Path, typer.Argument(help="Case file (TOML).")],
    json_path: JsonOption = None,
    out: Annotated[Path | None, typer.Option("--out", help="Folder for figures and the HTML report.")] = None,
) -> None:
    """Solve the bearing film at equilibrium under the case load."""
    _job(case_file, json_path, out, film=True, alignment=False)


@app.command("align")
def align(
    case_file: Annotated[Path, typer.Argument(help="Case file (TOML).")],
    json_path: JsonOption = None,
    out: Annotated[Path | None, typer.Option("--out", help="Folder for figures and the HTML report.")] = None,
) -> None:
    """Shaft alignment: elastic line, reactions, slopes, influence matrix and rule checks."""
    _job(case_file, json_path, out, film=False, alignment=True)


@app.command("run")
def run(
    case_file: Annotated[Path, typer.Argument(help="Case file (TOML).")],
    out: Annotated[Path | None, typer.Option("--out", help="Output folder (default results/<case name>).")] = None,
    json_path: JsonOption = None,
) -> None:
    """The main job: every analysis the case file asks for, with the HTML report."""
    _job(
        case_file,
        json_path,
        out or Path("results") / case_file.stem,
        film=True,
        alignment=True,
        wear=True,
        cpp="motion",
    )


@cpp_app.command("fretting")
def cpp_fretting(
    case_files: Annotated[list[Path], typer.Argument(help="Case file(s) (TOML) with a [cpp] section.")],
    json_path: JsonOption = None,
    out: Annotated[Path | None, typer.Option("--out", help="Folder for figures and the HTML report.")] = None,
) -> None:
    """Friction torque, fretting coefficient and hydraulic pressures over a revolution; with
    several case files, the propellers ranked by fretting risk."""
    if len(case_files) == 1:
        _job(case_files[0], json_path, out, film=False, alignment=False, cpp="fretting")
        return
    from shaftline.cpp.fretting import rank_by_fretting_risk
    from shaftline.jobs import dumps, write_text_atomic
    from shaftline.jobs.cpp import solve_cpp

    coefficients = {}
    try:
        for path in case_files:
            case = load_case(path)
            if case.cpp is None:
                raise InputError("case file", str(path), "", "a [cpp] section")
            coefficients[case.name] = solve_cpp(case.cpp, motion=False).coefficient
    except InputError as error:
        _fail(error)
    ranking = rank_by_fretting_risk(coefficients)
    document = {
        "ranking": [
            {"case": name, "max_abs_k_fret": value, "gross_fretting_both_ways": coefficients[name].fretting}
            for name, value in ranking
        ]
    }
    if json_path != "-":
        _print(
            ["case", "max |k_fret|", "fretting both ways"],
            [
                [r["case"], f"{r['max_abs_k_fret']:.3f}", "yes" if r["gross_fretting_both_ways"] else "no"]
                for r in document["ranking"]
            ],
            "Fretting risk, highest first",
        )
    if json_path == "-":
        sys.stdout.write(dumps(document) + "\n")
    elif json_path is not None:
        write_text_atomic(Path(json_path), dumps(document) + "\n")


@cpp_app.command("motion")
def cpp_motion(
    case_file: Annotated[Path, typer.Argument(help="Case file (TOML) with [cpp] and [cpp.motion].")],
    json_path: JsonOption = None,
    out: Annotated[Path | None, typer.Option("--out", help="Folder for figures and the HTML report.")] = None,
) -> None:
    """Fretting motion of the blade carrier over revolutions (oil spring, backlash, friction law)."""
    _job(case_file, json_path, out, film=False, alignment=False, cpp="motion")


@wear_app.command("pitchlog")
def wear_pitchlog(
    log_file: Annotated[Path, typer.Argument(help="Pitch log CSV: time (s), pitch (% of design pitch).")],
    case_file: Annotated[Path, typer.Option("--case", help="Case file with a [wear] section.")],
    json_path: JsonOption = None,
    out: Annotated[Path | None, typer.Option("--out", help="Folder for figures and the HTML report.")] = None,
) -> None:
    """Sliding distance and wear from a pitch log: standard control, active control, fretting."""
    _job(case_file, json_path, out, film=False, alignment=False, wear=True, log_file=log_file)


@wear_app.command("weibull")
def wear_weibull(
    data_file: Annotated[Path, typer.Argument(help="CSV with one column of wear depths or rates.")],
    threshold: Annotated[
        float | None, typer.Option("--threshold", help="Report P(value > threshold), same unit as the data.")
    ] = None,
    confidence: Annotated[float, typer.Option("--confidence", help="Level of the bounds.")] = 0.95,
    json_path: JsonOption = None,
    out: Annotated[Path | None, typer.Option("--out", help="Folder for the Weibull figure.")] = None,
) -> None:
    """Weibull fit (maximum likelihood) with confidence bounds."""
    from shaftline.jobs import atomic_folder, dumps, write_text_atomic
    from shaftline.report import wear_figures
    from shaftline.wear.reliability import fit_weibull, read_samples

    try:
        fit = fit_weibull(read_samples(data_file), confidence)
    except InputError as error:
        _fail(error)
    shape_interval, scale_interval = fit.interval("shape"), fit.interval("scale")
    document = {
        "shape": fit.shape,
        "scale": fit.scale,
        "shape_interval": shape_interval,
        "scale_interval": scale_interval,
        "confidence": confidence,
        "samples": fit.samples.tolist(),
    }
    if threshold is not None:
        low, mid, high = fit.exceedance(threshold)
        document["exceedance"] = {"threshold": threshold, "lower": low, "estimate": mid, "upper": high}
    if json_path != "-":
        console.print(
            f"Weibull fit of {fit.samples.size} samples: shape {fit.shape:.4g} "
            f"({shape_interval[0]:.4g}-{shape_interval[1]:.4g}), scale {fit.scale:.4g} "
            f"({scale_interval[0]:.4g}-{scale_interval[1]:.4g}), {confidence:.0%} intervals"
        )
        if threshold is not None:
            e = document["exceedance"]
            console.print(f"P(value > {threshold:g}) = {e['estimate']:.4g} ({e['lower']:.4g} - {e['upper']:.4g})")
    if json_path == "-":
        sys.stdout.write(dumps(document) + "\n")
    elif json_path is not None:
        write_text_atomic(Path(json_path), dumps(document) + "\n")
    if out is not None:
        with atomic_folder(out) as folder:
            marks = {"threshold": threshold} if threshold is not None else None
            wear_figures.weibull(fit, folder / "weibull.png", 1.0, "value", marks)
            (folder / "results.json").write_text(dumps(document), encoding="utf-8")


def main() -> None:
    """Console entry point."""
    app()


if __name__ == "__main__":
    main()
