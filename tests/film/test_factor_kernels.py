"""The film solver's linear-algebra kernels (issue 10): the bordered switch of a kept factor and
the set prediction by red-black projected SOR, each against a direct computation.

Reference: the free sub-matrix ``A[free, free]`` of the Reynolds operator, assembled here from
the stencil alone and solved by SuperLU (scipy), the active-set solver's own LCP solution, and
red-black Gauss-Seidel written out node by node in Python for the compiled sweeps.
Tolerances: 1e-11 relative for a switched solve (a k x k Schur complement of a handful of
nodes on a matrix of condition about 1e4 loses at most a few digits of 1e-16); 1e-13 for the
compiled sweeps against the Python ones (the same operations, grouped differently: a few
roundings of 1e-16 per sweep).
"""

from __future__ import annotations

from dataclasses import replace

import numpy as np
import pytest
import scipy.sparse as sp
import scipy.sparse.linalg as spla

from shaftline.film import JournalPosition
from shaftline.film.cavitation import ReynoldsCondition, SolverCounts
from shaftline.film.cavitation.node_set import NodeSetFactor
from shaftline.film.options import ActiveSetOptions
from shaftline.film.relaxation import projected_sor
from shaftline.film.stencil import Stencil, SymmetricPattern, stencil_diagonal
from tests.conftest import CLEARANCE, make_bearing

#: Switched nodes a kept factor carries by a bordered correction (the solver's default).
SWITCH_MAX_NODES = ActiveSetOptions().switch_max_nodes


def _free_matrix(stencil: Stencil, free: np.ndarray) -> sp.csc_matrix:
    """``A[free, free]`` built from the conductances (periodic in theta)."""
    nz, nt = stencil.c_theta.shape
    node = np.arange(nz * nt).reshape(nz, nt)
    a = np.concatenate([node.ravel(), node[:-1].ravel()])
    b = np.concatenate([np.roll(node, -1, axis=1).ravel(), node[1:].ravel()])
    c = np.concatenate([stencil.c_theta.ravel(), stencil.c_z.ravel()])
    full = sp.coo_matrix(
        (np.concatenate([-c, -c]), (np.concatenate([a, b]), np.concatenate([b, a]))), shape=(nz * nt,) * 2
    )
    full = full.tocsc()
    full = full - sp.diags(np.asarray(full.sum(axis=1)).ravel())
    index = np.flatnonzero(free)
    return sp.csc_matrix(full[index][:, index])


def _slot_values(stencil: Stencil, pattern: SymmetricPattern) -> np.ndarray:
    """Values of A on every slot of the upper-triangle pattern (``slot_source`` indexes
    ``concat(diag(A), -c_theta, -c_z)``), as the Reynolds condition fills its node-set factors."""
    source = np.concatenate([stencil_diagonal(stencil).ravel(), -stencil.c_theta.ravel(), -stencil.c_z.ravel()])
    return source[pattern.slot_source]


@pytest.fixture(scope="module")
def loaded_film():
    bearing = make_bearing(1.0, axial_nodes=21, circumferential_nodes=48)
    position = JournalPosition(ey=-0.5 * CLEARANCE, ez=0.2 * CLEARANCE)
    evaluation = bearing.solver.evaluate(position, warm=False)
    solver = bearing.solver.cavitation
    assert isinstance(solver, ReynoldsCondition)
    return solver, evaluation


def _boundary_nodes(free: np.ndarray, shape: tuple[int, int]) -> tuple[np.ndarray, np.ndarray]:
    """Free nodes next to a held one, and held (non-edge) nodes next to a free one (flat)."""
    grid = free.reshape(shape)
    next_to_held = grid & (np.roll(~grid, 1, axis=1) | np.roll(~grid, -1, axis=1))
    next_to_free = ~grid & (np.roll(grid, 1, axis=1) | np.roll(grid, -1, axis=1))
    next_to_free[[0, -1]] = False
    return np.flatnonzero(next_to_held), np.flatnonzero(next_to_free)


