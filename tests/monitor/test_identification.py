"""Journal centre, film and correction factor at a probe section (seed 001 Eq. 1-7; docs/theory.md M1-M6)."""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.optimize import brentq

from shaftline.monitor.identification import (
    directions,
    film_between_circles,
    film_noise_std,
    identify_orbits,
    probe_films,
    reference_points,
    section_film,
)
from shaftline.monitor.probes import Probe, ProbeLayout, Section, seed001_layout


def _ray_film(layout: ProbeLayout, ey: float, ez: float, theta: float, k: float = 0.0) -> float:
    """Film along the ray at ``theta`` found numerically: where the ray leaves the journal circle."""
    u = directions(np.array([theta]), layout.rotation)[0][0]
    journal = layout.journal_radius - k

    def outside(r: float) -> float:
        return math.hypot(r * u[0] - ey, r * u[1] - ez) - journal

    return layout.radius - brentq(outside, 0.0, 2 * layout.radius, xtol=1e-16, rtol=1e-15)


@pytest.mark.parametrize("rotation", [1, -1])
def test_exact_film_matches_a_ray_circle_intersection(rotation):
    """(M1) against the ray-circle intersection solved by root finding; tolerance 1e-12 m (round-off on R)."""
    layout = ProbeLayout(seed001_layout().sections, 1.2, 0.16205, 0.55e-3, rotation=rotation)
    rng = np.random.default_rng(3)
    for _ in range(20):
        e = 0.54e-3 * math.sqrt(rng.uniform())
        angle = rng.uniform(0, 2 * math.pi)
        ey, ez = e * math.cos(angle), e * math.sin(angle)
        theta = rng.uniform(0, 2 * math.pi, 5)
        k = rng.uniform(0, 30e-6)
        got = film_between_circles(np.array(ey), np.array(ez), theta, layout, k)
        want = [_ray_film(layout, ey, ez, t, k) for t in theta]
        assert got == pytest.approx(want, abs=1e-12)


def test_second_order_term_is_why_the_exact_form_is_kept():
    """At full eccentricity the linear film (seed Eq. 4) is off by c^2 / (2 R_j) 90 deg from the line of centres."""
    layout = seed001_layout()
    c = layout.radial_clearance
    exact = film_between_circles(np.array(-c), np.array(0.0), np.array([math.pi / 2]), layout)[0]
    linear = c  # c - u.e with u = (0, 1) normal to the offset
    assert exact - linear == pytest.approx(c**2 / (2 * layout.journal_radius), rel=1e-3)
    assert 0.9e-6 < exact - linear < 1.0e-6


def _gaps(layout: ProbeLayout, ey: np.ndarray, ez: np.ndarray, k: float = 0.0) -> np.ndarray:
    blocks = [film_between_circles(ey, ez, s.angles, layout, k) + s.mounting_distances for s in layout.sections]
    return np.hstack(blocks)


def test_orbit_is_recovered_from_exact_gaps():
    """Three probes per section, exact gaps: the centre back to 1e-11 m (two circle passes, error ~ (e/R)^3 c)."""
    layout = seed001_layout()
    t = np.linspace(0, 1, 2000)
    ey = -0.5e-3 + 20e-6 * np.cos(2 * math.pi * 3 * t)
    ez = -0.15e-3 + 30e-6 * np.sin(2 * math.pi * 3 * t)
    orbits = identify_orbits(layout, _gaps(layout, ey, ez))
    for orbit in orbits:
        assert np.abs(orbit.ey - ey).max() < 1e-11
        assert np.abs(orbit.ez - ez).max() < 1e-11
        assert orbit.min_film == pytest.approx(layout.radial_clearance - np.hypot(ey, ez), abs=1e-11)


def test_two_probes_are_exact_and_four_are_least_squares():
    """Two probes fix the centre exactly (Eq. 1-2); a fourth probe with a bias moves it by the LS share only."""
    angles = [math.radians(a) for a in (315.0, 45.0, 180.0, 90.0)]
    probes = tuple(Probe(f"p{i}", a, 1e-3) for i, a in enumerate(angles))
    two = ProbeLayout((Section("S", 0.5, probes[:2]),), 1.0, 0.1, 2e-4)
    four = ProbeLayout((Section("S", 0.5, probes),), 1.0, 0.1, 2e-4)
    ey, ez = np.array([-1.5e-4]), np.array([0.4e-4])
    orbit = identify_orbits(two, _gaps(two, ey, ez))[0]
    assert orbit.ey[0] == pytest.approx(ey[0], abs=1e-13) and orbit.ez[0] == pytest.approx(ez[0], abs=1e-13)
    gaps = _gaps(four, ey, ez)
    orbit = identify_orbits(four, gaps)[0]
    assert orbit.ey[0] == pytest.approx(ey[0], abs=1e-13)
    gaps[0, 3] += 1e-6  # the probe at 90 deg reads 1 um long: the horizontal centre moves by its LS weight
    moved = identify_orbits(four, gaps)[0]
    weight = np.linalg.pinv(directions(np.array(angles))[0])[1, 3]
    # The weight of the linear model; the circle term tilts the probe directions by up to e/R = 1.5e-3.
    assert moved.ez[0] - ez[0] == pytest.approx(-weight * 1e-6, rel=3e-3)


