"""Orbit descriptors in the vocabulary of machinery monitoring (Bently Nevada practice).

Peak-to-peak motion, the 1X (once per revolution) vector from a keyphasor, the orbit's
equivalent ellipse, "figure-8" detection (seed 001 Sect. 5.2 calls a figure-8 orbit a
sign of boundary or mixed lubrication), slow-roll runout compensation and the averaged
shaft centre line against speed. Inputs are sample arrays; every function is vectorised.

The shaft phase ``phi`` grows by 2 pi per revolution from a keyphasor mark (the once-
per-revolution notch passing its probe). A vector ``A`` at ``phase`` describes the motion
``x = A cos(phi - phase)``: ``phase`` is the lag of the positive peak behind the mark.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from shaftline.errors import InputError


def revolution_marks(keyphasor: np.ndarray, threshold: float | None = None) -> np.ndarray:
    """Sample indices of the keyphasor's rising edges (one per revolution).

    Parameters
    ----------
    keyphasor : ndarray (N,)
        Once-per-revolution channel (V).
    threshold : float, optional
        Level of the edge (default: midway between the channel's smallest and largest value).
    """
    signal = np.asarray(keyphasor, dtype=float)
    if signal.ndim != 1 or signal.size < 2:
        raise InputError("keyphasor", signal.shape, "", "a channel of 2 or more samples")
    level = 0.5 * (signal.min() + signal.max()) if threshold is None else float(threshold)
    above = signal >= level
    return np.flatnonzero(~above[:-1] & above[1:]) + 1


def shaft_phase(samples: int, marks: np.ndarray) -> np.ndarray:
    """Shaft phase at every sample, rad, linear between keyphasor marks (extrapolated at the ends)."""
    marks = np.asarray(marks)
    if marks.size < 2:
        raise InputError("marks", marks.size, "", "at least 2 keyphasor marks (one revolution)")
    index = np.arange(samples, dtype=float)
    turns = np.interp(index, marks, np.arange(marks.size, dtype=float))
    # Outside the marks, carry on at the first and last revolution's speed.
    first = (marks[1] - marks[0]) or 1
    last = (marks[-1] - marks[-2]) or 1
    turns = np.where(index < marks[0], (index - marks[0]) / first, turns)
    turns = np.where(index > marks[-1], marks.size - 1 + (index - marks[-1]) / last, turns)
    return 2.0 * math.pi * turns


def speed_from_marks(marks: np.ndarray, sample_rate: float) -> float:
    """Mean shaft speed over the marks, rev/s."""
    marks = np.asarray(marks)
    if marks.size < 2:
        raise InputError("marks", marks.size, "", "at least 2 keyphasor marks")
    return float((marks.size - 1) * sample_rate / (marks[-1] - marks[0]))


def whole_revolutions(marks: np.ndarray) -> slice:
    """Samples from the first mark to the last: whole revolutions only."""
    marks = np.asarray(marks)
    if marks.size < 2:
        raise InputError("marks", marks.size, "", "at least 2 keyphasor marks")
    return slice(int(marks[0]), int(marks[-1]))


def peak_to_peak(ey: np.ndarray, ez: np.ndarray, directions: int = 180) -> tuple[float, float, float]:
    """Peak-to-peak motion vertically, horizontally and the largest over all directions, m."""
    angle = np.linspace(0.0, math.pi, directions, endpoint=False)
    projected = np.outer(np.cos(angle), ey) + np.outer(np.sin(angle), ez)
    spans = projected.max(axis=1) - projected.min(axis=1)
    return float(np.ptp(ey)), float(np.ptp(ez)), float(spans.max())


@dataclass(frozen=True)
class Vector1X:
    """Once-per-revolution component of a motion.

    Attributes
    ----------
    amplitude : float
        Zero-to-peak amplitude, m.
    phase : float
        Lag of the positive peak behind the keyphasor mark, rad in [0, 2 pi).
    """

    amplitude: float
    phase: float


def harmonic(signal: np.ndarray, phase: np.ndarray, order: int = 1) -> complex:
    """Complex amplitude ``A exp(-i order phase_lag)`` of the ``order`` x component over whole revolutions."""
    signal = np.asarray(signal, dtype=float)
    return complex(2.0 * np.mean((signal - signal.mean()) * np.exp(-1j * order * phase)))


def vector_1x(signal: np.ndarray, phase: np.ndarray) -> Vector1X:
    """1X amplitude and phase lag of ``signal`` with the shaft phase ``phase`` (whole revolutions)."""
    value = harmonic(signal, phase, 1)
    return Vector1X(abs(value), float((-np.angle(value)) % (2.0 * math.pi)))


@dataclass(frozen=True)
class Ellipse:
    """Equivalent ellipse of an orbit (same second moments as the sampled motion).

    Attributes
    ----------
    centre_y, centre_z : float
        Mean position, m.
    major, minor : float
        Semi-axes, m (for a motion ``a cos phi, b sin phi`` sampled evenly in phi, a and b).
    inclination : float
        Angle of the major axis from the vertical towards +z, rad in [0, pi).
    signed_area : float
        Area swept by the orbit, m^2, positive for a counter-clockwise path in the (z, y)
        plane (+z right, +y up).
    enclosed_area : float
        Sum of the unsigned triangle areas about the mean position, m^2.
    figure_eight : bool
        True when the swept area is less than half the enclosed area: loops of opposite
        sense nearly cancel, as in a figure 8 (an ellipse, even a flat one, has them equal).
    """

    centre_y: float
    centre_z: float
    major: float
    minor: float
    inclination: float
    signed_area: float
    enclosed_area: float
    figure_eight: bool


#: Swept over enclosed area below which an orbit is called a figure 8.
FIGURE_EIGHT_RATIO = 0.5


def fit_ellipse(ey: np.ndarray, ez: np.ndarray) -> Ellipse:
    """Equivalent ellipse and figure-8 test of an orbit (pass one averaged revolution, or whole ones).

    The semi-axes are ``sqrt(2 lambda)`` of the covariance eigenvalues ``lambda``: exact for
    an elliptical orbit sampled evenly in shaft phase. The areas come from the shoelace
    formula about the mean position.
    """
    ey = np.asarray(ey, dtype=float)
    ez = np.asarray(ez, dtype=float)
    if ey.shape != ez.shape or ey.ndim != 1 or ey.size < 3:
        raise InputError("ey", ey.size, "samples", "3 or more, as many as ez")
    y = ey - ey.mean()
    z = ez - ez.mean()
    covariance = np.cov(np.vstack([y, z]), bias=True)
    values, vectors = np.linalg.eigh(covariance)
    major_vector = vectors[:, 1]
    inclination = float(math.atan2(major_vector[1], major_vector[0]) % math.pi)
    cross = z * np.roll(y, -1) - np.roll(z, -1) * y
    signed = 0.5 * float(cross.sum())
    enclosed = 0.5 * float(np.abs(cross).sum())
    eight = enclosed > 0.0 and abs(signed) < FIGURE_EIGHT_RATIO * enclosed
    return Ellipse(
        float(ey.mean()),
        float(ez.mean()),
        float(math.sqrt(2.0 * max(values[1], 0.0))),
        float(math.sqrt(2.0 * max(values[0], 0.0))),
        inclination,
        signed,
        enclosed,
        bool(eight),
    )


def phase_bin_sums(signal: np.ndarray, phase: np.ndarray, bins: int = 128) -> tuple[np.ndarray, np.ndarray]:
    """Sums of ``signal`` (N,) or (N, c) in ``bins`` equal steps of shaft phase, (bins, c), and
    the samples in each, (bins,): what :func:`synchronous_average` divides, kept apart so that a
    long recording can be averaged block by block."""
    signal = np.asarray(signal, dtype=float)
    flat = signal.reshape(signal.shape[0], -1)
    index = (np.floor((np.asarray(phase) % (2 * math.pi)) / (2 * math.pi) * bins).astype(int)) % bins
    counts = np.bincount(index, minlength=bins).astype(float)
    sums = np.stack([np.bincount(index, weights=column, minlength=bins) for column in flat.T], axis=1)
    return sums, counts


def binned_average(sums: np.ndarray, counts: np.ndarray) -> np.ndarray:
    """Mean in each phase bin from :func:`phase_bin_sums`, (bins, c); empty bins filled by
    periodic interpolation."""
    bins = counts.size
    filled = counts > 0
    if not filled.any():
        raise InputError("signal", 0, "samples", "at least one sample")
    centres = (np.arange(bins) + 0.5) * 2 * math.pi / bins
    mean = np.empty_like(sums)
    for column in range(sums.shape[1]):
        known = sums[filled, column] / counts[filled]
        mean[:, column] = np.interp(centres, centres[filled], known, period=2 * math.pi)
    return mean


def synchronous_average(signal: np.ndarray, phase: np.ndarray, bins: int = 128) -> np.ndarray:
    """Mean of ``signal`` (N,) or (N, c) in ``bins`` equal steps of shaft phase: one averaged revolution.

    Averaging over revolutions keeps what repeats once per turn (1X, 2X, runout) and
    removes what does not (noise, non-synchronous motion). Empty bins are filled by
    periodic interpolation.
    """
    signal = np.asarray(signal, dtype=float)
    if signal.shape[0] == 0:
        raise InputError("signal", signal.shape[0], "samples", "at least one sample")
    sums, counts = phase_bin_sums(signal, phase, bins)
    return binned_average(sums, counts).reshape((bins,) + signal.shape[1:])


def runout_profile(gaps: np.ndarray, phase: np.ndarray, bins: int = 128) -> np.ndarray:
    """Slow-roll runout of each channel: its synchronous average less its mean, m, (bins, channels).

    Recorded at slow roll, where the film and unbalance move the journal too little to
    show, the once-per-turn pattern of each probe is the surface's (and the probe track's
    electrical) runout, which every later gap carries at the same shaft phase.
    """
    average = synchronous_average(gaps, phase, bins)
    return average - average.mean(axis=0)


def runout_from_table(angles: list[np.ndarray], values: list[np.ndarray], bins: int = 128) -> np.ndarray:
    """Runout profile (bins, channels) from a table per channel of runout against shaft angle (rad from
    the keyphasor mark, rising within one turn): periodic linear interpolation at the bin centres of
    :func:`runout_profile`, less its mean, m."""
    centres = (np.arange(bins) + 0.5) * 2 * math.pi / bins
    columns = [
        np.interp(centres, np.asarray(a, dtype=float), np.asarray(v, dtype=float), period=2 * math.pi)
        for a, v in zip(angles, values, strict=True)
    ]
    profile = np.stack(columns, axis=1)
    return profile - profile.mean(axis=0)


def compensate_runout(gaps: np.ndarray, phase: np.ndarray, profile: np.ndarray) -> np.ndarray:
    """Gaps less the slow-roll runout at their shaft phase (periodic linear interpolation), m."""
    gaps = np.asarray(gaps, dtype=float)
    profile = np.asarray(profile, dtype=float)
    if profile.ndim != 2 or profile.shape[1] != gaps.shape[1]:
        raise InputError("profile", profile.shape, "m", f"(bins, {gaps.shape[1]})")
    bins = profile.shape[0]
    centres = (np.arange(bins) + 0.5) * 2 * math.pi / bins
    wrapped = np.asarray(phase) % (2 * math.pi)
    correction = np.stack(
        [np.interp(wrapped, centres, profile[:, c], period=2 * math.pi) for c in range(profile.shape[1])], axis=1
    )
    return gaps - correction


@dataclass(frozen=True, eq=False)
class CentreLinePoints:
    """Averaged shaft centre line against speed (one point per operating point, sorted by speed).

    Attributes
    ----------
    speed : ndarray (n,)
        Shaft speeds, rev/s.
    ey, ez : ndarray (n,)
        Mean journal centre at each speed, m.
    """

    speed: np.ndarray
    ey: np.ndarray
    ez: np.ndarray


def shaft_centre_line(speeds: np.ndarray, ey: list[np.ndarray], ez: list[np.ndarray]) -> CentreLinePoints:
    """Averaged shaft centre line: the mean centre of each recording, sorted by speed."""
    speeds = np.asarray(speeds, dtype=float)
    if speeds.ndim != 1 or speeds.size != len(ey) or len(ey) != len(ez):
        raise InputError("speeds", speeds.size, "", f"one per recording ({len(ey)})")
    order = np.argsort(speeds)
    mean_y = np.array([np.mean(v) for v in ey])[order]
    mean_z = np.array([np.mean(v) for v in ez])[order]
    return CentreLinePoints(speeds[order], mean_y, mean_z)
