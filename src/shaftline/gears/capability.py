"""Gear scuffing as a capability: ``[gears]`` in a case file, ``shaftline gears scuffing
CASE.toml [--calibrate TEST.csv]``, ``gears`` in results.json, a section of the report."""

from __future__ import annotations

import math
from collections.abc import Sequence
from pathlib import Path
from typing import TYPE_CHECKING, Any

from shaftline.registry import BuildContext, Capability, Command, Finding, Progress, no_progress
from shaftline.report.blocks import Block, Figure, Paragraph, Table

if TYPE_CHECKING:
    from shaftline.gears.case import GearsSection
    from shaftline.gears.study import GearResult, GearStudy

#: Contact fields along the path written to results.json, with their units.
PATH_FIELDS = {
    "peak_pressure": "Pa",
    "central_film": "m",
    "film_ratio": "",
    "friction": "",
    "power_intensity": "W/m^2",
}


def _numbers(values: Any) -> Any:
    import numpy as np

    array = np.asarray(values, dtype=float)
    if array.ndim == 0:
        number = float(array)
        return number if math.isfinite(number) else None
    return [_numbers(v) for v in array]


def _flash_form(result: GearResult) -> str:
    method = result.study.iso.flash_method if result.study.iso is not None else "iso_cylindrical"
    return {"iso_cylindrical": "its form for cylindrical gears, Eq. A.5", "iso_general": "its general Eq. 5"}[method]


#: Width of the terminal the summary's tables must fit, characters.
TERMINAL_WIDTH = 80


def _short(value: float) -> str:
    """A rating in at most four characters (two decimals below 10, one below 100); "-" when missing."""
    if not math.isfinite(value):
        return "-"
    magnitude = abs(value)
    return f"{value:.2f}" if magnitude < 10 else f"{value:.1f}" if magnitude < 100 else f"{value:.0f}"


def _table_width(columns: Sequence[Sequence[str]]) -> int:
    """Characters the terminal's table (rich, one space of padding each side, a rule between
    columns and at both edges) takes for ``columns`` (each its header then its cells)."""
    return sum(max(len(cell) for cell in column) + 3 for column in columns) + 1


def _verdict(sp: float) -> str:
    from shaftline.gears.scuffing import NO_SCUFFING, SCUFFING

    return "scuffing" if sp > SCUFFING else "safe" if sp < NO_SCUFFING else "uncertain"


