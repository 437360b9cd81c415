"""Hertz theory of dry elastic non-conformal contact: line and elliptical point contacts.

All functions take numpy arrays (or floats) that broadcast against each other and return
arrays, SI units throughout (N, m, Pa).

Conventions (Hamrock 1994, *Fundamentals of Fluid Film Lubrication*, Ch. 17):

* the reduced modulus is ``E' = 2 / ((1 - nu1^2)/E1 + (1 - nu2^2)/E2)``; Johnson's
  ``E* = E'/2`` (Johnson 1985, *Contact Mechanics*, Eq. 4.22);
* x is the rolling (entraining) direction, with the smaller reduced radius ``Rx <= Ry``;
  the contact ellipse has semi-axis ``b`` along x and ``a >= b`` along y, ellipticity
  ``k = a/b``; the curvature ratio is ``alpha_r = Ry/Rx``.

Line contact (Johnson 1985 Eq. 4.43-4.45 and Sect. 4.2(c), Fig. 4.6):
``b = sqrt(8 w' R / (pi E'))``, ``p0 = 2 w' / (pi b)``, ``p_mean = pi p0 / 4``; the largest
principal shear stress below the surface is ``0.300 p0`` at depth ``0.786 b``.

Elliptical contact (Johnson 1985 Eq. 4.39; Hamrock 1994 Eq. 17.29-17.40): k solves
``alpha_r = (k^2 E(m) - K(m)) / (K(m) - E(m))`` with ``m = 1 - 1/k^2`` and the complete
elliptic integrals K (first kind) and E (second kind) of parameter m (``scipy.special.ellipk``,
``ellipe``); then ``a = (6 k^2 E w R / (pi E'))^(1/3)``, ``b = (6 E w R / (pi k E'))^(1/3)``,
``p0 = 3 w / (2 pi a b)``, approach ``delta = K (9/(2 E R) (w/(pi k E'))^2)^(1/3)`` with
``1/R = 1/Rx + 1/Ry``. Beside the exact values, the curve fits of Hamrock & Brewe (1983)
and the simpler ones of Brewe & Hamrock (1977) (:data:`ELLIPTICITY_METHODS`).
"""

from __future__ import annotations

import functools
from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

from shaftline.errors import InputError, first_offending

ArrayLike = float | np.ndarray

#: Largest principal shear stress under a line contact over p0, and its depth over b
#: (Johnson 1985, Sect. 4.2(c): 0.300 p0 at z = 0.786 b; also Hamrock 1994 Fig. 17.7).
LINE_MAX_SHEAR = 0.300
LINE_MAX_SHEAR_DEPTH = 0.786


def _positive(name: str, value: ArrayLike, unit: str) -> np.ndarray:
    array = np.asarray(value, dtype=float)
    bad = ~(np.isfinite(array) & (array > 0.0))
    if np.any(bad):
        raise InputError(name, float(array[bad].flat[0]) if array.ndim else float(array), unit, "> 0 and finite")
    return array


def reduced_modulus(
    youngs_modulus_1: ArrayLike, poisson_ratio_1: ArrayLike, youngs_modulus_2: ArrayLike, poisson_ratio_2: ArrayLike
) -> np.ndarray:
    """Reduced (effective) elastic modulus ``E'`` of two bodies, Pa (Hamrock 1994 Eq. 17.23).

    Examples
    --------
    Steel on steel (210 GPa, 0.3): ``E' = 210e9 / 0.91 = 230.8 GPa``.

    >>> round(float(reduced_modulus(210e9, 0.3, 210e9, 0.3)) / 1e9, 1)
    230.8
    """
    e1 = _positive("youngs_modulus_1", youngs_modulus_1, "Pa")
    e2 = _positive("youngs_modulus_2", youngs_modulus_2, "Pa")
    for name, nu in (("poisson_ratio_1", poisson_ratio_1), ("poisson_ratio_2", poisson_ratio_2)):
        n = np.asarray(nu, dtype=float)
        if np.any(~((n >= 0.0) & (n < 0.5))):
            raise InputError(name, first_offending(n, (n >= 0.0) & (n < 0.5)), "", "in [0, 0.5)")
    return 2.0 / ((1.0 - np.asarray(poisson_ratio_1) ** 2) / e1 + (1.0 - np.asarray(poisson_ratio_2) ** 2) / e2)


