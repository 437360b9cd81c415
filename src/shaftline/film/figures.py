"""Figures a bearing designer expects: film and pressure maps, profiles, comparisons.

Each function draws into the axes it is given (``ax=``) and returns them; without axes it
makes a pyplot figure of its own (see :mod:`shaftline.report.plotting`).
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import TYPE_CHECKING, Any

import numpy as np

from shaftline.report.plotting import figure_function, plain

if TYPE_CHECKING:
    from shaftline.film.results import BearingState


def _unwrapped(state: BearingState) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Angles in degrees sorted in [0, 360] with the periodic column repeated, and the order."""
    theta = np.degrees(state.theta) % 360.0
    order = np.argsort(theta)
    theta_sorted = np.append(theta[order], theta[order][0] + 360.0)
    order = np.append(order, order[0])
    return theta_sorted, order, state.z


def _unwrapped_axes(axes: Any) -> None:
    """Axis labels and limits of a map over the unwrapped bore (theta, z)."""
    axes.set_xlabel("bearing angle θ from top, in sense of rotation [deg]")
    axes.set_ylabel("z from aft edge [m]")
    axes.set_xlim(0, 360)
    axes.set_xticks(range(0, 361, 60))


@figure_function(layout=(1, 2), size=(11, 4.2))
def film_and_pressure_maps(state: BearingState, title: str = "", *, ax: Any) -> Any:
    """Unwrapped film-thickness and pressure maps over (theta, z), as seed 004 Fig. 5-1;
    ``ax`` is a pair of axes."""
    theta, order, z = _unwrapped(state)
    film = state.film[:, order] * 1e6
    pressure = state.pressure[:, order] / 1e6
    for axes, field, label, cmap in (
        (ax[0], film, "film thickness h [µm]", "viridis_r"),
        (ax[1], pressure, "pressure p [MPa]", "inferno"),
    ):
        # the filled contours as an image inside the vector figure: a small, sharp SVG
        mesh = axes.contourf(theta, z, field, levels=30, cmap=cmap, rasterized=True)
        axes.figure.colorbar(mesh, ax=axes, label=label)
        _unwrapped_axes(axes)
    ax[0].plot(np.degrees(state.min_film_theta), state.min_film_z, "wx", ms=9, mew=2)
    head = f"{plain(title)}: " if title else ""
    ax[0].set_title(f"{head}h_min = {state.min_film_thickness * 1e6:.3g} µm")
    ax[1].plot(np.degrees(state.max_pressure_theta), state.max_pressure_z, "c+", ms=11, mew=2)
    ax[1].set_title(f"p_max = {state.max_pressure / 1e6:.2f} MPa")
    return ax


@figure_function(size=(7.5, 4))
def circumferential_profile(state: BearingState, title: str = "", *, ax: Any) -> Any:
    """Pressure and film around the bore in the axial plane of p_max."""
    theta, order, z = _unwrapped(state)
    row = int(np.argmin(np.abs(z - state.max_pressure_z)))
    ax.plot(theta, state.pressure[row, order] / 1e6, color="C3", label="pressure")
    ax.set_xlabel("bearing angle θ [deg]")
    ax.set_ylabel("pressure [MPa]", color="C3")
    ax.set_xlim(0, 360)
    ax.set_xticks(range(0, 361, 60))
    twin = ax.twinx()
    twin.plot(theta, state.film[row, order] * 1e6, color="C0", label="film")
    twin.set_ylabel("film thickness [µm]", color="C0")
    ax.set_title(f"{plain(title) + ': ' if title else ''}plane of p_max, z = {z[row]:.3f} m")
    return ax


@figure_function(size=(7.5, 4))
def axial_profiles(state: BearingState, title: str = "", *, ax: Any) -> Any:
    """Smallest film and largest pressure along the bearing, with the load centre."""
    z = state.z
    ax.plot(z, state.film.min(axis=1) * 1e6, color="C0", marker=".", label="h_min(z)")
    ax.set_xlabel("z from aft edge [m]")
    ax.set_ylabel("smallest film [µm]", color="C0")
    ax.axhline(0.0, color="0.6", lw=0.8)
    twin = ax.twinx()
    twin.plot(z, state.pressure.max(axis=1) / 1e6, color="C3", marker=".", label="p_max(z)")
    twin.set_ylabel("largest pressure [MPa]", color="C3")
    ax.axvline(0.5 * z[-1] + state.load_centre_offset, color="k", ls="--", lw=0.8)
    ax.set_title(f"{plain(title) + ': ' if title else ''}along the bearing (dashed: load centre)")
    return ax


