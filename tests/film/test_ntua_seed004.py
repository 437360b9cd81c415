"""The seed 004 stern-tube test case (Rossopoulos 2018, Table 5-1; examples/ntua_stern_tube.toml).

Numbers checked: the Sommerfeld number 0.0618 of Table 5-1 (0.061764 there), which fixes
the load (the two shaft forces of Table 4-5, 309.86 kN) and viscosity (0.07 Pa s; the
seed's "0.07 mPa s" is a unit slip). The seed's absolute pressures carry unit errors
(GPa for what are MPa), so for the slope variants we check the trends of Table 5-3
(linear shaft, psi_x = 0.3): slope boring raises h_min and moves the support point
towards L/2, the single slope parallel to the journal putting it at L/2. The gap in the
no-slope and double-slope columns is an open discrepancy (docs/validation.md); the tests at
the end hold its evidence (issue 11).
"""

from __future__ import annotations

from pathlib import Path

import pytest

from shaftline.cases import load_case
from shaftline.film.solve import solve_case

EXAMPLE = Path(__file__).resolve().parents[2] / "examples" / "ntua_stern_tube.toml"


@pytest.fixture(scope="module")
def runs():
    case = load_case(EXAMPLE)
    return {run.case.name.split(",")[-1].strip(): run for run in map(solve_case, case["bearing"].cases)}


def test_sommerfeld_number_of_table_5_1(runs):
    # Table 5-1 gives S = 0.061764; our load and viscosity reproduce it to 4 figures.
    for run in runs.values():
        assert run.equilibrium.state.sommerfeld_number == pytest.approx(0.061764, rel=5e-4)


def test_all_variants_carry_the_load(runs):
    for run in runs.values():
        assert run.equilibrium.converged and not run.equilibrium.contact


def test_slope_boring_raises_min_film(runs):
    hmin = {name: run.equilibrium.state.min_film_thickness for name, run in runs.items()}
    assert hmin["single slope"] > hmin["no slope"]
    assert hmin["double slope"] > hmin["no slope"]
    # Table 5-3 (linear shaft): 79.1, 175 and 145 um; the single-slope film, where the bore
    # follows the journal exactly, is the one the seed's modelling choices affect least.
    assert hmin["single slope"] == pytest.approx(175e-6, rel=0.03)


def test_slope_boring_moves_support_point_towards_mid_length(runs):
    offset = {name: abs(run.equilibrium.state.load_centre_offset) for name, run in runs.items()}
    assert offset["single slope"] < 1e-6  # bore parallel to the journal: support at L/2
    assert offset["double slope"] < offset["no slope"]
    # and the peak pressure falls, as in Table 5-3
    pmax = {name: run.equilibrium.state.max_pressure for name, run in runs.items()}
    assert pmax["single slope"] < pmax["no slope"] and pmax["double slope"] < pmax["no slope"]


def test_misalignment_puts_the_thin_film_at_the_aft_edge(runs):
    state = runs["no slope"].equilibrium.state
    assert state.min_film_z == 0.0
    assert state.load_centre_offset < 0  # support point aft of mid-length


# -- Table 5-3: the gap between the thesis and the project (docs/validation.md, issue 11) ---------
# Thesis, linear shaft, psi_x = 0.3, no slope: h_min 79.1 um, p_max 1.56 MPa, P_loss 2.395 kW;
# double slope: support point 0.0417 m forward of mid-length. benchmarks/seed004_table53.py
# prints the full comparison.
RB_MODE = {"film_start": "max_film", "cavitated_shear": "full_film"}


def _state(case, psi=None, geometry=None, **options):
    from dataclasses import replace

    from shaftline.film.bearing import JournalBearing

    geometry = geometry or case.geometry
    tilt = case.tilt_y if psi is None else psi * 2 * geometry.radial_clearance / geometry.length
    bearing = JournalBearing(geometry, case.operating, replace(case.options, **options))
    eq = bearing.equilibrium(case.load_y, case.load_z, tilt_y=tilt)
    assert eq.converged and not eq.contact
    return eq.state


@pytest.fixture(scope="module")
def cases():
    return {case.name.split(",")[-1].strip(): case for case in load_case(EXAMPLE)["bearing"].cases}


def test_where_the_bore_is_anchored_does_not_change_the_film(cases):
    """Under a given load and tilt the journal settles relative to the bore: moving the
    slope-bored bore's reference (fore, mid or aft end on the nominal axis) translates the
    equilibrium and changes nothing else, to round-off (seen 2e-14). So referring eccentricity
    to a bearing end cannot explain the gap to Table 5-3."""
    from dataclasses import replace

    double = cases["double slope"]
    states = [_state(double, geometry=replace(double.geometry, bore_anchor=a)) for a in ("fore", "mid", "aft")]
    assert len({round(s.position.ey * 1e6, 1) for s in states}) == 3  # the journal did move
    for state in states[1:]:
        for key in ("min_film_thickness", "max_pressure", "load_centre_offset", "power_loss"):
            assert getattr(state, key) == pytest.approx(getattr(states[0], key), rel=1e-10, abs=1e-12)


def test_rb_mode_brings_the_no_slope_case_close_to_table_5_3(cases):
    """With an ambient line at the largest film and shear over the whole clearance (the
    Raimondi & Boyd reading) the no-slope case comes within 10 % in h_min (seen +9.8 %) and 1 %
    in power loss (seen -0.7 %) of the thesis, and closer than the defaults in h_min, p_max
    and power loss (+23.5 %, -9.2 %, -9.0 %)."""
    default, rb = _state(cases["no slope"]), _state(cases["no slope"], **RB_MODE)
    thesis = {"min_film_thickness": 79.1e-6, "max_pressure": 1.56e6, "power_loss": 2.395e3}
    assert rb.min_film_thickness == pytest.approx(thesis["min_film_thickness"], rel=0.10)
    assert rb.power_loss == pytest.approx(thesis["power_loss"], rel=0.01)
    for key, value in thesis.items():
        assert abs(getattr(rb, key) / value - 1) < abs(getattr(default, key) / value - 1)


def test_a_larger_misalignment_reproduces_the_no_slope_pair(cases):
    """psi_x = 0.365 instead of 0.3 (defaults) gives the thesis's no-slope h_min and p_max
    together: seen 80.2 um (+1.4 %) and 1.560 MPa (-0.02 %); held to 2 % each."""
    state = _state(cases["no slope"], psi=0.365)
    assert state.min_film_thickness == pytest.approx(79.1e-6, rel=0.02)
    assert state.max_pressure == pytest.approx(1.56e6, rel=0.02)


def test_double_slope_support_point_stays_aft_open_discrepancy(cases):
    """Open discrepancy: the thesis puts the double-slope support point 0.0417 m forward of
    mid-length; the project, in either mode, 0.014-0.015 m aft of it (h_min 11-14 % above)."""
    for options in ({}, RB_MODE):
        state = _state(cases["double slope"], **options)
        assert -0.02 < state.load_centre_offset < -0.01
        assert state.min_film_thickness > 1.1 * 145e-6
