"""Figures of a shaft alignment: elastic line with bearings, moment and shear, reactions,
influence matrix, jack-up curve; with film bearings, the journal in its bore and the
comparison of point and film supports.

Each function draws into the axes it is given (``ax=``) and returns them; without axes it
makes a pyplot figure of its own (see :mod:`shaftline.report.plotting`).
"""

from __future__ import annotations

import math
import textwrap
from collections.abc import Sequence
from typing import TYPE_CHECKING, Any

import numpy as np

from shaftline.report.plotting import figure_function, plain

if TYPE_CHECKING:
    from shaftline.shaft.alignment import ConditionResult, InfluenceMatrix
    from shaftline.shaft.coupled import CoupledResult, FilmBearingResult
    from shaftline.shaft.jackup import JackUpCurve, JackUpFit
    from shaftline.shaft.lift_off import LiftOffResult
    from shaftline.shaft.model import ShaftLine


@figure_function(size=(11, 4.5))
def elastic_line(line: ShaftLine, results: Sequence[ConditionResult], *, ax: Any) -> Any:
    """Vertical elastic line per condition, with each bearing where it is in that condition
    (base offset plus the condition's offset): bottom of the bore as a thick bar, top of the
    clearance dashed, in the condition's colour."""
    conditions = {c.name: c for c in line.all_conditions()}
    for k, result in enumerate(results):
        color = f"C{k}"
        ax.plot(result.x, result.deflection_y * 1e3, color=color, label=plain(result.name))
        offsets = conditions[result.name].offsets_y if result.name in conditions else {}
        for bearing in line.bearings:
            aft, fore = bearing.x - 0.5 * bearing.length, bearing.x + 0.5 * bearing.length
            bottom = (bearing.offset_y + offsets.get(bearing.name, 0.0)) * 1e3
            ax.hlines(bottom, aft, fore, color=color, lw=3, alpha=0.7)
            if math.isfinite(bearing.vertical_clearance):
                ax.hlines(bottom + bearing.vertical_clearance * 1e3, aft, fore, color=color, lw=1.2, ls="--")
    for bearing in line.bearings:  # names along the bottom edge of the axes, clear of the lines' labels
        ax.annotate(
            plain(bearing.name),
            (bearing.x, 0.02),
            xycoords=("data", "axes fraction"),
            ha="center",
            va="bottom",
            fontsize=7,
            rotation=90,
            color="0.3",
        )
    ax.set_xlabel("x from the aft end [m]")
    ax.set_ylabel("vertical deflection [mm]")
    ax.set_title("Elastic line; bearings in each condition: bottom of the bore (bar), top of the clearance (dashed)")
    ax.legend(fontsize=8)
    return ax


@figure_function(layout=(2, 1), size=(11, 6), sharex=True)
def moment_and_shear(results: Sequence[ConditionResult], *, ax: Any) -> Any:
    """Bending moment (top) and shear force (bottom) along the line per condition; ``ax``
    is two axes."""
    top, bottom = ax
    for k, result in enumerate(results):
        top.plot(result.x, result.moment_y / 1e3, color=f"C{k}", label=plain(result.name))
        bottom.plot(result.x, result.shear_y / 1e3, color=f"C{k}")
    top.set_ylabel("bending moment [kN m]\n(+ sagging)")
    top.axhline(0, color="0.6", lw=0.8)
    bottom.axhline(0, color="0.6", lw=0.8)
    bottom.set_ylabel("shear force [kN]")
    bottom.set_xlabel("x from the aft end [m]")
    top.legend(fontsize=8)
    return ax


@figure_function(size=(11, 4))
def reactions(results: Sequence[ConditionResult], *, ax: Any) -> Any:
    """Vertical bearing reactions per condition."""
    names = [plain(b.name) for b in results[0].bearings]
    width = 0.8 / len(results)
    positions = np.arange(len(names))
    for k, result in enumerate(results):
        values = [b.reaction_y / 1e3 for b in result.bearings]
        ax.bar(positions + (k - (len(results) - 1) / 2) * width, values, width, label=plain(result.name))
    ax.axhline(0, color="k", lw=0.8)
    ax.set_xticks(positions, names, rotation=20, ha="right", fontsize=8)
    ax.set_ylabel("reaction [kN]")
    ax.legend(fontsize=8)
    return ax


