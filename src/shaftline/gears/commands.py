"""The command line of gear scuffing: ``shaftline gears scuffing CASE.toml [--calibrate TEST.csv]``.

The typer command of :meth:`GearScuffing.commands <shaftline.gears.capability.GearScuffing.commands>`,
apart from the capability so that importing it imports no typer.
"""

from __future__ import annotations

from pathlib import Path
from typing import Annotated

import typer

from shaftline.commandline import JsonOption, OutOption, strict_help


def scuffing_command(
    case_file: Annotated[Path, typer.Argument(help="Case file (TOML) with a [gears] table.")],
    calibrate: Annotated[
        Path | None,
        typer.Option(
            "--calibrate",
            help="Torque-step test record (CSV: torque_Nm, speed_rpm, oil_temperature_degC, scuffed) to calibrate "
            "seed 002's C on: SP = 1 at the first scuffed step.",
        ),
    ] = None,
    json_path: JsonOption = None,
    out: OutOption = None,
    strict: Annotated[
        bool,
        typer.Option(
            "--strict",
            # what GearScuffing.findings judges, with and without ``criterion``
            help=strict_help(
                "seed 002's scuffing parameter SP exceeds 1 or ISO/TS 6336-20's S_B falls below 1 at a torque-speed "
                "step",
                "seed 002's thermal correction clipped to 0 beyond its fit range (SP understated: no result)",
            ),
        ),
    ] = False,
) -> None:
    """Scuffing of a gear pair along the mesh: seed 002's scuffing parameter beside ISO/TS 6336-20."""
    from shaftline.commandline import run_cases

    overrides = {} if calibrate is None else {"gears.calibration": str(calibrate.expanduser().resolve())}
    run_cases(Path(case_file), json_path, out, only=["gears"], overrides=overrides, strict=strict)
