"""A service-wear study of a CPP blade bearing: sliding distance per scenario (standard
control, active control, fretting), Archard wear depth over the overhaul period, the
allowable wear rate and, from tested wear, the probability of exceeding it (seed 000 Ch. 6).

This is what ``[wear]`` in a case file becomes; notebooks can build one directly.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np

from shaftline.wear.service import PitchLog, ServiceProfile

if TYPE_CHECKING:
    from shaftline.wear.reliability import WeibullFit


@dataclass(frozen=True)
class ActiveControl:
    """Active (MIMO) pitch control: a sine of ``amplitude`` % of design pitch and ``frequency``
    Hz added between ``start`` and ``end`` s of the voyage (Sect. 6.3)."""

    amplitude: float
    frequency: float
    start: float
    end: float


@dataclass(frozen=True)
class Fretting:
    """Fretting of ``amplitude`` (m, at the bearing radius) at shaft ``speed`` (rad/s)."""

    amplitude: float
    speed: float


@dataclass(frozen=True)
class WearTests:
    """Repeated wear tests: depths (m) at ``pressure`` (Pa) over ``distance`` (m)."""

    depths: tuple[float, ...]
    pressure: float
    distance: float
    confidence: float = 0.95

    @property
    def rates(self) -> np.ndarray:
        """Specific wear rates of the tests, m^3/(N m) (seed Eq. 5.2)."""
        return np.asarray(self.depths) / (self.pressure * self.distance)


@dataclass(frozen=True, eq=False)
class WearStudy:
    """Service-wear inputs in SI (angles rad, rates m^3/(N m), pressures Pa).

    ``pitch_log`` is one voyage's pitch signal; ``pitch_travel_per_voyage`` (design
    pitches) stands for it when there is none.
    """

    design_pitch_angle: float
    bearing_radius: float
    contact_pressure: float
    allowable_depth: float
    wear_rate: float
    service: ServiceProfile
    dead_band: float = 0.5
    voyage_duration: float | None = None
    pitch_log: PitchLog | None = None
    pitch_travel_per_voyage: float | None = None
    mimo: ActiveControl | None = None
    fretting: Fretting | None = None
    tests: WearTests | None = None


@dataclass(frozen=True)
class Scenario:
    """Sliding per voyage and what it means over the overhaul period.

    Attributes
    ----------
    name : str
    distance_per_voyage, distance_total : float
        m.
    depth_total : float
        Archard depth at the study's wear rate after the overhaul period, m.
    allowable_rate : float
        Rate that would just reach the allowable depth, m^3/(N m).
    years_to_limit : float
        Years until the allowable depth at the study's wear rate.
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


@dataclass(frozen=True, eq=False)
class WearResult:
    """Scenarios of a wear study with the processed pitch signal and the Weibull fit."""

    study: WearStudy
    corrected: np.ndarray | None
    mimo_signal: np.ndarray | None
    travel_raw: float | None
    travel_corrected: float
    scenarios: list[Scenario]
    weibull: WeibullFit | None


def solve_wear(study: WearStudy, progress: Callable[[str], None] | None = None) -> WearResult:
    """Sliding distances (standard control, active control, fretting), depths and probabilities."""
    from shaftline.errors import InputError, located
    from shaftline.wear.archard import allowable_rate
    from shaftline.wear.reliability import fit_weibull
    from shaftline.wear.service import (
        fretting_distance,
        pitch_travel,
        sliding_distance,
        stepwise_constant,
        superimpose_oscillation,
    )

    if progress is not None:
        progress("service wear")
    log = study.pitch_log
    per_pitch = study.design_pitch_angle * study.bearing_radius  # m per design pitch of travel
    corrected = mimo_signal = None
    travel_raw = None
    if log is not None:
        corrected = stepwise_constant(log.pitch, study.dead_band)
        travel_raw = pitch_travel(log.pitch)
        travel = pitch_travel(corrected)
    else:
        travel = float(study.pitch_travel_per_voyage or 0.0)
    standard = sliding_distance(travel, study.design_pitch_angle, study.bearing_radius)
    distances = {"standard control": standard}
    if travel_raw is not None:
        distances["uncorrected signal"] = sliding_distance(travel_raw, study.design_pitch_angle, study.bearing_radius)
    if study.mimo is not None:
        m = study.mimo
        if log is not None and corrected is not None:
            mimo_signal = superimpose_oscillation(log, corrected, m.amplitude, m.frequency, m.start, m.end)
            distances["active (MIMO) control"] = per_pitch * pitch_travel(mimo_signal)
        else:  # four amplitudes of travel per period
            extra = 4 * m.amplitude / 100 * m.frequency * (m.end - m.start)
            distances["active (MIMO) control"] = standard + per_pitch * extra
    if study.fretting is not None and study.voyage_duration is not None:
        f = study.fretting
        distances["standard control with fretting"] = standard + fretting_distance(
            f.amplitude, f.speed, study.voyage_duration
        )
    if travel == 0.0:
        raise InputError("pitch_log", "no pitch change", "", "a voyage with pitch travel beyond the dead band")
    weibull = None
    if study.tests is not None:
        with located("weibull", {"samples": "weibull.wear_depths"}):
            weibull = fit_weibull(study.tests.rates, study.tests.confidence)
    scenarios = []
    voyages = study.service.voyages()
    per_year = study.service.voyages(1.0)
    for name, distance in distances.items():
        total = distance * voyages
        depth = study.wear_rate * study.contact_pressure * total
        limit = allowable_rate(study.allowable_depth, study.contact_pressure, total)
        years = study.allowable_depth / (study.wear_rate * study.contact_pressure * distance * per_year)
        exceed = weibull.exceedance(limit) if weibull is not None else None
        scenarios.append(Scenario(name, distance, total, depth, limit, years, exceed))
    return WearResult(study, corrected, mimo_signal, travel_raw, travel, scenarios, weibull)
