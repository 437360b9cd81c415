"""Mass-conserving (Jakobsson-Floberg-Olsson) cavitation on the Reynolds grid.

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
"""

from __future__ import annotations

import weakref
from dataclasses import dataclass, field
from functools import lru_cache
from typing import Generic, TypeVar

import numpy as np
import scipy.sparse as sp
import scipy.sparse.linalg as spla

from shaftline.film import reynolds
from shaftline.film.elastic import grid_splu
from shaftline.film.reynolds import (
    MAX_ACTIVE_SET_ITERATIONS,
    ReynoldsConvergenceError,
    ReynoldsSolution,
    ReynoldsSolver,
    Stencil,
    apply_operator,
    build_stencil,
    stencil_diagonal,
)

__all__ = ["JfoSolution", "jfo_residual", "relaxed_set", "solve_jfo", "void_transport"]

#: Relative tolerance of the set switches: a node enters the cavitated set when its pressure
#: is below ``-SWITCH_TOLERANCE * max|P|`` and leaves it when its void fraction is below
#: ``-SWITCH_TOLERANCE`` (round-off of the linear solve, not a modelling tolerance).
SWITCH_TOLERANCE = 1e-12

_T = TypeVar("_T")


class _PerSolver(Generic[_T]):
    """Values attached to live solvers: solver state of one process, never pickled.

    Keyed by identity and dropped when the solver is collected, so that a solver needs to be
    neither hashable nor to carry attributes of this module.
    """

    def __init__(self) -> None:
        self._values: dict[int, _T] = {}
        self._watched: set[int] = set()

    def has(self, solver: ReynoldsSolver) -> bool:
        return id(solver) in self._values

    def get(self, solver: ReynoldsSolver) -> _T | None:
        return self._values.get(id(solver))

    def set(self, solver: ReynoldsSolver, value: _T) -> None:
        key = id(solver)
        if key not in self._watched:
            self._watched.add(key)
            weakref.finalize(solver, self._forget, key)
        self._values[key] = value

    def pop(self, solver: ReynoldsSolver) -> None:
        self._values.pop(id(solver), None)

    def _forget(self, key: int) -> None:
        self._values.pop(key, None)
        self._watched.discard(key)


@dataclass(frozen=True, eq=False)
class _JfoPattern:
    """The periodic 5-point pattern in CSC form with, per stored entry, where its value comes from."""

    indptr: np.ndarray
    indices: np.ndarray
    row: np.ndarray
    col: np.ndarray
    off: np.ndarray  # off-diagonal entry
    source: np.ndarray  # index into the concatenation (diag, c_theta, c_z), all flattened
    downstream: np.ndarray  # theta-link entry whose row is the node east of its column


@lru_cache(maxsize=8)
def _jfo_pattern(nz: int, nt: int) -> _JfoPattern:
    n = nz * nt
    node = np.arange(n).reshape(nz, nt)
    east = np.roll(node, -1, axis=1).ravel()
    a_theta, a_z = node.ravel(), node[:-1].ravel()
    b_z = node[1:].ravel()
    rows = np.concatenate([np.arange(n), a_theta, east, a_z, b_z])
    cols = np.concatenate([np.arange(n), east, a_theta, b_z, a_z])
    z_link = np.arange(a_z.size) + 2 * n
    source = np.concatenate([np.arange(n), a_theta + n, a_theta + n, z_link, z_link])
    downstream = np.concatenate([np.zeros(2 * n, bool), np.ones(n, bool), np.zeros(2 * a_z.size, bool)])
    slots = sp.csc_matrix((np.arange(rows.size) + 1.0, (rows, cols)), shape=(n, n))
    slots.sort_indices()
    order = slots.data.astype(int) - 1
    return _JfoPattern(
        indptr=slots.indptr,
        indices=slots.indices,
        row=rows[order],
        col=cols[order],
        off=rows[order] != cols[order],
        source=source[order],
        downstream=downstream[order],
    )


