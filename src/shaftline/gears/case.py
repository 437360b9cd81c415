"""The ``[gears]`` table of a case file: a lubricated spur or helical pair rated for scuffing by
seed 002's scuffing parameter and by ISO/TS 6336-20's flash-temperature method (issue 14 part B).

Layout::

    [gears]             lubricant, oil and critical temperature, C or a calibration test record
    [gears.pair]        teeth, module, pressure angle, face width, helix, shifts, centre distance
    [gears.pinion]      flank roughness (and elastic constants) of each gear
    [gears.wheel]
    [gears.test]        torque steps and pinion speeds (or FZG load stages)
    [gears.load_sharing] a load distribution along the path (optional; ISO's by default)
    [gears.iso]         the oil's FZG failure stage and ISO's factors (optional)
    [gears.flash]       the form of ISO's flash temperature (optional, with [gears.iso])
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING, Annotated, Literal

from pydantic import Field, StrictBool, model_validator

from shaftline.cases.types import (
    Plausible,
    PositiveLength,
    PositivePressure,
    Quantity,
    Section,
    field_error,
)
from shaftline.errors import InputError
from shaftline.gears.mesh import HELIX_ANGLE_LIMIT_DEG, PRESSURE_ANGLE_LIMITS_DEG
from shaftline.registry import BuildContext

if TYPE_CHECKING:
    from shaftline.gears.study import GearStudy

_SEED = "seed 002"
_FZG = "FZG test gears (ISO 14635-1)"
MODULE = Plausible(
    3e-4, 0.05, f"fine-pitch gears (0.3 mm) to large marine gears (about 40 mm); {_SEED} 5 mm, {_FZG} 4.5 mm"
)
FACE_WIDTH = Plausible(1e-3, 1.5, "from instrument gears to the widest marine gears (engineering judgement)")
CENTRE_DISTANCE = Plausible(0.01, 10.0, f"{_SEED} 140 mm, {_FZG} 91.5 mm; marine gearboxes up to a few metres")
TIP_DIAMETER = Plausible(5e-3, 10.0, "tip diameters of gears from 5 mm to 10 m")
# The pressure and helix angles' plausible ranges are GearPair's own limits, shown in degrees: a
# bare number (radians) gets the unit that fits, and no offer of [case] unusual, which the limit
# would refuse again. The open ends sit one ulp inside, so that a value the range passes is one
# the model takes.
_DEG = math.radians(1.0)
PRESSURE_ANGLE = Plausible(
    math.nextafter(math.radians(PRESSURE_ANGLE_LIMITS_DEG[0]), 1.0),
    math.nextafter(math.radians(PRESSURE_ANGLE_LIMITS_DEG[1]), 0.0),
    "normal pressure angles of 14.5-30 deg in use; the model's range",
    shown_unit="deg",
    shown_factor=_DEG,
    limit=True,
    ends="()",
)
HELIX_ANGLE = Plausible(
    0.0,
    math.nextafter(math.radians(HELIX_ANGLE_LIMIT_DEG), 0.0),
    "spur (0) to double-helical gears (about 40 deg); the model's range",
    shown_unit="deg",
    shown_factor=_DEG,
    limit=True,
    ends="[)",
)
ROUGHNESS = Plausible(
    1e-9, 2e-5, f"superfinished (Ra 0.01 um) to rough machined (Ra 6 um) flanks ({_SEED} Table 1: 0.4 and 0.1 um)"
)
TORQUE = Plausible(
    0.1, 5e6, f"pinion torques from small gears to marine main gears ({_SEED}: up to 500 N m; FZG stage 12: 534.5 N m)"
)
PINION_SPEED = Plausible(0.1, 6.3e3, f"pinion speeds to 60 000 rpm ({_SEED}: up to 18 000 rpm; FZG A/8.3/90: 2170 rpm)")
MODULUS = Plausible(1e9, 1e12, "metals and ceramics (polymer gears are outside the contact models' data)")

#: Pinion torque of the FZG A/8.3/90 test per load stage 1-12, N m (ISO 14635-1).
FZG_TORQUES = (3.3, 13.7, 35.3, 60.8, 94.1, 135.3, 183.4, 239.3, 302.0, 372.6, 450.1, 534.5)

#: Case-file paths of the pair's fields as GearPair names them.
_PAIR_FIELDS = {
    "teeth_1": "pair.teeth[0]",
    "teeth_2": "pair.teeth[1]",
    "module": "pair.module",
    "pressure_angle": "pair.pressure_angle",
    "face_width": "pair.face_width",
    "helix_angle": "pair.helix_angle",
    "shift_1": "pair.shift[0]",
    "shift_2": "pair.shift[1]",
    "addendum": "pair.addendum",
    "centre_distance": "pair.centre_distance",
    "tip_radius_1": "pair.tip_diameter[0]",
    "tip_radius_2": "pair.tip_diameter[1]",
}


class PairSection(Section):
    """Involute geometry of the pair (ISO 21771)."""

    teeth: Annotated[list[Annotated[int, Field(ge=1)]], Field(min_length=2, max_length=2)]
    """Teeth of pinion and wheel."""
    module: Annotated[PositiveLength, MODULE]
    """Normal module."""
    pressure_angle: Annotated[float, Quantity("angle", gt=0), PRESSURE_ANGLE]
    """Normal pressure angle of the loaded flanks, 11.5-34.4 deg."""
    face_width: Annotated[PositiveLength, FACE_WIDTH]
    """Common face width."""
    helix_angle: Annotated[float, Quantity("angle", ge=0), HELIX_ANGLE] = 0.0
    """Helix angle (0: spur), below 45 deg."""
    shift: Annotated[
        list[Annotated[float, Quantity("dimensionless", ge=-2, le=2)]], Field(min_length=2, max_length=2)
    ] = [
        0.0,
        0.0,
    ]
    """Profile shift coefficients x of pinion and wheel."""
    addendum: Annotated[float, Quantity("dimensionless", gt=0, le=2)] = 1.0
    """Addendum coefficient h_a*."""
    centre_distance: Annotated[PositiveLength, CENTRE_DISTANCE] | None = None
    """Working centre distance (checked against the one the shifts give)."""
    tip_diameter: Annotated[list[Annotated[PositiveLength, TIP_DIAMETER]], Field(min_length=2, max_length=2)] | None = (
        None
    )
    """Tip diameters of pinion and wheel when not standard (shortened tips)."""
    allow_undercut: StrictBool = False
    """Accept shifts below the rack's undercut limit (teeth cut with undercut, e.g. the FZG type A wheel)."""


