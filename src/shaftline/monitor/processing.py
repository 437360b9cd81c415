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
from dataclasses import replace
from dataclasses import replace as replace_field
from pathlib import Path
from typing import TYPE_CHECKING

import numpy as np

from shaftline.errors import InputError
from shaftline.monitor.identified import (
    Identified,
    IdentifiedRecording,
    ProcessedRecording,
    RecordingPlan,
    RejectedWindow,
    SlowRoll,
)
from shaftline.monitor.orbits import binned_average, phase_bin_sums, revolution_marks, shaft_phase, speed_from_marks
from shaftline.monitor.probes import ProbeLayout, within_range
from shaftline.monitor.recordings import open_recording
from shaftline.monitor.regimes import film_ratio
from shaftline.monitor.study import IdentifyPlan, WindowResult, identify_window
from shaftline.monitor.trends import StoredRecording, TrendStore
from shaftline.registry import Progress, Tally, no_progress

if TYPE_CHECKING:
    from shaftline.monitor.identification import SectionReference

__all__ = [
    "BEARING",
    "Identified",
    "IdentifiedRecording",
    "MAX_INVALID_SHARE",
    "ProcessedRecording",
    "RecordingPlan",
    "identify_recordings",
    "mask_invalid",
    "SlowRoll",
    "plan_recording",
    "process_recording",
    "slow_roll_runout",
    "window_values",
]

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


#: Why a window was not identified (the value of ``(BEARING, "rejected")`` in the store).
REJECTED = {1: "more than max_invalid_share of its probe samples NaN or beyond range", 2: "no whole shaft revolution"}
#: Largest share of a window's probe samples that may be NaN or beyond the probe's range
#: (masked and filled); beyond it the window is refused (engineering judgement: 1 % of a
#: window's samples filled by interpolation moves its mean film by less than the noise).
MAX_INVALID_SHARE = 0.01
#: Plausible time-median film at a probe, in radial clearances: a journal inside its bore
#: gives 0 to 2 c (plus wear); a recording in mV read as V, or um read as mm, is 1000 times off.
FILM_PLAUSIBLE = (-1.0, 3.0)


def rejected_windows(store: TrendStore, recording: StoredRecording) -> tuple[RejectedWindow, ...]:
    """The windows of ``recording`` flagged in ``store`` as not identified, in order."""
    flags = store.series("rejected", BEARING, recording=recording)
    shares = store.series("invalid_share", BEARING, recording=recording)
    share_of = dict(zip(shares["window"], shares["value"], strict=True))
    return tuple(
        RejectedWindow(
            int(row.window),
            row.time.to_pydatetime(),
            REJECTED.get(int(row.value), "unknown"),
            float(share_of.get(row.window, math.nan)),
        )
        for row in flags.itertuples()
        if row.value and math.isfinite(row.value)
    )


def mask_invalid(layout: ProbeLayout, signals: np.ndarray) -> tuple[np.ndarray, int]:
    """Probe outputs with the NaN and out-of-range samples (:func:`~shaftline.monitor.probes.within_range`)
    filled by linear interpolation along time in their channel, and how many there were.

    A channel without any valid sample stays NaN (the share check refuses such a window first).
    """
    valid = within_range(layout, layout.gaps(signals))
    count = int(valid.size - np.count_nonzero(valid))
    if count == 0:
        return signals, 0
    filled = np.array(signals, dtype=float, copy=True)
    index = np.arange(filled.shape[0])
    # a loop over channels (tens), not samples
    for column in np.flatnonzero(~valid.all(axis=0)):
        good = valid[:, column]
        if good.any():
            filled[~good, column] = np.interp(index[~good], index[good], filled[good, column])
        else:
            filled[:, column] = np.nan
    return filled, count


def _check_share(masked: int, total: int, limit: float, where: str) -> None:
    if total and masked > limit * total:
        raise InputError(
            where,
            f"{masked / total:.2%} of the probe samples NaN or beyond the probe's range",
            "",
            f"at most {limit:.2%} (max_invalid_share; check the wiring, the probes' ranges and the units)",
        )


