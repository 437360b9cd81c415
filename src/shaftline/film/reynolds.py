"""Finite-volume Reynolds equation on the unwrapped bore, with cavitation.

Dimensionless form (docs/theory.md, Sect. "Reynolds equation"): with
``H = h / c``, ``Z = z / R`` and ``P = p / p_ref``, ``p_ref = 6 eta omega (R/c)^2``,

    d/dtheta (H^3 dP/dtheta) + d/dZ (H^3 dP/dZ) = dH/dtheta + (2/omega) dH/dt.

Each node is the centre of a control volume ``dtheta x dZ``; face conductances
are ``((H_a + H_b)/2)^3``. The discrete operator ``A`` (the negative of the
left-hand side) is a symmetric M-matrix; fixed-pressure nodes (the two bearing
edges, supply grooves) and cavitated nodes are removed by masking rows and
columns, which keeps one sparsity pattern for every solve so that the sparse
LDL^T factorisation (qdldl) reuses its symbolic analysis.

Cavitation models
-----------------
``"reynolds"``
    Swift-Stieber condition as a linear complementarity problem
    ``P >= 0, w = A P - b >= 0, P w = 0``, solved by the primal-dual active-set
    method (Hintermueller, Ito & Kunisch 2002), which terminates in finitely many
    steps for an M-matrix.
``"jfo"``
    Mass-conserving Jakobsson-Floberg-Olsson model in the complementarity form of
    Giacopini et al. (2010): each node carries either a pressure (full film) or a
    void fraction ``s = 1 - film fraction`` (cavitated); the Couette flux through a
    face is ``(1 - s_upstream) H_face``. Solved by the same active-set switching,
    with a sparse LU of the unsymmetric system.
``"half_sommerfeld"``
    The linear (full-Sommerfeld) solution with negative gauge pressures set to the
    cavitation pressure; offered only for comparison.

All pressures here are dimensionless and measured from the cavitation pressure.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from functools import lru_cache
from typing import Any

import numpy as np
import qdldl
import scipy.sparse as sp

from shaftline.errors import SolverFailure
from shaftline.film.geometry import coarse_shape
from shaftline.film.problem import CAVITATION_MODELS, Cavitation
from shaftline.film.relaxation import projected_sor
from shaftline.film.roughness import FilmFlow

__all__ = [
    "CAVITATION_MODELS",
    "CoarseGrid",
    "NODE_SET_MARGIN",
    "NESTED_SWING",
    "NODE_SET_SLACK",
    "MAX_ACTIVE_SET_ITERATIONS",
    "ReynoldsConvergenceError",
    "ReynoldsSolution",
    "ReynoldsSolver",
    "Stencil",
    "apply_operator",
    "build_stencil",
    "stencil_derivative",
    "stencil_diagonal",
]

#: Active-set iterations allowed before the solver gives up.
MAX_ACTIVE_SET_ITERATIONS = 200
#: Cells added around the free nodes, in each direction, when a kept factor's node set is
#: chosen: the cavitation boundary of the next trial sets, Newton steps and nearby films moves
#: by a few cells, and every set inside the node set reuses its ordering and symbolic analysis.
NODE_SET_MARGIN = 3
#: A kept node set is chosen again when it holds more than this many times the free nodes:
#: its factor then costs noticeably more than a factor of the free nodes alone.
NODE_SET_SLACK = 1.35
#: Conjugate-gradient solves of the trial active sets, preconditioned by the factor of a nearby
#: set: given up for a factorisation after this many iterations (a few dozen triangular solves
#: cost about one factorisation), and converged when the energy-norm error is below this
#: share of the solution's (the trial sets need only the signs; the settled set is solved
#: again with its own factor).
PCG_MAX_ITERATIONS = 30
#: Share of the nodes that a Newton trial's linear pressure guess may take below zero and
#: still start from its own swept set; beyond it the coarse grids predict the set
#: (:meth:`ReynoldsSolver.trial_set`). Over 27 test equilibria (grids 60 x 36 to 200 x 120,
#: three tilts and loads) 2 % took the fine active-set iterations from 308 to 279.
NESTED_SWING = 0.02
#: Projected SOR sweeps and over-relaxation factor of each small coarse grid that predicts the
#: cavitated set by sweeps alone (:meth:`ReynoldsSolver._swept_indicator`), from the coarsest
#: up. The sweeps run to the count (no early stop: the pressure, not only its set, starts the
#: next grid). NTUA 100 x 60 cold solution, 25 x 15 and 50 x 30 below it: 30 sweeps at 1.85
#: start the fine set 2 nodes off, as the coarse active sets did; at 1.7 it starts 4 off.
CASCADE_SWEEPS = 30
CASCADE_OMEGA = 1.85
#: The coarsest grid starts the sweeps from zero only up to this many nodes in either direction;
#: a longer one (the halving stops at an odd column count or below 9 axial nodes: 200 x 122 stops
#: at 100 x 61, 16 x 250 at 8 x 125) solves its own active set instead, as the sweeps carry
#: the boundary only some tens of cells. Sweeps from zero there left the 200 x 122 fine set up
#: to 2201 nodes off (14-17 fine active-set iterations instead of 3-4), 16 x 250 took 65 fine
#: iterations instead of 10 (four positions), and on 31 x 1202 the active set did not settle.
CASCADE_COARSEST_SPAN = 40
#: Active sets that differ from the kept factor's, on the same film, in at most this many
#: nodes are solved with the factor and a bordered correction (:meth:`_NodeSetFactor.switch`):
#: its k triangular solves (0.12 ms each on 100 x 60, against 1.0-1.3 ms for the numeric
#: factorisation; 0.6 against 8 ms on 200 x 120) cost less than a factorisation up to about
#: ten nodes. Nine NTUA equilibria (three loads, three tilts) on 200 x 120: 27 fine
#: factorisations with 3, 20 with 8; unchanged on 100 x 60 and 400 x 240.
SWITCH_MAX_NODES = 8
#: A solution asked for with ``settle=False`` (:meth:`ReynoldsSolver.solve`) stops at the first
#: trial set that leaves at most this many nodes on the wrong side of the complementarity
#: conditions: the pressure of that set, clipped at zero (the switch that settles it later
#: costs one triangular solve a node).
UNSETTLED_MAX_NODES = 3
PCG_TOLERANCE = 1e-9
#: Energy-norm share to which a refined solution (:meth:`ReynoldsSolver.solve` with ``refine_from``)
#: is iterated: near the rounding of a direct solve (its pressures agree with the factor's to
#: about 1e-12 of the peak), so that it stands for that set's solution.
REFINE_TOLERANCE = 1e-13
#: Grids below this many nodes factorise every trial set: there a conjugate-gradient
#: iteration, its array work in numpy included, costs a tenth of a factorisation or more
#: (0.25 ms against 1-3 ms on 100 x 60), and a trial set needs 10-25 of them.
PCG_MIN_NODES = 10_000


class ReynoldsConvergenceError(SolverFailure):
    """The active-set iteration did not settle (never seen on M-matrices; kept as a guard)."""


@dataclass(frozen=True, eq=False)
class _Pattern:
    """Sparsity pattern of the 5-point periodic stencil on an (nz, nt) grid."""

    nz: int
    nt: int
    upper: sp.csc_matrix  # upper triangle incl. diagonal, data = slot ids
    # For each slot of ``upper.data``: kind (0 diagonal, 1 theta-link, 2 z-link) and node ids.
    slot_kind: np.ndarray
    slot_row: np.ndarray
    slot_col: np.ndarray
    # Index of each slot's value in concat(diag(A), -c_theta, -c_z), all flattened.
    slot_source: np.ndarray


@lru_cache(maxsize=16)
def _pattern(nz: int, nt: int) -> _Pattern:
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
    return _Pattern(
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


@dataclass(eq=False)
class ReynoldsSolution:
    """Dimensionless solution of the Reynolds equation on the grid.

    Attributes
    ----------
    pressure : ndarray (nz, nt)
        ``P`` above the cavitation pressure (>= 0 except for half-Sommerfeld before clipping).
    film_fraction : ndarray (nz, nt)
        Share of the clearance filled with liquid (1 in the full film).
    cavitated : ndarray of bool (nz, nt)
        Nodes held at the cavitation pressure.
    iterations : int
        Active-set iterations used: linear solves of trial sets (factorisations, or on
        fine grids conjugate-gradient solves), the final solve with the settled set's
        factor included.
    settled : bool
        False for a solution left on a set a few nodes from the final one (a Newton iterate
        solved with ``settle=False``, :meth:`ReynoldsSolver.solve`); True otherwise.
    """

    pressure: np.ndarray
    film_fraction: np.ndarray
    cavitated: np.ndarray
    iterations: int
    settled: bool = field(default=True, kw_only=True)


class _MarchedSolution(ReynoldsSolution):
    """A Reynolds-condition solution whose film fraction is marched (:func:`_marched_film_fraction`)
    when first read: the Newton trials of an equilibrium never read it, only its final state."""

    def __init__(
        self, pressure: np.ndarray, cavitated: np.ndarray, iterations: int, film: np.ndarray, settled: bool = True
    ) -> None:
        self._film = film
        self._fraction: np.ndarray | None = None
        super().__init__(pressure, None, cavitated, iterations, settled=settled)  # type: ignore[arg-type]

    @property
    def film_fraction(self) -> np.ndarray:
        if self._fraction is None:
            self._fraction = _marched_film_fraction(self._film, self.cavitated)
        return self._fraction

    @film_fraction.setter
    def film_fraction(self, value: np.ndarray | None) -> None:
        self._fraction = value


class ReynoldsSolver:
    """Solver for one grid shape with fixed-pressure nodes.

    It keeps state between calls: the sparse LDL^T factorisation (qdldl), the
    active set it was factorised for, and a solver on the coarser grid that
    predicts the cavitated set. That state belongs to one process and does not
    pickle; :class:`shaftline.film.bearing.JournalBearing` builds it lazily.

    Parameters
    ----------
    shape : (int, int)
        (axial_nodes, circumferential_nodes).
    d_theta, d_z : float
        Dimensionless mesh steps (rad, and axial step / R).
    fixed : ndarray of bool (nz, nt)
        Nodes with prescribed pressure (edges, supply grooves).
    fixed_pressure : ndarray (nz, nt)
        Their dimensionless pressures above the cavitation pressure.
    """

    def __init__(
        self, shape: tuple[int, int], d_theta: float, d_z: float, fixed: np.ndarray, fixed_pressure: np.ndarray
    ) -> None:
        self.shape = shape
        self.d_theta = d_theta
        self.d_z = d_z
        self.fixed = np.asarray(fixed, dtype=bool)
        self.fixed_pressure = np.where(self.fixed, fixed_pressure, 0.0)
        self.pattern = _pattern(*shape)
        self._factor: _NodeSetFactor | None = None
        #: Factorise the full periodic pattern with the held rows and columns zeroed (one
        #: symbolic analysis for every set) instead of the free sub-matrix: set on the small
        #: coarse grids that only predict the cavitated set.
        self.masked = False
        self._masked_factor: _NodeSetFactor | None = None
        self._slot_cache: tuple[Stencil, np.ndarray] | None = None
        self._coarse_grid: CoarseGrid | None = None
        self.pcg_iterations = 0
        #: Flow model of the coarse grids that predict the cavitated set (:meth:`_nested_start`):
        #: None (the smooth film) unless the caller sets it, e.g. a turbulent film's, whose
        #: damped pressure flow moves the cavitation boundary (a function of H = h/c only, so
        #: the same object serves every grid).
        self.flow: FilmFlow | None = None

    def drop_factors(self) -> None:
        """Forget the kept node-set factors (and those of the coarser grids), keeping the
        sparsity patterns and coarse grids: the next solutions then round the same whatever
        this solver solved before (a design search shares one solver across bores, and its
        results must not depend on which worker evaluated which design before). The masked
        factor stays: its pattern is fixed, so its results depend on the matrix only. The
        mass-conserving solver's kept orders and last solution go too
        (:func:`shaftline.film.jfo.forget`)."""
        from shaftline.film.jfo import forget  # jfo imports this module

        self._factor = None
        forget(self)
        if self._coarse_grid is not None:
            self._coarse_grid.solver.drop_factors()

    # -- symmetric masked system -------------------------------------------------
    def _slot_values(self, stencil: Stencil) -> np.ndarray:
        """Values of A on every slot of the full pattern (upper triangle), kept per stencil:
        an active-set iteration builds several sub-matrices of one film."""
        cached = self._slot_cache
        if cached is not None and cached[0] is stencil:
            return cached[1]
        source = np.concatenate([stencil_diagonal(stencil).ravel(), -stencil.c_theta.ravel(), -stencil.c_z.ravel()])
        values = source[self.pattern.slot_source]
        self._slot_cache = (stencil, values)
        return values

    def _factorise(self, stencil: Stencil, held: np.ndarray) -> _NodeSetFactor | None:
        """LDL^T factor of the free sub-matrix ``A[free, free]`` (qdldl), kept between calls.

        The factor is that of a kept node set holding the free nodes and a few cells around
        them (:data:`NODE_SET_MARGIN`), with the held nodes inside it decoupled (their rows
        and columns zeroed, their diagonals kept): so ``x = 0`` there, and on the free nodes
        the solution is that of ``A[free, free]`` itself. Every active set inside the kept
        node set reuses its AMD ordering and symbolic analysis and costs only qdldl's numeric
        factorisation; the same set and film again (the frozen-set derivatives after a
        solution) cost nothing. A set with a free node outside it, or one much smaller than
        it (:data:`NODE_SET_SLACK`), gets a new node set. Returns None when no node is free.
        """
        free = ~held.ravel()
        if not free.any():
            self._factor = None
            return None
        factor = self._factor
        if factor is not None and factor.is_for(stencil, free):
            return factor
        if factor is None or not factor.holds(free):
            self._factor = None  # a fine grid's factors need not fit in memory twice
            factor = _NodeSetFactor.around(self.pattern, free, self.shape, NODE_SET_MARGIN, self.fixed.ravel())
        elif factor.switch(self._slot_values(stencil), stencil, free):
            return factor
        factor.factorise(self._slot_values(stencil), stencil, free)
        self._factor = factor
        return factor

    def _solve_free(
        self,
        stencil: Stencil,
        held: np.ndarray,
        rhs: np.ndarray,
        guess: np.ndarray | None,
        direct: bool,
        refine: bool = False,
    ) -> np.ndarray:
        """``x`` with ``A[free, free] x[free] = rhs[free]`` and ``x = 0`` on the held nodes (flat).

        Unless ``direct``, conjugate gradients preconditioned by the kept factor (of a nearby
        active set, possibly of a nearby film) come first: they end in a few iterations, as
        the two matrices differ in the rows and columns of the switched nodes and by the
        small change of the film. Otherwise, or when they do not converge, the factor of
        this set. ``guess`` (flat, or None) starts the iteration. ``refine``: conjugate
        gradients on any grid, to :data:`REFINE_TOLERANCE`.
        """
        free = ~held.ravel()
        out = np.zeros(free.size)
        if not free.any():
            return out
        if self.masked:
            return self._masked_factorisation(stencil, held).solve(np.where(free, rhs.ravel(), 0.0))
        iterative = (refine or free.size >= PCG_MIN_NODES) and self._factor is not None
        if iterative and not direct:
            tolerance = REFINE_TOLERANCE if refine else PCG_TOLERANCE
            solution = self._pcg(stencil, free, rhs.ravel()[free], None if guess is None else guess[free], tolerance)
            if solution is not None:
                out[free] = solution
                return out
        factor = self._factorise(stencil, held)
        assert factor is not None
        return factor.solve(np.where(free, rhs.ravel(), 0.0))

    def _masked_factorisation(self, stencil: Stencil, held: np.ndarray) -> _NodeSetFactor:
        """Factor of the full pattern with the held rows and columns zeroed, their diagonals
        kept (so ``x = 0`` there for a zero right-hand side): a :class:`_NodeSetFactor` whose
        node set is every node, so its one symbolic analysis serves every set."""
        free = ~held.ravel()
        factor = self._masked_factor
        if factor is None:
            everything = np.ones(free.size, dtype=bool)
            factor = self._masked_factor = _NodeSetFactor.around(self.pattern, everything, self.shape, 0)
        if not factor.is_for(stencil, free):
            factor.factorise(self._slot_values(stencil), stencil, free)
        return factor

    def _is_factored(self, stencil: Stencil, held: np.ndarray) -> bool:
        """Whether the kept factor is that of ``stencil`` and ``held`` (or no node is free)."""
        if held.all() or self.masked:
            return True  # a masked solve is always a direct solve of that set's own matrix
        return self._factor is not None and self._factor.is_for(stencil, ~held.ravel())

    def _pcg(
        self,
        stencil: Stencil,
        free: np.ndarray,
        rhs: np.ndarray,
        guess: np.ndarray | None,
        tolerance: float = PCG_TOLERANCE,
    ) -> np.ndarray | None:
        """Conjugate gradients on ``A[free, free]`` preconditioned by the kept factor.

        The preconditioner applies the kept factor's inverse on the nodes free in both sets
        and the inverse diagonal on the nodes freed since. For the same film it differs from
        the inverse of the new matrix by a term of rank at most about twice the switched
        nodes, so the iteration ends in about that many steps (Golub & Van Loan, Matrix
        Computations, 4th ed., Sect. 11.5); a factor of a nearby film adds a perturbation
        small in norm, which costs a few more.
        Stops when the preconditioned residual (the error in the energy norm) falls below
        ``tolerance`` of the solution's energy norm; None when it does not within
        ``PCG_MAX_ITERATIONS``.
        """
        factor = self._factor
        assert factor is not None and factor.free is not None
        kept_free = factor.free
        size = free.size
        in_kept = kept_free[free]  # free now and in the kept factor
        diag = stencil_diagonal(stencil).ravel()[free]
        extra = ~in_kept
        shape = self.shape
        both = free & kept_free

        def operator(x: np.ndarray) -> np.ndarray:
            full = np.zeros(size)
            full[free] = x
            return apply_operator(stencil.c_theta, stencil.c_z, full.reshape(shape)).ravel()[free]

        def precondition(r: np.ndarray) -> np.ndarray:
            z = np.empty_like(r)
            kept_rhs = np.zeros(size)
            kept_rhs[both] = r[in_kept]
            z[in_kept] = factor.solve(kept_rhs)[both]
            z[extra] = r[extra] / diag[extra]
            return z

        x = np.zeros(rhs.size) if guess is None else guess.copy()
        r = rhs - operator(x)
        z = precondition(r)
        p = z.copy()
        rz = _dot(r, z)
        for step in range(PCG_MAX_ITERATIONS):
            energy = abs(_dot(x, rhs)) + abs(_dot(x, r))
            if rz <= tolerance**2 * energy or rz == 0.0:
                self.pcg_iterations += step
                return x
            q = operator(p)
            alpha = rz / _dot(p, q)
            x += alpha * p
            r -= alpha * q
            z = precondition(r)
            rz_new = _dot(r, z)
            p = z + (rz_new / rz) * p
            rz = rz_new
        return None

    def _solve_masked(
        self,
        stencil: Stencil,
        held: np.ndarray,
        held_values: np.ndarray,
        guess: np.ndarray | None = None,
        direct: bool = True,
        refine: bool = False,
    ) -> np.ndarray:
        """Solve ``A P = b`` on the free nodes with ``P = held_values`` on held nodes."""
        # Moving the held values to the right-hand side: b - A_{free,held} P_held.
        boundary = np.where(held, held_values, 0.0)
        rhs = stencil.rhs - apply_operator(stencil.c_theta, stencil.c_z, boundary)
        pressure = self._solve_free(stencil, held, rhs, None if guess is None else guess.ravel(), direct, refine)
        return (pressure + boundary.ravel()).reshape(self.shape)

    def solve_linear(self, stencil: Stencil) -> np.ndarray:
        """Full-Sommerfeld solution (no cavitation), dimensionless pressure."""
        return self._solve_masked(stencil, self.fixed, self.fixed_pressure)

    def solve(
        self,
        stencil: Stencil,
        film: np.ndarray,
        cavitation: Cavitation = "reynolds",
        initial_cavitated: np.ndarray | None = None,
        refine_from: np.ndarray | None = None,
        settle: bool = True,
    ) -> ReynoldsSolution:
        """Solve with the chosen cavitation model; ``initial_cavitated`` warm-starts the active set.

        ``refine_from`` (Reynolds condition only), a pressure guess (nz, nt) close to the solution
        (a short Newton step's ``P + dP``): the active set's solves then iterate from it by
        conjugate gradients preconditioned by the kept factor (that of the nearby film), to
        :data:`REFINE_TOLERANCE`, instead of factorising this film's matrix.

        ``settle=False`` (Reynolds condition and JFO): stop at the first trial set within
        :data:`UNSETTLED_MAX_NODES` nodes of settling, the solution marked ``settled=False``: an
        iterate of a Newton iteration far from its root, whose step moves the force by far more
        than those nodes do, need not pay for the last set switch (a bordered update of the
        factor, about half a factorisation). Solving again from its set with the same
        ``stencil`` finishes it with that update (docs/theory.md Sect. 4.1).
        """
        if cavitation == "half_sommerfeld":
            pressure = np.maximum(self.solve_linear(stencil), 0.0)
            cavitated = (pressure <= 0.0) & ~self.fixed
            return ReynoldsSolution(pressure, _marched_film_fraction(film, cavitated), cavitated, 1)
        if cavitation == "jfo":
            # Warm-started from the previous JFO set; cold from the JFO solution on coarser grids.
            from shaftline.film.jfo import solve_jfo

            return solve_jfo(self, stencil, film, initial_cavitated, settle=settle)
        reynolds = self._solve_reynolds_lcp(stencil, initial_cavitated, film, refine_from=refine_from, settle=settle)
        if cavitation == "reynolds":
            return _MarchedSolution(reynolds.pressure, reynolds.cavitated, reynolds.iterations, film, reynolds.settled)
        raise ValueError(f"unknown cavitation model {cavitation!r}")

    def coarse_grid(self) -> CoarseGrid | None:
        """The grid halved in both directions under this one (kept), or None when too small."""
        halved = coarse_shape(self.shape)
        if halved is None:
            return None
        if self._coarse_grid is None:
            self._coarse_grid = CoarseGrid.under(self, halved)
        return self._coarse_grid

    def _nested_start(self, film: np.ndarray, stencil: Stencil, guess: np.ndarray | None = None) -> np.ndarray | None:
        """Cavitated set predicted from the same problem on the coarser grids.

        The coarse indicator ``P - w / diag(A)`` (pressure where the film is full, minus the
        scaled complementarity multiplier where it is cavitated; :func:`_set_indicator`)
        changes sign on the cavitation boundary; interpolated bilinearly onto this grid it
        places that boundary to within a cell or two. A few projected over-relaxation sweeps
        on this grid (:func:`~shaftline.film.relaxation.projected_sor`), from the
        interpolated pressure, remove that short-wavelength error: the set they leave is one
        or two nodes off the final one where the interpolated one is tens.

        On the small coarse grids (``masked``, below :data:`PCG_MIN_NODES`) the indicator
        comes from sweeps alone, carried up from the coarsest grid (:meth:`_swept_indicator`);
        a larger coarse grid solves its own active set, itself started this way. ``guess``, a
        Newton trial's pressure guess, starts the coarsest sweeps (restricted to it) or that
        active set (its swept set).
        """
        coarse = self.coarse_grid()
        if coarse is None:
            return None
        solver = coarse.solver
        film_c = coarse.restrict(film)
        solver.flow = self.flow
        guess_c = None if guess is None else coarse.restrict(guess)
        if solver.masked:
            return self.predicted_set(stencil, coarse.prolong(solver._swept_indicator(film_c, guess_c)))
        stencil_c = build_stencil(film_c, solver.d_theta, solver.d_z, rough=self.flow)
        return self.predicted_set(stencil, coarse.prolong(solver._solved_indicator(stencil_c, film_c, guess_c)))

    def _solved_indicator(self, stencil: Stencil, film: np.ndarray, guess: np.ndarray | None) -> np.ndarray:
        """The set indicator (:func:`_set_indicator`) of this grid's own active-set solution,
        started from the swept set of ``guess`` (a pressure guess on this grid) if given. Only a
        prediction: a set a few nodes short of settling predicts the finer one as well (its
        sweeps correct a node or two), without this grid's last switch."""
        start = None if guess is None else self.predicted_set(stencil, guess)
        solution = self._solve_reynolds_lcp(stencil, start, film, exact=False, settle=False)
        return _set_indicator(stencil, solution.pressure, solution.cavitated, self.fixed)

    def _swept_indicator(self, film: np.ndarray, guess: np.ndarray | None) -> np.ndarray:
        """The set indicator (:func:`_set_indicator`) of this grid's problem from
        :data:`CASCADE_SWEEPS` projected SOR sweeps at :data:`CASCADE_OMEGA`, started from the
        indicator of the grid below interpolated onto this one, or on the coarsest grid from
        ``guess`` (a pressure guess on this grid) or zero: the prediction climbs the grids by
        sweeps alone (a cascadic multigrid, docs/theory.md Sect. 4.1), with no factorisation.
        A coarsest grid longer than :data:`CASCADE_COARSEST_SPAN` either way solves its own
        active set instead (a prediction, a few nodes short of settling). On the NTUA case
        (25 x 15 and 50 x 30 under 100 x 60) the fine set starts 2 nodes off the final one, as
        from the coarse active sets this replaced, and a cold solution factorises once instead
        of seven times.
        """
        stencil = build_stencil(film, self.d_theta, self.d_z, rough=self.flow)
        coarse = self.coarse_grid()
        if coarse is None and max(self.shape) > CASCADE_COARSEST_SPAN:
            # Too long (the halving stopped at an odd column count or a short bore) for sweeps
            # from nothing to carry the boundary across: its own active set.
            return self._solved_indicator(stencil, film, guess)
        if coarse is None:
            start = np.zeros(self.shape) if guess is None else guess
        else:
            coarse.solver.flow = self.flow
            guess_below = None if guess is None else coarse.restrict(guess)
            start = coarse.prolong(coarse.solver._swept_indicator(coarse.restrict(film), guess_below))
        start = np.where(self.fixed, self.fixed_pressure, np.maximum(start, 0.0))
        pressure = projected_sor(
            start, stencil.c_theta, stencil.c_z, stencil.rhs, self.fixed, CASCADE_SWEEPS, CASCADE_OMEGA, False
        )
        return _set_indicator(stencil, pressure, (pressure <= 0.0) & ~self.fixed, self.fixed)

    def trial_set(self, stencil: Stencil, film: np.ndarray, pressure: np.ndarray) -> np.ndarray | None:
        """Start set of a Newton trial from its linear pressure guess ``P + dP`` (nz, nt):
        :meth:`predicted_set`, or the coarse grids' prediction (:meth:`_nested_start`) when the
        guess takes more than :data:`NESTED_SWING` of the nodes below zero. Such a long step
        moves the cavitation boundary by many cells, an error the sweeps cannot remove (on
        the NTUA case the first Newton trial's guess is 5 % negative and its swept set 31
        nodes off, four factorisations; from the coarse grids 4 nodes off, two)."""
        if np.count_nonzero((pressure < 0.0) & ~self.fixed) > NESTED_SWING * pressure.size:
            nested = self._nested_start(film, stencil, pressure)
            if nested is not None:
                return nested
        return self.predicted_set(stencil, pressure)

    def predicted_set(self, stencil: Stencil, pressure: np.ndarray) -> np.ndarray:
        """Cavitated set predicted from a pressure guess (nz, nt), e.g. interpolated from a
        coarser grid or extrapolated by a Newton step: the nodes that a few projected
        over-relaxation sweeps from it (:func:`~shaftline.film.relaxation.projected_sor`)
        leave at zero. The sweeps remove the guess's short-wavelength error around the
        cavitation boundary, so the set is a node or two off the final one."""
        start = np.where(self.fixed, self.fixed_pressure, np.maximum(pressure, 0.0))
        relaxed = projected_sor(start, stencil.c_theta, stencil.c_z, stencil.rhs, self.fixed)
        return (relaxed <= 0.0) & ~self.fixed

    def _solve_reynolds_lcp(
        self,
        stencil: Stencil,
        initial_cavitated: np.ndarray | None,
        film: np.ndarray | None = None,
        exact: bool = True,
        refine_from: np.ndarray | None = None,
        settle: bool = True,
    ) -> ReynoldsSolution:
        """Primal-dual active set (Hintermueller, Ito & Kunisch 2002) for the Reynolds LCP.

        The trial sets are solved by :meth:`_solve_free` (conjugate gradients preconditioned
        by the kept factor where they converge); once the set has settled, its pressures are
        solved again with the factor of that set (``exact``), so that the result depends only
        on the film and the set, which is unique, not on the start or the path. The coarse
        grids that only predict the set skip that last solve. With ``refine_from`` (a pressure guess,
        see :meth:`solve`) every set is solved iteratively to :data:`REFINE_TOLERANCE`; with
        ``settle=False`` it may stop a few nodes short of settling (see :meth:`solve`).
        """
        iterations = 0
        if initial_cavitated is None and film is not None and stencil.rhs.shape == film.shape:
            initial_cavitated = self._nested_start(film, stencil)
        if initial_cavitated is None:
            pressure = self.solve_linear(stencil)
            iterations += 1
            cavitated = (pressure < 0.0) & ~self.fixed
        else:
            cavitated = initial_cavitated & ~self.fixed
        scale = 1.0
        guess = refine_from
        values = np.where(self.fixed, self.fixed_pressure, 0.0)
        direct = False
        for _ in range(MAX_ACTIVE_SET_ITERATIONS):
            held = self.fixed | cavitated
            pressure = self._solve_masked(stencil, held, values, guess, direct=direct, refine=refine_from is not None)
            guess = pressure
            iterations += 1
            scale = max(float(np.abs(pressure).max()), 1e-300)
            multiplier = apply_operator(stencil.c_theta, stencil.c_z, pressure) - stencil.rhs
            rhs_scale = max(float(np.abs(stencil.rhs).max()), 1e-300)
            leave = cavitated & (multiplier < -1e-12 * rhs_scale)
            enter = ~held & (pressure < -1e-12 * scale)
            if not leave.any() and not enter.any():
                if exact and refine_from is None and not self._is_factored(stencil, held):
                    # Settled on an iterative solution: solve once more with this set's factor
                    # (and check it again) so that the result does not depend on the path.
                    direct = True
                    continue
                pressure = np.where(cavitated, 0.0, pressure)
                return ReynoldsSolution(pressure, np.ones_like(pressure), cavitated, iterations)
            if not settle and int(np.count_nonzero(leave | enter)) <= UNSETTLED_MAX_NODES:
                pressure = np.maximum(np.where(cavitated, 0.0, pressure), 0.0)
                return ReynoldsSolution(pressure, np.ones_like(pressure), cavitated, iterations, settled=False)
            cavitated = (cavitated & ~leave) | enter
        raise ReynoldsConvergenceError("Reynolds-condition active set did not settle")

    def linear_response(self, stencil: Stencil, solution: ReynoldsSolution, rhs_change: np.ndarray) -> np.ndarray:
        """Pressure change ``dP`` for a residual change ``dR`` with the active set frozen.

        Solves ``A_free dP = -dR`` on the pressurised free nodes, reusing the
        factorisation of the converged active set when it is still held.
        """
        held = self.fixed | solution.cavitated
        columns = np.atleast_2d(rhs_change.reshape(-1, self.shape[0] * self.shape[1]))
        out = np.array([self._solve_free(stencil, held, -column, None, direct=True) for column in columns])
        return out.reshape((-1,) + self.shape)


@dataclass(eq=False)
class _NodeSetFactor:
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
        pattern: _Pattern,
        free: np.ndarray,
        shape: tuple[int, int],
        margin: int,
        never_free: np.ndarray | None = None,
    ) -> _NodeSetFactor:
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

    def holds(self, free: np.ndarray) -> bool:
        """Whether ``free`` lies inside the node set and fills enough of it."""
        count = int(np.count_nonzero(free))
        return not (free & ~self.nodes).any() and int(self.structure[2]) <= NODE_SET_SLACK * count

    def is_for(self, stencil: Stencil, free: np.ndarray) -> bool:
        """Whether the factor is that of ``stencil`` with the free set ``free``."""
        return self.stencil is stencil and self.free is not None and np.array_equal(self.free, free)

    def factorise(self, slot_values: np.ndarray, stencil: Stencil, free: np.ndarray) -> None:
        """Numeric factorisation for ``free`` (inside the node set); the first builds the solver."""
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
        self.free, self.stencil, self.factored_free = free.copy(), stencil, free.copy()

    def switch(self, slot_values: np.ndarray, stencil: Stencil, free: np.ndarray) -> bool:
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
        or more than :data:`SWITCH_MAX_NODES` switched.
        """
        base = self.factored_free
        if self.stencil is not stencil or base is None or self.solver is None:
            return False
        switched = free != base
        count = int(np.count_nonzero(switched))
        if count == 0 or count > SWITCH_MAX_NODES or (switched & ~self.nodes).any():
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


@dataclass(frozen=True, eq=False)
class CoarseGrid:
    """A grid halved in both directions under a solver's grid, and the maps between them.

    Coarse columns are every other fine column; coarse rows lie evenly from edge to edge, so
    a fine field is restricted by linear interpolation in z, and a coarse field is brought
    back to the fine grid bilinearly. Both nested starts (Reynolds condition and JFO) predict
    the fine cavitated set this way.

    Attributes
    ----------
    solver : ReynoldsSolver
        Solver of the coarse grid: its fixed nodes are the fine ones on the coarse rows and
        columns, and both edges.
    z_index, z_weight : ndarray (nz_c,)
        Fine row below each coarse row, and the weight of the row above it.
    row_lo, row_hi, row_w : ndarray (nz,)
        Coarse rows around each fine row, and the weight of the upper one.
    col_lo, col_hi : ndarray (nt,)
        Coarse columns around each fine column (the same one for even fine columns).
    """

    solver: ReynoldsSolver
    z_index: np.ndarray
    z_weight: np.ndarray
    row_lo: np.ndarray
    row_hi: np.ndarray
    row_w: np.ndarray
    col_lo: np.ndarray
    col_hi: np.ndarray

    @classmethod
    def under(cls, fine: ReynoldsSolver, shape: tuple[int, int]) -> CoarseGrid:
        """The coarse grid of ``shape`` (from :func:`coarse_shape`) under ``fine``."""
        nz, nt = fine.shape
        nz_c, nt_c = shape
        position = np.linspace(0.0, 1.0, nz_c) * (nz - 1)
        z_index = np.minimum(np.floor(position).astype(int), nz - 2)
        fine_in_coarse = np.linspace(0.0, 1.0, nz) * (nz_c - 1)
        row_lo = np.minimum(np.floor(fine_in_coarse).astype(int), nz_c - 2)
        rows = np.rint(position).astype(int)
        fixed_c = fine.fixed[rows][:, ::2].copy()
        value_c = fine.fixed_pressure[rows][:, ::2].copy()
        fixed_c[[0, -1]] = True
        solver = ReynoldsSolver((nz_c, nt_c), 2.0 * fine.d_theta, fine.d_z * (nz - 1) / (nz_c - 1), fixed_c, value_c)
        # Small coarse grids predict the set by sweeps (_swept_indicator); where they solve an
        # active set (a grid continuation's coarse equilibrium, a long coarsest grid, the JFO's
        # coarsest start), one symbolic analysis of the full pattern, then numeric
        # factorisations only (2-4 times cheaper there than a fresh ordering).
        solver.masked = nz_c * nt_c < PCG_MIN_NODES
        return cls(
            solver=solver,
            z_index=z_index,
            z_weight=position - z_index,
            row_lo=row_lo,
            row_hi=row_lo + 1,
            row_w=fine_in_coarse - row_lo,
            col_lo=(np.arange(nt) // 2) % nt_c,
            col_hi=((np.arange(nt) + 1) // 2) % nt_c,
        )

    def restrict(self, field: np.ndarray) -> np.ndarray:
        """A fine field (nz, nt) on the coarse grid: linear in z, every other column."""
        w = self.z_weight[:, None]
        return (field[self.z_index] * (1.0 - w) + field[self.z_index + 1] * w)[:, ::2]

    def prolong(self, field: np.ndarray) -> np.ndarray:
        """A coarse field on the fine grid, bilinearly."""
        row_w = self.row_w[:, None]
        col_w = 0.5 * (np.arange(self.col_lo.size) % 2)[None, :]
        lo = field[self.row_lo] * (1.0 - row_w) + field[self.row_hi] * row_w
        return lo[:, self.col_lo] * (1.0 - col_w) + lo[:, self.col_hi] * col_w


def _set_indicator(stencil: Stencil, pressure: np.ndarray, cavitated: np.ndarray, fixed: np.ndarray) -> np.ndarray:
    """``P - w / diag(A)``: the pressure on the full-film nodes, minus the complementarity
    multiplier ``w = A P - b`` (>= 0 there, clipped) over the diagonal on the cavitated ones,
    zero on the fixed nodes. It changes sign on the cavitation boundary, and interpolated onto
    a finer grid it places that boundary between the nodes (docs/theory.md Sect. 4)."""
    multiplier = apply_operator(stencil.c_theta, stencil.c_z, pressure) - stencil.rhs
    indicator = np.where(cavitated, -np.maximum(multiplier, 0.0) / stencil_diagonal(stencil), pressure)
    return np.where(fixed, 0.0, indicator)


def _dot(a: np.ndarray, b: np.ndarray) -> float:
    """Inner product without BLAS: a BLAS ``ddot`` on a vector this short spends more time
    waking its threads than computing, and far more on a machine shared with other work."""
    return float(np.einsum("i,i->", a, b))


def _marched_film_fraction(film: np.ndarray, cavitated: np.ndarray) -> np.ndarray:
    """Film fraction in a cavitated zone from Couette transport of the film at rupture.

    Along each circumferential line the liquid leaving the last full-film node is
    carried unchanged through the cavitated zone (pure Couette flow), so the film
    fraction is ``h_rupture / h``. Used with the Reynolds and half-Sommerfeld
    conditions, which do not compute it themselves.
    """
    nz, nt = film.shape
    full = ~cavitated
    if full.all():
        return np.ones_like(film)
    index = np.where(full, np.arange(nt)[None, :], -1)
    # Two periods so that a zone wrapping past theta = 2 pi finds its upstream full node.
    doubled = np.concatenate([index - nt, index], axis=1)
    doubled = np.where(np.concatenate([full, full], axis=1), doubled, -(10 * nt))
    last_full = np.maximum.accumulate(doubled, axis=1)[:, nt:]
    rows = np.arange(nz)[:, None]
    has_source = last_full > -(5 * nt)
    source = np.where(has_source, last_full % nt, 0)
    # A rough film may close past the mean plane (h <= 0, boundary lubrication): the gap there is
    # the asperities' valleys, full (fraction 1), never a negative share.
    has_source = has_source & (film > 0.0)
    fraction = np.where(has_source, film[rows, source] / np.where(has_source, film, 1.0), 1.0)
    return np.where(full, 1.0, np.clip(fraction, 0.0, 1.0))
