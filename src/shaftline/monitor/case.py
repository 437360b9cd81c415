"""The ``[monitor]`` table of a case file: eddy-current probes in a journal bearing and, for
now, synthetic recordings of seed 001's rig (issue 13, part A).

Layout::

    [monitor]                       bearing length, diameter, clearance, roughness, rotation
    [[monitor.sections]]            measurement sections from the loaded end
    [[monitor.sections.probes]]     probes: angle, mounting distance, calibration
    [monitor.simulate]              forward model of seed 001's rig: speeds, load, noise...
    [monitor.identify]              recordings to identify: keyphasor, window, database...
"""

from __future__ import annotations

import datetime as dt
from pathlib import Path
from typing import TYPE_CHECKING, Annotated, Literal

from pydantic import BeforeValidator, Field, StrictBool, model_validator

from shaftline.cases.types import (
    SHAFT_SPEED,
    Angle,
    Length,
    NonNegativeLength,
    Plausible,
    PositiveForce,
    PositiveFrequency,
    PositiveLength,
    PositiveMass,
    PositiveSpeed,
    PositiveTime,
    Quantity,
    Section,
    Temperature,
    field_error,
)
from shaftline.errors import InputError, located
from shaftline.film.case import LinerSection, SurfaceSection
from shaftline.registry import BuildContext

if TYPE_CHECKING:
    import numpy as np

    from shaftline.film.roughness import SurfaceRoughness
    from shaftline.monitor.probes import ProbeLayout
    from shaftline.monitor.study import IdentifyPlan, MonitorStudy, RunoutTable

_SEED = "seed 001"
BEARING_LENGTH = Plausible(
    0.02, 4.0, f"stern-tube bearings of 0.02 to 4 m ({_SEED}: 1.2 m); mm written as m is above (engineering judgement)"
)
BORE_DIAMETER = Plausible(
    0.02, 2.0, f"journals of 20 mm to 2 m ({_SEED}: 323 mm); mm written as m is above (engineering judgement)"
)
SMALL_LENGTH = Plausible(
    0.0,
    0.02,
    f"probe mounting distances, ranges and zero points of tenths of a mm to a few mm ({_SEED} Table 2: 0.5 and 3 mm "
    "ranges, zero points 0.05 and 0.3 mm); 20 mm is beyond the eddy-current probes used in bearings; mm written as "
    "m is above",
)
FINE = Plausible(
    0.0,
    5e-6,
    f"probe resolutions and noise of hundredths to tenths of a um ({_SEED} Table 2: 0.025 and 0.15 um); 5 um would "
    "hide a film of a few um (engineering judgement); um written as mm is above",
)
MOTION = Plausible(
    0.0,
    1e-4,
    "orbit, runout and noise amplitudes of hundredths of a um to some tens of um (engineering judgement); um written "
    "as mm is above",
)
RUNOUT = Plausible(
    -1e-4,
    1e-4,
    "runouts of hundredths of a um to some tens of um either way (engineering judgement; Bently Nevada practice "
    "counts a few um as usual); um written as mm is beyond",
)
ROTATION_ALIASES = {"cw": "clockwise", "ccw": "anticlockwise", "counterclockwise": "anticlockwise"}


def _rotation_alias(value: object) -> object:
    if isinstance(value, str):
        key = value.strip().lower()
        return ROTATION_ALIASES.get(key, key)
    return value


class ProbeSection(Section):
    """An eddy-current displacement probe."""

    name: str
    """Channel name (a recording's column)."""
    angle: Annotated[
        Angle, Plausible(-6.3, 6.3, "an angle within a turn; deg written as a bare number (rad) is beyond")
    ]
    """Bearing angle of the probe axis from the top, in the direction of rotation."""
    mounting_distance: Annotated[NonNegativeLength, SMALL_LENGTH]
    """Distance from the probe face back to the bore surface (0: flush)."""
    sensitivity: Annotated[float, Quantity("sensitivity", gt=0)] = 1.0
    """Output per unit gap (e.g. "8 mV/um")."""
    zero: Annotated[NonNegativeLength, SMALL_LENGTH] = 0.0
    """Gap at which the output is zero (the sensor's zero point)."""
    sign: Literal[1, -1] = 1
    """+1: the output grows with the gap; -1: it falls."""
    measuring_range: Annotated[PositiveLength, SMALL_LENGTH] | None = None
    """Gap span the probe measures above its zero point (none: not checked)."""
    resolution: Annotated[NonNegativeLength, FINE] = 0.0
    """Smallest gap step the probe resolves (quantisation of the synthetic signals)."""


