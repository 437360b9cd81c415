"""Case-file section ``[cpp]``: blade-bearing friction, fretting and carrier motion."""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from shaftline.cases._base import Quantity, Strict
from shaftline.cpp.hydraulics import oil_spring_stiffness
from shaftline.cpp.loads import BladeBearing, BladeLoads, centrifugal_point_mass
from shaftline.csvio import read_columns
from shaftline.errors import InputError
from shaftline.units import to_si


class HarmonicIn(Strict):
    component: str  # force_x ... moment_z
    order: int
    amplitude: Quantity
    phase: Quantity = 0.0


class LoadsIn(Strict):
    table: str | None = None
    mean_force: list[Quantity] | None = None
    mean_moment: list[Quantity] | None = None
    harmonics: list[HarmonicIn] = []
    centrifugal_force: list[Quantity] | None = None
    centrifugal_moment: list[Quantity] | None = None
    blade_mass: Quantity | None = None
    centre_of_gravity: list[Quantity] | None = None
    points: int = 720


class BladeBearingIn(Strict):
    radius: Quantity
    friction_coefficient: float
    axial_radius: Quantity
    carrier_radius: Quantity
    thickness: Quantity
    youngs_modulus: Quantity = 120e9


class HydraulicsIn(Strict):
    bulk_modulus: Quantity = 1.5e9
    oil_volume: Quantity
    yoke_area: Quantity
    pin_radius: Quantity
    backlash: Quantity = 0.0
    other_friction: Quantity = 0.0
    counterbalance_pressure: Quantity = 0.0
    column_length: Quantity | None = None


class MotionIn(Strict):
    inertia: Quantity
    water_inertia: Quantity = 0.0
    friction: str = "lugre"
    revolutions: int = 20
    stiffness: Quantity = 5e10
    damping: Quantity = 1e8
    stribeck_velocity: Quantity = 0.002
    threshold_velocity: Quantity = 1e-4


class StudyIn(Strict):
    parameter: str
    values: list[Quantity | str]
    revolutions: int = 10


class CppIn(Strict):
    blades: int
    shaft_speed: Quantity
    propeller_diameter: Quantity
    pitch_angle: Quantity
    bearing: BladeBearingIn
    loads: LoadsIn
    hydraulics: HydraulicsIn
    motion: MotionIn | None = None
    study: StudyIn | None = None


STUDY_KINDS = {
    "holding_moment": "moment",
    "backlash": "length",
    "oil_stiffness": "stiffness",
    "water_inertia": "inertia",
    "spindle_scale": "dimensionless",
}