def _check_units(layout: ProbeLayout, signals: np.ndarray, where: str) -> None:
    """The time-median film at each probe must lie within the clearance (a factor 1000 off
    in the units of the outputs or the calibration is far outside)."""
    gaps = layout.gaps(signals)
    with np.errstate(all="ignore"):
        median = np.nanmedian(gaps, axis=0) if np.isfinite(gaps).any(axis=0).all() else None
    if median is None:
        return  # a channel of NaN only: the share check speaks
    clearance = layout.radial_clearance
    probes = [p for s in layout.sections for p in s.probes]
    low, high = FILM_PLAUSIBLE
    for probe, gap in zip(probes, median, strict=True):
        film = gap - probe.mounting_distance
        if not low * clearance <= film <= high * clearance:
            raise InputError(
                f"{where}, channel {probe.name}",
                f"median film {film * 1e3:.6g} mm",
                "",
                f"within the radial clearance {clearance * 1e3:g} mm ({low:g} to {high:g} c; an output in mV read "
                "as V, or a calibration in V/mm read as V/um, is 1000 times off)",
            )


#: Samples read at a time from a slow-roll recording (its revolutions are long: 4 s at 15 rpm).
SLOW_ROLL_BLOCK = 1 << 18
#: Bins of shaft phase of the runout profile (2.8 deg; the runout is a few harmonics).
RUNOUT_BINS = 128


def slow_roll_runout(
    layout: ProbeLayout,
    path: str | Path,
    keyphasor: str,
    sample_rate: float | None = None,
    ignore_channels: tuple[str, ...] | None = None,
    max_invalid_share: float = MAX_INVALID_SHARE,
    bins: int = RUNOUT_BINS,
) -> SlowRoll:
    """Runout of every probe from a slow-roll recording: the synchronous average of each probe's
    gap over the recording's whole revolutions, less its mean (Bently Nevada's slow-roll vector,
    every harmonic kept).

    The recording is read in blocks; the samples after a block's last keyphasor mark are carried
    into the next, so every whole revolution counts once whatever the block size. Invalid samples
    are masked as in :func:`mask_invalid`, the share checked per block.

    Raises
    ------
    InputError
        One line naming the file: channels, sample rate, units (the median film inside the
        clearance), too many invalid samples, or fewer than one whole revolution.
    """
    recording = open_recording(path)
    columns = [*layout.channels, keyphasor]
    rate = recording.sample_rate(columns, given=sample_rate)
    name = recording.path.name
    if ignore_channels is not None:
        extra = [c for c in recording.channels if c not in columns and c not in ignore_channels]
        if extra:
            raise InputError(
                f"{name} channels",
                ", ".join(extra),
                "",
                "only the probes' and the keyphasor's (name others in ignore_channels)",
            )
    sums = np.zeros((bins, len(layout.channels)))
    counts = np.zeros(bins)
    carry_gaps = np.empty((0, len(layout.channels)))
    carry_key = np.empty(0)
    turns = masked = 0
    span = 0  # samples from the first mark to the last
    for first, block in recording.blocks(columns, size=SLOW_ROLL_BLOCK):
        where = f"{name} samples {first}-{first + block.shape[0] - 1}"
        if first == 0:
            _check_units(layout, block[:, :-1], where)
        signals, bad = mask_invalid(layout, block[:, :-1])
        _check_share(bad, signals.size, max_invalid_share, where)
        masked += bad
        gaps = np.concatenate([carry_gaps, layout.gaps(signals)])
        key = np.concatenate([carry_key, block[:, -1]])
        marks = revolution_marks(key) if key.size >= 2 else np.empty(0, dtype=int)
        if marks.size >= 2:
            kept = slice(int(marks[0]), int(marks[-1]))
            phase = shaft_phase(key.size, marks)[kept]
            block_sums, block_counts = phase_bin_sums(gaps[kept], phase, bins)
            sums += block_sums
            counts += block_counts
            turns += marks.size - 1
            span += int(marks[-1] - marks[0])
            # from the sample before the last mark: a mark on a block's first sample is no edge
            carry_gaps, carry_key = gaps[int(marks[-1]) - 1 :], key[int(marks[-1]) - 1 :]
        else:
            carry_gaps, carry_key = gaps, key
        if carry_key.size > 64 * SLOW_ROLL_BLOCK:
            break  # no mark for 16 M samples: the keyphasor is not there (reported below)
    if turns < 1:
        raise InputError(
            f"{name} keyphasor {keyphasor}",
            f"{turns} whole revolutions",
            "",
            "a slow-roll recording of one whole revolution or more (two keyphasor marks)",
        )
    average = binned_average(sums, counts)
    profile = average - average.mean(axis=0)
    speed = 2 * np.pi * turns * rate / span
    return SlowRoll(name, recording.content_hash(), float(speed), turns, profile, masked, layout.channels)


