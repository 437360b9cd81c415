"""Mass-conserving (Jakobsson-Floberg-Olsson) cavitation on the film grid.

The complementarity form of Giacopini et al. (2010): each node carries either a
pressure ``P >= 0`` (full film) or a void fraction ``s = 1 - film fraction >= 0``
(cavitated), ``P s = 0``; the Couette flux through a face is
``(1 - s_upstream) q_face`` with ``q = dZ H_face``. Cell balance (docs/theory.md, Sect. 4):

    (A P)_k + q_k (1 - s_k) - q_w (1 - s_w) + squeeze_k = 0.

One unknown per node, ``u = P`` where the film is full and ``u = -s`` where it is
cavitated, turns the complementarity problem into the piecewise-linear equation
``R(u) = A u+ - T u- - b = 0`` (``u+ = max(u, 0)``, ``u- = max(-u, 0)``, ``T`` the
transport of the void fraction). Its generalised Jacobian on the set
``C = {u < 0}`` has column ``k`` equal to A's column for a full node and to the
transport column (``q_k`` on the diagonal, ``-q_k`` on the downstream neighbour) for
a cavitated node. Both live in the 5-point stencil, so every Jacobian has the
same sparsity pattern, assembled here without loops over nodes. Newton's method
on ``R`` (semi-smooth Newton, which here is the primal-dual active-set method:
``C <- {u < 0}`` after each solve) is exact on a fixed set, so it stops when the
set repeats. The LU factor of the last Jacobian stays with the newest solution: it
gives the exact linearisation of the discrete JFO film (void-fraction
sensitivity included) for the equilibrium's Newton steps and the dynamic
coefficients at one back-substitution per direction.

The model's state (its last solution and factor, the elimination order kept for its grid, a
factor rebuilt for an older solution) lives on the :class:`MassConserving` object of one grid,
which the film solver builds in each process.
"""

from __future__ import annotations

import weakref
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any, ClassVar

import numpy as np

from shaftline.film.cavitation.base import CavitationConvergenceError, CavitationSolution, NodeGrid, SolverCounts
from shaftline.film.cavitation.coarse import CoarseGrid
from shaftline.film.cavitation.reynolds import ReynoldsCondition
from shaftline.film.geometry import coarse_shape
from shaftline.film.stencil import Stencil, apply_operator, build_stencil, full_pattern, stencil_diagonal

if TYPE_CHECKING:
    from shaftline.film.options import ActiveSetOptions, JfoOptions
    from shaftline.film.problem import SolverOptions
    from shaftline.film.roughness import FilmFlow

__all__ = ["JfoSolution", "MassConserving", "jfo_residual", "void_transport"]


