"""One monitoring window from probe signals to film and regimes, and the synthetic study of the rig.

:func:`identify_window` is the whole chain for one block of samples (what a reader of long
recordings feeds chunk by chunk): gaps from the probe outputs, slow-roll runout removed at
the keyphasor's shaft phase, reference point and correction factor k, orbits, the centre line
with the shaft model's bending shape, h_min along the bearing, regime lengths and orbit
descriptors. :func:`solve_monitor` runs it on synthetic recordings of seed 001's rig and
compares the result with the truth that made them.
"""

from __future__ import annotations

import datetime as dt
import math
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import TYPE_CHECKING

import numpy as np

from shaftline.monitor.bending import CentreLine, least_squares_line, min_film_along, model_line
from shaftline.monitor.forward import Recording, RigCase, equilibrium_lines, rig_shape_for, simulate
from shaftline.monitor.identification import SectionOrbit, SectionReference, probe_films, reference_points
from shaftline.monitor.orbits import (
    Ellipse,
    Vector1X,
    compensate_runout,
    fit_ellipse,
    peak_to_peak,
    revolution_marks,
    runout_profile,
    shaft_phase,
    speed_from_marks,
    synchronous_average,
    vector_1x,
    whole_revolutions,
)
from shaftline.monitor.probes import ProbeLayout
from shaftline.monitor.regimes import RegimeLengths, regime_lengths

if TYPE_CHECKING:
    from shaftline.monitor.identified import Identified

#: Stations along the bearing for h_min and the regime lengths.
STATIONS = 121
#: Angles of the film reported round each section, rad (every 15 deg).
FILM_ANGLES = np.radians(np.arange(0.0, 360.0, 15.0))


@dataclass(frozen=True, eq=False)
class SectionDescriptors:
    """Orbit descriptors of one section over a window.

    Attributes
    ----------
    peak_to_peak : tuple of float
        Vertical, horizontal and largest peak-to-peak motion, m.
    vertical_1x, horizontal_1x : Vector1X
        Once-per-revolution components.
    ellipse : Ellipse
        Equivalent ellipse of the synchronously averaged orbit, with the figure-8 test.
    """

    peak_to_peak: tuple[float, float, float]
    vertical_1x: Vector1X
    horizontal_1x: Vector1X
    ellipse: Ellipse


@dataclass(frozen=True, eq=False)
class WindowResult:
    """Identification of one window of samples.

    Attributes
    ----------
    speed : float
        Shaft speed from the keyphasor, rad/s.
    references : tuple of SectionReference
        Reference point and correction factor k of each section.
    orbits : tuple of SectionOrbit
        Orbit of each section over the whole revolutions of the window.
    films : tuple of ndarray (N, m)
        Film at :data:`FILM_ANGLES` round each section, m.
    line : CentreLine
        Centre line along the bearing (the shaft model's shape, or least squares without one).
    stations : ndarray (nz,)
        Stations along the bearing, m from the loaded end.
    min_film : ndarray (nz,)
        Time-mean smallest film round the bore at each station, m.
    regimes : RegimeLengths
        Axial lengths of the regimes of that film, m.
    descriptors : tuple of SectionDescriptors
    """

    speed: float
    references: tuple[SectionReference, ...]
    orbits: tuple[SectionOrbit, ...]
    films: tuple[np.ndarray, ...] = field(repr=False)
    line: CentreLine = field(repr=False)
    stations: np.ndarray = field(repr=False)
    min_film: np.ndarray = field(repr=False)
    regimes: RegimeLengths = field(repr=False)
    descriptors: tuple[SectionDescriptors, ...] = field(repr=False)


