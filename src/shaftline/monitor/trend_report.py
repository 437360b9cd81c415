"""What ``shaftline monitor trend`` shows: the trend database read into its JSON document and
its blocks (the summary's tables and the report's figures).

The database is read alone, without a run of a case; a case, when given, lends its regime
thresholds and the alarm settings of its ``[monitor.identify]``. The command line that reads
the case and writes the outputs is :func:`shaftline.monitor.commands.trend_command`.
"""

from __future__ import annotations

import datetime as dt
import math
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np

from shaftline.errors import InputError
from shaftline.monitor.presentation import MICRO, alarm_text, count_text, rejected_text, trend_json, when_text
from shaftline.report.blocks import Block, Figure, Paragraph, Table

if TYPE_CHECKING:
    from shaftline.monitor.identified import RejectedWindow
    from shaftline.monitor.study import IdentifyPlan, MonitorStudy
    from shaftline.monitor.trends import CentreLine, SectionTrend, StoredRecording


@dataclass(frozen=True)
class AlarmSettings:
    """What the trends are judged by: the film parameter of an alarm, its shortest stretch (s)
    and the film limit the trend is projected to (m; None: the film at the threshold)."""

    threshold: float
    duration: float
    limit: float | None


@dataclass(frozen=True, eq=False)
class StoredTrends:
    """What the database holds: the trend of each section, the averaged centre lines, the
    recordings and, by recording id, their rejected windows."""

    trends: tuple[SectionTrend, ...]
    lines: tuple[CentreLine, ...]
    recordings: list[StoredRecording]
    rejected: dict[int, tuple[RejectedWindow, ...]]


def trend_report(
    study: MonitorStudy | None,
    db: str | None,
    limit_text: str | None,
    threshold: float | None,
    duration_text: str | None,
    check_outputs: Callable[[Sequence[Path]], None],
) -> tuple[dict[str, Any], list[Block], str]:
    """The trends of the database ``db`` (else the case's, else ``monitor.sqlite`` here) as the
    JSON document, the blocks and the database's URL as shown (password hidden).

    ``check_outputs`` is given the database file before anything is read, so that no output
    can replace it (every identify run writes it). Raises :class:`InputError` for a setting
    that cannot work or a database without identified windows.
    """
    from shaftline.monitor.regimes import thresholds
    from shaftline.monitor.trends import TrendStore, _hide_password

    plan = None if study is None else study.identify
    levels = None if study is None else thresholds(study.layout)
    settings = _alarm_settings(plan, threshold, duration_text, limit_text)
    database = db if db is not None else plan.database if plan is not None else "monitor.sqlite"
    url = TrendStore.url_of(database if "://" in database else Path(database).expanduser())
    shown = _hide_password(url)
    file = TrendStore.file_of(url)
    if file is not None and not file.is_file():
        raise InputError("--db", shown, "", "an existing trend database (made by monitor identify)")
    # the database is read here and written by every identify run: no output may replace it
    check_outputs([file] if file is not None else [])
    stored = _read_store(url, settings)
    if not stored.trends:
        raise InputError("--db", shown, "", "a database with identified windows (run monitor identify first)")
    bearing = next((t for t in stored.trends if t.section == "bearing"), stored.trends[-1])
    with np.errstate(all="ignore"):
        sigma = float(np.nanmedian(bearing.min_film / bearing.film_parameter))
    if levels is None and math.isfinite(sigma):
        levels = (sigma, 3.0 * sigma)  # seed 001's regimes: lambda 1 and 3
    blocks = _trend_blocks(stored, bearing, settings, shown, levels)
    return _trend_document(stored, settings, shown), blocks, shown


def _alarm_settings(
    plan: IdentifyPlan | None, threshold: float | None, duration_text: str | None, limit_text: str | None
) -> AlarmSettings:
    """The command line's alarm settings, the case's where not given, checked."""
    from shaftline.units import to_si

    if threshold is None:
        threshold = plan.lambda_threshold if plan is not None else 1.0
    if not (math.isfinite(threshold) and threshold > 0):
        raise InputError("--lambda-threshold", threshold, "", "> 0")
    duration = (
        (plan.alarm_duration if plan is not None else 600.0)
        if duration_text is None
        else to_si(duration_text, "time", "--min-duration")
    )
    if not duration >= 0.0:
        raise InputError("--min-duration", duration, "s", ">= 0")
    limit = None if limit_text is None else to_si(limit_text, "length", "--limit")
    if limit is not None and not limit > 0.0:
        raise InputError("--limit", limit, "m", "> 0")
    return AlarmSettings(threshold, duration, limit)


