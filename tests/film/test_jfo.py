"""Mass-conserving (JFO) cavitation: the solver's defining properties, its linearisation,
and an independent check against the analytic 1-D JFO solution (docs/theory.md, Sect. 4)."""

from __future__ import annotations

from dataclasses import replace

import numpy as np
import pytest
from scipy.integrate import quad
from scipy.optimize import fsolve

from shaftline.film import JournalPosition, SolverOptions
from shaftline.film.cavitation import MassConserving, NodeGrid, ReynoldsCondition, SolverCounts
from shaftline.film.cavitation.jfo import jfo_residual
from shaftline.film.equilibrium import find_equilibrium
from shaftline.film.equilibrium.starts import coarse_start
from shaftline.film.stencil import apply_operator, build_stencil, stencil_diagonal
from tests.conftest import CLEARANCE, make_bearing


@pytest.fixture(scope="module")
def jfo_bearing():
    """Edge-fed plain bearing (edges 20 kPa above the cavitation pressure): a starved film
    with rupture and reformation inside the grid."""
    return make_bearing(1.0, cavitation_pressure=-2e4, axial_nodes=31, circumferential_nodes=120, cavitation="jfo")


def test_every_cell_balances_and_the_complementarity_holds(jfo_bearing):
    """The discrete mass balance (C2) of every free cell to round-off (1e-12 of the largest
    Couette flux), P >= 0, 0 <= s <= 1 and P s = 0 exactly; a real cavitated zone exists."""
    evaluation = jfo_bearing.solver.evaluate(JournalPosition.from_polar(0.7 * CLEARANCE, np.pi), warm=False)
    solution = evaluation.cavitation
    residual = jfo_residual(evaluation.stencil, evaluation.relative_pressure, solution.void, solution.fixed)
    assert np.abs(residual).max() <= 1e-12 * np.abs(evaluation.stencil.couette_face).max()
    assert solution.void.max() > 0.3
    assert solution.pressure.min() >= 0.0
    assert 0.0 <= solution.void.min() and solution.void.max() <= 1.0
    assert np.all(solution.pressure[solution.cavitated] == 0.0)
    assert np.all(solution.void[~solution.cavitated] == 0.0)


def test_warm_start_gives_the_cold_solution(jfo_bearing):
    """The solution of the complementarity problem does not depend on the start: a warm start
    from a neighbouring position (through the set predictor) agrees with a cold one to 1e-9."""
    near = JournalPosition.from_polar(0.65 * CLEARANCE, np.pi + 0.1)
    here = JournalPosition.from_polar(0.7 * CLEARANCE, np.pi)
    jfo_bearing.solve_at(near, warm_start=False)
    warm = jfo_bearing.solve_at(here, warm_start=True)
    cold = jfo_bearing.solve_at(here, warm_start=False)
    assert np.abs(warm.pressure - cold.pressure).max() <= 1e-9 * cold.max_pressure
    assert np.abs(warm.film_fraction - cold.film_fraction).max() <= 1e-9


def test_linearisation_matches_central_differences(jfo_bearing):
    """dF/d(ey, ez) from the JFO Jacobian (void-fraction transport included) against central
    differences of cold solutions with a step of 1e-4 c: agreement to 1e-5 of the largest
    entry (seen: 1.3e-7; the differences carry O(h^2) and set-switch errors). The frozen-set
    Reynolds linearisation used before issue 10 misses the reformation term by far more."""
    position = JournalPosition.from_polar(0.7 * CLEARANCE, np.pi)
    exact = jfo_bearing.linearise(position).offset_derivative
    h = 1e-4 * CLEARANCE
    columns = []
    for dy, dz in ((h, 0.0), (0.0, h)):
        up = jfo_bearing.solve_at(JournalPosition(ey=position.ey + dy, ez=position.ez + dz), warm_start=False)
        down = jfo_bearing.solve_at(JournalPosition(ey=position.ey - dy, ez=position.ez - dz), warm_start=False)
        columns.append([(up.force_y - down.force_y) / (2 * h), (up.force_z - down.force_z) / (2 * h)])
    differences = np.array(columns).T
    assert np.abs(exact - differences).max() <= 1e-5 * np.abs(differences).max()


