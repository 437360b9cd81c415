"""What a monitoring result shows: its JSON (``monitor`` in results.json), the terminal's tables
and the report's blocks.

The presentation of :class:`~shaftline.monitor.capability.FilmMonitor`, apart from the
declaration of the capability (schema, build, solve, findings) and from its command line
(:mod:`shaftline.monitor.commands`). Heavy modules (numpy, the figures) are imported inside the
functions that need them, as the capability module imports this one to list its verbs.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from pathlib import Path
from typing import TYPE_CHECKING, Any

from shaftline.report.blocks import Block, DataFile, Figure, Heading, Paragraph, Table

if TYPE_CHECKING:
    import numpy as np

    from shaftline.monitor.forward import Recording, RigCase
    from shaftline.monitor.identification import SectionOrbit
    from shaftline.monitor.identified import Identified, RejectedWindow, SlowRoll
    from shaftline.monitor.probes import ProbeLayout
    from shaftline.monitor.study import MonitorResult, WindowResult
    from shaftline.monitor.trends import LambdaAlarm, SectionTrend

RPM = 30 / math.pi
MICRO = 1e6


def rpm_text(speed: float) -> str:
    """A shaft speed (rad/s) as shown: ``"135 rpm"``."""
    return f"{speed * RPM:.0f} rpm"


def monitor_json(result: MonitorResult) -> dict[str, Any]:
    """``monitor`` of results.json: each simulated point identified beside its truth, and what
    ``monitor identify`` stored (:func:`identified_json`), SI units."""
    from shaftline.monitor.regimes import thresholds

    layout = result.study.layout
    low, high = thresholds(layout)
    points = []
    for point in result.points:
        window = point.window
        points.append(
            {
                "speed": window.speed,
                "sections": [
                    {
                        "name": orbit.name,
                        "position": orbit.position,
                        "correction": reference.correction,
                        "residual": reference.residual,
                        "min_film": float(orbit.min_film.mean()),
                        "min_film_smallest": float(orbit.min_film.min()),
                        "eccentricity_ratio": float(orbit.eccentricity_ratio.mean()),
                        "attitude_angle": float(orbit.attitude_angle.mean()),
                        "peak_to_peak": list(descriptor.peak_to_peak),
                        "vertical_1x": [descriptor.vertical_1x.amplitude, descriptor.vertical_1x.phase],
                        "horizontal_1x": [descriptor.horizontal_1x.amplitude, descriptor.horizontal_1x.phase],
                        "figure_eight": descriptor.ellipse.figure_eight,
                    }
                    for orbit, reference, descriptor in zip(
                        window.orbits, window.references, window.descriptors, strict=True
                    )
                ],
                "stations": window.stations.tolist(),
                "min_film_along": window.min_film.tolist(),
                "regime_lengths": {
                    "boundary": float(window.regimes.boundary[0]),
                    "mixed": float(window.regimes.mixed[0]),
                    "hydrodynamic": float(window.regimes.hydrodynamic[0]),
                },
                "truth": {
                    "min_film_along": point.true_min_film.tolist(),
                    "regime_lengths": {
                        "boundary": float(point.true_regimes.boundary[0]),
                        "mixed": float(point.true_regimes.mixed[0]),
                        "hydrodynamic": float(point.true_regimes.hydrodynamic[0]),
                    },
                    "film_error": point.film_error,
                    "min_film_error": point.line_error,
                    "solver_contact": point.recording.contact,
                    "solver": {
                        "status": point.recording.solver_status,
                        "min_film": point.recording.solver_min_film,
                        "max_liner_deformation": point.recording.max_liner_deformation,
                        "asperity_load_share": point.recording.asperity_load_share,
                    },
                },
            }
        )
    return {
        "units": {"length": "m", "speed": "rad/s", "angle": "rad", "amplitude": "m", "duration": "s"},
        "channels": list(layout.channels),
        "thresholds": {"boundary_below": low, "hydrodynamic_above": high},
        "points": points,
        "identify": None if result.identified is None else identified_json(result.identified),
    }


def simulated_table(result: MonitorResult) -> Table:
    """The synthetic recordings identified: films, regime lengths and errors against the truth."""
    rows = []
    for point in result.points:
        window = point.window
        # Cells without spaces ("3.82/4.64/4.74", not "3.82 / 4.64 / 4.74"): a cell with
        # spaces is wrapped at them in an 80-column terminal, a row over two lines.
        films = "/".join(f"{orbit.min_film.mean() * MICRO:.2f}" for orbit in window.orbits)
        rows.append(
            [
                f"{window.speed * RPM:.0f}",
                films,
                f"{window.regimes.boundary[0] * 1e3:.0f}/{window.regimes.mixed[0] * 1e3:.0f}/"
                f"{window.regimes.hydrodynamic[0] * 1e3:.0f}",
                f"{point.true_regimes.boundary[0] * 1e3:.0f}/{point.true_regimes.mixed[0] * 1e3:.0f}/"
                f"{point.true_regimes.hydrodynamic[0] * 1e3:.0f}",
                f"{point.film_error * MICRO:.3f}",
                f"{point.line_error * MICRO:.3f}",
            ]
        )
    names = "/".join(section.name for section in result.study.layout.sections)
    # Headers no wider than their cells where they can be (units in the title): a table
    # wider than the terminal is narrowed by rich inside the cells, a row over two lines.
    headers = ["rpm", "h_min [µm]", "B/M/H [mm]", "true B/M/H", "film err", "h_min err"]
    title = (
        f"Synthetic recordings identified: mean h_min at {names} (journal to undeformed bore), lengths of the "
        "boundary, mixed and "
        "hydrodynamic regions (identified and true, mm), largest error of the mean film round the sections and "
        "of h_min along the bearing (µm)"
    )
    return Table(headers, rows, title)


def summary_blocks(result: MonitorResult) -> list[Block]:
    """What the terminal shows after a run: the recordings identified, then the simulated ones."""
    blocks: list[Block] = []
    if result.identified is not None:
        blocks += [
            *_masked_warnings(result.identified),
            *_runout_blocks(result.identified),
            *_identified_tables(result.identified, short_names=True),
        ]
    if result.points:
        blocks.append(simulated_table(result))
    if not blocks:
        return [Paragraph("No recordings: give [monitor.simulate] to make synthetic ones.")]
    return blocks


def report_blocks(result: MonitorResult) -> list[Block]:
    """The report's section: the layout, the recordings identified, the simulated rig and its figures."""

    import numpy as np

    from shaftline.monitor import figures
    from shaftline.monitor.orbits import shaft_centre_line
    from shaftline.monitor.regimes import thresholds

    study = result.study
    layout = study.layout
    low, high = thresholds(layout)
    blocks: list[Block] = [
        Paragraph(
            f"Bearing {layout.length * 1e3:.0f} mm long, bore {2 * layout.radius * 1e3:.1f} mm, radial clearance "
            f"{layout.radial_clearance * 1e3:.3f} mm; roughness Ra {layout.roughness_bearing * MICRO:.2f} µm "
            f"(bore) and {layout.roughness_journal * MICRO:.2f} µm (journal), Rq = {layout.rq_factor:g} Ra: "
            f"boundary lubrication below h_min = {low * MICRO:.2f} µm, hydrodynamic above {high * MICRO:.2f} µm. "
            f"Sections: "
            + ", ".join(f"{s.name} at {s.position * 1e3:.1f} mm ({len(s.probes)} probes)" for s in layout.sections)
            + "."
        )
    ]
    if result.identified is not None:
        blocks += _identified_blocks(result.identified, (low, high), layout)
    if not result.points:
        return blocks
    rig = study.rig
    assert rig is not None  # points come from the rig
    blocks.append(
        Paragraph(
            f"Synthetic recordings of seed 001's rig: {rig.load / 1e3:.0f} kN, misalignment "
            f"{rig.misalignment * 1e6:.1f} µrad, {rig.bend_scale:g} of the shaft model's bending, whirl "
            f"{rig.whirl * MICRO:.2f} µm at {rpm_text(rig.whirl_speed)}, runout {rig.runout[0] * MICRO:.2f}/"
            f"{rig.runout[1] * MICRO:.2f} µm (1X/2X, removed with the slow roll at {rpm_text(study.slow_roll_speed)}), "
            f"noise {rig.noise * MICRO:.3f} µm, {rig.sample_rate:g} Hz, "
            + (f"{rig.revolutions:g} revolutions" if rig.duration is None else f"{rig.duration:g} s")
            + " each. "
            + _rig_surfaces_text(rig)
        )
    )
    blocks.append(simulated_table(result))
    blocks.append(_solver_table(result))
    last = result.points[-1]
    window = last.window
    blocks.append(
        Figure(
            "monitor_min_film.png",
            figures.min_film_along,
            (window.stations, {rpm_text(p.window.speed): p.window.min_film for p in result.points}, layout),
            caption="smallest film along the bearing at each speed on the regime bands",
        )
    )
    blocks += window_blocks(window, layout, "monitor")
    middle = len(window.orbits) // 2
    points = shaft_centre_line(
        np.array([p.window.speed / (2 * math.pi) for p in result.points]),
        [p.window.orbits[middle].ey for p in result.points],
        [p.window.orbits[middle].ez for p in result.points],
    )
    blocks.append(
        Figure(
            "monitor_centre_line.png",
            figures.centre_line_vs_speed,
            (points, layout.radial_clearance, layout.rotation, window.orbits[middle].name),
            caption=f"averaged shaft centre line of section {window.orbits[middle].name} against speed",
        )
    )
    if study.write_recordings:
        for point in result.points:
            blocks.append(
                DataFile(
                    f"recording_{point.recording.speed * RPM:03.0f}rpm.csv",  # 035 before 135: globs sort by speed
                    _recording_writer(point.recording, layout.channels),
                    f"synthetic recording at {rpm_text(point.recording.speed)} (time, probe outputs in V, keyphasor)",
                )
            )
        if result.slow_roll is not None:
            # what `monitor identify --slow-roll` measures the runout on
            blocks.append(
                DataFile(
                    f"slow_roll_{result.slow_roll.speed * RPM:.0f}rpm.csv",
                    _recording_writer(result.slow_roll, layout.channels),
                    f"synthetic slow-roll recording at {rpm_text(result.slow_roll.speed)} (the runout)",
                )
            )
    return blocks


