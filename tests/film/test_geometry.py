"""Film thickness geometry (seed 004 Eq. 53-55 in fixed bearing axes)."""

from __future__ import annotations

import numpy as np
import pytest

from shaftline.errors import InputError
from shaftline.film import BearingGeometry, BentJournal, BoreSegment, FilmProfile, Grid, JournalPosition, film_thickness

GEOMETRY = BearingGeometry(length=1.0, diameter=0.5, radial_clearance=5e-4)
GRID = Grid(1.0, 11, 36)


def test_aligned_film_is_c_minus_e_cos():
    position = JournalPosition.from_polar(2e-4, np.pi)
    h = film_thickness(GEOMETRY, GRID, position)
    expected = 5e-4 - 2e-4 * np.cos(GRID.theta - np.pi)
    assert np.allclose(h, expected[None, :])
    # thinnest at the bottom of the bore (theta = 180 deg), for both senses of rotation
    assert GRID.theta[np.argmin(h[0])] == pytest.approx(np.pi)


def test_rotation_sense_mirrors_horizontal_offsets():
    cw = BearingGeometry(1.0, 0.5, 5e-4, rotation=1)
    ccw = BearingGeometry(1.0, 0.5, 5e-4, rotation=-1)
    position = JournalPosition(ey=0.0, ez=2e-4)  # journal moved to starboard
    h_cw = film_thickness(cw, GRID, position)
    h_ccw = film_thickness(ccw, GRID, position)
    # starboard is theta = 90 deg for clockwise-from-aft rotation, 270 deg otherwise
    assert GRID.theta[np.argmin(h_cw[0])] == pytest.approx(np.pi / 2)
    assert GRID.theta[np.argmin(h_ccw[0])] == pytest.approx(3 * np.pi / 2)


def test_tilt_changes_film_linearly_along_the_bearing():
    tilt = 4e-4
    h = film_thickness(GEOMETRY, GRID, JournalPosition(tilt_y=tilt))
    bottom = np.argmin(np.abs(GRID.theta - np.pi))
    # journal rising forward: the film at the bottom grows forward by tilt * dz
    assert np.allclose(np.diff(h[:, bottom]), tilt * GRID.dz)
    assert h[0, bottom] == pytest.approx(5e-4 - tilt * 0.5)


def test_single_slope_bore_parallel_to_tilted_journal_gives_uniform_film():
    tilt = 4e-4
    bored = BearingGeometry(1.0, 0.5, 5e-4, bore=(BoreSegment(1.0, tilt),), bore_anchor="mid")
    h = film_thickness(bored, GRID, JournalPosition(ey=-1e-4, tilt_y=tilt))
    assert np.allclose(h, h[0][None, :])


def test_double_slope_bore_is_continuous_with_a_knuckle():
    bored = BearingGeometry(1.0, 0.5, 5e-4, bore=(BoreSegment(0.6, 3e-4), BoreSegment(0.4, 1e-4)))
    z = np.linspace(0.0, 1.0, 101)
    line, _ = bored.bore_centre_line(z)
    assert line[-1] == 0.0  # anchored at the forward end
    assert line[0] == pytest.approx(-(0.6 * 3e-4 + 0.4 * 1e-4))
    slopes = np.diff(line) / np.diff(z)
    assert np.allclose(slopes[:59], 3e-4) and np.allclose(slopes[61:], 1e-4)


def test_bent_journal_is_interpolated_linearly():
    bent = BentJournal(z=[0.0, 0.5, 1.0], dy=[-1e-4, 0.0, 0.0], dz=[0.0, 0.0, 0.0])
    geometry = BearingGeometry(1.0, 0.5, 5e-4, bent_journal=bent)
    h = film_thickness(geometry, GRID, JournalPosition())
    bottom = np.argmin(np.abs(GRID.theta - np.pi))
    expected = 5e-4 + np.interp(GRID.z, [0.0, 0.5, 1.0], [-1e-4, 0.0, 0.0])
    assert np.allclose(h[:, bottom], expected)


def test_negative_film_is_reported_not_clipped():
    h = film_thickness(GEOMETRY, GRID, JournalPosition(ey=-6e-4))
    assert h.min() == pytest.approx(-1e-4)


