"""The ``[cpp]`` table of a case file: blade-bearing friction, fretting and carrier motion
of a controllable-pitch propeller (seed 000 Ch. 3-4).

Layout::

    [cpp]                   blades, speed, diameter, pitch
    [cpp.bearing]           the blade bearing
    [cpp.loads]             blade loads: a CSV table, or mean values and harmonics
    [[cpp.loads.harmonics]]
    [cpp.hydraulics]        oil spring, backlash, pressures
    [cpp.motion]            blade-carrier fretting motion
    [cpp.study]             one parameter varied (Sect. 4.7)
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING, Annotated, Any, Literal

from pydantic import Field, StrictBool, StrictFloat, StrictInt, model_validator

from shaftline.cases.types import (
    SHAFT_SPEED,
    Angle,
    Force,
    Length,
    Moment,
    NonNegativeInertia,
    NonNegativeLength,
    Plausible,
    PlausibleRatio,
    PositiveArea,
    PositiveInertia,
    PositiveLength,
    PositiveMass,
    PositivePressure,
    PositiveSpeed,
    PositiveVolume,
    Pressure,
    Quantity,
    Section,
    default_of,
    field_error,
)
from shaftline.cpp.loads import BladeBearing
from shaftline.cpp.motion import CarrierModel, MethodName
from shaftline.cpp.study import CarrierMotionRequest
from shaftline.errors import InputError, located
from shaftline.registry import BuildContext

if TYPE_CHECKING:
    from shaftline.cpp.study import BladeBearingStudy

Component = Literal["force_x", "force_y", "force_z", "moment_x", "moment_y", "moment_z"]
StudyParameter = Literal["holding_moment", "spindle_scale", "backlash", "friction", "oil_stiffness", "water_inertia"]

#: The quantity of the values of each study parameter, with its allowed range (friction
#: takes law names instead).
STUDY_VALUES = {
    "holding_moment": Quantity("moment"),
    "backlash": Quantity("length", ge=0),
    "oil_stiffness": Quantity("stiffness", gt=0),
    "water_inertia": Quantity("inertia", ge=0),
    "spindle_scale": Quantity("dimensionless", gt=0),
}


# Plausible ranges of a CPP blade bearing (the README's table of plausible ranges is made from
# them): generous, to catch a unit slip, not an unusual propeller ([case] unusual).
_SEED = "seed 000"
_EXAMPLE = "examples/cpp_blade_bearing.toml"
BLADE_FORCE = Plausible(
    -3e7,
    3e7,
    "thrust per blade of the largest CPPs is about 1 MN and the centrifugal force of a 10-20 t blade a few MN "
    f"({_EXAMPLE}: 95 kN); 30 MN is ten times beyond (engineering judgement)",
)
BLADE_MOMENT = Plausible(
    -5e7,
    5e7,
    f"blade-root moments of the largest CPPs are a few MN m ({_EXAMPLE}: 190 kN m; {_SEED} Sect. 4.7: "
    "hydraulic moments up to 0.3 MN m); 50 MN m is ten times beyond (engineering judgement)",
)
BLADE_RADIUS = Plausible(
    0.02,
    2.0,
    f"blade-bearing radii are about 0.1-0.2 of the propeller diameter ({_SEED} Ch. 6: 0.392 m); 2 m would fit a "
    "15 m propeller (engineering judgement); mm written as m is far above",
)
PITCH_ANGLE = Plausible(
    0.05,
    1.05,
    f"3 to 60 deg: design pitch angles at 0.7 R are about 13-36 deg for P/D 0.6-1.6 ({_SEED}: 28 deg) "
    "(engineering judgement)",
)


class HarmonicSection(Section):
    """A harmonic of a blade-load component over the blade angle: amplitude cos(order angle + phase)."""

    component: Component
    """Load component (blade axes: x along the shaft, z along the spindle)."""
    order: Annotated[int, Field(ge=1)]
    """Order (per revolution)."""
    amplitude: StrictFloat | StrictInt | str
    """Amplitude: a force (N) for force components, a moment (N m) for moment components."""
    phase: Annotated[
        Angle,
        Plausible(
            -2 * math.pi, 2 * math.pi, "a phase: a turn either way; deg as a bare number (rad) is beyond from 7 deg on"
        ),
    ] = 0.0
    """Phase."""


class LoadsSection(Section):
    """Loads on one blade at the blade-bearing centre over a revolution."""

    table: str | None = None
    """CSV: angle_deg, force_x, force_y, force_z (N), moment_x, moment_y, moment_z (N m), one row per
    blade angle within one turn; path relative to the case file."""
    mean_force: Annotated[list[Annotated[Force, BLADE_FORCE]], Field(min_length=3, max_length=3)] | None = None
    """Mean hydrodynamic force (x, y, z), without a table."""
    mean_moment: Annotated[list[Annotated[Moment, BLADE_MOMENT]], Field(min_length=3, max_length=3)] | None = None
    """Mean hydrodynamic moment (x, y, z), without a table."""
    harmonics: list[HarmonicSection] = []
    """Harmonics added to the mean values."""
    centrifugal_force: Annotated[list[Annotated[Force, BLADE_FORCE]], Field(min_length=3, max_length=3)] | None = None
    """Centrifugal force (x, y, z); or blade_mass and centre_of_gravity."""
    centrifugal_moment: Annotated[list[Annotated[Moment, BLADE_MOMENT]], Field(min_length=3, max_length=3)] | None = (
        None
    )
    """Centrifugal moment (x, y, z)."""
    blade_mass: (
        Annotated[
            PositiveMass,
            Plausible(
                0.5,
                1e5,
                f"CPP blades weigh from about a kg (small craft) to some tens of t ({_EXAMPLE}: 2.6 t); the "
                "cross-field check below catches a mass in t written in kg (engineering judgement)",
            ),
        ]
        | None
    ) = None
    """Blade mass (centrifugal load of a point mass)."""
    centre_of_gravity: (
        Annotated[
            list[
                Annotated[
                    Length,
                    Plausible(
                        -10.0,
                        10.0,
                        f"within the blade: less than the propeller radius ({_EXAMPLE}: up to 0.55 m); mm written "
                        "as m is beyond",
                    ),
                ]
            ],
            Field(min_length=3, max_length=3),
        ]
        | None
    ) = None
    """Blade centre of gravity from the bearing centre (x, y, z)."""
    points: Annotated[int, Field(ge=36)] = 720
    """Blade angles per revolution of harmonic loads."""

    @model_validator(mode="after")
    def _sources(self) -> LoadsSection:
        if self.table is None and (self.mean_force is None or self.mean_moment is None):
            raise field_error("mean_force", "missing", "mean_force and mean_moment, or a load table")
        given = self.centrifugal_force is not None and self.centrifugal_moment is not None
        point_mass = self.blade_mass is not None and self.centre_of_gravity is not None
        if not (given or point_mass):
            raise field_error(
                "centrifugal_force",
                "missing",
                "centrifugal_force and centrifugal_moment, or blade_mass and centre_of_gravity",
            )
        return self


class BladeBearingSection(Section):
    """The blade bearing: flange (radial part) and cylindrical seat (axial part)."""

    radius: Annotated[PositiveLength, BLADE_RADIUS]
    """Mean radius of the flange (where sliding and fretting are counted)."""
    friction_coefficient: Annotated[
        float,
        Quantity("dimensionless", gt=0, lt=1),
        Plausible(
            0.005,
            0.6,
            f"bronze on steel, lubricated to dry, about 0.05-0.3 ({_SEED} Tables 4.1-4.2, Ch. 5) (engineering "
            "judgement)",
        ),
    ]
    """Coefficient of friction of the bearing."""
    axial_radius: Annotated[PositiveLength, BLADE_RADIUS]
    """Radius of the bore of the axial part."""
    carrier_radius: Annotated[PositiveLength, BLADE_RADIUS]
    """Radius of the blade carrier in it."""
    thickness: Annotated[
        PositiveLength,
        Plausible(
            0.001, 0.5, f"the axial part of the bearing is some cm thick ({_EXAMPLE}: 0.12 m); mm written as m is above"
        ),
    ]
    """Thickness of the axial part."""
    youngs_modulus: Annotated[
        PositivePressure,
        Plausible(
            5e8,
            5e11,
            "bronzes about 100-130 GPa (CuNiAl 120 GPa), steels 210, polymer-lined bearings down to about 1 GPa "
            "(engineering judgement); GPa written as a bare number (Pa) is far below",
        ),
    ] = default_of(BladeBearing, "youngs_modulus")
    """Young's modulus of the bearing material."""


