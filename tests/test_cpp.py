"""CPP blade-bearing loads, friction torque, fretting coefficient and hydraulics (seed 000 Ch. 3-4)."""

from __future__ import annotations

import numpy as np
import pytest
from scipy.integrate import quad

from shaftline.cpp.fretting import (
    critical_values,
    fretting_coefficient,
    rank_by_fretting_risk,
    thrust_fretting_coefficient,
)
from shaftline.cpp.hydraulics import hydraulic_pressures, oil_spring_stiffness
from shaftline.cpp.loads import (
    BladeBearing,
    BladeLoads,
    centrifugal_point_mass,
    friction_torque,
    radial_friction_torque,
)
from shaftline.errors import InputError


@pytest.mark.parametrize("u_target", [0.0, 0.3, 0.8, 0.999, 1.0, 1.5, 4.0])
def test_radial_friction_closed_forms_match_quadrature(u_target):
    """Eq. 3.27/3.31 against r mu * integral of |q| r dphi of the line load of Eq. 3.23 (1e-8)."""
    radius, mu, moment = 0.4, 0.12, 2.0e5
    force = u_target * 2 * moment / radius
    closed, u = radial_friction_torque(np.array([force]), np.array([moment]), radius, mu)
    q = lambda phi: force / (2 * np.pi * radius) + 2 * moment * np.sin(phi) / (2 * np.pi * radius**2)  # noqa: E731
    numeric = radius * mu * quad(lambda phi: abs(q(phi)) * radius, 0, 2 * np.pi, limit=200, points=[np.pi])[0]
    assert u[0] == pytest.approx(u_target)
    assert closed[0] == pytest.approx(numeric, rel=1e-8)


def test_radial_friction_continuous_at_u_equal_one():
    radius, mu, moment = 0.4, 0.1, 1e5
    below, _ = radial_friction_torque(np.array([(1 - 1e-9) * 2 * moment / radius]), np.array([moment]), radius, mu)
    above, _ = radial_friction_torque(np.array([(1 + 1e-9) * 2 * moment / radius]), np.array([moment]), radius, mu)
    assert below[0] == pytest.approx(above[0], rel=1e-6) == pytest.approx(2 * mu * moment)


def test_undefined_distribution_factor():
    with pytest.raises(InputError) as error:
        radial_friction_torque(np.array([0.0]), np.array([0.0]), 0.4, 0.1)
    assert "u undefined" in str(error.value)


def test_friction_coefficient_range():
    with pytest.raises(InputError) as error:
        BladeBearing(0.4, 1.2, 0.35, 0.3499, 0.1)
    assert error.value.field == "friction_coefficient"


def test_oil_spring_of_sect_4_5():
    """1.5e9 Pa, 250 l, 0.95 m^2: the seed rounds the column to 0.25 m and gets 5.7e9 N/m; the
    exact column (0.263 m) gives 5.41e9 N/m."""
    assert oil_spring_stiffness(1.5e9, 0.250, 0.95, column_length=0.25) == pytest.approx(5.7e9)
    assert oil_spring_stiffness(1.5e9, 0.250, 0.95) == pytest.approx(5.415e9)


def test_centrifugal_point_mass_signs_follow_eq_3_8_3_9():
    """The seed's design values (Eq. 3.7-3.9, dimensionless): cg (0.15, -0.08, 0.75), force
    (0, -13.5, 131.7), moments (0, -6.2, -3.5): a point mass gives the same signs and
    F_y/F_z = y/z within the blade's shape effect (4 %)."""
    force, moment = centrifugal_point_mass(1.0, np.array([0.15, -0.08, 0.75]), 1.0)
    assert np.sign(force[1]) == np.sign(-13.5) and np.sign(force[2]) == np.sign(131.7)
    assert force[1] / force[2] == pytest.approx(-13.5 / 131.7, rel=0.05)
    assert np.sign(moment[1]) == np.sign(-6.2) and np.sign(moment[2]) == np.sign(-3.5) and moment[0] == 0