class MeasurementSection(Section):
    """A measurement section: two or more probes in one plane across the bearing."""

    name: str
    """Label (seed 001: D1, D2, D3)."""
    position: Annotated[NonNegativeLength, BEARING_LENGTH]
    """Axial position from the loaded (aft) end of the bearing."""
    probes: Annotated[list[ProbeSection], Field(min_length=2)]
    """The probes, at least two with axes not on one line."""


class SimulateSection(Section):
    """Synthetic recordings of seed 001's rig (shaftline.monitor.forward): the journal from the bearing
    solver and the shaft model, whirl, runout, noise and quantisation. The defaults are those of
    ``RigCase`` (not imported here: the schema stays cheap to import; a test keeps them equal)."""

    speeds: Annotated[list[Annotated[PositiveSpeed, SHAFT_SPEED]], Field(min_length=1)]
    """Shaft speeds of the recordings (e.g. ["135 rpm", "215 rpm"])."""
    slow_roll_speed: Annotated[PositiveSpeed, SHAFT_SPEED] = 15 * 3.141592653589793 / 30
    """Speed of the slow-roll recording that measures the runout."""
    load: Annotated[
        PositiveForce,
        Plausible(
            1e3,
            3e7,
            f"bearing loads of kN to MN ({_SEED} Table 3: 75 kN) (engineering judgement); kN written as N is below",
        ),
    ] = 75e3
    """Load on the bearing (downwards)."""
    temperature: Temperature = 25.0
    """Water temperature (viscosity from the water model)."""
    misalignment: Annotated[
        Angle,
        Plausible(
            -1e-3,
            1e-3,
            "a misalignment a film carries is below 1 mrad (engineering judgement); urad written as mrad is beyond",
        ),
    ] = 2e-6
    """Journal tilt relative to the bore, + rising away from the loaded end."""
    bend_scale: Annotated[float, Quantity("dimensionless", ge=0, le=10)] = 0.1
    """Share of the shaft model's bending inside the bearing that the journal carries."""
    overhung_mass: Annotated[
        PositiveMass,
        Plausible(
            50.0,
            2e5,
            f"overhung masses of 50 kg to 200 t ({_SEED}: 7.5 t) (engineering judgement); t written as kg is below",
        ),
    ] = 7500.0
    """Counterweight at the overhung end of the rig's shaft model."""
    whirl: Annotated[NonNegativeLength, MOTION] = 1e-6
    """1X forward whirl, zero-to-peak, at whirl_speed (grows with the speed squared)."""
    whirl_speed: Annotated[PositiveSpeed, SHAFT_SPEED] = 215 * 3.141592653589793 / 30
    """Speed at which the whirl has that amplitude."""
    runout: Annotated[list[Annotated[NonNegativeLength, MOTION]], Field(min_length=2, max_length=2)] = [0.3e-6, 0.15e-6]
    """1X and 2X runout amplitudes seen by every probe (random phases, the same at every speed)."""
    noise: Annotated[NonNegativeLength, FINE] = 0.05e-6
    """Standard deviation of white noise on each gap."""
    sleeve_wear: Annotated[NonNegativeLength, MOTION] = 0.0
    """Uniform wear of the journal sleeve (the correction factor k should find it)."""
    sample_rate: Annotated[
        PositiveFrequency, Plausible(10.0, 1e6, "data acquisition at 10 Hz to 1 MHz (engineering judgement)")
    ] = 2048.0
    """Samples per second."""
    revolutions: Annotated[float, Quantity("dimensionless", ge=2, le=1000)] = 8.0
    """Length of each recording in shaft revolutions (unless duration)."""
    duration: (
        Annotated[
            PositiveTime,
            Plausible(0.1, 3600.0, "recordings of a fraction of a second to an hour (engineering judgement)"),
        ]
        | None
    ) = None
    """Length of each recording, the same at every speed (e.g. "16 s"); none: revolutions. A recording should hold
    two revolutions or more at its speed (a slow roll's runout and every window need whole revolutions)."""
    seed: Annotated[int, Field(ge=0)] = 1
    """Seed of the random phases and noise."""
    write_recordings: StrictBool = True
    """Write each recording as CSV (time, channels in volts, keyphasor) beside the report."""
    surface: SurfaceSection | None = None
    """Rough journal and bore in the bearing solver ([monitor.simulate.surface], as [bearing.surface]; seed 001's:
    preset = "steel_polymer"): asperity contact and boundary lubrication where the film is thin. Roughnesses not
    given are the [monitor] table's. None: smooth surfaces."""
    liner: LinerSection | None = None
    """Elastic liner of the bore in the bearing solver ([monitor.simulate.liner], as [bearing.liner]; seed 001's:
    preset = "polymer_composite"). The probes sit in the housing: they see the journal, not the liner's surface.
    None: a rigid bore."""


