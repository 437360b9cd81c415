"""Closed-form journal-bearing solutions used for starting guesses and validation.

All functions take the eccentricity ratio ``epsilon`` in [0, 1) and return the
load components on the journal in units of ``eta * omega * R * L * (R/c)^2``
or dimensionless groups, as noted.

References
----------
Ocvirk, F. W. (1952), NACA TN 2808 (short bearing, half-Sommerfeld film).
Sommerfeld, A. (1904), Z. Math. Phys. 50, 97-155 (long bearing, full film).
Guembel, L. (1914) (long bearing, half-Sommerfeld film).
Hamrock, B. J., Schmid, S. R., Jacobson, B. O. (2004), *Fundamentals of Fluid
Film Lubrication*, 2nd ed., Ch. 10-11 (the forms used here).
"""

from __future__ import annotations

import numpy as np
from scipy.optimize import brentq


def short_bearing_load(epsilon: float, length_to_diameter: float) -> tuple[float, float]:
    """Ocvirk short bearing, half-Sommerfeld: (radial, tangential) load / (eta omega R L (R/c)^2).

    The radial part acts along the line of centres, the tangential part at right angles.
    """
    e = epsilon
    ld2 = length_to_diameter**2
    radial = 4.0 * ld2 * e**2 / (1.0 - e**2) ** 2
    tangential = ld2 * np.pi * e / (1.0 - e**2) ** 1.5
    return radial, tangential


def long_bearing_load(epsilon: float, condition: str = "half_sommerfeld") -> tuple[float, float]:
    """Long bearing: (radial, tangential) load / (eta omega R L (R/c)^2).

    ``condition`` is ``"full_sommerfeld"`` (Sommerfeld 1904: no radial component)
    or ``"half_sommerfeld"`` (Guembel: negative pressures discarded).
    """
    e = epsilon
    tangential_full = 12.0 * np.pi * e / ((2.0 + e**2) * np.sqrt(1.0 - e**2))
    if condition == "full_sommerfeld":
        return 0.0, tangential_full
    radial = 12.0 * e**2 / ((2.0 + e**2) * (1.0 - e**2))
    return radial, 0.5 * tangential_full


def long_bearing_pressure(theta: np.ndarray, epsilon: float) -> np.ndarray:
    """Sommerfeld full-film pressure / (6 eta omega (R/c)^2), theta from the thickest film.

    With ``h = c (1 + epsilon cos theta)``: ``p = eps sin theta (2 + eps cos theta) /
    ((2 + eps^2) (1 + eps cos theta)^2)``.
    """
    e = epsilon
    return e * np.sin(theta) * (2.0 + e * np.cos(theta)) / ((2.0 + e**2) * (1.0 + e * np.cos(theta)) ** 2)


def attitude_angle(radial: float, tangential: float) -> float:
    """Attitude angle, rad, from the load components along and across the line of centres."""
    return float(np.arctan2(tangential, radial))


def eccentricity_guess(sommerfeld: float, length_to_diameter: float) -> tuple[float, float]:
    """Starting (epsilon, attitude in rad) for a finite bearing at Sommerfeld number ``S``.

    Both the long- and the short-bearing theory over-predict the load of a finite
    bearing (each drops one path for the pressure to escape), so the finite load is
    approximated by the harmonic combination ``1/W = 1/W_long + 1/W_short``.
    """
    target = 1.0 / (np.pi * sommerfeld)

    def load(e: float) -> float:
        w_long = np.hypot(*long_bearing_load(e))
        w_short = np.hypot(*short_bearing_load(e, length_to_diameter))
        return 1.0 / (1.0 / w_long + 1.0 / w_short)

    if load(0.995) < target:
        epsilon = 0.995
    elif load(1e-4) > target:
        epsilon = 1e-4
    else:
        epsilon = brentq(lambda e: load(e) - target, 1e-4, 0.995, xtol=1e-10)
    return float(epsilon), attitude_angle(*short_bearing_load(epsilon, length_to_diameter))
