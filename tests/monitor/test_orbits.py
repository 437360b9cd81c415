"""Orbit descriptors: keyphasor, 1X vector, equivalent ellipse, figure-8, runout, centre line vs speed."""

from __future__ import annotations

import math

import numpy as np
import pytest

from shaftline.errors import InputError
from shaftline.monitor.orbits import (
    compensate_runout,
    fit_ellipse,
    peak_to_peak,
    revolution_marks,
    runout_profile,
    shaft_centre_line,
    shaft_phase,
    speed_from_marks,
    synchronous_average,
    vector_1x,
    whole_revolutions,
)

RATE = 1000.0


def _keyphased(revolutions: float = 10.0, speed: float = 3.0):
    samples = int(revolutions / speed * RATE)
    phase = 2 * math.pi * speed * np.arange(samples) / RATE + 1.0
    keyphasor = np.where(phase % (2 * math.pi) < 0.3, 5.0, 0.0)
    return phase, keyphasor


def test_marks_speed_and_phase_from_a_keyphasor():
    phase, keyphasor = _keyphased()
    marks = revolution_marks(keyphasor)
    assert marks.size == 10
    assert speed_from_marks(marks, RATE) == pytest.approx(3.0, rel=2e-3)  # one sample in 333 per revolution
    measured = shaft_phase(phase.size, marks)
    # Marks fall on the first sample past each notch edge: within one sample (2 pi / 333 rad) of the true phase.
    offset = (measured - (phase - 2 * math.pi * np.floor(phase[marks[0]] / (2 * math.pi)))) % (2 * math.pi)
    assert np.all(np.minimum(offset, 2 * math.pi - offset) < 2 * math.pi * 3.0 / RATE)
    with pytest.raises(InputError, match="^marks = 1"):
        shaft_phase(10, np.array([3]))


def test_1x_vector_amplitude_and_lag():
    phase, keyphasor = _keyphased()
    marks = revolution_marks(keyphasor)
    window = whole_revolutions(marks)
    measured = shaft_phase(phase.size, marks)
    signal = 2e-6 * np.cos(measured - 1.2) + 0.5e-6 * np.cos(2 * measured) + 3e-4
    vector = vector_1x(signal[window], measured[window])
    assert vector.amplitude == pytest.approx(2e-6, rel=1e-9)  # whole revolutions: the 2X and mean drop out
    assert vector.phase == pytest.approx(1.2, abs=1e-9)


def test_ellipse_axes_inclination_and_figure_eight():
    phi = np.linspace(0, 2 * math.pi, 256, endpoint=False)
    # Ellipse 3 x 1 um, major axis 30 deg from the vertical towards +z.
    a, b, tilt = 3e-6, 1e-6, math.radians(30)
    u, v = a * np.cos(phi), b * np.sin(phi)
    ey = -4e-4 + u * math.cos(tilt) - v * math.sin(tilt)
    ez = 1e-4 + u * math.sin(tilt) + v * math.cos(tilt)
    ellipse = fit_ellipse(ey, ez)
    assert (ellipse.major, ellipse.minor) == (pytest.approx(a, rel=1e-9), pytest.approx(b, rel=1e-9))
    assert ellipse.inclination == pytest.approx(tilt, abs=1e-9)
    assert abs(ellipse.signed_area) == pytest.approx(math.pi * a * b, rel=1e-3) and not ellipse.figure_eight
    flat = fit_ellipse(ey + 1e-6 * np.cos(phi), ez + 0.001e-6 * np.sin(phi))
    assert not flat.figure_eight  # a flat ellipse sweeps what it encloses
    eight = fit_ellipse(-4e-4 + 1e-6 * np.sin(2 * phi), 2e-6 * np.sin(phi))
    assert eight.figure_eight and abs(eight.signed_area) < 1e-3 * eight.enclosed_area
    looped = fit_ellipse(2e-6 * np.cos(phi) + 0.5e-6 * np.cos(2 * phi), 2e-6 * np.sin(phi) - 0.5e-6 * np.sin(2 * phi))
    assert not looped.figure_eight  # 1X with a backward 2X: an inner loop, not a figure 8


def test_peak_to_peak():
    phi = np.linspace(0, 2 * math.pi, 3600, endpoint=False)
    ey, ez = 2e-6 * np.cos(phi), 1e-6 * np.sin(phi)
    vertical, horizontal, largest = peak_to_peak(ey + ez, ey - ez)
    # Along 45 deg the motion is 2 sqrt(2) cos + 0 sin: amplitude sqrt(8) um (1 deg steps: cos(0.5 deg) ~ 1 - 4e-5).
    assert largest == pytest.approx(2 * math.sqrt(8) * 1e-6, rel=1e-4)
    assert vertical == pytest.approx(2 * math.hypot(2e-6, 1e-6), rel=1e-5)
    assert horizontal == pytest.approx(vertical, rel=1e-5)


def test_slow_roll_runout_is_removed_at_speed():
    """Runout measured at slow roll and subtracted at speed.

    Bound 15 nm: a keyphasor mark is up to one sample late, 2 pi 3/1000 = 0.019 rad at speed, times the
    runout's largest slope (0.3 + 2 x 0.2 um/rad) is 13 nm; the 128-bin interpolation adds about 1 nm.
    """
    slow_phase, slow_key = _keyphased(revolutions=20, speed=0.25)
    fast_phase, fast_key = _keyphased(revolutions=20, speed=3.0)

    def runout(phase):
        return np.stack([0.3e-6 * np.cos(phase - 0.4), 0.2e-6 * np.cos(2 * phase + 1.0)], axis=1)

    marks = revolution_marks(slow_key)
    window = whole_revolutions(marks)
    slow = 1e-3 + runout(slow_phase)
    profile = runout_profile(slow[window], shaft_phase(slow.shape[0], marks)[window])
    fast_marks = revolution_marks(fast_key)
    motion = 1e-6 * np.cos(fast_phase * 1.37)[:, None]  # non-synchronous motion stays
    fast = 1.2e-3 + motion + runout(fast_phase)
    cleaned = compensate_runout(fast, shaft_phase(fast.shape[0], fast_marks), profile)
    assert np.abs(cleaned - 1.2e-3 - motion).max() < 15e-9
    averaged = synchronous_average(fast, shaft_phase(fast.shape[0], fast_marks), bins=64)
    assert averaged.shape == (64, 2)


def test_shaft_centre_line_sorted_by_speed():
    points = shaft_centre_line(
        np.array([3.0, 1.0, 2.0]), [np.full(4, -3e-4), np.full(4, -5e-4), np.full(4, -4e-4)], [np.zeros(4)] * 3
    )
    assert points.speed.tolist() == [1.0, 2.0, 3.0]
    assert points.ey.tolist() == pytest.approx([-5e-4, -4e-4, -3e-4])
    with pytest.raises(InputError, match="^speeds = 2"):
        shaft_centre_line(np.array([1.0, 2.0]), [np.zeros(2)], [np.zeros(2)])