class RunoutSection(Section):
    """The runout of one probe against shaft angle, from a commissioning measurement (e.g. the synchronous
    average of a slow roll): subtracted at the keyphasor's shaft angle from every window."""

    probe: str
    """The probe's name (its channel)."""
    shaft_angle: Annotated[
        list[Annotated[Angle, Plausible(0.0, 6.2832, "within one turn, from the keyphasor mark: 0 to 360 deg")]],
        Field(min_length=3),
    ]
    """Shaft angles of the values, from the keyphasor mark in the direction of rotation, rising within one turn (e.g.
    ["0 deg", "30 deg", ...]); the runout is periodic and linear between them."""
    value: Annotated[list[Annotated[Length, RUNOUT]], Field(min_length=3)]
    """Runout at those angles (e.g. ["0.8 um", ...]): what the probe's gap reads more than the journal's position
    gives; its mean over the turn is removed (the mean gap is the reference point's)."""

    @model_validator(mode="after")
    def _one_value_per_rising_angle(self) -> RunoutSection:
        if len(self.value) != len(self.shaft_angle):
            raise field_error("value", len(self.value), f"one value per shaft angle ({len(self.shaft_angle)})")
        angles = self.shaft_angle
        for k in range(1, len(angles)):
            if not angles[k] > angles[k - 1]:
                raise field_error(
                    f"shaft_angle[{k}]", angles[k], f"> shaft_angle[{k - 1}] = {angles[k - 1]:.6g} rad (rising)", "rad"
                )
        if not angles[-1] < angles[0] + 2 * 3.141592653589793:
            raise field_error(
                f"shaft_angle[{len(angles) - 1}]", angles[-1], "less than one turn after shaft_angle[0]", "rad"
            )
        return self