def _read_store(url: str, settings: AlarmSettings) -> StoredTrends:
    """Everything the report of the trends needs from the database, read in one session."""
    from shaftline.monitor.processing import rejected_windows
    from shaftline.monitor.trends import TrendStore, centre_lines, section_trends

    with TrendStore(url) as store:
        trends = section_trends(store, settings.threshold, dt.timedelta(seconds=settings.duration), settings.limit)
        lines = centre_lines(store)
        stored = store.recordings()
        rejected = {r.id: rejected_windows(store, r) for r in stored}
    return StoredTrends(trends, lines, stored, rejected)


def _trend_rows(trends: Sequence[SectionTrend]) -> list[list[str]]:
    """One row per section: windows, lowest film and lambda, alarms, trend and projected crossing."""
    rows = []
    for t in trends:
        crossing = t.crossing
        rows.append(
            [
                t.section,
                f"{len(t.times)}",
                f"{np.nanmin(t.min_film) * MICRO:.2f}" if np.isfinite(t.min_film).any() else "-",
                f"{np.nanmin(t.film_parameter):.2f}" if np.isfinite(t.film_parameter).any() else "-",
                f"{len(t.alarms)}",
                "-" if crossing is None else f"{crossing.slope * MICRO:+.3g}",
                "-" if crossing is None or crossing.crossing is None else when_text(crossing.crossing),
            ]
        )
    return rows


def _trend_blocks(
    stored: StoredTrends,
    bearing: SectionTrend,
    settings: AlarmSettings,
    shown: str,
    levels: tuple[float, float] | None,
) -> list[Block]:
    """The note on what was read, the warnings, the table per section and the figures."""
    from shaftline.monitor import figures
    from shaftline.monitor.trends import MIN_TREND_SPAN

    threshold, rejected = settings.threshold, stored.rejected
    first, last = bearing.times[0], bearing.times[-1]
    blocks: list[Block] = [
        Paragraph(
            f"{count_text(len(stored.recordings), 'recording')} in {shown}, "
            f"{count_text(len(bearing.times), 'window')} from "
            f"{when_text(first)} to {when_text(last)} UTC. Alarms: film parameter below {threshold:g} for "
            f"{settings.duration:g} s or more. Trend: least-squares straight line of the smallest film against time, "
            f"projected to the limit {bearing.limit * MICRO:.2f} µm"
            + (
                "."
                if last - first >= MIN_TREND_SPAN
                else f"; not fitted: the windows span {(last - first).total_seconds():.3g} s, and a trend needs "
                f"{MIN_TREND_SPAN.days} day or more (over a shorter time the film follows the operating point, "
                "not wear)."
            )
        ),
        *[
            Paragraph("warning: " + rejected_text(r.name, rejected[r.id]), "warn")
            for r in stored.recordings
            if rejected[r.id]
        ],
        *[Paragraph("warning: " + alarm_text(a, threshold), "warn") for t in stored.trends for a in t.alarms],
        Table(
            [
                "section",
                "windows",
                "lowest h_min [µm]",
                "lowest lambda",
                "alarms",
                "trend [µm/day]",
                "projected crossing (UTC)",
            ],
            _trend_rows(stored.trends),
            "Smallest film per section over the stored windows",
        ),
        Figure(
            "monitor_trend.png",
            figures.trend,
            (stored.trends, levels),
            caption="smallest film per section against time: lambda alarms shaded, fitted trend to the limit",
        ),
    ]
    if stored.lines:
        blocks.append(
            Figure(
                "monitor_trend_centre_line.png",
                figures.centre_line_ratio,
                (stored.lines,),
                caption="averaged shaft centre line of each section against speed (5 rpm bins)",
            )
        )
    return blocks


def _trend_document(stored: StoredTrends, settings: AlarmSettings, shown: str) -> dict[str, Any]:
    """``monitor_trend`` of the JSON: the recordings, each section's trend and the centre lines (SI)."""
    return {
        "units": {"length": "m", "speed": "rad/s", "angle": "rad", "duration": "s"},
        "database": shown,
        "lambda_threshold": settings.threshold,
        "alarm_duration": settings.duration,
        "recordings": [
            {
                "name": r.name,
                "content_hash": r.content_hash,
                "started_at": r.started_at.isoformat(),
                "complete": r.complete,
                "rejected_windows": len(stored.rejected[r.id]),
            }
            for r in stored.recordings
        ],
        "sections": {t.section: trend_json(t) for t in stored.trends},
        "centre_line": {
            line.section: {
                "speed": line.speed.tolist(),
                "eccentricity_ratio": line.eccentricity_ratio.tolist(),
                "attitude_angle": line.attitude_angle.tolist(),
                "windows": line.windows.tolist(),
            }
            for line in stored.lines
        },
    }
