"""JFO on a published mass-conserving benchmark: Almqvist's pocketed slider.

No published mass-conserving test case could be found with its results in numbers (tables);
the sources checked and why each falls short are listed in docs/validation.md ("Published
benchmark: the pocketed slider"). This module takes the best-defined published case instead,
the one-dimensional pocketed slider of the routine ``LCP_pocket_pad.m`` in

    A. Almqvist, "A cavitation algorithm", MATLAB Central File Exchange (25 Apr 2013,
    updated 22 Apr 2016), read in the copy of that page in the nvidia/Nemotron-CC-Math-v1
    data set (huggingface.co/datasets/nvidia/Nemotron-CC-Math-v1),

which solves the complementarity formulation of A. Almqvist, J. Fabricius, R. Larsson,
P. Wall (2014), "A new approach for studying cavitation in lubrication", J. Tribol. 136(1),
011706 (whose abstract says Matlab code of a model problem is made available).

Its definition, quoted from that routine: length L = 20 mm; film h0 = 1 um except in a
pocket a < x < a + b with a = 2 mm, b = 3 mm, where h1 = 10 um; one surface sliding at
V = 1 m/s; viscosity 0.01 Pa s; pressure 100 kPa at both ends; cavitation pressure 50 kPa.
The routine's own lubricant is compressible (bulk modulus 5e8 Pa); shaftline's is not, and
here that matters: the pressure is built by a flow excess of only 4e-4 of the Couette flow,
the same order as the density change (p - pc)/beta = 8.5e-4, so the routine's output is not
a reference for an incompressible solver. No numerical result of the case was reachable
either, so the reference values here are the closed-form incompressible JFO solution of the
definition (h is piecewise constant, so p is piecewise linear and two mass balances fix
everything; derivation in docs/validation.md), not numbers read from a publication.

shaftline represents the slider as a journal bearing of circumference L with c = h0 at zero
eccentricity, the pocket as a ``FilmProfile`` of +9 um, and the two ends as one axial supply
groove at ambient pressure. The published case is infinitely wide (1-D); a bearing of finite
length is not: the pocket's axial conductance, 1000 times the land's, carries flux comparable
to the 4e-4 share of the Couette flow that builds the pressure, so the mid-plane of a finite
JFO bearing approaches the 1-D answer only for lengths of metres (docs/validation.md gives the
measured trend). The solution is therefore taken on a 1-D slice of the bearing's own film
(three rows, the outer two fixed, axial steps 1e3 times the circumferential one), as in
tests/film/test_jfo.py.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from shaftline.film import BearingGeometry, JournalBearing, JournalPosition, OperatingPoint, SolverOptions
from shaftline.film.cavitation import CAVITATION_MODELS, NodeGrid
from shaftline.film.geometry import FilmProfile
from shaftline.film.problem import SupplyGroove
from shaftline.film.stencil import build_stencil

# -- the published definition (LCP_pocket_pad.m) ----------------------------------------------
LENGTH = 20e-3  # m, slider length = bearing circumference
POCKET_START = 2e-3  # m, a
POCKET_LENGTH = 3e-3  # m, b
LAND_FILM = 1e-6  # m, h0
POCKET_FILM = 10e-6  # m, h1
SPEED = 1.0  # m/s, V
VISCOSITY = 0.01  # Pa s
AMBIENT = 100e3  # Pa (absolute), both ends
CAVITATION = 50e3  # Pa (absolute)

RADIUS = LENGTH / (2 * math.pi)


def closed_form() -> dict[str, float]:
    """The incompressible solution of the definition, absolute pressures, SI units.

    JFO: the film ruptures at the pocket's leading edge (x = a, p = pc), so the flow of the
    inlet land is ``q = V h0/2 + (pa - pc) h0^3 / (12 mu a)``; the cavity carries it at film
    fraction ``F = 2 q / (V h1)``; the exit land carries the same q back to pa, which fixes the
    peak at the pocket's trailing edge, and the pocket's full-film part (flow q again) rises
    from pc to that peak, which fixes the reformation point ``x_f``.

    Reynolds (Swift-Stieber): the same rupture at x = a, but then full film over the pocket and
    the exit land from pc to pa with one flow Q_R of its own (the mass made at rupture).
    """
    h0, h1, a, b = LAND_FILM, POCKET_FILM, POCKET_START, POCKET_LENGTH
    exit_land = LENGTH - a - b
    k = 12.0 * VISCOSITY
    q = SPEED * h0 / 2 + (AMBIENT - CAVITATION) * h0**3 / (k * a)
    peak = AMBIENT + k * (q - SPEED * h0 / 2) * exit_land / h0**3
    reformation = a + b - (peak - CAVITATION) * h1**3 / (k * (SPEED * h1 / 2 - q))
    resistance = b / h1**3 + exit_land / h0**3
    flow_reynolds = (
        SPEED * h1 / 2 * b / h1**3 + SPEED * h0 / 2 * exit_land / h0**3 - (AMBIENT - CAVITATION) / k
    ) / resistance
    peak_reynolds = CAVITATION + k * (SPEED * h1 / 2 - flow_reynolds) * b / h1**3
    return {
        "flow": q,
        "film_fraction": 2 * q / (SPEED * h1),
        "peak": peak,
        "reformation": reformation,
        "flow_reynolds": flow_reynolds,
        "peak_reynolds": peak_reynolds,
    }


def pocket_bearing(nodes: int) -> JournalBearing:
    """The slider as a shaftline bearing: circumference L, c = h0, pocket as a film profile,
    both slider ends as one axial groove at ambient (gauge 0), cavitation at pc - pa."""
    edge = 1e-9  # m: the table steps over 1 nm, far below a grid cell (10 um at 2000 nodes)
    x = np.array([0.0, POCKET_START - edge, POCKET_START + edge, POCKET_START + POCKET_LENGTH - edge])
    x = np.append(x, [POCKET_START + POCKET_LENGTH + edge, LENGTH - 1e-6])
    depth = np.array([0.0, 0.0, 1.0, 1.0, 0.0, 0.0]) * (POCKET_FILM - LAND_FILM)
    profile = FilmProfile(theta=x / RADIUS, z=np.array([0.0]), delta=depth[None, :])
    # Only the film of this bearing is used (a 1-D slice, see the module docstring): its axial
    # length just keeps the cells within the solver's aspect limit.
    geometry = BearingGeometry(length=4 * LENGTH, diameter=2 * RADIUS, radial_clearance=LAND_FILM, film_profile=profile)
    operating = OperatingPoint(
        speed=SPEED / RADIUS,
        viscosity=VISCOSITY,
        cavitation_pressure=CAVITATION - AMBIENT,
        grooves=(SupplyGroove(angle=0.0, pressure=0.0),),
    )
    axial = max(5, int(math.ceil(4 * nodes / 100)) + 1)
    return JournalBearing(geometry, operating, SolverOptions(axial_nodes=axial, circumferential_nodes=nodes))


def solve_slice(nodes: int, model: str) -> dict[str, np.ndarray]:
    """Pressure (absolute, Pa), film fraction and cavitated set along the slider, and x (m),
    from the bearing's own film on a 1-D slice of its grid (groove node fixed at ambient)."""
    bearing = pocket_bearing(nodes)
    position = JournalPosition(0.0, 0.0)
    grid = bearing.grid(position)
    film = bearing.film(position)[0] / LAND_FILM
    d_theta, d_z = 2 * np.pi / nodes, 1e3
    films = np.tile(film, (3, 1))
    fixed = np.zeros((3, nodes), dtype=bool)
    fixed[[0, 2]] = True
    fixed[1, 0] = True  # the groove, on the grid's first angle
    feed = (AMBIENT - CAVITATION) / bearing.pressure_scale
    grid_nodes = NodeGrid.of((3, nodes), d_theta, d_z, fixed, np.where(fixed, feed, 0.0))
    solver = CAVITATION_MODELS[model](grid_nodes, SolverOptions())
    stencil = build_stencil(films, d_theta, d_z)
    solution = solver.solve(stencil, films)
    pressure = np.where(fixed, feed, solution.pressure)[1] * bearing.pressure_scale + CAVITATION
    x = ((grid.theta - grid.theta[0]) % (2 * np.pi)) * RADIUS
    return {
        "x": x,
        "pressure": pressure,
        "film_fraction": solution.film_fraction[1],
        "cavitated": solution.cavitated[1],
    }