def slow_windows_runout(
    layout: ProbeLayout,
    plan: RecordingPlan,
    below: float,
    max_invalid_share: float = MAX_INVALID_SHARE,
    bins: int = RUNOUT_BINS,
) -> SlowRoll | None:
    """Runout of every probe from the windows of a recording slower than ``below`` (rad/s, speed
    from the keyphasor marks in the window): the synchronous average of each probe's gap over the
    whole revolutions of those windows, less its mean, as :func:`slow_roll_runout` does on a
    slow-roll file. Windows without a whole revolution or with more than ``max_invalid_share``
    of their samples invalid are left out (they are stored as rejected). None when no window is
    slow enough.
    """
    sums = np.zeros((bins, len(layout.channels)))
    counts = np.zeros(bins)
    turns = span = masked = used = 0
    for first, block in plan.blocks():
        if first // plan.size >= plan.windows:
            break
        marks = revolution_marks(block[:, -1])
        if marks.size < 2 or 2 * math.pi * speed_from_marks(marks, plan.sample_rate) >= below:
            continue
        signals, bad = mask_invalid(layout, block[:, :-1])
        if bad > max_invalid_share * signals.size:
            continue
        kept = slice(int(marks[0]), int(marks[-1]))
        phase = shaft_phase(block.shape[0], marks)[kept]
        block_sums, block_counts = phase_bin_sums(layout.gaps(signals)[kept], phase, bins)
        sums += block_sums
        counts += block_counts
        turns += marks.size - 1
        span += int(marks[-1] - marks[0])
        masked += bad
        used += 1
    if turns == 0:
        return None
    average = binned_average(sums, counts)
    recording = plan.recording
    return SlowRoll(
        recording.path.name,
        recording.content_hash(),
        float(2 * np.pi * turns * plan.sample_rate / span),
        turns,
        average - average.mean(axis=0),
        masked,
        layout.channels,
        source="slow windows",
        windows=used,
    )


def processing_settings(
    layout: ProbeLayout,
    plan: IdentifyPlan,
    shape: tuple[np.ndarray, np.ndarray] | None,
    runout: str,
    sample_rate: float,
) -> dict[str, str]:
    """What a recording's stored windows depend on besides its bytes, as text: the probe layout
    (calibration, clearance, roughness), the shaft model's bending shape, the window, keyphasor or
    given speed, the sample rate (Hz, the file's or the case's), invalid share, and the runout
    subtracted (``runout``: its source). Numbers to 12 significant digits, the shape's to 9 (the
    same case gives the same text on any machine); the layout and shape as SHA-256."""
    import hashlib

    def digest(text: str) -> str:
        return hashlib.sha256(text.encode()).hexdigest()

    def number(value: float | None) -> str:
        return "none" if value is None else f"{value:.12g}"

    shaped = "none"
    if shape is not None:
        shaped = digest(" ".join(f"{v:.9g}" for v in np.concatenate([np.ravel(shape[0]), np.ravel(shape[1])])))
    return {
        "layout": digest(repr(layout)),
        "shaft_shape": shaped,
        "window": f"{number(plan.window)} s",
        "keyphasor": plan.keyphasor or f"none, {number(plan.speed)} rad/s",
        "sample_rate": number(sample_rate),
        "max_invalid_share": number(plan.max_invalid_share),
        "runout": runout,
    }