def reduced_radius(radius_1: ArrayLike, radius_2: ArrayLike) -> np.ndarray:
    """Reduced radius ``R = (1/R1 + 1/R2)^-1``, m; a concave body has a negative radius and
    ``inf`` is a plane (a flat on a cylinder gives the cylinder's radius)."""
    r1 = np.asarray(radius_1, dtype=float)
    r2 = np.asarray(radius_2, dtype=float)
    curvature = 1.0 / r1 + 1.0 / r2
    if np.any(~(curvature > 0.0)):
        raise InputError(
            "radius_2",
            first_offending(r2, curvature > 0.0),
            "m",
            "a sum of curvatures 1/R1 + 1/R2 > 0 (convex contact)",
        )
    return 1.0 / curvature


@dataclass(frozen=True, eq=False)
class LineContact:
    """A Hertz line contact (arrays broadcast from the inputs).

    Attributes
    ----------
    half_width : ndarray
        Semi-width b of the contact band, m.
    peak_pressure : ndarray
        Maximum Hertz pressure p0, Pa.
    mean_pressure : ndarray
        Mean pressure ``pi p0 / 4``, Pa.
    max_shear : ndarray
        Largest principal shear stress below the surface, Pa.
    max_shear_depth : ndarray
        Its depth, m.
    """

    half_width: np.ndarray
    peak_pressure: np.ndarray
    mean_pressure: np.ndarray
    max_shear: np.ndarray
    max_shear_depth: np.ndarray


def line_contact(load_per_length: ArrayLike, radius: ArrayLike, modulus: ArrayLike) -> LineContact:
    """Hertz contact of two parallel cylinders (plane strain).

    Parameters
    ----------
    load_per_length : array_like
        Normal load per unit length w', N/m.
    radius : array_like
        Reduced radius R, m.
    modulus : array_like
        Reduced modulus E' (:func:`reduced_modulus`), Pa.

    Examples
    --------
    1000 N/mm on a 10 mm reduced radius, steel: b = 0.332 mm, p0 = 1.92 GPa.

    >>> c = line_contact(1e6, 0.01, 230.8e9)
    >>> round(float(c.half_width) * 1e3, 3), round(float(c.peak_pressure) / 1e9, 2)
    (0.332, 1.92)
    """
    w = _positive("load_per_length", load_per_length, "N/m")
    r = _positive("radius", radius, "m")
    e = _positive("modulus", modulus, "Pa")
    b = np.sqrt(8.0 * w * r / (np.pi * e))
    p0 = 2.0 * w / (np.pi * b)
    return LineContact(b, p0, np.pi * p0 / 4.0, LINE_MAX_SHEAR * p0, LINE_MAX_SHEAR_DEPTH * b)


# --- elliptical contacts ------------------------------------------------------------------


def _exact_integrals(ellipticity: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    from scipy.special import ellipe, ellipk

    m = 1.0 - 1.0 / ellipticity**2
    return ellipk(m), ellipe(m)


def _curvature_ratio_of(ellipticity: np.ndarray) -> np.ndarray:
    """``alpha_r = Ry/Rx`` of an ellipticity k (Johnson 1985 Eq. 4.39; exact)."""
    big_k, big_e = _exact_integrals(ellipticity)
    with np.errstate(invalid="ignore", divide="ignore"):
        ratio = (ellipticity**2 * big_e - big_k) / (big_k - big_e)
    return np.where(ellipticity > 1.0 + 1e-12, ratio, 1.0)


def exact_ellipticity(curvature_ratio: ArrayLike) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Ellipticity k and the elliptic integrals K, E of a curvature ratio ``Ry/Rx >= 1``.

    Newton's method on ``ln k`` from the Brewe-Hamrock value, vectorised (no loop over
    points); converged to 1e-12 relative in ``alpha_r`` within 8 iterations for
    ``1 <= alpha_r <= 1e4``.
    """
    alpha = _ratio(curvature_ratio)
    log_k = (2.0 / np.pi) * np.log(alpha)
    target = np.log(alpha)
    step = 1e-6
    for _ in range(12):
        k = np.exp(log_k)
        f = np.log(_curvature_ratio_of(np.maximum(k, 1.0 + 1e-9))) - target
        f2 = np.log(_curvature_ratio_of(np.exp(log_k + step))) - target
        slope = (f2 - f) / step
        update = np.where(np.abs(slope) > 0, f / np.where(slope == 0, 1.0, slope), 0.0)
        log_k = np.maximum(log_k - update, 0.0)
        if np.all(np.abs(update) < 1e-13):
            break
    k = np.where(alpha > 1.0 + 1e-12, np.exp(log_k), 1.0)
    big_k, big_e = _exact_integrals(k)
    return k, big_k, big_e


def hamrock_brewe_ellipticity(curvature_ratio: ArrayLike) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Hamrock & Brewe (1983) curve fits of k, K and E: ``k = 1.0339 alpha_r^0.6360``,
    ``E = 1.0003 + 0.5968 / alpha_r``, ``K = 1.5277 + 0.6023 ln(alpha_r)`` (Hamrock 1994
    Eq. 17.36-17.38)."""
    alpha = _ratio(curvature_ratio)
    return 1.0339 * alpha**0.6360, 1.5277 + 0.6023 * np.log(alpha), 1.0003 + 0.5968 / alpha


