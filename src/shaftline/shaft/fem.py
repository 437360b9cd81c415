"""Beam finite elements of the shaft line (one bending plane at a time).

Two-node elements with deflection v and section rotation theta per node, theta
positive turning +x towards +y (nose-up). Timoshenko elements use the shear
parameter phi = 12 E I / (kappa G A L^2) (Przemieniecki 1968; Friedman & Kosmatka
1993 interdependent interpolation), exact for end loads and uniform load;
phi = 0 gives Euler-Bernoulli. The shear coefficient of a hollow circular
section is Cowper's (1966):

    kappa = 6 (1 + nu) (1 + m^2)^2 / ((7 + 6 nu)(1 + m^2)^2 + (20 + 12 nu) m^2),  m = d_i / d_o.

The stiffness matrix is banded (three super-diagonals) and stored in LAPACK's
upper band form, so a factorisation and many right-hand sides cost microseconds
per element.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from scipy.linalg import cho_solve_banded, cholesky_banded

from shaftline.shaft.model import ShaftLine


def shear_coefficient(outer: np.ndarray, inner: np.ndarray, poisson: np.ndarray) -> np.ndarray:
    """Cowper's shear coefficient of a (hollow) circular section."""
    m2 = (inner / outer) ** 2
    return 6.0 * (1 + poisson) * (1 + m2) ** 2 / ((7 + 6 * poisson) * (1 + m2) ** 2 + (20 + 12 * poisson) * m2)


@dataclass(frozen=True, eq=False)
class Mesh:
    """Nodes and element properties along the shaft.

    Attributes
    ----------
    x : ndarray (n,)
        Node stations, m.
    length : ndarray (n-1,)
        Element lengths, m.
    bending_stiffness : ndarray (n-1,)
        E I, N m^2.
    shear_parameter : ndarray (n-1,)
        phi = 12 E I / (kappa G A L^2) (0 for Euler-Bernoulli).
    area : ndarray (n-1,)
        Cross-section area, m^2.
    inertia : ndarray (n-1,)
        Second moment of area, m^4.
    outer_diameter : ndarray (n-1,)
        Outer diameter at the element middle, m.
    weight_per_length : ndarray (n-1,)
        rho g A, N/m.
    """

    x: np.ndarray
    length: np.ndarray
    bending_stiffness: np.ndarray
    shear_parameter: np.ndarray
    area: np.ndarray
    inertia: np.ndarray
    outer_diameter: np.ndarray
    weight_per_length: np.ndarray

    @property
    def nodes(self) -> int:
        return self.x.size

    def node_at(self, x: float | np.ndarray) -> np.ndarray:
        """Index of the node nearest to station(s) x."""
        x = np.asarray(x, dtype=float)
        right = np.clip(np.searchsorted(self.x, x), 1, self.nodes - 1)
        left = right - 1
        return np.where(np.abs(self.x[left] - x) <= np.abs(self.x[right] - x), left, right)


#: Stations closer than this share a node, m. Much shorter elements would make the
#: Euler-Bernoulli stiffness (12 EI / L^3) ill-conditioned beside ordinary ones.
NODE_MERGE_DISTANCE = 1e-3


def build_mesh(line: ShaftLine, stations: np.ndarray) -> Mesh:
    """Mesh with a node at every segment boundary and at every station in ``stations``.

    Stations within :data:`NODE_MERGE_DISTANCE` of a kept one are merged into it
    (segment boundaries are kept first), so a support or load may move by up to 1 mm.
    """
    length = line.length
    edges = line.segment_edges()
    extra = np.sort(np.clip(np.asarray(stations, dtype=float), 0.0, length))
    kept = list(edges)
    for station in extra:
        if np.min(np.abs(np.asarray(kept) - station)) >= NODE_MERGE_DISTANCE:
            kept.append(station)
    key = sorted(kept)
    points = [key[0]]
    for a, b in zip(key[:-1], key[1:], strict=True):
        if b - a < 1e-9:
            continue
        pieces = max(1, math.ceil((b - a) / line.element_length - 1e-9))
        points.extend(a + (b - a) * np.arange(1, pieces + 1) / pieces)
    x = np.array(points)
    middle = 0.5 * (x[:-1] + x[1:])
    edges = line.segment_edges()
    owner = np.clip(np.searchsorted(edges, middle, side="right") - 1, 0, len(line.segments) - 1)
    outer = np.empty(middle.size)
    inner = np.empty(middle.size)
    youngs = np.empty(middle.size)
    shear = np.empty(middle.size)
    poisson = np.empty(middle.size)
    density = np.empty(middle.size)
    factor = np.full(middle.size, np.nan)
    for k, segment in enumerate(line.segments):
        pick = owner == k
        fraction = (middle[pick] - edges[k]) / segment.length
        outer[pick], inner[pick] = segment.diameters_at(fraction)
        youngs[pick] = segment.youngs_modulus
        shear[pick] = segment.shear
        poisson[pick] = segment.poisson_ratio
        density[pick] = segment.density
        if segment.shear_area_factor is not None:
            factor[pick] = segment.shear_area_factor
    area = np.pi / 4 * (outer**2 - inner**2)
    inertia = np.pi / 64 * (outer**4 - inner**4)
    element_length = np.diff(x)
    bending = youngs * inertia
    if line.beam_theory == "timoshenko":
        kappa = np.where(np.isnan(factor), shear_coefficient(outer, inner, poisson), factor)
        phi = 12.0 * bending / (kappa * shear * area * element_length**2)
    else:
        phi = np.zeros_like(bending)
    weight = density * area * line.gravity if line.self_weight else np.zeros_like(area)
    return Mesh(x, element_length, bending, phi, area, inertia, outer, weight)