def plan_recording(
    layout: ProbeLayout,
    path: str | Path,
    keyphasor: str,
    window_seconds: float = 1.0,
    sample_rate: float | None = None,
    started_at: dt.datetime | None = None,
    ignore_channels: tuple[str, ...] | None = None,
    max_invalid_share: float = MAX_INVALID_SHARE,
    speed: float | None = None,
) -> RecordingPlan:
    """Open a recording and check it before anything of it is stored: its channels (every
    probe and the keyphasor; with ``ignore_channels`` given, no others but those), one sample
    rate, at least one window, and a first window whose films lie inside the clearance (the
    units) with no more than ``max_invalid_share`` of its probe samples NaN or beyond range.
    ``keyphasor`` "" reads a recording without one at the given shaft ``speed`` (rad/s).

    Raises
    ------
    InputError
        One line naming the file and what is wrong.
    """
    if not (isinstance(window_seconds, float | int) and math.isfinite(window_seconds) and window_seconds > 0.0):
        raise InputError("window_seconds", window_seconds, "s", "a positive length of a few revolutions")
    if not keyphasor and not (speed is not None and math.isfinite(speed) and speed > 0.0):
        raise InputError(
            "speed", "none" if speed is None else speed, "rad/s", "the shaft speed of recordings without a keyphasor"
        )
    recording = open_recording(path)
    if keyphasor and keyphasor not in recording.channels:
        # the case's name for it, not the file's channel list, is what is wrong most often
        others = [c for c in recording.channels if c not in layout.channels]
        raise InputError(
            "monitor.identify.keyphasor",
            keyphasor,
            "",
            f"the once-per-revolution channel of {recording.path.name} (channels there besides the probes: "
            + (", ".join(others[:8]) or 'none; keyphasor = "" and speed for recordings without one')
            + ")",
        )
    columns = [*layout.channels, keyphasor] if keyphasor else list(layout.channels)
    rate = recording.sample_rate(columns, given=sample_rate)
    if ignore_channels is not None:
        extra = [c for c in recording.channels if c not in columns and c not in ignore_channels]
        if extra:
            raise InputError(
                f"{recording.path.name} channels",
                ", ".join(extra),
                "",
                "only the probes' and the keyphasor's (name others in ignore_channels)",
            )
    size = int(round(window_seconds * rate))
    whole, rest = divmod(recording.samples, size)
    windows = whole + (1 if rest >= size / 2 else 0)
    if windows == 0:
        raise InputError(
            "window_seconds", window_seconds, "s", f"at most the recording's {recording.samples / rate:g} s"
        )
    plan = RecordingPlan(
        recording, rate, size, windows, dt.datetime.now(dt.UTC), keyphasor, speed, tuple(layout.channels)
    )
    first = next(plan.blocks())[1]
    marks = revolution_marks(first[:, -1])
    if marks.size < 2:
        raise InputError(
            "window",
            window_seconds,
            "s",
            f"a window of one shaft revolution or more (window 0 of {recording.path.name} holds {marks.size} "
            f"marks of the keyphasor {keyphasor or 'made from the given speed'})",
        )
    where = f"{recording.path.name} window 0"
    _check_units(layout, first[:, :-1], where)
    _, masked = mask_invalid(layout, first[:, :-1])
    _check_share(masked, first[:, :-1].size, max_invalid_share, where)
    if started_at is None:
        started_at = dt.datetime.fromtimestamp(recording.path.stat().st_mtime, tz=dt.UTC)
    return replace(plan, started_at=started_at)


