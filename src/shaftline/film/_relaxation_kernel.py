"""Compiled red-black sweeps that predict the cavitated set of a film: projected over-relaxation
of the Reynolds complementarity problem, and nonlinear Gauss-Seidel of the mass-conserving (JFO)
equations.

The film solvers' loops over grid nodes (:func:`shaftline.film.relaxation.projected_sor` and
:meth:`shaftline.film.cavitation.jfo.MassConserving.relaxed_set` wrap them). A sweep updates
each free node from its four neighbours; the nodes are coloured so that no two neighbours share
a colour — red and black, (i + j) even or odd, and on a grid with an odd number of columns the
last column (a neighbour of the first across theta = 0) in two colours of its own by row parity
— and visited colour by colour, so the sweep is Gauss-Seidel in that order and its result does
not depend on the order within a colour.

This module imports numba; the film solvers import it when they first sweep, so that importing
the film package stays cheap for callers that never solve.
"""

from __future__ import annotations

import numpy as np

from shaftline._compiled import njit_cached

__all__ = ["projected_sor_sweeps"]


_GRID = "float64[:, ::1]"


@njit_cached("UniTuple(int64, 3)(int64, int64, int64)", nogil=True, inline="always")
def _columns(colour: int, j: int, nt: int) -> tuple[int, int, int]:
    """The columns of row ``j`` in ``colour`` as ``range(first, last, step)``: colours 0 and 1
    are red and black ((i + j) even or odd), without the last column of an odd count, which
    takes colours 2 (even rows) and 3 (odd rows); empty where the row has none."""
    paired = nt - 1 if nt % 2 else nt
    if colour < 2:
        return (j + colour) % 2, paired, 2
    if j % 2 == colour - 2:
        return nt - 1, nt, 1
    return 0, 0, 1


# Compiled (or loaded from numba's cache) when this module is imported, not at the first call: a
# process pool's fork server that imports it hands its workers the machine code.
@njit_cached(f"int64({_GRID}, {_GRID}, {_GRID}, {_GRID}, boolean[:, ::1], int64, float64, boolean)", nogil=True)
def projected_sor_sweeps(
    x: np.ndarray,
    c_theta: np.ndarray,
    c_z: np.ndarray,
    rhs: np.ndarray,
    fixed: np.ndarray,
    sweeps: int,
    omega: float,
    until_settled: bool,
) -> int:
    """Up to ``sweeps`` projected SOR sweeps of ``A P = b, P >= 0`` on ``x`` (nz, nt), in place.

    ``A`` is the five-point operator of the conductances ``c_theta`` (nz, nt; the link from
    node (j, i) to (j, i + 1), periodic in i) and ``c_z`` (nz - 1, nt; from (j, i) to
    (j + 1, i)): ``(A P)_n = sum_k c_nk (P_n - P_k)``. ``fixed`` (nz, nt) nodes keep their
    values. With ``until_settled`` the sweeps stop after the first one that changes no node's
    side of zero. Returns the number of sweeps done.
    """
    nz, nt = x.shape
    keep = 1.0 - omega
    # Each node's update as one multiply-add per neighbour: x <- keep x + r + sum_k a_k x_k.
    east = np.zeros((nz, nt))
    west = np.zeros((nz, nt))
    north = np.zeros((nz, nt))
    south = np.zeros((nz, nt))
    source = np.zeros((nz, nt))
    for j in range(nz):
        for i in range(nt):
            if fixed[j, i]:
                continue
            w = i - 1 if i > 0 else nt - 1
            diagonal = c_theta[j, i] + c_theta[j, w]
            if j + 1 < nz:
                diagonal += c_z[j, i]
            if j > 0:
                diagonal += c_z[j - 1, i]
            scale = omega / diagonal
            east[j, i] = scale * c_theta[j, i]
            west[j, i] = scale * c_theta[j, w]
            if j + 1 < nz:
                north[j, i] = scale * c_z[j, i]
            if j > 0:
                south[j, i] = scale * c_z[j - 1, i]
            source[j, i] = scale * rhs[j, i]
    done = 0
    while done < sweeps:
        done += 1
        switched = False
        for colour in range(4 if nt % 2 else 2):
            for j in range(nz):
                first, last, step = _columns(colour, j, nt)
                up = j + 1 if j + 1 < nz else j  # its coefficient is zero on the edge rows
                down = j - 1 if j > 0 else j
                for i in range(first, last, step):
                    if fixed[j, i]:
                        continue
                    e = i + 1 if i + 1 < nt else 0
                    w = i - 1 if i > 0 else nt - 1
                    old = x[j, i]
                    new = (
                        keep * old
                        + source[j, i]
                        + east[j, i] * x[j, e]
                        + west[j, i] * x[j, w]
                        + north[j, i] * x[up, i]
                        + south[j, i] * x[down, i]
                    )
                    if new < 0.0:
                        new = 0.0
                    if (new <= 0.0) != (old <= 0.0):
                        switched = True
                    x[j, i] = new
        if until_settled and not switched:
            break
    return done