def land_flow(result: dict[str, np.ndarray], start: float, stop: float) -> float:
    """Flow per unit width over a uniform land, V h0/2 - h0^3/(12 mu) dp/dx, m^2/s: the
    discrete pressure is exactly linear there, so two nodes give its slope."""
    x, p = result["x"], result["pressure"]
    i, j = np.searchsorted(x, start), np.searchsorted(x, stop)
    slope = (p[j] - p[i]) / (x[j] - x[i])
    return SPEED * LAND_FILM / 2 - LAND_FILM**3 / (12 * VISCOSITY) * slope


@pytest.fixture(scope="module")
def slices():
    return {(n, m): solve_slice(n, m) for n in (1000, 2000) for m in ("jfo", "reynolds")}


def test_cavity_film_fraction_and_mass_conservation(slices):
    """Mass conservation, the defining JFO property, against the closed form on 2000 nodes.
    The film fraction in the pocket's cavity is 2q/(V h1) = 0.1000417 to 1e-5 (seen 2.2e-6,
    4.4e-6 on 1000 nodes); the inlet land's flow is q to 5e-6 of the Couette flow V h0/2
    (seen 2.1e-6: the cavity starts on the node before the step, which shortens the inlet
    land by about one cell, 1 % of it on 1000 nodes: a first-order error); the exit land carries the inlet
    land's flow to 3e-7 of the Couette flow (seen 4e-8, 1.3e-7 on 1000 nodes: the slice's
    leak into its two fixed rows, which falls as 1/d_z^2 and is 1e-9 with d_z = 1e4).
    The Reynolds condition on the same film makes mass at rupture: its exit land carries
    6.64e-10 m^2/s (1.3e-3 of the Couette flow) more than its inlet land in closed form; the
    solver's excess, first order in the cell (+14 % on 1000 nodes, +7 % on 2000), gives it
    through the Richardson value 2 m(2000) - m(1000) within 1 % (seen 8e-5)."""
    ref = closed_form()
    jfo = slices[2000, "jfo"]
    x = jfo["x"]
    inside = (x > POCKET_START + 0.25e-3) & (x < POCKET_START + 1.5e-3)  # well inside the cavity
    assert jfo["cavitated"][inside].all()
    assert jfo["film_fraction"][inside] == pytest.approx(ref["film_fraction"], rel=1e-5)
    couette = SPEED * LAND_FILM / 2
    inlet, outlet = land_flow(jfo, 0.2e-3, 1.8e-3), land_flow(jfo, 6e-3, 19e-3)
    assert inlet == pytest.approx(ref["flow"], abs=5e-6 * couette)
    assert abs(outlet - inlet) <= 3e-7 * couette
    made = {}
    for nodes in (1000, 2000):
        reynolds = slices[nodes, "reynolds"]
        made[nodes] = land_flow(reynolds, 6e-3, 19e-3) - land_flow(reynolds, 0.2e-3, 1.8e-3)
    expected = ref["flow_reynolds"] - ref["flow"]
    assert made[2000] == pytest.approx(expected, rel=0.1)
    assert 2 * made[2000] - made[1000] == pytest.approx(expected, rel=1e-2)
    assert made[2000] > 1e4 * abs(outlet - inlet)  # JFO conserves what Reynolds makes