def process_recording(
    layout: ProbeLayout,
    path: str | Path | RecordingPlan,
    store: TrendStore,
    keyphasor: str,
    window_seconds: float = 1.0,
    sample_rate: float | None = None,
    started_at: dt.datetime | None = None,
    shape: tuple[np.ndarray, np.ndarray] | None = None,
    progress: Callable[[int, int], None] | None = None,
    max_invalid_share: float = MAX_INVALID_SHARE,
    runout: np.ndarray | None = None,
) -> ProcessedRecording:
    """Identify every window of a recording and store its summary.

    Parameters
    ----------
    layout : ProbeLayout
        Probes; their names are the recording's channel names.
    path : str, Path or RecordingPlan
        The recording (CSV, Parquet, HDF5, TDMS), or one checked by :func:`plan_recording`
        (then ``window_seconds``, ``sample_rate`` and ``started_at`` are its own).
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
    max_invalid_share : float
        Largest share of a window's probe samples that may be NaN or beyond range (masked,
        filled and counted). The first window beyond it refuses the recording before anything
        is stored (:func:`plan_recording`); a later one, or one without a whole shaft
        revolution, is stored as rejected (``(BEARING, "rejected")`` = the :data:`REJECTED`
        code, with its ``invalid_share``), not identified, and the run carries on.
    runout : ndarray (bins, channels), optional
        Slow-roll runout of each probe (:func:`slow_roll_runout`), subtracted at the keyphasor's
        shaft phase in every window before anything else.

    Raises
    ------
    InputError
        From the recording's checks (channels, sample rate, units, its first window's invalid
        samples) or ``"window_seconds"``, before anything is stored.
    """
    plan = (
        path
        if isinstance(path, RecordingPlan)
        else plan_recording(
            layout, path, keyphasor, window_seconds, sample_rate, started_at, max_invalid_share=max_invalid_share
        )
    )
    recording, rate, size, windows = plan.recording, plan.sample_rate, plan.size, plan.windows
    stored = store.recording(recording.content_hash(), recording.path.name, recording.samples, rate, plan.started_at)
    done = store.windows_done(stored)
    if stored.complete or len(done) >= windows:
        return ProcessedRecording(stored, windows, 0, rejected=rejected_windows(store, stored))
    # The reference point from the first window, whatever windows are left to do.
    first = next(plan.blocks())[1]
    signals, _ = mask_invalid(layout, first[:, :-1])
    references = identify_window(layout, signals, first[:, -1], rate, runout=runout, shape=shape).references
    start = min(k for k in range(windows) if k not in done)
    written = masked = samples = 0
    last, last_window = None, -1
    for first_sample, block in plan.blocks(start):
        k = first_sample // size
        if k >= windows:
            break
        if k in done:
            continue
        time = stored.started_at + dt.timedelta(seconds=first_sample / rate)
        added, result, bad, counted = _store_window(
            layout, store, stored, k, time, block, rate, max_invalid_share, runout, shape, references
        )
        written, masked, samples = written + added, masked + bad, samples + counted
        if result is not None:
            last, last_window = result, k
        if progress is not None:
            progress(k + 1, windows)
    store.mark_complete(stored)
    return ProcessedRecording(
        stored, windows, written, masked, samples, rejected_windows(store, stored), last, last_window
    )


def _store_window(
    layout: ProbeLayout,
    store: TrendStore,
    stored: StoredRecording,
    window: int,
    time: dt.datetime,
    block: np.ndarray,
    rate: float,
    max_invalid_share: float,
    runout: np.ndarray | None,
    shape: tuple[np.ndarray, np.ndarray] | None,
    references: tuple[SectionReference, ...],
) -> tuple[int, WindowResult | None, int, int]:
    """Window ``window`` of a recording (probe outputs, the keyphasor last) identified and its
    values stored, or stored as rejected when too many of its samples are invalid or it holds no
    whole revolution: (windows written, its result or None when rejected, masked probe samples
    and probe samples of an identified window)."""
    signals, bad = mask_invalid(layout, block[:, :-1])
    share = bad / signals.size
    marks = revolution_marks(block[:, -1])
    code = 1 if share > max_invalid_share else 2 if marks.size < 2 else 0
    if code:
        # a monitoring run goes on past a bad stretch: the window is flagged, not identified
        speed = 2 * math.pi * speed_from_marks(marks, rate) if marks.size >= 2 else None
        flagged = {(BEARING, "rejected"): float(code), (BEARING, "invalid_share"): share}
        return int(store.add_window(stored, window, time, flagged, speed=speed)), None, 0, 0
    result = identify_window(layout, signals, block[:, -1], rate, runout=runout, shape=shape, references=references)
    values = window_values(result, layout) | {(BEARING, "invalid_share"): share}
    added = int(store.add_window(stored, window, time, values, speed=result.speed))
    # counted in the windows identified only: a rejected window's samples were not filled
    return added, result, bad, signals.size


