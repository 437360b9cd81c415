"""Extreme of a nodal field located between nodes by a local quadratic fit.

The smallest film and the largest pressure of a film solution fall between nodes; their
node values err by the curvature times the squared distance to the node (docs/theory.md,
"h_min and p_max between nodes"). :func:`local_extreme` fits the quadratic
``f(a, b) = f0 + g.d + d.H.d / 2`` through the 3 x 3 nodes around the extreme node (central
differences, exact for a quadratic) and returns its stationary value where that is an
extreme of the right kind inside the neighbourhood. Near an edge row, or next to a node
whose value is not a sample of the smooth field (a fixed-pressure or cavitated node), it
falls back to a 1-D fit along each direction that has both neighbours usable, and to the
node value where neither has.

Fields are indexed ``[row, column]`` = ``[z, theta]``; columns are periodic (theta), rows
are not (the bearing edges).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

#: Node values within this share of the field's largest magnitude of the extreme are a tie.
TIE_SHARE = 1e-12


@dataclass(frozen=True)
class Extreme:
    """Located extreme of a nodal field.

    Attributes
    ----------
    value : float
        Fitted extreme value (the node value where no fit applies), in the field's unit.
    row, column : float
        Its position in fractional node indices: ``row`` along the rows (axial), within
        ``[0, rows - 1]``; ``column`` along the periodic columns (circumferential), within
        one step of the extreme node's index (not wrapped).
    fit : str
        ``"2d"``, ``"1d"`` (one or two separate 1-D fits) or ``"node"``.
    """

    value: float
    row: float
    column: float
    fit: str


def local_extreme(values: np.ndarray, usable: np.ndarray | None = None, maximum: bool = False) -> Extreme:
    """The smallest (or, with ``maximum``, largest) value of ``values`` between nodes.

    Parameters
    ----------
    values : ndarray (rows, columns)
        Nodal field, periodic along the columns.
    usable : ndarray of bool (rows, columns), optional
        Nodes whose values are samples of the smooth field (all by default). The fit uses
        only these; the extreme node itself is always used.
    maximum : bool
        Locate the largest value instead of the smallest.

    Returns
    -------
    Extreme
        Never beyond the extreme node value (a fitted maximum below the node value, or a
        minimum above it, is impossible: the node value is kept then) and never outside the
        3 x 3 neighbourhood (no extrapolation).
    """
    sign = -1.0 if maximum else 1.0
    f = sign * np.asarray(values, dtype=float)  # locate the minimum of f
    rows, columns = f.shape
    # Ties to rounding (a film uniform along the bearing, an aligned bore) go to the first node
    # in storage order, so that the reported place does not hop with the last bit.
    lowest = float(f.min())
    tie = TIE_SHARE * max(abs(lowest), float(np.abs(f).max()))
    j, i = (int(k) for k in np.unravel_index(np.argmax(f <= lowest + tie), f.shape))
    ok = np.ones(f.shape, dtype=bool) if usable is None else np.asarray(usable, dtype=bool)
    f0 = float(f[j, i])
    right, left = (i + 1) % columns, (i - 1) % columns
    # A direction is usable when both neighbours along it are (and exist: rows are not periodic).
    along_theta = bool(ok[j, right] and ok[j, left])
    along_z = bool(0 < j < rows - 1 and ok[j + 1, i] and ok[j - 1, i])
    g_theta = 0.5 * (f[j, right] - f[j, left]) if along_theta else 0.0
    h_theta = f[j, right] - 2.0 * f0 + f[j, left] if along_theta else 0.0
    g_z = 0.5 * (f[j + 1, i] - f[j - 1, i]) if along_z else 0.0
    h_z = f[j + 1, i] - 2.0 * f0 + f[j - 1, i] if along_z else 0.0
    if along_theta and along_z:
        corners = (j + 1, j + 1, j - 1, j - 1), (right, left, right, left)
        if bool(np.all(ok[corners])):
            c = f[corners]
            h_cross = 0.25 * (c[0] - c[1] - c[2] + c[3])
            determinant = h_theta * h_z - h_cross * h_cross
            if h_theta > 0.0 and h_z > 0.0 and determinant > 0.0:
                # Stationary point of the quadratic: H d = -g (Cramer's rule on the 2 x 2).
                d_theta = -(h_z * g_theta - h_cross * g_z) / determinant
                d_z = -(h_theta * g_z - h_cross * g_theta) / determinant
                if abs(d_theta) <= 1.0 and abs(d_z) <= 1.0:
                    value = min(f0 + 0.5 * (g_theta * d_theta + g_z * d_z), f0)
                    return Extreme(float(sign * value), float(j + d_z), float(i + d_theta), "2d")
    # 1-D fits: through three nodes with the middle one smallest the vertex lies within half a
    # step of it and below it, so these neither extrapolate nor pass the node value.
    value, d_theta, d_z, fitted = f0, 0.0, 0.0, False
    if along_theta and h_theta > 0.0:
        d_theta = -g_theta / h_theta
        value -= 0.5 * g_theta * g_theta / h_theta
        fitted = True
    if along_z and h_z > 0.0:
        d_z = -g_z / h_z
        value -= 0.5 * g_z * g_z / h_z
        fitted = True
    return Extreme(float(sign * min(value, f0)), float(j + d_z), float(i + d_theta), "1d" if fitted else "node")
