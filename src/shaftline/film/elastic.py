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
:func:`~shaftline.film.reynolds.stencil_derivative`, the film's own directional derivative
(checked against it in tests/film/test_liner.py).
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import cached_property, lru_cache

import numpy as np
import scipy.sparse as sp
import scipy.sparse.linalg as spla
from threadpoolctl import ThreadpoolController

from shaftline.film.layer import ElasticLayer
from shaftline.film.reynolds import Stencil
from shaftline.film.roughness import FilmFlow

__all__ = ["LayerSystem", "LinerSystem", "film_operator", "film_residual_jacobian"]


@lru_cache(maxsize=8)
def _face_structure(nz: int, nt: int) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """Ends ``a``, ``b`` of the theta faces (each node to its neighbour in the direction of
    rotation, periodic) and of the z faces (each row to the next), flat node numbers."""
    node = np.arange(nz * nt).reshape(nz, nt)
    return node.ravel(), np.roll(node, -1, axis=1).ravel(), node[:-1].ravel(), node[1:].ravel()


def film_residual_jacobian(
    film: np.ndarray,
    relative_pressure: np.ndarray,
    d_theta: float,
    d_z: float,
    rough: FilmFlow | None,
    film_rate: np.ndarray | None,
) -> sp.csr_matrix:
    """``B = dr/dH`` (n x n, n = nz nt, row-major), the film residual's change with the film at
    fixed pressure: the derivative of :func:`~shaftline.film.reynolds.stencil_derivative` (smooth
    or rough, with the squeeze factor) assembled face by face.

    A face between nodes ``a`` and ``b`` with conductance ``g(h_f)`` and Couette transport
    ``T(h_f)``, ``h_f = (H_a + H_b) / 2``, adds ``g (P_a - P_b) + T`` to ``r_a`` and
    ``g (P_b - P_a) - T`` to ``r_b`` (theta faces; z faces carry no transport), so both rows get
    ``g'/2 (P_a - P_b) + T'/2`` (and its negative) in the columns of ``a`` and ``b``.
    """
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
    rows = [theta_a, theta_a, theta_b, theta_b, z_a, z_a, z_b, z_b]
    cols = [theta_a, theta_b, theta_a, theta_b, z_a, z_b, z_a, z_b]
    vals = [along, along, across, across, up, up, -up, -up]
    if rough is not None and film_rate is not None:
        # The squeeze on the mean gap: r gains d_theta d_z rate Phi(H), a diagonal term.
        n = nz * nt
        rows.append(np.arange(n))
        cols.append(np.arange(n))
        vals.append((d_theta * d_z * film_rate * rough.squeeze_factor_derivative(film)).ravel())
    n = nz * nt
    return sp.csr_matrix((np.concatenate(vals), (np.concatenate(rows), np.concatenate(cols))), shape=(n, n))


def film_operator(stencil: Stencil) -> sp.csr_matrix:
    """The film operator ``A`` (n x n) of a stencil: ``A @ P = apply_operator(P)``."""
    nz, nt = stencil.c_theta.shape
    node = np.arange(nz * nt).reshape(nz, nt)
    a = np.concatenate([node.ravel(), node[:-1].ravel()])
    b = np.concatenate([np.roll(node, -1, axis=1).ravel(), node[1:].ravel()])
    c = np.concatenate([stencil.c_theta.ravel(), stencil.c_z.ravel()])
    rows = np.concatenate([a, b, a, b])
    cols = np.concatenate([a, b, b, a])
    vals = np.concatenate([c, c, -c, -c])
    return sp.csr_matrix((vals, (rows, cols)), shape=(nz * nt, nz * nt))


