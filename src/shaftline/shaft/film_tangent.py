"""Influence coefficients of a line whose bearings sit on their films: the tangent at the coupled
equilibrium.

Raising a bearing by ``d`` changes the reactions of a point-supported line linearly while its
contact set holds (:meth:`~shaftline.shaft.alignment.AlignmentModel.influence_matrix`). On a
film bearing the film's stiffness takes part as well: raising the bore squeezes the film, whose
force changes by its stiffness times the journal's motion relative to the bore, and that force
moves the shaft again. At the converged coupled solution ``s = G(f(s - r(o)) + K0 (s - o), o)``
(:mod:`shaftline.shaft.coupled`: ``s`` the shaft's degrees of freedom across the film bearings,
``G`` the inner point-support problem with its contact set held, ``f`` the nodal film forces,
``r(o)`` the bores and ``K0`` the auxiliary springs) the derivative by the offsets ``o`` solves

    (I - dG/df (df/ds + K0)) ds/do = dG/do - dG/df (df/ds + K0) t,

``t`` the unit rise of each film bearing's bore at its nodes (a rigid translation: deflections 1,
rotations 0). The matrix on the left is the coupled Newton iteration's own Jacobian, and both
planes are solved together, so the film's cross-coupling of vertical and horizontal motion is
in the result. The reactions follow: a point bearing's from the inner problem's reaction
response, a film bearing's as the change of its film resultant ``(df/ds) (ds/do - t)``
(docs/theory.md, Sect. 10.1). These derivatives are exact for the film's frozen cavitated set
and the held contact set, as the coupled Jacobian is; a finite difference of re-solved
equilibria agrees with them (tests/shaft/test_film_tangent.py).
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any, Protocol

import numpy as np

from shaftline.shaft.alignment import AlignmentModel, ConditionResult, InfluenceMatrix


class _FilmPart(Protocol):
    """What the tangent needs of one film bearing of the coupled solver."""

    index: int
    dofs: np.ndarray
    point_dofs: np.ndarray
    spring: float


def tangent_influence(
    model: AlignmentModel,
    inner: ConditionResult,
    films: Sequence[_FilmPart | Any],
    slices: Sequence[slice],
    jacobian: np.ndarray,
    stiffness: np.ndarray,
    condition: str,
) -> InfluenceMatrix:
    """d reaction_i / d offset_j (vertical) of every bearing of a film-supported line at its
    converged coupled solution, and d deflection / d offset_j of every node.

    Parameters
    ----------
    model : AlignmentModel
        The inner point-support problem (film bearings on their auxiliary springs).
    inner : ConditionResult
        Its solution at the coupled equilibrium (its contact set is held).
    films : sequence
        The film bearings of the coupled solver (their line index, nodal dofs, auxiliary spring
        points and stiffness).
    slices : sequence of slice
        Each film's place in the stacked film dofs of one plane.
    jacobian : ndarray (2m, 2m)
        The coupled Newton Jacobian ``I - dG/df (df/ds + K0)`` at the equilibrium.
    stiffness : ndarray (2m, 2m)
        ``df/ds + K0`` there (nodal film forces with the auxiliary springs, N/m and N/rad ...).
    condition : str
        The condition's name, kept in the result's label.

    Returns
    -------
    InfluenceMatrix
        ``kind = "film_tangent"``; not symmetric in general (a film's stiffness is not).
    """
    mesh = model.mesh
    supports = model.supports
    bearings = len(model.line.bearings)
    m = jacobian.shape[0] // 2
    # The rise of each bearing at every support point of the inner problem (film bearings' on
    # their auxiliary springs, which the K0 term of the right-hand side cancels).
    grouping = np.zeros((supports.x.size, bearings))
    grouping[np.arange(supports.x.size), supports.bearing] = 1.0
    direct_u, direct_r = model.linear_response(inner, True, offsets=grouping)
    rise = np.zeros((2 * m, bearings))
    springs = np.zeros(2 * m)
    unit_forces = [np.zeros((2 * mesh.nodes, m)), np.zeros((2 * mesh.nodes, m))]
    for film, part in zip(films, slices, strict=True):
        rise[part.start : part.stop : 2, film.index] = 1.0
        springs[part.start + film.point_dofs] = film.spring
        springs[m + part.start + film.point_dofs] = film.spring
        for plane in range(2):
            unit_forces[plane][film.dofs, np.arange(part.start, part.stop)] = 1.0
    force_u = []
    force_r = []
    for plane in range(2):
        u, r = model.linear_response(inner, plane == 0, forces=unit_forces[plane])
        force_u.append(u)
        force_r.append(r)
    dofs = np.concatenate([film.dofs for film in films])
    response = np.zeros((2 * m, 2 * m))
    response[:m, :m] = force_u[0][dofs]
    response[m:, m:] = force_u[1][dofs]
    rhs = np.zeros((2 * m, bearings))
    rhs[:m] = direct_u[dofs]
    rhs -= response @ (stiffness @ rise)
    motion = np.linalg.solve(jacobian, rhs)  # ds/do, both planes
    relative = motion - rise
    nodal = stiffness @ relative  # the change of the forces the inner problem is given
    vertical_u = direct_u + force_u[0] @ nodal[:m]
    reactions = grouping.T @ (direct_r + force_r[0] @ nodal[:m])
    film_force = nodal - springs[:, None] * relative  # the films' own part (the springs cancel)
    for film, part in zip(films, slices, strict=True):
        reactions[film.index] = film_force[part.start : part.stop : 2].sum(axis=0)
    return InfluenceMatrix(
        names=[b.name for b in model.line.bearings],
        matrix=reactions,
        deflection=vertical_u[0::2],
        kind="film_tangent",
        condition=condition,
    )
