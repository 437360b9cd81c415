"""The Reynolds-condition pressure does not depend on the solver's path (issue 10).

The discrete problem ``P >= 0, w = A P - b >= 0, P w = 0`` has a symmetric M-matrix ``A``,
hence a P-matrix, and so exactly one solution (Cottle, Pang & Stone, The Linear
Complementarity Problem, 1992, Thm. 3.3.7). The solver reaches it by several paths: the
set predicted on the coarse grids (cold start), the set of an earlier solution (warm start),
conjugate gradients preconditioned by the factor of another set or film, and one final
solve with the factor of the settled set. The reference here takes none of them: a plain
primal-dual active-set iteration (Hintermueller, Ito & Kunisch 2002) started from the
full-Sommerfeld solution, with every trial set solved by scipy's ``spsolve`` (SuperLU) on
an operator assembled in this file from the stencil's conductances.

Cases: the design-data grid of ``test_design_data.py`` (61 x 240, film starting at the line
of maximum film, L/D = 1 and 1/2) at eps = 0.2, 0.6 and 0.9, and the periodic film of the
same bearing with the journal tilted (misaligned), on 41 x 144.

Tolerance 1e-9 of the largest pressure: two direct solves of the same linear system agree
to about the condition number of ``A`` (below 1e5 on these grids) times the unit roundoff
(1.1e-16), i.e. 1e-11; 1e-9 leaves room for that and fails for any node on the wrong side
of the cavitation boundary (which changes the pressure at its neighbours by 1e-4 or more).
"""

from __future__ import annotations

import numpy as np
import pytest
import scipy.sparse as sp
import scipy.sparse.linalg as spla

from shaftline.errors import InputError
from shaftline.film import JournalPosition
from shaftline.film.equilibrium import find_equilibrium
from shaftline.film.equilibrium.starts import coarse_start
from shaftline.film.options import ActiveSetOptions
from tests.conftest import CLEARANCE, make_bearing

TOLERANCE = 1e-9


def _operator(stencil) -> sp.csr_matrix:
    """The finite-volume operator A (net diffusive outflow) from the link conductances."""
    nz, nt = stencil.rhs.shape
    node = np.arange(nz * nt).reshape(nz, nt)
    a = np.concatenate([node.ravel(), node[:-1].ravel()])
    b = np.concatenate([np.roll(node, -1, axis=1).ravel(), node[1:].ravel()])
    c = np.concatenate([stencil.c_theta.ravel(), stencil.c_z.ravel()])
    links = sp.coo_matrix((c, (a, b)), shape=(nz * nt, nz * nt)).tocsr()
    links = links + links.T
    return (sp.diags(np.asarray(links.sum(axis=1)).ravel()) - links).tocsr()


def _reference_pressure(stencil, fixed: np.ndarray, fixed_pressure: np.ndarray) -> np.ndarray:
    """Primal-dual active set from the full-Sommerfeld solution, each set by ``spsolve``."""
    matrix = _operator(stencil)
    rhs = stencil.rhs.ravel()
    fixed = fixed.ravel()
    cavitated = np.zeros(fixed.size, dtype=bool)
    for _ in range(500):
        held = fixed | cavitated
        free = ~held
        pressure = np.where(fixed, fixed_pressure.ravel(), 0.0)
        system = matrix[free][:, free].tocsc()
        pressure[free] = spla.spsolve(system, rhs[free] - matrix[free][:, held] @ pressure[held])
        multiplier = matrix @ pressure - rhs
        enter = free & (pressure < -1e-12 * np.abs(pressure).max())
        leave = cavitated & (multiplier < -1e-12 * np.abs(rhs).max())
        if not enter.any() and not leave.any():
            return np.where(cavitated, 0.0, pressure).reshape(stencil.rhs.shape)
        cavitated = (cavitated & ~leave) | enter
    raise AssertionError("reference active set did not settle")


def _reference(bearing, position: JournalPosition) -> np.ndarray:
    """Reference pressure (dimensionless, above cavitation, fixed nodes included) at ``position``."""
    evaluation = bearing.solver.evaluate(position, warm=False)
    nodes = bearing.solver.nodes
    pressure = _reference_pressure(evaluation.stencil, nodes.fixed, nodes.fixed_pressure)
    return np.where(nodes.fixed, nodes.fixed_pressure, pressure)