@dataclass(eq=False)
class JfoSolution(CavitationSolution):
    """A converged JFO film that can linearise itself (solver state: never pickled).

    Attributes
    ----------
    void : ndarray (nz, nt)
        Void fraction ``s`` (0 in the full film and on fixed nodes).
    fixed : ndarray of bool (nz, nt)
        Nodes with prescribed pressure (rows of the identity in the Jacobian).
    stencil : Stencil
        The film's stencil, from which the Jacobian is rebuilt if its factor is gone.
    """

    void: np.ndarray
    fixed: np.ndarray
    stencil: Stencil
    # Weak: the model keeps one factor alive at a time (that of its newest solution), so a
    # solution kept beside newer ones costs no memory; it refactorises if asked after them.
    _factor: weakref.ref[_Factor] | None = field(default=None, repr=False)
    # The model that solved it (weak: a solution kept after its solver is gone still linearises).
    _owner: weakref.ref[MassConserving] | None = field(default=None, repr=False)
    # A factor rebuilt after its model is gone, kept here instead.
    _kept: _Factor | None = field(default=None, repr=False)

    def factor(self) -> _Factor:
        """LU factor of the Jacobian ``dR/du`` on the converged set (rebuilt if released)."""
        factor = None if self._factor is None else self._factor()
        if factor is None:
            owner = None if self._owner is None else self._owner()
            counts = SolverCounts() if owner is None else owner.counts
            values = _jacobian_values(self.stencil, self.cavitated, self.fixed, stencil_diagonal(self.stencil))
            factor = _factorise_values(values, self.fixed.shape, counts)
            self._factor = weakref.ref(factor)
            if owner is not None:
                owner.rebuilt = factor  # kept like the newest solution's factor, until the next solve
            else:
                self._kept = factor
        return factor

    def unknown_response(self, residual_change: np.ndarray) -> np.ndarray:
        """``du = -J^{-1} dR`` for residual changes ``dR`` of shape (k, nz, nt); ``u = P`` or ``-s``."""
        shape = self.pressure.shape
        columns = np.asarray(residual_change).reshape(-1, shape[0] * shape[1])
        rhs = np.where(self.fixed.ravel()[None, :], 0.0, -columns)
        return np.asarray(self.factor().solve(np.ascontiguousarray(rhs.T))).T.reshape((-1,) + shape)

    def pressure_response(self, residual_change: np.ndarray) -> np.ndarray:
        """Pressure changes ``dP`` (k, nz, nt) on the full-film nodes for residual changes ``dR``."""
        full = ~(self.cavitated | self.fixed)
        return np.where(full[None], self.unknown_response(residual_change), 0.0)


def void_transport(couette_face: np.ndarray, void: np.ndarray) -> np.ndarray:
    """Change of each cell's net outflow by the voids: ``-s_k q_k + s_w q_w`` (nz, nt).

    With ``couette_face`` replaced by its derivative ``dq`` this is the void-fraction
    term of the JFO residual's derivative for a film change at fixed ``s``.
    """
    flux = couette_face * void
    return np.roll(flux, 1, axis=1) - flux


def jfo_residual(stencil: Stencil, pressure: np.ndarray, void: np.ndarray, fixed: np.ndarray) -> np.ndarray:
    """Mass balance of every cell, ``(A P)_k + q_k (1 - s_k) - q_w (1 - s_w) + squeeze_k`` (nz, nt).

    Dimensionless net outflow of each control volume (0 on a solution; fixed nodes set to 0).
    ``pressure`` holds the fixed values on the fixed nodes.
    """
    out = (
        apply_operator(stencil.c_theta, stencil.c_z, pressure)
        - stencil.rhs
        + void_transport(stencil.couette_face, void)
    )
    return np.where(fixed, 0.0, out)


def _jacobian_values(stencil: Stencil, cavitated: np.ndarray, fixed: np.ndarray, diag: np.ndarray) -> np.ndarray:
    """``dR/du`` on the set ``cavitated``: values in the fixed CSC pattern of
    :func:`~shaftline.film.stencil.full_pattern`."""
    pattern = full_pattern(*fixed.shape)
    cav = cavitated.ravel()
    held = fixed.ravel()
    q = stencil.couette_face.ravel()
    row, col, off = pattern.row, pattern.col, pattern.off
    coefficients = np.concatenate([diag.ravel(), stencil.c_theta.ravel(), stencil.c_z.ravel()])
    values = np.where(off, -1.0, 1.0) * coefficients[pattern.source]
    # Fixed nodes: their rows are the identity (scaled) and their values move to the right-hand side.
    values[off & (held[row] | held[col])] = 0.0
    # Cavitated column k: s_k cuts the Couette outflow of cell k and the inflow of its east cell.
    cav_col = cav[col]
    on_diagonal = cav_col & ~off
    values[on_diagonal] = q[col[on_diagonal]]
    moved = cav_col & off
    values[moved] = np.where(pattern.downstream[moved] & ~held[row[moved]], -q[col[moved]], 0.0)
    return values