def test_jfo_rupture_reformation_and_peak_against_the_closed_form(slices):
    """Free boundaries and peak on 1000 and 2000 nodes. The film ruptures at the pocket's
    leading edge (seen on the node one cell before it); reformation lies 7-8 cells
    downstream of x_f = 4.2129 mm on both grids (first-order upwind transport of the film
    fraction at the front, plus the arithmetic-mean film on the face across each step), so
    within 10 cells; the peak at the trailing edge is 475.0 kPa within 1.5 % on 1000 nodes and
    0.75 % on 2000 (seen +0.72 % and +0.35 %: first order, the error halves as the cell does)."""
    ref = closed_form()
    for nodes, peak_tolerance in ((1000, 0.015), (2000, 0.0075)):
        result = slices[nodes, "jfo"]
        x, cell = result["x"], LENGTH / nodes
        cavity = np.flatnonzero(result["cavitated"])
        assert abs(x[cavity[0]] - POCKET_START) <= 1.5 * cell  # the node before the step
        reformation = x[cavity[-1]] + 0.5 * cell
        assert 0.0 <= reformation - ref["reformation"] <= 10 * cell
        peak = result["pressure"].max()
        assert peak == pytest.approx(ref["peak"], rel=peak_tolerance)
        assert abs(x[result["pressure"].argmax()] - (POCKET_START + POCKET_LENGTH)) <= 1.5 * cell  # node after
    coarse = slices[1000, "jfo"]["pressure"].max() - ref["peak"]
    fine = slices[2000, "jfo"]["pressure"].max() - ref["peak"]
    assert 1.6 <= coarse / fine <= 2.4  # first order (seen 2.03)


def test_the_reynolds_condition_beside_it(slices):
    """The Swift-Stieber solution of the same film, the contrast the published case exists to
    show: it cavitates on a single node at the pocket's leading edge (JFO: 2.3 mm, most of the
    pocket), fills the pocket with full film and peaks at 1.670 MPa in closed form, 3.5 times
    the JFO peak. Its step error is larger than the JFO one (+10 % on 1000 nodes, +5 % on
    2000, first order), so each grid is held to 12 % and 6 % and the closed form is checked
    through the Richardson value 2 p(2000) - p(1000), within 1e-4 (seen 3.6e-6)."""
    ref = closed_form()
    peaks = {}
    for nodes, tolerance in ((1000, 0.12), (2000, 0.06)):
        result = slices[nodes, "reynolds"]
        cavity = np.flatnonzero(result["cavitated"])
        assert cavity.size == 1 and abs(result["x"][cavity[0]] - POCKET_START) <= 1.5 * LENGTH / nodes
        peaks[nodes] = result["pressure"].max()
        assert peaks[nodes] == pytest.approx(ref["peak_reynolds"], rel=tolerance)
    assert 2 * peaks[2000] - peaks[1000] == pytest.approx(ref["peak_reynolds"], rel=1e-4)
    assert peaks[2000] > 3 * slices[2000, "jfo"]["pressure"].max()
