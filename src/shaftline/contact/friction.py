"""Mixed-lubrication friction of a rolling-sliding contact (seed 002, Ciulli et al. 2010,
Sect. 1.1, Eq. 1-6), read as documented in docs/theory.md Sect. 15.4:

* Eq. 1: ``f_a = f_c g(Lambda) + f_b (1 - g(Lambda))``, boundary friction f_b (0.08-0.1);
* Eq. 2: Zhu-Hu load sharing ``g = 1.21 Lambda^0.64 / (1 + 0.37 Lambda^1.26)``, set to 1 for
  Lambda > 2 (it passes 1 at Lambda = 2.013, peaks at 1.003 at 2.26 and falls beyond, seed Fig. 1);
* Eq. 3 and 5: full-film friction from the Bair-Winer stress over the mean Hertz pressure,
  ``f_c = tau / p_m = (tau_L / p_m) (1 - exp(-eta u S / (tau_L h_c)))``, shear rate
  ``Delta u / h_c = S u / h_c``; p_m is the contact's own: ``2 p_H / 3`` for the elliptical
  (crowned-tooth) contact the seed writes Eq. 3 for, ``pi p_H / 4`` for a line contact
  (docs/theory.md Sect. 15.4, issue 14 (f));
* Eq. 6: thermal correction ``f = c f_a`` with, for ``S > S_m = 0.01 X^-3/2``,
  ``c = (0.39 - 0.28 ln X) S^-(0.088 ln X + 0.220)``, ``X = eta0 p_H u`` in Pa s x GPa x m/s
  (the units in which c(S_m) = 1 within 8 % over the fit range X = 0.1-1.8), and c = 1
  below S_m.
"""

from __future__ import annotations

import warnings
from dataclasses import dataclass

import numpy as np

from shaftline.contact.rheology import ExtrapolationWarning
from shaftline.errors import InputError, first_offending

ArrayLike = float | np.ndarray

#: Lambda above which the load-sharing function is 1 (seed 002 after Eq. 2).
FULL_FILM_RATIO = 2.0

#: Range of X = eta0 p_H u (Pa s GPa m/s) over which Eq. 6 meets c = 1 at S_m within 8 %:
#: the range its fit can have come from (docs/theory.md Sect. 15.4); outside it c(S_m) strays
#: from 1 (1.19 at X = 0.056, 0.52 at X = 3.2) and turns negative beyond X = 4.
THERMAL_FIT_RANGE = (0.1, 1.8)


def load_sharing(film_ratio: ArrayLike) -> np.ndarray:
    """Zhu-Hu share of the load carried by the film, g(Lambda) (seed 002 Eq. 2), 1 above
    Lambda = 2.

    >>> [round(float(load_sharing(x)), 3) for x in (0.0, 1.0, 2.0, 3.0)]
    [0.0, 0.883, 1.0, 1.0]
    """
    lam = np.asarray(film_ratio, dtype=float)
    if np.any(~(lam >= 0.0)):
        raise InputError("film_ratio", first_offending(lam, lam >= 0.0), "", ">= 0")
    g = 1.21 * lam**0.64 / (1.0 + 0.37 * lam**1.26)
    return np.where(lam > FULL_FILM_RATIO, 1.0, g)


def full_film_friction(
    limiting_stress: ArrayLike,
    viscosity: ArrayLike,
    rolling_speed: ArrayLike,
    slide_roll: ArrayLike,
    central_film: ArrayLike,
    mean_pressure: ArrayLike,
) -> np.ndarray:
    """Full-film friction coefficient f_c of seed 002 Eq. 3 and 5: the Bair-Winer shear stress at
    the shear rate ``|S| u / h_c`` over the mean Hertz pressure p_m (Pa; ``2 p_H / 3`` elliptical,
    ``pi p_H / 4`` line contact); 0 where the film is 0."""
    tau_l = np.asarray(limiting_stress, dtype=float)
    h = np.asarray(central_film, dtype=float)
    with np.errstate(divide="ignore", invalid="ignore"):
        rate = np.abs(np.asarray(slide_roll)) * np.asarray(rolling_speed) / h
        stress = tau_l * -np.expm1(-np.asarray(viscosity) * rate / tau_l)
    return np.where(h > 0.0, stress / np.asarray(mean_pressure), 0.0)


def mixed_friction(full_film: ArrayLike, boundary: ArrayLike, film_ratio: ArrayLike) -> np.ndarray:
    """``f_a = f_c g + f_b (1 - g)`` (seed 002 Eq. 1)."""
    g = load_sharing(film_ratio)
    return np.asarray(full_film) * g + np.asarray(boundary) * (1.0 - g)


def power_parameter(viscosity: ArrayLike, peak_pressure: ArrayLike, rolling_speed: ArrayLike) -> np.ndarray:
    """X = eta0 p_H u in the units of seed 002 Eq. 6: Pa s x GPa x m/s."""
    return np.asarray(viscosity) * np.asarray(peak_pressure) * 1e-9 * np.asarray(rolling_speed)


