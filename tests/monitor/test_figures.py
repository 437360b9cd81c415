"""Monitor figures draw what they say: the clearance circle, the regime contours and bands."""

from __future__ import annotations

import math

import numpy as np
import pytest
from matplotlib.figure import Figure

from shaftline.monitor import figures
from shaftline.monitor.identification import SectionOrbit
from shaftline.monitor.orbits import shaft_centre_line
from shaftline.monitor.probes import seed001_layout
from shaftline.monitor.regimes import thresholds


def _orbit() -> SectionOrbit:
    phi = np.linspace(0, 2 * math.pi, 100)
    return SectionOrbit("D1", 0.292, -5e-4 + 2e-6 * np.cos(phi), -1e-4 + 1e-6 * np.sin(phi), 1e-5, 0.55e-3, 1)


def test_orbit_inside_the_clearance_circle():
    axes = Figure().subplots(1, 2)
    figures.orbit(_orbit(), ax=axes)
    circle = axes[0].lines[0].get_xydata()
    assert np.hypot(circle[:, 0], circle[:, 1]) == pytest.approx(560.0)  # c + k in µm
    orbit = axes[0].lines[1].get_xydata()
    assert orbit[:, 1].mean() == pytest.approx(-500.0, abs=0.1)


def test_film_map_contours_are_the_regime_thresholds():
    layout = seed001_layout()
    theta = np.radians(np.arange(0, 360, 10.0))
    z = np.linspace(0, 1.2, 13)
    film = (1e-6 + 10e-6 * z[:, None]) * (1 + 0 * theta[None, :]) + 5e-4 * (1 + np.cos(theta))[None, :]
    ax = Figure().subplots()
    figures.film_map(theta, z, film, layout, ax=ax)
    contour = next(c for c in ax.collections if hasattr(c, "levels"))
    assert list(contour.levels) == pytest.approx([t * 1e6 for t in thresholds(layout)])


def test_negative_films_are_marked_not_hidden():
    """The probes' film is negative where the journal has pressed the liner in (docs/theory.md Sect. 18): the map
    hatches it and draws h = 0, the polar plot says where it put it; a positive film gets neither."""
    layout = seed001_layout()
    theta = np.radians(np.arange(0, 360, 10.0))
    z = np.linspace(0, 1.2, 13)
    pressed = (-5e-6 + 20e-6 * z[:, None]) + 5e-4 * (1 + np.cos(theta))[None, :]
    for film, marked in ((pressed, True), (pressed + 10e-6, False)):
        ax = Figure().subplots()
        figures.film_map(theta, z, film, layout, ax=ax)
        levels = [list(c.levels) for c in ax.collections if hasattr(c, "levels")]
        assert ([0.0] in levels) is marked
        polar = Figure().subplots()
        figures.film_polar(theta, film[0], layout, ax=polar)
        assert ("journal stands in the liner" in polar.get_xlabel()) is marked


def test_min_film_along_has_the_regime_bands():
    layout = seed001_layout()
    z = np.linspace(0, 1.2, 25)
    ax = Figure().subplots()
    figures.min_film_along(z, {"95 rpm": 1e-6 + 8e-6 * z, "175 rpm": 2e-6 + 9e-6 * z}, layout, ax=ax)
    low, high = (t * 1e6 for t in thresholds(layout))
    bands = [patch.get_y() for patch in ax.patches]
    assert bands[1] == pytest.approx(low) and bands[2] == pytest.approx(high)
    assert len(ax.get_lines()) == 2 + len(layout.positions)


def test_polar_film_and_centre_line_vs_speed_draw():
    layout = seed001_layout()
    theta = np.radians(np.arange(0, 360, 15.0))
    ax = Figure().subplots()
    figures.film_polar(theta, np.vstack([5e-6 + 1e-4 * (1 + np.cos(theta))] * 3), layout, label="D1", ax=ax)
    mean_curve = ax.lines[0].get_xydata()
    assert mean_curve[0] == pytest.approx([0.0, math.log10(1 + 205.0)])  # 0 deg at the top: 5 + 200 µm
    assert mean_curve[12] == pytest.approx([0.0, -math.log10(1 + 5.0)])  # 180 deg at the bottom
    points = shaft_centre_line(np.array([1.0, 2.0]), [np.full(3, -5e-4), np.full(3, -4e-4)], [np.zeros(3)] * 2)
    axes = Figure().subplots(1, 2)
    figures.centre_line_vs_speed(points, 0.55e-3, ax=axes)
    assert axes[1].lines[0].get_xydata()[:, 1] == pytest.approx([-500.0, -400.0])


