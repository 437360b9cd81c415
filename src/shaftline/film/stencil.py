"""The discrete Reynolds operator on the unwrapped bore and its sparsity patterns.

Dimensionless form (docs/theory.md, Sect. "Reynolds equation"): with ``H = h / c``,
``Z = z / R`` and ``P = p / p_ref``, ``p_ref = 6 eta omega (R/c)^2``,

    d/dtheta (H^3 dP/dtheta) + d/dZ (H^3 dP/dZ) = dH/dtheta + (2/omega) dH/dt.

Each node is the centre of a control volume ``dtheta x dZ``; face conductances are
``((H_a + H_b)/2)^3`` (with a rough or turbulent film's flow factors in their place). The
discrete operator ``A`` (the negative of the left-hand side) is a symmetric M-matrix;
fixed-pressure nodes (the two bearing edges, supply grooves) and cavitated nodes are removed
by masking rows and columns, which keeps one sparsity pattern for every solve, so that a
sparse factorisation reuses its symbolic analysis. Every cavitation model
(:mod:`shaftline.film.cavitation`) solves on this operator.

Only numpy is imported here; scipy.sparse when a pattern or a sparse operator is first built.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import lru_cache
from typing import TYPE_CHECKING, Any

import numpy as np

if TYPE_CHECKING:
    from shaftline.film.roughness import FilmFlow

__all__ = [
    "FullPattern",
    "Stencil",
    "SymmetricPattern",
    "apply_operator",
    "build_stencil",
    "film_operator",
    "full_pattern",
    "stencil_derivative",
    "stencil_diagonal",
    "symmetric_pattern",
]


@dataclass(frozen=True, eq=False)
class SymmetricPattern:
    """Sparsity pattern of the 5-point periodic stencil on an (nz, nt) grid: the upper triangle
    (diagonal included) that the symmetric LDL^T factors of the Reynolds condition fill."""

    nz: int
    nt: int
    upper: Any  # scipy.sparse.csc_matrix: upper triangle incl. diagonal, data = slot ids
    # For each slot of ``upper.data``: kind (0 diagonal, 1 theta-link, 2 z-link) and node ids.
    slot_kind: np.ndarray
    slot_row: np.ndarray
    slot_col: np.ndarray
    # Index of each slot's value in concat(diag(A), -c_theta, -c_z), all flattened.
    slot_source: np.ndarray


@lru_cache(maxsize=16)
def symmetric_pattern(nz: int, nt: int) -> SymmetricPattern:
    """The :class:`SymmetricPattern` of an (nz, nt) grid (memoised: a pure function of the shape)."""
    import scipy.sparse as sp

    n = nz * nt
    node = np.arange(n).reshape(nz, nt)
    east = np.roll(node, -1, axis=1)
    theta_a, theta_b = node.ravel(), east.ravel()
    z_a, z_b = node[:-1].ravel(), node[1:].ravel()
    rows = np.concatenate([np.arange(n), np.minimum(theta_a, theta_b), z_a])
    cols = np.concatenate([np.arange(n), np.maximum(theta_a, theta_b), z_b])
    kind = np.concatenate([np.zeros(n, int), np.ones(theta_a.size, int), np.full(z_a.size, 2)])
    link = np.concatenate([np.arange(n), np.arange(theta_a.size), np.arange(z_a.size)])
    slot = np.arange(rows.size)
    upper = sp.csc_matrix((slot.astype(float) + 1.0, (rows, cols)), shape=(n, n))
    upper.sort_indices()
    order = upper.data.astype(int) - 1
    return SymmetricPattern(
        nz=nz,
        nt=nt,
        upper=upper,
        slot_kind=kind[order],
        slot_row=rows[order],
        slot_col=cols[order],
        slot_source=(np.where(kind == 1, n, 0) + np.where(kind == 2, 2 * n, 0) + link)[order],
    )


def _east(field: np.ndarray) -> np.ndarray:
    """``field`` at the next column, ``np.roll(field, -1, axis=-1)`` (theta periodic), without
    np.roll's argument handling, which costs more than the copy on these grids."""
    out = np.empty_like(field)
    out[..., :-1] = field[..., 1:]
    out[..., -1] = field[..., 0]
    return out


def _west(field: np.ndarray) -> np.ndarray:
    """``field`` at the previous column, ``np.roll(field, 1, axis=-1)`` (theta periodic)."""
    out = np.empty_like(field)
    out[..., 1:] = field[..., :-1]
    out[..., 0] = field[..., -1]
    return out


@dataclass(eq=False)
class Stencil:
    """Conductances and right-hand side of the discrete Reynolds equation for one film.

    Attributes
    ----------
    c_theta : ndarray (nz, nt)
        Coefficient of the link between node (j, i) and (j, i+1).
    c_z : ndarray (nz-1, nt)
        Coefficient of the link between node (j, i) and (j+1, i).
    couette_face : ndarray (nz, nt)
        ``dZ * H`` at the face between (j, i) and (j, i+1) (Couette flux of a full film).
    rhs : ndarray (nz, nt)
        ``b = couette_in - couette_out - squeeze`` per control volume.
    """

    c_theta: np.ndarray
    c_z: np.ndarray
    couette_face: np.ndarray
    rhs: np.ndarray