class FlankSection(Section):
    """The flanks of one gear."""

    roughness_ra: Annotated[PositiveLength, ROUGHNESS]
    """Arithmetic mean roughness Ra (Rq = 1.25 Ra for the film ratio)."""
    youngs_modulus: Annotated[PositivePressure, MODULUS] = 206e9
    """Young's modulus (default: steel)."""
    poisson_ratio: Annotated[float, Quantity("dimensionless", ge=0, lt=0.5)] = 0.3
    """Poisson's ratio."""


class StepsSection(Section):
    """The torque steps and pinion speeds to rate (a torque-step test, or the FZG stages)."""

    torques: (
        Annotated[list[Annotated[float, Quantity("moment", gt=0), TORQUE]], Field(min_length=1, max_length=100)] | None
    ) = None
    """Pinion torque of each step (or fzg_load_stages)."""
    fzg_load_stages: Annotated[list[Annotated[int, Field(ge=1, le=12)]], Field(min_length=1)] | None = None
    """FZG A/8.3/90 load stages: the pinion torques of ISO 14635-1 (3.3-534.5 N m)."""
    speeds: Annotated[
        list[Annotated[float, Quantity("speed", gt=0), PINION_SPEED]], Field(min_length=1, max_length=200)
    ]
    """Pinion speeds; the first is the test speed of the SP-against-torque figure (several: the
    summary gives SP/S_B as one torque-step x speed matrix, the report each speed's tables too)."""

    @model_validator(mode="after")
    def _one_load(self) -> StepsSection:
        if (self.torques is None) == (self.fzg_load_stages is None):
            raise field_error(
                "torques", "missing" if self.torques is None else "both", "one of torques and fzg_load_stages"
            )
        return self

    def torque_steps(self) -> list[float]:
        if self.torques is not None:
            return list(self.torques)
        assert self.fzg_load_stages is not None  # checked by the validator
        return [FZG_TORQUES[k - 1] for k in self.fzg_load_stages]


class LoadSharingSection(Section):
    """Share of the pair's load on one tooth pair along the path, from A (0) to E (1)."""

    fraction: Annotated[list[Annotated[float, Quantity("dimensionless", ge=0, le=1)]], Field(min_length=2)]
    """Positions (rho - A)/(E - A), increasing from 0 to 1."""
    share: Annotated[list[Annotated[float, Quantity("dimensionless", gt=0, le=1)]], Field(min_length=2)]
    """Share of the load at those positions."""