def _rig_surfaces_text(rig: RigCase) -> str:
    """What the forward model's bearing solver has of surfaces and liner, and what the probes see."""
    surface = (
        "smooth surfaces"
        if rig.surface is None
        else f"rough surfaces (Rq {rig.surface.journal_rq * MICRO:.2f} µm journal, "
        f"{rig.surface.bore_rq * MICRO:.2f} µm bore, Greenwood-Tripp asperity contact)"
    )
    if rig.liner is None:
        return f"The bearing solver has {surface} and a rigid bore."
    liner = rig.liner
    return (
        f"The bearing solver has {surface} and a {liner.thickness * 1e3:g} mm liner (E {liner.modulus / 1e6:.0f} MPa, "
        f"ν {liner.poisson:g}, {liner.model} model). The probes sit in the housing and see the journal: the film they "
        "give (and the truth they are compared with) is the gap to the undeformed bore, negative where the journal "
        "has pressed the liner in; the bearing's own film is that plus the liner's compression (table below)."
    )


def _solver_table(result: MonitorResult) -> Table:
    """The bearing solver's state at each simulated speed: what the forward model's journal stands on."""
    rows = [
        [
            f"{point.recording.speed * RPM:.0f}",
            point.recording.solver_status,
            f"{point.recording.solver_min_film * MICRO:.2f}",
            f"{point.recording.max_liner_deformation * MICRO:.2f}",
            f"{100 * point.recording.asperity_load_share:.1f}",
        ]
        for point in result.points
    ]
    return Table(
        ["rpm", "solver", "h_min [µm]", "liner [µm]", "asperity [%]"],
        rows,
        "The bearing solver at each speed: its smallest film (liner deformed; rough surfaces: the separation of the "
        "mean planes, negative in boundary lubrication), the largest compression of the liner and the share of the "
        "load on the asperities",
    )