def _relative(bearing, state_pressure: np.ndarray, reference: np.ndarray) -> float:
    relative = (state_pressure - bearing.operating.cavitation_pressure) / bearing.pressure_scale
    return float(np.abs(relative - reference).max() / np.abs(reference).max())


def _design_bearing(length_to_diameter: float):
    return make_bearing(
        length_to_diameter,
        axial_nodes=61,
        circumferential_nodes=240,
        film_start="max_film",
        cavitated_shear="full_film",
    )


DESIGN_CASES = [(1.0, 0.2), (1.0, 0.6), (1.0, 0.9), (0.5, 0.6)]


@pytest.mark.parametrize("length_to_diameter, epsilon", DESIGN_CASES, ids=lambda v: str(v))
def test_cold_and_warm_start_match_the_reference(length_to_diameter, epsilon):
    """Cold start (coarse-grid prediction), then a warm start from a solution at a nearby
    position (its set and its factor, of another film): both match the reference."""
    bearing = _design_bearing(length_to_diameter)
    position = JournalPosition.from_polar(epsilon * CLEARANCE, np.pi)
    nearby = JournalPosition.from_polar((epsilon + 0.02) * CLEARANCE, np.pi + 0.05)
    reference = _reference(bearing, position)
    cold = bearing.solve_at(position, warm_start=False)
    assert _relative(bearing, cold.pressure, reference) <= TOLERANCE
    bearing.solve_at(nearby, warm_start=False)
    solver = bearing.solver.cavitation
    before = solver.pcg_iterations
    warm = bearing.solve_at(position, warm_start=True)
    assert _relative(bearing, warm.pressure, reference) <= TOLERANCE
    # The warm start took the iterative path (conjugate gradients) before its final solve.
    assert solver.pcg_iterations > before
    # and the final solve with a factor of the settled set makes the two equal to rounding
    # (bit for bit only when both factors share the kept node set's ordering)
    assert np.abs(warm.pressure - cold.pressure).max() <= 1e-12 * np.abs(cold.pressure).max()


@pytest.mark.parametrize(
    "ey, ez, tilt_y, tilt_z",
    [(-0.5e-4, 0.2e-4, 4e-4, 0.0), (-0.3e-4, -0.4e-4, -2e-4, 3e-4), (-0.75e-4, 0.3e-4, 1e-4, -1e-4)],
)
def test_misaligned_positions_match_the_reference(ey, ez, tilt_y, tilt_z):
    """Tilted journals on the periodic film, solved one after the other with warm starts
    (as a sweep does): every solution matches the reference."""
    bearing = make_bearing(1.0, axial_nodes=41, circumferential_nodes=144)
    bearing.solve_at(JournalPosition(ey=-0.4e-4, ez=0.0))  # a warm start from elsewhere
    position = JournalPosition(ey=ey, ez=ez, tilt_y=tilt_y, tilt_z=tilt_z)
    reference = _reference(bearing, position)
    assert _relative(bearing, bearing.solve_at(position).pressure, reference) <= TOLERANCE
    assert _relative(bearing, bearing.solve_at(position, warm_start=False).pressure, reference) <= TOLERANCE


def test_frozen_set_derivatives_match_a_direct_solve():
    """The pressure change with the cavitated set frozen (behind the Newton Jacobian and the
    stiffness and damping) against ``spsolve`` on the free sub-matrix of the reference
    operator: the same linear system, so the same 1e-9."""
    bearing = _design_bearing(1.0)
    evaluation = bearing.solver.evaluate(JournalPosition.from_polar(0.6 * CLEARANCE, np.pi), warm=False)
    solver = bearing.solver.cavitation
    change = np.random.default_rng(10).normal(size=evaluation.film.shape)
    d_pressure = solver.pressure_response(evaluation.stencil, evaluation.cavitation, change)[0]
    free = ~(bearing.solver.nodes.fixed | evaluation.cavitated).ravel()
    matrix = _operator(evaluation.stencil)[free][:, free].tocsc()
    expected = np.zeros(free.size)
    expected[free] = spla.spsolve(matrix, -change.ravel()[free])
    assert np.abs(d_pressure.ravel() - expected).max() <= TOLERANCE * np.abs(expected).max()