class HydraulicsSection(Section):
    """The pitch-control hydraulics behind the yoke."""

    bulk_modulus: Annotated[
        PositivePressure,
        Plausible(
            1e8,
            5e9,
            f"mineral oil about 1.5-2 GPa, with entrained air ten times less ({_SEED} Sect. 4.7.3); GPa written as "
            "a bare number (Pa) is far below",
        ),
    ] = 1.5e9
    """Bulk modulus of the oil."""
    oil_volume: Annotated[
        PositiveVolume,
        Plausible(
            1e-4,
            10.0,
            f"from about a litre in a small hub to some m^3 ({_EXAMPLE}: 250 l) (engineering judgement); litres "
            "written as a bare number (m^3) are above 10 m^3",
        ),
    ]
    """Oil volume behind the yoke."""
    yoke_area: Annotated[
        PositiveArea,
        Plausible(
            1e-3,
            10.0,
            f"yoke pistons from about 10 cm^2 to a few m^2 ({_EXAMPLE}: 0.95 m^2) (engineering judgement); cm^2 "
            "written as a bare number (m^2) is above",
        ),
    ]
    """Piston (yoke) area."""
    pin_radius: Annotated[PositiveLength, BLADE_RADIUS]
    """Eccentricity of the crank pin."""
    backlash: Annotated[
        NonNegativeLength,
        Plausible(
            0.0,
            0.005,
            f"free play of tenths of a mm ({_SEED} Sect. 4.7: 0.2 mm); 5 mm is 25 times that, mm written as a bare "
            "number (m) is far above",
        ),
    ] = 0.0
    """Total free play in the pin-slot-yoke chain."""
    other_friction: Annotated[Force, BLADE_FORCE] = 0.0
    """Friction of the other parts of the mechanism."""
    counterbalance_pressure: Annotated[
        Pressure,
        Plausible(
            -1e5,
            1e7,
            f"counterbalance valves open at a few bar ({_EXAMPLE}: 5 bar), pitch-control hydraulics run up to about "
            "100 bar (engineering judgement)",
        ),
    ] = 0.0
    """Counterbalance pressure."""
    column_length: (
        Annotated[PositiveLength, Plausible(0.01, 20.0, "an oil column in the hub and shaft (engineering judgement)")]
        | None
    ) = None
    """Length of the oil column (default: volume / area)."""


