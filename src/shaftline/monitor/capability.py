"""Film-thickness monitoring as a capability: ``[monitor]`` in a case file, ``shaftline monitor
simulate`` (synthetic recordings of seed 001's rig), ``shaftline monitor identify`` (recordings
window by window into the trend database) and ``shaftline monitor trend`` (the database's
trends, alarms and projected crossing of a limit), ``monitor`` in results.json, a section of
the report.

This module declares the capability (its verbs, schema, build, solve and findings); what a
result shows is :mod:`shaftline.monitor.presentation`, the command line of ``monitor identify``
and ``monitor trend`` is :mod:`shaftline.monitor.commands`.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import TYPE_CHECKING, Any

from shaftline.helptext import strict_help
from shaftline.monitor.presentation import (
    alarm_text,
    monitor_json,
    rejected_text,
    report_blocks,
    rpm_text,
    summary_blocks,
)
from shaftline.registry import BuildContext, Capability, Command, Finding, Progress, Verb, no_progress

if TYPE_CHECKING:
    from shaftline.monitor.case import MonitorSection
    from shaftline.monitor.study import MonitorResult, MonitorStudy
    from shaftline.report.blocks import Block


class FilmMonitor(Capability["MonitorSection", "MonitorStudy", "MonitorResult"]):
    key = "monitor"
    title = "Film-thickness monitoring (eddy-current probes)"
    verbs = (
        Verb(
            ("monitor", "simulate"),
            "Synthetic probe recordings of seed 001's rig from the bearing solver and the shaft model, identified "
            "(orbits, film round the sections and along the bearing, regimes) and compared with the truth.",
            options={"task": "simulate"},
            # what FilmMonitor.findings judges of a simulation (the recording findings are identify's)
            strict=strict_help(
                "the bearing solver finds no film carrying the load above its floor at a simulated speed"
            ),
        ),
    )

    def schema(self) -> type[MonitorSection]:
        from shaftline.monitor.case import MonitorSection

        return MonitorSection

    def build(self, section: MonitorSection, context: BuildContext) -> MonitorStudy:
        from shaftline.monitor.case import build_study

        return build_study(section, context)

    def solve(self, study: MonitorStudy, progress: Progress = no_progress, **options: Any) -> MonitorResult:
        from dataclasses import replace

        from shaftline.monitor.study import solve_monitor

        task = options.get("task", "all")
        result = solve_monitor(study, progress, simulate_rig=task in ("all", "simulate"))
        plan = study.identify
        if task == "identify" or (task == "all" and plan is not None and plan.recordings):
            from shaftline.errors import InputError
            from shaftline.monitor.processing import identify_recordings

            if plan is None:
                raise InputError("RECORDING", "none", "", "one recording file or more")
            again = bool(options.get("replace", False))
            identified = identify_recordings(study.layout, plan, study.bending_shape(), progress, again)
            result = replace(result, identified=identified)
        return result

    def commands(self) -> Sequence[Command]:
        from shaftline.monitor.commands import identify_command, trend_command

        return (Command(("monitor", "identify"), identify_command), Command(("monitor", "trend"), trend_command))

    def to_json(self, result: MonitorResult) -> dict[str, Any]:
        return monitor_json(result)

    def findings(self, result: MonitorResult) -> list[Finding]:
        found = []
        if result.identified is not None:
            # windows that could not be identified make the run's result not acceptable (exit 3)
            found += [
                Finding(rejected_text(item.plan.recording.path.name, item.processed.rejected), criterion=False)
                for item in result.identified.recordings
                if item.processed.rejected
            ]
            found += [
                Finding(alarm_text(alarm, result.identified.lambda_threshold), criterion=True)
                for item in result.identified.recordings
                for trend in item.trends
                for alarm in trend.alarms
            ]
        for point in result.points:
            if point.recording.contact:
                found.append(
                    Finding(
                        f"At {rpm_text(point.recording.speed)} the bearing solver found no film carrying the load "
                        "above its floor: the synthetic journal stands where its search stopped (the film there "
                        "is not a hydrodynamic one).",
                        criterion=True,
                    )
                )
            elif not point.recording.converged:
                found.append(
                    Finding(
                        f"At {rpm_text(point.recording.speed)} the bearing solver did not converge: the synthetic "
                        "journal stands where its search stopped, not where the film and asperities carry the load.",
                        criterion=False,
                    )
                )
        return found

    def summary(self, result: MonitorResult) -> list[Block]:
        return summary_blocks(result)

    def report(self, result: MonitorResult) -> list[Block]:
        return report_blocks(result)


CAPABILITY = FilmMonitor()
