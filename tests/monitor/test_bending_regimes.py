"""Centre line along the bearing (seed 001 Eq. 8-9, Sect. 5.3) and lubrication regimes (Eq. 10, Table 4)."""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.optimize import lsq_linear

from shaftline.errors import InputError
from shaftline.monitor.bending import (
    Basis,
    film_map,
    least_squares_line,
    min_film_along,
    model_line,
    model_shape,
    seed_objective,
)
from shaftline.monitor.forward import rig_bending_shape, rig_shaft_line
from shaftline.monitor.identification import SectionOrbit, film_between_circles
from shaftline.monitor.probes import seed001_layout
from shaftline.monitor.regimes import classify, film_ratio, regime_lengths, thresholds


def _orbits(positions, ey, ez, k=0.0):
    return [SectionOrbit(f"S{i}", p, ey[:, i], ez[:, i], k, 0.55e-3, 1) for i, p in enumerate(positions)]


def test_quadratic_line_through_three_sections_is_exact_and_degree_one_is_equation_8():
    positions = np.array([0.292, 0.4295, 0.856])
    t = np.linspace(0, 1, 50)[:, None]
    a0, a1, a2 = -4e-4 + 1e-6 * np.sin(6 * t), 5e-5 * (1 + t), -2e-4
    line = lambda z: a0 + a1 * (z - 0.6) + a2 * (z - 0.6) ** 2  # noqa: E731
    ey = line(positions)
    ez = -1e-4 + 3e-5 * (positions - 0.6) + 0 * t
    fitted = least_squares_line(_orbits(positions, ey, ez), degree=2, origin=0.6)
    z = np.linspace(0, 1.2, 13)
    assert fitted.at(z)[0] == pytest.approx(line(z), abs=1e-15)
    assert fitted.tilt(z)[1] == pytest.approx(np.full((50, 13), 3e-5), abs=1e-15)
    straight = least_squares_line(_orbits(positions[[0, 2]], ez[:, [0, 2]], ez[:, [0, 2]]), degree=2)
    assert straight.basis_y.degree == 1  # two sections: Eq. 8's straight, tilted journal
    # Eq. 8: the centre anywhere is that of one section plus the distance times the tilt.
    at_d3 = straight.at(np.array([0.856]))[1][:, 0]
    assert at_d3 == pytest.approx(ez[:, 0] + (0.856 - 0.292) * straight.tilt(np.array([0.292]))[1][:, 0], abs=1e-15)


def test_model_shape_is_the_alignment_deflection_less_its_chord():
    z, shape = rig_bending_shape()
    assert shape[0] == pytest.approx(0.0, abs=1e-15) and shape[-1] == pytest.approx(0.0, abs=1e-15)
    # The overhung mass lifts the middle of the stern bearing above the chord (the seed's "mid-arch").
    assert shape.max() > 20e-6 and shape.argmax() not in (0, z.size - 1)
    with pytest.raises(InputError, match="^bearing = 'aft'"):
        model_shape(rig_shaft_line(), "aft", z)


def test_model_line_recovers_offset_tilt_and_scale_and_agrees_with_bounded_least_squares():
    """DE on the seed's objective: the true line to 1e-10 m, and the bounded linear least squares optimum to 1e-9 m."""
    z, shape = rig_bending_shape()
    positions = np.array([0.292, 0.4295, 0.856])
    basis = Basis(0.6, 1, z, shape)
    true_y, true_z = np.array([-5.2e-4, 3e-6, 0.4]), np.array([-1e-4, -2e-6, -0.2])
    rng = np.random.default_rng(2)
    whirl = 1e-6 * rng.standard_normal((200, 1))
    ey = true_y @ basis.values(positions) + whirl
    ez = true_z @ basis.values(positions) - whirl
    line = model_line(_orbits(positions, ey, ez), z, shape, 0.55e-3, 1.2)
    assert line.objective == pytest.approx(-1.0, abs=1e-8)
    stations = np.linspace(0, 1.2, 25)
    want_y = (true_y @ basis.values(stations))[None, :] + whirl
    assert line.at(stations)[0] == pytest.approx(want_y, abs=1e-10)
    # Bounds bite: a shape bent the other way is held at scale 0 and matched by least squares otherwise.
    bent_back = np.array([-5.2e-4, 3e-6, -0.4]) @ basis.values(positions)
    held = model_line(_orbits(positions, bent_back[None, :], ez[:1]), z, shape, 0.55e-3, 1.2)
    matrix = basis.values(positions).T
    reference = lsq_linear(matrix, bent_back, bounds=([-1, -1, 0.0], [1, 1, 3.0]), tol=1e-15)
    assert held.coefficients_y[0, 2] == pytest.approx(0.0, abs=1e-6)
    # 1e-9 m: the optimiser stops there, 25 times below the finest probe resolution (0.025 um).
    assert held.at(positions)[0][0] == pytest.approx(matrix @ reference.x, abs=1e-9)