def test_equilibrium_converges_quadratically(jfo_bearing):
    """With the exact linearisation Newton's residual falls quadratically: each share of the
    load at most 10x the square of the one before (seen 0.153, 0.0134, 1.2e-4, 9.4e-9), and the
    equilibrium needs at most 5 iterations (17, linear, with the frozen Reynolds Jacobian)."""
    history: list[float] = []
    eq = jfo_bearing.equilibrium(load_y=-5e3, progress=lambda k, r: history.append(r))
    assert eq.converged and eq.iterations <= 5
    assert all(b <= 10.0 * a * a for a, b in zip(history[1:-1], history[2:], strict=False))


def _one_dimensional(nt: int, feed: float, film):
    """An infinitely long bearing on the solver's grid: three rows, the outer two fixed, an axial
    step 1e3 times the circumferential one (axial flow 1e-10 of the circumferential), and a feed
    node of pressure ``feed`` at theta = 0."""
    d_theta, d_z = 2 * np.pi / nt, 1e3
    theta = np.arange(nt) * d_theta
    h = np.tile(film(theta), (3, 1))
    fixed = np.zeros((3, nt), bool)
    fixed[[0, 2]] = True
    fixed[1, 0] = True
    nodes = NodeGrid.of((3, nt), d_theta, d_z, fixed, np.where(fixed, feed, 0.0))
    stencil = build_stencil(h, d_theta, d_z)
    return theta, MassConserving(nodes, SolverOptions()).solve(stencil, h), nodes, stencil, h