def brewe_hamrock_ellipticity(curvature_ratio: ArrayLike) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Brewe & Hamrock (1977) simplified approximations: ``k = alpha_r^(2/pi)``,
    ``E = 1 + (pi/2 - 1)/alpha_r``, ``K = pi/2 + (pi/2 - 1) ln(alpha_r)`` (Hamrock 1994
    Eq. 17.33-17.35)."""
    alpha = _ratio(curvature_ratio)
    k = alpha ** (2.0 / np.pi)
    return k, np.pi / 2.0 + (np.pi / 2.0 - 1.0) * np.log(alpha), 1.0 + (np.pi / 2.0 - 1.0) / alpha


def _ratio(curvature_ratio: ArrayLike) -> np.ndarray:
    alpha = np.asarray(curvature_ratio, dtype=float)
    if np.any(~(alpha >= 1.0)) or np.any(~np.isfinite(alpha)):
        raise InputError(
            "curvature_ratio",
            first_offending(alpha, (alpha >= 1.0) & np.isfinite(alpha)),
            "",
            ">= 1 and finite (Ry/Rx with Rx <= Ry)",
        )
    return alpha


#: Ways of finding the ellipticity and elliptic integrals (SciPy ``METHODS`` style).
ELLIPTICITY_METHODS: dict[str, Callable[[ArrayLike], tuple[np.ndarray, np.ndarray, np.ndarray]]] = {
    "exact": exact_ellipticity,
    "hamrock_brewe": hamrock_brewe_ellipticity,
    "brewe_hamrock": brewe_hamrock_ellipticity,
}


@dataclass(frozen=True, eq=False)
class PointContact:
    """A Hertz elliptical (point) contact.

    Attributes
    ----------
    semi_axis_x, semi_axis_y : ndarray
        Semi-axes b (rolling direction x) and a (transverse y) of the contact ellipse, m.
    ellipticity : ndarray
        k = a / b.
    curvature_ratio : ndarray
        alpha_r = Ry / Rx.
    peak_pressure, mean_pressure : ndarray
        p0 and ``2 p0 / 3``, Pa.
    approach : ndarray
        Mutual approach of distant points of the bodies, m.
    radius_x, radius : ndarray
        Reduced radius in x and ``(1/Rx + 1/Ry)^-1``, m.
    first_kind, second_kind : ndarray
        Complete elliptic integrals K and E used.
    max_shear, max_shear_depth : ndarray
        Largest principal shear stress below the centre and its depth
        (:func:`elliptical_max_shear`; k = 1: 0.31 p0 at 0.48 a for nu = 0.3, Johnson 1985
        Fig. 3.9).
    """

    semi_axis_x: np.ndarray
    semi_axis_y: np.ndarray
    ellipticity: np.ndarray
    curvature_ratio: np.ndarray
    peak_pressure: np.ndarray
    mean_pressure: np.ndarray
    approach: np.ndarray
    radius_x: np.ndarray
    radius: np.ndarray
    first_kind: np.ndarray
    second_kind: np.ndarray
    max_shear: np.ndarray
    max_shear_depth: np.ndarray


def circular_max_shear(poisson_ratio: ArrayLike) -> tuple[np.ndarray, np.ndarray]:
    """Largest principal shear stress on the axis of a circular Hertz contact, over p0, and its
    depth over a, from the exact stresses on the axis (Johnson 1985 Eq. 3.45):
    ``sigma_r/p0 = -(1+nu)(1 - zeta arctan(1/zeta)) + 1/(2(1+zeta^2))``,
    ``sigma_z/p0 = -1/(1+zeta^2)``, ``zeta = z/a``; maximised over depth on a fine grid.
    """
    nu = np.atleast_1d(np.asarray(poisson_ratio, dtype=float))
    zeta = np.linspace(1e-3, 2.0, 4001)[:, None]
    sigma_r = -(1.0 + nu) * (1.0 - zeta * np.arctan(1.0 / zeta)) + 0.5 / (1.0 + zeta**2)
    sigma_z = -1.0 / (1.0 + zeta**2)
    shear = 0.5 * np.abs(sigma_r - sigma_z)
    index = np.argmax(shear, axis=0)
    columns = np.arange(nu.size)
    return shear[index, columns], zeta[index, 0]


def axis_stresses(
    ellipticity: float, depth: np.ndarray, poisson_ratio: float = 0.3, order: int = 24
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Normal stresses sigma_x, sigma_y, sigma_z over p0 on the axis below the centre of a Hertz
    ellipse with semi-axes b = 1 (x) and a = k (y), at depths z/b: Boussinesq's point-load
    stresses (Johnson 1985 Eq. 3.20) integrated over the pressure p0 (1 - (x/b)^2 - (y/a)^2)^1/2
    by Gauss-Legendre quadrature in elliptical polar coordinates (``order`` radial by
    ``2 order`` angular nodes over a quarter, the stresses being even in x and y). On the axis
    the shear stresses vanish by symmetry, so these are the principal stresses."""
    s, ws = np.polynomial.legendre.leggauss(order)
    s, ws = 0.5 * (s + 1.0), 0.5 * ws
    th, wt = np.polynomial.legendre.leggauss(2 * order)
    th, wt = np.pi / 4.0 * (th + 1.0), np.pi / 4.0 * wt
    rr, tt = np.meshgrid(s, th, indexing="ij")
    weight = (np.sqrt(1.0 - rr**2) * ellipticity * rr * np.outer(ws, wt) * 4.0).ravel() / (2.0 * np.pi)
    x2 = ((rr * np.cos(tt)) ** 2).ravel()
    y2 = ((ellipticity * rr * np.sin(tt)) ** 2).ravel()
    r2 = x2 + y2
    z = np.asarray(depth, dtype=float)[:, None]
    rho = np.sqrt(r2 + z**2)
    radial = (1.0 - z / rho) / r2
    nu = 1.0 - 2.0 * poisson_ratio
    sigma_x = (weight * (nu / r2 * (radial * (x2 - y2) + z * y2 / rho**3) - 3.0 * z * x2 / rho**5)).sum(axis=1)
    sigma_y = (weight * (nu / r2 * (radial * (y2 - x2) + z * x2 / rho**3) - 3.0 * z * y2 / rho**5)).sum(axis=1)
    sigma_z = (-3.0 * weight * z**3 / rho**5).sum(axis=1)
    return sigma_x, sigma_y, sigma_z