def test_seed_objective_is_rmse_over_scale_less_correlation():
    measured = np.array([1.0, 2.0, 4.0])
    assert seed_objective(measured, measured, 1.0) == pytest.approx(-1.0)
    assert seed_objective(measured + 1.0, measured, 2.0) == pytest.approx(0.5 - 1.0)
    assert seed_objective(-measured, measured, 1.0) == pytest.approx(math.sqrt(np.mean(4 * measured**2)) + 1.0)


def test_film_map_equals_the_section_film_at_the_sections():
    layout = seed001_layout()
    positions = layout.positions
    ey = np.array([[-5.4e-4, -5.3e-4, -5.1e-4]])
    ez = np.array([[-0.6e-4, -0.5e-4, -0.4e-4]])
    line = least_squares_line(_orbits(positions, ey, ez, k=3e-6))
    theta = np.radians(np.arange(0, 360, 30.0))
    film = film_map(line, layout, theta, positions)
    for i in range(3):
        want = film_between_circles(ey[:, i], ez[:, i], theta, layout, 3e-6)
        assert film[:, i, :] == pytest.approx(want, abs=1e-15)
    hmin = min_film_along(line, layout, positions)
    fine = film_map(line, layout, np.radians(np.arange(0, 360, 0.01)), positions)
    assert hmin == pytest.approx(fine.min(axis=2), abs=1e-11)  # 0.01 deg grid: e (0.005 deg)^2 / 2 = 2e-12 m


def test_seed_thresholds_are_2_24_and_6_71_um():
    """Seed 001 Sect. 5.3: Ra 1.6 and 0.8 um, Rq = 1.25 Ra: lambda = 1 at 2.24 um and 3 at 6.71 um."""
    low, high = thresholds(seed001_layout())
    assert round(low * 1e6, 2) == 2.24 and round(high * 1e6, 2) == 6.71
    layout = seed001_layout()
    assert film_ratio(np.array([low, high]), layout) == pytest.approx([1.0, 3.0])
    assert classify(np.array([1e-6, 2.3e-6, 6.7e-6, 6.8e-6]), layout).tolist() == [0, 1, 1, 2]


def test_regime_lengths_of_a_linear_film_are_exact_on_a_coarse_grid():
    """h rising linearly from 0 to 12 um over 1.2 m: boundary 0.2236 m, mixed 0.4472 m, the rest hydrodynamic."""
    layout = seed001_layout()
    low, high = thresholds(layout)
    z = np.linspace(0, 1.2, 4)
    h = 12e-6 * z / 1.2
    lengths = regime_lengths(z, h, layout)
    assert lengths.boundary[0] == pytest.approx(low / 1e-5, rel=1e-12)
    assert lengths.mixed[0] == pytest.approx((high - low) / 1e-5, rel=1e-12)
    assert lengths.boundary[0] + lengths.mixed[0] + lengths.hydrodynamic[0] == pytest.approx(1.2)
    falling = regime_lengths(z, h[::-1], layout)
    assert falling.boundary[0] == pytest.approx(lengths.boundary[0]) and falling.mixed[0] == pytest.approx(
        lengths.mixed[0]
    )
    flat = regime_lengths(z, np.full(4, 4e-6), layout)
    assert (flat.boundary[0], flat.mixed[0], flat.hydrodynamic[0]) == (0.0, pytest.approx(1.2), 0.0)


def test_one_section_gives_a_parallel_journal_and_the_model_shape_needs_three():
    positions = np.array([0.4])
    ey, ez = np.array([[-5e-4], [-4e-4]]), np.array([[1e-5], [2e-5]])
    line = least_squares_line(_orbits(positions, ey, ez))
    assert line.at(np.array([0.0, 1.2]))[0] == pytest.approx(np.array([[-5e-4, -5e-4], [-4e-4, -4e-4]]), abs=1e-18)
    z, shape = rig_bending_shape()
    two = _orbits(np.array([0.3, 0.9]), np.zeros((1, 2)), np.zeros((1, 2)))
    with pytest.raises(InputError, match="^orbits = 2 sections: allowed at least 3"):
        model_line(two, z, shape, 0.55e-3, 1.2)
