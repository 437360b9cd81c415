"""The command line of service wear: ``shaftline wear pitchlog`` and ``shaftline wear weibull``.

The typer commands of :meth:`ServiceWear.commands <shaftline.wear.capability.ServiceWear.commands>`,
apart from the capability so that importing it imports no typer.
"""

from __future__ import annotations

from pathlib import Path
from typing import Annotated, Any

import typer

from shaftline.errors import located
from shaftline.report.blocks import Block, Figure, Paragraph, Section


def pitchlog(
    log_file: Annotated[Path, typer.Argument(help="Pitch log CSV: time (s), pitch (% of design pitch).")],
    case_file: Annotated[Path, typer.Option("--case", help="Case file with a [wear] table.")],
    json_path: Annotated[
        str | None, typer.Option("--json", help="Write results as JSON to PATH, or '-' for standard output.")
    ] = None,
    out: Annotated[Path | None, typer.Option("--out", help="Folder for results.json, figures and report.html.")] = None,
) -> None:
    """Sliding distance and wear from a pitch log: standard control, active control, fretting."""
    from shaftline.commandline import run_cases

    run_cases(case_file, json_path, out, only=["wear"], overrides={"wear.pitch_log": str(log_file.resolve())})


def weibull(
    data_file: Annotated[Path, typer.Argument(help="CSV with one column of wear depths or rates.")],
    threshold: Annotated[
        float | None, typer.Option("--threshold", help="Report P(value > threshold), same unit as the data.")
    ] = None,
    confidence: Annotated[float, typer.Option("--confidence", help="Level of the bounds.")] = 0.95,
    json_path: Annotated[
        str | None, typer.Option("--json", help="Write results as JSON to PATH, or '-' for standard output.")
    ] = None,
    out: Annotated[Path | None, typer.Option("--out", help="Folder for results.json, figures and report.html.")] = None,
) -> None:
    """Weibull fit (maximum likelihood) of wear samples with confidence bounds."""
    import math

    from shaftline.commandline import check_outputs, console, deliver, input_errors, interruptible
    from shaftline.errors import InputError
    from shaftline.wear import figures
    from shaftline.wear.presentation import weibull_json, weibull_text
    from shaftline.wear.reliability import fit_weibull, read_samples

    with interruptible(), input_errors():
        check_outputs(out, json_path, [data_file])
        if threshold is not None and not (math.isfinite(threshold) and threshold > 0):
            raise InputError("--threshold", threshold, "", "a positive number in the unit of the data")
        with located("", {"confidence": "--confidence"}):
            fit = fit_weibull(read_samples(data_file), confidence)
    document: dict[str, Any] = {**weibull_json(fit), "samples": fit.samples.tolist()}
    lines = [weibull_text(fit)]
    if threshold is not None:
        low, mid, high = fit.exceedance(threshold)
        document["exceedance"] = {"threshold": threshold, "lower": low, "estimate": mid, "upper": high}
        lines.append(f"P(value > {threshold:g}) = {mid:.4g} ({low:.4g} - {high:.4g})")
    if json_path != "-":
        for line in lines:
            console.print(line, markup=False, highlight=False)
    marks = {"threshold": threshold} if threshold is not None else None
    blocks: list[Block] = [
        *(Paragraph(line) for line in lines),
        Figure("weibull.png", figures.weibull, (fit, 1.0, "value", marks)),
    ]
    section = Section("weibull", "Weibull fit", blocks)
    with interruptible(), input_errors():
        deliver(
            document, json_path, out, [section], f"Weibull fit of {data_file.name}", "", str(data_file), "data file"
        )
