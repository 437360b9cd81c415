"""Service wear of CPP blade bearings as a capability: ``[wear]`` in a case file,
``shaftline wear pitchlog`` and ``shaftline wear weibull``, ``wear`` in results.json, a
section of the report."""

from __future__ import annotations

from collections.abc import Sequence
from typing import TYPE_CHECKING, Any

from shaftline.registry import BuildContext, Capability, Command, Finding, Progress, no_progress
from shaftline.report.blocks import Block, Figure, Paragraph, Table
from shaftline.wear.presentation import weibull_json, weibull_text

if TYPE_CHECKING:
    from shaftline.wear.case import WearSection
    from shaftline.wear.study import WearResult, WearStudy


class ServiceWear(Capability["WearSection", "WearStudy", "WearResult"]):
    key = "wear"
    title = "Blade-bearing wear in service"

    def schema(self) -> type[WearSection]:
        from shaftline.wear.case import WearSection

        return WearSection

    def build(self, section: WearSection, context: BuildContext) -> WearStudy:
        from shaftline.wear.case import build_study

        return build_study(section, context)

    def solve(self, study: WearStudy, progress: Progress = no_progress, **options: Any) -> WearResult:
        from shaftline.wear.study import solve_wear

        return solve_wear(study, lambda step: progress(f"solving {step}"))

    def to_json(self, result: WearResult) -> dict[str, Any]:
        from shaftline.wear.archard import wear_class

        out: dict[str, Any] = {
            "units": {"distance": "m", "depth": "m", "rate": "m^3/(N m)", "travel": "design pitches"},
            "wear_rate": result.study.wear_rate,
            "wear_class": wear_class(result.study.wear_rate),
            "pitch_travel_raw": result.travel_raw,
            "pitch_travel_corrected": result.travel_corrected,
            "scenarios": [
                {
                    "name": s.name,
                    "distance_per_voyage": s.distance_per_voyage,
                    "distance_total": s.distance_total,
                    "depth_total": s.depth_total,
                    "allowable_rate": s.allowable_rate,
                    "years_to_limit": s.years_to_limit,
                    "exceedance": None
                    if s.exceedance is None
                    else dict(zip(("lower", "estimate", "upper"), s.exceedance, strict=True)),
                }
                for s in result.scenarios
            ],
        }
        if result.weibull is not None:
            out["weibull"] = weibull_json(result.weibull)
        return out

    def _table(self, result: WearResult) -> Table:
        from shaftline.wear.archard import MM3_PER_NM

        # short headers: the table fits an 80-column terminal; the title says what they mean
        headers = [
            "scenario",
            "voyage [m]",
            f"{result.study.service.years:g} years [km]",
            "depth [µm]",
            "allowable [mm³/Nm]",
            "years",
            "P(exceed)",
        ]
        rows = []
        for s in result.scenarios:
            probability = "-"
            if s.exceedance is not None:
                low, mid, high = s.exceedance
                probability = f"{mid:.3g} ({low:.2g}–{high:.2g})"
            rows.append(
                [
                    s.name,
                    f"{s.distance_per_voyage:.3f}",
                    f"{s.distance_total / 1e3:.1f}",
                    f"{s.depth_total * 1e6:.0f}",
                    f"{s.allowable_rate / MM3_PER_NM:.3g}",
                    f"{s.years_to_limit:.1f}",
                    probability,
                ]
            )
        title = (
            "Blade-bearing wear: sliding per voyage and over the overhaul period, wear depth, the allowable wear "
            "rate, years to the allowable depth, P(wear rate > allowable) with bounds"
        )
        return Table(headers, rows, title)

    def findings(self, result: WearResult) -> list[Finding]:
        study = result.study
        return [
            Finding(
                f"{s.name}: the wear depth after {study.service.years:g} years, {s.depth_total * 1e6:.0f} µm, "
                f"exceeds the allowable {study.allowable_depth * 1e6:.0f} µm "
                f"(reached after {s.years_to_limit:.1f} years).",
                criterion=True,
            )
            for s in result.scenarios
            if s.depth_total > study.allowable_depth
        ]

    def summary(self, result: WearResult) -> list[Block]:
        from shaftline.wear.archard import MM3_PER_NM

        blocks: list[Block] = [self._table(result)]
        if result.weibull is not None:
            blocks.append(Paragraph("Tested wear rates: " + weibull_text(result.weibull, 1 / MM3_PER_NM, "mm³/(N·m)")))
        return blocks

    def report(self, result: WearResult) -> list[Block]:
        from shaftline.wear import figures
        from shaftline.wear.archard import MM3_PER_NM, wear_class

        study = result.study
        blocks: list[Block] = [
            Paragraph(
                f"Blade bearing radius {study.bearing_radius:.3f} m, design pitch "
                f"{study.design_pitch_angle * 180 / 3.141592653589793:.1f} deg, contact pressure "
                f"{study.contact_pressure / 1e6:.1f} N/mm², specific wear rate {study.wear_rate / MM3_PER_NM:.3g} "
                f"mm³/(N·m) (wear class {wear_class(study.wear_rate)}), allowable depth "
                f"{study.allowable_depth * 1e6:.0f} µm; {study.service.voyages_per_day:g} voyages a day, "
                f"{study.service.days_per_year:g} days a year, {study.service.years:g} years."
            ),
            self._table(result),
        ]
        if result.weibull is not None:
            blocks.append(Paragraph("Tested wear rates: " + weibull_text(result.weibull, 1 / MM3_PER_NM, "mm³/(N·m)")))
            marks = {f"allowable: {s.name}": s.allowable_rate for s in result.scenarios}
            blocks.append(
                Figure(
                    "wear_weibull.png",
                    figures.weibull,
                    (result.weibull, 1 / MM3_PER_NM, "wear rate [mm³/(N·m)]", marks),
                    caption="Weibull distribution of the tested wear rates and the allowable rates",
                )
            )
        if study.pitch_log is not None:
            blocks.append(Figure("wear_pitch_log.png", figures.pitch_log, (result,), caption="pitch log"))
        blocks.append(
            Figure("wear_depth.png", figures.depth_over_years, (result,), caption="wear depth over the years")
        )
        return blocks

    def commands(self) -> Sequence[Command]:
        from shaftline.wear.commands import pitchlog, weibull

        return (Command(("wear", "pitchlog"), pitchlog), Command(("wear", "weibull"), weibull))


CAPABILITY = ServiceWear()