@dataclass(eq=False)
class JfoSolution(ReynoldsSolution):
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
    # Weak: the solver keeps one factor alive at a time (that of its newest solution), so a
    # solution kept beside newer ones costs no memory; it refactorises if asked after them.
    _factor: weakref.ref[_Factor] | None = field(default=None, repr=False)

    def factor(self) -> _Factor:
        """LU factor of the Jacobian ``dR/du`` on the converged set (rebuilt if released)."""
        factor = None if self._factor is None else self._factor()
        if factor is None:
            factor = _factorise(self.stencil, self.cavitated, self.fixed, stencil_diagonal(self.stencil))
            self._factor = weakref.ref(factor)
            _FACTORS.append(factor)  # kept like the newest solver factor, until the next solve
            del _FACTORS[:-1]
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
    """``dR/du`` on the set ``cavitated``: values in the fixed CSC pattern of :func:`_jfo_pattern`."""
    pattern = _jfo_pattern(*fixed.shape)
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


def _jacobian(stencil: Stencil, cavitated: np.ndarray, fixed: np.ndarray, diag: np.ndarray) -> sp.csc_matrix:
    """``dR/du`` on the set ``cavitated`` as a sparse matrix, zeros of the pattern kept (for checks)."""
    pattern = _jfo_pattern(*fixed.shape)
    n = fixed.size
    values = _jacobian_values(stencil, cavitated, fixed, diag)
    return sp.csc_matrix((values, pattern.indices, pattern.indptr), shape=(n, n))


@dataclass(frozen=True, eq=False)
class _Factor:
    """LU factor of a Jacobian, of its rows and columns in ``order`` (None: grid order)."""

    lu: spla.SuperLU
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
        Entry of the :func:`_jfo_pattern` values at each entry of the permuted pattern (CSC).
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
    def of(cls, lu: spla.SuperLU, cavitated: np.ndarray) -> _Ordering:
        """The order SuperLU chose for ``lu``, the factor of the set ``cavitated`` (grid node
        ``k`` eliminated ``perm_c[k]``-th)."""
        pattern = _jfo_pattern(*cavitated.shape)
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

    def suits(self, cavitated: np.ndarray) -> bool:
        """Whether the order may serve the set ``cavitated`` (:data:`ORDERING_SET_CHANGE`)."""
        if cavitated.shape != self.cavitated.shape:
            return False
        return int(np.count_nonzero(cavitated != self.cavitated)) <= ORDERING_SET_CHANGE * self.boundary


#: A kept elimination order serves a later set of its grid that differs from the set it was
#: found for in at most this share of that set's boundary nodes; a set further off is ordered
#: afresh (and its order kept). The sets of one equilibrium differ along their boundaries, by
#: 13 and 26 nodes on the NTUA case (100 x 60 and 200 x 120, boundaries of 226 and 456 nodes),
#: and an order kept across its six sets factorises each in 2.2-3.1 ms against 3.1-3.3 ms ordered
#: afresh (the minimum-degree ordering costs a third of a factorisation). A zone moved round the
#: bore (another load direction) is another graph: kept there, the order gave 10-23 times a
#: fresh order's fill and 20-40 times its time (81 x 240, 161 x 240), and sets 1.7-2 % of the
#: nodes off still 1.5-2.3 times (review). With this share, 20 equilibria over load directions
#: and magnitudes (81 x 120, 161 x 240) keep every fine factor within 1.06 times a fresh
#: order's fill, warm starts across 90 degrees (81 x 240) within 1.18 times.
ORDERING_SET_CHANGE = 0.25
#: ... and while its factors hold at most this many times the entries of that set's factor: the
#: factor past it is used, and the next set ordered afresh.
ORDERING_FILL_GROWTH = 1.2


