"""The film and an elastic liner solved together: the lined bearing's film solver.

Behind the methods of :class:`~shaftline.film.solver.FilmSolver`, a lined solver solves each
film with the liner's deformation by Newton's method on the coupled system
(:mod:`shaftline.film.elastic`, docs/theory.md Sect. 17 "Elastic liner" and "Elastic layer"),
and its film responds with the liner following. It keeps the last deformation (the start of the
next film-liner iteration), the layer model's compliance on its grid and the orderings of the
coupled matrix per free set.
"""

from __future__ import annotations

from typing import ClassVar

import numpy as np

from shaftline.errors import SolverFailure
from shaftline.film.cavitation import SolverCounts
from shaftline.film.elastic import CoupledLiner, CoupledOrderings, LayerSystem, LinerSystem
from shaftline.film.layer import ElasticLayer, layer_operator
from shaftline.film.problem import BearingProblem
from shaftline.film.solver import Direction, FilmSolution, FilmSolver, _Found
from shaftline.film.stencil import build_stencil

__all__ = ["LinedFilmSolver", "LinerConvergenceError", "film_solver", "sharing_solver"]


class LinerConvergenceError(SolverFailure):
    """The film-liner Newton iteration did not settle (treated like a film that cuts the bore).

    ``residual`` (also ``args[0]``) is the liner residual left, of the clearance; ``evaluation``
    the iteration's last iterate where the solver raised it (None where it was raised elsewhere).
    Its message is a sentence (the command line printed the bare number: "not solved: 0.0079")."""

    def __init__(self, residual: float, evaluation: FilmSolution | None = None) -> None:
        super().__init__(residual)
        self.residual = float(residual)
        self.evaluation = evaluation

    def __str__(self) -> str:
        return f"the film-liner iteration did not settle (liner residual {self.residual:.3g} of the clearance)"