#: Ellipticities of the table of subsurface shear maxima; beyond the last, 1/k = 0 is the line
#: contact's 0.300 p0 at 0.786 b.
_SHEAR_TABLE_K = (1.0, 1.25, 1.5, 2.0, 3.0, 5.0, 8.0, 13.0, 20.0, 35.0, 60.0, 100.0)


@functools.lru_cache(maxsize=8)
def _shear_table(poisson_ratio: float) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    inverse, ratio, depth = [0.0], [LINE_MAX_SHEAR], [LINE_MAX_SHEAR_DEPTH]
    for k in reversed(_SHEAR_TABLE_K):
        z = np.linspace(0.2, 1.2, 51)
        stresses = np.stack(axis_stresses(k, z, poisson_ratio))
        tau = 0.5 * (stresses.max(axis=0) - stresses.min(axis=0))
        i = int(np.argmax(tau))
        fine = np.linspace(z[max(i - 1, 0)], z[min(i + 1, z.size - 1)], 41)
        stresses = np.stack(axis_stresses(k, fine, poisson_ratio))
        tau = 0.5 * (stresses.max(axis=0) - stresses.min(axis=0))
        j = int(np.argmax(tau))
        inverse.append(1.0 / k)
        ratio.append(float(tau[j]))
        depth.append(float(fine[j]))
    return np.array(inverse), np.array(ratio), np.array(depth)


