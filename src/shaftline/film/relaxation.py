"""Projected over-relaxation of the Reynolds complementarity problem, red-black ordered.

Used only to sharpen a predicted cavitated set before the active-set iteration, never to
produce a solution: the pressure interpolated from a coarser grid places the cavitation
boundary to within a cell or two, an error of short wavelength, which a few sweeps of a
Gauss-Seidel smoother remove (the smoothing property that multigrid rests on; Brandt &
Cryer 1983 for the projected, complementarity form). The active set then starts one or two
nodes from the final one instead of tens, and needs two factorisations instead of four
(docs/theory.md Sect. 4.1, benchmarks/bench_bearing.py).

The nodes are coloured so that no two neighbours share a colour — red and black, (i + j)
even or odd, and on a grid with an odd number of columns the last column (a neighbour of the
first across theta = 0) in two colours of its own — and all nodes of one colour are updated
at once, as one sparse product with the rows of that colour: Gauss-Seidel in that order,
without a loop over nodes in Python and without a compiled kernel (numba's import and cache
load cost 0.6-1.5 s per process, more than a thousand sweeps here).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import scipy.sparse as sp

__all__ = ["PREDICTION_OMEGA", "PREDICTION_SWEEPS", "Relaxation", "projected_sor"]

#: Over-relaxation factor and sweeps of the set prediction. On the NTUA case (100 x 60) the
#: set interpolated from 50 x 30 is 50 nodes off the final one; ten red-black sweeps leave
#: 0-2 at 1.5-1.8 (9, 3 and 8 after six). Over 27 equilibria (grids 60 x 36, 100 x 60,
#: 200 x 120; three tilts, three loads) the fine-grid active-set iterations fell from 467
#: without sweeps to about 300 with ten. Ten sweeps cost about half a factorisation there.
PREDICTION_OMEGA = 1.7
PREDICTION_SWEEPS = 10


@dataclass(frozen=True, eq=False)
class _Colour:
    start: int  # this colour's free nodes are ``order[start:stop]``
    stop: int
    columns: np.ndarray  # CSR column indices of their neighbours, in the colour-major order
    links: np.ndarray  # which conductance each entry takes (theta links, then z links)
    indptr: np.ndarray


class Relaxation:
    """Red-black projected SOR on one grid with its fixed nodes (kept by the solver).

    The free nodes are numbered colour by colour (``order``), so that each colour's pressures
    are one contiguous slice, updated in place: no gather or scatter per half-sweep.

    Parameters
    ----------
    shape : (int, int)
        (axial, circumferential) nodes; theta is periodic.
    fixed : ndarray of bool (nz, nt)
        Nodes whose pressure is held (never updated).
    """

    def __init__(self, shape: tuple[int, int], fixed: np.ndarray) -> None:
        nz, nt = shape
        size = nz * nt
        node = np.arange(size).reshape(nz, nt)
        a = np.concatenate([node.ravel(), node[:-1].ravel()])
        b = np.concatenate([np.roll(node, -1, axis=1).ravel(), node[1:].ravel()])
        link = np.arange(a.size)
        rows, columns, links = np.concatenate([a, b]), np.concatenate([b, a]), np.concatenate([link, link])
        j, i = np.divmod(np.arange(size), nt)
        colour = (i + j) % 2
        if nt % 2:
            last = i == nt - 1
            colour[last] = 2 + j[last] % 2
        free = ~np.asarray(fixed, dtype=bool).ravel()
        # Colour-major order: each colour's free nodes, then the fixed nodes (never updated).
        groups = [np.flatnonzero((colour == k) & free) for k in range(int(colour.max()) + 1)]
        order = np.concatenate([*groups, np.flatnonzero(~free)])
        place = np.empty(size, dtype=np.int64)
        place[order] = np.arange(size)
        colours = []
        start = 0
        for nodes in groups:
            row_of = np.full(size, -1)
            row_of[nodes] = np.arange(nodes.size)
            keep = row_of[rows] >= 0
            row, column, which = row_of[rows[keep]], place[columns[keep]], links[keep]
            sort = np.lexsort((column, row))
            indptr = np.zeros(nodes.size + 1, dtype=np.int64)
            np.cumsum(np.bincount(row, minlength=nodes.size), out=indptr[1:])
            colours.append(_Colour(start, start + nodes.size, column[sort], which[sort], indptr))
            start += nodes.size
        self.shape = (nz, nt)
        self.size = size
        self.order = order
        self._colours = tuple(colours)
        self._neighbours = tuple(
            sp.csr_matrix((np.zeros(c.links.size), c.columns, c.indptr), shape=(c.stop - c.start, size))
            for c in colours
        )

    def sweep(
        self,
        pressure: np.ndarray,
        c_theta: np.ndarray,
        c_z: np.ndarray,
        rhs: np.ndarray,
        sweeps: int = PREDICTION_SWEEPS,
        omega: float = PREDICTION_OMEGA,
    ) -> np.ndarray:
        """``sweeps`` projected SOR sweeps of ``A P = b, P >= 0`` from ``pressure`` (a new
        array); see :func:`projected_sor`."""
        order = self.order
        conductance = np.concatenate([c_theta.ravel(), c_z.ravel()])
        diagonal = c_theta + np.roll(c_theta, 1, axis=1)
        diagonal[:-1] += c_z
        diagonal[1:] += c_z
        step = (omega / diagonal.ravel())[order]
        b = rhs.ravel()[order]
        x = np.array(pressure, dtype=float).ravel()[order]
        parts = []
        for c, neighbours in zip(self._colours, self._neighbours, strict=True):
            # The kept matrices' values refilled: building scipy matrices per call costs more
            # than the sweeps' arithmetic on these grids.
            neighbours.data[:] = conductance[c.links]
            parts.append((x[c.start : c.stop], neighbours, b[c.start : c.stop], step[c.start : c.stop]))
        keep = 1.0 - omega
        zero = x <= 0.0
        for _ in range(int(sweeps)):
            for mine, neighbours, inflow, scale in parts:
                change = neighbours @ x
                change += inflow
                change *= scale
                mine *= keep
                mine += change
                np.maximum(mine, 0.0, out=mine)
            # Only the set of zero nodes is wanted: once a sweep leaves it unchanged, the
            # remaining error is smooth and further sweeps move the set by little.
            now = x <= 0.0
            if np.array_equal(now, zero):
                break
            zero = now
        out = np.empty(self.size)
        out[order] = x
        return out.reshape(self.shape)


def projected_sor(
    pressure: np.ndarray,
    c_theta: np.ndarray,
    c_z: np.ndarray,
    rhs: np.ndarray,
    fixed: np.ndarray,
    sweeps: int = PREDICTION_SWEEPS,
    omega: float = PREDICTION_OMEGA,
) -> np.ndarray:
    """``sweeps`` red-black projected SOR sweeps of ``A P = b, P >= 0`` from ``pressure``.

    Parameters
    ----------
    pressure : ndarray (nz, nt)
        Starting dimensionless pressure, with the fixed nodes' values.
    c_theta, c_z, rhs : ndarray
        The stencil (:class:`shaftline.film.reynolds.Stencil`): link conductances and
        right-hand side.
    fixed : ndarray of bool (nz, nt)
        Nodes whose pressure is held.
    sweeps : int
        Sweeps over every colour.
    omega : float
        Over-relaxation factor, in (0, 2).

    Returns
    -------
    ndarray (nz, nt)
        The relaxed pressure, >= 0 on the free nodes.

    Examples
    --------
    One free node between two held at 1 (unit links, no source) relaxes to their mean:

    >>> import numpy as np
    >>> fixed = np.array([[True], [False], [True]])
    >>> out = projected_sor(np.array([[1.0], [0.0], [1.0]]), np.zeros((3, 1)), np.ones((2, 1)),
    ...                     np.zeros((3, 1)), fixed, sweeps=1, omega=1.0)
    >>> out.ravel().tolist()
    [1.0, 1.0, 1.0]
    """
    return Relaxation(np.shape(pressure), fixed).sweep(pressure, c_theta, c_z, rhs, sweeps, omega)
