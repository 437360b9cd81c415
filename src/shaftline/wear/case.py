"""The ``[wear]`` table of a case file: service wear of a CPP blade bearing (seed 000 Ch. 6)."""

from __future__ import annotations

from typing import TYPE_CHECKING, Annotated

from pydantic import Field, model_validator

from shaftline.cases.types import (
    PositiveFrequency,
    PositiveLength,
    PositivePressure,
    PositiveSpeed,
    PositiveTime,
    PositiveWearRate,
    Quantity,
    Section,
    Time,
    field_error,
)
from shaftline.errors import InputError, located
from shaftline.registry import BuildContext

if TYPE_CHECKING:
    from shaftline.wear.study import WearStudy


class ServiceSection(Section):
    """How much the ship sails until the bearing is overhauled."""

    voyages_per_day: Annotated[float, Quantity("dimensionless", gt=0)]
    """Voyages a day."""
    days_per_year: Annotated[float, Quantity("dimensionless", gt=0, le=366)]
    """Days in service a year."""
    years: Annotated[float, Quantity("dimensionless", gt=0)]
    """Years to the overhaul."""
    voyage_duration: PositiveTime | None = None
    """Duration of a voyage (needed for fretting)."""


class ActiveControlSection(Section):
    """Active (MIMO) pitch control: an oscillation added to the pitch during free sailing (Sect. 6.3)."""

    amplitude: Annotated[float, Quantity("percent", gt=0, lt=100)]
    """Amplitude, % of design pitch (a number or e.g. "3 %")."""
    frequency: PositiveFrequency
    """Frequency of the oscillation."""
    start: Time
    """Start of the window, time into the voyage."""
    end: Time
    """End of the window."""

    @model_validator(mode="after")
    def _window(self) -> ActiveControlSection:
        if self.end <= self.start:
            raise field_error("end", self.end, f"after start ({self.start:g} s)", "s")
        return self


class FrettingSection(Section):
    """Fretting at the blade bearing: 2 amplitude of sliding per shaft revolution (Eq. 6.8)."""

    amplitude: PositiveLength
    """Fretting amplitude at the bearing radius."""
    shaft_speed: PositiveSpeed
    """Shaft speed while fretting."""


class WeibullSection(Section):
    """Wear depths of repeated wear tests, fitted with a Weibull distribution (Sect. 5.5.7)."""

    wear_depths: Annotated[list[PositiveLength], Field(min_length=3)]
    """Wear depth of each test."""
    test_pressure: PositivePressure
    """Contact pressure of the tests."""
    test_distance: PositiveLength
    """Sliding distance of the tests."""
    confidence: Annotated[float, Quantity("dimensionless", gt=0.5, lt=1)] = 0.95
    """Two-sided level of the bounds."""

    @model_validator(mode="after")
    def _spread(self) -> WeibullSection:
        if len(set(self.wear_depths)) == 1:
            raise field_error("wear_depths", self.wear_depths[0], "depths that are not all equal", "m")
        return self