def identify_window(
    layout: ProbeLayout,
    signals: np.ndarray,
    keyphasor: np.ndarray,
    sample_rate: float,
    runout: np.ndarray | None = None,
    shape: tuple[np.ndarray, np.ndarray] | None = None,
    correction: bool = True,
    references: tuple[SectionReference, ...] | None = None,
) -> WindowResult:
    """Film, orbits, regimes and descriptors of one window of probe outputs.

    Parameters
    ----------
    layout : ProbeLayout
    signals : ndarray (N, channels)
        Probe outputs, V, in ``layout.channels`` order.
    keyphasor : ndarray (N,)
        Once-per-revolution channel.
    sample_rate : float
        Hz.
    runout : ndarray (bins, channels), optional
        Slow-roll runout profile (:func:`shaftline.monitor.orbits.runout_profile`).
    shape : (stations, shape), optional
        Bending shape from the shaft model (:func:`shaftline.monitor.bending.model_shape`),
        used with three sections or more; otherwise the centre line is the least-squares
        polynomial (with one section, a journal parallel to the bore).
    correction : bool
        Identify the correction factor k from three or more probes per section.
    references : tuple of SectionReference, optional
        Reference points and k fixed from an earlier window of stable running (the seed's
        reference point); without them this window's mean gaps give them.
    """
    gaps = layout.gaps(signals)
    marks = revolution_marks(keyphasor)
    phase = shaft_phase(gaps.shape[0], marks)
    if runout is not None:
        gaps = compensate_runout(gaps, phase, runout)
    window = whole_revolutions(marks)
    gaps, phase = gaps[window], phase[window]
    if references is None:
        references = reference_points(layout, gaps, correction=correction)
    results = probe_films(layout, gaps, references, theta=FILM_ANGLES)
    orbits = tuple(orbit for orbit, _ in results)
    films = tuple(film for _, film in results)
    if shape is not None and len(orbits) >= 3:
        line = model_line(orbits, shape[0], shape[1], layout.radial_clearance, layout.length)
    else:
        line = least_squares_line(orbits)
    stations = np.linspace(0.0, layout.length, STATIONS)
    min_film = min_film_along(line, layout, stations).mean(axis=0)
    descriptors = []
    for orbit in orbits:
        averaged = synchronous_average(np.stack([orbit.ey, orbit.ez], axis=1), phase)
        descriptors.append(
            SectionDescriptors(
                peak_to_peak(orbit.ey, orbit.ez),
                vector_1x(orbit.ey, phase),
                vector_1x(orbit.ez, phase),
                fit_ellipse(averaged[:, 0], averaged[:, 1]),
            )
        )
    return WindowResult(
        2 * math.pi * speed_from_marks(marks, sample_rate),
        references,
        orbits,
        films,
        line,
        stations,
        min_film,
        regime_lengths(stations, min_film, layout),
        tuple(descriptors),
    )


@dataclass(frozen=True)
class RunoutTable:
    """Runout of every probe against shaft angle from the case (``[[monitor.identify.runout]]``).

    Attributes
    ----------
    channels : tuple of str
        The probes, in the layout's order.
    angles : tuple of tuple of float
        Shaft angles of each probe's values, rad from the keyphasor mark, rising within a turn.
    values : tuple of tuple of float
        Runout at those angles, m.
    """

    channels: tuple[str, ...]
    angles: tuple[tuple[float, ...], ...]
    values: tuple[tuple[float, ...], ...]

    def profile(self, bins: int = 128) -> np.ndarray:
        """The runout profile (bins, channels), mean removed, m
        (:func:`~shaftline.monitor.orbits.runout_from_table`)."""
        from shaftline.monitor.orbits import runout_from_table

        return runout_from_table([np.asarray(a) for a in self.angles], [np.asarray(v) for v in self.values], bins)

    def digest(self) -> str:
        """SHA-256 of the table (its numbers to 12 significant digits): what a stored recording's
        processing settings name."""
        import hashlib

        text = repr([(c, [f"{a:.12g}" for a in an], [f"{v:.12g}" for v in va])
                     for c, an, va in zip(self.channels, self.angles, self.values, strict=True)])  # fmt: skip
        return hashlib.sha256(text.encode()).hexdigest()


@dataclass(frozen=True)
class IdentifyPlan:
    """Recordings to identify into the trend database (``[monitor.identify]``).

    Attributes
    ----------
    recordings : tuple of str
        Files, in the order given.
    database : str
        SQLAlchemy URL or SQLite file.
    keyphasor : str
        Once-per-revolution channel.
    window : float
        Window length, s.
    sample_rate : float or None
        Hz where the files do not state it.
    start : datetime or None
        First sample of the first recording where the files do not state it (the others follow
        back to back); None: each file's modification time.
    ignore_channels : tuple of str
        Extra channels left alone.
    max_invalid_share : float
        Largest share of masked probe samples in a window.
    lambda_threshold : float
        Film parameter of an alarm.
    alarm_duration : float
        Shortest alarm stretch, s.
    slow_roll : str or None
        Slow-roll recording whose runout is subtracted from every window (None: none).
    speed : float or None
        Shaft speed of recordings without a keyphasor (``keyphasor`` ""), rad/s.
    slow_roll_speed : float or None
        Windows of a recording slower than this are its slow roll (their runout is subtracted from
        all its windows), rad/s; None: not used.
    runout : RunoutTable or None
        Runout of every probe from the case; None: none.
    """

    recordings: tuple[str, ...]
    database: str
    keyphasor: str = "keyphasor"
    window: float = 2.0
    sample_rate: float | None = None
    start: dt.datetime | None = None
    ignore_channels: tuple[str, ...] = ()
    max_invalid_share: float = 0.01
    lambda_threshold: float = 1.0
    alarm_duration: float = 600.0
    slow_roll: str | None = None
    speed: float | None = None
    slow_roll_speed: float | None = None
    runout: RunoutTable | None = None


