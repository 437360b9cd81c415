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
from typing import TYPE_CHECKING, Any

import numpy as np

from shaftline import export
from shaftline.export import quantity

if TYPE_CHECKING:
    from shaftline.film.bearing import JournalBearing
    from shaftline.film.results import BearingState


def _listed(matrix: np.ndarray) -> list[Any]:
    return matrix.tolist()


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

    stiffness: np.ndarray = quantity(
        "N/m, [[Kyy, Kyz], [Kzy, Kzz]]",
        "film stiffness matrix in (y, z); null where the film fails",
        convert=_listed,
    )
    damping: np.ndarray = quantity(
        "N s/m, [[Cyy, Cyz], [Czy, Czz]]",
        "film damping matrix in (y, z); null where the film fails",
        convert=_listed,
    )
    stiffness_4x4: np.ndarray | None = quantity(
        "rows (Fy, Fz) in N, (My, Mz) in N m; columns (ey, ez) per m, (tilt_y, tilt_z) per rad",
        "-d(Fy, Fz, My, Mz)/d(ey, ez, tilt_y, tilt_z): film stiffness with the tilt (moment) terms, "
        "M the first moments about mid-plane as moment_y, moment_z; `stiffness` is its top-left block; "
        "null where the film fails",
        convert=_listed,
        default=None,
    )
    damping_4x4: np.ndarray | None = quantity(
        "as stiffness_4x4, per m/s and per rad/s",
        "-d(Fy, Fz, My, Mz)/d(vy, vz, tilt rates): film damping with the tilt terms; `damping` is "
        "its top-left block; null where the film fails",
        convert=_listed,
        default=None,
    )

    def to_dict(self) -> dict[str, Any]:
        """The four matrices as nested lists (None where not computed)."""
        return export.to_dict(self)

    @staticmethod
    def absent() -> dict[str, None]:
        """The keys of :meth:`to_dict` with null values: where the film does not carry the load
        there is no linearisation."""
        return dict.fromkeys(export.units(DynamicCoefficients))

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
