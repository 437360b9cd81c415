"""Mass-conserving (Jakobsson-Floberg-Olsson) cavitation on the Reynolds grid.

The complementarity form of Giacopini et al. (2010): each node carries either a
pressure (full film) or a void fraction ``s = 1 - film fraction`` (cavitated); the
Couette flux through a face is ``(1 - s_upstream) H_face``. Started from the
Reynolds-condition active set of :class:`~shaftline.film.reynolds.ReynoldsSolver`.
"""

from __future__ import annotations

import numpy as np
import scipy.sparse as sp
import scipy.sparse.linalg as spla

from shaftline.film.reynolds import (
    MAX_ACTIVE_SET_ITERATIONS,
    ReynoldsConvergenceError,
    ReynoldsSolution,
    ReynoldsSolver,
    Stencil,
    apply_operator,
)

__all__ = ["solve_jfo"]


def solve_jfo(solver: ReynoldsSolver, stencil: Stencil, film: np.ndarray, start: ReynoldsSolution) -> ReynoldsSolution:
    """Mass-conserving cavitation, started from the Reynolds-condition active set."""
    nz, nt = solver.shape
    n = nz * nt
    node = np.arange(n).reshape(nz, nt)
    east = np.roll(node, -1, axis=1).ravel()
    cavitated = start.cavitated.copy()
    iterations = start.iterations
    upper = solver.pattern.upper
    for _ in range(MAX_ACTIVE_SET_ITERATIONS):
        held = solver.fixed | cavitated
        values, diag = solver._masked_values(stencil, held)
        matrix = sp.csc_matrix((values, upper.indices, upper.indptr), shape=(n, n))
        strict = sp.triu(matrix, k=1)
        symmetric = (matrix + strict.T).tocsr()
        # Void-fraction columns of cavitated free nodes: a void s_k cuts the Couette outflow of
        # cell k by s_k q_k and the inflow of the downstream cell by the same amount.
        cav = np.flatnonzero(cavitated.ravel())
        q = stencil.couette_face.ravel()[cav]
        down = east[cav]
        keep_down = ~solver.fixed.ravel()[down]
        # Cavitated rows keep their coupling to pressurised neighbours: restore them.
        rows_c, cols_c, vals_c = _rows_to_pressurised(stencil, cavitated, solver.fixed, solver.shape)
        transport = sp.csr_matrix(
            (
                np.concatenate([-q, q[keep_down], vals_c]),
                (np.concatenate([cav, down[keep_down], rows_c]), np.concatenate([cav, cav[keep_down], cols_c])),
            ),
            shape=(n, n),
        )
        # Cavitated rows: zero the symmetric (held) diagonal, the transport term replaces it.
        row_scale = np.where(cavitated.ravel(), 0.0, 1.0)
        system = (sp.diags(row_scale) @ symmetric + transport).tocsc()
        boundary = np.where(solver.fixed, solver.fixed_pressure, 0.0)
        rhs = stencil.rhs - apply_operator(stencil.c_theta, stencil.c_z, boundary)
        rhs = np.where(solver.fixed, diag.reshape(solver.shape) * solver.fixed_pressure, rhs)
        unknown = spla.spsolve(system, rhs.ravel()).reshape(solver.shape)
        iterations += 1
        pressure = np.where(cavitated, 0.0, unknown)
        void = np.where(cavitated, unknown, 0.0)
        scale = max(float(np.abs(pressure).max()), 1e-300)
        enter = ~held & (pressure < -1e-12 * scale)
        leave = cavitated & (void < -1e-12)
        if not enter.any() and not leave.any():
            fraction = np.clip(1.0 - void, 0.0, 1.0)
            return ReynoldsSolution(pressure, fraction, cavitated, iterations)
        cavitated = (cavitated & ~leave) | enter
    raise ReynoldsConvergenceError("JFO active set did not settle")


def _rows_to_pressurised(
    stencil: Stencil, cavitated: np.ndarray, fixed: np.ndarray, shape: tuple[int, int]
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Entries ``-c`` coupling cavitated rows to their pressurised free neighbours."""
    nz, nt = shape
    node = np.arange(nz * nt).reshape(nz, nt)
    pressurised = ~(cavitated | fixed)
    rows, cols, vals = [], [], []
    pairs = (
        (node, np.roll(node, -1, axis=1), stencil.c_theta),
        (np.roll(node, -1, axis=1), node, stencil.c_theta),
        (node[:-1], node[1:], stencil.c_z),
        (node[1:], node[:-1], stencil.c_z),
    )
    flat_cav = cavitated.ravel()
    flat_p = pressurised.ravel()
    for a, b, coef in pairs:
        a, b, coef = a.ravel(), b.ravel(), coef.ravel()
        pick = flat_cav[a] & flat_p[b]
        rows.append(a[pick])
        cols.append(b[pick])
        vals.append(-coef[pick])
    return np.concatenate(rows), np.concatenate(cols), np.concatenate(vals)