def build_stencil(
    film: np.ndarray,
    d_theta: float,
    d_z: float,
    film_rate: np.ndarray | None = None,
    rough: FilmFlow | None = None,
) -> Stencil:
    """Stencil for dimensionless film ``H`` (nz x nt) and its rate ``(2/omega) dH/dt``.

    With ``rough`` (docs/theory.md, "Mixed lubrication") the conductances carry the Patir-Cheng
    pressure flow factor, ``H^3 phi_x``, the Couette transport the mean gap and the shear flow
    factor, ``h_T/c + (sigma/c) w Phi_s``, and the squeeze acts on the mean gap
    (``dh_T/dt = Phi(h/sigma) dh/dt``); without it the smooth stencil, unchanged. A turbulent
    film (:class:`~shaftline.film.turbulence.TurbulentFilm`) takes the same path: its z faces
    use ``rough.axial_conductance`` (``12 / k_z`` where theta faces have ``12 / k_x``).
    """
    h_east = 0.5 * (film + _east(film))
    h_north = 0.5 * (film[:-1] + film[1:])
    if rough is None:
        c_theta = (d_z / d_theta) * h_east**3
        c_z = (d_theta / d_z) * h_north**3
        couette_face = d_z * h_east
    else:
        c_theta = (d_z / d_theta) * rough.conductance(h_east)
        c_z = (d_theta / d_z) * rough.axial_conductance(h_north)
        couette_face = d_z * rough.transport(h_east)
    rhs = _west(couette_face) - couette_face
    if film_rate is not None:
        squeeze = film_rate if rough is None else film_rate * rough.squeeze_factor(film)
        rhs = rhs - d_theta * d_z * squeeze
    return Stencil(c_theta=c_theta, c_z=c_z, couette_face=couette_face, rhs=rhs)


def stencil_diagonal(stencil: Stencil) -> np.ndarray:
    """Diagonal of the discrete operator A: the sum of each node's link coefficients, (nz, nt)."""
    diag = stencil.c_theta + _west(stencil.c_theta)
    diag[:-1] += stencil.c_z
    diag[1:] += stencil.c_z
    return diag


def apply_operator(c_theta: np.ndarray, c_z: np.ndarray, pressure: np.ndarray) -> np.ndarray:
    """``A @ P`` on every node: net diffusive outflow of each control volume."""
    flow_east = c_theta * (pressure - _east(pressure))
    out = flow_east - _west(flow_east)
    flow_north = c_z * (pressure[:-1] - pressure[1:])
    out[:-1] += flow_north
    out[1:] -= flow_north
    return out


def stencil_derivative(
    film: np.ndarray,
    film_derivative: np.ndarray,
    d_theta: float,
    d_z: float,
    rough: FilmFlow | None = None,
    film_rate: np.ndarray | None = None,
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Derivatives of (c_theta, c_z, rhs without its change of film rate) for a film change ``dH``.

    Smooth (``rough`` None): the Couette part of the rhs only, as before. Rough: also the
    change of the squeeze factor ``Phi(h/sigma)`` under a given ``film_rate`` (the rate itself
    held), so that the derivative is that of :func:`build_stencil` with the same arguments.
    """
    h_east = 0.5 * (film + _east(film))
    dh_east = 0.5 * (film_derivative + _east(film_derivative))
    h_north = 0.5 * (film[:-1] + film[1:])
    dh_north = 0.5 * (film_derivative[:-1] + film_derivative[1:])
    if rough is None:
        dc_theta = (d_z / d_theta) * 3.0 * h_east**2 * dh_east
        dc_z = (d_theta / d_z) * 3.0 * h_north**2 * dh_north
        d_couette = d_z * dh_east
        return dc_theta, dc_z, _west(d_couette) - d_couette
    dc_theta = (d_z / d_theta) * rough.conductance_derivative(h_east) * dh_east
    dc_z = (d_theta / d_z) * rough.axial_conductance_derivative(h_north) * dh_north
    d_couette = d_z * rough.transport_derivative(h_east) * dh_east
    d_rhs = _west(d_couette) - d_couette
    if film_rate is not None:
        d_rhs = d_rhs - d_theta * d_z * film_rate * rough.squeeze_factor_derivative(film) * film_derivative
    return dc_theta, dc_z, d_rhs


@dataclass(frozen=True, eq=False)
class FullPattern:
    """The periodic 5-point pattern in CSC form (both triangles) with, per stored entry, where its
    value comes from: the pattern of the mass-conserving model's unsymmetric Jacobians."""

    indptr: np.ndarray
    indices: np.ndarray
    row: np.ndarray
    col: np.ndarray
    off: np.ndarray  # off-diagonal entry
    source: np.ndarray  # index into the concatenation (diag, c_theta, c_z), all flattened
    downstream: np.ndarray  # theta-link entry whose row is the node east of its column


@lru_cache(maxsize=8)
def full_pattern(nz: int, nt: int) -> FullPattern:
    """The :class:`FullPattern` of an (nz, nt) grid (memoised: a pure function of the shape)."""
    import scipy.sparse as sp

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
    return FullPattern(
        indptr=slots.indptr,
        indices=slots.indices,
        row=rows[order],
        col=cols[order],
        off=rows[order] != cols[order],
        source=source[order],
        downstream=downstream[order],
    )


def film_operator(stencil: Stencil) -> Any:
    """The film operator ``A`` (n x n, a ``scipy.sparse.csr_matrix``) of a stencil:
    ``A @ P = apply_operator(P)``."""
    import scipy.sparse as sp

    nz, nt = stencil.c_theta.shape
    node = np.arange(nz * nt).reshape(nz, nt)
    a = np.concatenate([node.ravel(), node[:-1].ravel()])
    b = np.concatenate([np.roll(node, -1, axis=1).ravel(), node[1:].ravel()])
    c = np.concatenate([stencil.c_theta.ravel(), stencil.c_z.ravel()])
    rows = np.concatenate([a, b, a, b])
    cols = np.concatenate([a, b, b, a])
    vals = np.concatenate([c, c, -c, -c])
    return sp.csr_matrix((vals, (rows, cols)), shape=(nz * nt, nz * nt))
