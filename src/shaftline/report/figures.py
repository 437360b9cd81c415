"""Figures a bearing designer expects: film and pressure maps, profiles, comparisons."""

from __future__ import annotations

from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from shaftline.film.bearing import BearingState  # noqa: E402


def _unwrapped(state: BearingState) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Angles in degrees sorted in [0, 360] with the periodic column repeated, and the order."""
    theta = np.degrees(state.theta) % 360.0
    order = np.argsort(theta)
    theta_sorted = np.append(theta[order], theta[order][0] + 360.0)
    order = np.append(order, order[0])
    return theta_sorted, order, state.z


def film_and_pressure_maps(state: BearingState, title: str, path: Path) -> Path:
    """Unwrapped film-thickness and pressure maps over (theta, z), as seed 004 Fig. 5-1."""
    theta, order, z = _unwrapped(state)
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.2), constrained_layout=True)
    film = state.film[:, order] * 1e6
    pressure = state.pressure[:, order] / 1e6
    for ax, field, label, cmap in (
        (axes[0], film, "film thickness h [µm]", "viridis_r"),
        (axes[1], pressure, "pressure p [MPa]", "inferno"),
    ):
        mesh = ax.contourf(theta, z, field, levels=30, cmap=cmap)
        fig.colorbar(mesh, ax=ax, label=label)
        ax.set_xlabel("bearing angle θ from top, in sense of rotation [deg]")
        ax.set_ylabel("z from aft edge [m]")
        ax.set_xlim(0, 360)
        ax.set_xticks(range(0, 361, 60))
    axes[0].plot(np.degrees(state.min_film_theta), state.min_film_z, "wx", ms=9, mew=2)
    axes[0].set_title(f"h_min = {state.min_film_thickness * 1e6:.1f} µm")
    axes[1].plot(np.degrees(state.max_pressure_theta), state.max_pressure_z, "c+", ms=11, mew=2)
    axes[1].set_title(f"p_max = {state.max_pressure / 1e6:.2f} MPa")
    fig.suptitle(title)
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return path


def circumferential_profile(state: BearingState, title: str, path: Path) -> Path:
    """Pressure and film around the bore in the axial plane of p_max."""
    theta, order, z = _unwrapped(state)
    row = int(np.argmin(np.abs(z - state.max_pressure_z)))
    fig, ax = plt.subplots(figsize=(7.5, 4), constrained_layout=True)
    ax.plot(theta, state.pressure[row, order] / 1e6, color="C3", label="pressure")
    ax.set_xlabel("bearing angle θ [deg]")
    ax.set_ylabel("pressure [MPa]", color="C3")
    ax.set_xlim(0, 360)
    ax.set_xticks(range(0, 361, 60))
    twin = ax.twinx()
    twin.plot(theta, state.film[row, order] * 1e6, color="C0", label="film")
    twin.set_ylabel("film thickness [µm]", color="C0")
    ax.set_title(f"{title}: plane of p_max, z = {z[row]:.3f} m")
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return path


def axial_profiles(state: BearingState, title: str, path: Path) -> Path:
    """Smallest film and largest pressure along the bearing."""
    fig, ax = plt.subplots(figsize=(7.5, 4), constrained_layout=True)
    z = state.z
    ax.plot(z, state.film.min(axis=1) * 1e6, color="C0", marker=".", label="h_min(z)")
    ax.set_xlabel("z from aft edge [m]")
    ax.set_ylabel("smallest film [µm]", color="C0")
    ax.axhline(0.0, color="0.6", lw=0.8)
    twin = ax.twinx()
    twin.plot(z, state.pressure.max(axis=1) / 1e6, color="C3", marker=".", label="p_max(z)")
    twin.set_ylabel("largest pressure [MPa]", color="C3")
    ax.axvline(0.5 * z[-1] + state.load_centre_offset, color="k", ls="--", lw=0.8)
    ax.set_title(f"{title}: along the bearing (dashed: load centre)")
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return path


def comparison(names: list[str], states: list[BearingState], path: Path) -> Path:
    """Bar charts of h_min, p_max and power loss across the variants of a case."""
    fig, axes = plt.subplots(1, 3, figsize=(12, 3.8), constrained_layout=True)
    positions = np.arange(len(names))
    short = [name.split(",")[-1].strip() for name in names]
    data = (
        ([s.min_film_thickness * 1e6 for s in states], "h_min [µm]"),
        ([s.max_pressure / 1e6 for s in states], "p_max [MPa]"),
        ([s.power_loss / 1e3 for s in states], "power loss [kW]"),
    )
    for ax, (values, label) in zip(axes, data, strict=True):
        ax.bar(positions, values, color=[f"C{k}" for k in range(len(names))])
        ax.set_xticks(positions, short, rotation=15)
        ax.set_ylabel(label)
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return path
