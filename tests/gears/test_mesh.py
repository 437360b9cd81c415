"""Involute gear pair: identities of the geometry and kinematics, and the FZG type C gears."""

import math

import numpy as np
import pytest

from shaftline.errors import InputError
from shaftline.gears.mesh import GearPair, inverse_involute, involute, path_of_contact

DEG = math.pi / 180


def fzg_c() -> GearPair:
    # FZG test gear type C (the pitting and micropitting gear; named type A here
    # before - type A has x 0.8635/-0.5 and tips 88.77/112.5 mm, tests/gears/test_scuffing.py):
    # z 16/24, m 4.5 mm, 20 deg, x 0.1817/0.1715, a 91.5 mm, tip diameters 82.46 and 118.36 mm.
    return GearPair(
        16, 24, 4.5e-3, 20 * DEG, 20e-3, shift_1=0.1817, shift_2=0.1715,
        centre_distance=91.5e-3, tip_radius_1=82.46e-3 / 2, tip_radius_2=118.36e-3 / 2,
    )  # fmt: skip


def test_inverse_involute():
    for angle in (0.2, 0.35, 0.5):
        assert inverse_involute(float(involute(angle))) == pytest.approx(angle, rel=1e-13)


def test_fzg_type_c_geometry():
    # The shifts give the test rig's 91.5 mm within 0.01 mm (22.44 deg working pressure angle);
    # the transverse contact ratio of these (type C) gears is 1.44 as FZG reports quote it (2 figures).
    pair = fzg_c()
    assert pair._shifted_centre_distance() == pytest.approx(91.5e-3, abs=1e-5)
    assert math.degrees(pair.working_pressure_angle) == pytest.approx(22.44, abs=0.01)
    assert pair.transverse_contact_ratio == pytest.approx(1.44, abs=0.005)


def test_standard_spur_pair_by_hand():
    # z 20/40, m 5 mm, 20 deg, no shift: a = 150 mm, r_a = 55 and 105 mm, r_b = r cos 20;
    # g = sqrt(55^2 - 46.985^2) + sqrt(105^2 - 93.969^2) - 150 sin 20 = 24.135 mm, eps = g / (pi 5 cos 20).
    pair = GearPair(20, 40, 5e-3, 20 * DEG, 20e-3)
    rb1, rb2 = 50e-3 * math.cos(20 * DEG), 100e-3 * math.cos(20 * DEG)
    g = math.sqrt(55e-3**2 - rb1**2) + math.sqrt(105e-3**2 - rb2**2) - 150e-3 * math.sin(20 * DEG)
    assert pair.working_centre_distance == pytest.approx(150e-3, rel=1e-12)
    assert pair.path_length == pytest.approx(g, rel=1e-12)
    assert pair.transverse_contact_ratio == pytest.approx(g / (math.pi * 5e-3 * math.cos(20 * DEG)), rel=1e-12)


@pytest.mark.parametrize("helix", [0.0, 15 * DEG, 30 * DEG])
def test_base_pitch_and_path_identities(helix):
    pair = GearPair(19, 53, 3e-3, 20 * DEG, 30e-3, helix_angle=helix, shift_1=0.3, shift_2=-0.1)
    # both gears have the same transverse base pitch 2 pi r_b / z (the condition of meshing)
    assert 2 * math.pi * pair.base_radius_1 / 19 == pytest.approx(pair.base_pitch, rel=1e-13)
    assert 2 * math.pi * pair.base_radius_2 / 53 == pytest.approx(pair.base_pitch, rel=1e-13)
    # the pitch point divides T1T2 in the ratio of the teeth (pitch circles roll on each other)
    c = pair.points()["C"]
    assert c / (pair.line_of_action - c) == pytest.approx(19 / 53, rel=1e-12)
    # the path holds eps_alpha base pitches; B and D are a base pitch from E and A
    p = pair.points()
    assert (p["E"] - p["A"]) / pair.base_pitch == pytest.approx(pair.transverse_contact_ratio, rel=1e-13)
    assert p["E"] - p["B"] == pytest.approx(pair.base_pitch) and p["D"] - p["A"] == pytest.approx(pair.base_pitch)
    assert p["A"] < p["B"] < p["D"] < p["E"] and p["A"] < p["C"] < p["E"]