SPINDLE_INERTIA = Plausible(
    1e-3,
    1e5,
    "blade and carrier about the spindle: from about 0.01 kg m^2 of small blades to about 2e4 kg m^2 of the "
    f"largest (20 t at a radius of gyration of 1 m; {_EXAMPLE}: 650 kg m^2) (engineering judgement); t m^2 "
    "written as a bare number (kg m^2) is above",
)
_LUGRE = "a fitted model parameter: " + _SEED + " Table 4.2 gives {}; four decades either way (engineering judgement)"


class MotionSection(Section):
    """The blade-carrier fretting motion (Sect. 4.6): inertia, friction law, run length and
    integration."""

    inertia: Annotated[PositiveInertia, SPINDLE_INERTIA]
    """Blade and carrier inertia about the spindle axis."""
    water_inertia: Annotated[NonNegativeInertia, Plausible(0.0, SPINDLE_INERTIA.high, SPINDLE_INERTIA.source)] = 0.0
    """Entrained-water inertia."""
    friction: Literal["lugre", "static"] = default_of(CarrierModel, "friction")
    """LuGre (Eq. 4.13-4.15) or the finite-slope static law (Eq. 4.8)."""
    revolutions: Annotated[int, Field(ge=1, le=10000)] = 10
    """Shaft revolutions simulated at most (the last one is reported); fewer when the motion
    becomes periodic first and stop_when_periodic is on."""
    method: MethodName = default_of(CarrierMotionRequest, "method")
    """Integration method: trbdf2 (second order, L-stable), backward_euler (first order, the
    earlier default) or radau (scipy's adaptive Radau IIA, the reference, slower)."""
    stop_when_periodic: StrictBool = default_of(CarrierMotionRequest, "stop_when_periodic")
    """Stop at the first revolution at which the motion repeats the revolutions before it to
    periodic_tolerance (a cycle of up to 8 revolutions); false integrates all revolutions."""
    periodic_tolerance: Annotated[
        float,
        Quantity("dimensionless", gt=0, lt=1),
        Plausible(
            1e-9,
            1e-2,
            "the largest change of rotation and rotation rate from one cycle to the next over their "
            "peak-to-peak: the fixed-step methods repeat to about 1e-11, Radau to about its rtol (5e-6), so "
            "smaller values are never met; above 1e-2 the amplitude is not settled (engineering judgement)",
        ),
    ] = default_of(CarrierMotionRequest, "periodic_tolerance")
    """Periodicity tolerance (relative to the peak-to-peak of the motion)."""
    stiffness: Annotated[
        float, Quantity("rotational_stiffness", gt=0), Plausible(5e6, 5e14, _LUGRE.format("sigma_0 = 5e10 N m"))
    ] = default_of(CarrierModel, "stiffness")
    """LuGre bristle stiffness sigma_0 (Table 4.2)."""
    damping: Annotated[
        float, Quantity("rotational_damping", ge=0), Plausible(0.0, 1e12, _LUGRE.format("sigma_1 = 1e8 N m s"))
    ] = default_of(CarrierModel, "damping")
    """LuGre bristle damping sigma_1 (Table 4.2)."""
    stribeck_velocity: Annotated[PositiveSpeed, Plausible(2e-7, 20.0, _LUGRE.format("v_s = 0.002 rad/s"))] = default_of(
        CarrierModel, "stribeck_velocity"
    )
    """Stribeck velocity (rotational)."""
    threshold_velocity: Annotated[
        PositiveSpeed,
        Plausible(1e-8, 1.0, "1e-4 rad/s from the creep the seed reports (cpp/motion.py); four decades either way"),
    ] = default_of(CarrierModel, "threshold_velocity")
    """Threshold velocity of the static law (rotational)."""


