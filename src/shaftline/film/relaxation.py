"""Projected over-relaxation of the Reynolds complementarity problem, red-black ordered.

Used only to predict the cavitated set before the active-set iteration, never to produce a
solution, in two ways (docs/theory.md Sect. 4.1):

* On the grid being solved, a few sweeps sharpen a set interpolated from a coarser grid (or
  extrapolated by a Newton step): that set places the cavitation boundary to within a cell
  or two, an error of short wavelength, which a few sweeps of a Gauss-Seidel smoother remove
  (the smoothing property that multigrid rests on; Brandt & Cryer 1983 for the projected,
  complementarity form). The active set then starts one or two nodes from the final one
  instead of tens.
* On the coarse grids below it, sweeps alone carry the prediction from the coarsest grid
  upwards, level by level (a cascadic multigrid: each level's swept pressure, interpolated,
  starts the next; Bornemann & Deuflhard 1996, and Blum, Braess & Suttmeier 2004 for
  variational inequalities), instead of an active-set solution on each.

The sweeps are compiled (:mod:`shaftline.film._relaxation_kernel`, numba): a red-black sweep
in numpy, one sparse product per colour, cost 7-8 ns a node on 100 x 60 and far more on the
small coarse grids, where the call overhead dominates; the compiled loop costs 3 ns a node.
numba is imported when a solver first sweeps (about half a second, once per process).
"""

from __future__ import annotations

import numpy as np

__all__ = ["projected_sor"]


def projected_sor(
    pressure: np.ndarray,
    c_theta: np.ndarray,
    c_z: np.ndarray,
    rhs: np.ndarray,
    fixed: np.ndarray,
    sweeps: int,
    omega: float,
    until_settled: bool = True,
) -> np.ndarray:
    """Red-black projected SOR sweeps of ``A P = b, P >= 0`` from ``pressure``.

    Parameters
    ----------
    pressure : ndarray (nz, nt)
        Starting dimensionless pressure, with the fixed nodes' values.
    c_theta, c_z, rhs : ndarray
        The stencil (:class:`shaftline.film.stencil.Stencil`): link conductances, (nz, nt)
        round the bore (periodic) and (nz - 1, nt) along it, and right-hand side (nz, nt).
    fixed : ndarray of bool (nz, nt)
        Nodes whose pressure is held.
    sweeps : int
        Most sweeps over every colour (``ActiveSetOptions.prediction_sweeps`` where a set is
        sharpened, ``cascade_sweeps`` on the coarse grids).
    omega : float
        Over-relaxation factor, in (0, 2) (``prediction_omega``, ``cascade_omega``).
    until_settled : bool
        Stop after the first sweep that moves no node across zero: only the set of zero
        nodes is wanted, and once a sweep leaves it unchanged the remaining error is smooth,
        so further sweeps move it by little.

    Returns
    -------
    ndarray (nz, nt)
        The relaxed pressure (a new array), >= 0 on the free nodes.

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
    from shaftline.film._relaxation_kernel import projected_sor_sweeps  # imports numba

    out = np.array(pressure, dtype=np.float64, order="C")
    projected_sor_sweeps(
        out,
        np.ascontiguousarray(c_theta, dtype=np.float64),
        np.ascontiguousarray(c_z, dtype=np.float64),
        np.ascontiguousarray(rhs, dtype=np.float64),
        np.ascontiguousarray(fixed, dtype=np.bool_),
        int(sweeps),
        float(omega),
        bool(until_settled),
    )
    return out