def elliptical_max_shear(ellipticity: ArrayLike, poisson_ratio: float = 0.3) -> tuple[np.ndarray, np.ndarray]:
    """Largest principal shear stress on the axis of an elliptical Hertz contact over p0, and its
    depth over the semi-minor axis b, interpolated in 1/k in a table computed once per Poisson
    ratio from :func:`axis_stresses` (k = 1 ... 100, and the line contact at 1/k = 0): 0.310 at
    0.481 b for a circle (nu = 0.3), 0.324 at 0.63 b for k = 2, 0.302 at 0.786 b for k = 100."""
    inverse, ratio, depth = _shear_table(float(poisson_ratio))
    u = 1.0 / np.asarray(ellipticity, dtype=float)
    return np.interp(u, inverse, ratio), np.interp(u, inverse, depth)


def point_contact(
    load: ArrayLike,
    radius_x: ArrayLike,
    radius_y: ArrayLike,
    modulus: ArrayLike,
    method: str = "exact",
    poisson_ratio: float = 0.3,
) -> PointContact:
    """Hertz contact of two bodies with reduced radii ``Rx <= Ry`` (Ry = inf: a line-like
    contact is not allowed here; use :func:`line_contact`).

    Parameters
    ----------
    load : array_like
        Normal load w, N.
    radius_x, radius_y : array_like
        Reduced radii in the rolling and transverse directions, m (``Rx <= Ry``).
    modulus : array_like
        Reduced modulus E', Pa.
    method : str
        A key of :data:`ELLIPTICITY_METHODS`: ``"exact"`` (elliptic integrals) or
        ``"hamrock_brewe"`` (their approximations).
    poisson_ratio : float
        For the subsurface shear stress.

    Examples
    --------
    A 10 mm radius ball on a flat, 100 N, steel: a = 0.187 mm, p0 = 1.37 GPa.

    >>> c = point_contact(100.0, 0.01, 0.01, 230.8e9)
    >>> round(float(c.semi_axis_y) * 1e3, 3), round(float(c.peak_pressure) / 1e9, 2)
    (0.187, 1.37)
    """
    w = _positive("load", load, "N")
    rx = _positive("radius_x", radius_x, "m")
    ry = _positive("radius_y", radius_y, "m")
    e = _positive("modulus", modulus, "Pa")
    if np.any(ry < rx * (1.0 - 1e-12)):
        raise InputError(
            "radius_y",
            first_offending(ry, ry >= rx * (1.0 - 1e-12)),
            "m",
            ">= radius_x (x is the direction of smaller radius)",
        )
    if method not in ELLIPTICITY_METHODS:
        raise InputError("method", method, "", " or ".join(ELLIPTICITY_METHODS))
    alpha = ry / rx
    k, big_k, big_e = ELLIPTICITY_METHODS[method](alpha)
    radius = 1.0 / (1.0 / rx + 1.0 / ry)
    a = (6.0 * k**2 * big_e * w * radius / (np.pi * e)) ** (1.0 / 3.0)
    b = (6.0 * big_e * w * radius / (np.pi * k * e)) ** (1.0 / 3.0)
    p0 = 3.0 * w / (2.0 * np.pi * a * b)
    approach = big_k * (9.0 / (2.0 * big_e * radius) * (w / (np.pi * k * e)) ** 2) ** (1.0 / 3.0)
    ratio, depth = elliptical_max_shear(k, poisson_ratio)
    max_shear = ratio * p0
    max_depth = depth * b
    return PointContact(b, a, k, alpha, p0, 2.0 * p0 / 3.0, approach, rx, radius, big_k, big_e, max_shear, max_depth)
