"""A blade-bearing study of a controllable-pitch propeller: friction torque and fretting
coefficient over a revolution, hydraulic pressures, and the blade-carrier fretting motion
with its parameter study (seed 000 Ch. 3-4).

This is what ``[cpp]`` in a case file becomes; notebooks can build one directly.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

import numpy as np

from shaftline.cpp.loads import BladeBearing, BladeLoads
from shaftline.cpp.motion import DEFAULT_METHOD, PERIODIC_TOLERANCE, MethodName

if TYPE_CHECKING:
    from shaftline.cpp.fretting import FrettingCoefficient
    from shaftline.cpp.loads import FrictionTorque
    from shaftline.cpp.motion import CarrierModel, CarrierMotion


@dataclass(frozen=True)
class CarrierMotionRequest:
    """Inputs of the carrier motion that are not in the rest of the study: the fields of
    :class:`shaftline.cpp.motion.CarrierModel` of the same names (SI), the revolutions to
    simulate (at most), and how (the arguments of
    :func:`shaftline.cpp.motion.simulate_carrier` of the same names, with its defaults)."""

    inertia: float
    water_inertia: float
    friction: str
    revolutions: int
    stiffness: float
    damping: float
    stribeck_velocity: float
    threshold_velocity: float
    method: MethodName = DEFAULT_METHOD
    stop_when_periodic: bool = True
    periodic_tolerance: float = PERIODIC_TOLERANCE


@dataclass(frozen=True)
class ParameterStudy:
    """One carrier-motion parameter varied over ``values`` (seed Sect. 4.7)."""

    parameter: str
    values: tuple[Any, ...]
    revolutions: int = 10


@dataclass(frozen=True, eq=False)
class BladeBearingStudy:
    """Blade-bearing inputs in SI.

    Attributes
    ----------
    blades : int
    speed : float
        Shaft speed, rad/s.
    radius_07 : float
        0.7 of the propeller radius, m.
    pitch_angle : float
        Design pitch angle, rad.
    bearing : BladeBearing
    loads : BladeLoads
    oil_stiffness : float
        Oil spring behind the yoke, N/m.
    yoke_area, pin_radius, backlash : float
        m^2, m, m.
    other_friction : float
        Friction of the rest of the mechanism, N.
    counterbalance_pressure : float
        Pa.
    motion : CarrierMotionRequest or None
    study : ParameterStudy or None
    """

    blades: int
    speed: float
    radius_07: float
    pitch_angle: float
    bearing: BladeBearing
    loads: BladeLoads
    oil_stiffness: float
    yoke_area: float
    pin_radius: float
    backlash: float = 0.0
    other_friction: float = 0.0
    counterbalance_pressure: float = 0.0
    motion: CarrierMotionRequest | None = None
    study: ParameterStudy | None = None


@dataclass(frozen=True, eq=False)
class BladeBearingResult:
    """Friction, fretting, hydraulics and (when asked) the carrier motion of a study."""

    study: BladeBearingStudy
    friction: FrictionTorque
    coefficient: FrettingCoefficient
    f_fret: np.ndarray
    critical: tuple[float | None, float | None]
    pressures: dict[str, float]
    motion: CarrierMotion | None = None
    parameter_study: list[tuple[Any, CarrierMotion]] | None = None


def carrier_model(study: BladeBearingStudy, friction: FrictionTorque) -> CarrierModel:
    """The carrier-motion model of a study (it must have ``motion``)."""
    from shaftline.cpp.motion import CarrierModel

    m = study.motion
    if m is None:
        raise ValueError("the study has no carrier motion")
    return CarrierModel(
        inertia=m.inertia,
        water_inertia=m.water_inertia,
        speed=study.speed,
        angle=study.loads.angle,
        spindle_torque=study.loads.spindle_torque,
        coulomb_torque=friction.total,
        oil_stiffness=study.oil_stiffness,
        pin_radius=study.pin_radius,
        pitch_angle=study.pitch_angle,
        backlash=study.backlash,
        bearing_radius=study.bearing.radius,
        friction=m.friction,
        stiffness=m.stiffness,
        damping=m.damping,
        stribeck_velocity=m.stribeck_velocity,
        threshold_velocity=m.threshold_velocity,
    )


def solve_blade_bearing(
    study: BladeBearingStudy, motion: bool = True, progress: Callable[[str], None] | None = None
) -> BladeBearingResult:
    """Friction torque, fretting coefficient and hydraulic pressures; with ``motion`` (and a
    ``motion`` in the study) also the carrier motion and its parameter study.

    ``progress`` is told each step (``"blade-bearing friction"``) and, during the carrier motion
    and the parameter study, the share done (``"blade-carrier motion 35 %"``). Ctrl-C stops
    the motion within a fraction of a second (:func:`shaftline.cpp.motion.simulate_carrier`)."""
    from shaftline.cpp.fretting import critical_values, fretting_coefficient, thrust_fretting_coefficient
    from shaftline.cpp.hydraulics import hydraulic_pressures
    from shaftline.cpp.loads import friction_torque
    from shaftline.cpp.motion import parameter_study, simulate_carrier
    from shaftline.errors import located

    step = progress or (lambda _: None)
    step("blade-bearing friction")
    loads = study.loads
    friction = friction_torque(loads, study.bearing)
    coefficient = fretting_coefficient(loads.spindle_torque, friction.total, loads.angle)
    total_thrust = study.blades * float(loads.thrust.mean())
    f_fret = thrust_fretting_coefficient(loads.spindle_torque, total_thrust, study.blades, study.radius_07)
    pressures = hydraulic_pressures(
        float(loads.spindle_torque.mean()),
        float(friction.total.mean()),
        study.blades,
        study.pin_radius,
        study.pitch_angle,
        study.yoke_area,
        study.other_friction,
        study.counterbalance_pressure,
    )
    carrier = None
    varied: list[tuple[Any, CarrierMotion]] | None = None
    if motion and study.motion is not None:
        step("blade-carrier motion")
        with located("motion"):
            model = carrier_model(study, friction)
            how = study.motion
            carrier = simulate_carrier(
                model,
                how.revolutions,
                method=how.method,
                progress=percent_done(step, "blade-carrier motion"),
                stop_when_periodic=how.stop_when_periodic,
                periodic_tolerance=how.periodic_tolerance,
            )
        if study.study is not None:
            st = study.study
            label = f"parameter study of {st.parameter}"
            step(label)
            with located("study"):
                motions = parameter_study(
                    model,
                    st.parameter,
                    list(st.values),
                    st.revolutions,
                    progress=percent_done(step, label),
                    method=how.method,
                    stop_when_periodic=how.stop_when_periodic,
                    periodic_tolerance=how.periodic_tolerance,
                )
            varied = list(zip(st.values, motions, strict=True))
    return BladeBearingResult(
        study, friction, coefficient, f_fret, critical_values(coefficient, f_fret), pressures, carrier, varied
    )


def percent_done(progress: Callable[[str], None], label: str) -> Callable[[float], None]:
    """A fraction-done callback that tells ``progress`` ``"<label> 35 %"``, once per whole per cent
    (the integration reports after every chunk of about 0.1 s; the text changes less often)."""
    shown = -1

    def report(fraction: float) -> None:
        nonlocal shown
        percent = int(100 * fraction)
        if percent != shown:
            shown = percent
            progress(f"{label} {percent} %")

    return report


def settled_amplitude(motion: CarrierMotion) -> tuple[float, float, float]:
    """Largest, mean and smallest fretting amplitude (m) of the settled motion: over the last
    period (one cycle of ``motion.period`` revolutions) when the motion is periodic, else over
    the second half of the simulated revolutions, after the start-up transient.

    With backlash the carrier's motion need not repeat every revolution: in the tests it
    settles into a cycle of three, and in the example it does not settle within 20 revolutions
    (amplitudes between 129 and 141 µm), so the amplitude of the last revolution depends on
    how many were simulated. The largest of the settled ones is the one a designer checks
    against fretting.
    """
    if motion.periodic:
        settled = motion.amplitude[-motion.period :]
    else:
        settled = motion.amplitude[motion.revolutions // 2 :]
    return float(settled.max()), float(settled.mean()), float(settled.min())


def rank(results: Sequence[tuple[str, BladeBearingResult]]) -> list[tuple[str, float, bool]]:
    """Propellers ranked by fretting risk, highest first: (name, max |k_fret|, gross fretting both ways)."""
    from shaftline.cpp.fretting import rank_by_fretting_risk

    coefficients = {name: result.coefficient for name, result in results}
    return [(name, value, coefficients[name].fretting) for name, value in rank_by_fretting_risk(coefficients)]