def _jacobian(stencil: Stencil, cavitated: np.ndarray, fixed: np.ndarray, diag: np.ndarray) -> Any:
    """``dR/du`` on the set ``cavitated`` as a sparse matrix (``scipy.sparse.csc_matrix``), zeros
    of the pattern kept (for checks)."""
    import scipy.sparse as sp

    pattern = full_pattern(*fixed.shape)
    n = fixed.size
    values = _jacobian_values(stencil, cavitated, fixed, diag)
    return sp.csc_matrix((values, pattern.indices, pattern.indptr), shape=(n, n))


@dataclass(frozen=True, eq=False)
class _Factor:
    """LU factor of a Jacobian, of its rows and columns in ``order`` (None: grid order)."""

    lu: Any  # scipy.sparse.linalg.SuperLU
    order: np.ndarray | None = None

    def solve(self, rhs: np.ndarray) -> np.ndarray:
        """``J^{-1} rhs`` for real ``rhs`` of shape (n,) or (n, k)."""
        rhs = np.asarray(rhs)
        if np.iscomplexobj(rhs):
            raise TypeError("the JFO factor solves real right-hand sides only")
        if self.order is None:
            return np.asarray(self.lu.solve(np.ascontiguousarray(rhs, dtype=float)))
        out = np.empty(rhs.shape)
        out[self.order] = self.lu.solve(np.ascontiguousarray(rhs[self.order], dtype=float))
        return out


@dataclass(frozen=True, eq=False)
class _Ordering:
    """A fill-reducing elimination order of one grid's Jacobians, kept for its next sets.

    Attributes
    ----------
    cavitated : ndarray of bool (nz, nt)
        The set it was found for (its shape is the grid's).
    order : ndarray of int (n,)
        Grid nodes in elimination order.
    take : ndarray of int
        Entry of the :func:`~shaftline.film.stencil.full_pattern` values at each entry of the permuted pattern (CSC).
    indices, indptr : ndarray of int
        The permuted pattern's rows and column pointers.
    fill : int
        Entries of the factor of that set (SuperLU's ``nnz``).
    boundary : int
        Nodes of that set with a neighbour outside it (its rupture and reformation boundaries).
    """

    cavitated: np.ndarray
    order: np.ndarray
    take: np.ndarray
    indices: np.ndarray
    indptr: np.ndarray
    fill: int
    boundary: int

    @classmethod
    def of(cls, lu: Any, cavitated: np.ndarray) -> _Ordering:
        """The order SuperLU chose for ``lu``, the factor of the set ``cavitated`` (grid node
        ``k`` eliminated ``perm_c[k]``-th)."""
        pattern = full_pattern(*cavitated.shape)
        n = cavitated.size
        position = np.asarray(lu.perm_c, dtype=np.int64)
        row, col = position[pattern.row], position[pattern.col]
        take = np.argsort(col * n + row)  # column-major (CSC) order of the permuted entries
        indptr = np.zeros(n + 1, dtype=pattern.indptr.dtype)
        np.cumsum(np.bincount(col, minlength=n), out=indptr[1:])
        inside = np.roll(cavitated, 1, axis=1) & np.roll(cavitated, -1, axis=1)
        inside[1:] &= cavitated[:-1]
        inside[:-1] &= cavitated[1:]
        boundary = int(np.count_nonzero(cavitated & ~inside))
        return cls(cavitated.copy(), np.argsort(position), take, row[take], indptr, int(lu.nnz), boundary)

    def suits(self, cavitated: np.ndarray, set_change: float) -> bool:
        """Whether the order may serve the set ``cavitated``: it differs from the order's set in
        at most ``set_change`` of that set's boundary nodes (``JfoOptions.ordering_set_change``)."""
        if cavitated.shape != self.cavitated.shape:
            return False
        return int(np.count_nonzero(cavitated != self.cavitated)) <= set_change * self.boundary