def _polar_mean_and_smallest(
    orbit: SectionOrbit, theta: np.ndarray, layout: ProbeLayout, block: int = 4096
) -> tuple[np.ndarray, np.ndarray]:
    """Time-mean and smallest film round a section at ``theta`` from the orbit's samples, m, in
    blocks of samples: a window of 2 s at 10 kHz on a 1 deg grid is 58 MB a film array, and the
    exact form makes several (the 1 GiB of a long recording's run)."""
    import numpy as np

    from shaftline.monitor.identification import film_between_circles

    total = np.zeros(theta.size)
    smallest = np.full(theta.size, np.inf)
    for start in range(0, orbit.ey.size, block):
        part = film_between_circles(
            orbit.ey[start : start + block], orbit.ez[start : start + block], theta, layout, orbit.correction
        )
        total += part.sum(axis=0)
        smallest = np.minimum(smallest, part.min(axis=0))
    return total / max(orbit.ey.size, 1), smallest


def window_blocks(window: WindowResult, layout: ProbeLayout, prefix: str, label: str = "") -> list[Block]:
    """The unwrapped film map of a window's mean centre line, and the orbit and the film round
    each section, as figures named ``prefix``_film_map.png, ``prefix``_orbit_<i>.png and
    ``prefix``_film_polar_<i>.png."""
    from dataclasses import replace

    import numpy as np

    from shaftline.monitor import figures
    from shaftline.monitor.bending import film_map

    blocks: list[Block] = []
    # The polar film on a 1 deg grid from each sample's centre: the stored films' 15 deg grid missed the
    # smallest film (the example's journal sits at 188 deg: +2 um drawn where the orbit gives -1.7 um).
    # Reduced to the mean and the smallest at once, so the report holds two curves, not every sample.
    polar = np.radians(np.arange(0.0, 360.0, 1.0))
    stations = window.stations
    where = label or rpm_text(window.speed)
    # The map of the time-mean centre line on a 0.5 deg grid (every sample on it would not fit in memory).
    mean_line = replace(
        window.line,
        coefficients_y=window.line.coefficients_y.mean(axis=0, keepdims=True),
        coefficients_z=window.line.coefficients_z.mean(axis=0, keepdims=True),
    )
    fine = np.radians(np.arange(0.0, 360.0, 0.5))
    blocks.append(
        Figure(
            f"{prefix}_film_map.png",
            figures.film_map,
            (fine, stations, film_map(mean_line, layout, fine, stations)[0], layout),
            caption=f"unwrapped full-bearing film of the mean centre line at {where} with the regime contours",
        )
    )
    for index, orbit in enumerate(window.orbits):
        blocks.append(Heading(f"Section {orbit.name} at {where}"))
        blocks.append(
            Figure(f"{prefix}_orbit_{index}.png", figures.orbit, (orbit,), caption="orbit in the clearance circle")
        )
        mean, smallest = _polar_mean_and_smallest(orbit, polar, layout)
        blocks.append(
            Figure(
                f"{prefix}_film_polar_{index}.png",
                figures.film_polar,
                (polar, mean, layout),
                {"label": orbit.name, "smallest": smallest},
                caption="film round the section",
            )
        )
    return blocks


