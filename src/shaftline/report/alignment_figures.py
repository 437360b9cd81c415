"""Figures of a shaft alignment: elastic line with bearings, moment and shear, reactions,
influence matrix, jack-up curve."""

from __future__ import annotations

import math
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from shaftline.shaft.alignment import AlignmentModel, ConditionResult, InfluenceMatrix  # noqa: E402
from shaftline.shaft.jackup import JackUpCurve, JackUpFit  # noqa: E402


def elastic_line(model: AlignmentModel, results: list[ConditionResult], path: Path) -> Path:
    """Vertical elastic line per condition with each bearing's position and vertical clearance."""
    fig, ax = plt.subplots(figsize=(11, 4.5), constrained_layout=True)
    for k, result in enumerate(results):
        ax.plot(result.x, result.deflection_y * 1e3, color=f"C{k}", label=result.name)
    for bearing in model.line.bearings:
        aft, fore = bearing.x - 0.5 * bearing.length, bearing.x + 0.5 * bearing.length
        bottom = bearing.offset_y * 1e3
        ax.fill_between([aft, fore], bottom - 0.05, bottom, color="0.35", step="mid")
        if math.isfinite(bearing.vertical_clearance):
            top = (bearing.offset_y + bearing.vertical_clearance) * 1e3
            ax.fill_between([aft, fore], top, top + 0.05, color="0.6")
        ax.annotate(bearing.name, (bearing.x, bottom - 0.08), ha="center", va="top", fontsize=7, rotation=90)
    ax.set_xlabel("x from the aft end [m]")
    ax.set_ylabel("vertical deflection [mm]")
    ax.set_title("Elastic line (bearings at their base offsets: bottom of bore dark, top light)")
    ax.legend(fontsize=8)
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return path


def moment_and_shear(results: list[ConditionResult], path: Path) -> Path:
    fig, (top, bottom) = plt.subplots(2, 1, figsize=(11, 6), sharex=True, constrained_layout=True)
    for k, result in enumerate(results):
        top.plot(result.x, result.moment_y / 1e3, color=f"C{k}", label=result.name)
        bottom.plot(result.x, result.shear_y / 1e3, color=f"C{k}")
    top.set_ylabel("bending moment [kN m]\n(+ sagging)")
    top.axhline(0, color="0.6", lw=0.8)
    bottom.axhline(0, color="0.6", lw=0.8)
    bottom.set_ylabel("shear force [kN]")
    bottom.set_xlabel("x from the aft end [m]")
    top.legend(fontsize=8)
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return path


def reactions(results: list[ConditionResult], path: Path) -> Path:
    names = [b.name for b in results[0].bearings]
    fig, ax = plt.subplots(figsize=(11, 4), constrained_layout=True)
    width = 0.8 / len(results)
    positions = np.arange(len(names))
    for k, result in enumerate(results):
        values = [b.reaction_y / 1e3 for b in result.bearings]
        ax.bar(positions + (k - (len(results) - 1) / 2) * width, values, width, label=result.name)
    ax.axhline(0, color="k", lw=0.8)
    ax.set_xticks(positions, names, rotation=20, ha="right", fontsize=8)
    ax.set_ylabel("reaction [kN]")
    ax.legend(fontsize=8)
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return path


def influence_heatmap(influence: InfluenceMatrix, path: Path) -> Path:
    matrix = influence.matrix * 1e-3 * 1e-3  # kN per mm
    fig, ax = plt.subplots(figsize=(7.5, 6.5), constrained_layout=True)
    limit = np.abs(matrix).max()
    image = ax.imshow(matrix, cmap="RdBu_r", vmin=-limit, vmax=limit)
    fig.colorbar(image, ax=ax, label="reaction change [kN] per mm offset")
    ticks = np.arange(len(influence.names))
    ax.set_xticks(ticks, influence.names, rotation=45, ha="right", fontsize=8)
    ax.set_yticks(ticks, influence.names, fontsize=8)
    ax.set_xlabel("bearing raised")
    ax.set_ylabel("reaction of")
    for i in range(matrix.shape[0]):
        for j in range(matrix.shape[1]):
            ax.text(j, i, f"{matrix[i, j]:.0f}", ha="center", va="center", fontsize=6)
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return path


def jack_curve(curve: JackUpCurve, path: Path, measured=None, fit: JackUpFit | None = None) -> Path:
    fig, ax = plt.subplots(figsize=(7.5, 4.5), constrained_layout=True)
    ax.plot(curve.lifts * 1e3, curve.loads / 1e3, "C0-", label="model")
    ax.axhline(curve.liftoff_load / 1e3, color="C0", ls=":", label=f"lift-off {curve.liftoff_load / 1e3:.1f} kN")
    if measured is not None:
        ax.plot(measured[1] * 1e3, measured[0] / 1e3, "C3o", ms=3, label="measured")
    if fit is not None:
        ax.axhline(fit.knee_load / 1e3, color="C3", ls="--", label=f"measured knee {fit.knee_load / 1e3:.1f} kN")
    ax.set_xlabel("lift at the jack [mm]")
    ax.set_ylabel("jack load [kN]")
    ax.set_title(f"Jack-up of {curve.bearing} (correction factor {curve.correction_factor:.3f})")
    ax.legend(fontsize=8)
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return path