class IsoSection(Section):
    """ISO/TS 6336-20 flash-temperature and ISO/TS 6336-21 integral-temperature methods (docs/theory.md
    19.3, 19.5)."""

    fzg_load_stage: Annotated[float, Quantity("dimensionless", ge=1, le=14)]
    """Load stage at which the oil scuffs in the FZG A/8.3/90 test (its data sheet)."""
    base_oil: Literal[
        "mineral",
        "polyalphaolefin",
        "polyglycol non-water-soluble",
        "polyglycol water-soluble",
        "phosphate ester",
        "traction fluid",
    ] = "mineral"
    """Base oil (lubricant factor X_L)."""
    lubrication: Literal["dip", "spray", "immersed"] = "dip"
    """How the oil reaches the mesh (X_S)."""
    structural_factor: Annotated[float, Quantity("dimensionless", gt=0, le=2)] = 1.0
    """X_W (1.0 through-hardened or case-carburized steel; 1.5 nitrided)."""
    accuracy_grade: Annotated[int, Field(ge=1, le=12)] = 7
    """ISO 1328 flank tolerance grade (load sharing at A and E)."""


class FlashSection(Section):
    """Which form of ISO's flash temperature (docs/theory.md 19.3); needs [gears.iso]."""

    method: Literal["iso_cylindrical", "iso_general"] = "iso_cylindrical"
    """iso_cylindrical: ISO's form for cylindrical gears (Eq. A.5, Blok on the normal load; default);
    iso_general: ISO's general Eq. (5) as transcribed (Blok, K = 0.80 on the transverse load, 2.9 % lower
    flash temperature on 20 deg spur gears), for comparison with tools that use it."""


class GearsSection(Section):
    """A lubricated gear pair rated for scuffing: seed 002's SP and ISO's flash temperature."""

    lubricant: str
    """Lubricant: MIL-PRF-23699, ISO VG 100 or FVA 3 (docs/theory.md Sect. 15.3)."""
    oil_temperature: Annotated[float, Quantity("temperature", ge=-40, le=250)]
    """Oil bath / inlet temperature T_0."""
    critical_temperature: Annotated[float, Quantity("temperature", ge=-40, le=400)]
    """Critical temperature of the lubricant T_cr (seed 002: 126 degC for MIL-PRF-23699)."""
    thermal_coefficient: (
        Annotated[float, Quantity("thermal_conductivity", gt=0), Plausible(1.0, 1e7, "W/(m K); calibrate it")] | None
    ) = None
    """C of seed 002 Eq. 7, or calibration."""
    calibration: str | None = None
    """Test record (CSV: torque_Nm, speed_rpm, oil_temperature_degC, scuffed) to calibrate C on; replaces
    thermal_coefficient (the command line's --calibrate sets it)."""
    boundary_friction: Annotated[
        float, Quantity("dimensionless", gt=0, lt=1), Plausible(0.02, 0.3, f"{_SEED}: 0.08-0.1")
    ] = 0.1
    """Boundary friction coefficient f_b (seed 002 Eq. 1)."""
    thermal_method: Literal["gupta", "murch_wilson", "none"] = "gupta"
    """Inlet shear-heating reduction of the film."""
    extrapolate: StrictBool = False
    """Evaluate correlations outside their validity ranges with a warning instead of an error."""
    points: Annotated[int, Field(ge=20, le=2000)] = 200
    """Points along the path of contact."""
    pair: PairSection
    """Involute geometry of the pair."""
    pinion: FlankSection
    """Pinion flanks."""
    wheel: FlankSection
    """Wheel flanks."""
    test: StepsSection
    """Torque steps and pinion speeds to rate."""
    load_sharing: LoadSharingSection | None = None
    """A load distribution along the path (default: ISO's load sharing without tip relief)."""
    iso: IsoSection | None = None
    """ISO/TS 6336-20 and -21 (flash and integral temperature) beside SP (optional)."""
    flash: FlashSection | None = None
    """The form of ISO's flash temperature (optional; with ``[gears.iso]``)."""

    @model_validator(mode="after")
    def _coefficient(self) -> GearsSection:
        if self.flash is not None and self.iso is None:
            raise field_error("flash.method", self.flash.method, "only with [gears.iso] (ISO's rating)", "")
        if self.thermal_coefficient is None and self.calibration is None:
            raise field_error("thermal_coefficient", "missing", "C in W/(m K), or a calibration test record")
        if self.critical_temperature <= self.oil_temperature:
            raise field_error(
                "critical_temperature",
                self.critical_temperature,
                f"above the oil temperature {self.oil_temperature:g} degC",
                "degC",
            )
        return self