class LinedFilmSolver(FilmSolver):
    """The solver of a film problem with an elastic liner (``geometry.liner``), in one process.

    Attributes
    ----------
    last_deformation : ndarray or None
        Liner deformation of the last solution, m: the start of the next film-liner Newton
        iteration when none is given (a linearisation at an equilibrium starts from its own).
        Results then depend on earlier calls to within the liner tolerance (1e-9 of the
        clearance); an equilibrium clears it first.
    layer : ElasticLayer or None
        The layer model's compliance on this grid (built on first use; :mod:`shaftline.film.layer`).
    orderings : CoupledOrderings
        Orderings of the coupled film-liner matrix per free set, cleared with the deformation
        where a result must not depend on earlier calls.
    """

    lined: ClassVar[bool] = True

    def __init__(self, problem: BearingProblem, counts: SolverCounts | None = None) -> None:
        super().__init__(problem, counts)
        self.last_deformation: np.ndarray | None = None
        self.layer: ElasticLayer | None = None
        self.orderings = CoupledOrderings(problem.options.liner.kept_orderings, self.counts)

    def clear_history(self) -> None:
        super().clear_history()
        self.last_deformation = None
        self.orderings.clear()

    def _forget(self, shared: FilmSolver) -> None:
        self.last_deformation = None
        self.orderings = CoupledOrderings(self.options.liner.kept_orderings, self.counts)
        same = isinstance(shared, LinedFilmSolver) and shared.geometry.liner == self.geometry.liner
        self.layer = shared.layer if same and isinstance(shared, LinedFilmSolver) else None

    def with_last_deformation(self, film: np.ndarray) -> np.ndarray:
        """The rigid ``film`` (m) plus the last solution's liner deformation (the journal may pass
        the rigid bore into the liner): a prediction for nearby positions."""
        deformation = self.last_deformation
        if deformation is not None and deformation.shape == film.shape:
            return film + deformation
        return film

    # -- solving ------------------------------------------------------------------------------
    def _started_film(self, rigid: np.ndarray, deformation: np.ndarray | None) -> np.ndarray:
        """The journal may pass the rigid bore surface into the liner: the film is the rigid gap
        plus the deformation, started where none is given from the least deformation that leaves
        a film of the floor (the Newton iteration then finds the real one); a rough film's from
        the mean plane's approach, not from below it."""
        floor = self.surfaces.approach_floor
        if deformation is None and self.last_deformation is not None:
            deformation = self.last_deformation
        start_deformation = np.zeros_like(rigid) if deformation is None else deformation
        return rigid + np.maximum(start_deformation, floor - rigid)

    def _solve(
        self,
        found: _Found,
        start: np.ndarray | None,
        refine_from: np.ndarray | None,
        settle: bool,
        chord: CoupledLiner | None,
        liner_tolerance: float | None,
    ) -> FilmSolution:
        """The film and the liner solved together by Newton's method on the coupled system, from
        the started deformation on the rigid film (m, which may be negative where the journal has
        passed the rigid bore); a backtracking step keeps the film positive and lowers the liner
        residual. With ``chord``, the Newton matrix of a nearby film (a line-search trial's
        parent), the steps use it while each cuts the residual tenfold (a chord iteration: no
        factorisation), then the film's own, kept likewise for the next steps. The layer model
        (``liner.model == "layer"``) takes the same steps with its own liner residual and Newton
        system (:class:`~shaftline.film.elastic.LayerSystem`)."""
        tolerance = self.options.liner.tolerance if liner_tolerance is None else liner_tolerance
        iteration = _LinerIteration(self, found)
        d_nd = iteration.settled(found.film - found.rigid, tolerance)
        return iteration.run(d_nd, start, chord, tolerance)

    def layer_compliance(self) -> ElasticLayer:
        """The layer model's compliance on this bearing's grid (docs/theory.md, "Elastic layer"),
        built once per solver: the end rows carry half cells."""
        if self.layer is None:
            liner = self.geometry.liner
            assert liner is not None
            grid = self.grid
            self.layer = layer_operator(
                grid.shape,
                self.geometry.radius,
                grid.dz,
                liner.thickness,
                liner.modulus,
                liner.poisson,
                half_end_cells=True,
            )
        return self.layer

    def liner_system(self, solution: FilmSolution) -> CoupledLiner:
        """The coupled film-liner Newton matrix at ``solution``'s film (kept on it)."""
        if solution.liner_system is None:
            liner = self.geometry.liner
            assert liner is not None
            c = self.geometry.radial_clearance
            held = self.nodes.fixed | solution.cavitated
            slope = self.surfaces.contact_slope(solution.film)
            if liner.model == "layer":
                solution.liner_system = LayerSystem.build(
                    solution.stencil,
                    solution.film / c,
                    solution.relative_pressure,
                    held,
                    self.d_theta,
                    self.d_z,
                    self.flow,
                    solution.rate,
                    self.layer_compliance(),
                    np.zeros_like(solution.film) if slope is None else slope,
                    self.pressure_scale,
                    c,
                    self.orderings,
                    self.options.liner,
                )
                return solution.liner_system
            diagonal = np.ones_like(solution.film) if slope is None else 1.0 - liner.compliance * slope
            solution.liner_system = LinerSystem.build(
                solution.stencil,
                solution.film / c,
                solution.relative_pressure,
                held,
                self.d_theta,
                self.d_z,
                self.flow,
                solution.rate,
                liner.compliance * self.pressure_scale / c,
                diagonal,
                self.orderings,
            )
        return solution.liner_system

    def liner_tolerance(self, solution: FilmSolution, share: float) -> float:
        """Liner tolerance (max |R| over the clearance) that leaves a force error of about
        ``share`` of the force at ``solution``'s film: ``share * H_min``
        (``LinerOptions.inexact``), never below 1e-13, the round-off of the residual."""
        hmin = self.surfaces.liner_film(float(solution.film.min()))
        return max(1e-13, share * hmin / self.geometry.radial_clearance)

    # -- the response with the liner following ---------------------------------------------------
    def _film_direction(self, solution: FilmSolution, d_film: np.ndarray) -> np.ndarray:
        # The asperity load of the rigid film change deforms the liner too: the column model's
        # film changes by dH_r / M before the pressure change's share; the layer model takes that
        # share in its own solve (film/elastic.py, CoupledLiner).
        if solution.deformation is None:
            return d_film
        return self.liner_system(solution).film_direction(d_film)

    def _pressure_response(
        self, solution: FilmSolution, d_residual: np.ndarray, directions: list[Direction]
    ) -> np.ndarray:
        if solution.deformation is None:
            return super()._pressure_response(solution, d_residual, directions)
        # Elastic liner: the film follows the pressure change (docs/theory.md, "Elastic liner"
        # and "Elastic layer").
        rigid = np.array([np.broadcast_to(d_film, solution.film.shape) for d_film, _ in directions])
        d_pressure, _ = self.liner_system(solution).response(d_residual, rigid)
        return d_pressure

    def _followed_films(
        self, solution: FilmSolution, films: list[np.ndarray], d_pressure: np.ndarray | None
    ) -> list[np.ndarray]:
        system = solution.liner_system
        if system is None:
            return films
        # The film with the liner following: dH_r + dD of the linearised liner equation.
        assert d_pressure is not None
        return [system.film_change(d_film, dp) for d_film, dp in zip(films, d_pressure, strict=True)]

    def predicted_deformation(
        self, solution: FilmSolution, response: tuple[np.ndarray, np.ndarray], step: np.ndarray
    ) -> np.ndarray | None:
        """Liner deformation (m) after the journal moves by ``step`` (m), to first order: the
        start of the trial's film-liner Newton iteration."""
        system = solution.liner_system
        if solution.deformation is None or system is None:
            return solution.deformation
        d_pressure = np.tensordot(step, response[1], axes=1)
        d_ey, d_ez = self.offset_directions(solution)
        rigid = step[0] * d_ey + step[1] * d_ez
        # The linearised liner equation's dD (film/elastic.py, CoupledLiner.deformation_change).
        change = system.deformation_change(np.broadcast_to(rigid, d_pressure.shape), d_pressure)
        return solution.deformation + self.geometry.radial_clearance * change