class IdentifySection(Section):
    """Recordings of the probes identified window by window into the trend database
    (``shaftline monitor identify CASE.toml RECORDING...``)."""

    keyphasor: str = "keyphasor"
    """Name of the once-per-revolution channel; "" for recordings without one (then speed)."""
    speed: Annotated[PositiveSpeed, SHAFT_SPEED] | None = None
    """Shaft speed of recordings without a keyphasor: windows are cut into revolutions from the first
    sample at this speed (1X phases are then against the recording's start; no slow-roll runout)."""
    window: Annotated[
        PositiveTime, Plausible(0.05, 600.0, "windows of a few revolutions: 0.05 s to 10 min (engineering judgement)")
    ] = 2.0
    """Length of a window (each gives one row of trends)."""
    sample_rate: (
        Annotated[PositiveFrequency, Plausible(10.0, 1e6, "data acquisition at 10 Hz to 1 MHz (engineering judgement)")]
        | None
    ) = None
    """Samples per second where the files do not state it (checked against theirs where they do)."""
    start: dt.datetime | None = None
    """Time of the first sample of the first recording where the files do not state it (TOML date-time,
    UTC without a zone); the recordings follow back to back in the order given. None: each file's
    modification time."""
    recordings: list[str] = []
    """Recording files (CSV, Parquet, HDF5, TDMS), relative to this case; the command's RECORDING
    arguments replace them."""
    slow_roll: str | None = None
    """Slow-roll recording (same channels, a speed at which film and unbalance do not move the
    journal): each probe's runout against the keyphasor's phase is measured on it and subtracted
    from every window; --slow-roll replaces it. None: no runout compensation."""
    slow_roll_speed: Annotated[PositiveSpeed, SHAFT_SPEED] | None = None
    """Windows of each recording slower than this (speed from the keyphasor) are its slow roll: their gaps averaged
    over whole revolutions against the keyphasor's shaft angle are the probes' runout, subtracted from every window of
    that recording (e.g. "30 rpm" for a run-up from turning gear). None: not used."""
    runout: list[RunoutSection] = []
    """Runout of every probe against shaft angle from a commissioning measurement ([[monitor.identify.runout]]),
    subtracted from every window. At most one of slow_roll, slow_roll_speed and runout."""
    database: str = "monitor.sqlite"
    """Trend database: a SQLAlchemy URL, or a SQLite file relative to this case (made if new);
    --db replaces it."""
    ignore_channels: list[str] = []
    """Channels of the files that are neither probes nor the keyphasor and are left alone (any other
    extra channel is an error: a probe named wrong)."""
    max_invalid_share: Annotated[float, Quantity("dimensionless", gt=0, le=0.5)] = 0.01
    """Largest share of a window's probe samples that may be NaN or beyond the probe's range: they are
    masked, filled along time and counted. A recording whose first window has more is an input error
    (wiring, ranges, units); a later window with more is stored as rejected, left out of the trends,
    and makes the run not acceptable (exit 3)."""
    lambda_threshold: Annotated[float, Quantity("dimensionless", gt=0, le=10)] = 1.0
    """Film parameter below which a stretch of windows is an alarm (seed 001: boundary below 1)."""
    alarm_duration: Annotated[
        PositiveTime,
        Plausible(
            0.0,
            86400.0,
            "stretches of seconds to a day; a longer fall of the film is a trend, which the fitted line shows "
            "(engineering judgement)",
        ),
    ] = 600.0
    """Shortest stretch below the threshold that is an alarm."""

    @model_validator(mode="after")
    def _one_runout_source(self) -> IdentifySection:
        given = [name for name in ("slow_roll", "slow_roll_speed", "runout") if getattr(self, name)]

        def shown(name: str) -> tuple[object, str]:
            value = getattr(self, name)
            return (
                (f"{len(value)} probes", "")
                if name == "runout"
                else (value, "rad/s" if name == "slow_roll_speed" else "")
            )

        if len(given) > 1:
            value, unit = shown(given[1])
            raise field_error(given[1], value, f"one source of runout only ({' and '.join(given)} given)", unit)
        if given and not self.keyphasor:
            value, unit = shown(given[0])
            raise field_error(
                given[0], value, "recordings with a keyphasor (runout is a function of shaft angle)", unit
            )
        return self


class MonitorSection(Section):
    """Film-thickness monitoring with eddy-current probes (seed 001)."""

    length: Annotated[PositiveLength, BEARING_LENGTH]
    """Bearing length."""
    diameter: Annotated[PositiveLength, BORE_DIAMETER]
    """Bore diameter."""
    radial_clearance: PositiveLength
    """Radial clearance (after break-in); checked against the radius for a unit slip."""
    roughness_bearing: PositiveLength = 1.6e-6
    """Arithmetic mean roughness Ra of the bore (liner)."""
    roughness_journal: PositiveLength = 0.8e-6
    """Arithmetic mean roughness Ra of the journal (sleeve)."""
    rq_factor: Annotated[float, Quantity("dimensionless", ge=1.2, le=1.26)] = 1.25
    """Rq / Ra (seed 001: 1.20 to 1.25)."""
    rotation: Annotated[Literal["clockwise", "anticlockwise"], BeforeValidator(_rotation_alias)] = "clockwise"
    """Sense of rotation seen from aft."""
    sections: Annotated[list[MeasurementSection], Field(min_length=1)]
    """Measurement sections from the loaded end forward."""
    shaft_model: str | None = None
    """Case file whose [alignment] table models the machine's shaft line (path relative to this case): the
    bending shape of the journal in the bearing comes from it (none: seed 001's rig)."""
    shaft_bearing: str | None = None
    """Name of the monitored bearing in that [alignment] table (needed with shaft_model)."""
    simulate: SimulateSection | None = None
    """Synthetic recordings of seed 001's rig."""
    identify: IdentifySection | None = None
    """Recordings to identify into the trend database."""