def identify_recordings(
    layout: ProbeLayout,
    plan: IdentifyPlan,
    shape: tuple[np.ndarray, np.ndarray] | None = None,
    progress: Progress = no_progress,
    replace: bool = False,
) -> Identified:
    """Identify the recordings of ``plan`` into its trend database, window by window.

    Every recording is checked (:func:`plan_recording`) and the database reached before
    anything is stored, so bad input stores nothing. A recording stored before with other
    processing settings (:func:`processing_settings`: layout, window, runout source...) is
    refused, before anything is written, unless ``replace``: then its stored windows are
    deleted and it is identified again (no other recording is touched). Each window is then stored in its own
    transaction: Ctrl-C keeps every window stored so far and raises
    :class:`~shaftline.errors.Interrupted` saying how to resume (the same command again skips
    what is stored). ``progress`` gets a :class:`~shaftline.registry.Tally` of the windows of
    each recording.

    Raises
    ------
    InputError
        No recording, a bad recording (file, channels, sample rate, units, invalid samples)
        or a database that cannot be reached.
    """
    from shaftline.errors import Interrupted, interrupted_by_user
    from shaftline.monitor.trends import _hide_password

    _check_identify_plan(plan)
    slow_roll = _plan_runout(layout, plan)
    plans = _checked_recordings(layout, plan)
    source = _runout_source(slow_roll, plan)
    settings = [processing_settings(layout, plan, shape, source, c.sample_rate) for c in plans]
    shown = _hide_password(TrendStore.url_of(plan.database))
    done: list[IdentifiedRecording] = []
    try:
        opened = TrendStore(plan.database)
    except InputError as error:
        raise InputError("database", error.value, "", error.allowed, in_file=True) from None
    with opened as store:
        replaced = _settings_changed(store, plans, settings, shown, replace)
        try:
            for number, checked in enumerate(plans, 1):
                label = f"{checked.recording.path.name} ({number}/{len(plans)})"
                again = replaced[number - 1]
                done.append(
                    _identify_one(
                        store, layout, plan, checked, settings[number - 1], again, slow_roll, shape, label, progress
                    )  # fmt: skip
                )
        except (KeyboardInterrupt, SystemError) as stop:
            # Ctrl-C inside the compiled orbit kernel arrives as a SystemError caused by it
            if not interrupted_by_user(stop):
                raise
            raise Interrupted(
                f"every window identified so far is kept in {shown}: run the same command again to resume"
            ) from None
    return Identified(shown, tuple(done), plan.lambda_threshold, plan.alarm_duration, slow_roll, plan.slow_roll_speed)


def _named(error: InputError, name: str) -> InputError:
    """``error`` of the file ``name`` named by the file, not placed under [monitor] (the file is
    not the case)."""
    file = Path(name).name
    field = error.field if error.field.startswith(file) else f"{file}: {error.field}"
    return InputError(field, error.value, error.unit, error.allowed, in_file=True)


def _check_identify_plan(plan: IdentifyPlan) -> None:
    """What of ``plan`` can be refused before any file is read: no recording, no speed for
    recordings without a keyphasor, more than one source of runout, a runout without a
    keyphasor (named as the case names them)."""
    if not plan.recordings:
        raise InputError(
            "RECORDING",
            "none",
            "",
            "one recording file or more (or recordings = [...] in [monitor.identify])",
            in_file=True,
        )
    speed = plan.speed
    if not plan.keyphasor and not (speed is not None and math.isfinite(speed) and speed > 0.0):
        raise InputError(
            "identify.speed",
            "none" if speed is None else speed,
            "rad/s",
            'the shaft speed of recordings without a keyphasor (keyphasor = "")',
        )
    sources = [name for name in ("slow_roll", "slow_roll_speed", "runout") if getattr(plan, name) is not None]
    if len(sources) > 1:
        raise InputError(
            f"identify.{sources[1]}", "given", "", f"one source of runout only ({' and '.join(sources)} given)"
        )
    if sources and not plan.keyphasor:
        raise InputError(
            f"identify.{sources[0]}",
            plan.slow_roll if sources[0] == "slow_roll" else "given",
            "",
            "recordings with a keyphasor (the runout is a function of shaft phase)",
        )


def _plan_runout(layout: ProbeLayout, plan: IdentifyPlan) -> SlowRoll | None:
    """The runout subtracted from every window: the slow-roll recording's or the case's table
    (None: neither; with ``slow_roll_speed`` each recording gets its own later)."""
    if plan.slow_roll is not None:
        try:
            return slow_roll_runout(
                layout, plan.slow_roll, plan.keyphasor, plan.sample_rate, plan.ignore_channels, plan.max_invalid_share
            )
        except InputError as error:
            raise _named(error, plan.slow_roll) from None
    if plan.runout is not None:
        if plan.runout.channels != layout.channels:
            raise InputError("identify.runout", ", ".join(plan.runout.channels), "", "the layout's probes, in order")
        return SlowRoll(
            "runout table of the case",
            plan.runout.digest(),
            math.nan,
            0,
            plan.runout.profile(RUNOUT_BINS),
            channels=layout.channels,
            source="table",
        )
    return None