def _recording_writer(recording: Recording, channels: tuple[str, ...]) -> Any:
    def write(path: Path) -> None:
        import numpy as np

        time = np.arange(recording.signals.shape[0]) / recording.sample_rate
        table = np.column_stack([time, recording.signals, recording.keyphasor])
        header = ",".join(["time_s", *channels, "keyphasor"])
        np.savetxt(path, table, delimiter=",", header=header, comments="", fmt="%.9g")

    return write


def count_text(number: int, noun: str) -> str:
    """``"1 window"``, ``"3 windows"``."""
    return f"{number} {noun}" + ("" if number == 1 else "s")


def when_text(moment: Any) -> str:
    """A time as shown, to the second: ``"2026-11-02 06:00:00"``."""
    import datetime as dt

    # to the nearest second: a time a microsecond short of a whole second is shown as that second
    return f"{moment + dt.timedelta(microseconds=500_000):%Y-%m-%d %H:%M:%S}"


def rejected_text(name: str, rejected: Sequence[RejectedWindow]) -> str:
    """The finding of the windows of recording ``name`` not identified (the first five named)."""
    shown = ", ".join(
        f"{w.window} ({when_text(w.time)}: {w.reason}, {w.invalid_share:.1%} invalid)" for w in rejected[:5]
    ) + (f" and {len(rejected) - 5} more" if len(rejected) > 5 else "")
    return (
        f"{name}: {len(rejected)} window{'s' if len(rejected) > 1 else ''} not identified and flagged as rejected in "
        f"the database, left out of the trends: {shown}."
    )