@njit_cached(f"float64({_GRID}, boolean[:, ::1], {_GRID}, int64, int64)", nogil=True, inline="always")
def _pressure(u: np.ndarray, fixed: np.ndarray, fixed_pressure: np.ndarray, j: int, i: int) -> float:
    """The pressure of a JFO node: its held value, or ``max(u, 0)`` (zero where cavitated)."""
    return fixed_pressure[j, i] if fixed[j, i] else max(u[j, i], 0.0)


_JFO_SWEEPS = f"int64({_GRID}, {_GRID}, {_GRID}, {_GRID}, {_GRID}, {_GRID}, boolean[:, ::1], {_GRID}, int64)"


@njit_cached(_JFO_SWEEPS, nogil=True)
def jfo_gauss_seidel_sweeps(
    u: np.ndarray,
    c_theta: np.ndarray,
    c_z: np.ndarray,
    couette_face: np.ndarray,
    rhs: np.ndarray,
    diagonal: np.ndarray,
    fixed: np.ndarray,
    fixed_pressure: np.ndarray,
    sweeps: int,
) -> int:
    """Up to ``sweeps`` red-black nonlinear Gauss-Seidel sweeps of the JFO equations on the
    unknown ``u`` (nz, nt; ``P`` where the film is full, ``-s`` where cavitated), in place.

    With its neighbours held, a node's residual is piecewise linear and increasing in its own
    ``u``, with one root: ``-R0 / diag(A)`` when the residual at ``u = 0``, ``R0``, is negative,
    else ``-R0 / q`` (``q = couette_face``, the Couette flux out through the node's east face;
    :meth:`~shaftline.film.cavitation.jfo.MassConserving.relaxed_set`). ``R0`` is the inflow of
    the western face's void share ``q_west max(-u_west, 0)`` minus the pressure inflow from the four neighbours (their
    ``max(u, 0)``, or ``fixed_pressure`` on fixed nodes) minus ``rhs``. Fixed nodes keep
    ``u``. Stops after the first sweep that changes no node's side of zero (``u < 0``).
    Returns the number of sweeps done.
    """
    nz, nt = u.shape
    done = 0
    while done < sweeps:
        done += 1
        switched = False
        for colour in range(4 if nt % 2 else 2):
            for j in range(nz):
                first, last, step = _columns(colour, j, nt)
                for i in range(first, last, step):
                    if fixed[j, i]:
                        continue
                    e = i + 1 if i + 1 < nt else 0
                    w = i - 1 if i > 0 else nt - 1
                    inflow = c_theta[j, i] * _pressure(u, fixed, fixed_pressure, j, e)
                    inflow += c_theta[j, w] * _pressure(u, fixed, fixed_pressure, j, w)
                    if j + 1 < nz:
                        inflow += c_z[j, i] * _pressure(u, fixed, fixed_pressure, j + 1, i)
                    if j > 0:
                        inflow += c_z[j - 1, i] * _pressure(u, fixed, fixed_pressure, j - 1, i)
                    void_west = 0.0 if fixed[j, w] else max(-u[j, w], 0.0)
                    residual_at_zero = couette_face[j, w] * void_west - inflow - rhs[j, i]
                    old = u[j, i]
                    if residual_at_zero < 0.0:
                        new = -residual_at_zero / diagonal[j, i]
                    else:
                        new = -residual_at_zero / couette_face[j, i]
                    if (new < 0.0) != (old < 0.0):
                        switched = True
                    u[j, i] = new
        if not switched:
            break
    return done