class StudySection(Section):
    """One parameter of the carrier motion varied (seed Sect. 4.7)."""

    parameter: StudyParameter
    """The varied parameter (spindle_scale multiplies the spindle torque)."""
    values: Annotated[list[StrictFloat | StrictInt | str], Field(min_length=1)]
    """Its values (quantities with units; friction law names for friction)."""
    revolutions: Annotated[int, Field(ge=1, le=10000)] = 10
    """Revolutions simulated per value (at most: the stop at the periodic state of
    [cpp.motion] applies)."""


class CppSection(Section):
    """A CPP blade bearing: friction torque, fretting coefficient, hydraulics and carrier motion."""

    plausible_ratios = (
        PlausibleRatio(
            "loads.blade_mass",
            "m/(rho D^3)",
            lambda s, mass: mass / (7600.0 * s.propeller_diameter**3),
            3e-4,
            5e-2,
            "blade mass grows with the cube of the propeller diameter: about 2e-3 to 8e-3 with rho = 7600 kg/m^3 "
            f"(bronze; {_EXAMPLE}: 3.8e-3); the range is six times beyond either way, a mass in t written as a bare "
            "number (kg) is far below (engineering judgement)",
            "blade mass / (7600 kg/m^3 x cube of the propeller diameter)",
            uses=("propeller_diameter",),
        ),
    )

    blades: Annotated[int, Field(ge=2, le=8)]
    """Number of blades."""
    shaft_speed: Annotated[PositiveSpeed, SHAFT_SPEED]
    """Shaft speed."""
    propeller_diameter: Annotated[
        PositiveLength,
        Plausible(
            0.2,
            15.0,
            f"propellers from about 0.3 m (small craft) to about 10-11 m (the largest ships; {_EXAMPLE}: 4.5 m) "
            "(engineering judgement); mm written as m is far above",
        ),
    ]
    """Propeller diameter (R0.7 = 0.35 D)."""
    pitch_angle: Annotated[float, Quantity("angle", gt=0, lt=1.5707963267948966), PITCH_ANGLE]
    """Design pitch angle, below 90 deg (a number is in radians)."""
    bearing: BladeBearingSection
    """The blade bearing."""
    loads: LoadsSection
    """Blade loads."""
    hydraulics: HydraulicsSection
    """Hydraulics."""
    motion: MotionSection | None = None
    """Carrier motion."""
    study: StudySection | None = None
    """Parameter study of the carrier motion."""

    @model_validator(mode="after")
    def _study_needs_motion(self) -> CppSection:
        if self.study is not None and self.motion is None:
            raise field_error("study", self.study.parameter, "a [cpp.motion] table to vary")
        return self


def read_load_table(path: Any) -> tuple[Any, Any, Any]:
    """Blade loads over a revolution from CSV: angle_deg, force_x, force_y, force_z (N),
    moment_x, moment_y, moment_z (N m), one row per blade angle within one turn."""
    import numpy as np

    from shaftline.csvio import read_columns

    columns = ["angle_deg", "force_x", "force_y", "force_z", "moment_x", "moment_y", "moment_z"]
    data = read_columns(path, columns, "table", order_matters=True)
    table = np.column_stack([data[name] for name in columns])
    angle = np.radians(table[:, 0])
    if angle.size < 8 or np.any(np.diff(angle) <= 0) or angle[-1] - angle[0] >= 2 * math.pi:
        raise InputError("table", str(path), "", "at least 8 increasing angles within one turn")
    return angle, table[:, 1:4], table[:, 4:7]


