"""A recording from file to trend database, window by window (issue 13).

The recording is read in windows of a set length (blocks of samples x probe channels and the
keyphasor, :mod:`~shaftline.monitor.recordings`), each window identified
(:func:`~shaftline.monitor.study.identify_window`) and its summary stored
(:class:`~shaftline.monitor.trends.TrendStore`) in one transaction. The reference point of
every section (the seed's reference from stable running) is taken from the first window and
held for the whole recording, so each window's orbit is measured from the same point whether
the recording is processed in one run or resumed after a stop. A recording already stored in
full is recognised by its content hash and skipped.
"""

from __future__ import annotations

import datetime as dt
import math
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from shaftline.errors import InputError
from shaftline.monitor.probes import ProbeLayout
from shaftline.monitor.recordings import open_recording
from shaftline.monitor.regimes import film_ratio
from shaftline.monitor.study import WindowResult, identify_window
from shaftline.monitor.trends import StoredRecording, TrendStore

__all__ = ["BEARING", "ProcessedRecording", "process_recording", "window_values"]

#: Section name of the values that belong to the whole bearing (regime lengths, the smallest
#: film along it).
BEARING = "bearing"


def window_values(result: WindowResult, layout: ProbeLayout) -> dict[tuple[str, str], float]:
    """The numbers of one window kept in the trend database, by (section, quantity), SI units.

    Per measurement section: the time-mean smallest film (``min_film_thickness``, m) and its
    lowest value in the window (``min_film_thickness_low``), the film parameter of the mean
    (``film_parameter``), the mean eccentricity ratio and attitude angle (rad), the correction
    factor k (m), the largest peak-to-peak motion (m), the 1X amplitudes (m) and whether the
    averaged orbit is a figure 8 (1 or 0). For the bearing: the smallest time-mean film along
    it and its film parameter, and the lengths in boundary, mixed and hydrodynamic lubrication
    (m).
    """
    values: dict[tuple[str, str], float] = {}
    for orbit, descriptors in zip(result.orbits, result.descriptors, strict=True):
        name = orbit.name
        film = orbit.min_film
        attitude = orbit.attitude_angle
        values[(name, "min_film_thickness")] = float(film.mean())
        values[(name, "min_film_thickness_low")] = float(film.min())
        values[(name, "film_parameter")] = float(film_ratio(film.mean(), layout))
        values[(name, "eccentricity_ratio")] = float(orbit.eccentricity_ratio.mean())
        # circular mean: the attitude may sit near +-pi
        values[(name, "attitude_angle")] = float(np.angle(np.exp(1j * attitude).mean()))
        values[(name, "correction")] = float(orbit.correction)
        values[(name, "peak_to_peak")] = float(descriptors.peak_to_peak[2])
        values[(name, "vertical_1x")] = float(descriptors.vertical_1x.amplitude)
        values[(name, "horizontal_1x")] = float(descriptors.horizontal_1x.amplitude)
        values[(name, "figure_eight")] = float(descriptors.ellipse.figure_eight)
    smallest = float(np.min(result.min_film))
    values[(BEARING, "min_film_thickness")] = smallest
    values[(BEARING, "film_parameter")] = float(film_ratio(np.asarray(smallest), layout))
    for regime in ("boundary", "mixed", "hydrodynamic"):
        values[(BEARING, f"{regime}_length")] = float(np.mean(getattr(result.regimes, regime)))
    return values


@dataclass(frozen=True)
class ProcessedRecording:
    """What a run did with one recording.

    Attributes
    ----------
    recording : StoredRecording
    windows : int
        Windows in the recording.
    written : int
        Windows identified and stored by this run (0 for a recording stored before).
    """

    recording: StoredRecording
    windows: int
    written: int


def process_recording(
    layout: ProbeLayout,
    path: str | Path,
    store: TrendStore,
    keyphasor: str,
    window_seconds: float = 1.0,
    sample_rate: float | None = None,
    started_at: dt.datetime | None = None,
    shape: tuple[np.ndarray, np.ndarray] | None = None,
    progress: Callable[[int, int], None] | None = None,
) -> ProcessedRecording:
    """Identify every window of a recording and store its summary.

    Parameters
    ----------
    layout : ProbeLayout
        Probes; their names are the recording's channel names.
    path : str or Path
        The recording (CSV, Parquet, HDF5, TDMS).
    store : TrendStore
    keyphasor : str
        Name of the once-per-revolution channel.
    window_seconds : float
        Length of a window, s (several revolutions; the last, shorter window is dropped when
        it holds fewer than half a window's samples).
    sample_rate : float, optional
        Hz, where the file does not state it (checked against the file's where both exist).
    started_at : datetime, optional
        Time of the first sample; without it, the file's modification time.
    shape : (stations, shape), optional
        Bending shape of the shaft model for the centre line.
    progress : callable, optional
        Called with (windows done, windows in all) after each window.

    Raises
    ------
    InputError
        From the recording (channels, sample rate) or ``"window_seconds"``.
    """
    if not (isinstance(window_seconds, float | int) and math.isfinite(window_seconds) and window_seconds > 0.0):
        raise InputError("window_seconds", window_seconds, "s", "a positive length of a few revolutions")
    recording = open_recording(path)
    columns = [*layout.channels, keyphasor]
    rate = recording.sample_rate(columns, given=sample_rate)
    size = int(round(window_seconds * rate))
    whole, rest = divmod(recording.samples, size)
    windows = whole + (1 if rest >= size / 2 else 0)
    if windows == 0:
        raise InputError(
            "window_seconds", window_seconds, "s", f"at most the recording's {recording.samples / rate:g} s"
        )
    if started_at is None:
        started_at = dt.datetime.fromtimestamp(recording.path.stat().st_mtime, tz=dt.UTC)
    stored = store.recording(recording.content_hash(), recording.path.name, recording.samples, rate, started_at)
    done = store.windows_done(stored)
    if stored.complete or len(done) >= windows:
        return ProcessedRecording(stored, windows, 0)
    # The reference point from the first window, whatever windows are left to do.
    first = next(recording.blocks(columns, size=size))[1]
    references = identify_window(layout, first[:, :-1], first[:, -1], rate, shape=shape).references
    start = min(k for k in range(windows) if k not in done)
    written = 0
    for first_sample, block in recording.blocks(columns, size=size, start=start * size):
        k = first_sample // size
        if k >= windows:
            break
        if k in done:
            continue
        result = identify_window(layout, block[:, :-1], block[:, -1], rate, shape=shape, references=references)
        time = stored.started_at + dt.timedelta(seconds=first_sample / rate)
        if store.add_window(stored, k, time, window_values(result, layout), speed=result.speed):
            written += 1
        if progress is not None:
            progress(k + 1, windows)
    store.mark_complete(stored)
    return ProcessedRecording(stored, windows, written)