def alarm_text(alarm: LambdaAlarm, threshold: float) -> str:
    """The finding of a lambda alarm: where, when, how long and how low."""
    where = "along the bearing" if alarm.section == "bearing" else f"at section {alarm.section}"
    return (
        f"Film parameter below {threshold:g} {where} from {when_text(alarm.start)} to {when_text(alarm.end)} UTC "
        f"({alarm.duration.total_seconds():.0f} s, lowest {alarm.lowest:.2f}): boundary lubrication."
    )


def _numbers(values: Any) -> list[float | None]:
    return [float(v) if math.isfinite(v) else None for v in values]


def trend_json(trend: SectionTrend) -> dict[str, Any]:
    """A section's trend for the JSON: its windows' values, alarms, limit and fitted trend (SI)."""
    crossing = trend.crossing
    return {
        "times": [t.isoformat() for t in trend.times],
        "speed": _numbers(trend.speed),
        "min_film_thickness": _numbers(trend.min_film),
        "film_parameter": _numbers(trend.film_parameter),
        "alarms": [
            {
                "start": a.start.isoformat(),
                "end": a.end.isoformat(),
                "duration": a.duration.total_seconds(),
                "lowest": a.lowest,
            }
            for a in trend.alarms
        ],
        "limit": trend.limit if math.isfinite(trend.limit) else None,
        "trend": None
        if crossing is None
        else {
            "slope_per_day": crossing.slope,
            "value_now": crossing.value_now,
            "crossing": None if crossing.crossing is None else crossing.crossing.isoformat(),
        },
    }


def _runout_json(slow: SlowRoll | None) -> dict[str, Any] | None:
    if slow is None:
        return None
    return {
        "source": slow.source,
        "name": slow.name,
        "content_hash": slow.content_hash,
        "speed": slow.speed if math.isfinite(slow.speed) else None,
        "revolutions": slow.revolutions,
        "windows": slow.windows,
        "masked_samples": slow.masked,
        "runout_peak_to_peak": dict(zip(slow.channels, slow.peak_to_peak.tolist(), strict=True)),
    }