@pytest.mark.parametrize("entering, leaving", [(1, 0), (0, 1), (2, 1), (1, 2), (4, 4)])
def test_a_switched_set_solves_as_its_own_factorisation(loaded_film, entering, leaving):
    """Nodes entering the held set (their links cut) and leaving it (links restored), with the
    kept factor and a bordered correction: the solution of the new set's own matrix."""
    solver, evaluation = loaded_film
    held = solver.fixed | evaluation.cavitated
    base = ~held.ravel()
    factor = NodeSetFactor.around(solver.pattern, base, solver.shape, 3)
    values = _slot_values(evaluation.stencil, solver.pattern)
    factor.factorise(values, evaluation.stencil, base, SolverCounts())
    to_hold, to_free = _boundary_nodes(base, solver.shape)
    new = base.copy()
    new[to_hold[:entering]] = False
    new[to_free[5 : 5 + leaving]] = True
    assert factor.switch(values, evaluation.stencil, new, SWITCH_MAX_NODES)
    assert factor.is_for(evaluation.stencil, new)
    rhs = np.where(new, np.sin(np.arange(new.size)), 0.0)
    expected = spla.spsolve(_free_matrix(evaluation.stencil, new), rhs[new])
    got = factor.solve(rhs)
    assert np.abs(got[new] - expected).max() <= 1e-11 * np.abs(expected).max()
    assert not got[~new].any()


def test_a_switch_is_refused_for_another_film_or_too_many_nodes(loaded_film):
    solver, evaluation = loaded_film
    base = ~(solver.fixed | evaluation.cavitated).ravel()
    factor = NodeSetFactor.around(solver.pattern, base, solver.shape, 3)
    values = _slot_values(evaluation.stencil, solver.pattern)
    factor.factorise(values, evaluation.stencil, base, SolverCounts())
    to_hold, _ = _boundary_nodes(base, solver.shape)
    many = base.copy()
    many[to_hold[: SWITCH_MAX_NODES + 1]] = False
    assert not factor.switch(values, evaluation.stencil, many, SWITCH_MAX_NODES)
    few = base.copy()
    few[to_hold[:1]] = False
    other = Stencil(
        evaluation.stencil.c_theta * 1.01,
        evaluation.stencil.c_z,
        evaluation.stencil.couette_face,
        evaluation.stencil.rhs,
    )
    assert not factor.switch(values, other, few, SWITCH_MAX_NODES)
    assert factor.is_for(evaluation.stencil, base)  # a refused switch leaves the factor as it was


def test_the_solver_uses_the_switch_and_reaches_the_same_solution(loaded_film):
    """A cold solution whose predicted set is a node or two off: with and without the switch
    (``ActiveSetOptions.switch_max_nodes = 0``), the same set and pressures to rounding. The
    switch is used: counted in ``factorisations`` (every numeric factorisation, on every grid),
    the solution with it takes fewer (seen 1 against 2, both on the fine grid; the coarse grid
    predicts by sweeps alone)."""
    solver, evaluation = loaded_film
    film = evaluation.film / CLEARANCE
    options = solver.solver_options
    no_switch = replace(options, active_set=replace(options.active_set, switch_max_nodes=0))
    with_counts, without_counts = SolverCounts(), SolverCounts()
    with_switch = ReynoldsCondition(solver.nodes, options, with_counts).solve(evaluation.stencil, film)
    without = ReynoldsCondition(solver.nodes, no_switch, without_counts).solve(evaluation.stencil, film)
    # this film's predicted set is a node or two off: the switch is used, saving a factorisation
    assert 1 <= with_counts.factorisations < without_counts.factorisations
    np.testing.assert_array_equal(with_switch.cavitated, without.cavitated)
    scale = np.abs(without.pressure).max()
    assert np.abs(with_switch.pressure - without.pressure).max() <= 1e-11 * scale


def test_the_set_prediction_keeps_the_solutions_own_set(loaded_film):
    """From the LCP solution itself the sweeps change nothing (it is their fixed point), so
    the predicted set is the solution's set, and the early stop ends them after one sweep."""
    solver, evaluation = loaded_film
    predicted = solver.predicted_set(evaluation.stencil, evaluation.cavitation.pressure)
    np.testing.assert_array_equal(predicted, evaluation.cavitated)


def _python_sweeps(x, c_theta, c_z, rhs, fixed, sweeps, omega):
    """Red-black projected SOR written out node by node: red ((i + j) even) then black, and on
    a grid with an odd number of columns the last column apart, even rows then odd rows."""
    nz, nt = x.shape
    x = x.copy()
    paired = nt - 1 if nt % 2 else nt
    colours = [[(j, i) for j in range(nz) for i in range(paired) if (i + j) % 2 == k] for k in (0, 1)]
    if nt % 2:
        colours += [[(j, nt - 1) for j in range(nz) if j % 2 == k] for k in (0, 1)]
    for _ in range(sweeps):
        for nodes in colours:
            for j, i in nodes:
                if fixed[j, i]:
                    continue
                links = [(c_theta[j, i], x[j, (i + 1) % nt]), (c_theta[j, i - 1], x[j, i - 1])]
                if j + 1 < nz:
                    links.append((c_z[j, i], x[j + 1, i]))
                if j > 0:
                    links.append((c_z[j - 1, i], x[j - 1, i]))
                gauss_seidel = (rhs[j, i] + sum(c * v for c, v in links)) / sum(c for c, _ in links)
                x[j, i] = max((1.0 - omega) * x[j, i] + omega * gauss_seidel, 0.0)
    return x