def _factorise(
    stencil: Stencil, cavitated: np.ndarray, fixed: np.ndarray, diag: np.ndarray, solver: ReynoldsSolver | None = None
) -> _Factor:
    """LU of the Jacobian on ``cavitated``, in the elimination order kept for ``solver``'s grid
    when it suits the set (:data:`ORDERING_SET_CHANGE`), else in a fresh order, then kept."""
    values = _jacobian_values(stencil, cavitated, fixed, diag)
    ordering = None if solver is None else _ORDERINGS.get(solver)
    if ordering is None or not ordering.suits(cavitated):
        factor = _factorise_values(values, fixed.shape)
        if solver is not None:
            _ORDERINGS.set(solver, _Ordering.of(factor.lu, cavitated))
        return factor
    factor = _factorise_ordered(values, ordering)
    if solver is not None and factor.lu.nnz > ORDERING_FILL_GROWTH * ordering.fill:
        _ORDERINGS.pop(solver)
    return factor


def _splu(matrix: sp.csc_matrix, ordering: str) -> spla.SuperLU:
    """:func:`~shaftline.film.elastic.grid_splu` of a Jacobian (diagonal pivots, see
    :func:`_factorise_values`), a singular one (a whole circumferential line cavitated) raised
    as :class:`ReynoldsConvergenceError`."""
    try:
        return grid_splu(matrix, ordering, pivot_threshold=0.1)
    except RuntimeError as exc:
        raise ReynoldsConvergenceError(f"JFO Jacobian is singular ({exc})") from None


def _without_zeros(values: np.ndarray, indices: np.ndarray, indptr: np.ndarray) -> sp.csc_matrix:
    """The CSC matrix of ``values`` on the pattern (``indices``, ``indptr``), zero entries dropped."""
    n = indptr.size - 1
    kept = values != 0.0
    counts = np.add.reduceat(kept.astype(np.intp), indptr[:-1])  # every column keeps its diagonal
    return sp.csc_matrix((values[kept], indices[kept], np.concatenate([[0], np.cumsum(counts)])), shape=(n, n))