def _assert_same_equilibrium(result, reference, position_tolerance: float) -> None:
    """``result`` converged without contact at ``reference``'s journal position to
    ``position_tolerance`` (m) and on its pressure to 1e-6 of the peak."""
    assert result.converged and not result.contact
    assert abs(result.state.position.ey - reference.state.position.ey) < position_tolerance
    assert abs(result.state.position.ez - reference.state.position.ez) < position_tolerance
    scale = np.abs(reference.state.pressure).max()
    assert np.abs(result.state.pressure - reference.state.pressure).max() < 1e-6 * scale


@pytest.mark.parametrize("tilt_y", [0.0, 4e-4])
def test_equilibrium_started_from_a_neighbours_set_is_the_same_equilibrium(tilt_y):
    """``initial_cavitated`` (the sweep's warm start) changes the path, not the answer.

    The neighbour is the equilibrium under a load 10 % smaller; started from its position and
    cavitated set, the equilibrium under the full load must land on the cold start's journal
    position to 1e-9 of the clearance and on its pressure to the module's tolerance: the
    Newton iterations of both end below the same force tolerance, and the pressure of each
    film solution is the unique LCP solution (the argument at the top of this file). The
    neighbour's set must not cost more active-set iterations in the first film solution than
    the cold start (whose coarse-grid prediction, relaxed, is often already the final set).
    """
    bearing = make_bearing(1.0, axial_nodes=41, circumferential_nodes=144, tolerance=1e-10)
    load = -6e3
    cold = bearing.equilibrium(load, tilt_y=tilt_y)
    neighbour = bearing.equilibrium(0.9 * load, tilt_y=tilt_y)
    start = neighbour.state.position
    from_start = bearing.equilibrium(load, tilt_y=tilt_y, initial=start)
    solver = bearing.solver.cavitation
    starts = []
    solve = solver.solve

    def recording(stencil, film, start=None, **options):
        starts.append(start)
        return solve(stencil, film, start, **options)

    solver.solve = recording
    from_set = bearing.equilibrium(load, tilt_y=tilt_y, initial=start, initial_cavitated=neighbour.state.cavitated)
    del solver.solve
    # The first film solution of the equilibrium started from the neighbour's set.
    np.testing.assert_array_equal(starts[0], neighbour.state.cavitated)
    for warm in (from_start, from_set):
        _assert_same_equilibrium(warm, cold, 1e-9 * CLEARANCE)
    # The set carried over is the journal-position path's answer exactly (same first position).
    np.testing.assert_array_equal(from_set.state.cavitated, from_start.state.cavitated)
    assert from_set.iterations == from_start.iterations
    first_cold = bearing.solve_at(start, warm_start=False)
    bearing.solve_at(neighbour.state.position, warm_start=False)
    first_warm = bearing.solve_at(start)  # warm from the neighbour's set, as initial_cavitated does
    assert first_warm.iterations <= first_cold.iterations
    np.testing.assert_array_equal(first_warm.cavitated, first_cold.cavitated)


def test_a_start_set_of_the_wrong_shape_names_the_argument():
    bearing = make_bearing(1.0, axial_nodes=21, circumferential_nodes=72)
    with pytest.raises(InputError, match="initial_cavitated"):
        bearing.equilibrium(-5e3, initial_cavitated=np.zeros((5, 5), dtype=bool))


def test_linearisation_from_the_equilibrium_set_is_the_cold_linearisation():
    """``dynamic_coefficients`` starts the film solution at the equilibrium from the state's
    own cavitated set: it must reach the cold start's set and give its stiffness and damping
    to 1e-9 relative (both factorise the same free matrix of the same set; only rounding in
    the assembly order may differ)."""
    bearing = make_bearing(1.0, axial_nodes=41, circumferential_nodes=144)
    state = bearing.equilibrium(-6e3, tilt_y=4e-4).state
    cold = bearing.linearise(state.position)
    warm = bearing.linearise(state.position, initial_cavitated=state.cavitated)
    pairs = ((cold.offset_derivative, warm.offset_derivative), (cold.velocity_derivative, warm.velocity_derivative))
    for a, b in pairs:
        assert np.abs(a - b).max() <= 1e-9 * np.abs(a).max()
    # Per component against the force's size: the horizontal one is the equilibrium's residual
    # (1e-5 N of 6 kN), which a low-rank corrected solve rounds differently from a factor.
    np.testing.assert_allclose(warm.force, cold.force, rtol=1e-12, atol=1e-12 * np.abs(cold.force).max())


