"""What a cavitation model is: the grid it solves on, its solution, and the protocol it meets.

A cavitation model finds the pressure field of one film on one grid, with the nodes where
the film has ruptured (its cavitated set), and says how that field responds to a change of
the film. :class:`CavitationModel` says what a new model implements; the models of
:data:`shaftline.film.cavitation.CAVITATION_MODELS` are the examples.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import TYPE_CHECKING, ClassVar, Protocol

import numpy as np

from shaftline.errors import SolverFailure

if TYPE_CHECKING:
    from shaftline.film.cavitation.coarse import CoarseGrid
    from shaftline.film.problem import SolverOptions
    from shaftline.film.roughness import FilmFlow
    from shaftline.film.stencil import Stencil

__all__ = [
    "CavitationConvergenceError",
    "CavitationModel",
    "CavitationSolution",
    "NodeGrid",
    "SolverCounts",
]


class CavitationConvergenceError(SolverFailure):
    """A cavitation model's iteration did not settle (never seen on the film's M-matrices; kept
    as a guard), or its linear system was singular (a whole circumferential line cavitated)."""


@dataclass(frozen=True, eq=False)
class NodeGrid:
    """The nodes of one grid as a cavitation model sees them: dimensionless mesh steps and the
    nodes whose pressure is held.

    Attributes
    ----------
    shape : (int, int)
        (axial_nodes, circumferential_nodes).
    d_theta, d_z : float
        Dimensionless mesh steps (rad, and axial step / R).
    fixed : ndarray of bool (nz, nt)
        Nodes with prescribed pressure (edges, supply grooves, a film start line).
    fixed_pressure : ndarray (nz, nt)
        Their dimensionless pressures above the cavitation pressure (0 elsewhere).
    """

    shape: tuple[int, int]
    d_theta: float
    d_z: float
    fixed: np.ndarray
    fixed_pressure: np.ndarray

    @classmethod
    def of(
        cls, shape: tuple[int, int], d_theta: float, d_z: float, fixed: np.ndarray, fixed_pressure: np.ndarray
    ) -> NodeGrid:
        """The grid with ``fixed`` as booleans and ``fixed_pressure`` zero off the fixed nodes."""
        held = np.asarray(fixed, dtype=bool)
        return cls(tuple(shape), d_theta, d_z, held, np.where(held, fixed_pressure, 0.0))  # type: ignore[arg-type]


@dataclass
class SolverCounts:
    """What a solver has spent since it was made: the counters of one problem's solutions in one
    process (SciPy's ``nfev``, ``nlu``), shared by its grids and the equilibria that start it.

    Attributes
    ----------
    film_solutions : int
        Pressure fields solved on a film (a cavitation model's solution of a whole film; the
        set predictions on coarser grids inside one are not counted).
    factorisations : int
        Numeric factorisations of sparse matrices: the film operator's LDL^T, the
        mass-conserving Jacobian's LU, the film-liner matrix's LU (a kept factor updated by a
        bordered correction is not one), on every grid.
    """

    film_solutions: int = 0
    factorisations: int = 0

    def copy(self) -> SolverCounts:
        return SolverCounts(self.film_solutions, self.factorisations)


@dataclass(eq=False)
class CavitationSolution:
    """Dimensionless solution of the film equation on a grid with a cavitation model.

    Attributes
    ----------
    pressure : ndarray (nz, nt)
        ``P`` above the cavitation pressure (>= 0; the fixed nodes hold 0 here, their values
        are the grid's).
    film_fraction : ndarray (nz, nt)
        Share of the clearance filled with liquid (1 in the full film).
    cavitated : ndarray of bool (nz, nt)
        Nodes held at the cavitation pressure.
    iterations : int
        Active-set iterations used: linear solves of trial sets (factorisations, or on
        fine grids conjugate-gradient solves), the final solve with the settled set's
        factor included.
    settled : bool
        False for a solution left on a set a few nodes from the final one (a Newton iterate
        solved with ``settle=False``, :meth:`CavitationModel.solve`); True otherwise.
    """

    pressure: np.ndarray
    film_fraction: np.ndarray
    cavitated: np.ndarray
    iterations: int
    settled: bool = field(default=True, kw_only=True)


class CavitationModel(Protocol):
    """A cavitation model of the discrete film on one grid.

    A model is made for one grid (:class:`NodeGrid`), the solver's options and the solver's
    counters, and may keep state between its calls (factorisations, elimination orders,
    coarser grids, its last solution): that state belongs to one process and is never
    pickled (the problem is; the model is rebuilt from it). Its results may depend on that
    state only to rounding, never on which solutions came before.

    A new model implements the attributes and methods below, lives in its own module of
    :mod:`shaftline.film.cavitation` and is added to
    :data:`~shaftline.film.cavitation.CAVITATION_MODELS` (and to the ``Cavitation`` choices
    of :mod:`shaftline.film.problem`, which the case file offers). A class passed as
    ``SolverOptions(cavitation=...)`` serves as well, without a name in the case file.

    Attributes
    ----------
    name : str
        The model's name (its key in the registry; ``BearingState.cavitation``).
    active_set : bool
        Whether the solution is found by switching a cavitated set whose far Newton iterates
        may stop a few nodes short of settling; such a film's equilibrium also continues from
        the grid halved both ways on large grids.
    refines_trials : bool
        Whether a Newton trial close to the solution may iterate its pressure from the step's
        linear guess with the kept factor (``solve(..., refine_from=)``).
    starts_from_coarse_contact : bool
        Whether a coarse equilibrium that ends at the film floor still starts the fine one.
    rough_surfaces, liners : bool
        Whether the model's discrete film has the flow factors of rough surfaces and the
        linearisation the film-liner system is built on; a problem that needs them is refused
        otherwise, with ``refusal`` as the reason.
    needs_feed_pressure : bool
        Whether a film without an edge or groove pressure above the cavitation pressure runs
        dry (the problem is then refused).
    dense_bytes, factor_bytes : float
        Memory the model needs beyond the film solver's on the fine grid: bytes per node and
        per nonzero of the film operator's LDL^T factor (``estimated_memory``).
    nodes : NodeGrid
        The grid.

    Methods
    -------
    solve(stencil, film, start=None, *, refine_from=None, settle=True)
        The solution (:class:`CavitationSolution` or a subclass) of the film ``H = h/c``
        with ``stencil``, its cavitated set started from ``start`` (a set of a nearby
        solution; without one, the model predicts its own, e.g. from coarser grids).
    start_from_guess(stencil, film, guess)
        A start set from a pressure guess (a coarser grid's solution brought onto this grid,
        in the form :meth:`start_field` gives), or None when the model takes no such start.
    trial_guess(relative, step, response)
        The pressure guess of a Newton trial that moves the journal by ``step`` (m, (2,)) from a
        solution with relative pressure ``relative``, ``response`` the pressure changes per
        metre of the two offsets (2, nz, nt); or None.
    film_residual_change(solution, film_change)
        What the film equation's residual gains for a film change at the solution's cavitated
        set beyond the frozen-set stencil change (the mass-conserving model's void transport),
        or None.
    pressure_response(stencil, solution, residual_changes)
        Pressure changes ``dP`` (k, nz, nt) for residual changes (k, nz, nt), the cavitated set
        frozen: the exact linearisation of the discrete film where the model has one.
    start_field(solution, relative)
        The field of a solution that, prolonged onto a finer grid, starts that grid's set.
    unsettled_residual(options)
        Force residual (share of the load) above which the equilibrium's iterates may stay
        unsettled.
    coarse_grid()
        The grid halved both ways under this one with a model of the same kind on it
        (:class:`~shaftline.film.cavitation.coarse.CoarseGrid`), or None.
    drop_factors()
        Forget kept factors and orders, so that the next solutions round the same whatever
        was solved before.
    """

    name: ClassVar[str]
    active_set: ClassVar[bool]
    refines_trials: ClassVar[bool]
    starts_from_coarse_contact: ClassVar[bool]
    rough_surfaces: ClassVar[bool]
    liners: ClassVar[bool]
    refusal: ClassVar[str]
    needs_feed_pressure: ClassVar[bool]
    dense_bytes: ClassVar[float]
    factor_bytes: ClassVar[float]
    nodes: NodeGrid

    def __init__(
        self,
        nodes: NodeGrid,
        options: SolverOptions,
        counts: SolverCounts | None = None,
        flow: FilmFlow | None = None,
        masked: bool = False,
    ) -> None: ...

    def solve(
        self,
        stencil: Stencil,
        film: np.ndarray,
        start: np.ndarray | None = None,
        *,
        refine_from: np.ndarray | None = None,
        settle: bool = True,
    ) -> CavitationSolution: ...

    def start_from_guess(self, stencil: Stencil, film: np.ndarray, guess: np.ndarray) -> np.ndarray | None: ...

    def trial_guess(self, relative: np.ndarray, step: np.ndarray, response: np.ndarray) -> np.ndarray | None: ...

    def film_residual_change(self, solution: CavitationSolution, film_change: np.ndarray) -> np.ndarray | None: ...

    def pressure_response(
        self, stencil: Stencil, solution: CavitationSolution, residual_changes: np.ndarray
    ) -> np.ndarray: ...

    def start_field(self, solution: CavitationSolution, relative: np.ndarray) -> np.ndarray: ...

    def unsettled_residual(self, options: SolverOptions) -> float: ...

    def coarse_grid(self) -> CoarseGrid | None: ...

    def drop_factors(self) -> None: ...