@dataclass(eq=False)
class LinerSystem:
    """The coupled film-liner Newton matrix at one film, factorised.

    Attributes
    ----------
    free : ndarray of bool (n,)
        Free (pressurised, not fixed) nodes, flat.
    jacobian : csr_matrix (n, n)
        ``B = dr/dH``.
    diagonal : ndarray (n,)
        ``M = 1 - k dp_a/dh`` (1 without asperity contact).
    coupling : float
        ``K = k p_ref / c``.
    factor : SuperLU
        LU of ``(A + B diag(K / M))`` on the free nodes.
    """

    free: np.ndarray
    jacobian: sp.csr_matrix
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
    ) -> LinerSystem:
        """Assemble and factorise the matrix for the film ``film`` (dimensionless) with the
        ``held`` (fixed or cavitated) nodes out."""
        jacobian = film_residual_jacobian(film, relative_pressure, d_theta, d_z, rough, film_rate)
        free = ~held.ravel()
        scale = coupling / diagonal.ravel()
        matrix = film_operator(stencil) + jacobian @ sp.diags(scale)
        sub = matrix[free][:, free].tocsc()
        # The matrix is structurally symmetric (five-point) with a dominant diagonal (the film
        # operator's, an M-matrix, and B K / M): a minimum-degree ordering of A + A^T without
        # pivoting has 0.6 times the fill of the default and factorises 20 % faster (100 x 60).
        factor = spla.splu(sub, permc_spec="MMD_AT_PLUS_A", diag_pivot_thresh=0.0, options={"SymmetricMode": True})
        return cls(free=free, jacobian=jacobian, diagonal=diagonal.ravel(), coupling=coupling, factor=factor)

    @cached_property
    def free_rows(self) -> sp.csr_matrix:
        """The free nodes' rows of ``B`` (n_free x n)."""
        return self.jacobian[self.free]

    def solve(self, film_rhs: np.ndarray, liner_rhs: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """``(dP_free, dD)`` of the coupled system ``A dP + B dD = x`` (free rows),
        ``M dD - K dP = y`` (every node) for ``x = film_rhs`` (free nodes) and ``y = liner_rhs``
        (n): ``(A + B K/M) dP = x - B y/M``, ``dD = (y + K dP)/M``. The preconditioner of the
        layer model's system (:class:`LayerSystem`)."""
        d_free = self.factor.solve(film_rhs - self.free_rows @ (liner_rhs / self.diagonal))
        d_pressure = np.zeros(liner_rhs.size)
        d_pressure[self.free] = d_free
        return d_free, (liner_rhs + self.coupling * d_pressure) / self.diagonal

    def step(self, liner_residual: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """Newton step ``(dP, dD)`` (flat, n) for the liner residual ``R`` (film residual zero)."""
        r = liner_residual.ravel()
        rhs = self.jacobian[self.free] @ (r / self.diagonal)
        d_pressure = np.zeros(r.size)
        d_pressure[self.free] = self.factor.solve(rhs)
        return d_pressure, (self.coupling * d_pressure - r) / self.diagonal

    def response(self, residual_changes: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """Pressure changes ``dP`` and their share ``K dP / M`` of the deformation change
        (k, nz, nt) for film-residual changes ``dr`` (k, nz, nt), the liner following; ``dr`` of a
        rigid film change ``dH_r`` is that of ``dH_r / M``."""
        shape = residual_changes.shape
        flat = residual_changes.reshape(shape[0], -1)
        d_pressure = np.zeros_like(flat)
        if shape[0]:
            d_pressure[:, self.free] = self.factor.solve(np.ascontiguousarray(-flat[:, self.free].T)).T
        d_deformation = self.coupling * d_pressure / self.diagonal[None, :]
        return d_pressure.reshape(shape), d_deformation.reshape(shape)


#: Relative residual of the Krylov solve of a layer-model Newton step: an inexact Newton step
#: (Dembo, Eisenstat & Steihaug 1982): the film-liner iteration converges linearly at about this
#: rate once its quadratic phase is over, and tests its own residual.
LAYER_STEP_RTOL = 1e-6
#: Relative residual of the layer model's film response (the equilibrium's Jacobian and the
#: stiffness): close enough to the exact linearisation for Newton's quadratic convergence and
#: for the stiffness against central differences (tests/film/test_liner.py).
LAYER_RESPONSE_RTOL = 1e-10
#: Krylov iterations allowed per solve (restarted GMRES: RESTART per cycle).
LAYER_RESTART = 40
LAYER_CYCLES = 5


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
    krylov_iterations : int
        GMRES iterations spent in this system's solves so far.
    """

    column: LinerSystem
    operator: sp.csr_matrix
    layer: ElasticLayer
    slope: np.ndarray
    scale: float
    clearance: float
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
    ) -> LayerSystem:
        """Assemble the operator and factorise the preconditioner for the film ``film``
        (dimensionless) with the ``held`` nodes out; ``slope`` = ``dp_a/dh`` (Pa/m)."""
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
        )
        free = column.free
        operator = film_operator(stencil)[free][:, free].tocsr()
        return cls(column, operator, layer, slope.ravel(), scale, clearance)

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
                restart=LAYER_RESTART,
                maxiter=LAYER_CYCLES,
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
        return self.solve(np.zeros(int(self.free.sum())), -r, LAYER_STEP_RTOL)

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
            d_pressure[j], d_deformation[j] = self.solve(-flat[j, self.free], liner_rhs, LAYER_RESPONSE_RTOL)
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
                matrix, rhs, rtol=LAYER_RESPONSE_RTOL, atol=0.0, restart=LAYER_RESTART, maxiter=LAYER_CYCLES
            )
        return (w / diagonal).reshape(shape)