@figure_function(size=(7.5, 6.5))
def influence_heatmap(influence: InfluenceMatrix, *, ax: Any) -> Any:
    """Reaction change per mm of offset of each bearing, titled with which matrix it is (the
    declared supports', or the film-supported line's tangent)."""
    matrix = influence.matrix * 1e-3 * 1e-3  # kN per mm
    limit = np.abs(matrix).max()
    image = ax.imshow(matrix, cmap="RdBu_r", vmin=-limit, vmax=limit)
    ax.set_title("\n".join(textwrap.wrap(influence.label, 60)), fontsize=9)
    ax.figure.colorbar(image, ax=ax, label="reaction change [kN] per mm offset")
    ticks = np.arange(len(influence.names))
    names = [plain(name) for name in influence.names]
    ax.set_xticks(ticks, names, rotation=45, ha="right", fontsize=8)
    ax.set_yticks(ticks, names, fontsize=8)
    ax.set_xlabel("bearing raised")
    ax.set_ylabel("reaction of")
    size = 9 if matrix.shape[0] <= 6 else 7 if matrix.shape[0] <= 10 else 5.5
    for i in range(matrix.shape[0]):
        for j in range(matrix.shape[1]):
            # Light text on the dark ends of the colour map, dark text on the light middle.
            dark = abs(matrix[i, j]) > 0.6 * limit
            value = matrix[i, j]
            text = f"{value:.0f}" if abs(value) >= 100 else f"{value:.3g}"  # no exponents in a cell
            ax.text(j, i, text, ha="center", va="center", fontsize=size, color="w" if dark else "k")
    return ax


@figure_function(size=(7.5, 4.5))
def jack_curve(
    curve: JackUpCurve,
    measured: tuple[np.ndarray, np.ndarray] | None = None,
    fit: JackUpFit | None = None,
    *,
    ax: Any,
) -> Any:
    """Modelled jack load against lift, with the measured curve and its knee where given."""
    ax.plot(curve.lifts * 1e3, curve.loads / 1e3, "C0-", label="model")
    ax.axhline(curve.liftoff_load / 1e3, color="C0", ls=":", label=f"lift-off {curve.liftoff_load / 1e3:.1f} kN")
    if measured is not None:
        ax.plot(measured[1] * 1e3, measured[0] / 1e3, "C3o", ms=3, label="measured")
    if fit is not None:
        ax.axhline(fit.knee_load / 1e3, color="C3", ls="--", label=f"measured knee {fit.knee_load / 1e3:.1f} kN")
    ax.set_xlabel("lift at the jack [mm]")
    ax.set_ylabel("jack load [kN]")
    ax.set_title(f"Jack-up of {plain(curve.bearing)} (correction factor {curve.correction_factor:.3f})")
    ax.legend(fontsize=8)
    return ax


@figure_function(layout=(2, 1), size=(9, 6), sharex=True)
def journal_in_bore(film: FilmBearingResult, *, ax: Any) -> Any:
    """The journal centre line inside its bore, vertical (top) and horizontal (bottom): the
    bore's centre line (slope boring) with the clearance either side, and the journal centre,
    in µm from the bearing's nominal axis; ``ax`` is two axes."""
    # The film averaged round the bore is the radial clearance (cos and sin average out).
    clearance = float(film.state.film.mean())
    top, bottom = ax
    z = film.z
    for axes, centre, bore, label in (
        (top, film.centre_y, film.bore_y, "vertical"),
        (bottom, film.centre_z, film.bore_z, "horizontal (+ starboard)"),
    ):
        axes.fill_between(z, (bore - clearance) * 1e6, (bore + clearance) * 1e6, color="0.92", label="clearance")
        axes.plot(z, bore * 1e6, color="0.5", ls="--", lw=1, label="bore centre line")
        axes.plot(z, centre * 1e6, color="C0", lw=2, label="journal centre")
        axes.set_ylabel(f"{label} [µm]")
    for axes, point, plane in ((top, film.support_point_y, "vertical"), (bottom, film.support_point_z, "horizontal")):
        if math.isfinite(point):
            axes.axvline(0.5 * z[-1] + point, color="C3", ls=":", label="film resultant (support point)")
        elif plane in film.couple_planes:
            axes.text(
                0.01,
                0.95,
                "film carries a couple: resultant outside the bearing",
                transform=axes.transAxes,
                va="top",
                fontsize=8,
                color="C3",
            )
    # h_min to 3 significant digits (a film at its floor, 0.03 µm, read "0.0 µm"); a grounded
    # film's line is the last one reached, not an equilibrium: the title says so.
    grounded = " (at its floor: solved as contact)" if film.contact else ""
    support = (
        f"vertical support point {film.support_point_y * 1e3:+.0f} mm from mid-length"
        if math.isfinite(film.support_point_y)
        else "vertical resultant outside the bearing (a couple)"
    )
    if "horizontal" in film.couple_planes:
        support += "; horizontal: a couple"
    top.set_title(
        f"{plain(film.name)}: journal in the bore{grounded}; h_min {film.state.min_film_thickness * 1e6:.3g} µm, "
        + support,
        fontsize=9,
    )
    top.legend(fontsize=7, loc="best")
    bottom.set_xlabel("z from the aft edge [m]")
    return ax