def _factorise_values(values: np.ndarray, shape: tuple[int, int]) -> _Factor:
    """LU of the Jacobian with ``values`` in the pattern of :func:`_jfo_pattern` for ``shape``.

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
    pattern = _jfo_pattern(*shape)
    return _Factor(_splu(_without_zeros(values, pattern.indices, pattern.indptr), "MMD_AT_PLUS_A"))


def _factorise_ordered(values: np.ndarray, ordering: _Ordering) -> _Factor:
    """LU of the Jacobian with ``values`` (pattern order) in a kept elimination order: rows and
    columns permuted to it, zeros dropped, and SuperLU told to keep that order (``NATURAL``)."""
    matrix = _without_zeros(values[ordering.take], ordering.indices, ordering.indptr)
    return _Factor(_splu(matrix, "NATURAL"), ordering.order)


#: Last solution of each solver in use and its factor, which predict the set of the next warm
#: start; dropped when the next solve starts, so that one fine factor is alive at a time.
_LAST: _PerSolver[tuple[JfoSolution, _Factor]] = _PerSolver()
#: A factor rebuilt for an older solution (at most one).
_FACTORS: list[_Factor] = []
#: The elimination order kept for each solver's grid (:class:`_Ordering`).
_ORDERINGS: _PerSolver[_Ordering] = _PerSolver()


def forget(solver: ReynoldsSolver) -> None:
    """Drop what this module keeps for ``solver`` (its last solution and factor, its elimination
    order), so that its next JFO solutions round the same whatever it solved before."""
    _LAST.pop(solver)
    _ORDERINGS.pop(solver)


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


#: Red-black nonlinear Gauss-Seidel sweeps that sharpen a JFO set interpolated from a coarser
#: grid (:func:`relaxed_set`). On the NTUA case (100 x 60) the set prolonged from the 50 x 30
#: equilibrium is 126 nodes off the final one, mostly along the reformation boundary where it
#: runs obliquely near the edges; one sweep leaves 33, two 20, five 12.
PREDICTION_SWEEPS = 5


def relaxed_set(
    solver: ReynoldsSolver, stencil: Stencil, unknown: np.ndarray, sweeps: int = PREDICTION_SWEEPS
) -> np.ndarray:
    """Cavitated set left by ``sweeps`` red-black nonlinear Gauss-Seidel sweeps of the JFO
    equation ``R(u) = 0`` (C3) from a guess of the unknown (nz, nt; ``P`` or ``-s``).

    With its neighbours held, a node's residual is continuous, piecewise linear and increasing
    in its own unknown (slope ``diag(A)`` for ``u >= 0``, ``q`` for ``u < 0``), so it has one
    root: ``u = -R0 / diag(A)`` when the residual at ``u = 0``, ``R0``, is negative (full
    film), else ``u = -R0 / q`` (cavitated). Nodes of one colour share no neighbour, so the
    order within a colour does not matter. The sweeps remove the short-wavelength error of an interpolated
    set (the smoothing property multigrid rests on), on both the rupture and the reformation
    boundary, where the Reynolds-condition sweeps (:mod:`shaftline.film.relaxation`) would
    move the reformation boundary to the Reynolds condition's. Stops early once a sweep leaves
    the set unchanged. The sweeps are compiled (:mod:`shaftline.film._relaxation_kernel`): in
    numpy, each colour a dozen operations on the whole grid, they cost 0.6-1 ms on 100 x 60.
    """
    from shaftline.film._relaxation_kernel import jfo_gauss_seidel_sweeps  # imports numba

    fixed = solver.fixed
    u = np.where(fixed, 0.0, unknown).astype(np.float64, order="C")
    jfo_gauss_seidel_sweeps(
        u,
        np.ascontiguousarray(stencil.c_theta, dtype=np.float64),
        np.ascontiguousarray(stencil.c_z, dtype=np.float64),
        np.ascontiguousarray(stencil.couette_face, dtype=np.float64),
        np.ascontiguousarray(stencil.rhs, dtype=np.float64),
        np.ascontiguousarray(stencil_diagonal(stencil), dtype=np.float64),
        np.ascontiguousarray(fixed, dtype=np.bool_),
        np.ascontiguousarray(np.where(fixed, solver.fixed_pressure, 0.0), dtype=np.float64),
        int(sweeps),
    )
    return (u < 0.0) & ~fixed


def solve_jfo(
    solver: ReynoldsSolver,
    stencil: Stencil,
    film: np.ndarray,
    initial_cavitated: np.ndarray | None = None,
    remember: bool = True,
    settle: bool = True,
) -> JfoSolution:
    """Mass-conserving cavitation by semi-smooth Newton on ``u`` (``P`` or ``-s`` per node).

    Parameters
    ----------
    solver : ReynoldsSolver
        Grid, fixed nodes and their pressures.
    stencil : Stencil
        Conductances, Couette fluxes and right-hand side of the film.
    film : ndarray (nz, nt)
        Dimensionless film H = h / c.
    initial_cavitated : ndarray of bool, optional
        Cavitated set of a previous JFO solution of ``solver`` to start from (through the
        chord-step predictor when it is the set of the last solution); without it the set
        predicted by the JFO solution on the grid halved each way, or on a grid too small
        to halve the set of the Reynolds (Swift-Stieber) solution.
    remember : bool
        Keep the solution as the predictor of the next warm start of ``solver`` (the
        coarse grids of a cold start, never warm-started, do not).
    settle : bool
        False: stop at the first set within :data:`~shaftline.film.reynolds.UNSETTLED_MAX_NODES`
        nodes of settling, that set's solution (pressure and void fraction clipped at zero)
        marked ``settled=False``, its factor that set's Jacobian (a Newton iterate far from
        the equilibrium, or a coarse grid's prediction: each set costs an LU factorisation).
        Solving again from its set finishes it (the chord-step predictor leads to the next set).

    Returns
    -------
    JfoSolution
        Dimensionless pressure (fixed values on fixed nodes, 0 where cavitated), film fraction
        ``1 - s`` (clipped to [0, 1]), cavitated set, active-set iterations on this grid
        (plus those of a Reynolds start) and the means to linearise it.
    """
    fixed = solver.fixed
    iterations = 0
    if initial_cavitated is None:
        nested = _nested_start(solver, stencil, film)
        if nested is None:
            start = solver.solve(stencil, film, "reynolds")
            cavitated = start.cavitated & ~fixed
            iterations = start.iterations
        else:
            cavitated = nested
    else:
        cavitated = np.asarray(initial_cavitated, dtype=bool) & ~fixed
        last = _LAST.get(solver)
        if last is not None and np.array_equal(last[0].cavitated, cavitated):
            cavitated = _predicted_set(last[0], last[1], stencil)
    _LAST.pop(solver)
    _FACTORS.clear()
    diag = stencil_diagonal(stencil)
    boundary = np.where(fixed, solver.fixed_pressure, 0.0)
    rhs = stencil.rhs - apply_operator(stencil.c_theta, stencil.c_z, boundary)
    rhs = np.where(fixed, diag * solver.fixed_pressure, rhs).ravel()
    factor: _Factor | None = None
    for _ in range(MAX_ACTIVE_SET_ITERATIONS):
        factor = None  # free the last factor before the next is made: one factor at a time
        factor = _factorise(stencil, cavitated, fixed, diag, solver)
        unknown = factor.solve(rhs).reshape(solver.shape)
        iterations += 1
        pressure = np.where(cavitated, 0.0, unknown)
        scale = max(float(np.abs(pressure).max()), 1e-300)
        enter = ~(fixed | cavitated) & (unknown < -SWITCH_TOLERANCE * scale)
        leave = cavitated & (unknown > SWITCH_TOLERANCE)
        settled = not enter.any() and not leave.any()
        if settled or (not settle and int(np.count_nonzero(enter | leave)) <= reynolds.UNSETTLED_MAX_NODES):
            void = np.where(cavitated, -unknown, 0.0)
            if not settled:  # the few nodes on the wrong side, at zero
                pressure, void = np.maximum(pressure, 0.0), np.maximum(void, 0.0)
            fraction = np.clip(1.0 - void, 0.0, 1.0)
            solution = JfoSolution(
                pressure, fraction, cavitated, iterations, void, fixed, stencil, weakref.ref(factor), settled=settled
            )
            if remember:
                _LAST.set(solver, (solution, factor))
            return solution
        cavitated = (cavitated & ~leave) | enter
    raise ReynoldsConvergenceError("JFO active set did not settle")


def _nested_start(solver: ReynoldsSolver, stencil: Stencil, film: np.ndarray) -> np.ndarray | None:
    """Cavitated set predicted by the JFO solution of the same film on the grid halved each way.

    The coarse unknown ``u`` (``P`` in the full film, ``-s`` where cavitated) changes sign on
    both the rupture and the reformation boundary; interpolated bilinearly onto the fine
    grid it places them to within a coarse cell, and the sweeps of :func:`relaxed_set` on this
    grid remove most of that error. Recursive down to the coarsest grid, which starts from the
    Reynolds condition.
    """
    coarse = solver.coarse_grid()
    if coarse is None:
        return None
    d_theta, d_z = solver.d_theta, solver.d_z
    # The squeeze part of the right-hand side, (2/omega) dH/dt per cell, restricted with the film.
    rate = (np.roll(stencil.couette_face, 1, axis=1) - stencil.couette_face - stencil.rhs) / (d_theta * d_z)

    film_c = coarse.restrict(film)
    rate_c = coarse.restrict(rate) if np.any(rate) else None
    solver_c = coarse.solver
    stencil_c = build_stencil(film_c, solver_c.d_theta, solver_c.d_z, rate_c)
    solution = solve_jfo(solver_c, stencil_c, film_c, remember=False, settle=False)  # a prediction only
    indicator = np.where(solution.cavitated, -solution.void, solution.pressure)
    indicator = np.where(solver_c.fixed, 0.0, indicator)
    return relaxed_set(solver, stencil, coarse.prolong(indicator))