def test_one_dimensional_jfo_against_the_analytic_solution():
    """Infinitely long bearing H = 1 - 0.6 sin(theta) fed at theta = 0 with P_f = 0.05: the
    analytic JFO solution (docs/theory.md, Sect. 4: constant flux Q = H(theta_r), two
    quadratures fix rupture theta_r and reformation theta_f). The scheme is second order in
    the full film and first order (upwind) at the free boundaries: on 720 nodes the peak
    pressure within 1e-4 relative (seen 3e-5), rupture and reformation within 2 cells (seen
    0.3 and 0.1), the film fraction F = Q/H in mid-cavity within 1 % (seen 0.1 %)."""
    eps, feed = 0.6, 0.05

    def film(t):
        return 1.0 - eps * np.sin(t)

    def gradient(t, q):
        return (film(t) - q) / film(t) ** 3

    def conditions(x):
        rupture, reform = x
        q = film(rupture)
        return [
            feed + quad(gradient, 0.0, rupture, args=(q,))[0],
            quad(gradient, reform, 2 * np.pi, args=(q,))[0] - feed,
        ]

    rupture, reform = fsolve(conditions, [2.2, 5.0], xtol=1e-13)
    flux = film(rupture)
    grid = np.linspace(0.0, rupture, 4001)
    peak = feed + max(quad(gradient, 0.0, t, args=(flux,))[0] for t in grid[::10])
    nt = 720
    theta, solution, *_ = _one_dimensional(nt, feed, film)
    cavity = np.flatnonzero(solution.cavitated[1])
    d_theta = 2 * np.pi / nt
    assert solution.pressure[1].max() == pytest.approx(peak, rel=1e-4)
    assert abs(theta[cavity[0]] - rupture) <= 2 * d_theta
    assert abs(theta[cavity[-1]] + d_theta - reform) <= 2 * d_theta
    middle = cavity[cavity.size // 2]
    assert solution.film_fraction[1, middle] == pytest.approx(flux / film(theta[middle]), rel=1e-2)


def test_jfo_equals_the_reynolds_condition_where_nothing_reforms():
    """Fed at the thickest film with the feed at the cavitation pressure, the cavitated zone runs
    from rupture into the feed line: nothing reforms inside the grid, and the JFO pressure is
    the Swift-Stieber one to round-off (1e-10 of the peak)."""
    _, solution, nodes, stencil, film = _one_dimensional(360, 0.0, lambda t: 1.0 + 0.6 * np.cos(t))
    reynolds = ReynoldsCondition(nodes, SolverOptions()).solve(stencil, film)
    assert solution.cavitated.any()
    assert np.array_equal(solution.cavitated, reynolds.cavitated)
    assert np.abs(solution.pressure - reynolds.pressure).max() <= 1e-10 * reynolds.pressure.max()


def test_assembled_jacobian_is_the_residual_on_its_set(jfo_bearing):
    """The sparse Jacobian of a set, as the solver factorises it for its solution, is the
    residual's map on that set: for any u of that set's signs (u < 0 exactly on the cavitated
    nodes) the residual (C2) of P = u+, s = u- computed cell by cell from the stencil, plus the
    right-hand side, is J u, so the solution's factor (``unknown_response``, ``du = -J^-1 dR``)
    brings it back to u: the piecewise-linear map is linear on each set. To 1e-11 of the largest
    |u| (seen 7e-13: the back-substitution carries the condition of J; J u itself matched the
    residual to 5e-14 of the largest flux)."""
    evaluation = jfo_bearing.solver.evaluate(JournalPosition.from_polar(0.7 * CLEARANCE, np.pi), warm=False)
    model = jfo_bearing.solver.cavitation
    solution, stencil = evaluation.cavitation, evaluation.stencil
    cavitated, fixed = solution.cavitated, model.fixed
    rng = np.random.default_rng(7)
    magnitude = rng.uniform(0.01, 1.0, fixed.shape)
    u = np.where(cavitated, -magnitude, magnitude)
    pressure = np.where(fixed, model.fixed_pressure, np.maximum(u, 0.0))
    void = np.where(fixed, 0.0, np.maximum(-u, 0.0))
    expected = jfo_residual(stencil, pressure, void, fixed)
    boundary = np.where(fixed, model.fixed_pressure, 0.0)
    rhs = stencil.rhs - apply_operator(stencil.c_theta, stencil.c_z, boundary)
    # J u = R(u) + b on the free nodes; the fixed nodes' rows are decoupled (u = 0 there)
    recovered = -solution.unknown_response(np.where(fixed, 0.0, expected + rhs)[None])[0]
    free_u = np.where(fixed, 0.0, u)
    assert np.abs(recovered - free_u).max() <= 1e-11 * np.abs(free_u).max()


def test_a_kept_elimination_order_solves_as_a_fresh_one(jfo_bearing):
    """A JFO factor in the elimination order kept from another film's set (rows and columns
    permuted to it, SuperLU keeping that order) solves the same system as one ordered afresh:
    on a film far from the one the order was found for, to 1e-10 of the largest entry (two
    pivot orders' round-off) for one right-hand side and for several; a film solved with a kept
    order (warm, after a nearby film) agrees with one solved after the solver forgot its order
    to 1e-10 of the peak; and an order that lets the fill grow past
    ``JfoOptions.ordering_fill_growth`` is dropped, so that the next set is ordered afresh.

    The far film's order is made to serve by a model on the same grid that keeps any order
    (``ordering_set_change`` and ``ordering_fill_growth`` unbounded); the fresh factor is the
    one the solution rebuilds once the solver has dropped its own (``JfoSolution.factor``)."""
    solver = jfo_bearing.solver
    model = solver.cavitation
    c = jfo_bearing.geometry.radial_clearance
    far_film = solver.evaluate(JournalPosition.from_polar(0.3 * CLEARANCE, 2.0), warm=False)
    here = JournalPosition.from_polar(0.8 * CLEARANCE, np.pi)
    evaluation = solver.evaluate(here, warm=False)
    stencil, cavitated = evaluation.stencil, evaluation.cavitated

    options = jfo_bearing.options
    keeping = replace(options, jfo=replace(options.jfo, ordering_set_change=1e9, ordering_fill_growth=1e9))
    kept_model = MassConserving(model.nodes, keeping, SolverCounts())
    kept_model.solve(far_film.stencil, far_film.film / c)
    far = kept_model.ordering
    assert far is not None
    in_far_order = kept_model.solve(stencil, evaluation.film / c)
    assert kept_model.ordering is far  # every factor of this film was made in the far film's order
    np.testing.assert_array_equal(in_far_order.cavitated, cavitated)
    ordered = in_far_order.factor()
    model.drop_factors()  # releases the solution's factor: it is rebuilt, ordered afresh
    fresh = evaluation.cavitation.factor()
    assert ordered.order is not None and fresh.order is None
    rhs = np.random.default_rng(3).normal(size=(model.fixed.size, 3))
    for right in (rhs[:, 0], rhs):
        expected = fresh.solve(right)
        assert np.abs(ordered.solve(right) - expected).max() <= 1e-10 * np.abs(expected).max()

    solver.evaluate(JournalPosition.from_polar(0.79 * CLEARANCE, np.pi + 0.01), warm=False)
    kept = model.ordering
    with_kept = solver.evaluate(here, warm=True)
    assert model.ordering is kept  # the nearby film's order served this film's sets
    model.drop_factors()
    afresh = solver.evaluate(here, warm=False)
    assert model.ordering is not kept
    peak = np.abs(afresh.relative_pressure).max()
    assert np.abs(with_kept.relative_pressure - afresh.relative_pressure).max() <= 1e-10 * peak

    kept = model.ordering
    assert kept is not None and kept.suits(cavitated, model.options.ordering_set_change)
    grown = replace(kept, fill=1)  # any factor in it grows past ordering_fill_growth
    model.ordering = grown
    again = solver.evaluate(here, start=cavitated, warm=False)
    assert again.cavitation.iterations == 1  # one factor, made in the grown order
    np.testing.assert_array_equal(again.cavitated, cavitated)
    assert model.ordering is None  # dropped after the factor that grew past it
    solver.evaluate(here, start=cavitated, warm=False)
    assert model.ordering is not None and model.ordering is not grown and model.ordering.fill > 1  # afresh


def test_a_kept_order_does_not_serve_a_zone_moved_round_the_bore(jfo_bearing):
    """The cavitated zone of a load turned round the bore is another graph: the order kept from
    the last film must not serve it (kept, it gave 10-23 times a fresh order's fill and 20-40
    times its time on 81 x 240 and 161 x 240; 4.4 times the fill here). After a film at 0, every
    factor of the fine grid made for a cold film at pi holds at most 1.3 times the entries of
    the final set's factor ordered afresh.

    The film at pi starts from the set its coarse grid predicts (the start of a cold solution,
    found here as the solver finds it), so that the first factor is known to be that set's: the
    order the model keeps after the solve is the one found for it (``ordering.cavitated``), so
    that factor was ordered afresh, not in the order from 0, and the order was never dropped,
    so every later factor held at most ``ordering_fill_growth`` times its entries; the last
    one, the solution's own, is checked as well (seen: 46 608 entries ordered afresh, then
    47 108 and 47 122 in its order; 47 048 for the final set afresh)."""
    solver = jfo_bearing.solver
    model = solver.cavitation
    solver.evaluate(JournalPosition.from_polar(0.8 * CLEARANCE, 0.0), warm=False)
    from_zero = model.ordering
    assert from_zero is not None
    position = JournalPosition.from_polar(0.8 * CLEARANCE, np.pi)
    film = jfo_bearing.film(position) / jfo_bearing.geometry.radial_clearance
    stencil = build_stencil(film, solver.d_theta, solver.d_z)
    coarse = model.coarse_grid()
    assert coarse is not None
    film_c = coarse.restrict(film)
    coarse_solution = coarse.model.solve(
        build_stencil(film_c, coarse.model.nodes.d_theta, coarse.model.nodes.d_z), film_c, settle=False
    )
    indicator = np.where(coarse_solution.cavitated, -coarse_solution.void, coarse_solution.pressure)
    start = model.relaxed_set(stencil, coarse.prolong(np.where(coarse.model.fixed, 0.0, indicator)))

    turned = solver.evaluate(position, start=start, warm=False)
    assert turned.cavitation.iterations >= 2  # a factor after the first one
    first = model.ordering
    assert first is not None and first is not from_zero
    np.testing.assert_array_equal(first.cavitated, start)  # found for the first factor: afresh
    last = turned.cavitation.factor()
    assert last.order is not None  # the solution's own factor, made in that order
    last_fill = last.lu.nnz
    del last
    model.drop_factors()  # releases it: the solution rebuilds its factor
    fresh = turned.cavitation.factor()  # the final set's factor, ordered afresh
    assert fresh.order is None
    growth = jfo_bearing.options.jfo.ordering_fill_growth
    assert first.fill <= 1.3 * fresh.lu.nnz and last_fill <= 1.3 * fresh.lu.nnz
    assert growth * first.fill <= 1.3 * fresh.lu.nnz  # every factor in between


def test_a_bearing_sharing_the_solver_does_not_depend_on_its_history():
    """``with_geometry`` (a design search sharing one solver across bores) promises results that
    do not depend on what the shared solver solved before: a JFO equilibrium after another at
    a load 3 % lower (whose sets are near enough for its kept orders to serve), through
    ``with_geometry``, equals that of a fresh bearing bit for bit (the JFO solver's kept orders
    and last solution are dropped with the solver's factors)."""

    def bearing():
        return make_bearing(1.0, cavitation_pressure=-2e4, axial_nodes=21, circumferential_nodes=72, cavitation="jfo")

    used = bearing()
    used.equilibrium(-2.9e5)
    shared = used.with_geometry(replace(used.geometry))
    after = shared.equilibrium(-3e5).state
    fresh = bearing().equilibrium(-3e5).state
    assert (after.position.ey, after.position.ez) == (fresh.position.ey, fresh.position.ez)
    np.testing.assert_array_equal(after.pressure, fresh.pressure)


def test_relaxed_set_keeps_a_solution_and_sharpens_an_interpolated_one(jfo_bearing):
    """The nonlinear Gauss-Seidel sweeps of the set prediction: a converged JFO film is their
    fixed point (every node's residual is zero, so each node's own root is its value: the
    set comes back unchanged); from the film's coarse-grid solution interpolated bilinearly
    (the nested start's prolonged unknown) they leave the set at most a third as far from the
    final one as the interpolated set (on this 31 x 120 film the interpolated one is 134 nodes
    off, the swept one 16)."""
    position = JournalPosition.from_polar(0.7 * CLEARANCE, np.pi)
    evaluation = jfo_bearing.solver.evaluate(position, warm=False)
    solution, stencil = evaluation.cavitation, evaluation.stencil
    model = jfo_bearing.solver.cavitation
    unknown = np.where(solution.cavitated, -solution.void, solution.pressure)
    np.testing.assert_array_equal(model.relaxed_set(stencil, unknown), solution.cavitated)

    coarse = model.coarse_grid()
    assert coarse is not None
    film_c = coarse.restrict(evaluation.film / jfo_bearing.geometry.radial_clearance)
    stencil_c = build_stencil(film_c, coarse.model.nodes.d_theta, coarse.model.nodes.d_z)
    coarse_solution = coarse.model.solve(stencil_c, film_c)
    indicator = np.where(coarse_solution.cavitated, -coarse_solution.void, coarse_solution.pressure)
    prolonged = coarse.prolong(np.where(coarse.model.fixed, 0.0, indicator))
    interpolated = (prolonged < 0.0) & ~model.fixed
    swept = model.relaxed_set(stencil, prolonged)
    off_before = int(np.count_nonzero(interpolated != solution.cavitated))
    off_after = int(np.count_nonzero(swept != solution.cavitated))
    assert off_before > 20
    assert off_after <= off_before / 3


def _vectorised_jfo_sweeps(u, stencil, fixed, fixed_pressure, sweeps):
    """The JFO sweeps written colour by colour on whole arrays (numpy), as the solver did
    before they were compiled: a reference computed another way."""
    nz, nt = fixed.shape
    row, column = np.indices((nz, nt))
    colour = (row + column) % 2
    if nt % 2:
        colour[:, -1] = 2 + row[:, -1] % 2
    c_theta, c_z, q = stencil.c_theta, stencil.c_z, stencil.couette_face
    c_west = np.roll(c_theta, 1, axis=1)
    diag = stencil_diagonal(stencil)
    u = np.where(fixed, 0.0, u)
    for _ in range(sweeps):
        for k in range(int(colour.max()) + 1):
            pressure = np.where(fixed, fixed_pressure, np.maximum(u, 0.0))
            inflow = c_theta * np.roll(pressure, -1, axis=1) + c_west * np.roll(pressure, 1, axis=1)
            inflow[:-1] += c_z * pressure[1:]
            inflow[1:] += c_z * pressure[:-1]
            residual_at_zero = np.roll(q * np.maximum(-u, 0.0), 1, axis=1) - inflow - stencil.rhs
            root = np.where(residual_at_zero < 0.0, -residual_at_zero / diag, -residual_at_zero / q)
            u = np.where((colour == k) & ~fixed, root, u)
    return u


@pytest.mark.parametrize("circumferential_nodes", [120, 45])
def test_the_compiled_jfo_sweeps_are_the_colour_by_colour_sweeps(circumferential_nodes):
    """The compiled nonlinear Gauss-Seidel sweeps against the same sweeps on whole arrays, on an
    edge-fed starved film (rupture and reformation) with a supply groove (fixed nodes inside the
    grid), even and odd column counts, from a perturbed solution (nodes cross zero both ways).
    Tolerance 1e-12 of the largest |u|: the same arithmetic in another order."""
    from shaftline.film._relaxation_kernel import jfo_gauss_seidel_sweeps

    bearing = make_bearing(
        1.0, cavitation_pressure=-2e4, axial_nodes=21, circumferential_nodes=circumferential_nodes, cavitation="jfo"
    )
    evaluation = bearing.solver.evaluate(JournalPosition.from_polar(0.7 * CLEARANCE, np.pi), warm=False)
    model, stencil, solution = bearing.solver.cavitation, evaluation.stencil, evaluation.cavitation
    fixed = model.fixed.copy()
    fixed[5:9, circumferential_nodes // 3] = True  # a short groove at 120 degrees
    fixed_pressure = np.where(fixed, np.where(model.fixed, model.fixed_pressure, 0.3), 0.0)
    rng = np.random.default_rng(3)
    unknown = np.where(solution.cavitated, -solution.void, solution.pressure)
    start = unknown + 0.2 * np.abs(unknown).max() * rng.normal(size=unknown.shape)
    expected = _vectorised_jfo_sweeps(start, stencil, fixed, fixed_pressure, 3)
    got = np.where(fixed, 0.0, start)
    done = jfo_gauss_seidel_sweeps(
        got,
        stencil.c_theta,
        stencil.c_z,
        stencil.couette_face,
        stencil.rhs,
        stencil_diagonal(stencil),
        fixed,
        fixed_pressure,
        3,
    )
    assert done == 3  # a perturbation this large moves nodes across zero in every sweep
    assert ((got < 0.0) & ~fixed).any() and ((got > 0.0) & ~fixed).any()
    assert np.abs(got - expected).max() <= 1e-12 * np.abs(expected).max()


def test_an_older_solution_still_linearises(jfo_bearing):
    """The solver keeps one factor alive (its newest solution's); a solution asked for its
    derivatives after a newer solve refactorises and gives the same Jacobian (to 1e-10).
    Released and rebuilt: its derivatives cost one factorisation (``counts.factorisations``),
    those of the newest solution none."""
    solver = jfo_bearing.solver
    here = JournalPosition.from_polar(0.7 * CLEARANCE, np.pi)
    older = solver.evaluate(here, warm=False)
    solver.evaluate(JournalPosition.from_polar(0.5 * CLEARANCE, 3.0), warm=False)
    last = solver.cavitation.last
    assert last is not None and last[0] is not older.cavitation  # the newer solution's factor is kept
    before = solver.counts.factorisations
    stale = solver.position_response(older)[0]
    assert solver.counts.factorisations == before + 1  # released: refactorised
    newest = solver.evaluate(here, warm=False)
    before = solver.counts.factorisations
    fresh = solver.position_response(newest)[0]
    assert solver.counts.factorisations == before  # its own factor, kept
    assert np.abs(stale - fresh).max() <= 1e-10 * np.abs(fresh).max()


def test_damping_matches_central_differences(jfo_bearing):
    """dF/d(vy, vz) of a JFO film (squeeze term as the solver has it) against central
    differences of cold solutions, velocity step 1e-4 c omega: to 1e-6 of the largest entry
    (seen 1e-13: the film is linear in the squeeze term on a fixed set). The frozen-set Reynolds
    linearisation used before issue 10 was 14 % off here."""
    position = JournalPosition.from_polar(0.7 * CLEARANCE, np.pi)
    exact = jfo_bearing.linearise(position).velocity_derivative
    h = 1e-4 * CLEARANCE * jfo_bearing.operating.speed
    columns = []
    for vy, vz in ((h, 0.0), (0.0, h)):
        up = jfo_bearing.solve_at(replace(position, vy=vy, vz=vz), warm_start=False)
        down = jfo_bearing.solve_at(replace(position, vy=-vy, vz=-vz), warm_start=False)
        columns.append([(up.force_y - down.force_y) / (2 * h), (up.force_z - down.force_z) / (2 * h)])
    differences = np.array(columns).T
    assert np.abs(exact - differences).max() <= 1e-6 * np.abs(differences).max()


def test_an_unsettled_jfo_solution_finishes_on_the_settled_one(jfo_bearing):
    """``settle=False`` (a Newton iterate far from the equilibrium, a coarse grid's prediction)
    stops a JFO solve started two nodes off at that set: pressure and void fraction clipped at
    zero, marked unsettled, the force within 1e-3 of the settled one's. Finishing it from its
    own set (the chord-step predictor of its factor leads to the next set) must give the cold
    solution to 1e-9, as any JFO start does (``test_warm_start_gives_the_cold_solution``)."""
    solver = jfo_bearing.solver
    position = JournalPosition.from_polar(0.7 * CLEARANCE, np.pi)
    settled = solver.evaluate(position, warm=False)
    fixed = settled.cavitation.fixed
    cavitated = settled.cavitated
    full = ~(fixed | cavitated)
    beside = cavitated & np.roll(full, 1, axis=1)  # first cavitated node downstream of the film
    rows, columns = np.nonzero(beside)
    middle = np.argsort(np.abs(rows - cavitated.shape[0] // 2))[:2]
    start = cavitated.copy()
    start[rows[middle], columns[middle]] = False
    loose = solver.evaluate(position, start=start, settle=False)
    assert not loose.settled
    np.testing.assert_array_equal(loose.cavitated, start)
    assert loose.cavitation.pressure.min() >= 0.0 and loose.cavitation.void.min() >= 0.0
    scale = float(np.hypot(*settled.force))
    assert 0.0 < float(np.hypot(*(loose.force - settled.force))) < 1e-3 * scale
    finished = solver.settled(loose)
    assert finished.settled
    np.testing.assert_array_equal(finished.cavitated, cavitated)
    peak = np.abs(settled.relative_pressure).max()
    assert np.abs(finished.relative_pressure - settled.relative_pressure).max() <= 1e-9 * peak
    assert np.abs(finished.cavitation.void - settled.cavitation.void).max() <= 1e-9


def test_jfo_equilibrium_from_the_coarse_grid_is_the_closed_form_starts_equilibrium():
    """Grid continuation of the mass-conserving film (5 000 nodes or more, its fine start set
    from the coarse JFO unknown, loose iterates far from the root) changes the path, not the
    answer: on 80 x 72 (5 760 nodes) against the equilibrium started from the closed-form
    position (``initial``, no coarse grid), both to 1e-10 of the load: positions to 1e-8 of the
    clearance (as for the Reynolds condition in test_solver_paths.py) and pressures to 1e-6 of
    the peak; the continued one in fewer fine Newton iterations."""
    bearing = make_bearing(
        1.0, cavitation_pressure=-2e4, axial_nodes=80, circumferential_nodes=72, cavitation="jfo", tolerance=1e-10
    )
    load, tilt_y = -5e3, 2e-4
    coarse = coarse_start(bearing.solver, np.array([load, 0.0]), tilt_y, 0.0, find_equilibrium)
    assert coarse is not None  # it does continue
    continued = bearing.equilibrium(load, tilt_y=tilt_y)
    closed_form = bearing.initial_position(load, 0.0, tilt_y, 0.0)
    direct = bearing.equilibrium(load, tilt_y=tilt_y, initial=closed_form)
    for result in (continued, direct):
        assert result.converged and not result.contact
    assert abs(continued.state.position.ey - direct.state.position.ey) < 1e-8 * CLEARANCE
    assert abs(continued.state.position.ez - direct.state.position.ez) < 1e-8 * CLEARANCE
    peak = np.abs(direct.state.pressure).max()
    assert np.abs(continued.state.pressure - direct.state.pressure).max() < 1e-6 * peak
    assert continued.iterations < direct.iterations