def identified_json(identified: Identified) -> dict[str, Any]:
    """``monitor.identify`` of results.json: per recording its windows and trends (SI units)."""
    return {
        "database": identified.database,
        "lambda_threshold": identified.lambda_threshold,
        "alarm_duration": identified.alarm_duration,
        "slow_roll": _runout_json(identified.slow_roll),
        "slow_roll_speed": identified.slow_roll_speed,
        "recordings": [
            {
                "name": item.plan.recording.path.name,
                "content_hash": item.processed.recording.content_hash,
                "started_at": item.processed.recording.started_at.isoformat(),
                "sample_rate": item.plan.sample_rate,
                "duration": item.plan.duration,
                "windows": item.processed.windows,
                "written": item.processed.written,
                "masked_samples": item.processed.masked,
                "runout": _runout_json(item.runout),
                "replaced": item.replaced,
                "rejected_windows": [
                    {
                        "window": w.window,
                        "time": w.time.isoformat(),
                        "reason": w.reason,
                        "invalid_share": w.invalid_share,
                    }
                    for w in item.processed.rejected
                ],
                "sections": {trend.section: trend_json(trend) for trend in item.trends},
            }
            for item in identified.recordings
        ],
    }


#: A slow-roll recording faster than this share of the lowest identified speed is warned about
#: (engineering judgement: seed 001's rig rolls slowly at 15 rpm against 135-215 rpm, 0.11).
SLOW_ROLL_SHARE = 0.5


def _slow_windows_notes(identified: Identified) -> list[Block]:
    """What ``slow_roll_speed`` found in each recording identified by this run."""
    import numpy as np

    below = identified.slow_roll_speed
    assert below is not None
    blocks: list[Block] = []
    for item in identified.recordings:
        name, runout = item.plan.recording.path.name, item.runout
        if runout is None and item.processed.written == 0:
            continue  # stored before with these settings: nothing identified now
        if runout is None:
            blocks.append(
                Paragraph(
                    f"warning: {name}: no window below slow_roll_speed {rpm_text(below)}: the probes' runout is not "
                    "subtracted from its windows.",
                    "warn",
                )
            )
            continue
        worst = int(np.argmax(runout.peak_to_peak))
        text = (
            f"{name}: runout from its {count_text(runout.windows, 'window')} below {rpm_text(below)} "
            f"({runout.revolutions} revolutions at {rpm_text(runout.speed)}) subtracted from all its windows, up to "
            f"{runout.peak_to_peak[worst] * MICRO:.2f} µm peak to peak (probe {runout.channels[worst]})"
        )
        speeds = np.concatenate([t.speed for t in item.trends if t.section == "bearing"] or [np.empty(0)])
        faster = speeds[np.isfinite(speeds) & (speeds >= below)]
        # as for a slow-roll file: a "slow roll" near the running speed holds the film's and the
        # unbalance's motion, which would then be subtracted from every window
        if faster.size == 0:
            blocks.append(
                Paragraph(
                    f"warning: {text}; but every window is below slow_roll_speed: the runout is the whole synchronous "
                    "motion of the recording. Set slow_roll_speed below its running speed.",
                    "warn",
                )
            )
        elif runout.speed > SLOW_ROLL_SHARE * float(faster.min()):
            blocks.append(
                Paragraph(
                    f"warning: {text}; but its slow windows ran at {rpm_text(runout.speed)}, more than "
                    f"{SLOW_ROLL_SHARE:.0%} of its lowest speed above the threshold ({rpm_text(float(faster.min()))}): "
                    "their runout holds the film's and the unbalance's motion. Set slow_roll_speed near turning gear.",
                    "warn",
                )
            )
        else:
            blocks.append(Paragraph(text + "."))
    return blocks


def _runout_blocks(identified: Identified) -> list[Block]:
    """The runout subtracted (or not) and the recordings whose windows were replaced."""
    runout = _slow_windows_notes(identified) if identified.slow_roll_speed is not None else [_runout_note(identified)]
    replaced: list[Block] = [
        Paragraph(
            f"{item.plan.recording.path.name}: stored before with other processing settings; its windows were "
            "replaced (--replace)."
        )
        for item in identified.recordings
        if item.replaced
    ]
    return [*runout, *replaced]


