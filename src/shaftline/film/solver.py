"""The film solver of one bearing problem in one process: the film at a journal position, its
force, and its response to a change of the film with the cavitated set frozen.

A :class:`FilmSolver` holds what a problem builds to be solved: the grid and its area weights,
the fixed-pressure nodes, the cavitation model (with its factorisations and coarser grids),
the surfaces' flow factors and limits, the last cavitated set (the warm start of the next
solution) and the counters. It belongs to one process; :class:`~shaftline.film.JournalBearing`
builds it from the problem on first use and drops it when pickled. This module solves the
film of a rigid bore; :mod:`shaftline.film.lined` solves the film and an elastic liner together
behind the same methods.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace
from typing import TYPE_CHECKING, ClassVar

import numpy as np

from shaftline.errors import InputError
from shaftline.film.cavitation import CavitationModel, CavitationSolution, NodeGrid, SolverCounts
from shaftline.film.geometry import BearingGeometry, Grid, JournalPosition, film_thickness, squeeze_velocity
from shaftline.film.problem import BearingProblem
from shaftline.film.roughness import FilmFlow
from shaftline.film.stencil import Stencil, apply_operator, build_stencil, stencil_derivative
from shaftline.film.surfaces import FilmSurfaces, film_surfaces
from shaftline.film.turbulence import TurbulentFilm, clearance_reynolds, turbulence_active

if TYPE_CHECKING:
    from shaftline.film.elastic import CoupledLiner
    from shaftline.film.problem import SolverOptions

__all__ = ["FilmSolution", "FilmSolver", "NegativeFilm"]


class NegativeFilm(Exception):
    """The film at a position closes below the lowest film the solver evaluates (``value``, m):
    the journal cuts the bore (smooth) or passes the end of the asperity tables (rough)."""

    def __init__(self, value: float) -> None:
        super().__init__(value)
        self.value = value


@dataclass(eq=False)
class FilmSolution:
    """The film solved at one journal position, as the solver and the equilibrium use it.

    Attributes
    ----------
    position : JournalPosition
        Where it was solved.
    grid : Grid
        The grid at that position (its first angle may follow the position).
    film : ndarray (nz, nt)
        Film thickness, m (with a liner's deformation).
    stencil : Stencil
        The discrete film equation of that film.
    cavitation : CavitationSolution
        The cavitation model's solution (dimensionless pressure, cavitated set, iterations).
    relative_pressure : ndarray (nz, nt)
        Dimensionless pressure above the cavitation pressure, fixed nodes included.
    force : ndarray (2,)
        Force of the film and the asperities on the journal, N.
    rate : ndarray or None
        ``(2/omega) dH/dt`` of a moving journal (None at rest).
    contact : ndarray or None
        Asperity pressure, Pa (rough surfaces).
    deformation : ndarray or None
        Liner deformation, m (elastic liner).
    liner_system : CoupledLiner or None
        The coupled film-liner Newton matrix at this film (built on demand).
    liner_iterations : int
        Newton iterations of the film-liner system.
    liner_residual : float
        Largest liner residual left, of the clearance.
    nearby_system : CoupledLiner or None
        The last matrix factorised in its liner iteration.
    shortened : bool
        A line-search trial reached by a step its residual test shortened.
    """

    position: JournalPosition
    grid: Grid
    film: np.ndarray
    stencil: Stencil
    cavitation: CavitationSolution
    relative_pressure: np.ndarray
    force: np.ndarray
    rate: np.ndarray | None = None
    contact: np.ndarray | None = None
    deformation: np.ndarray | None = None
    liner_system: CoupledLiner | None = None
    liner_iterations: int = 0
    liner_residual: float = 0.0
    nearby_system: CoupledLiner | None = None
    shortened: bool = False

    @property
    def cavitated(self) -> np.ndarray:
        """The cavitated set of the solution."""
        return self.cavitation.cavitated

    @property
    def settled(self) -> bool:
        """Whether the cavitated set settled (a far Newton iterate's may stop a few nodes short)."""
        return self.cavitation.settled


@dataclass(frozen=True, eq=False)
class _Found:
    """What :meth:`FilmSolver.evaluate` has found before it solves: the position, its grid, the
    rigid film and the film started from (m), the stencil of the latter, the film rate and the
    geometry (the problem's, or a bent journal's)."""

    position: JournalPosition
    grid: Grid
    rigid: np.ndarray
    film: np.ndarray
    stencil: Stencil
    rate: np.ndarray | None
    geometry: BearingGeometry


#: A film change per unit of a parameter (dH, of H = h/c) and the change of the film rate
#: ``(2/omega) dH/dt`` it brings (None: none).
Direction = tuple[np.ndarray, np.ndarray | None]


class FilmSolver:
    """The solver of one film problem in one process (a rigid bore; :func:`~shaftline.film.lined.film_solver` picks
    the lined one for a bearing with an elastic liner).

    Parameters
    ----------
    problem : BearingProblem
        What is solved.
    counts : SolverCounts, optional
        Counters to add to (shared with a finer grid's solver whose start this one finds).

    Attributes
    ----------
    problem : BearingProblem
    grid : Grid
        The grid with its first angle at 0 (:meth:`grid_at` turns it with the position).
    d_theta, d_z : float
        Dimensionless mesh steps: rad, and axial step over the radius.
    area_weights : ndarray (nz, 1)
        Bore area per node, m^2 (trapezoid in z, periodic in theta).
    nodes : NodeGrid
        The grid's nodes with the fixed-pressure ones (edges, grooves, a film start line).
    cavitation : CavitationModel
        The cavitation model on this grid, with its kept factors and coarser grids.
    surfaces : FilmSurfaces
        Where the film may go and what the surfaces carry (smooth or rough).
    flow : FilmFlow or None
        The film equation's flow factors: roughness's, with the turbulence coefficients where
        they apply; None for a smooth laminar film.
    last_cavitated : ndarray or None
        The cavitated set of the last solution (the warm start of the next).
    counts : SolverCounts
        Film solutions and factorisations so far.
    """

    #: Whether the bore is lined (:class:`~shaftline.film.lined.LinedFilmSolver`).
    lined: ClassVar[bool] = False

    def __init__(self, problem: BearingProblem, counts: SolverCounts | None = None) -> None:
        geometry, options = problem.geometry, problem.options
        self.problem = problem
        self.counts = SolverCounts() if counts is None else counts
        grid = Grid(geometry.length, options.axial_nodes, options.circumferential_nodes)
        self.grid = grid
        self.d_theta = grid.d_theta
        self.d_z = grid.dz / geometry.radius
        wz = np.full(grid.axial_nodes, grid.dz)
        wz[[0, -1]] *= 0.5
        self.area_weights = wz[:, None] * (geometry.radius * grid.d_theta)
        self.nodes = self._fixed_nodes()
        self.surfaces: FilmSurfaces = film_surfaces(geometry.surface, geometry.radial_clearance, options.min_film_floor)
        self.flow = self._flow()
        # A turbulent film's coarse-grid prediction of the cavitated set uses its own flow (the
        # laminar one put the boundary off by many nodes: 8 active-set solves instead of 1).
        prediction = self.flow if isinstance(self.flow, TurbulentFilm) else None
        model = options.cavitation_model
        self.cavitation: CavitationModel = model(self.nodes, options, self.counts, prediction)
        self.last_cavitated: np.ndarray | None = None
        #: Solvers of the problem on the grid halved both ways and of the bore without its liner:
        #: the starts of an equilibrium (:mod:`shaftline.film.equilibrium.starts`), built there.
        self.coarse: FilmSolver | None = None
        self.rigid: FilmSolver | None = None

    # -- the problem ------------------------------------------------------------------------
    @property
    def geometry(self) -> BearingGeometry:
        return self.problem.geometry

    @property
    def options(self) -> SolverOptions:
        return self.problem.options

    @property
    def pressure_scale(self) -> float:
        return self.problem.pressure_scale

    @property
    def reynolds_number(self) -> float:
        """Clearance Reynolds number ``Re_c = rho omega R c / mu``; the local one is ``Re_c h / c``."""
        g, op = self.geometry, self.problem.operating
        return clearance_reynolds(op.density, op.speed, g.radius, g.radial_clearance, op.viscosity)

    @property
    def turbulent(self) -> bool:
        """Whether the turbulence coefficients apply (``options.turbulence``: on, or auto with the
        largest local Reynolds number above the Taylor-vortex onset)."""
        g = self.geometry
        return turbulence_active(self.options.turbulence, self.reynolds_number, g.radius, g.radial_clearance)

    def _flow(self) -> FilmFlow | None:
        """The flow factors of the film equation: the roughness's, combined with the turbulence
        coefficients when they apply; None for a smooth laminar film."""
        rough = self.surfaces.flow
        if self.turbulent:
            return TurbulentFilm(self.reynolds_number, self.options.turbulence_model, rough)
        return rough

    def _fixed_nodes(self) -> NodeGrid:
        """The bearing's edges at their pressures, the supply grooves, and with
        ``film_start="max_film"`` and no groove the grid's first column at ambient pressure."""
        problem, grid = self.problem, self.grid
        op, options = problem.operating, problem.options
        nz, nt = grid.shape
        fixed = np.zeros(grid.shape, dtype=bool)
        value = np.zeros(grid.shape)
        fixed[0], value[0] = True, op.aft_pressure
        fixed[-1], value[-1] = True, op.fore_pressure
        if op.grooves:
            first = op.grooves[0].angle
            for groove in op.grooves:
                column = int(round(((groove.angle - first) % (2 * math.pi)) / grid.d_theta)) % nt
                half = 0.5 * groove.length_fraction * grid.length
                rows = np.abs(grid.z - 0.5 * grid.length) <= half + 1e-12 * grid.length
                fixed[rows, column] = True
                value[rows & ~np.isin(np.arange(nz), (0, nz - 1)), column] = groove.pressure
        elif options.film_start == "max_film":
            fixed[:, 0] = True
            value[1:-1, 0] = 0.0
        relative = (value - op.cavitation_pressure) / problem.pressure_scale
        return NodeGrid.of(grid.shape, self.d_theta, self.d_z, fixed, relative)

    def sharing(self, problem: BearingProblem, kind: type[FilmSolver] | None = None) -> FilmSolver:
        """A solver of ``problem`` (this one's with another bore or journal shape), of class
        ``kind`` (default this one's), that shares this one's grid, fixed nodes, cavitation model
        and counters; the model's kept factors are dropped so that its results do not depend on
        what this one solved before. :func:`~shaftline.film.lined.sharing_solver` picks ``kind``
        from the bore."""
        kind = type(self) if kind is None else kind
        other = kind.__new__(kind)
        other.__dict__.update(self.__dict__)
        other.problem = problem
        geometry = problem.geometry
        other.surfaces = film_surfaces(geometry.surface, geometry.radial_clearance, problem.options.min_film_floor)
        other.flow = other._flow()
        other.last_cavitated = None
        other.coarse = None
        other.rigid = None
        # The shared model's coarse grids predict with the flow of the film being solved.
        self.cavitation.flow = other.flow if isinstance(other.flow, TurbulentFilm) else None  # type: ignore[attr-defined]
        self.cavitation.drop_factors()
        other._forget(self)
        return other

    def _forget(self, shared: FilmSolver) -> None:
        """What a lined solver keeps of its last solution, dropped, and what it may share of
        ``shared``'s liner (nothing for a rigid bore)."""

    # -- the film without solving -----------------------------------------------------------
    def local_polar(self, position: JournalPosition) -> tuple[float, float]:
        """Eccentricity (m) and line-of-centres angle (rad) relative to the bore centre at mid-plane."""
        bore_y, bore_z = self.geometry.bore_centre_line(np.array([0.5 * self.geometry.length]))
        local = JournalPosition(ey=position.ey - float(bore_y[0]), ez=position.ez - float(bore_z[0]))
        return local.polar(self.geometry.rotation)

    def grid_at(self, position: JournalPosition) -> Grid:
        """The grid on which the film is solved with the journal at ``position``: its first angle on
        the first supply groove, or with ``film_start="max_film"`` on the line of maximum film at
        ``position``; otherwise at 0 (then the grid does not depend on the position)."""
        base = self.grid
        if self.problem.operating.grooves:
            start = self.problem.operating.grooves[0].angle
        elif self.options.film_start == "max_film":
            e, angle = self.local_polar(position)
            start = angle + math.pi if e > 0 else 0.0
        else:
            return base
        return replace(base, theta_start=float(start))

    def film(self, position: JournalPosition, geometry: BearingGeometry | None = None) -> np.ndarray:
        """Rigid film thickness on :meth:`grid_at` for ``position``, m, shape (nz, nt) (no clipping)."""
        return film_thickness(geometry or self.geometry, self.grid_at(position), position)

    def min_film(self, position: JournalPosition) -> float:
        """Smallest rigid film at ``position``, m (negative when the journal cuts the bore)."""
        return float(self.film(position).min())

    def with_last_deformation(self, film: np.ndarray) -> np.ndarray:
        """The rigid ``film`` (m) with the last solution's liner deformation (itself for a rigid bore)."""
        return film

    def start_set(self, initial_cavitated: np.ndarray | None) -> np.ndarray | None:
        """A caller's start set for the active set, checked against the grid."""
        if initial_cavitated is None:
            return None
        start = np.asarray(initial_cavitated, dtype=bool)
        shape = self.grid.shape
        if start.shape != shape:
            raise InputError(
                "initial_cavitated",
                f"shape {start.shape}",
                "",
                f"the grid's shape {shape} (axial, circumferential nodes)",
            )
        return start

    def clear_history(self) -> None:
        """Forget the last solution, so that the next ones depend only on the problem and their
        arguments (an equilibrium starts so)."""
        self.last_cavitated = None

    # -- solving ------------------------------------------------------------------------------
    def evaluate(
        self,
        position: JournalPosition,
        start: np.ndarray | None = None,
        *,
        warm: bool = True,
        geometry: BearingGeometry | None = None,
        tilt_rates: tuple[float, float] = (0.0, 0.0),
        guess: np.ndarray | None = None,
        refine_from: np.ndarray | None = None,
        settle: bool = True,
        deformation: np.ndarray | None = None,
        chord: CoupledLiner | None = None,
        liner_tolerance: float | None = None,
    ) -> FilmSolution:
        """The film solution at ``position``.

        Parameters
        ----------
        position : JournalPosition
            Offsets (m), tilts (rad) and velocities (m/s) of the journal.
        start : ndarray of bool (nz, nt), optional
            Cavitated set to start from; with ``warm`` (default) the last solution's when none
            is given, else the model predicts one (coarser grids).
        geometry : BearingGeometry, optional
            In place of the problem's (a bent journal along a centre line: :mod:`shaftline.film.linearise`).
        tilt_rates : (float, float)
            Rates of the tilts (rad/s, dy/dx and dz/dx per second): the squeeze of a tilting
            journal, ``dh/dt = -(z - L/2)(w_y cos + s w_z sin)`` (the position carries only the
            centre's velocities).
        guess : ndarray (nz, nt), optional
            A guess of the relative pressure (a coarse solution prolonged, a Newton trial's
            linear guess, in the form the model's ``start_field`` gives): the model's start set
            from it replaces ``start``.
        refine_from : ndarray (nz, nt), optional
            A pressure guess close to the solution with ``start`` the set it starts from: a model
            that ``refines_trials`` iterates it with its kept factor instead of factorising.
        settle : bool
            False: the active set may stop a few nodes short of settling, as a Newton iterate far
            from the equilibrium may (:meth:`settled` finishes it).
        deformation, chord, liner_tolerance
            The film-liner iteration's start, Newton matrix and tolerance (:mod:`shaftline.film.lined`;
            ignored for a rigid bore).

        Raises
        ------
        NegativeFilm
            When the film closes below the lowest film evaluated.
        """
        grid = self.grid_at(position)
        rigid = film_thickness(geometry or self.geometry, grid, position)
        film = self._started_film(rigid, deformation)
        if film.min() <= self.surfaces.film_limit:
            raise NegativeFilm(float(film.min()))
        rate = self._film_rate(grid, position, tilt_rates)
        film_nd = film / self.geometry.radial_clearance
        stencil = build_stencil(film_nd, self.d_theta, self.d_z, rate, self.flow)
        if guess is not None:
            predicted = self.cavitation.start_from_guess(stencil, film_nd, guess)
            if predicted is not None:
                start = predicted
        if start is None and warm:
            start = self.last_cavitated
        found = _Found(position, grid, rigid, film, stencil, rate, geometry or self.geometry)
        return self._solve(found, start, refine_from, settle, chord, liner_tolerance)

    def _started_film(self, rigid: np.ndarray, deformation: np.ndarray | None) -> np.ndarray:
        """The film the solution starts from: the rigid one (a liner's adds its start deformation)."""
        return rigid

    def _film_rate(self, grid: Grid, position: JournalPosition, tilt_rates: tuple[float, float]) -> np.ndarray | None:
        """``(2/omega) dH/dt`` of a moving or tilting journal (None at rest)."""
        if not (position.vy or position.vz or tilt_rates[0] or tilt_rates[1]):
            return None
        tilting = replace(position, vy=tilt_rates[0], vz=tilt_rates[1])
        arm = (grid.z - 0.5 * self.geometry.length)[:, None]
        dh_dt = squeeze_velocity(self.geometry, grid, position) + arm * squeeze_velocity(self.geometry, grid, tilting)
        return (2.0 / self.problem.operating.speed) * dh_dt / self.geometry.radial_clearance

    def _solve(
        self,
        found: _Found,
        start: np.ndarray | None,
        refine_from: np.ndarray | None,
        settle: bool,
        chord: CoupledLiner | None,
        liner_tolerance: float | None,
    ) -> FilmSolution:
        """The rigid film's solution from its stencil (a lined solver solves film and liner here)."""
        film_nd = found.film / self.geometry.radial_clearance
        self.counts.film_solutions += 1
        solution = self.cavitation.solve(found.stencil, film_nd, start, refine_from=refine_from, settle=settle)
        contact = self.surfaces.contact(found.film)
        relative, force = self._solved(solution, found.grid, contact)
        return FilmSolution(
            found.position, found.grid, found.film, found.stencil, solution, relative, force, found.rate, contact
        )

    def _solved(
        self, solution: CavitationSolution, grid: Grid, contact: np.ndarray | None
    ) -> tuple[np.ndarray, np.ndarray]:
        """Relative pressure (dimensionless, fixed nodes included) and force (N, film and
        asperities) of a rigid film's solution; its set becomes the next warm start."""
        self.last_cavitated = solution.cavitated
        relative = np.where(self.nodes.fixed, self.nodes.fixed_pressure, solution.pressure)
        return relative, self.force(grid, relative, contact=contact)

    def settled(self, solution: FilmSolution) -> FilmSolution:
        """``solution`` with its active set settled (itself when it is): the solve continues from
        its set on its own stencil, so the kept factor of that set and film carries the last
        switch as a bordered update (rigid bore; see :meth:`evaluate`, ``settle``)."""
        if solution.settled:
            return solution
        film_nd = solution.film / self.geometry.radial_clearance
        self.counts.film_solutions += 1
        finished = self.cavitation.solve(solution.stencil, film_nd, solution.cavitated)
        relative, force = self._solved(finished, solution.grid, solution.contact)
        return replace(solution, cavitation=finished, relative_pressure=relative, force=force)

    def evaluate_inside(self, position: JournalPosition, warm: bool, start: np.ndarray | None = None) -> FilmSolution:
        """:meth:`evaluate`, with a journal cutting the bore reported as bad input."""
        try:
            return self.evaluate(position, start, warm=warm)
        except NegativeFilm as exc:
            raise InputError(
                "position",
                f"e=({position.ey:.4g}, {position.ez:.4g}) m",
                "",
                f"a journal position inside the clearance (film would be {exc.value:.3g} m)",
            ) from None

    # -- forces -------------------------------------------------------------------------------
    def gauge(self, relative: np.ndarray) -> np.ndarray:
        """Gauge pressure, Pa, of a dimensionless relative pressure."""
        return relative * self.pressure_scale + self.problem.operating.cavitation_pressure

    def _load(self, relative: np.ndarray, gauge: bool, contact: np.ndarray | None) -> np.ndarray:
        pressure = self.gauge(relative) if gauge else relative * self.pressure_scale
        if contact is not None:
            pressure = pressure + contact
        return pressure

    def force(
        self, grid: Grid, relative: np.ndarray, gauge: bool = True, contact: np.ndarray | None = None
    ) -> np.ndarray:
        """Film force on the journal, N, from dimensionless pressures (a change of them when
        ``gauge`` is False, which leaves out the constant cavitation-pressure offset), with the
        asperity pressure ``contact`` (Pa, or its change) added."""
        pressure = self._load(relative, gauge, contact)
        # Per-column sums first (one product with the area weights): the film force is
        # computed at every trial and derivative, and this is its cheapest form.
        per_column = self.area_weights[:, 0] @ pressure
        theta = grid.theta
        return np.array([-(per_column @ np.cos(theta)), -self.geometry.rotation * (per_column @ np.sin(theta))])

    def moment(
        self, grid: Grid, relative: np.ndarray, gauge: bool = True, contact: np.ndarray | None = None
    ) -> np.ndarray:
        """First moments ``(M_y, M_z) = sum((z - L/2) dF)`` of the film force about the
        mid-plane, N*m, from dimensionless pressures (as :meth:`force`)."""
        pressure = self._load(relative, gauge, contact)
        arm = grid.z - 0.5 * self.geometry.length
        weighted = pressure * self.area_weights * arm[:, None]
        theta = grid.theta
        my = -np.sum(weighted * np.cos(theta)[None, :])
        mz = -self.geometry.rotation * np.sum(weighted * np.sin(theta)[None, :])
        return np.array([my, mz])

    def row_forces(
        self, grid: Grid, relative: np.ndarray, gauge: bool, contact: np.ndarray | None = None
    ) -> np.ndarray:
        """Film force on the journal per axial grid row, (2, nz), N (sums to :meth:`force`)."""
        pressure = self._load(relative, gauge, contact)
        weighted = pressure * self.area_weights
        theta = grid.theta
        return np.stack([-weighted @ np.cos(theta), -self.geometry.rotation * (weighted @ np.sin(theta))])

    # -- the response with the cavitated set frozen ---------------------------------------------
    def pressure_changes(self, solution: FilmSolution, directions: list[Direction]) -> tuple[np.ndarray, np.ndarray]:
        """Residual and pressure changes, each (k, nz, nt), for film changes ``dH`` and film-rate
        changes ``dRate`` (``directions``, per unit of a parameter), the cavitated set frozen."""
        c = self.geometry.radial_clearance
        changes = []
        for d_film, d_rate in directions:
            d_film = self._film_direction(solution, d_film)
            dc_theta, dc_z, d_couette = stencil_derivative(
                solution.film / c, d_film, self.d_theta, self.d_z, self.flow, solution.rate
            )
            d_residual = apply_operator(dc_theta, dc_z, solution.relative_pressure) - d_couette
            if d_rate is not None:
                squeeze = d_rate if self.flow is None else d_rate * self.flow.squeeze_factor(solution.film / c)
                d_residual = d_residual + self.d_theta * self.d_z * squeeze
            moved = self.cavitation.film_residual_change(solution.cavitation, d_film)
            if moved is not None:
                d_residual = d_residual + moved
            changes.append(d_residual)
        d_residual = np.array(changes)
        return d_residual, self._pressure_response(solution, d_residual, directions)

    def _film_direction(self, solution: FilmSolution, d_film: np.ndarray) -> np.ndarray:
        """The film change along which the residual's change is taken (a liner's follows the load)."""
        return d_film

    def _pressure_response(
        self, solution: FilmSolution, d_residual: np.ndarray, directions: list[Direction]
    ) -> np.ndarray:
        """Pressure changes for residual changes, the cavitated set frozen (the model's linearisation)."""
        return self.cavitation.pressure_response(solution.stencil, solution.cavitation, d_residual)

    def contact_changes(
        self, solution: FilmSolution, films: list[np.ndarray], d_pressure: np.ndarray | None = None
    ) -> list[np.ndarray | None]:
        """Asperity pressure changes (Pa) for film changes ``dH`` (of H = h/c); None when smooth.
        With an elastic liner the film also changes by the liner's deformation under the
        pressure changes ``d_pressure`` (k, nz, nt), which must then be given."""
        slope = self.surfaces.contact_slope(solution.film)
        if slope is None or solution.contact is None:
            return [None] * len(films)
        slope = slope * self.geometry.radial_clearance
        return [slope * d_film for d_film in self._followed_films(solution, films, d_pressure)]

    def _followed_films(
        self, solution: FilmSolution, films: list[np.ndarray], d_pressure: np.ndarray | None
    ) -> list[np.ndarray]:
        """The film changes with the liner following (the rigid ones for a rigid bore)."""
        return films

    def load_changes(
        self, solution: FilmSolution, directions: list[Direction]
    ) -> tuple[np.ndarray, np.ndarray, list[np.ndarray | None]]:
        """Residual, pressure and asperity-pressure changes of ``directions``: what the force,
        moment and row-load changes are integrated from."""
        d_residual, d_pressure = self.pressure_changes(solution, directions)
        d_contact = self.contact_changes(solution, [d_film for d_film, _ in directions], d_pressure)
        return d_residual, d_pressure, d_contact

    def offset_directions(self, solution: FilmSolution) -> tuple[np.ndarray, np.ndarray]:
        """Changes of H = h/c per metre of journal offset ey and ez, shape (nz, nt)."""
        theta = solution.grid.theta
        c = self.geometry.radial_clearance
        shape = solution.film.shape
        d_ey = np.broadcast_to(-np.cos(theta) / c, shape)
        d_ez = np.broadcast_to(-self.geometry.rotation * np.sin(theta) / c, shape)
        return d_ey, d_ez

    def position_response(self, solution: FilmSolution) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """d(force)/d(ey, ez), N/m, with the active set frozen (exact for the Reynolds condition),
        with the residual and pressure changes per metre of ey and ez it comes from, each
        (2, nz, nt): a Newton step's trials predict their cavitated sets from these."""
        d_ey, d_ez = self.offset_directions(solution)
        d_residual, d_pressure, d_contact = self.load_changes(solution, [(d_ey, None), (d_ez, None)])
        dfy, dfz = (
            self.force(solution.grid, dp, gauge=False, contact=dc) for dp, dc in zip(d_pressure, d_contact, strict=True)
        )
        return np.column_stack([dfy, dfz]), d_residual, d_pressure

    # -- what a lined solver adds (nothing for a rigid bore) ------------------------------------
    def predicted_deformation(
        self, solution: FilmSolution, response: tuple[np.ndarray, np.ndarray], step: np.ndarray
    ) -> np.ndarray | None:
        """Liner deformation (m) after the journal moves by ``step`` (m), to first order (None
        without a liner)."""
        return solution.deformation

    def liner_tolerance(self, solution: FilmSolution, share: float) -> float:
        """Liner tolerance that leaves a force error of about ``share`` of the force (0: no liner)."""
        return 0.0