def read_load_table(path) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Blade loads over a revolution from CSV: angle_deg, force_x, force_y, force_z (N),
    moment_x, moment_y, moment_z (N m), one row per blade angle within one turn."""
    columns = ["angle_deg", "force_x", "force_y", "force_z", "moment_x", "moment_y", "moment_z"]
    data = read_columns(path, columns, "cpp.loads.table", order_matters=True)
    table = np.column_stack([data[name] for name in columns])
    angle = np.radians(table[:, 0])
    if angle.size < 8 or np.any(np.diff(angle) <= 0) or angle[-1] - angle[0] >= 2 * math.pi:
        raise InputError("cpp.loads.table", str(path), "", "at least 8 increasing angles within one turn")
    return angle, table[:, 1:4], table[:, 4:7]


@dataclass(frozen=True)
class CppCase:
    """Blade-bearing inputs in SI."""

    blades: int
    speed: float
    radius_07: float
    pitch_angle: float
    bearing: BladeBearing
    loads: BladeLoads
    oil_stiffness: float
    yoke_area: float
    pin_radius: float
    backlash: float
    other_friction: float
    counterbalance_pressure: float
    motion: dict | None
    study: dict | None = None


def _vector(values: list[Quantity], kind: str, where: str) -> np.ndarray:
    if len(values) != 3:
        raise InputError(where, len(values), "components", "three (x, y, z)")
    return np.array([to_si(v, kind, f"{where}[{k}]") for k, v in enumerate(values)])


def build_cpp(data: CppIn, base_dir=None) -> CppCase:
    if not 2 <= data.blades <= 8:
        raise InputError("cpp.blades", data.blades, "", "2 to 8")
    speed = to_si(data.shaft_speed, "speed", "cpp.shaft_speed")
    diameter = to_si(data.propeller_diameter, "length", "cpp.propeller_diameter")
    if speed <= 0 or diameter <= 0:
        raise InputError("cpp.shaft_speed", speed, "rad/s", "> 0 (and a positive diameter)")
    b = data.bearing
    bearing = BladeBearing(
        to_si(b.radius, "length", "cpp.bearing.radius"),
        b.friction_coefficient,
        to_si(b.axial_radius, "length", "cpp.bearing.axial_radius"),
        to_si(b.carrier_radius, "length", "cpp.bearing.carrier_radius"),
        to_si(b.thickness, "length", "cpp.bearing.thickness"),
        to_si(b.youngs_modulus, "pressure", "cpp.bearing.youngs_modulus"),
    )
    ld = data.loads
    if ld.centrifugal_force is not None and ld.centrifugal_moment is not None:
        f_ce = _vector(ld.centrifugal_force, "force", "cpp.loads.centrifugal_force")
        m_ce = _vector(ld.centrifugal_moment, "moment", "cpp.loads.centrifugal_moment")
    elif ld.blade_mass is not None and ld.centre_of_gravity is not None:
        f_ce, m_ce = centrifugal_point_mass(
            to_si(ld.blade_mass, "mass", "cpp.loads.blade_mass"),
            _vector(ld.centre_of_gravity, "length", "cpp.loads.centre_of_gravity"),
            speed,
        )
    else:
        raise InputError(
            "cpp.loads.centrifugal_force",
            "missing",
            "",
            "centrifugal_force and centrifugal_moment, or blade_mass and centre_of_gravity",
        )
    harmonics: dict[str, list] = {}
    for k, h in enumerate(ld.harmonics):
        kind = "moment" if h.component.startswith("moment") else "force"
        harmonics.setdefault(h.component, []).append(
            (
                h.order,
                to_si(h.amplitude, kind, f"cpp.loads.harmonics[{k}].amplitude"),
                to_si(h.phase, "angle", f"cpp.loads.harmonics[{k}].phase"),
            )
        )
    if ld.table is not None:
        from pathlib import Path

        path = Path(ld.table)
        angle, force, moment = read_load_table(path if path.is_absolute() else (base_dir or Path.cwd()) / path)
        loads = BladeLoads(angle, force, moment, f_ce, m_ce)
    else:
        if ld.mean_force is None or ld.mean_moment is None:
            raise InputError("cpp.loads.mean_force", "missing", "", "mean_force and mean_moment, or a load table")
        if ld.points < 36:
            raise InputError("cpp.loads.points", ld.points, "", ">= 36 per revolution")
        angle = np.linspace(0.0, 2 * math.pi, ld.points, endpoint=False)
        loads = BladeLoads.from_harmonics(
            angle,
            _vector(ld.mean_force, "force", "cpp.loads.mean_force"),
            _vector(ld.mean_moment, "moment", "cpp.loads.mean_moment"),
            harmonics,
            f_ce,
            m_ce,
        )
    hy = data.hydraulics
    volume = to_si(hy.oil_volume, "volume", "cpp.hydraulics.oil_volume")
    area = to_si(hy.yoke_area, "area", "cpp.hydraulics.yoke_area")
    column = None if hy.column_length is None else to_si(hy.column_length, "length", "cpp.hydraulics.column_length")
    k_oil = oil_spring_stiffness(
        to_si(hy.bulk_modulus, "pressure", "cpp.hydraulics.bulk_modulus"), volume, area, column
    )
    motion = None
    if data.motion is not None:
        m = data.motion
        motion = {
            "inertia": to_si(m.inertia, "inertia", "cpp.motion.inertia"),
            "water_inertia": to_si(m.water_inertia, "inertia", "cpp.motion.water_inertia"),
            "friction": m.friction,
            "revolutions": m.revolutions,
            "stiffness": to_si(m.stiffness, "rotational_stiffness", "cpp.motion.stiffness"),
            "damping": to_si(m.damping, "rotational_damping", "cpp.motion.damping"),
            "stribeck_velocity": to_si(m.stribeck_velocity, "speed", "cpp.motion.stribeck_velocity"),
            "threshold_velocity": to_si(m.threshold_velocity, "speed", "cpp.motion.threshold_velocity"),
        }
    study = None
    if data.study is not None:
        st = data.study
        if st.parameter == "friction":
            values = [str(v) for v in st.values]
        elif st.parameter in STUDY_KINDS:
            values = [to_si(v, STUDY_KINDS[st.parameter], f"cpp.study.values[{k}]") for k, v in enumerate(st.values)]
        else:
            raise InputError("cpp.study.parameter", st.parameter, "", "one of friction, " + ", ".join(STUDY_KINDS))
        if data.motion is None:
            raise InputError("cpp.study", st.parameter, "", "a [cpp.motion] section to vary")
        study = {"parameter": st.parameter, "values": values, "revolutions": st.revolutions}
    return CppCase(
        data.blades,
        speed,
        0.35 * diameter,
        to_si(data.pitch_angle, "angle", "cpp.pitch_angle"),
        bearing,
        loads,
        k_oil,
        area,
        to_si(hy.pin_radius, "length", "cpp.hydraulics.pin_radius"),
        to_si(hy.backlash, "length", "cpp.hydraulics.backlash"),
        to_si(hy.other_friction, "force", "cpp.hydraulics.other_friction"),
        to_si(hy.counterbalance_pressure, "pressure", "cpp.hydraulics.counterbalance_pressure"),
        motion,
        study,
    )