def _checked_recordings(layout: ProbeLayout, plan: IdentifyPlan) -> list[RecordingPlan]:
    """Every recording of ``plan`` checked (:func:`plan_recording`), each starting where the one
    before ends when the plan gives the first one's start."""
    plans = []
    start = plan.start
    for name in plan.recordings:
        try:
            checked = plan_recording(
                layout, name, plan.keyphasor, plan.window, plan.sample_rate, start, plan.ignore_channels,
                plan.max_invalid_share, plan.speed,
            )  # fmt: skip
        except InputError as error:
            raise _named(error, name) from None
        plans.append(checked)
        if start is not None:  # the next file follows this one
            start = start + dt.timedelta(seconds=checked.duration)
    return plans


def _runout_source(slow_roll: SlowRoll | None, plan: IdentifyPlan) -> str:
    """The runout's source as the processing settings name it: by content (a slow-roll file
    renamed or moved is the same slow roll)."""
    if slow_roll is not None:
        kind = "slow-roll recording" if slow_roll.source == "recording" else "table"
        return f"{kind} sha256 {slow_roll.content_hash}"
    if plan.slow_roll_speed is not None:
        return f"slow windows below {plan.slow_roll_speed:.12g} rad/s"
    return "none"


def _settings_changed(
    store: TrendStore, plans: list[RecordingPlan], settings: list[dict[str, str]], shown: str, replace: bool
) -> list[bool]:
    """Whether each recording was stored before with other settings: refused unless ``replace``,
    all before anything is written."""
    replaced = []
    for checked, wanted in zip(plans, settings, strict=True):
        stored = store.find(checked.recording.content_hash())
        before = None if stored is None else store.settings(stored)
        differ = sorted(k for k in wanted if before is not None and before.get(k) != wanted[k])
        if differ and not replace:
            file = checked.recording.path.name
            raise InputError(
                f"{file}: settings",
                "; ".join(f"{k} {wanted[k]}" for k in differ),
                "",
                f"the settings its windows in {shown} were identified with ("
                + "; ".join(f"{k} {(before or {}).get(k, 'not recorded')}" for k in differ)
                + "); --replace identifies it again in place of its stored windows (other recordings are kept), "
                "or use another database",
                in_file=True,
            )
        replaced.append(bool(differ))
    return replaced


def _identify_one(
    store: TrendStore,
    layout: ProbeLayout,
    plan: IdentifyPlan,
    checked: RecordingPlan,
    settings: dict[str, str],
    replaced: bool,
    slow_roll: SlowRoll | None,
    shape: tuple[np.ndarray, np.ndarray] | None,
    label: str,
    progress: Progress,
) -> IdentifiedRecording:
    """One checked recording into the store (its stored windows first deleted when ``replaced``)
    and its trends, with the progress tally of its windows under ``label``."""
    from shaftline.monitor.trends import section_trends

    progress(Tally(label, 0, checked.windows, "windows"))

    def told(windows: int, total: int) -> None:
        progress(Tally(label, windows, total, "windows"))

    recording = checked.recording
    stored = store.recording(
        recording.content_hash(), recording.path.name, recording.samples, checked.sample_rate, checked.started_at
    )
    if replaced or store.settings(stored) is None:
        # (a recording stored before settings were kept takes this run's)
        store.keep_settings(stored, settings, replace=replaced)
        stored = replace_field(stored, complete=stored.complete and not replaced)
    runout = slow_roll
    if plan.slow_roll_speed is not None:
        # per recording; not read again when nothing of it is left to identify
        below, share = plan.slow_roll_speed, plan.max_invalid_share
        runout = None if stored.complete else slow_windows_runout(layout, checked, below, share)
    processed = process_recording(
        layout,
        checked,
        store,
        plan.keyphasor,
        shape=shape,
        progress=told,
        max_invalid_share=plan.max_invalid_share,
        runout=None if runout is None else runout.profile,
    )
    duration = dt.timedelta(seconds=plan.alarm_duration)
    trends = section_trends(store, plan.lambda_threshold, duration, recording=processed.recording)
    return IdentifiedRecording(checked, processed, trends, runout, replaced)