def _splu(matrix: Any, ordering: str, counts: SolverCounts) -> Any:
    """:func:`~shaftline.film.elastic.grid_splu` of a Jacobian (diagonal pivots, see
    :func:`_factorise_values`), a singular one (a whole circumferential line cavitated) raised
    as :class:`CavitationConvergenceError`; counted in ``counts.factorisations``."""
    from shaftline.film.elastic import grid_splu

    counts.factorisations += 1
    try:
        return grid_splu(matrix, ordering, pivot_threshold=0.1)
    except RuntimeError as exc:
        raise CavitationConvergenceError(f"JFO Jacobian is singular ({exc})") from None


def _without_zeros(values: np.ndarray, indices: np.ndarray, indptr: np.ndarray) -> Any:
    """The CSC matrix of ``values`` on the pattern (``indices``, ``indptr``), zero entries dropped."""
    import scipy.sparse as sp

    n = indptr.size - 1
    kept = values != 0.0
    counts = np.add.reduceat(kept.astype(np.intp), indptr[:-1])  # every column keeps its diagonal
    return sp.csc_matrix((values[kept], indices[kept], np.concatenate([[0], np.cumsum(counts)])), shape=(n, n))


def _factorise_values(values: np.ndarray, shape: tuple[int, int], counts: SolverCounts) -> _Factor:
    """LU of the Jacobian with ``values`` in the pattern of :func:`~shaftline.film.stencil.full_pattern`
    for ``shape``.

    The entries that are zero on this set (the couplings of fixed nodes, the unused entries
    of cavitated columns) are dropped first, and SuperLU orders what is left by minimum
    degree on A + A^T. The cavitated columns then hold two entries each and their interior
    forms bidiagonal chains along theta, which the ordering eliminates almost without fill:
    on the NTUA case this is twice as fast as one ordering of the full pattern reused for
    every set (4.2 vs 7.8 ms on 100 x 60 nodes, 20 vs 48 ms on 200 x 120, ordering included).
    The Jacobian is column diagonally dominant (A's columns, and transport columns q, -q),
    and stays so under a symmetric permutation, so Gaussian elimination needs no row
    exchanges: the diagonal pivots are kept (``SymmetricMode``).
    """
    pattern = full_pattern(*shape)
    return _Factor(_splu(_without_zeros(values, pattern.indices, pattern.indptr), "MMD_AT_PLUS_A", counts))


def _factorise_ordered(values: np.ndarray, ordering: _Ordering, counts: SolverCounts) -> _Factor:
    """LU of the Jacobian with ``values`` (pattern order) in a kept elimination order: rows and
    columns permuted to it, zeros dropped, and SuperLU told to keep that order (``NATURAL``)."""
    matrix = _without_zeros(values[ordering.take], ordering.indices, ordering.indptr)
    return _Factor(_splu(matrix, "NATURAL", counts), ordering.order)


def _predicted_set(last: JfoSolution, factor: _Factor, stencil: Stencil) -> np.ndarray:
    """Cavitated set after one chord step from the last solution to the new film.

    ``u = u0 - J0^{-1} R(u0)`` with ``R`` the new film's residual and ``J0`` the last
    Jacobian (one back-substitution): exact where the set does not change except for the
    change of the Jacobian itself, so it moves the rupture and reformation boundaries of a
    Newton step or a sweep in one go instead of a few cells per factorisation.
    """
    pressure = np.where(last.fixed, 0.0, last.pressure)
    residual = jfo_residual(stencil, last.pressure, last.void, last.fixed).ravel()
    step = factor.solve(np.where(last.fixed.ravel(), 0.0, -residual)).reshape(residual.shape)
    unknown = np.where(last.cavitated, -last.void, pressure).ravel() + step
    return (unknown.reshape(last.fixed.shape) < 0.0) & ~last.fixed