def build_study(section: MonitorSection, context: BuildContext) -> MonitorStudy:
    """The monitoring study in SI domain objects."""
    import math

    from shaftline.film.case import liner_of
    from shaftline.lubricants import Lubricant
    from shaftline.monitor.forward import RigCase, rig_geometry
    from shaftline.monitor.probes import Probe, ProbeLayout
    from shaftline.monitor.probes import Section as ProbeSectionDomain
    from shaftline.monitor.study import MonitorStudy

    sections = tuple(
        ProbeSectionDomain(
            s.name,
            s.position,
            tuple(
                Probe(
                    p.name,
                    p.angle,
                    p.mounting_distance,
                    p.sensitivity,
                    p.zero,
                    p.sign,
                    math.inf if p.measuring_range is None else p.measuring_range,
                    p.resolution,
                )
                for p in s.probes
            ),
        )
        for s in section.sections
    )
    layout = ProbeLayout(
        sections,
        length=section.length,
        radius=0.5 * section.diameter,
        radial_clearance=section.radial_clearance,
        roughness_bearing=section.roughness_bearing,
        roughness_journal=section.roughness_journal,
        rq_factor=section.rq_factor,
        rotation=1 if section.rotation == "clockwise" else -1,
    )
    shape = None
    if section.shaft_model is not None:
        shape = model_bending_shape(section.shaft_model, section.shaft_bearing, layout.length, context)
    rig = None
    if section.simulate is not None:
        sim = section.simulate
        with located("simulate"):
            viscosity = float(Lubricant.preset("water").dynamic_viscosity(sim.temperature))
            surface = None if sim.surface is None else _rig_surface(sim.surface, section)
            liner = None
            if sim.liner is not None:
                with located("liner"):
                    liner = liner_of(sim.liner)
            rig = RigCase(
                layout=layout,
                load=sim.load,
                viscosity=viscosity,
                misalignment=sim.misalignment,
                bend_scale=sim.bend_scale,
                overhung_mass=sim.overhung_mass,
                whirl=sim.whirl,
                whirl_speed=sim.whirl_speed,
                runout=(sim.runout[0], sim.runout[1]),
                noise=sim.noise,
                sleeve_wear=sim.sleeve_wear,
                sample_rate=sim.sample_rate,
                revolutions=sim.revolutions,
                duration=sim.duration,
                seed=sim.seed,
                shape=shape,
                surface=surface,
                liner=liner,
            )
            # the bearing is made at solve time: its checks (liner against the radius...) now,
            # before anything is written
            rig_geometry(rig)
            if sim.duration is not None:
                # every recording (the slow roll's too) needs two keyphasor marks, one whole revolution
                # between them; without this check the simulation stopped on an internal field name
                slowest = min((*sim.speeds, sim.slow_roll_speed))
                needed = 2 * (2 * math.pi / slowest)
                if sim.duration < needed * (1.0 - 1e-9):
                    raise InputError(
                        "duration",
                        sim.duration,
                        "s",
                        f">= {needed:.4g} s: two revolutions at the slowest speed ({slowest * 30 / math.pi:.4g} rpm)",
                    )
    speeds = tuple(section.simulate.speeds) if section.simulate is not None else ()
    slow_roll = section.simulate.slow_roll_speed if section.simulate is not None else 0.0
    write = section.simulate.write_recordings if section.simulate is not None else False
    identify = None if section.identify is None else _identify_plan(section.identify, context, layout)
    return MonitorStudy(layout, rig, speeds, slow_roll, write, shape, identify)


def _rig_surface(surface: SurfaceSection, section: MonitorSection) -> SurfaceRoughness:
    """The forward model's surfaces, checked against the clearance as [bearing.surface] is. Beside a
    preset, roughnesses the table does not give are the [monitor] table's (with its Rq factor), so
    that the solver's surfaces are those the regimes are judged on."""
    from shaftline.film.case import checked_surface

    journal, bore = surface.journal_roughness, surface.bore_roughness
    if journal is None and bore is None:
        update = {
            "roughness_parameter": "Rq",
            "journal_roughness": section.rq_factor * section.roughness_journal,
            "bore_roughness": section.rq_factor * section.roughness_bearing,
        }
    else:
        factor = section.rq_factor if surface.roughness_parameter == "Rq" else 1.0
        update = {
            "journal_roughness": factor * section.roughness_journal if journal is None else journal,
            "bore_roughness": factor * section.roughness_bearing if bore is None else bore,
        }
    return checked_surface(surface.model_copy(update=update), section.radial_clearance)