def build_study(section: CppSection, context: BuildContext) -> BladeBearingStudy:
    """The blade-bearing study in SI domain objects."""
    import numpy as np

    from shaftline.cpp.hydraulics import oil_spring_stiffness
    from shaftline.cpp.loads import BladeLoads, centrifugal_point_mass
    from shaftline.cpp.study import BladeBearingStudy, CarrierMotionRequest, ParameterStudy
    from shaftline.units import to_si

    speed = section.shaft_speed
    b = section.bearing
    with located("bearing"):
        bearing = BladeBearing(
            b.radius, b.friction_coefficient, b.axial_radius, b.carrier_radius, b.thickness, b.youngs_modulus
        )
    ld = section.loads
    if ld.centrifugal_force is not None and ld.centrifugal_moment is not None:
        f_ce, m_ce = np.array(ld.centrifugal_force), np.array(ld.centrifugal_moment)
    else:
        assert ld.blade_mass is not None and ld.centre_of_gravity is not None  # checked by the schema
        f_ce, m_ce = centrifugal_point_mass(ld.blade_mass, np.array(ld.centre_of_gravity), speed)
    harmonics: dict[str, list[tuple[int, float, float]]] = {}
    for k, h in enumerate(ld.harmonics):
        kind = "moment" if h.component.startswith("moment") else "force"
        amplitude = to_si(h.amplitude, kind, f"loads.harmonics[{k}].amplitude")
        harmonics.setdefault(h.component, []).append((h.order, amplitude, h.phase))
    with located("loads"):
        if ld.table is not None:
            angle, force, moment = read_load_table(context.path(ld.table))
            loads = BladeLoads(angle, force, moment, f_ce, m_ce)
        else:
            assert ld.mean_force is not None and ld.mean_moment is not None  # checked by the schema
            angle = np.linspace(0.0, 2 * math.pi, ld.points, endpoint=False)
            loads = BladeLoads.from_harmonics(
                angle, np.array(ld.mean_force), np.array(ld.mean_moment), harmonics, f_ce, m_ce
            )
    hy = section.hydraulics
    with located("hydraulics"):
        oil_stiffness = oil_spring_stiffness(hy.bulk_modulus, hy.oil_volume, hy.yoke_area, hy.column_length)
    motion = None
    if section.motion is not None:
        m = section.motion
        motion = CarrierMotionRequest(
            inertia=m.inertia,
            water_inertia=m.water_inertia,
            friction=m.friction,
            revolutions=m.revolutions,
            stiffness=m.stiffness,
            damping=m.damping,
            stribeck_velocity=m.stribeck_velocity,
            threshold_velocity=m.threshold_velocity,
            method=m.method,
            stop_when_periodic=m.stop_when_periodic,
            periodic_tolerance=m.periodic_tolerance,
        )
    study = None
    if section.study is not None:
        st = section.study
        values: list[Any]
        if st.parameter == "friction":
            values = [str(v) for v in st.values]
            for k, value in enumerate(values):
                if value not in ("lugre", "static"):
                    raise InputError(f"study.values[{k}]", value, "", "lugre or static")
        else:
            quantity = STUDY_VALUES[st.parameter]
            values = [to_si(v, quantity.kind, f"study.values[{k}]") for k, v in enumerate(st.values)]
            for k, value in enumerate(values):
                if not quantity.inside(value):
                    raise InputError(f"study.values[{k}]", value, quantity.unit, quantity.allowed())
        study = ParameterStudy(st.parameter, tuple(values), st.revolutions)
    return BladeBearingStudy(
        blades=section.blades,
        speed=speed,
        radius_07=0.35 * section.propeller_diameter,
        pitch_angle=section.pitch_angle,
        bearing=bearing,
        loads=loads,
        oil_stiffness=oil_stiffness,
        yoke_area=hy.yoke_area,
        pin_radius=hy.pin_radius,
        backlash=hy.backlash,
        other_friction=hy.other_friction,
        counterbalance_pressure=hy.counterbalance_pressure,
        motion=motion,
        study=study,
    )