class WearSection(Section):
    """Service wear of a CPP blade bearing: sliding from pitch usage, wear over the overhaul period."""

    design_pitch_angle: Annotated[float, Quantity("angle", gt=0, lt=1.5707963267948966)]
    """Design pitch angle (100 % pitch), below 90 deg (a number is in radians)."""
    bearing_radius: PositiveLength
    """Radius of the blade bearing at which sliding is counted."""
    contact_pressure: PositivePressure
    """Largest contact pressure of the bearing."""
    allowable_depth: PositiveLength
    """Wear depth allowed until overhaul."""
    wear_rate: PositiveWearRate | None = None
    """Specific wear rate (e.g. "0.54e-7 mm^3/(N*m)"); or material_pair."""
    material_pair: str | None = None
    """A material pair of the bundled data set (seed 000 Tables 5.4, 5.6, 5.12): CuNiAl-42CrMo4,
    CuNiAl-MnAl bronze, DP4-42CrMo4, DU-42CrMo4."""
    dead_band: Annotated[float, Quantity("percent", gt=0, lt=50)] = 0.5
    """Dead band of the stepwise-constant noise removal, % of design pitch (the actuation resolution;
    a number or e.g. "0.5 %")."""
    pitch_log: str | None = None
    """CSV of one voyage: columns time (s), pitch (% of design pitch); path relative to the case file."""
    pitch_travel_per_voyage: Annotated[float, Quantity("dimensionless", gt=0)] | None = None
    """Pitch travel of a voyage in design pitches, when there is no log."""
    service: ServiceSection
    """Service profile."""
    mimo: ActiveControlSection | None = None
    """Active pitch control scenario."""
    fretting: FrettingSection | None = None
    """Fretting scenario."""
    weibull: WeibullSection | None = None
    """Weibull fit of tested wear."""

    @model_validator(mode="after")
    def _sources(self) -> WearSection:
        if (self.wear_rate is None) == (self.material_pair is None):
            raise field_error(
                "wear_rate",
                "missing" if self.wear_rate is None else self.wear_rate,
                "exactly one of wear_rate or material_pair",
            )
        if self.pitch_log is None and self.pitch_travel_per_voyage is None:
            raise field_error("pitch_log", "missing", "a pitch log, or pitch_travel_per_voyage")
        if self.fretting is not None and self.service.voyage_duration is None:
            raise field_error("service.voyage_duration", "missing", "a voyage duration for the fretting scenario", "s")
        return self


def build_study(section: WearSection, context: BuildContext) -> WearStudy:
    """The wear study in SI domain objects."""
    from shaftline.wear.archard import material_pairs
    from shaftline.wear.service import ServiceProfile, read_pitch_log
    from shaftline.wear.study import ActiveControl, Fretting, WearStudy, WearTests

    if section.wear_rate is not None:
        rate = section.wear_rate
    else:
        pairs = [p for p in material_pairs() if p.name == section.material_pair and p.kind == "overall"]
        if not pairs:
            names = sorted({p.name for p in material_pairs() if p.kind == "overall"})
            raise InputError("material_pair", section.material_pair, "", "one of " + ", ".join(names))
        rate = pairs[0].rate
    s = section.service
    with located("service"):
        service = ServiceProfile(s.voyages_per_day, s.days_per_year, s.years)
    log = None
    if section.pitch_log is not None:
        with located("pitch_log"):
            log = read_pitch_log(context.path(section.pitch_log))
    mimo = None
    if section.mimo is not None:
        m = section.mimo
        if log is not None:
            first, last = float(log.time[0]), float(log.time[-1])
            if not first <= m.start < last:
                raise InputError("mimo.start", m.start, "s", f"within the pitch log, [{first:g}, {last:g}) s")
            if m.end > last:
                raise InputError("mimo.end", m.end, "s", f"within the pitch log, <= {last:g} s")
        mimo = ActiveControl(m.amplitude, m.frequency, m.start, m.end)
    fretting = None
    if section.fretting is not None:
        fretting = Fretting(section.fretting.amplitude, section.fretting.shaft_speed)
    tests = None
    if section.weibull is not None:
        w = section.weibull
        tests = WearTests(tuple(w.wear_depths), w.test_pressure, w.test_distance, w.confidence)
    return WearStudy(
        design_pitch_angle=section.design_pitch_angle,
        bearing_radius=section.bearing_radius,
        contact_pressure=section.contact_pressure,
        allowable_depth=section.allowable_depth,
        wear_rate=rate,
        dead_band=section.dead_band,
        service=service,
        voyage_duration=s.voyage_duration,
        pitch_log=log,
        pitch_travel_per_voyage=section.pitch_travel_per_voyage,
        mimo=mimo,
        fretting=fretting,
        tests=tests,
    )