def _runout_note(identified: Identified) -> Paragraph:
    slow = identified.slow_roll
    if slow is not None and slow.source == "table":
        import numpy as np

        worst = int(np.argmax(slow.peak_to_peak))
        return Paragraph(
            f"Runout subtracted from every window: the case's runout table ([[monitor.identify.runout]]), up to "
            f"{slow.peak_to_peak[worst] * MICRO:.2f} µm peak to peak (probe {slow.channels[worst]})."
        )
    if slow is None:
        return Paragraph(
            "No slow-roll recording (--slow-roll or [monitor.identify] slow_roll): the probes' runout is not "
            "subtracted, so it shows in the orbits, the 1X vectors and each window's lowest film (not in the mean "
            "film, over whole revolutions)."
        )
    import numpy as np

    worst = int(np.argmax(slow.peak_to_peak))
    text = (
        f"Runout subtracted from every window: measured on {slow.name} ({slow.revolutions} revolutions at "
        f"{rpm_text(slow.speed)}), up to {slow.peak_to_peak[worst] * MICRO:.2f} µm peak to peak (probe "
        f"{slow.channels[worst]})."
    )
    speeds = [t.speed for item in identified.recordings for t in item.trends if np.isfinite(t.speed).any()]
    lowest = min((float(np.nanmin(v)) for v in speeds), default=math.inf)
    if slow.speed > SLOW_ROLL_SHARE * lowest:
        # A slow roll is taken where film and unbalance do not move the journal; one near the
        # running speed measures that motion as "runout" and subtracts it from every window.
        return Paragraph(
            f"warning: {text[0].lower()}{text[1:-1]}; but the slow roll ran at {rpm_text(slow.speed)}, more than "
            f"{SLOW_ROLL_SHARE:.0%} of the lowest speed identified ({rpm_text(lowest)}): its runout holds the film's "
            "and the unbalance's motion at that speed. Record the slow roll at turning-gear speed.",
            "warn",
        )
    return Paragraph(text)


def _masked_warnings(identified: Identified) -> list[Block]:
    blocks: list[Block] = []
    for item in identified.recordings:
        done = item.processed
        if done.masked:
            blocks.append(
                Paragraph(
                    f"warning: {item.plan.recording.path.name}: {done.masked} probe samples of {done.samples} "
                    f"({done.masked / done.samples:.3%}) were NaN, text or beyond their probe's range, masked and "
                    "filled along time",
                    "warn",
                )
            )
    return blocks


#: Longest recording name in the terminal's tables of ``monitor identify``: the widest that
#: leaves the first table (its start time, three counts) within 80 columns.
NAME_WIDTH = 24


def shortened(name: str, width: int = NAME_WIDTH) -> str:
    """``name`` in at most ``width`` characters, cut in the middle (an ellipsis there) so that its
    start and its end, where a recording's date, speed or number and its suffix usually are, stay.

    >>> shortened("stern_tube_aft_2026-11-02T06-00-00_120rpm.csv")
    'stern_tube_…0_120rpm.csv'
    >>> shortened("run1.tdms")
    'run1.tdms'
    """
    if len(name) <= width:
        return name
    head = (width - 1) // 2
    return name[:head] + "…" + name[len(name) - (width - 1 - head) :]


