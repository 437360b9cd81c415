"""How the load of a gear pair is shared between the teeth in contact along the path A..E.

Two ways (docs/theory.md Sect. 19.1):

* :func:`iso_load_sharing` - the load-sharing factor X_Gamma of the flash-temperature method
  (ISO/TS 6336-20, DIN 3990-4 / ISO/TR 13989-1 before it) for profiles without tip relief: in
  the double contact A..B the entering pair carries ``(Q - 2)/15`` at A (Q = 7 for accuracy
  grades 7 and finer: 1/3), rising linearly by 1/3 towards B; the single contact B..D carries
  the whole load; D..E mirrors A..B. For grade Q <= 7 the two pairs' shares add to 1; a coarser
  grade makes the entering pair carry more (their sum exceeds 1, the standard's allowance for
  pitch errors). Helical pairs with overlap ratio >= 1 carry ``1/eps_alpha`` everywhere (the
  mean load of wide helical gears); narrow helical pairs (eps_beta < 1) take the spur shape.
  ISO's buttressing factor near the tips of helical teeth is not applied.
* :func:`tabulated_load_sharing` - a share given as a table over the path (from a load
  distribution program, as seed 002 took it from LDP), interpolated linearly.

The normal load per unit length of contact line is ``X_Gamma T_1 / (r_b1 b)`` (spur and
helical: the normal force ``T_1 / (r_b1 cos beta_b)`` on a line ``b / cos beta_b`` long).
"""

from __future__ import annotations

import numpy as np

from shaftline.errors import InputError, first_offending
from shaftline.gears.mesh import GearPair


def iso_load_sharing(pair: GearPair, position: np.ndarray, accuracy_grade: int = 7) -> np.ndarray:
    """Load-sharing factor X_Gamma at positions rho_1 (m) on the path, profiles without tip relief.

    Parameters
    ----------
    pair : GearPair
    position : ndarray
        rho_1, distance from T1 along the line of action, m (within A..E).
    accuracy_grade : int
        ISO 1328 flank tolerance grade; Q = max(grade, 7) sets the share at A and E, (Q - 2)/15.

    Examples
    --------
    >>> import math
    >>> pair = GearPair(20, 40, 5e-3, math.radians(20.0), 20e-3)
    >>> p = pair.points()
    >>> at = [p["A"], (p["A"] + p["B"]) / 2, p["B"], p["C"], p["D"], p["E"]]
    >>> [round(float(iso_load_sharing(pair, x)), 4) for x in at]  # B..D: single contact
    [0.3333, 0.5, 1.0, 1.0, 1.0, 0.3333]
    """
    if not 1 <= accuracy_grade <= 12:
        raise InputError("accuracy_grade", accuracy_grade, "", "an ISO 1328 grade 1-12")
    rho = np.asarray(position, dtype=float)
    eps_alpha = pair.transverse_contact_ratio
    if pair.overlap_ratio >= 1.0:
        return np.full(rho.shape, 1.0 / eps_alpha)
    if eps_alpha >= 2.0:
        # no single-tooth contact: two or three pairs share it everywhere; ISO's shape for
        # high-contact-ratio spur gears is not coded, the mean load stands for it
        return np.full(rho.shape, 1.0 / eps_alpha)
    points = pair.points()
    a, b, d, e = points["A"], points["B"], points["D"], points["E"]
    start = (max(accuracy_grade, 7) - 2.0) / 15.0
    approach = start + (rho - a) / (b - a) / 3.0
    recess = start + (e - rho) / (e - d) / 3.0
    return np.where(rho < b, approach, np.where(rho > d, recess, 1.0))


def tabulated_load_sharing(pair: GearPair, position: np.ndarray, fraction: np.ndarray, share: np.ndarray) -> np.ndarray:
    """A load share given at fractions of the path (0 at A, 1 at E), interpolated linearly.

    Parameters
    ----------
    pair : GearPair
    position : ndarray
        rho_1 where the share is wanted, m.
    fraction : ndarray
        Increasing positions of the table, (rho_1 - A)/(E - A), from 0 to 1.
    share : ndarray
        Share of the pair's load carried by one tooth pair at those positions, in (0, 1].
    """
    x = np.asarray(fraction, dtype=float)
    y = np.asarray(share, dtype=float)
    if x.ndim != 1 or x.shape != y.shape or x.size < 2:
        raise InputError("load_sharing.fraction", list(x.ravel()), "", "a list of 2 or more, as long as share")
    if not (np.all(np.diff(x) > 0) and abs(x[0]) < 1e-9 and abs(x[-1] - 1.0) < 1e-9):
        raise InputError("load_sharing.fraction", list(x), "", "increasing from 0 (A) to 1 (E)")
    if np.any(~((y > 0.0) & (y <= 1.0))):
        raise InputError("load_sharing.share", float(y[~((y > 0.0) & (y <= 1.0))][0]), "", "in (0, 1]")
    t = (np.asarray(position, dtype=float) - pair.start_of_contact) / pair.path_length
    return np.interp(t, x, y)


def normal_load_per_length(pair: GearPair, pinion_torque: float | np.ndarray, share: np.ndarray) -> np.ndarray:
    """Normal load per unit length of contact line, ``X_Gamma T_1 / (r_b1 b)``, N/m (torque N m)."""
    torque = np.asarray(pinion_torque, dtype=float)
    if np.any(~(torque > 0)):
        raise InputError("pinion_torque", first_offending(torque, torque > 0), "N m", "> 0")
    return torque * np.asarray(share) / (pair.base_radius_1 * pair.face_width)