def test_a_refined_trial_is_the_reference_solution_without_a_factorisation():
    """A Newton trial near the equilibrium (``NewtonOptions.refine_residual``) iterates its
    pressure from the step's linear guess with the kept factor of the film it steps from: it
    must land on the reference LCP solution at the new position to the module's tolerance and
    leave the kept factor that of the old film (no factorisation of the new one). From a guess
    of zero (a long way off) it must still reach the reference: the iteration then needs more
    steps or falls back to a factorisation, never a wrong answer. What is factorised is counted
    by the solver's ``counts.factorisations`` (every numeric factorisation; a kept factor's
    frozen-set solves and bordered updates are not one): unchanged over the trial, and over the
    old film's frozen-set derivatives after it, which a factor of any other film would need."""
    bearing = make_bearing(1.0, axial_nodes=41, circumferential_nodes=144)
    position = JournalPosition.from_polar(0.6 * CLEARANCE, np.pi, tilt_y=4e-4)
    solver = bearing.solver
    evaluation = solver.evaluate(position, warm=False)
    factorisations = solver.counts.factorisations
    _, _, d_pressure = solver.position_response(evaluation)
    # The kept factor is the current film's (its frozen-set derivatives cost no factorisation).
    assert solver.counts.factorisations == factorisations
    step = np.array([2e-4, -1e-4]) * CLEARANCE
    moved = JournalPosition(
        ey=position.ey + step[0], ez=position.ez + step[1], tilt_y=position.tilt_y, tilt_z=position.tilt_z
    )
    guess = evaluation.relative_pressure + np.tensordot(step, d_pressure, axes=1)
    trial = solver.evaluate(moved, start=evaluation.cavitated, refine_from=guess)
    assert solver.counts.factorisations == factorisations  # nothing factorised
    solver.position_response(evaluation)
    assert solver.counts.factorisations == factorisations  # the kept factor is still the old film's
    reference = _reference(bearing, moved)
    assert np.abs(trial.relative_pressure - reference).max() <= TOLERANCE * np.abs(reference).max()
    solver.position_response(evaluation)  # the old film's factor again
    far = solver.evaluate(moved, start=evaluation.cavitated, refine_from=np.zeros_like(guess))
    assert np.abs(far.relative_pressure - reference).max() <= TOLERANCE * np.abs(reference).max()


def test_equilibrium_from_the_coarse_grid_is_the_closed_form_starts_equilibrium():
    """Grid continuation (5 000 nodes or more, ``ContinuationOptions.nodes``) changes
    the start, not the answer: the default equilibrium on 80 x 72 (5 760 nodes) against the one
    started from the closed-form position (``initial``, which skips the coarse grid), both to a
    force tolerance of 1e-10 of the load: the journal positions agree to 1e-8 of the clearance
    (the Jacobian's scale, 1e6 N/m per micrometre here, turns 1e-10 of 6 kN into 1e-9 c) and the
    pressures to 1e-6 of the peak; the continuation takes fewer fine Newton iterations."""
    bearing = make_bearing(1.0, axial_nodes=80, circumferential_nodes=72, tolerance=1e-10)
    load, tilt_y = -6e3, 4e-4
    assert coarse_start(bearing.solver, np.array([load, 0.0]), tilt_y, 0.0, find_equilibrium) is not None  # continues
    continued = bearing.equilibrium(load, tilt_y=tilt_y)
    closed_form = bearing.initial_position(load, 0.0, tilt_y, 0.0)
    direct = bearing.equilibrium(load, tilt_y=tilt_y, initial=closed_form)
    assert direct.converged and not direct.contact
    _assert_same_equilibrium(continued, direct, 1e-8 * CLEARANCE)
    assert continued.iterations < direct.iterations


