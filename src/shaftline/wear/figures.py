"""Figures of service wear: pitch signal and sliding distance, wear depth over the years,
Weibull plot with confidence bounds.

Each function draws into the axes it is given (``ax=``) and returns them; without axes it
makes a pyplot figure of its own (see :mod:`shaftline.report.plotting`).
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING, Any

import numpy as np

from shaftline.report.plotting import figure_function, plain

if TYPE_CHECKING:
    from shaftline.wear.reliability import WeibullFit
    from shaftline.wear.study import WearResult


@figure_function(layout=(3, 1), size=(11, 9))
def pitch_log(result: WearResult, *, ax: Any) -> Any:
    """Raw and corrected pitch, a two-minute zoom on free sailing, and the cumulative
    sliding distance; ``ax`` is three axes."""
    study = result.study
    log = study.pitch_log
    if log is None or result.corrected is None:
        raise ValueError("the study has no pitch log")
    # tens of thousands of samples per line: drawn as an image inside the vector figure
    ax[0].plot(log.time, log.pitch, color="0.6", lw=0.6, label="measured", rasterized=True)
    ax[0].plot(
        log.time,
        result.corrected,
        color="C0",
        lw=1.0,
        label=f"corrected ({study.dead_band:g} % dead band)",
        rasterized=True,
    )
    if result.mimo_signal is not None:
        ax[0].plot(
            log.time, result.mimo_signal, color="C3", lw=0.5, alpha=0.6, label="active (MIMO) control", rasterized=True
        )
    ax[0].set_ylabel("pitch [% design]")
    ax[0].legend(fontsize=8)
    middle = 0.5 * (log.time[0] + log.time[-1])
    zoom = (log.time > middle - 60) & (log.time < middle + 60)
    ax[1].plot(log.time[zoom], log.pitch[zoom], color="0.6", lw=0.8, label="measured")
    ax[1].step(log.time[zoom], result.corrected[zoom], where="post", color="C0", label="corrected")
    ax[1].set_ylabel("pitch [% design]")
    ax[1].set_title("two minutes in the middle of the log")
    per_percent = study.design_pitch_angle * study.bearing_radius / 100.0
    for signal, label, color in (
        (log.pitch, "measured", "0.6"),
        (result.corrected, "corrected", "C0"),
        (result.mimo_signal, "active (MIMO) control", "C3"),
    ):
        if signal is None:
            continue
        cumulative = np.concatenate([[0.0], np.cumsum(np.abs(np.diff(signal)))]) * per_percent
        ax[2].plot(log.time, cumulative, color=color, label=f"{label}: {cumulative[-1]:.2f} m", rasterized=True)
    ax[2].set_xlabel("time [s]")
    ax[2].set_ylabel("sliding distance [m]")
    ax[2].legend(fontsize=8)
    return ax


@figure_function(size=(8, 4.5))
def depth_over_years(result: WearResult, *, ax: Any) -> Any:
    """Wear depth over the years in service per scenario, with the allowable depth."""
    study = result.study
    years = np.linspace(0, study.service.years, 50)
    per_year = study.service.voyages(1.0)
    for k, scenario in enumerate(result.scenarios):
        depth = study.wear_rate * study.contact_pressure * scenario.distance_per_voyage * per_year * years
        ax.plot(years, depth * 1e6, color=f"C{k}", label=plain(scenario.name))
    ax.axhline(study.allowable_depth * 1e6, color="k", ls="--", label="allowable depth")
    ax.set_xlabel("years in service")
    ax.set_ylabel("wear depth [µm]")
    ax.legend(fontsize=8)
    return ax


@figure_function(layout=(1, 2), size=(11, 4.2))
def weibull(
    fit: WeibullFit, scale: float = 1.0, unit: str = "", marks: Mapping[str, float] | None = None, *, ax: Any
) -> Any:
    """Histogram with the fitted density, and the empirical and fitted CDF with confidence
    bounds; vertical lines at ``marks`` (name: value); values shown times ``scale`` in
    ``unit``. ``ax`` is two axes."""
    left, right = ax
    x_max = max(float(fit.samples.max()), *(marks or {"": 0.0}).values()) * 1.3
    x = np.linspace(fit.samples.min() * 0.3, x_max, 300)
    low, high = fit.cdf_bounds(x)
    left.hist(fit.samples * scale, bins=6, density=True, color="0.8", label="samples")
    density = fit.shape / fit.scale * (x / fit.scale) ** (fit.shape - 1) * np.exp(-((x / fit.scale) ** fit.shape))
    left.plot(x * scale, density / scale, "C0", label=f"Weibull β={fit.shape:.2f}")
    left.set_xlabel(unit)
    left.set_ylabel("probability density")
    left.legend(fontsize=8)
    ordered = np.sort(fit.samples)
    median_rank = (np.arange(1, ordered.size + 1) - 0.3) / (ordered.size + 0.4)
    right.plot(ordered * scale, median_rank, "ko", ms=4, label="samples (median ranks)")
    right.plot(x * scale, fit.cdf(x), "C0", label="fit")
    right.fill_between(x * scale, low, high, color="C0", alpha=0.2, label=f"{fit.confidence:.0%} bounds")
    for k, (name, value) in enumerate((marks or {}).items()):
        right.axvline(value * scale, color=f"C{k + 1}", ls="--", lw=1, label=plain(name))
    right.set_xlabel(unit)
    right.set_ylabel("cumulative probability")
    right.legend(fontsize=7)
    return ax