def _identified_tables(identified: Identified, short_names: bool = False) -> list[Block]:
    """What ``monitor identify`` did with each recording (windows, stored, rejected) and what it
    found (speed, mean h_min per section, lowest lambda, alarms): two tables, each row on one line
    of an 80-column terminal (one table of nine columns folded every row over five lines and its
    headers inside words, "window s"). With ``short_names`` (the terminal) names longer than
    :data:`NAME_WIDTH` are cut in the middle (:func:`shortened`; rich folded them over lines), with
    a note that the report and results.json have them in full."""
    import numpy as np

    work, found = [], []
    cut = False
    for item in identified.recordings:
        done = item.processed
        name = item.plan.recording.path.name
        if short_names and len(name) > NAME_WIDTH:
            name, cut = shortened(name), True
        by_name = {trend.section: trend for trend in item.trends}
        # no spaces in a cell that must stay on one line (wrapped at them otherwise)
        films = "/".join(
            f"{np.nanmean(t.min_film) * MICRO:.2f}" if np.isfinite(t.min_film).any() else "-"
            for name_, t in by_name.items()
            if name_ != "bearing"
        )
        whole = by_name.get("bearing")
        lowest = f"{np.nanmin(whole.film_parameter):.2f}" if whole is not None and whole.times else "-"
        speeds = next(iter(by_name.values())).speed if by_name else np.array([])
        work.append(
            [name, when_text(done.recording.started_at), f"{done.windows}", f"{done.written}", f"{len(done.rejected)}"]
        )
        found.append(
            [
                name,
                f"{np.nanmean(speeds) * RPM:.0f}" if speeds.size else "-",
                films,
                lowest,
                f"{sum(len(t.alarms) for t in item.trends)}",
            ]
        )
    names = "/".join(
        t.section for t in (identified.recordings[0].trends if identified.recordings else ()) if t.section != "bearing"
    )
    # Headers no wider than their cells where they can be: a table wider than the terminal is
    # narrowed by rich inside the cells (the recording names folded).
    note: list[Block] = []
    if cut:
        note = [
            Paragraph(
                f"Recording names longer than {NAME_WIDTH} characters are cut in the middle (…) here; the report "
                "and results.json give them in full.",
                "note",
            )
        ]
    section_films = [t.min_film for item in identified.recordings for t in item.trends if len(t.min_film)]
    if any(np.nanmin(np.asarray(f)) < 0.0 for f in section_films):
        # `monitor simulate` says this of its rig; a user's own recordings with negative films need it as much
        note.append(
            Paragraph(
                "A negative film (and lambda) is the journal nearer the probes than the undeformed bore: the probes "
                "sit in the housing, so where the journal has pressed the liner in (or the liner has worn) the gap "
                "they give is negative (docs/theory.md Sect. 18).",
                "note",
            )
        )
    return [
        Table(
            ["recording", "start (UTC)", "windows", "stored", "rejected"],
            work,
            f"Recordings identified into {identified.database}: windows found, stored by this run (not stored "
            "before), rejected",
        ),
        Table(
            ["recording", "rpm", "h_min [µm]", "min lambda", "alarms"],
            found,
            f"Identified films: mean speed, mean h_min at {names}, lowest film parameter lambda, lambda alarms "
            f"(below {identified.lambda_threshold:g} for {identified.alarm_duration:g} s or more)",
        ),
        *note,
    ]


def _identified_blocks(identified: Identified, levels: tuple[float, float], layout: ProbeLayout) -> list[Block]:
    from shaftline.monitor import figures

    blocks: list[Block] = [*_masked_warnings(identified), *_runout_blocks(identified), *_identified_tables(identified)]
    for index, item in enumerate(identified.recordings):
        if not item.trends:
            continue
        blocks.append(
            Figure(
                f"monitor_identified_{index}.png",
                figures.trend,
                (item.trends, levels),
                {"fit": False},
                caption=f"{item.plan.recording.path.name}: smallest film of each section over its windows, regime "
                "thresholds, lambda alarms shaded",
            )
        )
    # what the trends leave out: the film round and along the bearing, the orbits, of the last
    # window identified of each recording (the figures `monitor simulate` draws of its recordings)
    last = [(item, item.processed.last) for item in identified.recordings if item.processed.last is not None]
    if last:
        item, window = last[-1]
        name = item.plan.recording.path.name
        blocks.append(Heading(f"Last window identified: {name}, window {item.processed.last_window}"))
        blocks.append(
            Figure(
                "monitor_identified_min_film.png",
                figures.min_film_along,
                (
                    window.stations,
                    {f"{i.plan.recording.path.name} ({rpm_text(w.speed)})": w.min_film for i, w in last},
                    layout,
                ),  # fmt: skip
                caption="smallest film along the bearing in the last window of each recording on the regime bands",
            )
        )
        blocks += window_blocks(window, layout, "monitor_identified", f"{rpm_text(window.speed)} ({name})")
    return blocks
