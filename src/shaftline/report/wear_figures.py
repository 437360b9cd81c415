"""Figures of service wear: pitch signal and sliding distance, wear depth over the years,
Weibull plot with confidence bounds."""

from __future__ import annotations

from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from shaftline.wear.reliability import WeibullFit  # noqa: E402


def pitch_log(run, path: Path) -> Path:
    """Raw and corrected pitch (with a zoom on free sailing) and cumulative sliding distance."""
    log, case = run.log, run.case
    fig, axes = plt.subplots(3, 1, figsize=(11, 9), constrained_layout=True)
    axes[0].plot(log.time, log.pitch, color="0.6", lw=0.6, label="measured")
    axes[0].plot(log.time, run.corrected, color="C0", lw=1.0, label=f"corrected ({case.dead_band:g} % dead band)")
    if run.mimo_signal is not None:
        axes[0].plot(log.time, run.mimo_signal, color="C3", lw=0.5, alpha=0.6, label="active (MIMO) control")
    axes[0].set_ylabel("pitch [% design]")
    axes[0].legend(fontsize=8)
    middle = 0.5 * (log.time[0] + log.time[-1])
    zoom = (log.time > middle - 60) & (log.time < middle + 60)
    axes[1].plot(log.time[zoom], log.pitch[zoom], color="0.6", lw=0.8, label="measured")
    axes[1].step(log.time[zoom], run.corrected[zoom], where="post", color="C0", label="corrected")
    axes[1].set_ylabel("pitch [% design]")
    axes[1].set_title("two minutes of free sailing")
    per_percent = case.design_pitch_angle * case.bearing_radius / 100.0
    for signal, label, color in (
        (log.pitch, "measured", "0.6"),
        (run.corrected, "corrected", "C0"),
        (run.mimo_signal, "active (MIMO) control", "C3"),
    ):
        if signal is None:
            continue
        cumulative = np.concatenate([[0.0], np.cumsum(np.abs(np.diff(signal)))]) * per_percent
        axes[2].plot(log.time, cumulative, color=color, label=f"{label}: {cumulative[-1]:.2f} m")
    axes[2].set_xlabel("time [s]")
    axes[2].set_ylabel("sliding distance [m]")
    axes[2].legend(fontsize=8)
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return path


def depth_over_years(run, path: Path) -> Path:
    case = run.case
    years = np.linspace(0, case.service.years, 50)
    per_year = case.service.voyages(1.0)
    fig, ax = plt.subplots(figsize=(8, 4.5), constrained_layout=True)
    for k, scenario in enumerate(run.scenarios):
        depth = case.wear_rate * case.contact_pressure * scenario.distance_per_voyage * per_year * years
        ax.plot(years, depth * 1e6, color=f"C{k}", label=scenario.name)
    ax.axhline(case.allowable_depth * 1e6, color="k", ls="--", label="allowable depth")
    ax.set_xlabel("years in service")
    ax.set_ylabel("wear depth [µm]")
    ax.legend(fontsize=8)
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return path


def weibull(fit: WeibullFit, path: Path, scale: float = 1.0, unit: str = "", marks: dict | None = None) -> Path:
    """Empirical and fitted CDF with confidence bounds; vertical lines at ``marks`` (name: value)."""
    x_max = max(fit.samples.max(), *(marks or {0: 0}).values()) * 1.3
    x = np.linspace(fit.samples.min() * 0.3, x_max, 300)
    low, high = fit.cdf_bounds(x)
    fig, (left, right) = plt.subplots(1, 2, figsize=(11, 4.2), constrained_layout=True)
    left.hist(fit.samples * scale, bins=6, density=True, color="0.8", label="samples")
    density = fit.shape / fit.scale * (x / fit.scale) ** (fit.shape - 1) * np.exp(-((x / fit.scale) ** fit.shape))
    left.plot(x * scale, density / scale, "C0", label=f"Weibull β={fit.shape:.2f}")
    left.set_xlabel(unit)
    left.legend(fontsize=8)
    ordered = np.sort(fit.samples)
    median_rank = (np.arange(1, ordered.size + 1) - 0.3) / (ordered.size + 0.4)
    right.plot(ordered * scale, median_rank, "ko", ms=4, label="samples (median ranks)")
    right.plot(x * scale, fit.cdf(x), "C0", label="fit")
    right.fill_between(x * scale, low, high, color="C0", alpha=0.2, label=f"{fit.confidence:.0%} bounds")
    for k, (name, value) in enumerate((marks or {}).items()):
        right.axvline(value * scale, color=f"C{k + 1}", ls="--", lw=1, label=f"allowable: {name}")
    right.set_xlabel(unit)
    right.set_ylabel("cumulative probability")
    right.legend(fontsize=7)
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return path
