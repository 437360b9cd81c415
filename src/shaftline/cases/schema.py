"""Case-file schema (pydantic) and its conversion to the SI domain objects.

A quantity is a number (SI, temperatures in degC) or a string with a unit
(``"0.45 mm"``, ``"90 rpm"``, ``"40 degC"``). Unknown keys are errors, so a
misspelt field is reported rather than silently ignored.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np
from pydantic import model_validator

from shaftline.cases._base import Quantity, Strict
from shaftline.cases.alignment_schema import (
    AlignmentBearingIn,
    AlignmentCase,
    AlignmentIn,
    ConditionIn,
    DistributedLoadIn,
    MassIn,
    PointLoadIn,
    PropellerIn,
    ShaftIn,
    build_alignment,
)
from shaftline.cases.cpp_schema import CppCase, CppIn, build_cpp
from shaftline.cases.wear_schema import WearCase, WearIn, build_wear
from shaftline.csvio import read_columns
from shaftline.errors import InputError
from shaftline.film.bearing import OperatingPoint, SolverOptions, SupplyGroove
from shaftline.film.geometry import BearingGeometry, BentJournal, BoreSegment, FilmProfile
from shaftline.lubricants import Lubricant
from shaftline.units import to_si

ROTATIONS = {
    "clockwise": 1,
    "clockwise_from_aft": 1,
    "cw": 1,
    "anticlockwise": -1,
    "counterclockwise": -1,
    "anticlockwise_from_aft": -1,
    "ccw": -1,
}


class CaseInfo(Strict):
    name: str = "unnamed case"
    description: str = ""


class BoreSegmentIn(Strict):
    length_fraction: float
    slope: Quantity | None = None
    slope_ratio: float | None = None
    slope_horizontal: Quantity = 0.0

    @model_validator(mode="after")
    def _one_slope(self) -> BoreSegmentIn:
        if self.slope is not None and self.slope_ratio is not None:
            raise ValueError("give either slope (an angle) or slope_ratio (a share of 2c/L), not both")
        return self


class BentJournalIn(Strict):
    z: list[Quantity]
    dy: list[Quantity]
    dz: list[Quantity] | None = None


class FilmProfileIn(Strict):
    file: str
    length_unit: str = "m"


class BearingIn(Strict):
    length: Quantity
    diameter: Quantity
    radial_clearance: Quantity | None = None
    diametral_clearance: Quantity | None = None
    rotation: str = "clockwise"
    bore_anchor: str = "fore"
    bore: list[BoreSegmentIn] = []
    bent_journal: BentJournalIn | None = None
    film_profile: FilmProfileIn | None = None

    @model_validator(mode="after")
    def _one_clearance(self) -> BearingIn:
        if (self.radial_clearance is None) == (self.diametral_clearance is None):
            raise ValueError("give exactly one of radial_clearance or diametral_clearance")
        return self


class GrooveIn(Strict):
    angle: Quantity
    pressure: Quantity = 0.0
    length_fraction: float = 1.0


class OperationIn(Strict):
    speed: Quantity
    load: Quantity
    load_horizontal: Quantity = 0.0
    tilt_vertical: Quantity | None = None
    tilt_horizontal: Quantity | None = None
    misalignment_ratio_vertical: float | None = None
    misalignment_ratio_horizontal: float | None = None
    aft_pressure: Quantity = 0.0
    fore_pressure: Quantity = 0.0
    cavitation_pressure: Quantity = 0.0
    grooves: list[GrooveIn] = []

    @model_validator(mode="after")
    def _one_tilt(self) -> OperationIn:
        if self.tilt_vertical is not None and self.misalignment_ratio_vertical is not None:
            raise ValueError("give either tilt_vertical or misalignment_ratio_vertical, not both")
        if self.tilt_horizontal is not None and self.misalignment_ratio_horizontal is not None:
            raise ValueError("give either tilt_horizontal or misalignment_ratio_horizontal, not both")
        return self


class LubricantIn(Strict):
    viscosity: Quantity | None = None
    preset: str | None = None
    temperature: Quantity | None = None
    density: Quantity | None = None
    kinematic_viscosity_1: Quantity | None = None
    temperature_1: Quantity | None = None
    kinematic_viscosity_2: Quantity | None = None
    temperature_2: Quantity | None = None
    name: str | None = None

    @model_validator(mode="after")
    def _one_source(self) -> LubricantIn:
        two_points = self.kinematic_viscosity_1 is not None or self.kinematic_viscosity_2 is not None
        sources = sum([self.viscosity is not None, self.preset is not None, two_points])
        if sources != 1:
            raise ValueError(
                "give exactly one of: viscosity; preset with temperature; "
                "kinematic_viscosity_1/temperature_1/kinematic_viscosity_2/temperature_2 with temperature"
            )
        if (self.preset is not None or two_points) and self.temperature is None:
            raise ValueError("temperature is needed with a preset or a two-point viscosity")
        return self


class SolverIn(Strict):
    axial_nodes: int = 41
    circumferential_nodes: int = 120
    cavitation: str = "reynolds"
    film_start: str = "periodic"
    cavitated_shear: str = "film_fraction"
    min_film_floor: float = 1e-3


class VariantIn(Strict):
    name: str
    bore: list[BoreSegmentIn] | None = None
    misalignment_ratio_vertical: float | None = None
    tilt_vertical: Quantity | None = None


class CaseIn(Strict):
    case: CaseInfo = CaseInfo()
    # Stern-tube bearing film (all three or none).
    bearing: BearingIn | None = None
    operation: OperationIn | None = None
    lubricant: LubricantIn | None = None
    solver: SolverIn = SolverIn()
    variants: list[VariantIn] = []
    # Shaft alignment.
    shaft: ShaftIn | None = None
    bearings: list[AlignmentBearingIn] = []
    loads: list[PointLoadIn] = []
    masses: list[MassIn] = []
    distributed_loads: list[DistributedLoadIn] = []
    propeller: PropellerIn | None = None
    conditions: list[ConditionIn] = []
    alignment: AlignmentIn | None = None
    # Service wear of a CPP blade bearing.
    wear: WearIn | None = None
    # CPP blade-bearing friction, fretting and carrier motion.
    cpp: CppIn | None = None

    @model_validator(mode="after")
    def _something_to_do(self) -> CaseIn:
        film = [self.bearing is not None, self.operation is not None, self.lubricant is not None]
        if any(film) and not all(film):
            missing = [n for n, given in zip(("bearing", "operation", "lubricant"), film, strict=True) if not given]
            raise ValueError(
                f"a bearing-film case needs [bearing], [operation] and [lubricant]; missing [{missing[0]}]"
            )
        alignment_parts = bool(self.bearings or self.loads or self.masses or self.conditions or self.propeller)
        if alignment_parts and self.shaft is None:
            raise ValueError("alignment inputs need a [shaft] with [[shaft.segments]]")
        if self.shaft is not None and not self.bearings:
            raise ValueError("a [shaft] needs its [[bearings]]")
        if not any(film) and self.shaft is None and self.wear is None and self.cpp is None:
            raise ValueError(
                "nothing to solve: give a bearing film ([bearing], [operation], [lubricant]), "
                "a [shaft], [wear] or [cpp]"
            )
        return self


# -- domain objects -------------------------------------------------------------------------


@dataclass(frozen=True)
class BearingCase:
    """One bearing problem in SI units: what :func:`shaftline.film.JournalBearing` needs plus the load.

    Attributes
    ----------
    name : str
        Label of the case or variant.
    geometry, operating, options :
        Inputs of :class:`shaftline.film.JournalBearing`.
    load_y, load_z : float
        Applied load on the journal, N (``load_y < 0`` downwards).
    tilt_y, tilt_z : float
        Journal tilt relative to the nominal bore axis, rad.
    lubricant : Lubricant
        The lubricant (for the report).
    temperature : float or None
        Effective film temperature, degC, where given.
    """

    name: str
    geometry: BearingGeometry
    operating: OperatingPoint
    options: SolverOptions
    load_y: float
    load_z: float
    tilt_y: float
    tilt_z: float
    lubricant: Lubricant
    temperature: float | None = None


@dataclass(frozen=True)
class Case:
    """A parsed case file: a title, the bearing-film problems (base case first) and an alignment."""

    name: str
    description: str
    bearings: list[BearingCase] = field(default_factory=list)
    alignment: AlignmentCase | None = None
    wear: WearCase | None = None
    cpp: CppCase | None = None


def _lubricant(data: LubricantIn) -> tuple[Lubricant, float, float, float | None]:
    """(lubricant, viscosity Pa*s, density kg/m^3, temperature degC or None)."""
    temperature = None
    if data.temperature is not None:
        temperature = to_si(data.temperature, "temperature", "lubricant.temperature")
    if temperature is not None and not -40.0 <= temperature <= 250.0:
        raise InputError("lubricant.temperature", temperature, "degC", "in [-40, 250]")
    if data.viscosity is not None:
        viscosity = to_si(data.viscosity, "viscosity", "lubricant.viscosity")
        if viscosity <= 0:
            raise InputError("lubricant.viscosity", viscosity, "Pa*s", "> 0")
        density = 880.0 if data.density is None else to_si(data.density, "density", "lubricant.density")
        if density <= 0:
            raise InputError("lubricant.density", density, "kg/m^3", "> 0")
        lubricant = Lubricant.constant(viscosity, density, name=data.name or "constant viscosity")
        return lubricant, viscosity, density, temperature
    if data.preset is not None:
        lubricant = Lubricant.preset(data.preset)
    else:
        missing = [
            name
            for name in ("kinematic_viscosity_1", "temperature_1", "kinematic_viscosity_2", "temperature_2")
            if getattr(data, name) is None
        ]
        if missing:
            raise InputError(f"lubricant.{missing[0]}", "missing", "", "all four two-point fields")
        density15 = 880.0 if data.density is None else to_si(data.density, "density", "lubricant.density")
        lubricant = Lubricant.from_two_points(
            data.name or "two-point oil",
            to_si(data.temperature_1, "temperature", "lubricant.temperature_1"),
            to_si(data.kinematic_viscosity_1, "kinematic_viscosity", "lubricant.kinematic_viscosity_1"),
            to_si(data.temperature_2, "temperature", "lubricant.temperature_2"),
            to_si(data.kinematic_viscosity_2, "kinematic_viscosity", "lubricant.kinematic_viscosity_2"),
            density15,
        )
    assert temperature is not None  # checked by the schema
    return (
        lubricant,
        float(lubricant.dynamic_viscosity(temperature)),
        float(lubricant.density(temperature)),
        temperature,
    )


def _bore(segments: list[BoreSegmentIn], where: str, length: float, clearance: float) -> tuple[BoreSegment, ...]:
    out = []
    for k, segment in enumerate(segments):
        if segment.slope_ratio is not None:
            slope = segment.slope_ratio * 2.0 * clearance / length
        elif segment.slope is not None:
            slope = to_si(segment.slope, "angle", f"{where}[{k}].slope")
        else:
            raise InputError(f"{where}[{k}].slope", "missing", "rad", "an angle, or slope_ratio")
        out.append(
            BoreSegment(
                length_fraction=segment.length_fraction,
                slope=slope,
                slope_horizontal=to_si(segment.slope_horizontal, "angle", f"{where}[{k}].slope_horizontal"),
            )
        )
    return tuple(out)


def _tilt(value: Quantity | None, ratio: float | None, field_name: str, length: float, clearance: float) -> float:
    if ratio is not None:
        if not math.isfinite(ratio):
            raise InputError(field_name.replace("tilt", "misalignment_ratio"), ratio, "", "a finite number")
        return ratio * 2.0 * clearance / length
    if value is None:
        return 0.0
    return to_si(value, "angle", field_name)


def read_film_profile(path: Path, length_unit: str = "m") -> FilmProfile:
    """Read an additive film profile from CSV: columns ``theta_deg, z, delta``, one row per
    point of a full regular grid (any order); z and delta in ``length_unit``."""
    field_name = "bearing.film_profile.file"
    scale = to_si(f"1 {length_unit}", "length", "bearing.film_profile.length_unit")
    table = read_columns(path, ["theta_deg", "z", "delta"], field_name)
    theta = np.unique(table["theta_deg"])
    z = np.unique(table["z"])
    if theta.size * z.size != table["z"].size:
        raise InputError(field_name, str(path), "", f"a full grid of {theta.size} angles x {z.size} stations")
    delta = np.full((z.size, theta.size), np.nan)
    delta[np.searchsorted(z, table["z"]), np.searchsorted(theta, table["theta_deg"])] = table["delta"]
    if np.isnan(delta).any():
        raise InputError(field_name, str(path), "", "each (theta_deg, z) pair exactly once")
    return FilmProfile(theta=np.radians(theta), z=z * scale, delta=delta * scale)


def build_case(data: CaseIn, base_dir: Path | None = None) -> Case:
    """Convert a validated case file into SI domain objects (raises :class:`InputError`).

    ``base_dir`` is the folder that relative file names in the case are read from.
    """
    alignment = None
    if data.shaft is not None:
        alignment = build_alignment(
            data.shaft,
            data.bearings,
            data.loads,
            data.masses,
            data.distributed_loads,
            data.propeller,
            data.conditions,
            data.alignment,
            base_dir,
        )
    bearings = _build_film(data, base_dir) if data.bearing is not None else []
    wear = build_wear(data.wear, base_dir) if data.wear is not None else None
    cpp = build_cpp(data.cpp, base_dir) if data.cpp is not None else None
    return Case(
        name=data.case.name,
        description=data.case.description,
        bearings=bearings,
        alignment=alignment,
        wear=wear,
        cpp=cpp,
    )


def _build_film(data: CaseIn, base_dir: Path | None) -> list[BearingCase]:
    b = data.bearing
    length = to_si(b.length, "length", "bearing.length")
    diameter = to_si(b.diameter, "length", "bearing.diameter")
    if b.radial_clearance is not None:
        clearance = to_si(b.radial_clearance, "length", "bearing.radial_clearance")
    else:
        clearance = 0.5 * to_si(b.diametral_clearance, "length", "bearing.diametral_clearance")
    if clearance <= 0:
        name = "bearing.radial_clearance" if b.radial_clearance is not None else "bearing.diametral_clearance"
        shown = clearance if b.radial_clearance is not None else 2 * clearance
        raise InputError(name, shown, "m", "> 0")
    for name, value in (("bearing.length", length), ("bearing.diameter", diameter)):
        if value <= 0:
            raise InputError(name, value, "m", "> 0")
    rotation = ROTATIONS.get(b.rotation.strip().lower())
    if rotation is None:
        raise InputError("bearing.rotation", b.rotation, "", "clockwise or anticlockwise (seen from aft)")
    bent = None
    if b.bent_journal is not None:
        bj = b.bent_journal
        z = [to_si(v, "length", f"bearing.bent_journal.z[{k}]") for k, v in enumerate(bj.z)]
        dy = [to_si(v, "length", f"bearing.bent_journal.dy[{k}]") for k, v in enumerate(bj.dy)]
        dz = [to_si(v, "length", f"bearing.bent_journal.dz[{k}]") for k, v in enumerate(bj.dz)] if bj.dz else None
        bent = BentJournal(z=z, dy=dy, dz=dz if dz is not None else [0.0] * len(z))
    profile = None
    if b.film_profile is not None:
        profile_path = Path(b.film_profile.file)
        if not profile_path.is_absolute():
            profile_path = (base_dir or Path.cwd()) / profile_path
        profile = read_film_profile(profile_path, b.film_profile.length_unit)
    geometry = BearingGeometry(
        length=length,
        diameter=diameter,
        radial_clearance=clearance,
        bore=_bore(b.bore, "bearing.bore", length, clearance),
        bore_anchor=b.bore_anchor,
        bent_journal=bent,
        film_profile=profile,
        rotation=rotation,
    )
    op = data.operation
    lubricant, viscosity, density, temperature = _lubricant(data.lubricant)
    speed = to_si(op.speed, "speed", "operation.speed")
    load = to_si(op.load, "force", "operation.load")
    if speed < 0:
        raise InputError("operation.speed", speed, "rad/s", ">= 0")
    if load < 0:
        raise InputError("operation.load", load, "N", ">= 0 (the magnitude of a downward load)")
    load_z = to_si(op.load_horizontal, "force", "operation.load_horizontal")
    if speed == 0 and (load > 0 or load_z != 0):
        raise InputError("operation.speed", 0.0, "rad/s", "> 0 when the bearing carries a load")
    if load == 0 and load_z == 0:
        raise InputError("operation.load", 0.0, "N", "> 0")
    grooves = tuple(
        SupplyGroove(
            angle=to_si(g.angle, "angle", f"operation.grooves[{k}].angle"),
            pressure=to_si(g.pressure, "pressure", f"operation.grooves[{k}].pressure"),
            length_fraction=g.length_fraction,
        )
        for k, g in enumerate(op.grooves)
    )
    operating = OperatingPoint(
        speed=speed,
        viscosity=viscosity,
        density=density,
        aft_pressure=to_si(op.aft_pressure, "pressure", "operation.aft_pressure"),
        fore_pressure=to_si(op.fore_pressure, "pressure", "operation.fore_pressure"),
        cavitation_pressure=to_si(op.cavitation_pressure, "pressure", "operation.cavitation_pressure"),
        grooves=grooves,
    )
    s = data.solver
    options = SolverOptions(
        axial_nodes=s.axial_nodes,
        circumferential_nodes=s.circumferential_nodes,
        cavitation=s.cavitation,
        film_start=s.film_start,
        cavitated_shear=s.cavitated_shear,
        min_film_floor=s.min_film_floor,
    )
    # Validate the grid now so that a coarse grid is reported before any solving.
    from shaftline.film.geometry import Grid

    Grid(length, s.axial_nodes, s.circumferential_nodes)
    tilt_y = _tilt(op.tilt_vertical, op.misalignment_ratio_vertical, "operation.tilt_vertical", length, clearance)
    tilt_z = _tilt(op.tilt_horizontal, op.misalignment_ratio_horizontal, "operation.tilt_horizontal", length, clearance)
    base = BearingCase(
        name=data.case.name,
        geometry=geometry,
        operating=operating,
        options=options,
        load_y=-load,
        load_z=load_z,
        tilt_y=tilt_y,
        tilt_z=tilt_z,
        lubricant=lubricant,
        temperature=temperature,
    )
    bearings = [base]
    names = {base.name}
    for k, variant in enumerate(data.variants):
        if variant.name in names:
            raise InputError(f"variants[{k}].name", variant.name, "", "a name not used before in the case")
        names.add(variant.name)
        new_geometry = geometry
        if variant.bore is not None:
            new_geometry = BearingGeometry(
                length=length,
                diameter=diameter,
                radial_clearance=clearance,
                bore=_bore(variant.bore, f"variants[{k}].bore", length, clearance),
                bore_anchor=b.bore_anchor,
                bent_journal=bent,
                film_profile=profile,
                rotation=rotation,
            )
        new_tilt = tilt_y
        if variant.misalignment_ratio_vertical is not None or variant.tilt_vertical is not None:
            new_tilt = _tilt(
                variant.tilt_vertical,
                variant.misalignment_ratio_vertical,
                f"variants[{k}].tilt_vertical",
                length,
                clearance,
            )
        bearings.append(
            BearingCase(
                name=variant.name,
                geometry=new_geometry,
                operating=operating,
                options=options,
                load_y=-load,
                load_z=load_z,
                tilt_y=new_tilt,
                tilt_z=tilt_z,
                lubricant=lubricant,
                temperature=temperature,
            )
        )
    return bearings
