"""Linearised stiffness and damping of the film at an equilibrium.

``K_ij = -dF_i/dq_j`` and ``C_ij = -dF_i/dq'_j`` with ``q = (y, z)`` the journal
centre offsets and ``q'`` their velocities, in the shaft axes (y up, z
starboard). They come from the Reynolds equation linearised about the solution
with the cavitation boundary frozen, using the factorisation of the converged
active set (exact to first order for the Swift-Stieber condition, where
``p = dp/dn = 0`` on the boundary; an approximation for JFO reformation).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from shaftline.film.bearing import BearingState, JournalBearing


@dataclass(frozen=True)
class DynamicCoefficients:
    """Film stiffness (N/m) and damping (N*s/m) matrices, rows/columns (y, z).

    Attributes
    ----------
    stiffness : ndarray (2, 2)
        ``[[K_yy, K_yz], [K_zy, K_zz]]``, N/m.
    damping : ndarray (2, 2)
        ``[[C_yy, C_yz], [C_zy, C_zz]]``, N*s/m.
    """

    stiffness: np.ndarray
    damping: np.ndarray

    def dimensionless(self, load: float, clearance: float, speed: float) -> tuple[np.ndarray, np.ndarray]:
        """``K c / W`` and ``C c omega / W``, the usual design-chart groups."""
        return self.stiffness * clearance / load, self.damping * clearance * speed / load


def dynamic_coefficients(bearing: JournalBearing, state: BearingState) -> DynamicCoefficients:
    """Stiffness and damping of ``bearing`` about the position of ``state``."""
    evaluation = bearing._evaluate(state.position, warm=False)
    theta = evaluation.grid.theta
    c = bearing.geometry.radial_clearance
    s = bearing.geometry.rotation
    shape = evaluation.film.shape
    d_ey = np.broadcast_to(-np.cos(theta) / c, shape)
    d_ez = np.broadcast_to(-s * np.sin(theta) / c, shape)
    omega = bearing.operating.speed
    zero = np.zeros(shape)
    directions = [
        (d_ey, None),
        (d_ez, None),
        (zero, (2.0 / omega) * d_ey),
        (zero, (2.0 / omega) * d_ez),
    ]
    dfy, dfz, dfvy, dfvz = bearing._force_derivatives(evaluation, directions)
    stiffness = -np.column_stack([dfy, dfz])
    damping = -np.column_stack([dfvy, dfvz])
    return DynamicCoefficients(stiffness=stiffness, damping=damping)