def test_teeth_in_contact_average_the_contact_ratio():
    # Independent of the path formula: follow the pinion's flanks as it turns. Flank j meets
    # the line of action at rho_1 = r_b1 (phi + 2 pi j / z1) (an involute unwinds its base
    # circle); the number of flanks between A and E, averaged over a turn, is eps_alpha.
    pair = fzg_c()
    phi = np.linspace(0.0, 2 * math.pi, 200001)[:-1, None]
    rho = pair.base_radius_1 * (phi + 2 * math.pi * np.arange(16)[None, :] / 16) % (2 * math.pi * pair.base_radius_1)
    in_contact = (rho >= pair.start_of_contact) & (rho <= pair.end_of_contact)
    assert in_contact.sum(axis=1).mean() == pytest.approx(pair.transverse_contact_ratio, abs=1e-4)


def test_kinematics_along_the_path():
    pair = GearPair(28, 28, 5e-3, 20 * DEG, 20e-3)  # seed 002's test gears (140 mm centre distance)
    speeds = np.array([[100.0], [1885.0]])  # rad/s (18 000 rpm)
    path = path_of_contact(pair, speeds, 201)
    assert path.rolling_speed.shape == (2, 201)
    # no sliding at the pitch point (the middle for equal gears), sliding grows linearly away from it
    assert np.abs(path.sliding_speed[:, 100]).max() < 1e-9 * path.rolling_speed.max()
    slope = np.diff(path.sliding_speed, axis=1)
    np.testing.assert_allclose(slope, slope[:, :1] * np.ones_like(slope), rtol=1e-9)
    # sliding speed = (omega_1 + omega_2) x distance from C (equal and opposite turning)
    c = pair.pitch_point
    np.testing.assert_allclose(path.sliding_speed, -(speeds + speeds) * (path.position - c), rtol=1e-9, atol=1e-9)
    # radius of curvature at the pitch point: r sin(alpha) = 70 mm sin 20 deg
    assert pair.pitch_point == pytest.approx(70e-3 * math.sin(20 * DEG), rel=1e-12)


def test_helical_normal_radius():
    spur = GearPair(20, 40, 4e-3, 20 * DEG, 40e-3)
    helical = GearPair(20, 40, 4e-3, 20 * DEG, 40e-3, helix_angle=20 * DEG)
    path = path_of_contact(helical, 100.0, 3)
    beta_b = math.asin(math.sin(20 * DEG) * math.cos(20 * DEG))
    np.testing.assert_allclose(path.radius_1 * math.cos(beta_b), path.position, rtol=1e-12)
    assert helical.overlap_ratio == pytest.approx(40e-3 * math.sin(20 * DEG) / (math.pi * 4e-3))
    assert spur.overlap_ratio == 0.0


def test_bad_gear_input():
    with pytest.raises(InputError, match=r"shift_1 = 0: allowed >= 0.2981: below it 12 teeth are undercut"):
        GearPair(12, 40, 5e-3, 20 * DEG, 20e-3)
    GearPair(12, 40, 5e-3, 20 * DEG, 20e-3, shift_1=0.3, shift_2=-0.3)  # shifted: fine
    with pytest.raises(InputError, match="centre_distance = 0.152 m: allowed 0.15 m within 0.05 module"):
        GearPair(20, 40, 5e-3, 20 * DEG, 20e-3, centre_distance=0.152)
    # a pinion tip reaching past T2 (rho_2 < 0 at E): named, not a negative radius downstream
    with pytest.raises(InputError, match="tip_radius_1 = 0.1 m: allowed a pinion tip that meets the wheel flank"):
        GearPair(28, 28, 5e-3, 20 * DEG, 20e-3, tip_radius_1=0.1)
    with pytest.raises(
        InputError, match="addendum = 0.5: allowed teeth long enough for a transverse contact ratio >= 1"
    ):
        GearPair(20, 40, 5e-3, 20 * DEG, 20e-3, addendum=0.5)
    # with tips given, the tip furthest below the addendum rule's is named (here the wheel's:
    # 102 mm against 110 mm), not the pinion's, which is right
    with pytest.raises(InputError, match=r"tip_radius_2 = 0.051 m: allowed teeth long enough"):
        GearPair(20, 20, 5e-3, 20 * DEG, 20e-3, tip_radius_1=0.055, tip_radius_2=0.051)
    # one tip given, longer than the rule's, and a short addendum on the other gear: the addendum
    with pytest.raises(InputError, match="addendum = 0.3: allowed teeth long enough"):
        GearPair(20, 40, 5e-3, 20 * DEG, 20e-3, addendum=0.3, tip_radius_1=0.0525)
    with pytest.raises(InputError, match="teeth_1"):
        GearPair(3, 40, 5e-3, 20 * DEG, 20e-3)
    with pytest.raises(InputError, match="pinion_speed"):
        path_of_contact(GearPair(20, 40, 5e-3, 20 * DEG, 20e-3), 0.0)