def element_stiffness(mesh: Mesh) -> np.ndarray:
    """Element stiffness matrices, shape (n-1, 4, 4), dofs (v1, theta1, v2, theta2)."""
    length = mesh.length
    phi = mesh.shear_parameter
    scale = mesh.bending_stiffness / ((1 + phi) * length**3)
    ll = length
    k = np.empty((length.size, 4, 4))
    k[:, 0] = np.stack([12 + 0 * ll, 6 * ll, -12 + 0 * ll, 6 * ll], axis=1)
    k[:, 1] = np.stack([6 * ll, (4 + phi) * ll**2, -6 * ll, (2 - phi) * ll**2], axis=1)
    k[:, 2] = np.stack([-12 + 0 * ll, -6 * ll, 12 + 0 * ll, -6 * ll], axis=1)
    k[:, 3] = np.stack([6 * ll, (2 - phi) * ll**2, -6 * ll, (4 + phi) * ll**2], axis=1)
    return k * scale[:, None, None]


def banded_stiffness(mesh: Mesh, k: np.ndarray) -> np.ndarray:
    """Global stiffness in LAPACK upper band form, shape (4, 2n)."""
    n = 2 * mesh.nodes
    band = np.zeros((4, n))
    for a in range(4):
        for b in range(a, 4):
            # entry (row 2e + a, col 2e + b) goes to band[3 + a - b, 2e + b]
            np.add.at(band[3 + a - b], 2 * np.arange(mesh.nodes - 1) + b, k[:, a, b])
    return band


def uniform_load_vector(mesh: Mesh, load: np.ndarray) -> np.ndarray:
    """Consistent nodal forces of a uniform load per element (N/m, + up), shape (2n,)."""
    length = mesh.length
    f = np.zeros(2 * mesh.nodes)
    np.add.at(f, 2 * np.arange(mesh.nodes - 1), 0.5 * load * length)
    np.add.at(f, 2 * np.arange(mesh.nodes - 1) + 1, load * length**2 / 12)
    np.add.at(f, 2 * np.arange(mesh.nodes - 1) + 2, 0.5 * load * length)
    np.add.at(f, 2 * np.arange(mesh.nodes - 1) + 3, -load * length**2 / 12)
    return f


class PinnedBeam:
    """The stiffness of one bending plane with some degrees of freedom held at zero, factorised once.

    The alignment pins the deflection at two nodes, which removes the rigid-body motion;
    any self-equilibrated load then has the true shaft deflection up to a rigid line,
    which the alignment solution supplies. ``fixed_dofs`` are global dof numbers
    (2 * node for deflection, 2 * node + 1 for rotation).
    """

    def __init__(self, mesh: Mesh, fixed_dofs: tuple[int, ...]) -> None:
        self.mesh = mesh
        self.k = element_stiffness(mesh)
        band = banded_stiffness(mesh, self.k)
        self._pinned_dofs = np.array(fixed_dofs, dtype=int)
        scale = float(band[3].max())
        for dof in self._pinned_dofs:
            for d in range(1, 4):
                if dof + d < band.shape[1]:
                    band[3 - d, dof + d] = 0.0  # row dof, column dof + d
                if dof - d >= 0:
                    band[3 - d, dof] = 0.0  # row dof - d, column dof
            band[3, dof] = scale
        self.factor = cholesky_banded(band, lower=False, check_finite=False)

    def solve(self, forces: np.ndarray, prescribed: np.ndarray | None = None) -> np.ndarray:
        """Displacements (2n,) or (2n, m) for nodal forces of the same shape.

        The fixed dofs take the values ``prescribed`` (same order as ``fixed_dofs``;
        zero when omitted); their effect on the free dofs moves to the right-hand side.
        """
        rhs = np.array(forces, dtype=float, copy=True)
        if prescribed is not None and np.any(prescribed):
            imposed = np.zeros(rhs.shape[0])
            imposed[self._pinned_dofs] = prescribed
            rhs = rhs - (self.internal_forces(imposed) if rhs.ndim == 1 else self.internal_forces(imposed)[:, None])
        rhs[self._pinned_dofs] = 0.0
        u = cho_solve_banded((self.factor, False), rhs, check_finite=False)
        if prescribed is not None:
            u[self._pinned_dofs] = prescribed if u.ndim == 1 else np.asarray(prescribed)[:, None]
        return u

    def internal_forces(self, displacement: np.ndarray) -> np.ndarray:
        """K u of the unconstrained beam, (2n,)."""
        nodes = self.mesh.nodes
        index = 2 * np.arange(nodes - 1)[:, None] + np.arange(4)[None, :]
        internal = np.zeros(2 * nodes)
        np.add.at(internal, index, np.einsum("eab,eb->ea", self.k, displacement[index]))
        return internal

    def reactions(self, displacement: np.ndarray, forces: np.ndarray) -> np.ndarray:
        """Forces the fixed degrees of freedom exert on the beam: (K u - f) at those dofs."""
        return (self.internal_forces(displacement) - forces)[self._pinned_dofs]

    def end_forces(self, displacement: np.ndarray, uniform_load: np.ndarray) -> np.ndarray:
        """Forces of the nodes on each element, (n-1, 4): (V1, M1, V2, M2), less the element load."""
        nodes = self.mesh.nodes
        index = 2 * np.arange(nodes - 1)[:, None] + np.arange(4)[None, :]
        u = displacement[index]
        length = self.mesh.length
        equivalent = np.stack(
            [
                0.5 * uniform_load * length,
                uniform_load * length**2 / 12,
                0.5 * uniform_load * length,
                -uniform_load * length**2 / 12,
            ],
            axis=1,
        )
        return np.einsum("eab,eb->ea", self.k, u) - equivalent
