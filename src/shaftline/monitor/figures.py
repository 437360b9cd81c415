"""Figures of the film monitor in the vocabulary monitoring engineers use (Bently Nevada).

The orbit of a section inside its clearance circle, the averaged shaft centre line against
speed, the film round a section (polar), the unwrapped full-bearing film map with the regime
contours, and h_min along the bearing with the regime bands. Each function draws into the
axes it is given (``ax=``) and returns them; without axes it makes a pyplot figure of its
own (see :mod:`shaftline.report.plotting`). Angles are drawn as bearing angles from the top,
clockwise on the page as in seed 001 (Sect. 5.1); lengths in µm and mm.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import TYPE_CHECKING, Any

import numpy as np

from shaftline.monitor.regimes import thresholds
from shaftline.report.plotting import figure_function, plain

if TYPE_CHECKING:
    from shaftline.monitor.identification import SectionOrbit
    from shaftline.monitor.orbits import CentreLinePoints
    from shaftline.monitor.probes import ProbeLayout
    from shaftline.monitor.trends import CentreLine as TrendCentreLine
    from shaftline.monitor.trends import SectionTrend

MICRO = 1e6
#: Colours of the regime bands: boundary, mixed, hydrodynamic.
REGIME_COLOURS = ("C3", "C1", "C2")


def _page(ey: np.ndarray, ez: np.ndarray, rotation: int) -> tuple[np.ndarray, np.ndarray]:
    """Centre offsets as page coordinates, µm: right is the direction of increasing bearing
    angle at the top (s e_z), up is up."""
    return rotation * np.asarray(ez) * MICRO, np.asarray(ey) * MICRO


@figure_function(layout=(1, 2), size=(10, 4.8))
def orbit(section: SectionOrbit, *, ax: Any) -> Any:
    """Journal-centre orbit inside the clearance circle (left) and enlarged (right), µm."""
    full, zoom = ax
    x, y = _page(section.ey, section.ez, section.rotation)
    mean = (x.mean(), y.mean())
    # At most ~4000 points drawn: more only slow the figure (and bloat its SVG) at this size.
    step = max(1, x.size // 4000)
    x, y = x[::step], y[::step]
    radius = (section.clearance + section.correction) * MICRO
    angle = np.linspace(0, 2 * np.pi, 361)
    full.plot(radius * np.sin(angle), radius * np.cos(angle), "k", lw=0.8, label="clearance circle c + k")
    full.plot(x, y, "C0", lw=0.8, label="orbit")
    full.plot(*mean, "C3+", label="mean centre")
    full.set_aspect("equal")
    full.set_xlabel("horizontal [µm] (towards rising bearing angle)")
    full.set_ylabel("vertical [µm]")
    full.legend(fontsize=8, loc="upper right")
    ratio = float(section.eccentricity_ratio.mean())
    # e/c > 1 reads as impossible unless said: the probes see the journal, which a pressed-in (or
    # worn) liner lets pass the undeformed bore (docs/theory.md Sect. 18)
    beyond = "\n(> 1: the journal stands in the liner)" if ratio > 1.0 else ""
    full.set_title(f"{plain(section.name)}: e/c = {ratio:.3f}{beyond}")
    zoom.plot(x, y, "C0", lw=0.8)
    zoom.plot(*mean, "C3+")
    zoom.set_aspect("equal", adjustable="datalim")
    zoom.set_xlabel("horizontal [µm]")
    film = section.min_film
    zoom.set_title(f"orbit, h_min {film.mean() * MICRO:.2f} µm (mean), {film.min() * MICRO:.2f} µm (lowest)")
    return ax


#: Film at which the polar plot's radius scale turns from linear to logarithmic, µm.
POLAR_REFERENCE = 1.0


def _polar_radius(film_um: np.ndarray) -> np.ndarray:
    """Radius of the polar film plot: log10(1 + h / 1 µm), so that a 2 µm film and a 1 mm one
    both show (a linear radius squeezes the loaded zone into the centre)."""
    return np.log10(1.0 + np.maximum(film_um, 0.0) / POLAR_REFERENCE)


@figure_function(size=(6, 6))
def film_polar(
    theta: np.ndarray,
    film: np.ndarray,
    layout: ProbeLayout,
    *,
    label: str = "",
    smallest: np.ndarray | None = None,
    ax: Any,
) -> Any:
    """Film round a section as a polar curve (0 deg at the top, clockwise; radius
    log10(1 + h / 1 µm) with rings at 1, 10, 100, 1000 µm), with the circles of the regime
    thresholds. ``film`` is (m,) or (N, m): drawn as its mean and, for samples, its smallest;
    ``smallest`` (m,): the smallest film over the samples where ``film`` is already their mean."""
    theta = np.asarray(theta, dtype=float)
    film = np.atleast_2d(np.asarray(film, dtype=float)) * MICRO
    low = None if smallest is None else np.asarray(smallest, dtype=float) * MICRO
    closed = np.append(theta, theta[0] + 2 * np.pi)

    def curve(values: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        radius = _polar_radius(np.append(values, values[0]))
        return radius * np.sin(closed), radius * np.cos(closed)

    angle = np.linspace(0, 2 * np.pi, 361)
    ax.plot(*curve(film.mean(axis=0)), "C0", label=plain(label) or "mean film")
    if low is None and film.shape[0] > 1:
        low = film.min(axis=0)
    if low is not None:
        ax.plot(*curve(low), "C0", lw=0.5, ls=":", label="smallest")
    for level, name, colour in zip(thresholds(layout), ("λ = 1", "λ = 3"), REGIME_COLOURS, strict=False):
        radius = _polar_radius(np.array(level * MICRO))
        ax.plot(radius * np.sin(angle), radius * np.cos(angle), color=colour, lw=0.8, label=name)
    for ring in (1.0, 10.0, 100.0, 1000.0):
        radius = _polar_radius(np.array(ring))
        ax.plot(radius * np.sin(angle), radius * np.cos(angle), color="0.8", lw=0.5, zorder=0)
        ax.annotate(f"{ring:g} µm", (0.0, float(radius)), fontsize=7, color="0.5", ha="center")
    ax.set_aspect("equal")
    ax.set_xticks([])
    ax.set_yticks([])
    label_text = "film round the section (0 deg at the top, clockwise; radius log10(1 + h / 1 µm))"
    if np.any(film <= 0.0) or (low is not None and np.any(low <= 0.0)):
        # probes in the housing read a negative film where the journal has pressed the liner in
        label_text += "\nfilms ≤ 0 at the centre: the journal stands in the liner (negative film)"
    ax.set_xlabel(label_text)
    ax.legend(fontsize=8, loc="lower right")
    return ax


@figure_function(size=(10, 4.5))
def film_map(theta: np.ndarray, z: np.ndarray, film: np.ndarray, layout: ProbeLayout, *, ax: Any) -> Any:
    """Unwrapped full-bearing film h(theta, z), µm (log colour scale), with the regime contours.

    ``film`` is (nz, nt) at stations ``z`` (m from the loaded end) and angles ``theta`` (rad).
    """
    from matplotlib.colors import LogNorm

    film = np.asarray(film, dtype=float) * MICRO
    degrees = np.degrees(np.asarray(theta, dtype=float))
    positive = np.clip(film, 0.1, None)
    # Rasterised: as vector paths the cells of a fine map make a slow, huge SVG.
    mesh = ax.pcolormesh(degrees, np.asarray(z) * 1e3, positive, shading="nearest", norm=LogNorm(), rasterized=True)
    ax.figure.colorbar(mesh, ax=ax, label="film [µm]")
    levels = [level * MICRO for level in thresholds(layout)]
    contours = ax.contour(degrees, np.asarray(z) * 1e3, film, levels=levels, colors=["w", "k"], linewidths=1.0)
    ax.clabel(contours, fmt={levels[0]: "λ = 1", levels[1]: "λ = 3"}, fontsize=8)
    if film.min() < 0.0 < film.max():
        # the log scale cannot show a negative film (the journal pressed into the liner): hatch it
        ax.contourf(degrees, np.asarray(z) * 1e3, film, levels=[film.min(), 0.0], colors="none", hatches=["///"])
        zero = ax.contour(degrees, np.asarray(z) * 1e3, film, levels=[0.0], colors="r", linewidths=1.0)
        ax.clabel(zero, fmt={0.0: "h = 0"}, fontsize=8)
    for position in layout.positions:
        ax.axhline(position * 1e3, color="w", lw=0.5, ls="--")
    ax.set_xlabel("bearing angle [deg] (0 = top, in the direction of rotation)")
    ax.set_ylabel("from the loaded end [mm]")
    return ax


@figure_function(size=(9, 4.5))
def min_film_along(z: np.ndarray, min_films: dict[str, np.ndarray], layout: ProbeLayout, *, ax: Any) -> Any:
    """Smallest film along the bearing (one curve per operating point), µm, on the regime bands.

    ``min_films`` maps a label (a speed) to h_min at stations ``z`` (m from the loaded end).
    """
    z_mm = np.asarray(z) * 1e3
    low, high = (level * MICRO for level in thresholds(layout))
    values = [np.asarray(v, dtype=float) * MICRO for v in min_films.values()]
    bottom = min([0.0] + [float(v.min()) for v in values])
    top = max([1.5 * high] + [1.1 * float(v.max()) for v in values])
    ax.axhspan(bottom, low, color=REGIME_COLOURS[0], alpha=0.15, label="boundary")
    ax.axhspan(low, high, color=REGIME_COLOURS[1], alpha=0.15, label="mixed")
    ax.axhspan(high, top, color=REGIME_COLOURS[2], alpha=0.1, label="hydrodynamic")
    for k, (label, curve) in enumerate(zip(min_films, values, strict=True)):
        ax.plot(z_mm, curve, f"C{k % 10}", label=plain(label))
    for position in layout.positions:
        ax.axvline(position * 1e3, color="k", lw=0.5, ls="--")
    if bottom < 0.0:
        # below it the journal stands in the liner (the probes' film, docs/theory.md Sect. 18)
        ax.axhline(0.0, color="r", lw=0.8, label="h = 0")
    ax.set_xlim(z_mm[0], z_mm[-1])
    ax.set_ylim(bottom, top)
    ax.set_xlabel("from the loaded end [mm] (dashed: probe sections)")
    ax.set_ylabel("h_min [µm]")
    ax.legend(fontsize=8, ncol=2)
    return ax


@figure_function(layout=(1, 2), size=(10, 4.8))
def centre_line_vs_speed(
    points: CentreLinePoints, clearance: float, rotation: int = 1, section: str = "", *, ax: Any
) -> Any:
    """Averaged shaft centre line: the mean journal centre at each speed in the clearance circle
    (left) and enlarged (right), µm; ``section`` names the measurement section in the titles."""
    full, zoom = ax
    x, y = _page(points.ey, points.ez, rotation)
    angle = np.linspace(0, 2 * np.pi, 361)
    radius = clearance * MICRO
    full.plot(radius * np.sin(angle), radius * np.cos(angle), "k", lw=0.8, label="clearance circle")
    for axes in (full, zoom):
        axes.plot(x, y, "C0o-", ms=4, label="centre at each speed")
        axes.set_xlabel("horizontal [µm]")
    for xi, yi, speed in zip(x, y, points.speed, strict=True):
        zoom.annotate(f"{speed * 60:.0f} rpm", (xi, yi), fontsize=7, textcoords="offset points", xytext=(4, 4))
    full.set_aspect("equal")
    full.set_ylabel("vertical [µm]")
    full.legend(fontsize=8)
    zoom.set_aspect("equal", adjustable="datalim")
    zoom.xaxis.set_major_locator(_few_ticks())  # an equal-aspect zoom widens the x range: labels overlap
    zoom.set_ylabel("vertical [µm]")
    where = f", section {plain(section)}" if section else ""
    full.set_title(f"clearance circle{where}")
    zoom.set_title(f"averaged shaft centre line{where}")
    return ax


@figure_function(size=(10, 5))
def trend(
    trends: Sequence[SectionTrend], thresholds_m: tuple[float, float] | None = None, fit: bool = True, *, ax: Any
) -> Any:
    """Trend of the smallest film of each section against time, µm: the lambda alarm stretches
    shaded, the fitted straight line of the bearing's smallest film carried on to its limit
    (the projected crossing date marked; not with ``fit`` False), and the regime thresholds where
    known."""
    top = 0.0
    bottom = 0.0
    marked = False
    for k, item in enumerate(trends):
        film = np.asarray(item.min_film) * MICRO
        style = "k-" if item.section == "bearing" else f"C{k % 10}-"
        ax.plot(
            item.times,
            film,
            style,
            lw=1.0 if item.section != "bearing" else 1.4,
            marker=".",
            ms=3,
            label=plain("smallest along the bearing" if item.section == "bearing" else item.section),
        )
        top = max(top, float(np.nanmax(film)) if np.isfinite(film).any() else 0.0)
        bottom = min(bottom, float(np.nanmin(film)) if np.isfinite(film).any() else 0.0)
        for alarm in item.alarms:
            ax.axvspan(alarm.start, alarm.end, color="C3", alpha=0.2, label=None if marked else "lambda alarm")
            marked = True
    whole = next((item for item in trends if item.section == "bearing"), trends[-1] if trends else None)
    if fit and whole is not None and whole.crossing is not None and whole.times:
        start, end = whole.times[0], whole.times[-1]
        crossing = whole.crossing
        stop = crossing.crossing if crossing.crossing is not None and crossing.crossing > end else end
        days = np.array([0.0, (stop - start).total_seconds() / 86400.0])
        last = (end - start).total_seconds() / 86400.0
        line = (crossing.value_now + crossing.slope * (days - last)) * MICRO
        ax.plot([start, stop], line, "k--", lw=0.8, label="fitted trend")
        ax.axhline(whole.limit * MICRO, color="C3", lw=0.8, ls=":", label=f"limit {whole.limit * MICRO:.2f} µm")
        if crossing.crossing is not None:
            past = crossing.value_now <= whole.limit
            when = f"{crossing.crossing:%Y-%m-%d %H:%M}"
            label = "trend at or below the limit now" if past else f"projected crossing {when}"
            ax.plot([crossing.crossing], [whole.limit * MICRO], "C3v", ms=8, label=label)
    if thresholds_m is not None:
        low, high = (level * MICRO for level in thresholds_m)
        ax.axhline(low, color=REGIME_COLOURS[0], lw=0.6, ls="-.", label=f"boundary below {low:.2f} µm")
        ax.axhline(high, color=REGIME_COLOURS[2], lw=0.6, ls="-.", label=f"hydrodynamic above {high:.2f} µm")
        top = max(top, high)
    if bottom < 0.0:
        # probes in the housing read a negative film where the journal has pressed the liner in: the axis
        # goes below zero (it stopped at 0, which hid a loaded end in boundary lubrication)
        ax.axhline(0.0, color="k", lw=0.5)
    ax.set_ylim(bottom=1.1 * bottom, top=max(1.1 * top, 1.0))
    ax.set_ylabel("h_min [µm]")
    ax.set_xlabel("time (UTC)" + ("; shaded: lambda alarms" if marked else ""))
    ax.xaxis.set_major_formatter(_time_axis(ax.xaxis.get_major_locator()))
    ax.legend(fontsize=7, ncol=2)
    return ax


def _time_axis(locator: Any) -> Any:
    """Tick labels of a time axis from seconds to years: matplotlib's concise labels, except
    that ticks seconds apart (the windows of one recording) read as clock times, 06:00:02, not
    as bare seconds (02) beside a 06:00 whose minute the reader must infer; the date is the
    offset at the axis' end."""
    import matplotlib.dates as mdates

    clock = "%H:%M:%S.%f"  # trailing zeros of the fraction are dropped by the formatter
    return mdates.ConciseDateFormatter(
        locator,
        formats=["%Y", "%b", "%d", "%H:%M", "%H:%M", clock],
        zero_formats=["", "%Y", "%b", "%b-%d", "%H:%M", clock],
        offset_formats=["", "%Y", "%Y-%m", "%Y-%m-%d", "%Y-%m-%d", "%Y-%m-%d"],
    )


