"""Hertz contacts against closed forms of Johnson (1985, Contact Mechanics) written
independently of the module's Hamrock-style formulas."""

import numpy as np
import pytest

from shaftline.contact import hertz
from shaftline.errors import InputError

E_STEEL = 210e9
NU = 0.3
E_PRIME = float(hertz.reduced_modulus(E_STEEL, NU, E_STEEL, NU))
E_STAR = E_STEEL / (2 * (1 - NU**2))  # Johnson Eq. 4.22, two equal bodies


def test_reduced_modulus_is_twice_johnsons():
    assert E_PRIME == pytest.approx(2 * E_STAR, rel=1e-14)


def test_line_contact_matches_johnson_closed_forms():
    # Johnson Eq. 4.43-4.45: b^2 = 4 P R / (pi E*), p0 = (P E* / (pi R))^(1/2), p_mean = pi p0/4.
    load = np.array([1e5, 4e5, 1.2e6])
    radius = np.array([0.005, 0.012, 0.04])
    c = hertz.line_contact(load, radius, E_PRIME)
    np.testing.assert_allclose(c.half_width, np.sqrt(4 * load * radius / (np.pi * E_STAR)), rtol=1e-12)
    np.testing.assert_allclose(c.peak_pressure, np.sqrt(load * E_STAR / (np.pi * radius)), rtol=1e-12)
    np.testing.assert_allclose(c.mean_pressure * 2 * c.half_width, load, rtol=1e-12)  # equilibrium


def test_line_contact_subsurface_shear_from_mcewens_stresses():
    # Stresses on the axis of a line contact (McEwen 1949; Johnson Eq. 4.49):
    # sigma_x = -p0/b ((b^2 + 2 z^2)/sqrt(b^2 + z^2) - 2 z), sigma_z = -p0 b / sqrt(b^2 + z^2);
    # the largest principal shear (sigma_x - sigma_z)/2 found on a fine grid. Tolerance 1e-3:
    # the module's constants are Johnson's rounded 0.300 and 0.786.
    z = np.linspace(1e-4, 3.0, 300001)
    sx = -((1 + 2 * z**2) / np.sqrt(1 + z**2) - 2 * z)
    sz = -1 / np.sqrt(1 + z**2)
    tau = 0.5 * np.abs(sx - sz)
    assert tau.max() == pytest.approx(hertz.LINE_MAX_SHEAR, abs=1e-3)
    assert z[np.argmax(tau)] == pytest.approx(hertz.LINE_MAX_SHEAR_DEPTH, abs=1e-3)


@pytest.mark.parametrize("method", sorted(hertz.ELLIPTICITY_METHODS))
def test_circular_contact_matches_johnson(method):
    # Johnson Eq. 4.22-4.23 for a sphere on a flat: a = (3 P R / (4 E*))^(1/3), p0 = 3P/(2 pi a^2),
    # delta = a^2 / R. Every method is exact at alpha_r = 1 except the 1983 fit (k = 1.0339,
    # K = 1.5277): 1.2 % on a, 2.3 % on p0 and 5.4 % on the approach there.
    load, radius = 250.0, 0.008
    c = hertz.point_contact(load, radius, radius, E_PRIME, method)
    a = (3 * load * radius / (4 * E_STAR)) ** (1 / 3)
    rtol = 6e-2 if method == "hamrock_brewe" else 1e-12
    assert float(c.semi_axis_y) == pytest.approx(a, rel=rtol)
    assert float(c.peak_pressure) == pytest.approx(3 * load / (2 * np.pi * a**2), rel=rtol)
    assert float(c.approach) == pytest.approx(a**2 / radius, rel=rtol)


def test_circular_subsurface_shear():
    # Johnson Sect. 3.4 (Fig. 3.9): tau_1 max = 0.31 p0 at z = 0.48 a for nu = 0.3.
    ratio, depth = hertz.circular_max_shear(0.3)
    assert float(ratio[0]) == pytest.approx(0.31, abs=0.005)
    assert float(depth[0]) == pytest.approx(0.48, abs=0.005)