@pytest.mark.parametrize("shape", [(7, 8), (6, 9)])
def test_the_compiled_sweeps_are_red_black_gauss_seidel(shape):
    """Random positive conductances, a source of both signs (some nodes go to zero), fixed edge
    rows and one fixed interior node; even and odd numbers of columns."""
    rng = np.random.default_rng(7)
    nz, nt = shape
    c_theta, c_z = rng.uniform(0.5, 2.0, (nz, nt)), rng.uniform(0.5, 2.0, (nz - 1, nt))
    rhs = rng.normal(size=(nz, nt))
    fixed = np.zeros(shape, dtype=bool)
    fixed[[0, -1]] = True
    fixed[3, 4] = True
    start = np.where(fixed, 0.3, rng.uniform(0.0, 1.0, shape))
    expected = _python_sweeps(start, c_theta, c_z, rhs, fixed, 3, 1.6)
    got = projected_sor(start, c_theta, c_z, rhs, fixed, sweeps=3, omega=1.6, until_settled=False)
    assert np.abs(got - expected).max() <= 1e-13 * np.abs(expected).max()
    assert (got[~fixed] == 0.0).any() and (got[~fixed] > 0.0).any()  # the projection is exercised
    np.testing.assert_array_equal(got[fixed], start[fixed])


def test_the_sweeps_converge_to_the_active_set_solution(loaded_film):
    """Projected SOR converges to the solution of the complementarity problem (Cryer 1971), which
    the active-set solver finds directly: its sign convention, stencil and fixed nodes agree."""
    solver, evaluation = loaded_film
    stencil = evaluation.stencil
    start = np.where(solver.fixed, solver.fixed_pressure, 0.0)
    relaxed = projected_sor(start, stencil.c_theta, stencil.c_z, stencil.rhs, solver.fixed, 4000, 1.9, False)
    exact = evaluation.cavitation.pressure
    assert np.abs(relaxed - exact).max() <= 1e-9 * np.abs(exact).max()


def test_the_small_coarse_grids_predict_the_set_without_factorising():
    """A cold solution of the NTUA-like loaded film (100 x 60): the coarse grids below it (50 x 30,
    25 x 15) predict the set by sweeps alone, and the fine set starts within a bordered switch
    of the final one, so the solution costs one factorisation. Counted: the solver's
    ``factorisations`` (every numeric factorisation on every grid, the coarse grids' masked ones
    included), so one means the fine grid's alone."""
    bearing = make_bearing(1.0, axial_nodes=100, circumferential_nodes=60)
    before = bearing.solver.counts.copy()
    state = bearing.solve_at(JournalPosition(ey=-0.6 * CLEARANCE, ez=0.3 * CLEARANCE), warm_start=False)
    assert state.cavitated.any()
    assert bearing.solver.counts.film_solutions - before.film_solutions == 1
    assert bearing.solver.counts.factorisations - before.factorisations == 1
    coarse = bearing.solver.cavitation.coarse_grid()
    assert coarse is not None and isinstance(coarse.model, ReynoldsCondition) and coarse.model.masked


def test_a_long_coarsest_grid_solves_its_own_set_before_the_sweeps():
    """200 x 122 halves once, to 100 x 61 (61 columns: no further halving): sweeps from zero on
    a grid that long leave the fine set thousands of nodes off (14-16 fine active-set
    iterations), so that grid solves its own active set and the fine set starts near the
    final one (4 iterations)."""
    bearing = make_bearing(1.0, axial_nodes=200, circumferential_nodes=122)
    coarse = bearing.solver.cavitation.coarse_grid()
    assert coarse is not None and coarse.model.shape == (100, 61) and coarse.model.coarse_grid() is None
    state = bearing.solve_at(JournalPosition(ey=-0.6 * CLEARANCE, ez=0.3 * CLEARANCE), warm_start=False)
    assert state.cavitated.any()
    assert state.iterations <= 6
