"""The records of ``monitor identify``: a recording checked before anything of it is stored,
what a run did with it, its runout, and the run's whole result.

Data only, shared by :mod:`~shaftline.monitor.processing`, which makes them, and
:mod:`~shaftline.monitor.study`, whose :class:`~shaftline.monitor.study.MonitorResult` holds
them, so that neither module needs the other's at run time.
"""

from __future__ import annotations

import datetime as dt
import math
from collections.abc import Iterator
from dataclasses import dataclass, field
from typing import TYPE_CHECKING

import numpy as np

if TYPE_CHECKING:
    from shaftline.monitor.recordings import Recording
    from shaftline.monitor.study import WindowResult
    from shaftline.monitor.trends import SectionTrend, StoredRecording


@dataclass(frozen=True)
class RecordingPlan:
    """A recording checked before anything of it is stored.

    Attributes
    ----------
    recording : Recording
    sample_rate : float
        Hz.
    size : int
        Samples per window.
    windows : int
        Windows in the recording.
    started_at : datetime
        Time of its first sample.
    keyphasor : str
        Its once-per-revolution channel ("": none; then ``speed``).
    speed : float or None
        Shaft speed given for a recording without a keyphasor, rad/s.
    channels : tuple of str
        The probes' channels, in the layout's order.
    """

    recording: Recording
    sample_rate: float
    size: int
    windows: int
    started_at: dt.datetime
    keyphasor: str = "keyphasor"
    speed: float | None = None
    channels: tuple[str, ...] = ()

    def blocks(self, start: int = 0) -> Iterator[tuple[int, np.ndarray]]:
        """Windows of probe outputs with the keyphasor as the last column, from window ``start``:
        the recording's channel, or without one, one-sample marks at every revolution of the given
        speed counted from the first sample (the 1X phases are then against the recording's
        start, not a mark on the shaft)."""
        layout_columns = list(self.channels)
        if self.keyphasor:
            yield from self.recording.blocks([*layout_columns, self.keyphasor], size=self.size, start=start * self.size)
            return
        assert self.speed is not None
        step = self.speed / (2 * math.pi) / self.sample_rate  # revolutions a sample
        for first, block in self.recording.blocks(layout_columns, size=self.size, start=start * self.size):
            turns = (first + np.arange(block.shape[0])) * step
            marks = np.floor(turns) != np.floor(turns - step)
            yield first, np.column_stack([block, np.where(marks, 5.0, 0.0)])

    @property
    def duration(self) -> float:
        """Length of the recording, s."""
        return self.recording.samples / self.sample_rate


@dataclass(frozen=True)
class RejectedWindow:
    """A window stored as not acceptable instead of identified.

    Attributes
    ----------
    window : int
        Its number in the recording.
    time : datetime
        Time of its first sample.
    reason : str
        Why (:data:`~shaftline.monitor.processing.REJECTED`).
    invalid_share : float
        Share of its probe samples that were NaN or beyond range.
    """

    window: int
    time: dt.datetime
    reason: str
    invalid_share: float


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
    masked : int
        Probe samples of the windows of this run that were NaN or beyond their probe's range,
        masked and filled by interpolation along time.
    samples : int
        Probe samples of the windows of this run.
    rejected : tuple of RejectedWindow
        Windows of the recording in the store (this run's and earlier ones') that were not
        identified: flagged there with the reason, left out of the trends.
    last : WindowResult or None
        The last window this run identified (for the report's figures), None when it
        identified none.
    last_window : int
        Its number (-1 without one).
    """

    recording: StoredRecording
    windows: int
    written: int
    masked: int = 0
    samples: int = 0
    rejected: tuple[RejectedWindow, ...] = ()
    last: WindowResult | None = field(default=None, repr=False, compare=False)
    last_window: int = -1


@dataclass(frozen=True, eq=False)
class SlowRoll:
    """The runout of every probe measured on a slow-roll recording.

    Attributes
    ----------
    name : str
        The recording's file name.
    content_hash : str
        SHA-256 of its bytes.
    speed : float
        Mean shaft speed over its whole revolutions, rad/s.
    revolutions : int
        Whole revolutions averaged.
    profile : ndarray (bins, channels)
        Runout of each probe against the keyphasor's shaft phase, mean removed, m
        (:func:`~shaftline.monitor.orbits.runout_profile`).
    masked : int
        Probe samples that were NaN or beyond range, masked and filled.
    channels : tuple of str
        The probes' channels, in the order of the profile's columns.
    source : str
        Where the runout comes from: ``"recording"`` (a slow-roll recording), ``"slow windows"``
        (the windows of a recording below ``slow_roll_speed``; then ``name`` and ``content_hash``
        are that recording's) or ``"table"`` (the case's runout table; ``content_hash`` its
        :meth:`~shaftline.monitor.study.RunoutTable.digest`, no speed).
    windows : int
        Windows averaged (``"slow windows"``).
    """

    name: str
    content_hash: str
    speed: float
    revolutions: int
    profile: np.ndarray
    masked: int = 0
    channels: tuple[str, ...] = ()
    source: str = "recording"
    windows: int = 0

    @property
    def peak_to_peak(self) -> np.ndarray:
        """Peak-to-peak runout of each probe, m."""
        return np.ptp(self.profile, axis=0)


@dataclass(frozen=True, eq=False)
class IdentifiedRecording:
    """One recording of a ``monitor identify`` run and its trends as stored.

    Attributes
    ----------
    plan : RecordingPlan
    processed : ProcessedRecording
    trends : tuple of SectionTrend
        Smallest film of each section over the recording's windows, with its lambda alarms.
    runout : SlowRoll or None
        The runout subtracted from its windows identified by this run (None: none, or none
        identified with ``slow_roll_speed``).
    replaced : bool
        Its windows stored with other processing settings were deleted and identified again
        (``replace``).
    """

    plan: RecordingPlan
    processed: ProcessedRecording
    trends: tuple[SectionTrend, ...]
    runout: SlowRoll | None = None
    replaced: bool = False


@dataclass(frozen=True, eq=False)
class Identified:
    """What ``monitor identify`` did.

    Attributes
    ----------
    database : str
        The trend database's URL as it may be shown (password hidden).
    recordings : tuple of IdentifiedRecording
    lambda_threshold : float
    alarm_duration : float
        s.
    slow_roll : SlowRoll or None
        The runout subtracted from every window: a slow-roll recording's or the case's table
        (None: neither; with ``slow_roll_speed`` each recording has its own,
        :attr:`IdentifiedRecording.runout`).
    slow_roll_speed : float or None
        rad/s, where the runout of each recording comes from its windows below it.
    """

    database: str
    recordings: tuple[IdentifiedRecording, ...]
    lambda_threshold: float
    alarm_duration: float
    slow_roll: SlowRoll | None = None
    slow_roll_speed: float | None = None