def _two_nodes_off(bearing, cavitated: np.ndarray) -> np.ndarray:
    """``cavitated`` with two of its nodes next to the pressurised film made free: a start set
    two nodes short of the settled one (their pressures go negative when solved)."""
    free = ~(bearing.solver.nodes.fixed | cavitated)
    beside = cavitated & (np.roll(free, 1, axis=1) | np.roll(free, -1, axis=1))
    rows, columns = np.nonzero(beside)
    middle = np.argsort(np.abs(rows - cavitated.shape[0] // 2))[:2]  # mid-length: well inside the film
    out = cavitated.copy()
    out[rows[middle], columns[middle]] = False
    return out


def test_an_unsettled_iterate_is_finished_by_its_own_factor():
    """``settle=False`` (``ActiveSetOptions.unsettled_max_nodes``, the Newton iterates far from the
    equilibrium) stops at a set two nodes short of settling: its pressure is that set's, clipped
    at zero, and is marked unsettled; its force is within 1e-4 of the settled one's (the two
    nodes sit on the cavitation boundary, where P is small). Finishing it on its own stencil
    (``FilmSolver.settled``) must reach the reference LCP solution to the module's tolerance with the
    kept factor and a low-rank update (no new factorisation: ``solver.counts.factorisations``
    unchanged; below ``pcg_min_nodes`` every other path to a new set factorises)."""
    bearing = make_bearing(1.0, axial_nodes=41, circumferential_nodes=144)
    position = JournalPosition.from_polar(0.6 * CLEARANCE, np.pi, tilt_y=4e-4)
    solver = bearing.solver
    settled = solver.evaluate(position, warm=False)
    start = _two_nodes_off(bearing, settled.cavitated)
    loose = solver.evaluate(position, start=start, settle=False)
    assert not loose.settled
    np.testing.assert_array_equal(loose.cavitated, start)
    assert loose.cavitation.pressure.min() >= 0.0
    scale = float(np.hypot(*settled.force))
    assert 0.0 < float(np.hypot(*(loose.force - settled.force))) < 1e-4 * scale
    factorisations = solver.counts.factorisations
    finished = solver.settled(loose)
    assert finished.settled
    assert solver.counts.factorisations == factorisations  # switched, not factorised
    reference = _reference(bearing, position)
    assert np.abs(finished.relative_pressure - reference).max() <= TOLERANCE * np.abs(reference).max()
    np.testing.assert_array_equal(finished.cavitated, settled.cavitated)
    assert solver.settled(finished) is finished


def test_equilibrium_through_unsettled_iterates_ends_on_the_exact_solution(monkeypatch):
    """The equilibrium's Newton iterates may leave their sets unsettled; its answer may not. With
    a start set two nodes off (``initial_cavitated``) and on the continued 80 x 72 grid, the
    equilibrium must (a) pass through unsettled iterates, (b) end on the reference LCP solution at
    its own position to the module's tolerance, and (c) land where the equilibrium with every
    iterate settled (``ActiveSetOptions(unsettled_max_nodes=0)``) lands: positions to 1e-8 of the
    clearance and pressures to 1e-6 of the peak (both converge to a force tolerance of 1e-10 of
    the load; see ``test_equilibrium_from_the_coarse_grid_is_the_closed_form_starts_equilibrium``).
    The fine grid's film solutions are recorded at its cavitation model's ``solve``."""
    bearing = make_bearing(1.0, axial_nodes=80, circumferential_nodes=72, tolerance=1e-10)
    load, tilt_y = -6e3, 4e-4
    solutions = []

    def record(bearing) -> None:
        model = bearing.solver.cavitation
        solve = model.solve

        def recording(*args, **options):
            solution = solve(*args, **options)
            solutions.append(solution)
            return solution

        monkeypatch.setattr(model, "solve", recording)

    record(bearing)
    loose = bearing.equilibrium(load, tilt_y=tilt_y)
    assert any(not s.settled for s in solutions) and solutions[-1].settled
    reference = _reference(bearing, loose.state.position)
    assert _relative(bearing, loose.state.pressure, reference) <= TOLERANCE
    start = _two_nodes_off(bearing, loose.state.cavitated)
    solutions.clear()
    from_set = bearing.equilibrium(load, tilt_y=tilt_y, initial=loose.state.position, initial_cavitated=start)
    assert not solutions[0].settled and solutions[-1].settled
    reference = _reference(bearing, from_set.state.position)
    assert _relative(bearing, from_set.state.pressure, reference) <= TOLERANCE
    every = make_bearing(
        1.0,
        axial_nodes=80,
        circumferential_nodes=72,
        tolerance=1e-10,
        active_set=ActiveSetOptions(unsettled_max_nodes=0),
    )
    record(every)
    solutions.clear()
    settled = every.equilibrium(load, tilt_y=tilt_y)
    assert all(s.settled for s in solutions)
    _assert_same_equilibrium(loose, settled, 1e-8 * CLEARANCE)
    _assert_same_equilibrium(from_set, settled, 1e-8 * CLEARANCE)


def test_an_equilibrium_never_reports_an_unsettled_set():
    """The two ways an equilibrium can end on an unsettled iterate: (a) one already within the
    force tolerance (here 1e-3 of the load, from the converged position with a start set two
    nodes off: its force is within 1e-4 of the load) is settled and checked again, no Newton
    step taken; (b) one left when the iterations run out (``max_iterations = 1`` from the
    closed-form start, whose trial stops two or three nodes short here) is settled before the
    state is built. Both states must carry the reference LCP solution at their positions to
    the module's tolerance."""
    load, tilt_y = -3e3, 4e-4
    exact = make_bearing(1.0, axial_nodes=80, circumferential_nodes=72).equilibrium(load, tilt_y=tilt_y)
    for options, start in (
        ({"tolerance": 1e-3}, "converged"),
        ({"tolerance": 1e-10, "max_iterations": 1}, "closed form"),
    ):
        bearing = make_bearing(1.0, axial_nodes=80, circumferential_nodes=72, **options)
        solver = bearing.solver.cavitation
        settled = []
        solve = solver.solve

        def recording(*args, _solve=solve, _settled=settled, **keywords):
            solution = _solve(*args, **keywords)
            _settled.append(solution.settled)
            return solution

        solver.solve = recording
        if start == "converged":
            result = bearing.equilibrium(
                load,
                tilt_y=tilt_y,
                initial=exact.state.position,
                initial_cavitated=_two_nodes_off(bearing, exact.state.cavitated),
            )
            assert result.converged and result.iterations == 0
        else:
            initial = bearing.initial_position(load, 0.0, tilt_y, 0.0)
            result = bearing.equilibrium(load, tilt_y=tilt_y, initial=initial)
            assert not result.converged and result.iterations == 1
        assert settled[-2:] == [False, True], (start, settled)
        reference = _reference(bearing, result.state.position)
        assert _relative(bearing, result.state.pressure, reference) <= TOLERANCE


def test_an_unsettled_start_at_the_root_still_converges():
    """A start a hair from the root (the viscosity update of the heat balance restarts from the
    last position: here the viscosity 6.3e-7 higher) is evaluated unsettled, its force off by
    about 1e-6 of the load, about its true residual. Stepping from it, the line search measured
    progress against that error and rejected every step (review of the eighth session: reported
    not converged at 6.4e-7 of the load). An unsettled iterate below ``NewtonOptions.refine_residual`` is
    settled before its step, so it must converge in one iteration, over a scan of viscosity
    changes of 1e-7 to 1e-2 either way too."""
    from dataclasses import replace

    from shaftline.film import JournalBearing

    bearing = make_bearing(1.0, axial_nodes=41, circumferential_nodes=144)
    root = bearing.equilibrium(-1e4, tilt_y=4e-4).state.position
    for change in [6.30957344480193e-07, *np.logspace(-7, -2, 6), *-np.logspace(-7, -2, 6)]:
        operating = replace(bearing.operating, viscosity=0.02 * (1.0 + change))
        result = JournalBearing(bearing.geometry, operating, bearing.options).equilibrium(
            -1e4, tilt_y=4e-4, initial=root
        )
        assert result.converged and not result.contact, change
        assert result.iterations <= 3, (change, result.iterations)  # 1 near the root, 3 at 1 %