def _runout_table(section: IdentifySection, channels: tuple[str, ...]) -> RunoutTable | None:
    """The case's runout table in the layout's channel order: every probe once, no other name."""
    from shaftline.errors import InputError
    from shaftline.monitor.study import RunoutTable

    if not section.runout:
        return None
    by_probe: dict[str, RunoutSection] = {}
    for k, row in enumerate(section.runout):
        if row.probe not in channels:
            raise InputError(f"identify.runout[{k}].probe", row.probe, "", "one of the probes: " + ", ".join(channels))
        if row.probe in by_probe:
            raise InputError(f"identify.runout[{k}].probe", row.probe, "", "each probe once")
        by_probe[row.probe] = row
    missing = [c for c in channels if c not in by_probe]
    if missing:
        raise InputError(
            "identify.runout",
            f"{len(by_probe)} of {len(channels)} probes",
            "",
            f"a runout table for every probe (missing: {', '.join(missing)}; a probe without runout: values of 0 um)",
        )
    return RunoutTable(
        channels,
        tuple(tuple(by_probe[c].shaft_angle) for c in channels),
        tuple(tuple(by_probe[c].value) for c in channels),
    )


def _identify_plan(section: IdentifySection, context: BuildContext, layout: ProbeLayout) -> IdentifyPlan:
    from shaftline.monitor.study import IdentifyPlan
    from shaftline.monitor.trends import TrendStore

    database = section.database
    if "://" not in database:
        # a file beside the case: kept across runs, never one of the run's inputs
        database = str(context.base_dir / Path(database).expanduser())
    file = TrendStore.file_of(database)
    if file is not None:
        # written in place by the run: no --json or --out may replace it or hold it
        context.kept.append(file)
    recordings = tuple(str(context.path(name)) for name in section.recordings)
    slow_roll = None if section.slow_roll is None else str(context.path(section.slow_roll))
    start = section.start
    if start is not None and start.tzinfo is None:
        start = start.replace(tzinfo=dt.UTC)
    return IdentifyPlan(
        recordings=recordings,
        database=database,
        keyphasor=section.keyphasor,
        window=section.window,
        sample_rate=section.sample_rate,
        start=start,
        ignore_channels=tuple(section.ignore_channels),
        max_invalid_share=section.max_invalid_share,
        lambda_threshold=section.lambda_threshold,
        alarm_duration=section.alarm_duration,
        slow_roll=slow_roll,
        speed=section.speed,
        slow_roll_speed=section.slow_roll_speed,
        runout=_runout_table(section, layout.channels),
    )


#: Stations of a bending shape along the bearing.
SHAPE_STATIONS = 49


def model_bending_shape(
    path: str, bearing: str | None, length: float, context: BuildContext
) -> tuple[np.ndarray, np.ndarray]:
    """Stations (m from the loaded end) and the bending shape (m) of the journal in ``bearing``
    of the ``[alignment]`` table of the case file ``path``."""
    import numpy as np

    from shaftline.cases import load_case
    from shaftline.errors import InputError
    from shaftline.monitor.bending import model_shape

    if bearing is None:
        raise InputError("shaft_bearing", "missing", "", "the name of the monitored bearing in the shaft model")
    file = context.path(path)
    try:
        case = load_case(file, only=["alignment"])
    except InputError as error:
        raise InputError("shaft_model", path, "", f"a case file with a valid [alignment] table ({error})") from None
    if "alignment" not in case.studies:
        raise InputError("shaft_model", path, "", "a case file with an [alignment] table")
    line = case.studies["alignment"].line
    names = [b.name for b in line.bearings]
    if bearing not in names:
        raise InputError("shaft_bearing", bearing, "", "one of " + ", ".join(names))
    modelled = line.bearings[names.index(bearing)].length
    if abs(modelled - length) > 0.01 * length:
        raise InputError(
            "shaft_bearing", bearing, "", f"a bearing of the monitored length {length:g} m, not {modelled:g} m"
        )
    stations = np.linspace(0.0, length, SHAPE_STATIONS)
    with located("shaft_bearing"):
        return stations, model_shape(line, bearing, stations)