def design_like_loads(spindle_amplitude: float) -> BladeLoads:
    angle = np.linspace(0, 2 * np.pi, 721)[:-1]
    return BladeLoads.from_harmonics(
        angle,
        mean_force=[4.0e5, 2.4e5, 3.0e4],
        mean_moment=[8.0e4, 1.3e5, 1.0e4],
        harmonics={
            "force_x": [(1, 1.2e5, 0.3)],
            "moment_z": [(1, spindle_amplitude, 2.4), (2, 0.3 * spindle_amplitude, 0.5)],
        },
        centrifugal_force=[0.0, -7.0e4, 7.0e5],
        centrifugal_moment=[0.0, -3.3e4, -1.5e4],
    )


BEARING = BladeBearing(radius=0.392, friction_coefficient=0.1, axial_radius=0.33, carrier_radius=0.3295, thickness=0.12)


def test_fretting_windows_and_ranking():
    calm = design_like_loads(2.0e4)
    rough = design_like_loads(1.2e5)
    results = {}
    for name, loads in (("calm", calm), ("rough", rough)):
        friction = friction_torque(loads, BEARING)
        assert np.all(friction.total > 0) and np.all(friction.radial > 0) and np.all(friction.axial > 0)
        results[name] = fretting_coefficient(loads.spindle_torque, friction.total, loads.angle)
    assert not results["calm"].fretting
    assert results["rough"].fretting
    start, end = results["rough"].windows_positive[0]
    assert 0 <= start <= end < 2 * np.pi
    assert [name for name, _ in rank_by_fretting_risk(results)] == ["rough", "calm"]
    f = thrust_fretting_coefficient(rough.spindle_torque, 4 * rough.thrust.mean(), 4, 2.0)
    positive, negative = critical_values(results["rough"], f)
    assert positive is not None and negative is not None and negative < 0 < positive


def test_hydraulic_pressures_eq_3_40_3_41():
    p = hydraulic_pressures(1e4, 5e4, 4, 0.3, 0.2, 0.95, other_friction=1e4, counterbalance_pressure=5e5)
    arm = 0.3 * np.cos(0.2)
    assert p["ahead"] == pytest.approx((4 * 6e4 / arm + 1e4) / 0.95 + 5e5)
    assert p["astern"] < p["holding"] < p["ahead"]


def test_errors_name_the_field_relative_to_the_checker():
    """Domain code names a field by the dataclass attribute or function parameter that holds
    it; the case layer prefixes the section path (it knows where the value came from)."""
    checks = [
        (lambda: oil_spring_stiffness(-1.5e9, 0.25, 0.95), "bulk_modulus"),
        (lambda: BladeBearing(0.4, 0.1, 0.35, 0.36, 0.1), "carrier_radius"),
        (lambda: centrifugal_point_mass(0.0, np.zeros(3), 10.0), "mass"),
        (
            lambda: BladeLoads.from_harmonics(
                np.zeros(4), np.zeros(3), np.zeros(3), {"torque_z": []}, np.zeros(3), np.zeros(3)
            ),
            "harmonics.torque_z",
        ),
        (lambda: fretting_coefficient(np.ones(3), np.array([1.0, 0.0, 1.0]), np.arange(3.0)), "friction"),
    ]
    for call, field in checks:
        with pytest.raises(InputError) as error:
            call()
        assert error.value.field == field


def test_blade_bearing_study_reports_the_motion_in_per_cent():
    """The command line shows "solving blade-carrier motion 35 %": the study turns the
    motion's share done into whole per cents, each once, up to 100 %. Twenty revolutions (the
    example's, which do not become periodic) take several chunks: the first has 2048 steps and
    each may at most quadruple."""
    from dataclasses import replace
    from pathlib import Path

    from shaftline.cases import load_case
    from shaftline.cpp.study import ParameterStudy, solve_blade_bearing

    example = Path(__file__).parents[1] / "examples" / "cpp_blade_bearing.toml"
    study = load_case(example).studies["cpp"]
    assert study.motion is not None
    study = replace(
        study, motion=replace(study.motion, revolutions=20), study=ParameterStudy("backlash", (0.0, 1e-4), 1)
    )
    told: list[str] = []
    solve_blade_bearing(study, progress=told.append)
    motion = [t for t in told if t.startswith("blade-carrier motion ")]
    percents = [int(t.split()[-2]) for t in motion]
    assert percents[-1] == 100 and percents == sorted(set(percents)) and len(percents) > 2
    assert told[told.index("parameter study of backlash") + 1 :][-1] == "parameter study of backlash 100 %"
