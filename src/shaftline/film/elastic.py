"""The film and a column-model (Winkler) liner solved together: Newton on the coupled system.

Dimensionless unknowns (docs/theory.md, "Elastic liner"): the relative pressure ``P`` on the
free nodes (the cavitated set frozen, as in the film's other derivatives) and the liner
deformation ``D = u / c`` on every node; the film is ``H = H_rigid + D``. The two equations are

    r(P, H) = A(H) P - b(H) = 0                          (Reynolds, free nodes)
    R(D, P) = D - K P - (k / c) (p_cav + p_a(c H)) = 0   (liner, every node)

with ``k`` the liner compliance (m/Pa), ``K = k p_ref / c`` and ``p_a`` the asperity pressure.
``A`` is the film operator, ``B = dr/dH`` at fixed ``P`` is as sparse as ``A`` (a node's residual
depends on the film at itself and its four neighbours) and ``dR/dD = M = 1 - k dp_a/dh`` is
diagonal, so eliminating ``dD = M^-1 (K dP - R)`` leaves one sparse system on the free nodes,

    (A + B diag(K / M)) dP = B M^-1 R   (minus the film residual, zero after a film solve),

factorised by a sparse LU (scipy's SuperLU). The same matrix gives the film's response to a
rigid film change ``dH_r`` with the liner following: the liner equation linearised is
``M dD = K dP + k p_a' dH_r``, so the film changes by ``dH = (dH_r + K dP) / M`` and
``(A + B K/M) dP = -B (dH_r / M)``.

``B`` is assembled face by face from the same conductance and transport derivatives as
:func:`~shaftline.film.stencil.stencil_derivative`, the film's own directional derivative
(checked against it in tests/film/test_liner.py).
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import cached_property, lru_cache
from typing import Protocol

import numpy as np
import scipy.sparse as sp
import scipy.sparse.linalg as spla
from threadpoolctl import ThreadpoolController

from shaftline.film.cavitation.base import SolverCounts
from shaftline.film.layer import ElasticLayer
from shaftline.film.options import LinerOptions
from shaftline.film.roughness import FilmFlow
from shaftline.film.stencil import Stencil, film_operator

__all__ = [
    "CoupledLiner",
    "CoupledOrderings",
    "LayerSystem",
    "LinerSystem",
    "film_residual_jacobian",
    "grid_splu",
]


@lru_cache(maxsize=8)
def _face_structure(nz: int, nt: int) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """Ends ``a``, ``b`` of the theta faces (each node to its neighbour in the direction of
    rotation, periodic) and of the z faces (each row to the next), flat node numbers."""
    node = np.arange(nz * nt).reshape(nz, nt)
    return node.ravel(), np.roll(node, -1, axis=1).ravel(), node[:-1].ravel(), node[1:].ravel()


@dataclass(frozen=True, eq=False)
class _FacePattern:
    """The periodic five-point pattern on an (nz, nt) grid in CSC form (row indices sorted in
    each column), shared by ``A``, ``B`` and the coupled matrix: each face's four entries
    ``(a, a), (a, b), (b, a), (b, b)`` (theta faces, then z faces) and the diagonal land in
    the slots ``slots`` (in that order), summed where they meet."""

    size: int
    indptr: np.ndarray
    indices: np.ndarray
    slots: np.ndarray

    @property
    def nnz(self) -> int:
        return int(self.indices.size)

    def matrix(self, contributions: np.ndarray) -> sp.csc_matrix:
        """The matrix whose entries are the ``contributions`` (in the order of ``slots``) summed."""
        values = np.bincount(self.slots, weights=contributions, minlength=self.nnz)
        return sp.csc_matrix((values, self.indices, self.indptr), shape=(self.size, self.size))


@lru_cache(maxsize=8)
def _face_pattern(nz: int, nt: int) -> _FacePattern:
    theta_a, theta_b, z_a, z_b = _face_structure(nz, nt)
    a, b = np.concatenate([theta_a, z_a]), np.concatenate([theta_b, z_b])
    n = nz * nt
    diagonal = np.arange(n)
    rows = np.concatenate([a, a, b, b, diagonal])
    cols = np.concatenate([a, b, a, b, diagonal])
    unique, slots = np.unique(cols * n + rows, return_inverse=True)
    indptr = np.concatenate([[0], np.cumsum(np.bincount(unique // n, minlength=n))])
    return _FacePattern(n, indptr, unique % n, slots.ravel())


def _face_derivatives(
    film: np.ndarray,
    relative_pressure: np.ndarray,
    d_theta: float,
    d_z: float,
    rough: FilmFlow | None,
    film_rate: np.ndarray | None,
) -> tuple[np.ndarray, np.ndarray, np.ndarray | None]:
    """The entries of ``B = dr/dH`` by face (:func:`film_residual_jacobian`): the value ``f_a``
    each face puts in row ``a`` (columns ``a`` and ``b``) and ``f_b`` in row ``b`` (theta faces
    then z faces, flat), and the diagonal of the squeeze term (None without it)."""
    nz, nt = film.shape
    theta_a, theta_b, z_a, z_b = _face_structure(nz, nt)
    h_east = 0.5 * (film + np.roll(film, -1, axis=1))
    h_north = 0.5 * (film[:-1] + film[1:])
    if rough is None:
        g_theta = (d_z / d_theta) * 3.0 * h_east**2
        g_z = (d_theta / d_z) * 3.0 * h_north**2
        t_theta = np.full(h_east.shape, d_z)
    else:
        g_theta = (d_z / d_theta) * rough.conductance_derivative(h_east)
        g_z = (d_theta / d_z) * rough.axial_conductance_derivative(h_north)
        t_theta = d_z * rough.transport_derivative(h_east)
    p = relative_pressure.ravel()
    along = 0.5 * (g_theta.ravel() * (p[theta_a] - p[theta_b]) + t_theta.ravel())
    across = 0.5 * (g_theta.ravel() * (p[theta_b] - p[theta_a]) - t_theta.ravel())
    up = 0.5 * g_z.ravel() * (p[z_a] - p[z_b])
    squeeze = None
    if rough is not None and film_rate is not None:
        # The squeeze on the mean gap: r gains d_theta d_z rate Phi(H), a diagonal term.
        squeeze = (d_theta * d_z * film_rate * rough.squeeze_factor_derivative(film)).ravel()
    return np.concatenate([along, up]), np.concatenate([across, -up]), squeeze


def film_residual_jacobian(
    film: np.ndarray,
    relative_pressure: np.ndarray,
    d_theta: float,
    d_z: float,
    rough: FilmFlow | None,
    film_rate: np.ndarray | None,
) -> sp.csc_matrix:
    """``B = dr/dH`` (n x n, n = nz nt, row-major), the film residual's change with the film at
    fixed pressure: the derivative of :func:`~shaftline.film.stencil.stencil_derivative` (smooth
    or rough, with the squeeze factor) assembled face by face.

    A face between nodes ``a`` and ``b`` with conductance ``g(h_f)`` and Couette transport
    ``T(h_f)``, ``h_f = (H_a + H_b) / 2``, adds ``g (P_a - P_b) + T`` to ``r_a`` and
    ``g (P_b - P_a) - T`` to ``r_b`` (theta faces; z faces carry no transport), so both rows get
    ``g'/2 (P_a - P_b) + T'/2`` (and its negative) in the columns of ``a`` and ``b``.
    """
    pattern = _face_pattern(*film.shape)
    row_a, row_b, squeeze = _face_derivatives(film, relative_pressure, d_theta, d_z, rough, film_rate)
    diagonal = np.zeros(pattern.size) if squeeze is None else squeeze
    return pattern.matrix(np.concatenate([row_a, row_a, row_b, row_b, diagonal]))


def _coupled_matrix(
    stencil: Stencil,
    pattern: _FacePattern,
    row_a: np.ndarray,
    row_b: np.ndarray,
    squeeze: np.ndarray | None,
    scale: np.ndarray,
) -> np.ndarray:
    """Values of ``A + B diag(scale)`` on every slot of ``pattern`` (the film operator's links
    ``c`` give ``c, -c, -c, c`` in a face's four entries)."""
    nz, nt = stencil.c_theta.shape
    theta_a, theta_b, z_a, z_b = _face_structure(nz, nt)
    a, b = np.concatenate([theta_a, z_a]), np.concatenate([theta_b, z_b])
    c = np.concatenate([stencil.c_theta.ravel(), stencil.c_z.ravel()])
    scale_a, scale_b = scale[a], scale[b]
    diagonal = np.zeros(pattern.size) if squeeze is None else squeeze * scale
    contributions = np.concatenate(
        [c + row_a * scale_a, row_a * scale_b - c, row_b * scale_a - c, c + row_b * scale_b, diagonal]
    )
    return np.bincount(pattern.slots, weights=contributions, minlength=pattern.nnz)


def _restriction(pattern: _FacePattern, nodes: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The sub-matrix on ``nodes`` (in that order) of a matrix on ``pattern``, as the slots of
    its CSC data (row indices sorted) with its row indices and column pointers."""
    slots = sp.csc_matrix(
        (np.arange(1.0, pattern.nnz + 1.0), pattern.indices, pattern.indptr), shape=(pattern.size, pattern.size)
    )
    sub = slots.tocsr()[nodes][:, nodes].tocsc()
    sub.sort_indices()
    return sub.data.astype(np.intp) - 1, sub.indices, sub.indptr


class CoupledLiner(Protocol):
    """The coupled film-liner Newton system at one film as the bearing uses it, whichever the
    liner model: :class:`LinerSystem` (column) or :class:`LayerSystem` (layer).

    Arrays of the film's shape are (nz, nt) or flat (n) as each method says; ``dH_r`` is a change
    of the rigid film, ``dP`` of the relative pressure, ``dD`` of the deformation, all over the
    clearance (docs/theory.md Sect. 17, "Elastic liner" and "Elastic layer")."""

    def step(self, liner_residual: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """Newton step ``(dP, dD)`` (flat, n) for the liner residual ``R`` (film residual zero)."""
        ...

    def film_direction(self, rigid_change: np.ndarray) -> np.ndarray:
        """The film change along which the film residual's change ``dr`` handed to
        :meth:`response` is taken for a rigid film change ``dH_r`` (nz, nt)."""
        ...

    def response(self, residual_changes: np.ndarray, rigid_changes: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """Pressure changes ``dP`` (k, nz, nt) and the deformation changes the solve gives with
        them (the column model: the pressure's share only) for film-residual changes ``dr``
        (k, nz, nt) of the rigid film changes ``dH_r`` (k, nz, nt), the liner following."""
        ...

    def deformation_change(self, rigid_change: np.ndarray, d_pressure: np.ndarray) -> np.ndarray:
        """``dD`` (shape of ``d_pressure``) of the linearised liner equation for ``dH_r`` and ``dP``."""
        ...

    def film_change(self, rigid_change: np.ndarray, d_pressure: np.ndarray) -> np.ndarray:
        """``dH = dH_r + dD`` (shape of ``d_pressure``), the film following ``dH_r`` and ``dP``."""
        ...


#: SuperLU's panel width and supernode relaxation of the grids' factors (:func:`grid_splu`): a
#: setting of the library call for the narrow supernodes of a 2-D grid, not a tuning of the method.
SUPERLU_PANEL = 4


class CoupledOrderings:
    """Fill-reducing orderings of the coupled film-liner matrix kept per free set.

    SuperLU's minimum-degree ordering (of ``A + A^T``) depends on the matrix's structure
    only, i.e. on the free set, and costs about a third of a factorisation on 100 x 60; a film
    seen again (the liner iteration's and the equilibrium's iterates share their cavitated set
    once it settles) is factorised in the ordering found the first time, with the sub-matrix
    permuted to it and SuperLU told to keep that order (``NATURAL``). The factor is the same
    up to round-off (the same pivots: diagonal, no pivoting); the owner clears the orderings
    where its results must not depend on earlier calls (:meth:`clear`). At most ``kept`` free
    sets are kept (``LinerOptions.kept_orderings``), the oldest dropped first; every
    factorisation is counted in ``counts.factorisations``.
    """

    def __init__(self, kept: int = LinerOptions.kept_orderings, counts: SolverCounts | None = None) -> None:
        self._sets: dict[bytes, tuple[np.ndarray, tuple[np.ndarray, np.ndarray, np.ndarray] | None]] = {}
        self.kept = kept
        self.counts = SolverCounts() if counts is None else counts

    def clear(self) -> None:
        self._sets.clear()

    def __len__(self) -> int:
        return len(self._sets)

    def factorise(self, pattern: _FacePattern, values: np.ndarray, free: np.ndarray) -> tuple[np.ndarray, spla.SuperLU]:
        """The factor of the matrix ``values`` (on ``pattern``) on the ``free`` nodes and the
        nodes (flat numbers) of its rows and columns, in order."""
        key = np.packbits(free).tobytes()
        kept = self._sets.get(key)
        self.counts.factorisations += 1
        if kept is None:
            nodes = np.flatnonzero(free)
            factor = _factorise(pattern, values, nodes, "MMD_AT_PLUS_A")
            if len(self._sets) >= self.kept:
                self._sets.pop(next(iter(self._sets)))
            # The elimination order: the sub-matrix's column perm_c[j] is eliminated j-th.
            self._sets[key] = (nodes[np.argsort(factor.perm_c)], None)
            return nodes, factor
        nodes, restriction = kept
        if restriction is None:
            restriction = _restriction(pattern, nodes)
            self._sets[key] = (nodes, restriction)
        return nodes, _factorise(pattern, values, nodes, "NATURAL", restriction)


def _factorise(
    pattern: _FacePattern,
    values: np.ndarray,
    nodes: np.ndarray,
    ordering: str,
    restriction: tuple[np.ndarray, np.ndarray, np.ndarray] | None = None,
) -> spla.SuperLU:
    """SuperLU factor of the sub-matrix on ``nodes`` (in that order) of ``values`` on ``pattern``."""
    take, indices, indptr = _restriction(pattern, nodes) if restriction is None else restriction
    sub = sp.csc_matrix((values[take], indices, indptr), shape=(nodes.size, nodes.size))
    # The matrix is structurally symmetric (five-point) with a dominant diagonal (the film
    # operator's, an M-matrix, and B K / M): a minimum-degree ordering of A + A^T without
    # pivoting has 0.6 times the fill of the default and factorises 20 % faster (100 x 60).
    return grid_splu(sub, ordering)


def grid_splu(matrix: sp.csc_matrix, ordering: str, pivot_threshold: float = 0.0) -> spla.SuperLU:
    """SuperLU's factor of a structurally symmetric five-point matrix on a grid, in
    ``ordering`` (SuperLU's ``permc_spec``), preferring diagonal pivots (``SymmetricMode``;
    ``pivot_threshold`` is SuperLU's ``diag_pivot_thresh``). Panels of
    :data:`SUPERLU_PANEL` columns (SuperLU's default 20, relaxed supernodes of 10) suit the
    narrow supernodes of a 2-D grid: 25 % faster on the film-liner matrix of 100 x 60
    (bench_liner_work.py), 13-20 % on JFO Jacobians; the relaxation is kept no larger than the
    panel, as SuperLU requires."""
    return spla.splu(
        matrix,
        permc_spec=ordering,
        diag_pivot_thresh=pivot_threshold,
        relax=SUPERLU_PANEL,
        panel_size=SUPERLU_PANEL,
        options={"SymmetricMode": True},
    )


@dataclass(eq=False)
class LinerSystem:
    """The coupled film-liner Newton matrix at one film, factorised.

    Attributes
    ----------
    free : ndarray of bool (n,)
        Free (pressurised, not fixed) nodes, flat.
    nodes : ndarray of int (n_free,)
        The free nodes (flat numbers) in the order of the factor's rows and columns.
    jacobian : csc_matrix (n, n)
        ``B = dr/dH``.
    diagonal : ndarray (n,)
        ``M = 1 - k dp_a/dh`` (1 without asperity contact).
    coupling : float
        ``K = k p_ref / c``.
    factor : SuperLU
        LU of ``(A + B diag(K / M))`` on the free nodes (in the order ``nodes``).
    """

    free: np.ndarray
    nodes: np.ndarray
    jacobian: sp.csc_matrix
    diagonal: np.ndarray
    coupling: float
    factor: spla.SuperLU

    @classmethod
    def build(
        cls,
        stencil: Stencil,
        film: np.ndarray,
        relative_pressure: np.ndarray,
        held: np.ndarray,
        d_theta: float,
        d_z: float,
        rough: FilmFlow | None,
        film_rate: np.ndarray | None,
        coupling: float,
        diagonal: np.ndarray,
        orderings: CoupledOrderings | None = None,
    ) -> LinerSystem:
        """Assemble and factorise the matrix for the film ``film`` (dimensionless) with the
        ``held`` (fixed or cavitated) nodes out, in the kept ordering of the free set when
        ``orderings`` has one (and keeping it there otherwise).

        The matrices are assembled on the grid's fixed five-point pattern
        (:func:`_face_pattern`): each face's entries summed into their slots, without sparse
        matrix arithmetic (which costs more than the numbers on 100 x 60)."""
        pattern = _face_pattern(*film.shape)
        row_a, row_b, squeeze = _face_derivatives(film, relative_pressure, d_theta, d_z, rough, film_rate)
        jacobian = pattern.matrix(
            np.concatenate([row_a, row_a, row_b, row_b, np.zeros(pattern.size) if squeeze is None else squeeze])
        )
        free = ~held.ravel()
        scale = coupling / diagonal.ravel()
        values = _coupled_matrix(stencil, pattern, row_a, row_b, squeeze, scale)
        if orderings is None:
            nodes = np.flatnonzero(free)
            factor = _factorise(pattern, values, nodes, "MMD_AT_PLUS_A")
        else:
            nodes, factor = orderings.factorise(pattern, values, free)
        return cls(
            free=free, nodes=nodes, jacobian=jacobian, diagonal=diagonal.ravel(), coupling=coupling, factor=factor
        )

    @cached_property
    def free_rows(self) -> sp.csr_matrix:
        """The free nodes' rows of ``B`` (n_free x n)."""
        return self.jacobian[self.free]

    def solve(self, film_rhs: np.ndarray, liner_rhs: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """``(dP_free, dD)`` of the coupled system ``A dP + B dD = x`` (free rows),
        ``M dD - K dP = y`` (every node) for ``x = film_rhs`` (free nodes) and ``y = liner_rhs``
        (n): ``(A + B K/M) dP = x - B y/M``, ``dD = (y + K dP)/M``. The preconditioner of the
        layer model's system (:class:`LayerSystem`)."""
        rhs = -(self.jacobian @ (liner_rhs / self.diagonal))
        rhs[self.free] += film_rhs
        d_pressure = np.zeros(liner_rhs.size)
        d_pressure[self.nodes] = self.factor.solve(rhs[self.nodes])
        return d_pressure[self.free], (liner_rhs + self.coupling * d_pressure) / self.diagonal

    def step(self, liner_residual: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """Newton step ``(dP, dD)`` (flat, n) for the liner residual ``R`` (film residual zero)."""
        r = liner_residual.ravel()
        rhs = self.jacobian @ (r / self.diagonal)
        d_pressure = np.zeros(r.size)
        d_pressure[self.nodes] = self.factor.solve(rhs[self.nodes])
        return d_pressure, (self.coupling * d_pressure - r) / self.diagonal

    def film_direction(self, rigid_change: np.ndarray) -> np.ndarray:
        """``dH_r / M`` (nz, nt): the asperity load of a rigid film change deforms the liner node
        by node, so the film residual's change for :meth:`response` is taken along it."""
        return rigid_change / self.diagonal.reshape(rigid_change.shape)

    def response(
        self, residual_changes: np.ndarray, rigid_changes: np.ndarray | None = None
    ) -> tuple[np.ndarray, np.ndarray]:
        """Pressure changes ``dP`` and their share ``K dP / M`` of the deformation change
        (k, nz, nt) for film-residual changes ``dr`` (k, nz, nt), the liner following; ``dr`` of a
        rigid film change ``dH_r`` is that of ``dH_r / M`` (:meth:`film_direction`), which holds
        the rigid change's share, so ``rigid_changes`` is not needed (:class:`CoupledLiner`)."""
        shape = residual_changes.shape
        flat = residual_changes.reshape(shape[0], -1)
        d_pressure = np.zeros_like(flat)
        if shape[0]:
            d_pressure[:, self.nodes] = self.factor.solve(np.ascontiguousarray(-flat[:, self.nodes].T)).T
        d_deformation = self.coupling * d_pressure / self.diagonal[None, :]
        return d_pressure.reshape(shape), d_deformation.reshape(shape)

    def deformation_change(self, rigid_change: np.ndarray, d_pressure: np.ndarray) -> np.ndarray:
        """``dD = (K dP + (1 - M) dH_r) / M`` (shape of ``d_pressure``), the linearised liner
        equation ``M dD = K dP + k p_a' c dH_r / c`` with ``k p_a' = 1 - M``."""
        diagonal = self.diagonal.reshape(d_pressure.shape)
        return (self.coupling * d_pressure + (1.0 - diagonal) * rigid_change) / diagonal

    def film_change(self, rigid_change: np.ndarray, d_pressure: np.ndarray) -> np.ndarray:
        """``dH = dH_r + dD = (dH_r + K dP) / M`` (shape of ``d_pressure``)."""
        return (rigid_change + self.coupling * d_pressure) / self.diagonal.reshape(d_pressure.shape)


@lru_cache(maxsize=1)
def _threadpools() -> ThreadpoolController:
    """The BLAS thread pools loaded (numpy's and scipy's), found once."""
    return ThreadpoolController()


@dataclass(eq=False)
class LayerSystem:
    """The coupled film-liner Newton system of a bonded elastic layer (docs/theory.md Sect. 17,
    "Elastic layer"), solved by right-preconditioned GMRES with the column model's factor.

    The liner equation is ``R = D - C(p_ref P + p_cav + p_a(c H)) / c`` with ``C`` the layer's
    dense compliance (:class:`~shaftline.film.layer.ElasticLayer`, applied by FFT), so with
    ``s = dp_a/dh`` the Newton matrix on ``(dP_free, dD)`` is

        [ A      B           ]
        [ -K_C   I - C diag(s)],   K_C = C p_ref / c,

    never formed: a product costs two sparse products and one FFT pair. The preconditioner is
    the same system with ``C`` replaced by a column liner of the layer's self-compliance
    ``k_self`` (the diagonal of ``C``; :class:`LinerSystem`, one sparse LU).

    Attributes
    ----------
    column : LinerSystem
        The preconditioner (with ``K = k_self p_ref / c``, ``M = 1 - k_self s``).
    operator : csr_matrix (n_free, n_free)
        The film operator ``A`` on the free nodes.
    layer : ElasticLayer
        The compliance ``C``, m/Pa.
    slope : ndarray (n,)
        ``dp_a/dh``, Pa/m (zero without asperities).
    scale : float
        The film's pressure scale ``p_ref``, Pa.
    clearance : float
        Radial clearance ``c``, m.
    options : LinerOptions
        The Krylov solves' tolerances and iteration limits (``layer_step_rtol``,
        ``layer_response_rtol``, ``layer_restart``, ``layer_cycles``).
    krylov_iterations : int
        GMRES iterations spent in this system's solves so far.
    """

    column: LinerSystem
    operator: sp.csr_matrix
    layer: ElasticLayer
    slope: np.ndarray
    scale: float
    clearance: float
    options: LinerOptions = LinerOptions()
    krylov_iterations: int = 0

    @classmethod
    def build(
        cls,
        stencil: Stencil,
        film: np.ndarray,
        relative_pressure: np.ndarray,
        held: np.ndarray,
        d_theta: float,
        d_z: float,
        rough: FilmFlow | None,
        film_rate: np.ndarray | None,
        layer: ElasticLayer,
        slope: np.ndarray,
        scale: float,
        clearance: float,
        orderings: CoupledOrderings | None = None,
        options: LinerOptions | None = None,
    ) -> LayerSystem:
        """Assemble the operator and factorise the preconditioner for the film ``film``
        (dimensionless) with the ``held`` nodes out; ``slope`` = ``dp_a/dh`` (Pa/m);
        ``orderings`` as in :meth:`LinerSystem.build`; ``options`` the Krylov solves'."""
        k_self = layer.self_compliance
        diagonal = 1.0 - k_self * slope
        column = LinerSystem.build(
            stencil,
            film,
            relative_pressure,
            held,
            d_theta,
            d_z,
            rough,
            film_rate,
            k_self * scale / clearance,
            diagonal,
            orderings,
        )
        free = column.free
        operator = film_operator(stencil)[free][:, free].tocsr()
        return cls(column, operator, layer, slope.ravel(), scale, clearance, options or LinerOptions())

    @property
    def free(self) -> np.ndarray:
        return self.column.free

    def _deflection(self, load: np.ndarray) -> np.ndarray:
        """``C load / c`` (flat), ``load`` (Pa, flat)."""
        shape = self.layer.shape
        return self.layer.apply(load.reshape(shape)).ravel() / self.clearance

    def _product(self, d_free: np.ndarray, d_deformation: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        d_pressure = np.zeros(d_deformation.size)
        d_pressure[self.free] = d_free
        film = self.operator @ d_free + self.column.free_rows @ d_deformation
        load = self.scale * d_pressure + self.clearance * self.slope * d_deformation
        return film, d_deformation - self._deflection(load)

    def solve(self, film_rhs: np.ndarray, liner_rhs: np.ndarray, rtol: float) -> tuple[np.ndarray, np.ndarray]:
        """``(dP, dD)`` (flat, n; dP zero on the held nodes) of the Newton system for the
        right-hand sides ``film_rhs`` (free nodes) and ``liner_rhs`` (n), to a relative residual
        ``rtol`` (GMRES on the system right-preconditioned by :attr:`column`)."""
        n_free = int(self.free.sum())
        n = liner_rhs.size

        def precondition(w: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
            return self.column.solve(w[:n_free], w[n_free:])

        def product(w: np.ndarray) -> np.ndarray:
            return np.concatenate(self._product(*precondition(w)))

        rhs = np.concatenate([film_rhs, liner_rhs])
        d_pressure = np.zeros(n)
        if not np.any(rhs):
            return d_pressure, np.zeros(n)
        count = [0]

        def counter(_: float) -> None:
            count[0] += 1

        matrix = spla.LinearOperator((n_free + n, n_free + n), matvec=product, dtype=float)
        # GMRES's inner products on vectors of 1e4 are BLAS level 1: threads only cost there
        # (8 times slower with two threads on a busy two-core machine, bench_liner_work.py).
        with _threadpools().limit(limits=1, user_api="blas"):
            w, _ = spla.gmres(
                matrix,
                rhs,
                rtol=rtol,
                atol=0.0,
                restart=self.options.layer_restart,
                maxiter=self.options.layer_cycles,
                callback=counter,
                callback_type="pr_norm",
            )
        self.krylov_iterations += count[0]
        d_free, d_deformation = precondition(w)
        d_pressure[self.free] = d_free
        return d_pressure, d_deformation

    def step(self, liner_residual: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """Newton step ``(dP, dD)`` (flat, n) for the liner residual ``R`` (film residual zero)."""
        r = liner_residual.ravel()
        return self.solve(np.zeros(int(self.free.sum())), -r, self.options.layer_step_rtol)

    def film_direction(self, rigid_change: np.ndarray) -> np.ndarray:
        """``dH_r`` itself: the layer's solve (:meth:`response`) takes the asperity load's share."""
        return rigid_change

    def response(self, residual_changes: np.ndarray, rigid_changes: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """Pressure and deformation changes ``dP``, ``dD`` (k, nz, nt) for film-residual changes
        ``dr`` (k, nz, nt) of rigid film changes ``dH_r`` (k, nz, nt), the liner following:
        ``A dP + B dD = -dr``, ``(I - C s) dD - K_C dP = C s c dH_r / c``."""
        shape = residual_changes.shape
        flat = residual_changes.reshape(shape[0], -1)
        rigid = rigid_changes.reshape(shape[0], -1)
        d_pressure = np.zeros_like(flat)
        d_deformation = np.zeros_like(flat)
        for j in range(shape[0]):  # one Krylov solve per direction (2 to 8 of them)
            liner_rhs = self._deflection(self.clearance * self.slope * rigid[j])
            rtol = self.options.layer_response_rtol
            d_pressure[j], d_deformation[j] = self.solve(-flat[j, self.free], liner_rhs, rtol)
        return d_pressure.reshape(shape), d_deformation.reshape(shape)

    def deformation_change(self, rigid_change: np.ndarray, d_pressure: np.ndarray) -> np.ndarray:
        """``dD`` (shape of ``d_pressure``) of the linearised liner equation for a rigid film
        change ``dH_r`` and a pressure change ``dP``: ``(I - C s) dD = C (p_ref dP + s c dH_r) / c``
        (GMRES preconditioned by ``1 - k_self s`` where there is asperity contact)."""
        shape = d_pressure.shape
        rhs = self._deflection(self.scale * d_pressure.ravel() + self.clearance * self.slope * rigid_change.ravel())
        if not np.any(self.slope):
            return rhs.reshape(shape)
        diagonal = self.column.diagonal

        def product(w: np.ndarray) -> np.ndarray:
            x = w / diagonal
            return x - self._deflection(self.clearance * self.slope * x)

        matrix = spla.LinearOperator((rhs.size, rhs.size), matvec=product, dtype=float)
        with _threadpools().limit(limits=1, user_api="blas"):
            w, _ = spla.gmres(
                matrix,
                rhs,
                rtol=self.options.layer_response_rtol,
                atol=0.0,
                restart=self.options.layer_restart,
                maxiter=self.options.layer_cycles,
            )
        return (w / diagonal).reshape(shape)

    def film_change(self, rigid_change: np.ndarray, d_pressure: np.ndarray) -> np.ndarray:
        """``dH = dH_r + dD`` (shape of ``d_pressure``), ``dD`` of :meth:`deformation_change`."""
        return rigid_change + self.deformation_change(rigid_change, d_pressure)