@figure_function(layout=(1, 3), size=(12, 3.8))
def comparison(names: Sequence[str], states: Sequence[BearingState], *, ax: Any) -> Any:
    """Bar charts of h_min, p_max and power loss across the variants of a study; ``ax`` is
    three axes."""
    positions = np.arange(len(names))
    data = (
        ([s.min_film_thickness * 1e6 for s in states], "h_min [µm]"),
        ([s.max_pressure / 1e6 for s in states], "p_max [MPa]"),
        ([s.power_loss / 1e3 for s in states], "power loss [kW]"),
    )
    for axes, (values, label) in zip(ax, data, strict=True):
        axes.bar(positions, values, color=[f"C{k}" for k in range(len(names))])
        axes.set_xticks(positions, [plain(name) for name in names], rotation=20, ha="right", fontsize=8)
        axes.set_ylabel(label)
    return ax


@figure_function(layout=(1, 2), size=(11, 4.2))
def contact_maps(state: BearingState, title: str = "", *, ax: Any) -> Any:
    """Unwrapped asperity contact pressure and film-thickness ratio lambda = h/sigma maps of a
    rough film (``state.rough``), with the regime limits 1 and 3 as contours."""
    theta, order, z = _unwrapped(state)
    rough = state.rough
    assert rough is not None
    contact = rough.asperity_pressure[:, order] / 1e6
    ratio = np.minimum(rough.film_ratio[:, order], 10.0)
    # A film below the asperities' mean plane (boundary lubrication, docs/theory.md) has λ < 0:
    # the scale reaches down to it, with λ = 0 drawn too.
    low = min(0.0, float(np.floor(ratio.min())))
    mesh = ax[0].contourf(theta, z, contact, levels=30, cmap="magma", rasterized=True)
    ax[0].figure.colorbar(mesh, ax=ax[0], label="asperity pressure p_a [MPa]")
    # quarter steps from a whole number: the colour bands break at λ = 0, 1 and 3
    mesh = ax[1].contourf(theta, z, ratio, levels=np.arange(low, 10.125, 0.25), cmap="RdYlGn", rasterized=True)
    ax[1].figure.colorbar(mesh, ax=ax[1], label="λ = h/σ (capped at 10)")
    limits = [1.0, 3.0] if low == 0.0 else [0.0, 1.0, 3.0]
    ax[1].contour(theta, z, ratio, levels=limits, colors="k", linewidths=0.8)
    for axes in ax:
        _unwrapped_axes(axes)
    head = f"{plain(title)}: " if title else ""
    ax[0].set_title(f"{head}asperities carry {100 * rough.asperity_load_share:.2g} % of the load")
    shown = ", ".join(f"{v:g}" for v in limits)
    ax[1].set_title(f"λ_min = {rough.min_film_ratio:.2f} ({rough.lubrication_regime}); contours λ = {shown}")
    return ax


@figure_function(layout=(1, 2), size=(11, 4.2))
def liner_maps(state: BearingState, title: str = "", *, ax: Any) -> Any:
    """Unwrapped liner deformation and film (deformation included) maps of a bore with an
    elastic liner (``state.liner``)."""
    theta, order, z = _unwrapped(state)
    liner = state.liner
    assert liner is not None
    mesh = ax[0].contourf(theta, z, liner.deformation[:, order] * 1e6, levels=30, cmap="viridis", rasterized=True)
    ax[0].figure.colorbar(mesh, ax=ax[0], label="liner deformation u [µm]")
    mesh = ax[1].contourf(theta, z, state.film[:, order] * 1e6, levels=30, cmap="Blues", rasterized=True)
    ax[1].figure.colorbar(mesh, ax=ax[1], label="film h with deformation [µm]")
    for axes in ax:
        _unwrapped_axes(axes)
    head = f"{plain(title)}: " if title else ""
    ax[0].set_title(f"{head}liner deformation, max {liner.max_deformation * 1e6:.3g} µm")
    ax[1].set_title(f"film with deformation, h_min {state.min_film_thickness * 1e6:.3g} µm")
    return ax