def _grounded(coupled: CoupledResult, name: str) -> bool:
    """True for a film bearing of ``coupled`` that fell back to contact at its bore."""
    return any(f.name == name and f.contact for f in coupled.films)


@figure_function(layout=(1, 2), size=(12, 4.2))
def point_vs_film(coupled: CoupledResult, *, ax: Any) -> Any:
    """Point supports (the bearings as declared) against film supports: vertical reactions (left)
    and the relative slope of the shaft across each bearing (right); ``ax`` is two axes. A film
    bearing that fell back to contact is drawn apart (hatched, "film at its floor: contact at
    the bore"): its bar is the contact solution's, not a film's."""
    left, right = ax
    names = [plain(b.name) for b in coupled.condition.bearings]
    positions = np.arange(len(names))
    grounded = np.array([_grounded(coupled, b.name) for b in coupled.condition.bearings], dtype=bool)
    for axes, key, scale, label in (
        (left, "reaction_y", 1e-3, "reaction [kN]"),
        (right, "relative_slope", 1e3, "relative slope [mrad]"),
    ):
        point = [getattr(b, key) * scale for b in coupled.point_supports.bearings]
        film = np.array([getattr(b, key) * scale for b in coupled.condition.bearings])
        axes.bar(positions - 0.2, point, 0.4, label="point supports", color="0.6")
        if not grounded.all():
            axes.bar(positions[~grounded] + 0.2, film[~grounded], 0.4, label="film supports", color="C0")
        if grounded.any():
            axes.bar(
                positions[grounded] + 0.2,
                film[grounded],
                0.4,
                label="film at its floor: contact at the bore",
                color="C3",
                hatch="//",
            )
        axes.axhline(0, color="k", lw=0.8)
        axes.set_xticks(positions, names, rotation=20, ha="right", fontsize=8)
        axes.set_ylabel(label)
    left.set_title(f"Point supports vs film supports: {plain(coupled.condition.name)}")
    left.legend(fontsize=8)
    return ax


@figure_function(size=(8.0, 4.5))
def lift_off_curve(result: LiftOffResult, *, ax: Any) -> Any:
    """Smallest film against shaft speed per film bearing (the lift-off curve), with the
    limit and the minimum speed; contact (the film at its floor) as open markers."""
    rpm = result.speeds * 30.0 / math.pi
    for k, name in enumerate(result.names):
        color = f"C{k}"
        hmin = result.min_film[k] * 1e6
        ax.plot(rpm, hmin, color=color, marker=".", label=plain(name))
        touching = result.contact[k]
        if touching.any():
            ax.plot(rpm[touching], hmin[touching], ls="none", marker="o", mfc="none", color=color)
    ax.axhline(result.limit * 1e6, color="0.4", ls="--", lw=1.0, label=f"limit {result.limit * 1e6:.3g} µm")
    if math.isfinite(result.speed):
        minimum = result.speed * 30.0 / math.pi
        ax.axvline(minimum, color="C3", ls=":", lw=1.2, label=f"minimum speed {minimum:.3g} rpm")
    ax.set_xlabel("shaft speed [rpm]")
    ax.set_ylabel("smallest film h_min [µm]")
    ax.set_title("Lift-off curve: smallest film of each film bearing against speed")
    ax.set_ylim(bottom=0.0)
    ax.legend(fontsize=8)
    return ax
