"""Blade-carrier fretting motion (seed 000 Sect. 4.6): the compiled backward-Euler integrator
against scipy's Radau, and the seed's qualitative findings."""

from __future__ import annotations

import numpy as np
import pytest

from shaftline.cpp.motion import CarrierModel, simulate_carrier
from shaftline.errors import InputError

ANGLE = np.linspace(0, 2 * np.pi, 361)[:-1]
COULOMB = 3.4e5 * (1 + 0.2 * np.cos(ANGLE))


def model(amplitude=3.6e5, friction="lugre", backlash=0.0):
    spindle = 3.0e4 + amplitude * np.cos(ANGLE + 2.4) + 0.28 * amplitude * np.cos(2 * ANGLE + 0.5)
    return CarrierModel(
        inertia=1500.0,
        water_inertia=500.0,
        speed=150 * 2 * np.pi / 60,
        angle=ANGLE,
        spindle_torque=spindle,
        coulomb_torque=COULOMB,
        oil_stiffness=5.7e9,
        pin_radius=0.3,
        pitch_angle=np.radians(28.0),
        backlash=backlash,
        friction=friction,
        threshold_velocity=1e-4,
    )


@pytest.mark.parametrize("friction", ["lugre", "static"])
def test_compiled_integrator_against_radau(friction):
    """Over three revolutions the fixed-step backward Euler (7200 steps a revolution) stays
    within 2.5 % of Radau's amplitude and sliding, and halving the step halves the gap (first
    order)."""
    reference = simulate_carrier(model(friction=friction), 3, method="radau")
    coarse = simulate_carrier(model(friction=friction), 3, steps_per_revolution=7200)
    fine = simulate_carrier(model(friction=friction), 3, steps_per_revolution=14400)
    assert coarse.amplitude[-1] == pytest.approx(reference.amplitude[-1], rel=0.025)
    assert coarse.sliding_per_revolution[-1] == pytest.approx(reference.sliding_per_revolution[-1], rel=0.025)
    gap_coarse = abs(coarse.amplitude[-1] - reference.amplitude[-1])
    gap_fine = abs(fine.amplitude[-1] - reference.amplitude[-1])
    assert gap_fine < 0.75 * gap_coarse or gap_coarse < 1e-3 * reference.amplitude[-1]


def test_friction_model_hardly_changes_the_amplitude():
    """Seed Sect. 4.6.3: LuGre and the static law give nearly the same fretting amplitude."""
    lugre = simulate_carrier(model(friction="lugre"), 6).amplitude[-1]
    static = simulate_carrier(model(friction="static"), 6).amplitude[-1]
    assert static == pytest.approx(lugre, rel=0.1)


def test_no_fretting_below_friction_and_more_with_amplitude_and_backlash():
    """No gross motion when the spindle torque never overcomes the friction; the amplitude
    grows with the spindle-torque amplitude and with backlash (seed Sect. 4.7)."""
    quiet = simulate_carrier(model(amplitude=1.5e5, friction="static"), 4).amplitude[-1]
    base = simulate_carrier(model(friction="static"), 4).amplitude[-1]
    stronger = simulate_carrier(model(amplitude=4.5e5, friction="static"), 4).amplitude[-1]
    loose = simulate_carrier(model(friction="static", backlash=100e-6), 4).amplitude[-1]
    assert quiet < 0.1 * base
    assert base < stronger and base < loose


def test_oil_pressure_signal_follows_fretting():
    """Sect. 4.8: the oil-spring force fluctuates with the carrier motion, so a pressure signal
    can reveal fretting: zero fluctuation without motion, proportional to it with motion."""
    still = simulate_carrier(model(amplitude=1.0e5, friction="static"), 3)
    moving = simulate_carrier(model(friction="static"), 3)
    assert still.force_fluctuation[-1] < 0.1 * moving.force_fluctuation[-1]
    assert moving.force_fluctuation[-1] > 0


def test_bad_motion_input():
    with pytest.raises(InputError):
        CarrierModel(
            inertia=-1.0,
            water_inertia=0.0,
            speed=10.0,
            angle=ANGLE,
            spindle_torque=COULOMB,
            coulomb_torque=COULOMB,
            oil_stiffness=1e9,
            pin_radius=0.3,
            pitch_angle=0.4,
        )
    with pytest.raises(InputError):
        simulate_carrier(model(), 0)


def test_parameter_study_of_sect_4_7():
    """Seed Sect. 4.7.1: a mean (holding) hydraulic moment does not change the amplitude, it
    offsets the motion; Sect. 4.7.2: the amplitude grows with the spindle torque (the seed
    finds -25 % / +25 % for 0.8 / 1.2 times the design torque; here, with the illustrative
    loads, a monotone rise)."""
    from shaftline.cpp.motion import parameter_study

    base = model(friction="static")
    scaled = [m.amplitude[-1] for m in parameter_study(base, "spindle_scale", [0.8, 1.0, 1.2], 4)]
    assert scaled[0] < scaled[1] < scaled[2]
    held = parameter_study(base, "holding_moment", [0.0, 3.0e4, -3.0e4], 4)
    amplitudes = [m.amplitude[-1] for m in held]
    assert amplitudes[1] == pytest.approx(amplitudes[0], rel=0.02)
    assert amplitudes[2] == pytest.approx(amplitudes[0], rel=0.02)
    means = [float(np.mean(m.rotation)) for m in held]
    assert means[1] < means[0] < means[2]  # the holding moment offsets the motion
    with pytest.raises(InputError):
        parameter_study(base, "colour", [1], 1)
