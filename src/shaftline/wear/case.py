"""The ``[wear]`` table of a case file: service wear of a CPP blade bearing (seed 000 Ch. 6)."""

from __future__ import annotations

from typing import TYPE_CHECKING, Annotated

from pydantic import Field, model_validator

from shaftline.cases.types import (
    SHAFT_SPEED,
    Plausible,
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


# Plausible ranges of CPP blade-bearing wear (the README's table of plausible ranges is made
# from them): generous, to catch a unit slip, not an unusual ship ([case] unusual).
_SEED = "seed 000"
_FERRY = "examples/ferry_wear.toml"
CONTACT_PRESSURE = Plausible(
    1e5,
    5e8,
    f"blade-bearing pressures of some tens of MPa ({_SEED} Sect. 2: 21 N/mm^2 in service; wear tests at 48 "
    "N/mm^2); 500 MPa is beyond the strength of bearing bronzes (engineering judgement); N/mm^2 written as a bare "
    "number (Pa) is far below",
)
WEAR_DEPTH = Plausible(
    1e-6,
    0.01,
    f"wear of tens to hundreds of um ({_SEED} Sect. 2: 200 um allowed, up to 500 um seen in service; Wear Test 6 "
    "depths 43-107 um); below 1 um is not measured, 10 mm is twenty times beyond; mm written as a bare "
    "number (m) is far above",
)


class ServiceSection(Section):
    """How much the ship sails until the bearing is overhauled."""

    voyages_per_day: Annotated[
        float,
        Quantity("dimensionless", gt=0),
        Plausible(
            1e-3,
            100.0,
            f"from a crossing every few months to short ferry runs ({_FERRY}: 10 a day) (engineering judgement)",
        ),
    ]
    """Voyages a day."""
    days_per_year: Annotated[
        float, Quantity("dimensionless", gt=0, le=366), Plausible(1.0, 366.0, f"days of a year ({_FERRY}: 340)")
    ]
    """Days in service a year."""
    years: Annotated[
        float,
        Quantity("dimensionless", gt=0),
        Plausible(
            0.1,
            40.0,
            f"a CPP is overhauled about every five years ({_SEED} Sect. 2), a ship lives 25-30; months written as "
            "years are above 40",
        ),
    ]
    """Years to the overhaul."""
    voyage_duration: (
        Annotated[
            PositiveTime,
            Plausible(
                180.0,
                60 * 86400.0,
                f"from a few minutes (short ferry runs; {_FERRY}: 100 min) to two months (engineering judgement); "
                "a voyage under 3 h written in minutes as a bare number (s) is below",
            ),
        ]
        | None
    ) = None
    """Duration of a voyage (needed for fretting)."""


VOYAGE_TIME = Plausible(0.0, 60 * 86400.0, "a time into a voyage: up to two months (engineering judgement)")


class ActiveControlSection(Section):
    """Active (MIMO) pitch control: an oscillation added to the pitch during free sailing (Sect. 6.3)."""

    amplitude: Annotated[
        float,
        Quantity("percent", gt=0, lt=100),
        Plausible(
            0.1,
            30.0,
            f"active pitch control adds a few % of design pitch ({_SEED} Sect. 6.3, {_FERRY}: 3 %) (engineering "
            "judgement); a share written for a percentage (0.03 for 3 %) is below",
        ),
    ]
    """Amplitude, % of design pitch (a number or e.g. "3 %")."""
    frequency: Annotated[
        PositiveFrequency,
        Plausible(
            1e-3,
            10.0,
            f"pitch oscillations of seconds to minutes ({_FERRY}: 0.1 Hz); mHz written as a bare number (Hz) is above "
            "for periods under 100 s (engineering judgement)",
        ),
    ]
    """Frequency of the oscillation."""
    start: Annotated[Time, VOYAGE_TIME]
    """Start of the window, time into the voyage."""
    end: Annotated[Time, VOYAGE_TIME]
    """End of the window."""

    @model_validator(mode="after")
    def _window(self) -> ActiveControlSection:
        if self.end <= self.start:
            raise field_error("end", self.end, f"after start ({self.start:g} s)", "s")
        return self


class FrettingSection(Section):
    """Fretting at the blade bearing: 2 amplitude of sliding per shaft revolution (Eq. 6.8)."""

    amplitude: Annotated[
        PositiveLength,
        Plausible(
            1e-6,
            0.005,
            f"fretting is a motion of less than 1 mm ({_SEED} Ch. 4: about 110 um, 500 um with 0.2 mm backlash); "
            "a few um is partial slip, 5 mm ten times the largest; mm written as a bare number (m) is far above",
        ),
    ]
    """Fretting amplitude at the bearing radius."""
    shaft_speed: Annotated[PositiveSpeed, SHAFT_SPEED]
    """Shaft speed while fretting."""


class WeibullSection(Section):
    """Wear depths of repeated wear tests, fitted with a Weibull distribution (Sect. 5.5.7)."""

    wear_depths: Annotated[list[Annotated[PositiveLength, WEAR_DEPTH]], Field(min_length=3)]
    """Wear depth of each test."""
    test_pressure: Annotated[PositivePressure, CONTACT_PRESSURE]
    """Contact pressure of the tests."""
    test_distance: Annotated[
        PositiveLength,
        Plausible(
            100.0,
            1e7,
            f"sliding distances of wear tests, hundreds of m to some km ({_SEED} Wear Test 6: 10800 m), and of "
            "service periods, up to thousands of km (engineering judgement); km written as a bare number (m) is "
            "below for tests under 100 km",
        ),
    ]
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

    design_pitch_angle: Annotated[
        float,
        Quantity("angle", gt=0, lt=1.5707963267948966),
        Plausible(
            0.05,
            1.05,
            f"3 to 60 deg: design pitch angles at 0.7 R are about 13-36 deg for P/D 0.6-1.6 ({_SEED}: 28 deg) "
            "(engineering judgement)",
        ),
    ]
    """Design pitch angle (100 % pitch), below 90 deg (a number is in radians)."""
    bearing_radius: Annotated[
        PositiveLength,
        Plausible(
            0.02,
            2.0,
            f"blade-bearing radii are about 0.1-0.2 of the propeller diameter ({_SEED} Ch. 6: 0.392 m); mm written "
            "as m is far above",
        ),
    ]
    """Radius of the blade bearing at which sliding is counted."""
    contact_pressure: Annotated[PositivePressure, CONTACT_PRESSURE]
    """Largest contact pressure of the bearing."""
    allowable_depth: Annotated[PositiveLength, WEAR_DEPTH]
    """Wear depth allowed until overhaul."""
    wear_rate: (
        Annotated[
            PositiveWearRate,
            Plausible(
                1e-20,
                1e-11,
                f"specific wear rates of bearing pairs, 1e-18 to 1e-15 m^3/(N m) in mild wear ({_SEED} Tables "
                "5.4-5.12: 0.54e-7 mm^3/(N m) = 5.4e-17) and up to about 1e-13 in severe wear (engineering "
                "judgement); mm^3/(N m) written as a bare number (m^3/(N m)) is far above",
            ),
        ]
        | None
    ) = None
    """Specific wear rate (e.g. "0.54e-7 mm^3/(N*m)"); or material_pair."""
    material_pair: str | None = None
    """A material pair of the bundled data set (seed 000 Tables 5.4, 5.6, 5.12): CuNiAl-42CrMo4,
    CuNiAl-MnAl bronze, DP4-42CrMo4, DU-42CrMo4."""
    dead_band: Annotated[
        float,
        Quantity("percent", gt=0, lt=50),
        Plausible(
            0.01,
            10.0,
            f"the actuation resolution of pitch control, about 0.5 % of design pitch ({_SEED} Ch. 6) (engineering "
            "judgement); a share written for a percentage (0.005 for 0.5 %) is below",
        ),
    ] = 0.5
    """Dead band of the stepwise-constant noise removal, % of design pitch (the actuation resolution;
    a number or e.g. "0.5 %")."""
    pitch_log: str | None = None
    """CSV of one voyage: columns time (s), pitch (% of design pitch); path relative to the case file."""
    pitch_travel_per_voyage: (
        Annotated[
            float,
            Quantity("dimensionless", gt=0),
            Plausible(
                1e-3,
                1e4,
                f"{_SEED} Eq. 6.3: 9.54 design pitches a ferry voyage; continuous pitch control (dynamic "
                "positioning) travels far more (engineering judgement)",
            ),
        ]
        | None
    ) = None
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