def test_exact_ellipticity_satisfies_johnsons_equation_and_approach():
    # k solves Johnson Eq. 4.39 to 1e-10; the approach equals Johnson's delta = p0 b K(e) / E*
    # (Eq. 4.37), a different closed form from Hamrock's used by the module (1e-12).
    alpha = np.logspace(0, 3, 31)
    k, big_k, big_e = hertz.exact_ellipticity(alpha)
    m = 1 - 1 / k**2
    with np.errstate(invalid="ignore"):
        ratio = np.where(k > 1, (k**2 * big_e - big_k) / (big_k - big_e), 1.0)
    np.testing.assert_allclose(ratio, alpha, rtol=1e-10)
    assert np.all(m >= 0)
    c = hertz.point_contact(300.0, 0.004, 0.004 * alpha, E_PRIME)
    np.testing.assert_allclose(c.approach, c.peak_pressure * c.semi_axis_x * c.first_kind / E_STAR, rtol=1e-12)
    # load balance: p_mean over the ellipse carries the load
    np.testing.assert_allclose(c.mean_pressure * np.pi * c.semi_axis_x * c.semi_axis_y, 300.0, rtol=1e-12)


def test_curve_fits_against_exact():
    # Hamrock & Brewe (1983) and Brewe & Hamrock (1977) beside the exact values for 1 <= Ry/Rx <= 100:
    # the deviations found (k 6.3 % and 3.8 %, K 2.7 % and 2.1 %, E 1.7 % and 0.9 %) with a margin,
    # so that a slip in a constant shows.
    alpha = np.logspace(0, 2, 81)
    k, big_k, big_e = hertz.exact_ellipticity(alpha)
    for name, limits in (("hamrock_brewe", (0.065, 0.03, 0.02)), ("brewe_hamrock", (0.04, 0.025, 0.01))):
        k2, big_k2, big_e2 = hertz.ELLIPTICITY_METHODS[name](alpha)
        assert np.abs(k2 / k - 1).max() < limits[0]
        assert np.abs(big_k2 / big_k - 1).max() < limits[1]
        assert np.abs(big_e2 / big_e - 1).max() < limits[2]


def test_bad_input_names_the_field():
    with pytest.raises(InputError, match="radius_y"):
        hertz.point_contact(100.0, 0.01, 0.005, E_PRIME)
    with pytest.raises(InputError, match="load_per_length"):
        hertz.line_contact(-1.0, 0.01, E_PRIME)
    with pytest.raises(InputError, match="poisson_ratio_2"):
        hertz.reduced_modulus(E_STEEL, 0.3, E_STEEL, 0.6)
    with pytest.raises(InputError, match="method"):
        hertz.point_contact(100.0, 0.01, 0.01, E_PRIME, "nope")


def test_axis_stresses_of_a_circle_match_johnson():
    # The quadrature of Boussinesq's stresses against the closed forms on the axis of a circular
    # contact (Johnson Eq. 3.45): sigma_r = -(1+nu)(1 - z atan(1/z)) + 1/(2(1+z^2)),
    # sigma_z = -1/(1+z^2), z in units of a; 1e-5 (24 x 48 Gauss nodes: found 5e-6, the square-root
    # edge of the pressure slows Gauss convergence; 2e-7 with 64 x 128).
    z = np.array([0.1, 0.3, 0.48, 1.0, 2.0])
    sx, sy, sz = hertz.axis_stresses(1.0, z, 0.3)
    sr = -(1.3) * (1 - z * np.arctan(1 / z)) + 0.5 / (1 + z**2)
    np.testing.assert_allclose(sx, sr, atol=1e-5)
    np.testing.assert_allclose(sy, sr, atol=1e-5)
    np.testing.assert_allclose(sz, -1 / (1 + z**2), atol=1e-5)


def test_elliptical_subsurface_shear_between_circle_and_line():
    # Limits: the circle (Johnson Fig. 3.9: 0.31 p0 at 0.48 a) and the line contact (0.300 p0 at
    # 0.786 b) as k grows; 0.005 and 0.01 b (table interpolation and Johnson's rounding).
    ratio, depth = hertz.elliptical_max_shear(np.array([1.0, 100.0, 1e4]))
    assert ratio[0] == pytest.approx(0.31, abs=0.005) and depth[0] == pytest.approx(0.48, abs=0.01)
    assert ratio[1] == pytest.approx(0.300, abs=0.005) and depth[1] == pytest.approx(0.786, abs=0.01)
    assert ratio[2] == pytest.approx(0.300, abs=0.001)
    # and along a point contact of growing ellipticity the depth moves from 0.48 b to 0.79 b
    c = hertz.point_contact(300.0, 0.004, 0.004 * np.array([1.0, 4.0, 30.0]), E_PRIME)
    np.testing.assert_array_less(np.diff(c.max_shear_depth / c.semi_axis_x), 0.4)
    assert np.all(np.diff(c.max_shear_depth / c.semi_axis_x) > 0)