def peak_slide_roll(power: ArrayLike) -> np.ndarray:
    """S_m = 0.01 X^(-3/2), the slide-to-roll ratio of the traction maximum (seed 002)."""
    return 0.01 * np.asarray(power, dtype=float) ** -1.5


def thermal_correction(power: ArrayLike, slide_roll: ArrayLike, extrapolate: bool = False) -> np.ndarray:
    """Thermal correction c of seed 002 Eq. 6 (as read in docs/theory.md Sect. 15.4).

    Parameters
    ----------
    power : array_like
        X = eta0 p_H u, Pa s GPa m/s (:func:`power_parameter`).
    slide_roll : array_like
        Slide-to-roll ratio S = Delta u / u (its magnitude is used).
    extrapolate : bool
        Where the correction applies (S > S_m) and X lies outside
        :data:`THERMAL_FIT_RANGE`: False raises an InputError naming the range, True warns and
        clips c to [0, 1].

    Examples
    --------
    >>> round(float(thermal_correction(0.3, 0.5)), 3)
    0.787
    >>> float(thermal_correction(0.3, 0.01))  # below S_m = 0.061
    1.0
    """
    x = np.asarray(power, dtype=float)
    s = np.abs(np.asarray(slide_roll, dtype=float))
    if np.any(~(x > 0.0)):
        raise InputError("eta0 p_H u", first_offending(x, x > 0.0), "Pa s GPa m/s", "> 0")
    applies = s > peak_slide_roll(x)
    low, high = THERMAL_FIT_RANGE
    outside = applies & ((x < low) | (x > high))
    log_x = np.log(x)
    with np.errstate(divide="ignore"):
        c = (0.39 - 0.28 * log_x) * s ** -(0.088 * log_x + 0.220)
    if np.any(outside):
        value = float(np.broadcast_to(x, outside.shape)[outside][0])
        bounds = f"[{low}, {high}] Pa s GPa m/s where S > S_m (the fit range of seed 002 Eq. 6)"
        if not extrapolate:
            raise InputError(
                "eta0 p_H u (oil viscosity x peak Hertz pressure x rolling speed)",
                value,
                "Pa s GPa m/s",
                f"in {bounds}: change the temperature, load or speed, or extrapolate=true to go beyond",
            )
        warnings.warn(
            f"eta0 p_H u = {value:g} Pa s GPa m/s is outside the validity range {bounds}: extrapolated, c clipped to "
            "[0, 1]",
            ExtrapolationWarning,
            stacklevel=2,
        )
        c = np.where(outside, np.clip(c, 0.0, 1.0), c)
    return np.where(applies, c, 1.0)


@dataclass(frozen=True, eq=False)
class SeedFriction:
    """Friction of seed 002 at each point (arrays).

    Attributes
    ----------
    coefficient : ndarray
        f = c f_a.
    mixed : ndarray
        f_a (Eq. 1).
    full_film : ndarray
        f_c (Eq. 5).
    load_sharing : ndarray
        g(Lambda) (Eq. 2).
    thermal : ndarray
        c (Eq. 6).
    peak_slide_roll : ndarray
        S_m.
    """

    coefficient: np.ndarray
    mixed: np.ndarray
    full_film: np.ndarray
    load_sharing: np.ndarray
    thermal: np.ndarray
    peak_slide_roll: np.ndarray


def seed_friction(
    *,
    film_ratio: ArrayLike,
    boundary: ArrayLike,
    limiting_stress: ArrayLike,
    viscosity_at_pressure: ArrayLike,
    viscosity: ArrayLike,
    rolling_speed: ArrayLike,
    slide_roll: ArrayLike,
    central_film: ArrayLike,
    peak_pressure: ArrayLike,
    mean_pressure: ArrayLike,
    extrapolate: bool = False,
) -> SeedFriction:
    """Seed 002's friction coefficient ``f = c f_a`` (Eq. 1-6) at every point.

    ``viscosity_at_pressure`` is the viscosity in the contact (at the mean Hertz pressure) that
    the Bair-Winer stress uses; ``viscosity`` is eta0 (ambient pressure) of Eq. 6;
    ``mean_pressure`` divides the stress (Eq. 3), ``peak_pressure`` enters Eq. 6's eta0 p_H u.
    """
    f_c = full_film_friction(
        limiting_stress, viscosity_at_pressure, rolling_speed, slide_roll, central_film, mean_pressure
    )
    g = load_sharing(film_ratio)
    f_a = f_c * g + np.asarray(boundary) * (1.0 - g)
    x = power_parameter(viscosity, peak_pressure, rolling_speed)
    c = thermal_correction(x, slide_roll, extrapolate)
    return SeedFriction(c * f_a, f_a, f_c, g, c, peak_slide_roll(x))
