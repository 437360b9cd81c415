"""Service wear of a CPP blade bearing: sliding distances per scenario, wear depth over the
years, allowable wear rates and the Weibull probability of exceeding them."""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np
from markupsafe import Markup

from shaftline.cases.wear_schema import WearCase
from shaftline.report import wear_figures
from shaftline.report.html import Section, image, table
from shaftline.wear.archard import MM3_PER_NM, allowable_rate, wear_class
from shaftline.wear.reliability import WeibullFit, fit_weibull
from shaftline.wear.service import (
    PitchLog,
    fretting_distance,
    pitch_travel,
    sliding_distance,
    stepwise_constant,
    superimpose_oscillation,
)


@dataclass(frozen=True)
class Scenario:
    """Sliding per voyage and what it means over the overhaul period.

    Attributes
    ----------
    name : str
    distance_per_voyage, distance_total : float
        m.
    depth_total : float
        Archard depth at the case's wear rate after the overhaul period, m.
    allowable_rate : float
        Rate that would just reach the allowable depth, m^3/(N m).
    years_to_limit : float
        Years until the allowable depth at the case's wear rate.
    exceedance : tuple or None
        P(wear rate > allowable rate): (lower bound, estimate, upper bound) from the Weibull fit.
    """

    name: str
    distance_per_voyage: float
    distance_total: float
    depth_total: float
    allowable_rate: float
    years_to_limit: float
    exceedance: tuple[float, float, float] | None = None


@dataclass(frozen=True)
class WearRun:
    case: WearCase
    log: PitchLog | None
    corrected: np.ndarray | None
    mimo_signal: np.ndarray | None
    travel_raw: float | None
    travel_corrected: float
    scenarios: list[Scenario]
    weibull: WeibullFit | None

    def summary(self) -> dict[str, Any]:
        out: dict[str, Any] = {
            "units": {"distance": "m", "depth": "m", "rate": "m^3/(N m)", "travel": "design pitches"},
            "wear_rate": self.case.wear_rate,
            "wear_class": wear_class(self.case.wear_rate),
            "pitch_travel_raw": self.travel_raw,
            "pitch_travel_corrected": self.travel_corrected,
            "scenarios": [
                {
                    "name": s.name,
                    "distance_per_voyage": s.distance_per_voyage,
                    "distance_total": s.distance_total,
                    "depth_total": s.depth_total,
                    "allowable_rate": s.allowable_rate,
                    "years_to_limit": s.years_to_limit,
                    "exceedance": None
                    if s.exceedance is None
                    else dict(zip(("lower", "estimate", "upper"), s.exceedance, strict=True)),
                }
                for s in self.scenarios
            ],
        }
        if self.weibull is not None:
            out["weibull"] = {
                "shape": self.weibull.shape,
                "scale": self.weibull.scale,
                "shape_interval": self.weibull.interval("shape"),
                "scale_interval": self.weibull.interval("scale"),
                "confidence": self.weibull.confidence,
            }
        return out


def solve_wear(case: WearCase, log: PitchLog | None = None) -> WearRun:
    """Sliding distances (standard control, active control, fretting), depths and probabilities."""
    log = log if log is not None else case.pitch_log
    per_voyage_pitch = case.design_pitch_angle * case.bearing_radius  # m per design pitch of travel
    corrected = mimo_signal = None
    travel_raw = None
    if log is not None:
        corrected = stepwise_constant(log.pitch, case.dead_band)
        travel_raw = pitch_travel(log.pitch)
        travel = pitch_travel(corrected)
    else:
        travel = float(case.pitch_travel_per_voyage)
    standard = sliding_distance(travel, case.design_pitch_angle, case.bearing_radius)
    distances = {"standard control": standard}
    if travel_raw is not None:
        distances["uncorrected signal"] = sliding_distance(travel_raw, case.design_pitch_angle, case.bearing_radius)
    if case.mimo is not None:
        m = case.mimo
        if log is not None:
            mimo_signal = superimpose_oscillation(log, corrected, m["amplitude"], m["frequency"], m["start"], m["end"])
            distances["active (MIMO) control"] = per_voyage_pitch * pitch_travel(mimo_signal)
        else:  # four amplitudes of travel per period
            extra = 4 * m["amplitude"] / 100 * m["frequency"] * (m["end"] - m["start"])
            distances["active (MIMO) control"] = standard + per_voyage_pitch * extra
    if case.fretting is not None:
        f = case.fretting
        distances["standard control with fretting"] = standard + fretting_distance(
            f["amplitude"], f["speed"], case.voyage_duration
        )
    weibull = fit_weibull(case.weibull["rates"], case.weibull["confidence"]) if case.weibull else None
    scenarios = []
    voyages = case.service.voyages()
    per_year = case.service.voyages(1.0)
    for name, distance in distances.items():
        total = distance * voyages
        depth = case.wear_rate * case.contact_pressure * total
        limit = allowable_rate(case.allowable_depth, case.contact_pressure, total)
        years = case.allowable_depth / (case.wear_rate * case.contact_pressure * distance * per_year)
        exceed = weibull.exceedance(limit) if weibull is not None else None
        scenarios.append(Scenario(name, distance, total, depth, limit, years, exceed))
    return WearRun(case, log, corrected, mimo_signal, travel_raw, travel, scenarios, weibull)


