"""The Reynolds condition's sparse LDL^T factors, kept on a node set for the sets around it.

A factor of the film operator on the free nodes costs a fill-reducing ordering, a symbolic
analysis and a numeric factorisation; the active-set iteration, the Newton trials of an
equilibrium and nearby films meet free sets that differ along their cavitation boundary by a
few cells. A :class:`NodeSetFactor` is the factor of a node set holding the free nodes and a
margin around them: every set inside it reuses the ordering and the analysis, and a set a few
nodes from the factorised one, on the same film, is solved by a bordered correction of the
kept factor (docs/theory.md Sect. 4.1). qdldl (LDL^T with AMD) does the factorisations.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

import numpy as np

if TYPE_CHECKING:
    from shaftline.film.cavitation.base import SolverCounts
    from shaftline.film.stencil import Stencil, SymmetricPattern

__all__ = ["NodeSetFactor"]


@dataclass(eq=False)
class NodeSetFactor:
    """qdldl factor of the Reynolds operator on a kept node set, for a free set inside it.

    Attributes
    ----------
    nodes : ndarray of bool (n,)
        The node set (flat grid order).
    slots : ndarray of bool
        Slots of the full pattern with both ends in the node set.
    slot_diagonal : ndarray of bool
        Of those slots, the diagonal ones.
    slot_row, slot_col : ndarray of int
        Grid nodes at both ends of those slots.
    structure : tuple
        ``(indices, indptr, size)`` of the upper triangle of ``A[nodes, nodes]`` (CSC).
    index : ndarray of int (n,)
        Each grid node's position in the node set's numbering (meaningful on its nodes).
    solver : qdldl.Solver or None
        The factor, with the ordering and symbolic analysis of the node set.
    matrix : scipy.sparse.csc_matrix or None
        The node set's matrix, its values refilled for each numeric factorisation.
    free, stencil
        The free set and film last factorised.
    """

    nodes: np.ndarray
    slots: np.ndarray
    slot_diagonal: np.ndarray
    slot_row: np.ndarray
    slot_col: np.ndarray
    structure: tuple[np.ndarray, np.ndarray, int]
    index: np.ndarray
    solver: Any = None
    matrix: Any = None
    free: np.ndarray | None = None
    stencil: Stencil | None = None
    #: The free set the numeric factor is of, when ``free`` differs from it by a few switched
    #: nodes whose change the factor carries as a bordered correction (:meth:`switch`).
    factored_free: np.ndarray | None = None
    correction: tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray, np.ndarray, np.ndarray] | None = None

    @classmethod
    def around(
        cls,
        pattern: SymmetricPattern,
        free: np.ndarray,
        shape: tuple[int, int],
        margin: int,
        never_free: np.ndarray | None = None,
    ) -> NodeSetFactor:
        """A node set holding ``free`` (flat bool) and ``margin`` cells around it, without the
        nodes ``never_free`` (flat bool: the fixed nodes, which no set frees; in the set they
        would only add fill, 3 % of the NTUA factorisation's time for the two edge rows)."""
        grid = free.reshape(shape)
        for _ in range(margin):
            grown = grid | np.roll(grid, 1, axis=1) | np.roll(grid, -1, axis=1)
            grown[1:] |= grid[:-1]
            grown[:-1] |= grid[1:]
            grid = grown
        nodes = grid.ravel() if never_free is None else grid.ravel() & ~never_free
        slots = nodes[pattern.slot_row] & nodes[pattern.slot_col]
        index = np.cumsum(nodes) - 1
        size = int(index[-1]) + 1
        indptr = np.zeros(size + 1, dtype=np.int64)
        np.cumsum(np.bincount(index[pattern.slot_col[slots]], minlength=size), out=indptr[1:])
        return cls(
            nodes=nodes,
            slots=slots,
            slot_diagonal=pattern.slot_kind[slots] == 0,
            slot_row=pattern.slot_row[slots],
            slot_col=pattern.slot_col[slots],
            structure=(index[pattern.slot_row[slots]], indptr, size),
            index=index,
        )

    def holds(self, free: np.ndarray, slack: float) -> bool:
        """Whether ``free`` lies inside the node set and fills at least ``1 / slack`` of it."""
        count = int(np.count_nonzero(free))
        return not (free & ~self.nodes).any() and int(self.structure[2]) <= slack * count

    def is_for(self, stencil: Stencil, free: np.ndarray) -> bool:
        """Whether the factor is that of ``stencil`` with the free set ``free``."""
        return self.stencil is stencil and self.free is not None and np.array_equal(self.free, free)

    def factorise(self, slot_values: np.ndarray, stencil: Stencil, free: np.ndarray, counts: SolverCounts) -> None:
        """Numeric factorisation for ``free`` (inside the node set); the first builds the solver.
        Counted in ``counts.factorisations``."""
        import qdldl
        import scipy.sparse as sp

        values = slot_values[self.slots].copy()
        # Held nodes inside the set are decoupled: zero links, own diagonal kept (well scaled).
        values[~self.slot_diagonal & ~(free[self.slot_row] & free[self.slot_col])] = 0.0
        self.free, self.stencil, self.correction = None, None, None
        if self.solver is None:
            indices, indptr, size = self.structure
            self.matrix = sp.csc_matrix((values, indices, indptr), shape=(size, size))
            self.solver = qdldl.Solver(self.matrix, upper=True)
        else:
            self.matrix.data[:] = values  # kept: a new scipy matrix per call costs 0.1 ms
            self.solver.update(self.matrix, upper=True)
        counts.factorisations += 1
        self.free, self.stencil, self.factored_free = free.copy(), stencil, free.copy()

    def switch(self, slot_values: np.ndarray, stencil: Stencil, free: np.ndarray, max_nodes: int) -> bool:
        """Carry a free set a few nodes from the factorised one, for the same film, as a
        bordered solve with the kept factor instead of a new factorisation.

        With ``M1`` the factorised matrix (free set ``F1``, the other nodes of the set decoupled),
        nodes ``R`` leaving the free set and ``G`` joining it, the new solution is
        ``x = M1^-1 (b - a_G x_G - e_R l)`` on the nodes free in both sets, with ``a_g`` the
        couplings of an added node to them and ``e_R`` unit vectors of the removed nodes, whose
        multipliers ``l`` hold ``x_R = 0``; the added nodes' own rows of the new matrix and
        ``x_R = 0`` give the k = |G| + |R| unknowns ``(x_G, l)`` from a k x k system (block
        elimination, Golub & Van Loan, Matrix Computations, 4th ed., Sect. 3.2.10, the
        Schur complement of the bordered system). That takes k triangular solves with the kept
        factor, against 2k for the symmetric Woodbury form of a rank-2k change. Returns False
        (nothing changed) when the film is another, a switched node lies outside the node set,
        or more than ``max_nodes`` switched.
        """
        base = self.factored_free
        if self.stencil is not stencil or base is None or self.solver is None:
            return False
        switched = free != base
        count = int(np.count_nonzero(switched))
        if count == 0 or count > max_nodes or (switched & ~self.nodes).any():
            return False
        index = self.index
        size = int(self.structure[2])
        added = np.flatnonzero(switched & free)
        removed = np.flatnonzero(switched & ~free)
        n_added = added.size
        column_of = np.full(free.size, -1)
        column_of[added] = np.arange(n_added)
        # Couplings of the added nodes: to the nodes free in both sets (a_G, by node-set row)
        # and among themselves; their diagonals.
        values = slot_values[self.slots]
        rows, cols = self.slot_row, self.slot_col
        touching = np.flatnonzero((column_of[rows] >= 0) | (column_of[cols] >= 0))
        rows, cols, values = rows[touching], cols[touching], values[touching]
        diagonal = self.slot_diagonal[touching]
        kept = free & base
        borders = np.zeros((size, n_added))
        own = np.zeros((n_added, n_added))
        for node, other in ((rows, cols), (cols, rows)):
            mine = (column_of[node] >= 0) & ~diagonal
            into = mine & kept[other]
            np.add.at(borders, (index[other[into]], column_of[node[into]]), values[into])
            among = mine & (column_of[other] >= 0)
            np.add.at(own, (column_of[node[among]], column_of[other[among]]), values[among])
        on_diagonal = diagonal & (column_of[rows] >= 0)
        own[column_of[rows[on_diagonal]], column_of[rows[on_diagonal]]] = values[on_diagonal]
        units = np.zeros((size, removed.size))
        units[index[removed], np.arange(removed.size)] = 1.0
        solved = np.column_stack([self.solver.solve(column) for column in np.hstack([borders, units]).T])
        added_at, removed_at = index[added], index[removed]
        capacitance = np.vstack(
            [np.hstack([own, np.zeros((n_added, removed.size))]) - borders.T @ solved, solved[removed_at]]
        )
        self.correction = (solved, borders, capacitance, added_at, removed_at, ~free[self.nodes])
        self.free = free.copy()
        return True

    def solve(self, rhs: np.ndarray) -> np.ndarray:
        """``x`` (flat grid) with ``A[free, free] x[free] = rhs[free]``, zero elsewhere.

        ``rhs`` must be zero off the free nodes."""
        out = np.zeros(self.nodes.size)
        local = rhs[self.nodes]
        x = self.solver.solve(local)
        if self.correction is not None:
            solved, borders, capacitance, added_at, removed_at, held = self.correction
            unknowns = np.linalg.solve(capacitance, np.concatenate([local[added_at] - borders.T @ x, x[removed_at]]))
            x = x - solved @ unknowns
            x[added_at] = unknowns[: added_at.size]
            x[held] = 0.0  # exactly, as the factor of the set itself gives (not to rounding)
        out[self.nodes] = x
        return out