def test_the_centre_line_zoom_keeps_its_tick_labels_apart():
    """The stored centre line of the example (e/c 0.98-0.97 over three speeds): the equal-aspect zoom
    widened its x range and matplotlib put six or more labels of six characters on it (nine in the
    example's report, overlapping); at most five ticks now, on a figure of the report's size."""
    from shaftline.monitor.trends import CentreLine

    speed = np.array([135.0, 175.0, 215.0]) * math.pi / 30
    lines = [CentreLine("D1", speed, np.array([0.993, 0.991, 0.989]), np.array([2.99, 2.96, 2.94]), np.ones(3))]
    figure = Figure(figsize=(10, 4.8), layout="constrained")
    axes = figure.subplots(1, 2)
    figures.centre_line_ratio(lines, ax=axes)
    figure.draw_without_rendering()  # the layout, as the report's drawing, fixes the limits
    low, high = axes[1].get_xlim()
    shown = [t for t in axes[1].get_xticks() if low <= t <= high]
    assert 2 <= len(shown) <= 5


@pytest.mark.parametrize(
    ("step", "pattern", "offset"),
    [
        (2.0, r"06:00:\d\d", "2026-11-02"),  # the windows of one recording: clock times, not bare seconds
        (0.05, r"0[56]:\d\d:\d\d\.\d+", "2026-11-02"),  # windows of 0.05 s (the case's shortest)
        (20 * 60.0, r"\d\d:\d\d", "2026-11-02"),  # a stretch of minutes: hours and minutes, as before
    ],
)
def test_trend_time_axis_reads_as_clock_times(step, pattern, offset):
    """The trend over seconds labelled its ticks 06:00, 01, 02, ... (bare seconds): every label is
    now a clock time to the tick's resolution, the date the offset at the axis' end."""
    import datetime as dt
    import re

    from shaftline.monitor.trends import SectionTrend

    start = dt.datetime(2026, 11, 2, 6, 0, tzinfo=dt.UTC)
    times = [start + dt.timedelta(seconds=step * k) for k in range(4)]
    trend = SectionTrend("bearing", times, np.full(4, 2e-6), np.full(4, 0.9), np.ones(4), (), 2.2e-6, None)
    ax = Figure().subplots()
    figures.trend([trend], ax=ax)
    ax.figure.canvas.draw()
    labels = [label.get_text() for label in ax.get_xticklabels() if label.get_text()]
    assert len(labels) >= 3 and all(re.fullmatch(pattern, label) for label in labels), labels
    assert ax.xaxis.get_major_formatter().get_offset() == offset


def test_the_trend_shows_negative_films():
    """The example's loaded section (D1) and the bearing's smallest film are negative at every speed (the journal
    pressed into the liner): the trend's axis stopped at 0 and hid both, leaving D3 and the top of D2. Every point
    drawn now lies inside the axis, with the h = 0 line."""
    import datetime as dt

    from shaftline.monitor.trends import SectionTrend

    start = dt.datetime(2026, 11, 2, 6, 0, tzinfo=dt.UTC)
    times = [start + dt.timedelta(seconds=8.0 * k) for k in range(4)]
    films = {"D1": np.array([-9.7, -7.9, -3.1, -1.7]) * 1e-6, "bearing": np.array([-24.3, -22.0, -17.0, -16.0]) * 1e-6}
    trends = [
        SectionTrend(name, times, film, film / 2.24e-6, np.ones(4), (), 2.24e-6, None) for name, film in films.items()
    ]
    ax = Figure().subplots()
    figures.trend(trends, (2.24e-6, 6.71e-6), ax=ax)
    low, high = ax.get_ylim()
    assert low < -24.3 and high > 6.71
    assert any(np.all(np.asarray(line.get_ydata()) == 0.0) for line in ax.lines)


def test_a_journal_in_the_liner_is_said_on_the_orbit_and_the_film_along():
    """e/c > 1 and h_min < 0 (the probes see the journal past the undeformed bore where the liner is pressed in)
    read as impossible unless said: the orbit's title says it and h_min along the bearing draws h = 0; an orbit
    inside the clearance and positive films get neither. The centre line names its section."""
    layout = seed001_layout()
    phi = np.linspace(0, 2 * math.pi, 100)
    inside = _orbit()
    beyond = SectionOrbit("D1", 0.292, -5.7e-4 + 1e-6 * np.cos(phi), 1e-6 * np.sin(phi), 1e-5, 0.55e-3, 1)
    for orbit, said in ((inside, False), (beyond, True)):
        axes = Figure().subplots(1, 2)
        figures.orbit(orbit, ax=axes)
        assert ("journal stands in the liner" in axes[0].get_title()) is said
    z = np.linspace(0, 1.2, 25)
    for films, drawn in (({"35 rpm": 1e-6 + 8e-6 * z}, False), ({"35 rpm": -9e-6 + 20e-6 * z}, True)):
        ax = Figure().subplots()
        figures.min_film_along(z, films, layout, ax=ax)
        assert any(line.get_label() == "h = 0" for line in ax.get_lines()) is drawn
    points = shaft_centre_line(np.array([1.0, 2.0]), [np.full(3, -5e-4), np.full(3, -4e-4)], [np.zeros(3)] * 2)
    axes = Figure().subplots(1, 2)
    figures.centre_line_vs_speed(points, 0.55e-3, 1, "D2", ax=axes)
    assert axes[1].get_title().endswith("section D2") and axes[1].get_ylabel() == "vertical [µm]"