class MassConserving:
    """The mass-conserving (Jakobsson-Floberg-Olsson) cavitation model on one grid, solved by
    semi-smooth Newton on ``u`` (``P`` or ``-s`` per node); a :class:`CavitationModel`.

    Its state belongs to one process: the last solution and its LU factor (the chord-step
    predictor of the next warm start), the elimination order kept for the grid
    (:class:`_Ordering`), a factor rebuilt for an older solution, the same model on the grid
    halved each way (the nested start of a cold solution) and, on a grid too small to halve,
    the Reynolds condition that starts it.

    Parameters
    ----------
    nodes, options, counts, flow, masked
        As :class:`~shaftline.film.cavitation.reynolds.ReynoldsCondition` (``flow`` is not
        used: the model's film has no flow factors; ``masked`` passes to the Reynolds start).
    """

    name: ClassVar[str] = "jfo"
    active_set: ClassVar[bool] = True
    refines_trials: ClassVar[bool] = False
    starts_from_coarse_contact: ClassVar[bool] = False
    rough_surfaces: ClassVar[bool] = False
    liners: ClassVar[bool] = False
    # The void transport rides on the smooth Couette flux; its rough form (mean gap and shear
    # flow factor) is not derived yet.
    refusal: ClassVar[str] = "the mass-conserving model has no flow factors yet"
    needs_feed_pressure: ClassVar[bool] = True
    #: Further bytes per fine-grid node: its Jacobian in the fixed 5-point pattern, the residual
    #: arrays and its own coarse grids. Measured with narrow SuperLU panels and kept elimination
    #: orders, at a light load (5 kN, little cavitation: the most fill) and at 300 kN: peaks of
    #: an equilibrium with stiffness and damping at 0.79-0.95 of the estimate lightly loaded
    #: (81 x 120, 161 x 240, 321 x 240, 161 x 480; three runs each), 0.72-0.83 at 300 kN
    #: (docs/validation.md) ...
    dense_bytes: ClassVar[float] = 500.0
    #: ... and its SuperLU factors, per nonzero of the LDL^T factor of the fine grid.
    factor_bytes: ClassVar[float] = 12.0

    def __init__(
        self,
        nodes: NodeGrid,
        options: SolverOptions,
        counts: SolverCounts | None = None,
        flow: FilmFlow | None = None,
        masked: bool = False,
    ) -> None:
        self.nodes = nodes
        self.solver_options = options
        self.options: JfoOptions = options.jfo
        self.active_set_options: ActiveSetOptions = options.active_set
        self.counts = SolverCounts() if counts is None else counts
        self.masked = masked
        self._coarse_grid: CoarseGrid[MassConserving] | None = None
        self._reynolds: ReynoldsCondition | None = None
        #: The last solution and its factor, which predict the set of the next warm start;
        #: dropped when the next solve starts, so that one fine factor is alive at a time.
        self.last: tuple[JfoSolution, _Factor] | None = None
        #: A factor rebuilt for an older solution (at most one), kept until the next solve.
        self.rebuilt: _Factor | None = None
        #: The elimination order kept for this grid's Jacobians.
        self.ordering: _Ordering | None = None

    @property
    def fixed(self) -> np.ndarray:
        return self.nodes.fixed

    @property
    def fixed_pressure(self) -> np.ndarray:
        return self.nodes.fixed_pressure

    def drop_factors(self) -> None:
        """Forget the last solution, its factor and the kept elimination order (and those of
        the coarser grids), so that the next solutions round the same whatever this model
        solved before."""
        self.last = None
        self.ordering = None
        if self._reynolds is not None:
            self._reynolds.drop_factors()
        if self._coarse_grid is not None:
            self._coarse_grid.model.drop_factors()

    def coarse_grid(self) -> CoarseGrid[MassConserving] | None:
        """The grid halved in both directions under this one with its own model (kept), or None
        when too small."""
        halved = coarse_shape(self.nodes.shape)
        if halved is None:
            return None
        if self._coarse_grid is None:

            def make(nodes: NodeGrid) -> MassConserving:
                masked = nodes.shape[0] * nodes.shape[1] < self.active_set_options.pcg_min_nodes
                return MassConserving(nodes, self.solver_options, self.counts, masked=masked)

            self._coarse_grid = CoarseGrid.under(self.nodes, halved, make)
        return self._coarse_grid

    def _reynolds_start(self) -> ReynoldsCondition:
        """The Reynolds condition on this grid: the cold start of a grid too small to halve."""
        if self._reynolds is None:
            self._reynolds = ReynoldsCondition(self.nodes, self.solver_options, self.counts, masked=self.masked)
        return self._reynolds

    def solve(
        self,
        stencil: Stencil,
        film: np.ndarray,
        start: np.ndarray | None = None,
        *,
        refine_from: np.ndarray | None = None,
        settle: bool = True,
    ) -> JfoSolution:
        """Mass-conserving cavitation by semi-smooth Newton on ``u`` (``P`` or ``-s`` per node).

        Parameters
        ----------
        stencil : Stencil
            Conductances, Couette fluxes and right-hand side of the film.
        film : ndarray (nz, nt)
            Dimensionless film H = h / c.
        start : ndarray of bool, optional
            Cavitated set of a previous JFO solution of this model to start from (through the
            chord-step predictor when it is the set of the last solution); without it the set
            predicted by the JFO solution on the grid halved each way, or on a grid too small
            to halve the set of the Reynolds (Swift-Stieber) solution.
        refine_from : None
            Not used (the Reynolds condition's refined trials).
        settle : bool
            False: stop at the first set within ``ActiveSetOptions.unsettled_max_nodes`` nodes
            of settling, that set's solution (pressure and void fraction clipped at zero) marked
            ``settled=False``, its factor that set's Jacobian (a Newton iterate far from the
            equilibrium, or a coarse grid's prediction: each set costs an LU factorisation).
            Solving again from its set finishes it (the chord-step predictor leads to the next set).

        Returns
        -------
        JfoSolution
            Dimensionless pressure (fixed values on fixed nodes, 0 where cavitated), film fraction
            ``1 - s`` (clipped to [0, 1]), cavitated set, active-set iterations on this grid
            (plus those of a Reynolds start) and the means to linearise it.
        """
        return self._solve(stencil, film, start, settle=settle, remember=True)

    def _solve(
        self, stencil: Stencil, film: np.ndarray, start: np.ndarray | None, settle: bool, remember: bool
    ) -> JfoSolution:
        """:meth:`solve`; ``remember`` keeps the solution as the predictor of this model's next
        warm start (the coarse grids of a cold start, never warm-started, do not)."""
        fixed = self.fixed
        iterations = 0
        if start is None:
            nested = self._nested_start(stencil, film)
            if nested is None:
                first = self._reynolds_start().solve(stencil, film)
                cavitated = first.cavitated & ~fixed
                iterations = first.iterations
            else:
                cavitated = nested
        else:
            cavitated = np.asarray(start, dtype=bool) & ~fixed
            last = self.last
            if last is not None and np.array_equal(last[0].cavitated, cavitated):
                cavitated = _predicted_set(last[0], last[1], stencil)
        self.last = None
        self.rebuilt = None
        diag = stencil_diagonal(stencil)
        boundary = np.where(fixed, self.fixed_pressure, 0.0)
        rhs = stencil.rhs - apply_operator(stencil.c_theta, stencil.c_z, boundary)
        rhs = np.where(fixed, diag * self.fixed_pressure, rhs).ravel()
        factor: _Factor | None = None
        tolerance = self.options.switch_tolerance
        unsettled = self.active_set_options.unsettled_max_nodes
        for _ in range(self.active_set_options.max_iterations):
            factor = None  # free the last factor before the next is made: one factor at a time
            factor = self._factorise(stencil, cavitated, diag)
            unknown = factor.solve(rhs).reshape(self.nodes.shape)
            iterations += 1
            pressure = np.where(cavitated, 0.0, unknown)
            scale = max(float(np.abs(pressure).max()), 1e-300)
            enter = ~(fixed | cavitated) & (unknown < -tolerance * scale)
            leave = cavitated & (unknown > tolerance)
            settled = not enter.any() and not leave.any()
            if settled or (not settle and int(np.count_nonzero(enter | leave)) <= unsettled):
                void = np.where(cavitated, -unknown, 0.0)
                if not settled:  # the few nodes on the wrong side, at zero
                    pressure, void = np.maximum(pressure, 0.0), np.maximum(void, 0.0)
                fraction = np.clip(1.0 - void, 0.0, 1.0)
                solution = JfoSolution(
                    pressure,
                    fraction,
                    cavitated,
                    iterations,
                    void,
                    fixed,
                    stencil,
                    weakref.ref(factor),
                    weakref.ref(self),
                    settled=settled,
                )
                if remember:
                    self.last = (solution, factor)
                return solution
            cavitated = (cavitated & ~leave) | enter
        raise CavitationConvergenceError("JFO active set did not settle")

    def _factorise(self, stencil: Stencil, cavitated: np.ndarray, diag: np.ndarray) -> _Factor:
        """LU of the Jacobian on ``cavitated``, in the elimination order kept for this grid when
        it suits the set (``JfoOptions.ordering_set_change``), else in a fresh order, then kept."""
        fixed = self.fixed
        values = _jacobian_values(stencil, cavitated, fixed, diag)
        ordering = self.ordering
        if ordering is None or not ordering.suits(cavitated, self.options.ordering_set_change):
            factor = _factorise_values(values, fixed.shape, self.counts)
            self.ordering = _Ordering.of(factor.lu, cavitated)
            return factor
        factor = _factorise_ordered(values, ordering, self.counts)
        if factor.lu.nnz > self.options.ordering_fill_growth * ordering.fill:
            self.ordering = None
        return factor

    def _nested_start(self, stencil: Stencil, film: np.ndarray) -> np.ndarray | None:
        """Cavitated set predicted by the JFO solution of the same film on the grid halved each way.

        The coarse unknown ``u`` (``P`` in the full film, ``-s`` where cavitated) changes sign on
        both the rupture and the reformation boundary; interpolated bilinearly onto the fine
        grid it places them to within a coarse cell, and the sweeps of :meth:`relaxed_set` on this
        grid remove most of that error. Recursive down to the coarsest grid, which starts from the
        Reynolds condition.
        """
        coarse = self.coarse_grid()
        if coarse is None:
            return None
        d_theta, d_z = self.nodes.d_theta, self.nodes.d_z
        # The squeeze part of the right-hand side, (2/omega) dH/dt per cell, restricted with the film.
        rate = (np.roll(stencil.couette_face, 1, axis=1) - stencil.couette_face - stencil.rhs) / (d_theta * d_z)

        film_c = coarse.restrict(film)
        rate_c = coarse.restrict(rate) if np.any(rate) else None
        model_c = coarse.model
        stencil_c = build_stencil(film_c, model_c.nodes.d_theta, model_c.nodes.d_z, rate_c)
        solution = model_c._solve(stencil_c, film_c, None, settle=False, remember=False)  # a prediction only
        indicator = np.where(solution.cavitated, -solution.void, solution.pressure)
        indicator = np.where(model_c.fixed, 0.0, indicator)
        return self.relaxed_set(stencil, coarse.prolong(indicator))

    def relaxed_set(self, stencil: Stencil, unknown: np.ndarray, sweeps: int | None = None) -> np.ndarray:
        """Cavitated set left by ``sweeps`` (``JfoOptions.prediction_sweeps``) red-black nonlinear
        Gauss-Seidel sweeps of the JFO equation ``R(u) = 0`` (C3) from a guess of the unknown
        (nz, nt; ``P`` or ``-s``).

        With its neighbours held, a node's residual is continuous, piecewise linear and increasing
        in its own unknown (slope ``diag(A)`` for ``u >= 0``, ``q`` for ``u < 0``), so it has one
        root: ``u = -R0 / diag(A)`` when the residual at ``u = 0``, ``R0``, is negative (full
        film), else ``u = -R0 / q`` (cavitated). Nodes of one colour share no neighbour, so the
        order within a colour does not matter. The sweeps remove the short-wavelength error of an
        interpolated set (the smoothing property multigrid rests on), on both the rupture and the
        reformation boundary, where the Reynolds-condition sweeps (:mod:`shaftline.film.relaxation`)
        would move the reformation boundary to the Reynolds condition's. Stops early once a sweep
        leaves the set unchanged. The sweeps are compiled (:mod:`shaftline.film._relaxation_kernel`):
        in numpy, each colour a dozen operations on the whole grid, they cost 0.6-1 ms on 100 x 60.
        """
        from shaftline.film._relaxation_kernel import jfo_gauss_seidel_sweeps  # imports numba

        fixed = self.fixed
        u = np.where(fixed, 0.0, unknown).astype(np.float64, order="C")
        jfo_gauss_seidel_sweeps(
            u,
            np.ascontiguousarray(stencil.c_theta, dtype=np.float64),
            np.ascontiguousarray(stencil.c_z, dtype=np.float64),
            np.ascontiguousarray(stencil.couette_face, dtype=np.float64),
            np.ascontiguousarray(stencil.rhs, dtype=np.float64),
            np.ascontiguousarray(stencil_diagonal(stencil), dtype=np.float64),
            np.ascontiguousarray(fixed, dtype=np.bool_),
            np.ascontiguousarray(np.where(fixed, self.fixed_pressure, 0.0), dtype=np.float64),
            int(self.options.prediction_sweeps if sweeps is None else sweeps),
        )
        return (u < 0.0) & ~fixed

    def start_from_guess(self, stencil: Stencil, film: np.ndarray, guess: np.ndarray) -> np.ndarray | None:
        """The set of :meth:`relaxed_set` from a guess of the unknown (``P``, or ``-s`` where
        cavitated: a coarse JFO solution prolonged, which changes sign on both boundaries)."""
        return self.relaxed_set(stencil, guess)

    def trial_guess(self, relative: np.ndarray, step: np.ndarray, response: np.ndarray) -> np.ndarray | None:
        """None: a warm start's set is predicted by a chord step of the last factor (:meth:`solve`)."""
        return None

    def film_residual_change(self, solution: CavitationSolution, film_change: np.ndarray) -> np.ndarray | None:
        """The voids ride on the Couette flux, whose change moves them too: ``-s_k dq_k + s_w dq_w``
        (the exact linearisation, docs/theory.md Eq. C4)."""
        assert isinstance(solution, JfoSolution)
        d_face = self.nodes.d_z * 0.5 * (film_change + np.roll(film_change, -1, axis=1))
        return void_transport(d_face, solution.void)

    def pressure_response(
        self, stencil: Stencil, solution: CavitationSolution, residual_changes: np.ndarray
    ) -> np.ndarray:
        """:meth:`JfoSolution.pressure_response` (one back-substitution per change)."""
        assert isinstance(solution, JfoSolution)
        return solution.pressure_response(residual_changes)

    def start_field(self, solution: CavitationSolution, relative: np.ndarray) -> np.ndarray:
        """The JFO unknown: ``P``, or ``-s`` where cavitated."""
        assert isinstance(solution, JfoSolution)
        return np.where(solution.cavitated, -solution.void, relative)

    def unsettled_residual(self, options: SolverOptions) -> float:
        """``options.jfo.unsettled_residual``."""
        return options.jfo.unsettled_residual