@figure_function(size=(7, 4.2))
def reynolds_map(state: BearingState, title: str = "", *, ax: Any) -> Any:
    """Unwrapped map of the local Reynolds number ``rho omega R h / mu`` (``state.turbulence``,
    with ``[solver] turbulence`` on or auto)."""
    theta, order, z = _unwrapped(state)
    turbulence = state.turbulence
    assert turbulence is not None
    mesh = ax.contourf(theta, z, turbulence.reynolds_number[:, order], levels=30, cmap="cividis", rasterized=True)
    ax.figure.colorbar(mesh, ax=ax, label="local Reynolds number Re_h [-]")
    _unwrapped_axes(ax)
    head = f"{plain(title)}: " if title else ""
    kind = "turbulent" if turbulence.turbulent else "laminar"
    ax.set_title(f"{head}Re_h max {turbulence.max_reynolds_number:.4g} ({kind} film)")
    return ax


@figure_function(layout=(1, 2), size=(11, 4.2))
def stribeck(curve: Any, title: str = "", *, ax: Any) -> Any:
    """Friction coefficient (Stribeck curve) and h_min against speed, shaded by lubrication
    regime (boundary lambda < 1, mixed 1-3, full film > 3), with the transition speed."""
    from matplotlib.patches import Patch

    rpm = curve.speed * 30.0 / np.pi
    contact = curve.contact.astype(bool)
    stalled = curve.stalled
    ok = ~contact & ~stalled
    # the curve breaks (NaN) at a speed that is no solution rather than bridging it
    ax[0].loglog(
        rpm, np.where(ok, curve.friction_coefficient, np.nan), "o-", color="C0", ms=3, label="friction coefficient"
    )
    ax[1].semilogx(rpm, np.where(ok, curve.min_film_thickness * 1e6, np.nan), "o-", color="C2", ms=3, label="h_min")
    # The same speeds marked on both panels, off the curve: a film at its floor is not an
    # equilibrium's h_min, and a speed that did not converge is no solution at all.
    for axes, values in ((ax[0], curve.friction_coefficient), (ax[1], curve.min_film_thickness * 1e6)):
        if contact.any():
            axes.plot(rpm[contact], values[contact], "x", color="C3", label="contact: load not carried")
        if stalled.any():
            shown = stalled & (values > 0.0) if axes is ax[0] else stalled
            axes.plot(
                rpm[shown], values[shown], "o", mfc="none", color="0.45", ms=4, label="not converged: no solution"
            )
    colours = {"boundary": "#f4cccc", "mixed": "#fff2cc", "full film": "#d9ead3"}
    edges = np.sqrt(rpm[1:] * rpm[:-1])
    lows = np.concatenate([[rpm[0]], edges])
    highs = np.concatenate([edges, [rpm[-1]]])
    for low, high, regime in zip(lows, highs, curve.regime, strict=True):
        if regime is not None:
            for axes in ax:
                axes.axvspan(low, high, color=colours[regime], lw=0, zorder=0)
    if curve.transition_speed is not None:
        label = "asperity share < 1 %" + (" (uncertain: speeds not converged)" if curve.transition_uncertain else "")
        for axes in ax:
            axes.axvline(curve.transition_speed * 30.0 / np.pi, color="k", ls="--", lw=1, label=label)
    ax[0].set_ylabel("friction coefficient [-]")
    ax[1].set_ylabel("h_min [µm]")
    # The regimes' colours in the legend (they were named in a title too long for the axes).
    present = [regime for regime in colours if regime in curve.regime]
    keys = {"boundary": "boundary (λ < 1)", "mixed": "mixed (1-3)", "full film": "full film (λ > 3)"}
    for axes in ax:
        axes.set_xlabel("shaft speed [rpm]")
        handles, labels = axes.get_legend_handles_labels()
        handles += [Patch(color=colours[regime]) for regime in present]
        labels += [keys[regime] for regime in present]
        axes.legend(handles, labels, fontsize=8)
    head = f"{plain(title)}: " if title else ""
    ax[0].set_title(f"{head}Stribeck curve")
    ax[1].set_title("smallest film")
    return ax