def _few_ticks() -> Any:
    """Five major ticks at most (the zoom of a short centre line: its labels overlap otherwise)."""
    from matplotlib.ticker import MaxNLocator

    return MaxNLocator(5)


@figure_function(layout=(1, 2), size=(10, 4.8))
def centre_line_ratio(lines: Sequence[TrendCentreLine], *, ax: Any) -> Any:
    """Averaged shaft centre line of each section from the stored windows, in eccentricity
    ratio: the mean centre in each speed bin inside the clearance circle e/c = 1 (left) and
    enlarged (right); horizontal towards rising bearing angle, as the orbits."""
    full, zoom = ax
    angle = np.linspace(0, 2 * np.pi, 361)
    full.plot(np.sin(angle), np.cos(angle), "k", lw=0.8, label="clearance circle")
    for k, line in enumerate(lines):
        # position angle = attitude + pi, from the top towards rotation: page x = e sin, y = e cos
        x = -line.eccentricity_ratio * np.sin(line.attitude_angle)
        y = -line.eccentricity_ratio * np.cos(line.attitude_angle)
        for axes in (full, zoom):
            axes.plot(x, y, f"C{k % 10}o-", ms=3, label=plain(line.section))
        for xi, yi, speed in zip(x, y, line.speed, strict=True):
            zoom.annotate(f"{speed * 30 / np.pi:.0f}", (xi, yi), fontsize=6, textcoords="offset points", xytext=(3, 3))
    full.set_aspect("equal")
    full.set_xlabel("horizontal e/c")
    full.set_ylabel("vertical e/c")
    full.legend(fontsize=7)
    zoom.set_aspect("equal", adjustable="datalim")
    zoom.set_xlabel("horizontal e/c (labels: rpm)")
    # an equal-aspect zoom of a short line widens the x range: fewer ticks, or their labels overlap
    zoom.xaxis.set_major_locator(_few_ticks())
    zoom.set_title("averaged shaft centre line against speed")
    return ax