class _LinerIteration:
    """One film-liner Newton iteration of a lined solver at one position (:meth:`LinedFilmSolver._solve`)."""

    def __init__(self, solver: LinedFilmSolver, found: _Found) -> None:
        self.solver = solver
        self.found = found
        liner = found.geometry.liner
        assert liner is not None
        self.clearance = solver.geometry.radial_clearance
        self.compliance = liner.compliance
        self.layer = solver.layer_compliance() if liner.model == "layer" else None
        self.rigid_nd = found.rigid / self.clearance
        fixed = solver.nodes.fixed
        self.fixed = fixed
        self.fixed_load = solver.gauge(solver.nodes.fixed_pressure)[fixed]

    def solve(self, d_nd: np.ndarray, start_set: np.ndarray | None) -> tuple[FilmSolution, np.ndarray, float]:
        """The film solution with the deformation ``d_nd`` (of c), its liner residual and the
        residual's largest magnitude."""
        solver, found, c = self.solver, self.found, self.clearance
        film_nd = self.rigid_nd + d_nd
        stencil = build_stencil(film_nd, solver.d_theta, solver.d_z, found.rate, solver.flow)
        solver.counts.film_solutions += 1
        solution = solver.cavitation.solve(stencil, film_nd, start_set)
        relative = np.where(solver.nodes.fixed, solver.nodes.fixed_pressure, solution.pressure)
        film = film_nd * c
        contact = solver.surfaces.contact(film)
        load = solver.gauge(relative) if contact is None else solver.gauge(relative) + contact
        if self.layer is None:
            residual = d_nd - (self.compliance / c) * load
        else:
            residual = d_nd - self.layer.apply(load) / c
        force = solver.force(found.grid, relative, contact=contact)
        evaluation = FilmSolution(found.position, found.grid, film, stencil, solution, relative, force)
        evaluation.rate, evaluation.contact, evaluation.deformation = found.rate, contact, d_nd * c
        return evaluation, residual, float(np.abs(residual).max())

    def settled(self, deformation: np.ndarray, tolerance: float) -> np.ndarray:
        """``deformation`` (m) over the clearance with the column liner's equation solved node by
        node on the fixed-pressure nodes (the bearing's ends, grooves): there ``R = D - (k/c)(p +
        p_a(c (H_r + D)))`` depends on the node's own deformation only, so a scalar Newton
        iteration settles the asperity contact's nonlinearity (seed 001's polymer liner at 1 rpm:
        ~1 MPa at the aft end) without film solutions, and the coupled steps are left with the
        free nodes'. (Not on the cavitated nodes: their set is the film's, and a node settled as
        cavitated that the film then pressurises slowed the iteration from far starts.)"""
        return self.settle_fixed(deformation / self.clearance, tolerance)

    def settle_fixed(self, d_nd: np.ndarray, tolerance: float) -> np.ndarray:
        """:meth:`settled` of a deformation over the clearance."""
        solver, fixed, c = self.solver, self.fixed, self.clearance
        surfaces = solver.surfaces
        if not surfaces.rough or self.layer is not None or not fixed.any():
            return d_nd  # linear there (the Newton step is exact) / the layer couples all nodes
        options = solver.options.liner
        d = d_nd[fixed]
        rigid_fixed = self.rigid_nd[fixed]
        limit_nd = surfaces.film_limit / c
        if float((rigid_fixed + d).min()) * c < surfaces.approach_floor:
            # Below the mean plane (boundary lubrication) the coupled steps alone converge,
            # settled nodes there made the film-liner iteration stall (seed 001's rig, 15 rpm).
            return d_nd
        for _ in range(options.fixed_iterations):
            film = (rigid_fixed + d) * c
            contact = surfaces.contact(film)
            assert contact is not None
            r = d - (self.compliance / c) * (self.fixed_load + contact)
            if np.abs(r).max() <= options.fixed_tolerance * tolerance:
                break
            slope = surfaces.contact_slope(film)
            assert slope is not None
            # R is increasing and concave in D (p_a convex and decreasing in h): Newton's
            # iterates approach the root from below after at most one step; the film may
            # close by at most 80 % of itself in a step (fraction to the boundary).
            # (Counted from the lowest film evaluated: 0 smooth, below the mean plane rough.)
            d = d + np.maximum(-r / (1.0 - self.compliance * slope), -0.8 * (rigid_fixed + d - limit_nd))
        out = d_nd.copy()
        out[fixed] = d
        return out

    def run(
        self, d_nd: np.ndarray, start: np.ndarray | None, chord: CoupledLiner | None, tolerance: float
    ) -> FilmSolution:
        """Newton's iteration from the deformation ``d_nd`` (of c) to ``tolerance``."""
        solver, options, c = self.solver, self.solver.options.liner, self.clearance
        evaluation, residual, norm = self.solve(d_nd, start)
        iterations = 0
        factorised = None  # the last matrix factorised here (at one of this solution's iterates)
        history = [norm]
        while norm > tolerance:
            if iterations >= options.iterations:
                raise LinerConvergenceError(norm, evaluation)
            if iterations >= options.stagnation and norm > 0.5 * history[-options.stagnation]:
                # No halving of the residual in that many steps: a trial the film cannot hold (the
                # line search then shortens the step); it would only spend the remaining steps so.
                raise LinerConvergenceError(norm, evaluation)
            iterations += 1
            if chord is None:
                system = factorised = solver.liner_system(evaluation)
            else:
                system = chord
            step = system.step(residual)[1].reshape(d_nd.shape)
            alpha = self._boundary_step(d_nd, step)
            if chord is not None:
                trial = self.solve(self.settle_fixed(d_nd + alpha * step, tolerance), evaluation.cavitated)
                if trial[2] > options.chord_reduction * norm:
                    chord = None  # too slow or diverging: the film's own matrix from the next step
                if trial[2] < 0.5 * norm:
                    # Progress all the same: keep the iterate (its film solution is paid for).
                    evaluation, residual, norm = trial
                    assert evaluation.deformation is not None
                    d_nd = evaluation.deformation / c
                history.append(norm)
                continue
            evaluation, residual, norm, alpha = self._backtrack(d_nd, step, alpha, evaluation, norm, tolerance)
            assert evaluation.deformation is not None
            d_nd = evaluation.deformation / c
            # The next steps keep this factor while it cuts the residual tenfold.
            chord = system
            history.append(norm)
        solver.last_cavitated = evaluation.cavitated
        solver.last_deformation = evaluation.deformation
        evaluation.liner_iterations = iterations
        evaluation.liner_residual = norm
        evaluation.nearby_system = factorised
        return evaluation

    def _boundary_step(self, d_nd: np.ndarray, step: np.ndarray) -> float:
        """Fraction to the boundary: the film may close by at most 80 % of what is left of it
        above the lowest film evaluated (0 smooth, below the mean plane rough)."""
        film_now = self.rigid_nd + d_nd
        room = film_now - self.solver.surfaces.film_limit / self.clearance
        closing = np.min(np.where(step < 0.0, -0.8 * room / np.minimum(step, -1e-300), np.inf))
        return min(1.0, float(closing))

    def _backtrack(
        self, d_nd: np.ndarray, step: np.ndarray, alpha: float, evaluation: FilmSolution, norm: float, tolerance: float
    ) -> tuple[FilmSolution, np.ndarray, float, float]:
        """The step halved until it lowers the liner residual (Armijo share 1e-4)."""
        while True:
            trial = self.solve(self.settle_fixed(d_nd + alpha * step, tolerance), evaluation.cavitated)
            if trial[2] < (1.0 - 1e-4 * alpha) * norm or alpha < 1e-6:
                break
            alpha *= 0.5
        if alpha < 1e-6:
            raise LinerConvergenceError(norm, evaluation)
        return trial[0], trial[1], trial[2], alpha


def film_solver(problem: BearingProblem, counts: SolverCounts | None = None) -> FilmSolver:
    """The solver of ``problem``: :class:`~shaftline.film.solver.FilmSolver` for a rigid bore,
    :class:`LinedFilmSolver` for a bearing with an elastic liner."""
    if problem.geometry.liner is not None:
        return LinedFilmSolver(problem, counts)
    return FilmSolver(problem, counts)


def sharing_solver(solver: FilmSolver, problem: BearingProblem) -> FilmSolver:
    """The solver of ``problem`` sharing ``solver``'s grid, cavitation model and counters
    (:meth:`FilmSolver.sharing`): lined where ``problem``'s bore has an elastic liner."""
    return solver.sharing(problem, LinedFilmSolver if problem.geometry.liner is not None else FilmSolver)