def wear_table_rows(run: WearRun) -> tuple[list[str], list[list[str]]]:
    headers = [
        "scenario",
        "sliding per voyage [m]",
        f"sliding in {run.case.service.years:g} years [km]",
        "wear depth [um]",
        "allowable rate [mm3/Nm]",
        "years to limit",
        "P(rate > allowable)",
    ]
    rows = []
    for s in run.scenarios:
        probability = "-"
        if s.exceedance is not None:
            low, mid, high = s.exceedance
            probability = f"{mid:.3g} ({low:.3g} - {high:.3g})"
        rows.append(
            [
                s.name,
                f"{s.distance_per_voyage:.3f}",
                f"{s.distance_total / 1e3:.1f}",
                f"{s.depth_total * 1e6:.0f}",
                f"{s.allowable_rate / MM3_PER_NM:.3g}",
                f"{s.years_to_limit:.1f}",
                probability,
            ]
        )
    return headers, rows


def wear_section(run: WearRun, folder: Path) -> Section:
    figure_dir = folder / "figures"
    figure_dir.mkdir(exist_ok=True)
    headers, rows = wear_table_rows(run)
    c = run.case
    parts = [
        Markup(
            f"<p>Blade bearing radius {c.bearing_radius:.3f} m, design pitch {np.degrees(c.design_pitch_angle):.1f}"
            f" deg, contact pressure {c.contact_pressure / 1e6:.1f} N/mm², specific wear rate "
            f"{c.wear_rate / MM3_PER_NM:.3g} mm³/Nm (wear class {wear_class(c.wear_rate)}), allowable depth "
            f"{c.allowable_depth * 1e6:.0f} µm; {c.service.voyages_per_day:g} voyages a day, "
            f"{c.service.days_per_year:g} days a year, {c.service.years:g} years.</p>"
        ),
        table(headers, rows),
    ]
    if run.weibull is not None:
        lo_b, hi_b = run.weibull.interval("shape")
        parts.append(
            Markup(
                f"<p>Weibull fit of the tested wear rates: shape {run.weibull.shape:.3g} "
                f"({lo_b:.3g}-{hi_b:.3g}), scale {run.weibull.scale / MM3_PER_NM:.3g} mm³/Nm; "
                f"{run.weibull.confidence:.0%} bounds.</p>"
            )
        )
        path = wear_figures.weibull(
            run.weibull,
            figure_dir / "wear_weibull.png",
            1 / MM3_PER_NM,
            "mm³/Nm",
            {s.name: s.allowable_rate for s in run.scenarios},
        )
        parts.append(image(f"figures/{path.name}", "Weibull"))
    if run.log is not None:
        path = wear_figures.pitch_log(run, figure_dir / "wear_pitch_log.png")
        parts.append(image(f"figures/{path.name}", "pitch log"))
    path = wear_figures.depth_over_years(run, figure_dir / "wear_depth.png")
    parts.append(image(f"figures/{path.name}", "wear depth"))
    return Section("Blade-bearing wear in service", Markup("").join(parts))