@dataclass(frozen=True, eq=False)
class MonitorStudy:
    """A monitoring case: the probe layout and, for now, the synthetic recordings to make.

    Attributes
    ----------
    layout : ProbeLayout
    rig : RigCase or None
        Forward model of seed 001's rig (None: no synthetic recordings).
    speeds : tuple of float
        Speeds of the recordings, rad/s.
    slow_roll_speed : float
        Speed of the slow-roll recording, rad/s.
    write_recordings : bool
        Keep the recordings for CSV files beside the report.
    shape : (stations, shape) or None
        Bending shape of the journal from the machine's shaft model (None: the rig's).
    identify : IdentifyPlan or None
        Recordings to identify into the trend database.
    """

    layout: ProbeLayout
    rig: RigCase | None
    speeds: tuple[float, ...]
    slow_roll_speed: float
    write_recordings: bool
    shape: tuple[np.ndarray, np.ndarray] | None = None
    identify: IdentifyPlan | None = None

    def bending_shape(self) -> tuple[np.ndarray, np.ndarray] | None:
        """The bending shape ``monitor simulate`` uses: the shaft model's, else the rig's
        forward model's where the case simulates it, else none (least squares)."""
        if self.shape is not None:
            return self.shape
        return None if self.rig is None else rig_shape_for(self.rig)


@dataclass(frozen=True, eq=False)
class SimulatedPoint:
    """One synthetic recording, its identification and the truth.

    Attributes
    ----------
    recording : Recording
    window : WindowResult
    true_min_film : ndarray (nz,)
        True time-mean smallest film at ``window.stations``, m.
    true_regimes : RegimeLengths
    film_error : float
        Largest error of the time-mean film at the probe sections (every 15 deg), m.
    line_error : float
        Largest error of the time-mean h_min along the bearing, m.
    """

    recording: Recording = field(repr=False)
    window: WindowResult = field(repr=False)
    true_min_film: np.ndarray = field(repr=False)
    true_regimes: RegimeLengths = field(repr=False)
    film_error: float
    line_error: float


@dataclass(frozen=True, eq=False)
class MonitorResult:
    """Result of a monitoring case.

    Attributes
    ----------
    study : MonitorStudy
    points : tuple of SimulatedPoint
        One per speed, in the order given.
    runout : ndarray (bins, channels) or None
        Runout measured at slow roll, m.
    identified : Identified or None
        Recordings identified into the trend database (``monitor identify``).
    slow_roll : Recording or None
        The synthetic slow-roll recording the runout was measured on.
    """

    study: MonitorStudy
    points: tuple[SimulatedPoint, ...]
    runout: np.ndarray | None = field(repr=False)
    identified: Identified | None = field(default=None, repr=False)
    slow_roll: Recording | None = field(default=None, repr=False)


def solve_monitor(
    study: MonitorStudy, progress: Callable[[str], None] | None = None, simulate_rig: bool = True
) -> MonitorResult:
    """Make the synthetic recordings of the study, identify each and compare with the truth
    (none with ``simulate_rig`` False)."""
    if study.rig is None or not simulate_rig:
        return MonitorResult(study, (), None)
    rig, layout = study.rig, study.layout
    # The journal's equilibria (the costly part, 0.2-3 s each) over the cores at once; the
    # recordings and their identification after.
    told = None if progress is None else (lambda done, total: progress(f"bearing solver: {done} of {total} speeds"))
    lines = equilibrium_lines(rig, (study.slow_roll_speed, *study.speeds), progress=told)
    if progress is not None:
        progress(f"slow roll at {study.slow_roll_speed * 30 / math.pi:.0f} rpm")
    slow = simulate(rig, study.slow_roll_speed, lines[0])
    gaps = layout.gaps(slow.signals)
    marks = revolution_marks(slow.keyphasor)
    window = whole_revolutions(marks)
    runout = runout_profile(gaps[window], shaft_phase(gaps.shape[0], marks)[window])
    shape = study.shape if study.shape is not None else rig_shape_for(rig)
    points = []
    for speed, line in zip(study.speeds, lines[1:], strict=True):
        if progress is not None:
            progress(f"recording at {speed * 30 / math.pi:.0f} rpm")
        recording = simulate(rig, speed, line)
        result = identify_window(layout, recording.signals, recording.keyphasor, rig.sample_rate, runout, shape)
        kept = whole_revolutions(revolution_marks(recording.keyphasor))
        ey, ez = recording.centres(result.stations)
        true_min = (recording.clearance - np.hypot(ey, ez))[kept].mean(axis=0)
        film_error = 0.0
        for section, film in zip(layout.sections, result.films, strict=True):
            true = recording.film(layout, FILM_ANGLES, np.array([section.position]))[kept, 0, :]
            film_error = max(film_error, float(np.abs((film - true).mean(axis=0)).max()))
        points.append(
            SimulatedPoint(
                recording,
                result,
                true_min,
                regime_lengths(result.stations, true_min, layout),
                film_error,
                float(np.abs(result.min_film - true_min).max()),
            )
        )
    return MonitorResult(study, tuple(points), runout, slow_roll=slow)
