"""Film-thickness monitoring as a capability: ``[monitor]`` in a case file, ``shaftline monitor
simulate``, ``monitor`` in results.json, a section of the report (issue 13, part A: synthetic
recordings of seed 001's rig; readers of real recordings, trends and alarms follow)."""

from __future__ import annotations

import math
from pathlib import Path
from typing import TYPE_CHECKING, Any

from shaftline.registry import BuildContext, Capability, Finding, Progress, Verb, no_progress
from shaftline.report.blocks import Block, DataFile, Figure, Heading, Paragraph, Table

if TYPE_CHECKING:
    from shaftline.monitor.case import MonitorSection
    from shaftline.monitor.study import MonitorResult, MonitorStudy, SimulatedPoint

RPM = 30 / math.pi
MICRO = 1e6


def _rpm(speed: float) -> str:
    return f"{speed * RPM:.0f} rpm"


class FilmMonitor(Capability["MonitorSection", "MonitorStudy", "MonitorResult"]):
    key = "monitor"
    title = "Film-thickness monitoring (eddy-current probes)"
    verbs = (
        Verb(
            ("monitor", "simulate"),
            "Synthetic probe recordings of seed 001's rig from the bearing solver and the shaft model, identified "
            "(orbits, film round the sections and along the bearing, regimes) and compared with the truth.",
        ),
    )

    def schema(self) -> type[MonitorSection]:
        from shaftline.monitor.case import MonitorSection

        return MonitorSection

    def build(self, section: MonitorSection, context: BuildContext) -> MonitorStudy:
        from shaftline.monitor.case import build_study

        return build_study(section, context)

    def solve(self, study: MonitorStudy, progress: Progress = no_progress, **options: Any) -> MonitorResult:
        from shaftline.monitor.study import solve_monitor

        return solve_monitor(study, progress)

    def to_json(self, result: MonitorResult) -> dict[str, Any]:
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
                    },
                }
            )
        return {
            "units": {"length": "m", "speed": "rad/s", "angle": "rad", "amplitude": "m"},
            "channels": list(layout.channels),
            "thresholds": {"boundary_below": low, "hydrodynamic_above": high},
            "points": points,
        }

    def _table(self, result: MonitorResult) -> Table:
        rows = []
        for point in result.points:
            window = point.window
            films = " / ".join(f"{orbit.min_film.mean() * MICRO:.2f}" for orbit in window.orbits)
            rows.append(
                [
                    _rpm(window.speed),
                    films,
                    f"{window.regimes.boundary[0] * 1e3:.0f} / {window.regimes.mixed[0] * 1e3:.0f} / "
                    f"{window.regimes.hydrodynamic[0] * 1e3:.0f}",
                    f"{point.true_regimes.boundary[0] * 1e3:.0f} / {point.true_regimes.mixed[0] * 1e3:.0f} / "
                    f"{point.true_regimes.hydrodynamic[0] * 1e3:.0f}",
                    f"{point.film_error * MICRO:.3f}",
                    f"{point.line_error * MICRO:.3f}",
                ]
            )
        names = "/".join(section.name for section in result.study.layout.sections)
        headers = [
            "speed",
            f"h_min {names} [µm]",
            "B/M/H [mm]",
            "true B/M/H [mm]",
            "film err [µm]",
            "h_min err [µm]",
        ]
        title = (
            "Synthetic recordings identified: mean h_min at each section, lengths of the boundary, mixed and "
            "hydrodynamic regions (identified and true), largest error of the mean film round the sections and of "
            "h_min along the bearing"
        )
        return Table(headers, rows, title)

    def findings(self, result: MonitorResult) -> list[Finding]:
        found = []
        for point in result.points:
            if point.recording.contact:
                found.append(
                    Finding(
                        f"At {_rpm(point.recording.speed)} the bearing solver found no film carrying the load "
                        "above its floor: the synthetic journal stands where its search stopped (the film there "
                        "is not a hydrodynamic one).",
                        criterion=True,
                    )
                )
        return found

    def summary(self, result: MonitorResult) -> list[Block]:
        if not result.points:
            return [Paragraph("No recordings: give [monitor.simulate] to make synthetic ones.")]
        return [self._table(result)]

    def report(self, result: MonitorResult) -> list[Block]:
        from dataclasses import replace

        import numpy as np

        from shaftline.monitor import figures
        from shaftline.monitor.bending import film_map
        from shaftline.monitor.orbits import shaft_centre_line
        from shaftline.monitor.regimes import thresholds
        from shaftline.monitor.study import FILM_ANGLES

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
        if not result.points:
            return blocks
        rig = study.rig
        assert rig is not None  # points come from the rig
        blocks.append(
            Paragraph(
                f"Synthetic recordings of seed 001's rig: {rig.load / 1e3:.0f} kN, misalignment "
                f"{rig.misalignment * 1e6:.1f} µrad, {rig.bend_scale:g} of the shaft model's bending, whirl "
                f"{rig.whirl * MICRO:.2f} µm at {_rpm(rig.whirl_speed)}, runout {rig.runout[0] * MICRO:.2f}/"
                f"{rig.runout[1] * MICRO:.2f} µm (1X/2X, removed with the slow roll at {_rpm(study.slow_roll_speed)}), "
                f"noise {rig.noise * MICRO:.3f} µm, {rig.sample_rate:g} Hz, {rig.revolutions:g} revolutions each."
            )
        )
        blocks.append(self._table(result))
        last = result.points[-1]
        window = last.window
        blocks.append(
            Figure(
                "monitor_min_film.png",
                figures.min_film_along,
                (window.stations, {_rpm(p.window.speed): p.window.min_film for p in result.points}, layout),
                caption="smallest film along the bearing at each speed on the regime bands",
            )
        )
        theta = FILM_ANGLES
        stations = window.stations
        # The map of the time-mean centre line on a 0.5 deg grid (every sample on it would not fit in memory).
        mean_line = replace(
            window.line,
            coefficients_y=window.line.coefficients_y.mean(axis=0, keepdims=True),
            coefficients_z=window.line.coefficients_z.mean(axis=0, keepdims=True),
        )
        fine = np.radians(np.arange(0.0, 360.0, 0.5))
        blocks.append(
            Figure(
                "monitor_film_map.png",
                figures.film_map,
                (fine, stations, film_map(mean_line, layout, fine, stations)[0], layout),
                caption=f"unwrapped full-bearing film of the mean centre line at {_rpm(window.speed)} with the "
                "regime contours",
            )
        )
        for index, orbit in enumerate(window.orbits):
            blocks.append(Heading(f"Section {orbit.name} at {_rpm(window.speed)}"))
            blocks.append(
                Figure(f"monitor_orbit_{index}.png", figures.orbit, (orbit,), caption="orbit in the clearance circle")
            )
            blocks.append(
                Figure(
                    f"monitor_film_polar_{index}.png",
                    figures.film_polar,
                    (theta, window.films[index], layout),
                    {"label": orbit.name},
                    caption="film round the section",
                )
            )
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
                (points, layout.radial_clearance, layout.rotation),
                caption=f"averaged shaft centre line of section {window.orbits[middle].name} against speed",
            )
        )
        if study.write_recordings:
            for point in result.points:
                blocks.append(
                    DataFile(
                        f"recording_{point.recording.speed * RPM:.0f}rpm.csv",
                        _recording_writer(point, layout.channels),
                        f"synthetic recording at {_rpm(point.recording.speed)} (time, probe outputs in V, keyphasor)",
                    )
                )
        return blocks


def _recording_writer(point: SimulatedPoint, channels: tuple[str, ...]) -> Any:
    def write(path: Path) -> None:
        import numpy as np

        recording = point.recording
        time = np.arange(recording.signals.shape[0]) / recording.sample_rate
        table = np.column_stack([time, recording.signals, recording.keyphasor])
        header = ",".join(["time_s", *channels, "keyphasor"])
        np.savetxt(path, table, delimiter=",", header=header, comments="", fmt="%.9g")

    return write


CAPABILITY = FilmMonitor()
