"""Sliding distance of a blade bearing in service, from a pitch log (seed 000 Sect. 6.2-6.4).

A pitch-position signal (percent of design pitch, e.g. 10 Hz) carries measurement noise
that would count as motion. It is cleaned by stepwise-constant fitting with a dead band:
the level holds until the signal leaves the band around it, then jumps to the signal
(0.5 % in the seed, the resolution of the pitch actuation). The total pitch travel
sum |d level| in design pitches gives the sliding distance at the bearing radius:

    S = travel * phi_d * r                                  (Eq. 6.3, phi_d in rad)

projected over an overhaul period: S * voyages/day * days/year * years (Eq. 6.4).
Scenarios: active (MIMO) pitch control as an oscillation superimposed in a window
(Sect. 6.3), and fretting adding 2 d per revolution (Eq. 6.8).
"""

from __future__ import annotations

import itertools
import math
from collections.abc import Iterator
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from shaftline.csvio import read_columns
from shaftline.errors import InputError, require_finite, require_positive


@dataclass(frozen=True, eq=False)
class PitchLog:
    """Time (s) and pitch (% of design pitch)."""

    time: np.ndarray
    pitch: np.ndarray

    def __post_init__(self) -> None:
        time = np.asarray(self.time, dtype=float)
        pitch = np.asarray(self.pitch, dtype=float)
        if time.ndim != 1 or time.size != pitch.size or time.size < 2:
            raise InputError("time", time.size, "samples", "at least 2 (time, pitch) pairs")
        for name, values in (("time", time), ("pitch", pitch)):
            bad = np.flatnonzero(~np.isfinite(values))
            if bad.size:
                raise InputError(f"{name}[{int(bad[0])}]", "NaN", "", "a number")
        steps = np.diff(time)
        if np.any(steps <= 0):
            k = int(np.flatnonzero(steps <= 0)[0]) + 1
            raise InputError(f"time[{k}]", float(time[k]), "s", "times increasing sample to sample")
        typical = float(np.median(steps))
        if np.any(steps > 10 * typical):
            k = int(np.flatnonzero(steps > 10 * typical)[0]) + 1
            raise InputError(
                f"time[{k}]",
                float(time[k]),
                "s",
                f"no gap longer than 10 sampling intervals ({10 * typical:.3g} s)",
            )
        object.__setattr__(self, "time", time)
        object.__setattr__(self, "pitch", pitch)

    @property
    def duration(self) -> float:
        return float(self.time[-1] - self.time[0])


def read_pitch_log(path: str | Path) -> PitchLog:
    """A pitch log from CSV with columns ``time`` (s) and ``pitch`` (% of design pitch);
    an error names the file's row (the header is row 1)."""
    path = Path(path)
    columns = read_columns(path, ["time", "pitch"], "file")
    try:
        return PitchLog(columns["time"], columns["pitch"])
    except InputError as error:
        name, _, index = error.field.rstrip("]").partition("[")
        if not index:
            raise InputError("file", str(path), "", f"{error.allowed} (has {error.value})") from None
        raise InputError(
            f"{path.name}: row {int(index) + 2}, {name}", error.value, error.unit, error.allowed, in_file=True
        ) from None


def stepwise_constant(signal: np.ndarray, dead_band: float) -> np.ndarray:
    """Hold a level until the signal leaves ``level +- dead_band``, then jump to the signal."""
    require_positive("dead_band", dead_band, "%")
    values = np.asarray(signal, dtype=float).tolist()
    # itertools.accumulate runs the recursion in C; the function is one comparison.
    levels: Iterator[float] = itertools.accumulate(values, lambda level, x: x if abs(x - level) > dead_band else level)
    return np.fromiter(levels, dtype=float, count=len(values))


def pitch_travel(signal: np.ndarray) -> float:
    """Total pitch travel, in design pitches (sum of |changes| / 100 for a % signal)."""
    return float(np.abs(np.diff(signal)).sum() / 100.0)


def sliding_distance(travel: float, design_pitch_angle: float, radius: float) -> float:
    """Sliding distance at the bearing radius for a pitch travel in design pitches, m (Eq. 6.3)."""
    require_positive("design_pitch_angle", design_pitch_angle, "rad")
    require_positive("radius", radius, "m")
    return travel * design_pitch_angle * radius


def superimpose_oscillation(
    log: PitchLog, signal: np.ndarray, amplitude: float, frequency: float, start: float, end: float
) -> np.ndarray:
    """Signal with a sine of ``amplitude`` % and ``frequency`` Hz added between ``start`` and ``end`` s."""
    require_positive("amplitude", amplitude, "%")
    require_positive("frequency", frequency, "Hz")
    if not log.time[0] <= start < end <= log.time[-1]:
        raise InputError("end", end, "s", f"start < end within the log [{log.time[0]}, {log.time[-1]}]")
    window = (log.time >= start) & (log.time <= end)
    out = np.array(signal, dtype=float, copy=True)
    out[window] += amplitude * np.sin(2 * np.pi * frequency * (log.time[window] - start))
    return out


def fretting_distance(amplitude: float, speed: float, duration: float) -> float:
    """Sliding from fretting, 2 d per shaft revolution (Eq. 6.8), m (speed in rad/s, duration s)."""
    require_finite("amplitude", amplitude, "m")
    require_positive("speed", speed, "rad/s")
    return 2.0 * amplitude * speed / (2.0 * math.pi) * duration


@dataclass(frozen=True)
class ServiceProfile:
    """How much the ship sails: voyages a day, days a year, years to overhaul."""

    voyages_per_day: float
    days_per_year: float
    years: float

    def __post_init__(self) -> None:
        require_positive("voyages_per_day", self.voyages_per_day)
        if not 0 < self.days_per_year <= 366:
            raise InputError("days_per_year", self.days_per_year, "days", "in (0, 366]")
        require_positive("years", self.years, "years")

    def voyages(self, years: float | None = None) -> float:
        return self.voyages_per_day * self.days_per_year * (self.years if years is None else years)
