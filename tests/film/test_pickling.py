"""A bearing, solved or not, pickles and copies as its problem and solves the same anywhere.

Sweeps and optimisations send bearings to process pools and Dask workers. Pickling,
``copy.copy`` and ``copy.deepcopy`` carry only the BearingProblem; the solver state
(qdldl factorisation, coarse grid, last active set) is rebuilt on first use.

Results are compared bit for bit, not to a tolerance: the equilibrium and the
linearisation start the active set from the coarse grid, never from an earlier call,
so they are the same sequence of floating-point operations on the same inputs with the
same libraries, in this process or in a spawned one. A difference in the last bit would
mean that some state survived that should not have.
"""

from __future__ import annotations

import copy
import multiprocessing
import pickle
from concurrent.futures import ProcessPoolExecutor
from dataclasses import fields

import numpy as np

from shaftline.film import (
    BearingGeometry,
    BearingProblem,
    BoreSegment,
    Equilibrium,
    JournalBearing,
    JournalPosition,
    OperatingPoint,
    SolverOptions,
    dynamic_coefficients,
)
from shaftline.film.dynamics import DynamicCoefficients

LOAD_Y = -4e3
TILT_Y = 2e-4


def _problem() -> BearingProblem:
    """A slope-bored, misaligned bearing with an edge feed: every part of the problem is used."""
    return BearingProblem(
        BearingGeometry(
            length=0.1, diameter=0.1, radial_clearance=1e-4, bore=(BoreSegment(0.6, 2e-4), BoreSegment(0.4))
        ),
        OperatingPoint(speed=60.0, viscosity=0.02, aft_pressure=1e4),
        SolverOptions(axial_nodes=21, circumferential_nodes=72),
    )


def _solve(bearing: JournalBearing) -> tuple[Equilibrium, DynamicCoefficients]:
    """Equilibrium under the test load, and stiffness and damping there (run in a worker too)."""
    equilibrium = bearing.equilibrium(LOAD_Y, tilt_y=TILT_Y)
    return equilibrium, dynamic_coefficients(bearing, equilibrium.state)


def _assert_identical(a: tuple[Equilibrium, DynamicCoefficients], b: tuple[Equilibrium, DynamicCoefficients]) -> None:
    (eq_a, k_a), (eq_b, k_b) = a, b
    assert (eq_a.converged, eq_a.iterations, eq_a.residual) == (eq_b.converged, eq_b.iterations, eq_b.residual)
    for item in fields(eq_a.state):
        left, right = getattr(eq_a.state, item.name), getattr(eq_b.state, item.name)
        if isinstance(left, np.ndarray):
            assert np.array_equal(left, right), item.name
        else:
            assert left == right, item.name
    assert np.array_equal(k_a.stiffness, k_b.stiffness)
    assert np.array_equal(k_a.damping, k_b.damping)


def test_a_solved_bearing_pickles_as_its_problem_only():
    problem = _problem()
    fresh = JournalBearing.from_problem(problem)
    solved = JournalBearing.from_problem(problem)
    _solve(solved)
    assert pickle.dumps(solved) == pickle.dumps(fresh)
    assert solved.problem is problem
    restored = pickle.loads(pickle.dumps(solved))
    assert restored.problem == problem


def test_a_solved_bearing_solves_the_same_in_another_process():
    bearing = JournalBearing.from_problem(_problem())
    here = _solve(bearing)
    assert here[0].converged
    # spawn: a fresh interpreter, as a cluster worker would be (fork would copy this process).
    with ProcessPoolExecutor(max_workers=1, mp_context=multiprocessing.get_context("spawn")) as pool:
        there = pool.submit(_solve, bearing).result(timeout=300)
    _assert_identical(here, there)


def test_deep_and_shallow_copies_of_a_solved_bearing_solve_the_same():
    bearing = JournalBearing.from_problem(_problem())
    here = _solve(bearing)
    for duplicate in (copy.deepcopy(bearing), copy.copy(bearing)):
        assert duplicate.problem == bearing.problem
        _assert_identical(here, _solve(duplicate))
    # and the original, whose solver state the copies did not share, still gives the same
    _assert_identical(here, _solve(bearing))


def test_warm_start_is_not_carried_but_the_solution_is_the_same():
    """After unpickling, the first warm solve starts cold: it is, iterations and every bit of
    the pressure included, the solve of a bearing made afresh. Against the original
    bearing's warm solve: the same active set, and the pressures to rounding (the warm solve
    factorises on the node set kept from the last position, whose ordering differs; the set,
    hence the solution, is unique)."""
    bearing = JournalBearing.from_problem(_problem())
    bearing.solve_at(JournalPosition(ey=-0.6e-4, ez=0.3e-4, tilt_y=TILT_Y))
    nearby = JournalPosition(ey=-0.61e-4, ez=0.31e-4, tilt_y=TILT_Y)
    restored = pickle.loads(pickle.dumps(bearing))
    warm, cold = bearing.solve_at(nearby), restored.solve_at(nearby)
    fresh = JournalBearing.from_problem(_problem()).solve_at(nearby)
    assert cold.iterations == fresh.iterations
    assert np.array_equal(cold.pressure, fresh.pressure)
    assert np.array_equal(warm.cavitated, cold.cavitated)
    np.testing.assert_allclose(warm.pressure, cold.pressure, rtol=1e-12, atol=1e-12 * np.abs(cold.pressure).max())