def test_seed_equation_2_reading_equals_the_solver():
    """Eq. 2 as read (docs/theory.md M3): X0 = -d2 sqrt(1 + (d1/d2)^2) sin(45 deg - atan(d1/d2)), Y0 with cos.

    Linear gaps (the seed's model), so the two agree to round-off (1e-15 m).
    """
    layout = seed001_layout()
    for ey, ez in ((-4e-4, -1e-4), (-2e-4, 2.5e-4), (-5e-4, 0.5e-4)):
        section = layout.sections[0]
        along, _ = directions(section.angles, layout.rotation)
        d = -(along @ np.array([ey, ez]))  # d_i = a_i - S_i - c on the linear model
        ratio = d[0] / d[1]
        radius = -d[1] * math.sqrt(1 + ratio**2)
        x0 = radius * math.sin(math.radians(45.0) - math.atan(ratio))
        y0 = radius * math.cos(math.radians(45.0) - math.atan(ratio))
        assert y0 == pytest.approx(ey, abs=1e-15)
        assert x0 == pytest.approx(layout.rotation * ez, abs=1e-15)


def _seed_equation_6(d1: float, d2: float, d3: float, factor: float) -> tuple[float, float, float]:
    """Seed Eq. 6-7 for probes at 315, 45 and 180 deg: tan(theta0) = factor / (1 - 2 r), r = (d1-d3)/(d1-d2)."""
    r = (d1 - d3) / (d1 - d2)
    theta0 = math.atan2(factor, 1 - 2 * r)
    e = -(d1 - d2) / (math.sqrt(2) * math.sin(theta0))
    if e < 0:  # the other root of the arctangent
        theta0 += math.pi
        e = -e
    k = d1 - e * math.cos(math.radians(45.0) + theta0)
    return theta0, e, k


def test_seed_equations_6_7_need_the_factor_one_plus_root_two():
    """Eq. 6 as printed, tan(theta0) = 1 / (1 - 2 r), misses (1 + sqrt 2); with it the closed form equals
    the three-probe least squares. Linear gaps h_i = c + e cos(theta_i - theta0) + k; exact to 1e-12."""
    theta = np.radians([315.0, 45.0, 180.0])
    for theta0, e, k in ((math.radians(45.0), 3e-4, 2e-5), (math.radians(200.0), 5e-4, -1e-5), (2.5, 1e-4, 0.0)):
        d = e * np.cos(theta - theta0) + k
        got = _seed_equation_6(*d, factor=1 + math.sqrt(2))
        assert (got[0] - theta0) % (2 * math.pi) == pytest.approx(0.0, abs=1e-12)
        assert got[1] == pytest.approx(e, abs=1e-15) and got[2] == pytest.approx(k, abs=1e-15)
    printed = _seed_equation_6(*(3e-4 * np.cos(theta - math.radians(45.0))), factor=1.0)
    assert math.degrees(printed[0]) == pytest.approx(22.5)  # not 45: the printed form is garbled


def test_correction_factor_from_three_probes():
    """A journal 20 um smaller (sleeve wear) opens every gap alike: k = 20 um from the mean gaps (Eq. 5-7)."""
    layout = seed001_layout()
    t = np.linspace(0, 1, 4096, endpoint=False)
    ey = -0.52e-3 + 2e-6 * np.cos(2 * math.pi * 4 * t)
    ez = -0.1e-3 + 2e-6 * np.sin(2 * math.pi * 4 * t)
    gaps = _gaps(layout, ey, ez, k=20e-6)
    references = reference_points(layout, gaps)
    for reference in references:
        # The mean gap of a circular orbit is the gap of the mean centre to (a/R)^2 c: 1e-13 m.
        assert reference.correction == pytest.approx(20e-6, abs=1e-11)
        assert reference.residual < 1e-12
    no_k = reference_points(layout, gaps, correction=False)
    assert all(r.correction == 0.0 and r.residual > 1e-6 for r in no_k)
    orbit, film = probe_films(layout, gaps, references)[0]
    assert film == pytest.approx(gaps[:, :3] - layout.sections[0].mounting_distances, abs=1e-11)
    assert section_film(orbit, np.array([math.pi]), layout)[:, 0] == pytest.approx(film[:, 2], abs=1e-15)


def test_film_noise_propagation_matches_monte_carlo():
    """film_noise_std against 40 000 noisy samples: the sample std is within 2 % (its own scatter is 0.35 %)."""
    layout = seed001_layout()
    section = layout.sections[0]
    rng = np.random.default_rng(7)
    n = 40_000
    sigma = np.array([0.2e-6, 0.2e-6, 0.05e-6])
    ey, ez = np.full(n, -0.5e-3), np.full(n, -0.1e-3)
    gaps = _gaps(layout, ey, ez)
    gaps[:, :3] += rng.standard_normal((n, 3)) * sigma
    theta = np.radians([0.0, 45.0, 120.0, 180.0, 270.0])
    orbit, film = probe_films(layout, gaps, theta=theta)[0]
    true = film_between_circles(ey[:1], ez[:1], theta, layout)[0]
    assert (film - true).std(axis=0) == pytest.approx(film_noise_std(section, theta, 1, sigma), rel=0.02)


def test_attitude_and_position_angles():
    layout = seed001_layout()
    ey, ez = np.array([-3e-4]), np.array([-3e-4])
    orbit = identify_orbits(layout, _gaps(layout, ey, ez))[0]
    # Journal down and to port with clockwise rotation: the thinnest film at 225 deg, 45 deg past the bottom.
    assert math.degrees(orbit.position_angle[0]) == pytest.approx(225.0, abs=1e-6)
    assert math.degrees(orbit.attitude_angle[0]) == pytest.approx(45.0, abs=1e-6)
    assert orbit.eccentricity_ratio[0] == pytest.approx(math.hypot(3e-4, 3e-4) / 0.55e-3, abs=1e-8)  # 5e-12 m