class GearScuffing(Capability["GearsSection", "GearStudy", "GearResult"]):
    key = "gears"
    title = "Gear scuffing: seed 002's scuffing parameter beside ISO/TS 6336-20"

    def schema(self) -> type[GearsSection]:
        from shaftline.gears.case import GearsSection

        return GearsSection

    def build(self, section: GearsSection, context: BuildContext) -> GearStudy:
        from shaftline.gears.case import build_study

        return build_study(section, context)

    def solve(self, study: GearStudy, progress: Progress = no_progress, **options: Any) -> GearResult:
        from shaftline.gears.study import solve_gears

        return solve_gears(study, lambda step: progress(f"solving {step}"))

    def commands(self) -> Sequence[Command]:
        from shaftline.gears.commands import scuffing_command

        return (Command(("gears", "scuffing"), scuffing_command),)

    def to_json(self, result: GearResult) -> dict[str, Any]:
        study, state = result.study, result.state
        pair = study.mesh.pair
        top = len(study.torques) - 1
        out: dict[str, Any] = {
            "units": {
                "torque": "N m",
                "speed": "rad/s",
                "temperature": "degC",
                "position": "m",
                "thermal_coefficient": "W/(m K)",
                "power_integral": "W/m",
                "load": "N/m",
                "flash_temperature": "K",
                **{k: v for k, v in PATH_FIELDS.items() if v},
            },
            "pair": {
                "working_centre_distance": pair.working_centre_distance,
                "working_pressure_angle_deg": math.degrees(pair.working_pressure_angle),
                "transverse_contact_ratio": pair.transverse_contact_ratio,
                "overlap_ratio": pair.overlap_ratio,
                "points": pair.points(),
            },
            "lubricant": study.mesh.model.lubricant.name,
            "oil_temperature": study.oil_temperature,
            "critical_temperature": study.critical_temperature,
            "load_sharing": "table" if study.mesh.load_table is not None else "ISO (no tip relief)",
            "thermal_coefficient": result.coefficient,
            "calibration": None,
            "torques": _numbers(study.torques),
            "fzg_load_stages": None if study.fzg_load_stages is None else list(study.fzg_load_stages),
            "speeds": _numbers(study.speeds),
            "approach_integral": _numbers(state.approach),
            "recess_integral": _numbers(state.recess),
            "sp": _numbers(result.sp),
            "warnings": list(result.warnings),
            "path": {
                "torque": float(study.torques[top]),
                "speed": float(study.speeds[0]),
                "position": _numbers(state.path.position),
                "share": _numbers(state.share),
                "load": _numbers(state.load[top, 0]),
                **{name: _numbers(getattr(state.contact, name)[top, 0]) for name in PATH_FIELDS},
            },
            "iso": None,
            "iso_integral": None,
        }
        if result.calibrated_at is not None and study.calibration is not None:
            torque, speed, t0, integral = result.calibrated_at
            out["calibration"] = {
                "record": study.calibration.source,
                "failure_step": study.calibration.failure + 1,
                "torque": torque,
                "speed": speed,
                "oil_temperature": t0,
                "power_integral": integral,
            }
        iso = result.iso
        if iso is not None:
            out["iso"] = {
                "fzg_load_stage": study.iso.fzg_load_stage if study.iso is not None else None,
                "flash_method": study.iso.flash_method if study.iso is not None else None,
                "mean_friction": _numbers(iso.friction),
                "flash_max": _numbers(iso.flash_max),
                "bulk_temperature": _numbers(iso.bulk),
                "contact_temperature_max": _numbers(iso.contact_max),
                "scuffing_temperature": _numbers(iso.scuffing_temperature),
                "safety": _numbers(iso.safety),
                "flash_along_path": _numbers(iso.flash[top, 0]),
            }
        rating = result.integral
        if rating is not None:
            out["iso_integral"] = {
                "mean_friction": _numbers(rating.friction),
                "flash_tip": _numbers(rating.flash_tip),
                "flash_integral": _numbers(rating.flash_integral),
                "bulk_temperature": _numbers(rating.bulk),
                "integral_temperature": _numbers(rating.integral),
                "scuffing_integral_temperature": rating.scuffing_integral,
                "safety": _numbers(rating.safety),
            }
        return out

    def _tables(self, result: GearResult) -> list[Table]:
        """Seed 002's SP and, with ``[gears.iso]``, ISO's ratings, as two tables over the same
        torque steps, for each pinion speed of the study in turn (its rpm in the titles): one
        table of nine or ten columns wrapped every row in an 80-column terminal, and one table
        of all speeds showed only the first."""
        study, c = result.study, result.state.contact
        stages = study.fzg_load_stages
        first = ["stage"] if stages else []  # the FZG load stage, named so in the titles
        by_stage = "FZG load stages, " if stages else ""
        steps = [([str(stages[k])] if stages else []) + [f"{torque:g}"] for k, torque in enumerate(study.torques)]
        tables = []
        for j, omega in enumerate(study.speeds):
            speed = float(omega) * 30.0 / math.pi
            rows = []
            for k, step in enumerate(steps):
                sp = float(result.sp[k, j])
                rows.append(
                    [
                        *step,
                        f"{float(c.peak_pressure[k, j].max()) / 1e9:.2f}",
                        f"{float(c.film_ratio[k, j].min()):.2f}",
                        f"{float(c.friction[k, j].max()):.3f}",
                        f"{sp:.2f}",
                        _verdict(sp),
                    ]
                )
            tables.append(
                Table(
                    [*first, "T_pinion [N m]", "max p_H [GPa]", "min Λ", "max f", "SP", "seed 002"],
                    rows,
                    f"{by_stage}{study.mesh.model.lubricant.name} at {study.oil_temperature:g} °C, {speed:.0f} rpm: "
                    f"seed 002's SP, C = {result.coefficient:.4g} W/(m K), T_cr = {study.critical_temperature:g} °C",
                )
            )
            if result.iso is None:
                continue
            iso, integral = result.iso, result.integral
            headers = [*first, "T_pinion [N m]", "θ_B,max [°C]", "S_B"]
            iso_rows = []
            for k, step in enumerate(steps):
                row = [*step, f"{float(iso.contact_max[k, j]):.0f}", f"{float(iso.safety[k, j]):.2f}"]
                if integral is not None:
                    row.append(f"{float(integral.safety[k, j]):.2f}")
                iso_rows.append(row)
            if integral is not None:
                headers.append("S_intS")
            tables.append(
                Table(
                    headers,
                    iso_rows,
                    "ISO/TS 6336-20 flash temperature (θ_B,max, S_B)"
                    + (" and 6336-21 integral temperature (S_intS)" if integral is not None else "")
                    + f", {by_stage}{speed:.0f} rpm",
                )
            )
        return tables

    def _matrix(self, result: GearResult) -> list[Block]:
        """Seed 002's SP and ISO's S_B (``[gears.iso]``) as one compact matrix, torque steps (FZG
        load stages) by pinion speed, each cell ``SP/S_B``, marked where either says scuffing;
        the speeds split over as many tables as it takes to fit :data:`TERMINAL_WIDTH` columns
        (the per-speed tables of :meth:`_tables` took a screen each: five speeds, 173 lines)."""
        from shaftline.gears.scuffing import NO_SCUFFING, SCUFFING

        study, iso = result.study, result.iso
        stages = study.fzg_load_stages
        first = ["stage"] if stages else []
        leading = [[*first, "T [N m]"]] + [
            ([str(stages[k])] if stages else []) + [f"{torque:g}"] for k, torque in enumerate(study.torques)
        ]
        lead_columns = [list(column) for column in zip(*leading, strict=True)]

        def column(j: int) -> list[str]:
            header = f"{float(study.speeds[j]) * 30.0 / math.pi:.0f} rpm"
            cells = [
                _short(float(result.sp[k, j])) + ("" if iso is None else "/" + _short(float(iso.safety[k, j])))
                for k in range(len(study.torques))
            ]
            return [header, *cells]

        def mark(k: int, j: int) -> str:
            scuffing = result.sp[k, j] > SCUFFING or (iso is not None and iso.safety[k, j] < 1.0)
            return "fail" if scuffing else ""

        # Greedy chunks of speeds in rising order (a case may list its test speed first), each as
        # wide as fits (at least one speed per table).
        chunks: list[list[int]] = [[]]
        for j in sorted(range(len(study.speeds)), key=lambda i: float(study.speeds[i])):
            trial = [*chunks[-1], j]
            if chunks[-1] and _table_width(lead_columns + [column(i) for i in trial]) > TERMINAL_WIDTH:
                chunks.append([j])
            else:
                chunks[-1] = trial
        what = "SP" if iso is None else "SP/S_B"
        rated = f"seed 002's SP (C = {result.coefficient:.4g} W/(m K), T_cr = {study.critical_temperature:g} °C)" + (
            "" if iso is None else " / ISO/TS 6336-20's S_B"
        )
        by = "FZG load stage" if stages else "torque step"
        blocks: list[Block] = []
        for n, chunk in enumerate(chunks, start=1):
            columns = [column(j) for j in chunk]
            part = f" ({n} of {len(chunks)})" if len(chunks) > 1 else ""
            blocks.append(
                Table(
                    [*(c[0] for c in lead_columns), *(c[0] for c in columns)],
                    [
                        [*(lead[k + 1] for lead in lead_columns), *(c[k + 1] for c in columns)]
                        for k in range(len(study.torques))
                    ],
                    f"{what} by {by} and pinion speed{part}: {rated}; {study.mesh.model.lubricant.name} at "
                    f"{study.oil_temperature:g} °C",
                    marks=[[""] * len(lead_columns) + [mark(k, j) for j in chunk] for k in range(len(study.torques))],
                )
            )
        iso_rule = "" if iso is None else "; S_B < 1 scuffing risk (ISO)"
        blocks.append(
            Paragraph(
                f"SP > {SCUFFING:g} scuffing, < {NO_SCUFFING:g} safe, uncertain between (seed 002){iso_rule}; "
                "marked where either says scuffing. Per speed, p_H, Λ, f"
                + ("" if iso is None else ", θ_B,max" + (" and S_intS" if result.integral is not None else ""))
                + ": the report and results.json.",
                "note",
            )
        )
        return blocks

    def _notes(self, result: GearResult) -> list[Block]:
        blocks: list[Block] = [Paragraph(f"Extrapolated: {text}", "warn") for text in result.warnings]
        if result.calibrated_at is not None and result.study.calibration is not None:
            torque, speed, t0, integral = result.calibrated_at
            blocks.append(
                Paragraph(
                    f"C calibrated on {Path(result.study.calibration.source).name}: SP = 1 at its first scuffed step "
                    f"({torque:g} N m, {speed * 30 / math.pi:.0f} rpm, oil {t0:g} °C, power integral "
                    f"{integral / 1e3:.1f} kW/m).",
                    "note",
                )
            )
        return blocks

    def findings(self, result: GearResult) -> list[Finding]:
        from shaftline.gears.scuffing import SCUFFING

        found = []
        clipped = _clipped_thermal_correction(result)
        if clipped is not None:
            found.append(clipped)
        over = result.sp > SCUFFING
        if over.any():
            k, j = (int(v) for v in next(zip(*over.nonzero(), strict=True)))
            found.append(
                Finding(
                    f"seed 002's scuffing parameter exceeds 1 (scuffing) from {result.study.torques[k]:g} N m at "
                    f"{result.study.speeds[j] * 30 / math.pi:.0f} rpm (SP = {result.sp[k, j]:.2f}).",
                    criterion=True,
                )
            )
        if result.iso is not None and (result.iso.safety < 1.0).any():
            safety = result.iso.safety
            k, j = (int(v) for v in next(zip(*(safety < 1.0).nonzero(), strict=True)))
            found.append(
                Finding(
                    f"ISO/TS 6336-20 scuffing safety below 1 from {result.study.torques[k]:g} N m at "
                    f"{result.study.speeds[j] * 30 / math.pi:.0f} rpm (S_B = {safety[k, j]:.2f}).",
                    criterion=True,
                )
            )
        return found

    def summary(self, result: GearResult) -> list[Block]:
        """One speed: its two tables (SP with p_H, Λ, f; ISO's ratings); several: the compact
        SP/S_B matrix of every speed (:meth:`_matrix`), the per-speed tables in the report."""
        if len(result.study.speeds) > 1:
            return [*self._notes(result), *self._matrix(result)]
        return [*self._notes(result), *self._tables(result)]

    def report(self, result: GearResult) -> list[Block]:
        from shaftline.gears import figures

        overview = self._matrix(result) if len(result.study.speeds) > 1 else []
        return [
            *self._notes(result),
            *overview,
            *self._tables(result),
            Paragraph(f"Lubricant data: {result.study.mesh.model.lubricant.source}", "note"),
            Paragraph(
                "SP: seed 002 Eq. 7 as read in docs/theory.md 19.2; ISO: flash-temperature (S_B, TS 6336-20, "
                f"{_flash_form(result)}) and "
                "integral-temperature (S_intS, TS 6336-21; a ratio of temperatures in °C, < 1 high risk, 1-2 "
                "critical) methods with coefficients as transcribed (theory 19.3, 19.5).",
                "note",
            ),
            Figure(
                "gears_path.png",
                figures.along_path,
                (result,),
                caption="along the path of contact at the highest torque step",
            ),
            Figure("gears_sp.png", figures.sp_steps, (result,), caption="SP against torque beside ISO's S_B"),
        ]


def _clipped_thermal_correction(result: GearResult) -> Finding | None:
    """A finding (not acceptable as it stands, exit 3) where seed 002's thermal correction was
    clipped to 0 outside its fit range (``extrapolate``): friction, frictional power and so SP are
    0 or understated there, which no warning may leave looking like a safe result (issue 14 (g))."""
    import numpy as np

    c = result.state.contact.thermal_correction
    zero = c <= 0.0
    if not zero.any():
        return None
    steps = np.asarray(zero.any(axis=-1))
    k, j = (int(v) for v in next(zip(*steps.nonzero(), strict=True)))
    study = result.study
    return Finding(
        f"seed 002's thermal correction (Eq. 6) was clipped to c = 0 beyond its fit range of eta0 p_H u at "
        f"{int(zero.sum())} of {zero.size} points, first at {study.torques[k]:g} N m and "
        f"{study.speeds[j] * 30 / math.pi:.0f} rpm (SP = {result.sp[k, j]:.2f}): friction and frictional power are 0 "
        f"there, so SP is understated at {int(steps.sum())} of {steps.size} torque-speed steps - not a result; "
        "the correlation does not cover this oil, load and speed.",
        criterion=False,
    )


CAPABILITY = GearScuffing()
