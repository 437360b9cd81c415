"""Case-file section ``[wear]``: service wear of a CPP blade bearing (seed 000 Ch. 6)."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from shaftline.cases._base import Quantity, Strict
from shaftline.errors import InputError
from shaftline.units import to_si
from shaftline.wear.archard import material_pairs
from shaftline.wear.service import ServiceProfile


class ServiceIn(Strict):
    voyages_per_day: float
    days_per_year: float
    years: float
    voyage_duration: Quantity | None = None


class MimoIn(Strict):
    amplitude: float  # % of design pitch
    frequency: Quantity
    start: Quantity
    end: Quantity


class FrettingIn(Strict):
    amplitude: Quantity
    shaft_speed: Quantity


class WeibullIn(Strict):
    wear_depths: list[Quantity]
    test_pressure: Quantity
    test_distance: Quantity
    confidence: float = 0.95


class WearIn(Strict):
    design_pitch_angle: Quantity
    bearing_radius: Quantity
    contact_pressure: Quantity
    allowable_depth: Quantity
    wear_rate: Quantity | None = None
    material_pair: str | None = None
    dead_band: float = 0.5
    pitch_travel_per_voyage: float | None = None
    pitch_log: str | None = None
    service: ServiceIn
    mimo: MimoIn | None = None
    fretting: FrettingIn | None = None
    weibull: WeibullIn | None = None


@dataclass(frozen=True)
class WearCase:
    """Service-wear inputs in SI (angles rad, rates m^3/(N m), pressures Pa).

    ``pitch_log`` is a CSV of one voyage (path resolved against the case file);
    ``pitch_travel_per_voyage`` (design pitches) stands for it when there is none.
    ``weibull`` holds ``rates`` (m^3/(N m), from test depths by Eq. 5.2) and ``confidence``.
    """

    design_pitch_angle: float
    bearing_radius: float
    contact_pressure: float
    allowable_depth: float
    wear_rate: float
    dead_band: float
    service: ServiceProfile
    voyage_duration: float | None
    pitch_travel_per_voyage: float | None
    mimo: dict | None
    fretting: dict | None
    weibull: dict | None
    pitch_log: object | None = None


def build_wear(data: WearIn, base_dir=None) -> WearCase:
    angle = to_si(data.design_pitch_angle, "angle", "wear.design_pitch_angle")
    radius = to_si(data.bearing_radius, "length", "wear.bearing_radius")
    pressure = to_si(data.contact_pressure, "pressure", "wear.contact_pressure")
    depth = to_si(data.allowable_depth, "length", "wear.allowable_depth")
    for name, value, unit in (
        ("design_pitch_angle", angle, "rad"),
        ("bearing_radius", radius, "m"),
        ("contact_pressure", pressure, "Pa"),
        ("allowable_depth", depth, "m"),
    ):
        if value <= 0:
            raise InputError(f"wear.{name}", value, unit, "> 0")
    if (data.wear_rate is None) == (data.material_pair is None):
        raise InputError("wear.wear_rate", "?", "", "exactly one of wear_rate or material_pair")
    if data.wear_rate is not None:
        rate = to_si(data.wear_rate, "wear_rate", "wear.wear_rate")
        if rate <= 0:
            raise InputError("wear.wear_rate", rate, "m^3/(N m)", "> 0")
    else:
        pairs = [p for p in material_pairs() if p.name == data.material_pair and p.kind == "overall"]
        if not pairs:
            names = sorted({p.name for p in material_pairs() if p.kind == "overall"})
            raise InputError("wear.material_pair", data.material_pair, "", "one of " + ", ".join(names))
        rate = pairs[0].rate
    if not 0 < data.dead_band < 50:
        raise InputError("wear.dead_band", data.dead_band, "% of design pitch", "in (0, 50)")
    service = ServiceProfile(data.service.voyages_per_day, data.service.days_per_year, data.service.years)
    duration = None
    if data.service.voyage_duration is not None:
        duration = to_si(data.service.voyage_duration, "time", "wear.service.voyage_duration")
    mimo = None
    if data.mimo is not None:
        mimo = {
            "amplitude": data.mimo.amplitude,
            "frequency": to_si(data.mimo.frequency, "frequency", "wear.mimo.frequency"),
            "start": to_si(data.mimo.start, "time", "wear.mimo.start"),
            "end": to_si(data.mimo.end, "time", "wear.mimo.end"),
        }
    fretting = None
    if data.fretting is not None:
        fretting = {
            "amplitude": to_si(data.fretting.amplitude, "length", "wear.fretting.amplitude"),
            "speed": to_si(data.fretting.shaft_speed, "speed", "wear.fretting.shaft_speed"),
        }
        if duration is None:
            raise InputError("wear.service.voyage_duration", "missing", "s", "a voyage duration for fretting")
    weibull = None
    if data.weibull is not None:
        depths = np.array(
            [to_si(v, "length", f"wear.weibull.wear_depths[{k}]") for k, v in enumerate(data.weibull.wear_depths)]
        )
        test_pressure = to_si(data.weibull.test_pressure, "pressure", "wear.weibull.test_pressure")
        test_distance = to_si(data.weibull.test_distance, "length", "wear.weibull.test_distance")
        if test_pressure <= 0 or test_distance <= 0:
            raise InputError("wear.weibull.test_pressure", test_pressure, "Pa", "> 0 with a distance > 0")
        weibull = {
            "rates": depths / (test_pressure * test_distance),
            "depths": depths,
            "confidence": data.weibull.confidence,
        }
    log = None
    if data.pitch_log is not None:
        from pathlib import Path

        from shaftline.wear.service import read_pitch_log

        path = Path(data.pitch_log)
        log = read_pitch_log(path if path.is_absolute() else (base_dir or Path.cwd()) / path)
    if log is None and data.pitch_travel_per_voyage is None:
        raise InputError("wear.pitch_log", "missing", "", "a pitch log, or pitch_travel_per_voyage")
    return WearCase(
        angle,
        radius,
        pressure,
        depth,
        rate,
        data.dead_band,
        service,
        duration,
        data.pitch_travel_per_voyage,
        mimo,
        fretting,
        weibull,
        log,
    )
