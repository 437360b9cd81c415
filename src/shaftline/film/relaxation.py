"""Projected over-relaxation of the Reynolds complementarity problem (compiled).

Used only to sharpen a predicted cavitated set before the active-set iteration, never to
produce a solution: the pressure interpolated from a coarser grid places the cavitation
boundary to within a cell or two, an error of short wavelength, which a few sweeps of a
Gauss-Seidel smoother remove (the smoothing property that multigrid rests on; Brandt &
Cryer 1983 for the projected, complementarity form). The active set then starts one or two
nodes from the final one instead of tens, and needs two factorisations instead of four
(docs/theory.md Sect. 4.1, benchmarks/bench_bearing.py).
"""

from __future__ import annotations

from collections.abc import Callable
from functools import lru_cache
from typing import Any

import numpy as np

__all__ = ["PREDICTION_OMEGA", "PREDICTION_SWEEPS", "load", "projected_sor"]

#: Over-relaxation factor and sweeps of the set prediction. On the NTUA case (100 x 60) the
#: set interpolated from 50 x 30 is 50 nodes off the final one; Gauss-Seidel (1.0) leaves 23
#: after 10 sweeps, 1.5 leaves 1. Over 27 equilibria (grids 60 x 36, 100 x 60, 200 x 120;
#: three tilts, three loads) the fine-grid active-set iterations were 467 without sweeps,
#: 311 with 10 at 1.5, 304 with 10 at 1.7, 297 with 10 at 1.8, 317 with 6 at 1.7 and 303
#: with 20 at 1.5; 10 sweeps cost about half a factorisation on 100 x 60.
PREDICTION_OMEGA = 1.7
PREDICTION_SWEEPS = 10


def _sweeps(
    pressure: np.ndarray,
    c_theta: np.ndarray,
    c_z: np.ndarray,
    rhs: np.ndarray,
    fixed: np.ndarray,
    sweeps: int,
    omega: float,
) -> None:
    nz, nt = pressure.shape
    # omega / diag(A), once: a third of the sweep's time otherwise.
    step = np.empty((nz, nt))
    for j in range(nz):
        for i in range(nt):
            west = i - 1 if i > 0 else nt - 1
            diagonal = c_theta[j, i] + c_theta[j, west]
            if j > 0:
                diagonal += c_z[j - 1, i]
            if j < nz - 1:
                diagonal += c_z[j, i]
            step[j, i] = omega / diagonal
    for _ in range(sweeps):
        for j in range(nz):
            below, above = j > 0, j < nz - 1
            for i in range(nt):
                if fixed[j, i]:
                    continue
                west = i - 1 if i > 0 else nt - 1
                east = i + 1 if i < nt - 1 else 0
                inflow = rhs[j, i] + c_theta[j, i] * pressure[j, east] + c_theta[j, west] * pressure[j, west]
                if below:
                    inflow += c_z[j - 1, i] * pressure[j - 1, i]
                if above:
                    inflow += c_z[j, i] * pressure[j + 1, i]
                value = (1.0 - omega) * pressure[j, i] + step[j, i] * inflow
                pressure[j, i] = value if value > 0.0 else 0.0


@lru_cache(maxsize=1)
def load() -> Callable[..., Any]:
    """The compiled sweep kernel, loaded from numba's cache (or compiled) on first use.

    numba is imported here, not with the module: importing it and loading the kernel take
    0.3-0.7 s once per process, which a command that solves no film (``--version``, an
    input error) should not pay. The process pool's fork server calls this before it forks
    its workers (:mod:`shaftline._compiled`), so they start with the kernel loaded."""
    from numba import njit

    return njit(cache=True)(_sweeps)


def projected_sor(
    pressure: np.ndarray,
    c_theta: np.ndarray,
    c_z: np.ndarray,
    rhs: np.ndarray,
    fixed: np.ndarray,
    sweeps: int = PREDICTION_SWEEPS,
    omega: float = PREDICTION_OMEGA,
) -> np.ndarray:
    """``sweeps`` projected SOR sweeps of ``A P = b, P >= 0`` from ``pressure`` (a new array).

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
        Lexicographic sweeps over the grid (theta periodic).
    omega : float
        Over-relaxation factor, in (0, 2).

    Returns
    -------
    ndarray (nz, nt)
        The relaxed pressure, >= 0 on the free nodes.
    """
    out = np.array(pressure, dtype=float, copy=True)
    load()(
        out,
        np.ascontiguousarray(c_theta, dtype=float),
        np.ascontiguousarray(c_z, dtype=float),
        np.ascontiguousarray(rhs, dtype=float),
        np.ascontiguousarray(fixed, dtype=np.bool_),
        int(sweeps),
        float(omega),
    )
    return out
