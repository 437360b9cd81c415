"""Linearised stiffness and damping of the film at an equilibrium.

``K_ij = -dF_i/dq_j`` and ``C_ij = -dF_i/dq'_j`` with ``q = (y, z)`` the journal
centre offsets and ``q'`` their velocities, in the shaft axes (y up, z
starboard); the 4 x 4 set adds the journal tilts to ``q`` and the film moments
about the mid-plane to ``F``. They come from the Reynolds equation linearised about the solution
with the cavitation boundary frozen, using the factorisation of the converged
active set (exact to first order for the Swift-Stieber condition, where
``p = dp/dn = 0`` on the boundary); for the JFO model, from the JFO system
linearised with its void-fraction transport (docs/theory.md, Eq. C4).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from shaftline.film.bearing import BearingState, JournalBearing


@dataclass(frozen=True, eq=False)
class DynamicCoefficients:
    """Film stiffness (N/m) and damping (N*s/m) matrices, rows/columns (y, z), and the full
    4 x 4 set with the tilt (moment) coefficients.

    Attributes
    ----------
    stiffness : ndarray (2, 2)
        ``[[K_yy, K_yz], [K_zy, K_zz]]``, N/m.
    damping : ndarray (2, 2)
        ``[[C_yy, C_yz], [C_zy, C_zz]]``, N*s/m.
    stiffness_4x4, damping_4x4 : ndarray (4, 4) or None
        ``-d(F_y, F_z, M_y, M_z)/d(ey, ez, tilt_y, tilt_z)`` and the same by the rates
        (:class:`shaftline.film.bearing.TiltLinearisation`); ``stiffness`` and ``damping``
        are their top-left blocks. None where not computed.

    Equality is identity: the fields hold arrays, which have no single truth value.
    """

    stiffness: np.ndarray
    damping: np.ndarray
    stiffness_4x4: np.ndarray | None = None
    damping_4x4: np.ndarray | None = None

    def dimensionless(self, load: float, clearance: float, speed: float) -> tuple[np.ndarray, np.ndarray]:
        """``K c / W`` and ``C c omega / W``, the usual design-chart groups."""
        return self.stiffness * clearance / load, self.damping * clearance * speed / load


def dynamic_coefficients(bearing: JournalBearing, state: BearingState) -> DynamicCoefficients:
    """Stiffness and damping of ``bearing`` about the position of ``state``, with the tilt.

    The negated derivatives of :meth:`JournalBearing.linearise_with_tilt` at
    ``state.position``, started from the state's cavitated set (the film solution there is
    unique, so this only spares the cold start); the 2 x 2 matrices are its top-left blocks,
    identical to those of :meth:`JournalBearing.linearise`.
    """
    linearisation = bearing.linearise_with_tilt(state.position, initial_cavitated=state.cavitated)
    return DynamicCoefficients(
        stiffness=linearisation.stiffness[:2, :2],
        damping=linearisation.damping[:2, :2],
        stiffness_4x4=linearisation.stiffness,
        damping_4x4=linearisation.damping,
    )