def _pair(section: PairSection) -> object:
    from shaftline.gears.mesh import GearPair

    tips = section.tip_diameter
    try:
        return GearPair(
            section.teeth[0],
            section.teeth[1],
            section.module,
            section.pressure_angle,
            section.face_width,
            helix_angle=section.helix_angle,
            shift_1=section.shift[0],
            shift_2=section.shift[1],
            addendum=section.addendum,
            centre_distance=section.centre_distance,
            tip_radius_1=None if tips is None else tips[0] / 2.0,
            tip_radius_2=None if tips is None else tips[1] / 2.0,
            allow_undercut=section.allow_undercut,
        )
    except InputError as error:
        field = _PAIR_FIELDS.get(error.field, f"pair.{error.field}")
        value, unit = error.value, error.unit
        if error.field.startswith("tip_radius") and isinstance(value, float):
            value = 2.0 * value
        if error.field in ("pressure_angle", "helix_angle"):
            unit = "deg"
        raise InputError(field, value, unit, error.allowed.replace("radius", "diameter")) from None


def build_study(section: GearsSection, context: BuildContext) -> GearStudy:
    """The gear study in SI domain objects."""
    import numpy as np

    from shaftline.contact.lubricated import ContactModel, Surfaces
    from shaftline.contact.rheology import contact_lubricant
    from shaftline.gears.flash import IsoScuffingData
    from shaftline.gears.mesh import GearPair
    from shaftline.gears.scuffing import GearMesh
    from shaftline.gears.study import GearStudy, read_test_record

    pair = _pair(section.pair)
    assert isinstance(pair, GearPair)
    lubricant = contact_lubricant(section.lubricant)
    rq = math.sqrt(math.pi / 2.0)
    p, w = section.pinion, section.wheel
    surfaces = Surfaces(
        p.youngs_modulus, p.poisson_ratio, w.youngs_modulus, w.poisson_ratio, p.roughness_ra * rq, w.roughness_ra * rq
    )
    model = ContactModel(
        lubricant=lubricant,
        geometry="line",
        thermal_method=section.thermal_method,
        boundary_friction=section.boundary_friction,
        extrapolate=section.extrapolate,
    )
    table = None
    if section.load_sharing is not None:
        table = (np.asarray(section.load_sharing.fraction), np.asarray(section.load_sharing.share))
        if len(table[0]) != len(table[1]):
            raise InputError("load_sharing.share", len(table[1]), "", f"{len(table[0])} values, one per fraction")
    grade = section.iso.accuracy_grade if section.iso is not None else 7
    mesh = GearMesh(pair, model, surfaces, grade, table, section.points)
    mesh.load_sharing(mesh.positions())  # a bad table fails here, at build time
    if not section.extrapolate:
        # the oil must have viscosity data at the oil temperature (with extrapolate: a warning at solve)
        try:
            lubricant.check_temperature(section.oil_temperature)
        except InputError as error:
            raise InputError("oil_temperature", error.value, error.unit, error.allowed) from None
    iso = None
    if section.iso is not None:
        iso = IsoScuffingData(
            section.iso.fzg_load_stage,
            base_oil=section.iso.base_oil,
            roughness_ra=0.5 * (p.roughness_ra + w.roughness_ra),
            structural_factor=section.iso.structural_factor,
            lubrication=section.iso.lubrication,
            reduced_modulus=surfaces.modulus,
            flash_method=section.flash.method if section.flash is not None else "iso_cylindrical",
        )
    record = None
    if section.calibration is not None:
        record = read_test_record(context.path(section.calibration), "calibration")
    return GearStudy(
        mesh=mesh,
        oil_temperature=section.oil_temperature,
        critical_temperature=section.critical_temperature,
        thermal_coefficient=section.thermal_coefficient,
        calibration=record,
        torques=np.asarray(section.test.torque_steps(), dtype=float),
        speeds=np.asarray(section.test.speeds, dtype=float),
        fzg_load_stages=None if section.test.fzg_load_stages is None else tuple(section.test.fzg_load_stages),
        iso=iso,
    )