def test_additive_profile_follows_the_grid():
    """A wear scar given on its own table lands at the same bearing angle on any grid,
    including one whose first node is rotated (grooves, film start at h_max)."""
    theta = np.radians(np.arange(0, 360, 10.0))
    scar = np.where(np.abs(theta - np.pi) < 0.3, 3e-5, 0.0)
    profile = FilmProfile(theta=theta, z=[0.0, 1.0], delta=np.vstack([scar, scar]))
    geometry = BearingGeometry(1.0, 0.5, 5e-4, film_profile=profile)
    for start in (0.0, 0.7):
        grid = Grid(1.0, 11, 36, theta_start=start)
        added = film_thickness(geometry, grid, JournalPosition()) - 5e-4
        expected = np.interp((grid.theta) % (2 * np.pi), np.append(theta, 2 * np.pi), np.append(scar, scar[0]))
        assert np.allclose(added, expected[None, :])


def test_additive_profile_interpolates_in_z():
    profile = FilmProfile(theta=[0.0, np.pi], z=[0.0, 1.0], delta=[[0.0, 0.0], [2e-5, 2e-5]])
    geometry = BearingGeometry(1.0, 0.5, 5e-4, film_profile=profile)
    added = film_thickness(geometry, GRID, JournalPosition()) - 5e-4
    assert np.allclose(added[:, 0], 2e-5 * GRID.z)


@pytest.mark.parametrize(
    "kwargs, field",
    [
        ({"radial_clearance": 0.0}, "radial_clearance"),
        ({"radial_clearance": -1e-4}, "radial_clearance"),
        ({"length": 0.0}, "length"),
        ({"diameter": -0.5}, "diameter"),
        ({"radial_clearance": float("nan")}, "radial_clearance"),
        ({"bore": (BoreSegment(0.5, 1e-4), BoreSegment(0.4, 0.0))}, "bore.length_fraction"),
    ],
)
def test_bad_geometry_names_the_field(kwargs, field):
    values = {"length": 1.0, "diameter": 0.5, "radial_clearance": 5e-4} | kwargs
    with pytest.raises(InputError) as error:
        BearingGeometry(**values)
    assert error.value.field == field


def test_coarse_grid_is_rejected():
    with pytest.raises(InputError) as error:
        Grid(1.0, 3, 60)
    assert error.value.field == "axial_nodes"
    with pytest.raises(InputError) as error:
        Grid(1.0, 20, 8)
    assert error.value.field == "circumferential_nodes"


@pytest.mark.parametrize(
    "kwargs, field",
    [
        ({"bore": (BoreSegment(0.5, 1e-4), BoreSegment(0.5, float("nan")))}, "bore[1].slope"),
        ({"bore": (BoreSegment(1.5),)}, "bore[0].length_fraction"),
        ({"bore": (BoreSegment(1.0, 0.0, float("inf")),)}, "bore[0].slope_horizontal"),
        ({"bent_journal": BentJournal(z=[0.0, 2.0], dy=[0.0, 0.0], dz=[0.0, 0.0])}, "bent_journal.z"),
        ({"rotation": 2}, "rotation"),
        ({"bore_anchor": "middle"}, "bore_anchor"),
    ],
)
def test_bad_geometry_names_the_attribute_path(kwargs, field):
    """Fields are named from the geometry down (never from a case file): the case layer adds its own path."""
    values = {"length": 1.0, "diameter": 0.5, "radial_clearance": 5e-4} | kwargs
    with pytest.raises(InputError) as error:
        BearingGeometry(**values)
    assert error.value.field == field


def test_bad_bent_journal_and_profile_name_their_own_attributes():
    with pytest.raises(InputError) as error:
        BentJournal(z=[0.0, 1.0], dy=[0.0, float("nan")], dz=[0.0, 0.0])
    assert error.value.field == "dy"
    with pytest.raises(InputError) as error:
        FilmProfile(theta=[0.0, 1.0], z=[0.0], delta=[[0.0, 0.0, 0.0]])
    assert error.value.field == "delta"


def test_grid_nodes_are_shared_read_only_and_results_get_their_own():
    """A grid computes its node angles and stations once and hands out read-only arrays (the
    solver asks for them at every film solution); what a user receives — a state's ``theta``
    and ``z``, ``axial_stations`` — stays a writable array of its own, as before."""
    from tests.conftest import make_bearing

    grid = Grid(length=0.1, axial_nodes=11, circumferential_nodes=24)
    assert grid.z is grid.z and not grid.z.flags.writeable and not grid.theta.flags.writeable
    with pytest.raises(ValueError):
        grid.z[0] = 1.0
    bearing = make_bearing(1.0, axial_nodes=11, circumferential_nodes=24)
    state = bearing.solve_at(JournalPosition.from_polar(3e-5, np.pi))
    stations = bearing.axial_stations
    for array in (state.theta, state.z, stations):
        assert array.flags.writeable
    state.z[0] = -1.0
    assert bearing.axial_stations[0] == 0.0 and bearing.solve_at(state.position).z[0] == 0.0
