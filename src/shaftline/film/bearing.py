"""Journal bearing: the film solution at a journal position and the equilibrium under a load.

Forces are those of the film on the journal, in the shaft axes (y up, z
starboard), N. Pressures are gauge pressures above the ambient pressure, Pa.
An applied load ``(load_y, load_z)`` is carried when the film force balances it:
``force + load = 0``.

A :class:`JournalBearing` is a :class:`~shaftline.film.problem.BearingProblem`
(pure data) plus a film solver that belongs to one process
(:class:`~shaftline.film.solver.FilmSolver`: the cavitation model with its sparse
factorisations and coarser grids, the last active set as the warm start). Pickling or
deep-copying a bearing carries only the problem; the solver is rebuilt on first use. This
class is the face of the film package: the solver, the equilibrium
(:mod:`shaftline.film.equilibrium`), the linearisations (:mod:`shaftline.film.linearise`) and
the results (:mod:`shaftline.film.results`) live in their modules.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import replace
from typing import Any

import numpy as np

from shaftline.errors import InputError
from shaftline.film.geometry import BearingGeometry, Grid, JournalPosition
from shaftline.film.lined import LinerConvergenceError, film_solver, sharing_solver
from shaftline.film.problem import BearingProblem, OperatingPoint, SolverOptions, SupplyGroove
from shaftline.film.results import (
    BearingState,
    Equilibrium,
    FilmLinearisation,
    FilmLoad,
    TiltLinearisation,
)
from shaftline.film.solver import FilmSolver

__all__ = [
    # Problem data and results, defined in their modules and re-exported here.
    "BearingProblem",
    "BearingState",
    "Equilibrium",
    "FilmLinearisation",
    "FilmLoad",
    "JournalBearing",
    "LinerConvergenceError",
    "OperatingPoint",
    "SolverOptions",
    "SupplyGroove",
    "TiltLinearisation",
]


class JournalBearing:
    """A finite journal bearing: geometry, operating point and solver options.

    The inputs form a :class:`~shaftline.film.problem.BearingProblem` (``.problem``),
    checked when the bearing is made. The film solver (:attr:`solver`: cavitation model,
    sparse factorisations, coarse grids, last active set) is built on first use in each
    process: pickling, ``copy.copy`` or ``copy.deepcopy`` carry only the problem, so
    a bearing, solved or not, can be sent to a process pool. The first
    ``solve_at(..., warm_start=True)`` after that starts cold; :meth:`equilibrium`,
    :meth:`linearise` and ``solve_at(..., warm_start=False)`` never depend on
    earlier calls.

    Parameters
    ----------
    geometry : BearingGeometry
    operating : OperatingPoint
    options : SolverOptions, optional
        Defaults to ``SolverOptions()``.

    Raises
    ------
    InputError
        ``"operating.cavitation_pressure"`` for a ``"jfo"`` film without feed pressure.

    Examples
    --------
    >>> from shaftline.film import BearingGeometry, JournalBearing, OperatingPoint
    >>> bearing = JournalBearing(
    ...     BearingGeometry(length=0.1, diameter=0.1, radial_clearance=1e-4),
    ...     OperatingPoint(speed=100.0, viscosity=0.02),
    ... )
    >>> eq = bearing.equilibrium(load_y=-5e3, load_z=0.0)
    >>> round(eq.state.sommerfeld_number, 3), round(eq.state.eccentricity_ratio, 2)
    (0.159, 0.53)
    >>> stiffness = bearing.linearise(eq.state.position).stiffness  # N/m
    >>> bool(stiffness[0, 0] > 0)
    True
    """

    def __init__(
        self, geometry: BearingGeometry, operating: OperatingPoint, options: SolverOptions | None = None
    ) -> None:
        self._problem = BearingProblem(geometry, operating, SolverOptions() if options is None else options)
        self._solver: FilmSolver | None = None

    @classmethod
    def from_problem(cls, problem: BearingProblem) -> JournalBearing:
        """The bearing of ``problem``, which it keeps as it is (already checked when made)."""
        bearing = cls.__new__(cls)
        bearing.__setstate__({"problem": problem})
        return bearing

    def with_geometry(self, geometry: BearingGeometry) -> JournalBearing:
        """This bearing with another bore or journal shape, sharing the solver it has built.

        For a design search over bores: the grid, the fixed nodes and the cavitation model
        with its kept factorisations depend on the length, diameter, clearance, sense of
        rotation, operating point and options, not on the bore profile, the bent journal or a
        film profile, so a bearing that differs only in those reuses them (the starts of the
        equilibrium, which carry the geometry, are built again). The kept factors are dropped,
        so that its results do not depend on what the shared solver solved before (their
        orderings would round differently).

        Raises
        ------
        InputError
            ``"geometry.length"`` (or ``diameter``, ``radial_clearance``, ``rotation``) when it
            differs from this bearing's.
        """
        for name in ("length", "diameter", "radial_clearance", "rotation"):
            if getattr(geometry, name) != getattr(self.geometry, name):
                raise InputError(
                    f"geometry.{name}", getattr(geometry, name), "", f"{getattr(self.geometry, name)}, as the bearing's"
                )
        other = JournalBearing.from_problem(replace(self._problem, geometry=geometry))
        if self._solver is not None:
            other._solver = sharing_solver(self._solver, other._problem)
        return other

    # -- the problem: read-only, since the solver is built from it ------------------------
    @property
    def problem(self) -> BearingProblem:
        """Geometry, operating point and solver options (pure data)."""
        return self._problem

    @property
    def geometry(self) -> BearingGeometry:
        """``problem.geometry``."""
        return self._problem.geometry

    @property
    def operating(self) -> OperatingPoint:
        """``problem.operating``."""
        return self._problem.operating

    @property
    def options(self) -> SolverOptions:
        """``problem.options``."""
        return self._problem.options

    @property
    def pressure_scale(self) -> float:
        """Pressure scale p_ref = 6 eta omega (R/c)^2, Pa."""
        return self._problem.pressure_scale

    @property
    def flow_scale(self) -> float:
        """Flow scale omega R^2 c / 2, m^3/s."""
        return self._problem.flow_scale

    def __repr__(self) -> str:
        return f"JournalBearing({self._problem!r})"

    # -- pickling and copying carry the problem only ------------------------------------
    def __getstate__(self) -> dict[str, Any]:
        return {"problem": self._problem}

    def __setstate__(self, state: dict[str, Any]) -> None:
        self._problem = state["problem"]
        self._solver = None

    @property
    def solver(self) -> FilmSolver:
        """The film solver of this process (built on first use): its :meth:`~FilmSolver.evaluate`,
        its cavitation model and its counters (``solver.counts``)."""
        if self._solver is None:
            self._solver = film_solver(self._problem)
        return self._solver

    # -- the film --------------------------------------------------------------------------
    def grid(self, position: JournalPosition) -> Grid:
        """The grid on which the film is solved with the journal at ``position``.

        Its first angle sits on the first supply groove, or with ``film_start="max_film"``
        on the line of maximum film at ``position``; otherwise at 0 (then the grid does
        not depend on the position).
        """
        return self.solver.grid_at(position)

    def film(self, position: JournalPosition) -> np.ndarray:
        """Film thickness on :meth:`grid` for ``position``, m, shape (nz, nt) (no clipping)."""
        return self.solver.film(position)

    def min_film(self, position: JournalPosition) -> float:
        """Smallest film thickness at ``position``, m (negative when the journal cuts the bore)."""
        return self.solver.min_film(position)

    @property
    def film_floor(self) -> float:
        """Smallest film the solver lets a journal approach, m: ``min_film_floor`` of the
        clearance, with rough surfaces the boundary limit ``-3 sigma`` below the mean plane
        (negative)."""
        return self.solver.surfaces.floor

    @property
    def axial_stations(self) -> np.ndarray:
        """Axial grid stations from the aft edge, m (where :meth:`film_load` takes the journal)."""
        return self.solver.grid.z.copy()

    @property
    def reynolds_number(self) -> float:
        """Clearance Reynolds number ``Re_c = rho omega R c / mu``; the local one is ``Re_c h / c``."""
        return self.solver.reynolds_number

    @property
    def turbulent(self) -> bool:
        """Whether the turbulence coefficients apply (``options.turbulence``: on, or auto with the
        largest local Reynolds number above the Taylor-vortex onset)."""
        return self.solver.turbulent

    def contact_zone_nodes(self, film: np.ndarray) -> int:
        """:func:`~shaftline.film.surfaces.contact_zone_nodes` of ``film`` (m, on :meth:`grid`)
        with this bearing's composite roughness (0 for smooth surfaces)."""
        return self.solver.surfaces.zone_nodes(film)

    # -- solutions -------------------------------------------------------------------------
    def solve_at(self, position: JournalPosition, warm_start: bool = True) -> BearingState:
        """Film solution with the journal held at ``position``.

        ``warm_start`` starts the cavitation active set from the previous solution of this
        bearing in this process (a sweep over nearby positions); otherwise from the nested
        coarse-grid guess. Both settle on the same active set; only ``iterations`` differs.

        Raises
        ------
        InputError
            ``"position"`` when the journal at that position would cut into the bore (h <= 0).
        """
        from shaftline.film.state import bearing_state

        return bearing_state(self.solver, self.solver.evaluate_inside(position, warm=warm_start))

    def linearise(self, position: JournalPosition, initial_cavitated: np.ndarray | None = None) -> FilmLinearisation:
        """Film force at ``position`` and its derivatives by journal offset and velocity.

        Solved from the coarse-grid guess, or from ``initial_cavitated`` (e.g. the
        ``cavitated`` set of the equilibrium state at ``position``, which spares the cold
        start), never from an earlier call, so the result depends only on the problem and
        ``position`` (the solution of the cavitation problem is unique); the four
        derivatives reuse the factorisation of the converged active set (one triangular
        solve each). ``position`` may carry velocities ``vy, vz``; the derivatives are taken
        about them. The stiffness and damping of :func:`shaftline.film.dynamics.dynamic_coefficients`
        are ``-offset_derivative`` and ``-velocity_derivative``.

        Parameters
        ----------
        position : JournalPosition
            Journal offsets (m), tilts (rad) and velocities (m/s).
        initial_cavitated : ndarray of bool (nz, nt), optional
            Cavitated set to start the film solution from.

        Returns
        -------
        FilmLinearisation
            Force (N), ``dF/dq`` (N/m) and ``dF/dv`` (N*s/m) with the cavitated set frozen.

        Raises
        ------
        InputError
            ``"position"`` when the journal at that position would cut into the bore (h <= 0).
        """
        from shaftline.film.linearise import linearise

        return linearise(self.solver, position, self.solver.start_set(initial_cavitated))

    def linearise_with_tilt(
        self, position: JournalPosition, initial_cavitated: np.ndarray | None = None
    ) -> TiltLinearisation:
        """Film force and moment at ``position`` and their derivatives by journal offset,
        tilt and their rates: the 4 x 4 stiffness and damping (docs/theory.md §7.1).

        Solved as :meth:`linearise` (from the coarse-grid guess or ``initial_cavitated``, never
        from an earlier call); :func:`~shaftline.film.linearise.tilt_linearisation` of that
        solution. The top-left 2 x 2 blocks are :meth:`linearise`'s.

        Parameters
        ----------
        position : JournalPosition
            Journal offsets (m), tilts (rad) and velocities (m/s); the tilt rates are zero.
        initial_cavitated : ndarray of bool (nz, nt), optional
            Cavitated set to start the film solution from.

        Returns
        -------
        TiltLinearisation
            Force (N), moment (N*m) and their derivatives with the cavitated set frozen.

        Raises
        ------
        InputError
            ``"position"`` when the journal at that position would cut into the bore (h <= 0).
        """
        from shaftline.film.linearise import tilt_linearisation

        solution = self.solver.evaluate_inside(position, warm=False, start=self.solver.start_set(initial_cavitated))
        return tilt_linearisation(self.solver, solution)

    def linearise_line(
        self, centre_y: np.ndarray, centre_z: np.ndarray, initial_cavitated: np.ndarray | None = None
    ) -> TiltLinearisation:
        """The 4 x 4 film stiffness and damping of a journal along a centre line of any shape (a
        bent shaft's elastic line, given as in :meth:`film_load`) moving as a rigid body about its
        mid-plane: :func:`~shaftline.film.linearise.tilt_linearisation` of the film along that line,
        started as :meth:`film_load` is (this bearing's previous solution, or ``initial_cavitated``).
        Its ``position`` is the line's mid-plane offsets and chord tilts.

        Raises
        ------
        InputError
            ``"centre_y"`` for a line of the wrong length or one that cuts into the bore.
        """
        from shaftline.film.linearise import line_solution, tilt_linearisation

        start = self.solver.start_set(initial_cavitated)
        return tilt_linearisation(self.solver, line_solution(self.solver, centre_y, centre_z, start=start))

    def film_load(
        self,
        centre_y: np.ndarray,
        centre_z: np.ndarray,
        directions: np.ndarray | None = None,
        warm_start: bool = True,
        initial_cavitated: np.ndarray | None = None,
        velocity_directions: np.ndarray | None = None,
    ) -> FilmLoad:
        """Film solution and its load along the bearing for a journal centre line of any shape.

        The journal of an elastohydrodynamic alignment (:mod:`shaftline.shaft.coupled`) is the
        shaft's elastic line: its centre is given at every axial grid station, and the film
        returns its force per grid row and, optionally, how those forces change with chosen
        changes of the centre line (the film stiffness of the shaft's degrees of freedom).

        Parameters
        ----------
        centre_y, centre_z : ndarray (nz,)
            Journal centre offsets from the nominal bore axis (the bore of a straight bearing;
            a slope-bored bore is the geometry's) at :attr:`axial_stations`, m. Any bent
            journal of the geometry is replaced by this line.
        directions : ndarray (k, 2, nz), optional
            Changes of ``(centre_y, centre_z)`` per unit of k parameters.
        warm_start : bool
            Start the cavitation set from this bearing's previous solution (nearby shapes).
        initial_cavitated : ndarray of bool (nz, nt), optional
            Start set instead (it wins over ``warm_start``); the result does not depend on it.
        velocity_directions : ndarray (q, 2, nz), optional
            Velocities of the centre line (m/s per unit of q parameters), for damping: the
            journal at this line moving so.

        Returns
        -------
        FilmLoad
            The state at the mid-plane offsets and chord tilt of the line, the force per row
            and its derivatives (cavitated set frozen, exact for the Reynolds condition).

        Raises
        ------
        InputError
            ``"centre_y"`` for a line of the wrong length or one that cuts into the bore.
        """
        from shaftline.film.linearise import film_load

        start = self.solver.start_set(initial_cavitated)
        return film_load(self.solver, centre_y, centre_z, directions, warm_start, start, velocity_directions)

    def min_film_of_line(self, centre_y: np.ndarray, centre_z: np.ndarray) -> float:
        """Smallest film for a journal centre line given as in :meth:`film_load`, m (no solve).

        With an elastic liner the film is the rigid gap plus the liner deformation of the last
        solution (the journal may pass the rigid bore into the liner): a prediction for nearby
        lines, as the equilibrium's own line search uses."""
        from shaftline.film.linearise import centre_line

        solver = self.solver
        position, geometry = centre_line(self.geometry, solver.grid.z, centre_y, centre_z)
        return float(solver.with_last_deformation(solver.film(position, geometry)).min())

    def initial_position(
        self, load_y: float, load_z: float, tilt_y: float = 0.0, tilt_z: float = 0.0
    ) -> JournalPosition:
        """The closed-form start of an equilibrium under ``(load_y, load_z)`` (N) with the tilts
        (rad): :func:`~shaftline.film.equilibrium.starts.initial_position`."""
        from shaftline.film.equilibrium import initial_position

        return initial_position(self.solver, np.array([load_y, load_z]), tilt_y, tilt_z)

    def equilibrium(
        self,
        load_y: float,
        load_z: float = 0.0,
        tilt_y: float = 0.0,
        tilt_z: float = 0.0,
        initial: JournalPosition | None = None,
        progress: Callable[[int, float], None] | None = None,
        initial_cavitated: np.ndarray | None = None,
        initial_deformation: np.ndarray | None = None,
    ) -> Equilibrium:
        """Find the mid-plane journal offsets at which the film carries the applied load.

        Newton's method on ``force(ey, ez) + load = 0`` with the Jacobian from the
        reused factorisation (frozen active set), a fraction-to-boundary rule that keeps
        the film above the floor, and a backtracking line search on the residual
        (:mod:`shaftline.film.equilibrium`). The tilts are held fixed (misalignment is an
        input). Each trial starts its cavitated set from the one the step predicts; without
        ``initial``, a grid of ``options.continuation.nodes`` or more starts from the
        equilibrium on the grid halved both ways (docs/theory.md, Sect. 4.1), and a bearing
        with an elastic liner from the rigid bore's equilibrium (its iterations not counted in
        ``iterations``, but in ``newton_iterations``), solving its trials' liners only as far
        as the force residual needs (docs/theory.md Sect. 17).

        Parameters
        ----------
        load_y, load_z : float
            Load applied to the journal, N (e.g. ``load_y = -W`` for a weight).
        tilt_y, tilt_z : float
            Journal tilt relative to the bore in the vertical and horizontal planes, rad.
        initial : JournalPosition, optional
            Starting position (warm start from a previous equilibrium).
        progress : callable, optional
            Called after each Newton iteration with its number and the force residual
            ``|force + load|`` as a share of the load; on a fine grid an iteration takes
            seconds to minutes. It does not change the result.
        initial_cavitated : ndarray of bool (nz, nt), optional
            Cavitated set to start the first film solution from, e.g. ``state.cavitated`` of
            a neighbouring equilibrium (a sweep); without it the set comes from the coarse
            grids. The solution of the cavitation problem is unique, so this changes the
            active-set iterations, not the result.
        initial_deformation : ndarray (nz, nt), optional
            Liner deformation (m) to start the first film-liner iteration from, e.g.
            ``state.liner.deformation`` of a neighbouring equilibrium (a sweep); without it the
            iteration starts from the undeformed liner. It changes the iterations and the result
            only within the liner's tolerance (a grid that turns with the journal,
            ``film_start = "max_film"``, takes it node by node: a start, not a map). Ignored
            without a liner.

        Returns
        -------
        Equilibrium
            The state there, whether it converged or met the film floor, and the counters of
            the work it took (``film_solutions``, ``factorisations``, ``newton_iterations``).

        Raises
        ------
        InputError
            Naming the parameter: ``"load_y"``, ``"load_z"``, ``"tilt_y"`` or ``"tilt_z"``
            for a value that is not finite, ``"load_y"`` for no load at all, the
            larger tilt for a misalignment that does not fit in the clearance, and
            ``"initial_deformation"`` for one that is not finite or not on the grid.
        """
        from shaftline.film.equilibrium.result import solve_equilibrium

        return solve_equilibrium(
            self.solver, load_y, load_z, tilt_y, tilt_z, initial, progress, initial_cavitated, initial_deformation
        )
