"""Elastohydrodynamic film thickness of line and point contacts, the lubrication regimes,
the inlet shear-heating reduction and the film-thickness ratio Lambda.

Dimensionless groups (Hamrock 1994, Ch. 18 and 21-22), with the mean entraining velocity
``u = (u1 + u2) / 2``, reduced modulus E', reduced radius Rx in the rolling direction and
Barus' alpha of the inlet temperature:

    U = eta0 u / (E' Rx)   G = alpha E'   H = h / Rx
    line:  W' = w' / (E' Rx)   (w': load per unit length)
    point: W  = w / (E' Rx^2)  (w: load), ellipticity k

Formulas (every one vectorised over numpy arrays):

* line, Dowson & Toyoda (1979): ``Hc = 3.06 U^0.69 G^0.56 W'^-0.10``,
  ``Hmin = 2.65 U^0.70 G^0.54 W'^-0.13``;
* line, Moes (1992; Venner & Lubrecht 2000 Eq. 10.14) central film from the asymptotes of the
  four regimes in ``M = W' (2U)^-1/2``, ``L = G (2U)^1/4``, ``Hc (2U)^-1/2``;
* point, Hamrock & Dowson (1977): ``Hc = 2.69 U^0.67 G^0.53 W^-0.067 (1 - 0.61 e^-0.73k)``,
  ``Hmin = 3.63 U^0.68 G^0.49 W^-0.073 (1 - e^-0.68k)``;
* point, isoviscous-elastic (soft contacts), Hamrock & Dowson (1978):
  ``Hc = 7.32 U^0.64 W^-0.22 (1 - 0.72 e^-0.28k)``, ``Hmin = 7.43 U^0.65 W^-0.21 (1 - 0.85 e^-0.31k)``;
* regime map of point contacts: the minimum film of the four regimes rigid/elastic x
  isoviscous/piezoviscous (Hamrock & Dowson 1981, the rigid-piezoviscous formula as revised by
  Esfahanian & Hamrock 1991; ``H^ = H (W/U)^2``, ``gV = G W^3 / U^2``, ``gE = W^(8/3) / U^2``);
  the boundaries of the map are where neighbouring formulas give the same film and the regime
  is the one whose formula gives the largest film (docs/theory.md Sect. 15.2);
* thermal reduction of the inlet (shear heating): Gupta et al. (1992), with the slide-to-roll
  ratio S and the thermal loading ``L = beta eta0 u^2 / k_f``:
  ``phi_T = (1 - 13.2 (p0/E') L^0.42) / (1 + 0.213 (1 + 2.23 S^0.83) L^0.64)``, and Murch &
  Wilson (1975), pure rolling: ``phi_T = 3.94 / (3.94 + L^0.62)``;
* ``Lambda = h / sqrt(Rq1^2 + Rq2^2)``.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import TypeVar

import numpy as np

from shaftline.errors import InputError

ArrayLike = float | np.ndarray
FilmFormula = Callable[..., tuple[np.ndarray, np.ndarray]]
T = TypeVar("T")

#: Regime names, in the order of the codes of :func:`point_regime`.
REGIMES = ("rigid-isoviscous", "rigid-piezoviscous", "elastic-isoviscous", "elastic-piezoviscous")


def speed_parameter(
    viscosity: ArrayLike, rolling_speed: ArrayLike, modulus: ArrayLike, radius_x: ArrayLike
) -> np.ndarray:
    """U = eta0 u / (E' Rx), with u the mean entraining velocity."""
    return np.asarray(viscosity) * np.asarray(rolling_speed) / (np.asarray(modulus) * np.asarray(radius_x))


def material_parameter(alpha: ArrayLike, modulus: ArrayLike) -> np.ndarray:
    """G = alpha E'."""
    return np.asarray(alpha) * np.asarray(modulus)


def line_load_parameter(load_per_length: ArrayLike, modulus: ArrayLike, radius_x: ArrayLike) -> np.ndarray:
    """W' = w' / (E' Rx)."""
    return np.asarray(load_per_length) / (np.asarray(modulus) * np.asarray(radius_x))


def point_load_parameter(load: ArrayLike, modulus: ArrayLike, radius_x: ArrayLike) -> np.ndarray:
    """W = w / (E' Rx^2)."""
    return np.asarray(load) / (np.asarray(modulus) * np.asarray(radius_x) ** 2)


# --- line contacts ------------------------------------------------------------------------


def dowson_toyoda(u: ArrayLike, g: ArrayLike, w: ArrayLike) -> tuple[np.ndarray, np.ndarray]:
    """Dowson & Toyoda (1979) central and minimum film, H = h/Rx, of a line contact."""
    u, g, w = np.asarray(u), np.asarray(g), np.asarray(w)
    return 3.06 * u**0.69 * g**0.56 * w**-0.10, 2.65 * u**0.70 * g**0.54 * w**-0.13


def moes(u: ArrayLike, g: ArrayLike, w: ArrayLike) -> tuple[np.ndarray, np.ndarray]:
    """Moes (1992) central film of a line contact, H = h/Rx, from its four asymptotes
    ``H_RI = 3/M``, ``H_EI = 2.621 M^-1/5``, ``H_RP = 1.287 L^2/3``,
    ``H_EP = 1.311 M^-1/8 L^3/4`` blended as
    ``H = ((H_RI^7/3 + H_EI^7/3)^(3s/7) + (H_RP^-7/2 + H_EP^-7/2)^(-2s/7))^(1/s)``,
    ``s = (7 + 8 exp(-2 H_EI / H_RI)) / 5`` (the line contact's s; ``3/2 (1 + exp(-1.2 H_EI/H_RI))``
    is the point contact's, Nijenbanning, Venner & Moes 1994). Moes gives no minimum film: NaN."""
    h_ri, h_rp, h_ei, h_ep, root_two_u = _moes_asymptotes(u, g, w)
    s = (7.0 + 8.0 * np.exp(-2.0 * h_ei / h_ri)) / 5.0
    h = ((h_ri ** (7 / 3) + h_ei ** (7 / 3)) ** (3 * s / 7) + (h_rp**-3.5 + h_ep**-3.5) ** (-2 * s / 7)) ** (1 / s)
    central = h * root_two_u
    return central, np.full_like(central, np.nan)


def _moes_asymptotes(u: ArrayLike, g: ArrayLike, w: ArrayLike) -> tuple[np.ndarray, ...]:
    """Moes' four asymptotes H_RI, H_RP, H_EI, H_EP (in Hc (2U)^-1/2) and (2U)^1/2."""
    two_u = 2.0 * np.asarray(u, dtype=float)
    m = np.asarray(w) * two_u**-0.5
    lam = np.asarray(g) * two_u**0.25
    return 3.0 / m, 1.287 * lam ** (2.0 / 3.0), 2.621 * m**-0.2, 1.311 * m**-0.125 * lam**0.75, two_u**0.5


def line_regime(u: ArrayLike, g: ArrayLike, w: ArrayLike) -> np.ndarray:
    """Regime code (index into :data:`REGIMES`) of a line contact from Moes' asymptotes, the
    line contact's regime map in M and L (docs/theory.md Sect. 15.2): in Moes' blend the larger of
    H_RI, H_EI carries the isoviscous part and the smaller of H_RP, H_EP the piezoviscous part
    (negative exponent), and the larger of the two parts the film; the regime is the asymptote
    that so dominates."""
    h_ri, h_rp, h_ei, h_ep, _ = _moes_asymptotes(u, g, w)
    iso = np.where(h_ri >= h_ei, 0, 2)
    piezo = np.where(h_rp <= h_ep, 1, 3)
    return np.where(np.maximum(h_ri, h_ei) >= np.minimum(h_rp, h_ep), iso, piezo)


#: Film formulas of line contacts: ``formula(U, G, W') -> (Hc, Hmin)``.
LINE_FILM_METHODS: dict[str, FilmFormula] = {"dowson_toyoda": dowson_toyoda, "moes": moes}


# --- point contacts -----------------------------------------------------------------------


def hamrock_dowson(u: ArrayLike, g: ArrayLike, w: ArrayLike, k: ArrayLike) -> tuple[np.ndarray, np.ndarray]:
    """Hamrock & Dowson (1977) central and minimum film, H = h/Rx, of an elliptical contact."""
    u, g, w, k = (np.asarray(x) for x in (u, g, w, k))
    central = 2.69 * u**0.67 * g**0.53 * w**-0.067 * (1.0 - 0.61 * np.exp(-0.73 * k))
    minimum = 3.63 * u**0.68 * g**0.49 * w**-0.073 * (1.0 - np.exp(-0.68 * k))
    return central, minimum


def hamrock_dowson_soft(u: ArrayLike, g: ArrayLike, w: ArrayLike, k: ArrayLike) -> tuple[np.ndarray, np.ndarray]:
    """Hamrock & Dowson (1978) isoviscous-elastic (soft contact) film, H = h/Rx; G is unused."""
    u, w, k = (np.asarray(x) for x in (u, w, k))
    central = 7.32 * u**0.64 * w**-0.22 * (1.0 - 0.72 * np.exp(-0.28 * k))
    minimum = 7.43 * u**0.65 * w**-0.21 * (1.0 - 0.85 * np.exp(-0.31 * k))
    return central, minimum


#: Film formulas of point contacts: ``formula(U, G, W, k) -> (Hc, Hmin)``.
POINT_FILM_METHODS: dict[str, FilmFormula] = {
    "hamrock_dowson": hamrock_dowson,
    "hamrock_dowson_soft": hamrock_dowson_soft,
}


def point_regime(u: ArrayLike, g: ArrayLike, w: ArrayLike, k: ArrayLike) -> tuple[np.ndarray, np.ndarray]:
    """Regime code and minimum film H = h/Rx of an elliptical contact in ``H^ = H (W/U)^2``:
    rigid-isoviscous ``128 alpha_r lambda^2 (0.131 arctan(alpha_r/2) + 1.683)^2`` with
    ``alpha_r = k^(pi/2)``, ``lambda = (1 + 2/(3 alpha_r))^-1`` (Brewe, Hamrock & Taylor 1979);
    rigid-piezoviscous ``1.41 gV^0.375 (1 - e^(-0.0387 alpha_r))`` (Esfahanian & Hamrock 1991,
    who revised Hamrock & Dowson's ``1.66 gV^(2/3) (1 - e^-0.68k)``); elastic-isoviscous
    ``8.70 gE^0.67 (1 - 0.85 e^-0.31k)``; elastic-piezoviscous ``3.42 gV^0.49 gE^0.17
    (1 - e^-0.68k)`` (Hamrock & Dowson 1981); the regime is the formula of the largest film
    (docs/theory.md Sect. 15.2)."""
    u, g, w, k = (np.asarray(x, dtype=float) for x in (u, g, w, k))
    g_v = g * w**3 / u**2
    g_e = w ** (8.0 / 3.0) / u**2
    alpha_r = k ** (np.pi / 2.0)
    lam = 1.0 / (1.0 + 2.0 / (3.0 * alpha_r))
    rigid_iso = 128.0 * alpha_r * lam**2 * (0.131 * np.arctan(alpha_r / 2.0) + 1.683) ** 2
    films = np.stack(
        np.broadcast_arrays(
            rigid_iso,
            1.41 * g_v**0.375 * (1.0 - np.exp(-0.0387 * alpha_r)),
            8.70 * g_e**0.67 * (1.0 - 0.85 * np.exp(-0.31 * k)),
            3.42 * g_v**0.49 * g_e**0.17 * (1.0 - np.exp(-0.68 * k)),
        )
    )
    code = np.argmax(films, axis=0)
    return code, np.max(films, axis=0) * (u / w) ** 2


# --- thermal reduction --------------------------------------------------------------------


def thermal_loading(
    temperature_viscosity_coefficient: ArrayLike,
    viscosity: ArrayLike,
    rolling_speed: ArrayLike,
    conductivity: ArrayLike,
) -> np.ndarray:
    """Thermal loading factor ``L = beta eta0 u^2 / k_f`` (Gupta et al. 1992), -."""
    return (
        np.asarray(temperature_viscosity_coefficient)
        * np.asarray(viscosity)
        * np.asarray(rolling_speed) ** 2
        / np.asarray(conductivity)
    )


def gupta(loading: ArrayLike, slide_roll: ArrayLike, pressure_ratio: ArrayLike) -> np.ndarray:
    """Gupta, Cheng, Zhu, Forster & Schrand (1992) thermal reduction factor of the central
    film: ``(1 - 13.2 (p0/E') L^0.42) / (1 + 0.213 (1 + 2.23 |S|^0.83) L^0.64)``.

    The numerator vanishes at ``L = (13.2 p0/E')^(-1/0.42)`` (about 1000 for steel at 1 GPa)
    and is negative beyond: a negative film. There the fit is outside its range and an
    :class:`InputError` names the limit (Murch & Wilson's factor has no such limit).

    >>> round(float(gupta(1.0, 0.0, 0.004)), 3)
    0.781
    """
    lo = np.asarray(loading, dtype=float)
    s = np.abs(np.asarray(slide_roll, dtype=float))
    ratio = np.asarray(pressure_ratio, dtype=float)
    numerator = 1.0 - 13.2 * ratio * lo**0.42
    bad = ~(numerator > 0.0)
    if np.any(bad):
        value = float(np.broadcast_to(lo, bad.shape)[bad].flat[0])
        limit = float((13.2 * np.broadcast_to(ratio, bad.shape)[bad].flat[0]) ** (-1.0 / 0.42))
        raise InputError(
            "thermal loading L = beta eta0 u^2 / k_f (from the temperature and the speeds)",
            float(f"{value:.4g}"),
            "",
            f"< {limit:.4g}, where Gupta's thermal reduction stays positive (beyond it the fit gives a negative "
            "film: a colder, more viscous oil or a higher speed than it covers); thermal_method = "
            "'murch_wilson' has no such limit",
        )
    return numerator / (1.0 + 0.213 * (1.0 + 2.23 * s**0.83) * lo**0.64)


def murch_wilson(loading: ArrayLike, slide_roll: ArrayLike = 0.0, pressure_ratio: ArrayLike = 0.0) -> np.ndarray:
    """Murch & Wilson (1975) thermal reduction factor, pure rolling: ``3.94 / (3.94 + L^0.62)``."""
    lo = np.asarray(loading, dtype=float)
    return 3.94 / (3.94 + lo**0.62) + 0.0 * np.asarray(slide_roll) + 0.0 * np.asarray(pressure_ratio)


def no_reduction(loading: ArrayLike, slide_roll: ArrayLike = 0.0, pressure_ratio: ArrayLike = 0.0) -> np.ndarray:
    """Isothermal film: factor 1."""
    return np.ones(np.broadcast_shapes(np.shape(loading), np.shape(slide_roll), np.shape(pressure_ratio)))


#: Thermal reduction factors: ``factor(L, S, p0/E')``.
THERMAL_METHODS: dict[str, Callable[..., np.ndarray]] = {
    "gupta": gupta,
    "murch_wilson": murch_wilson,
    "none": no_reduction,
}


# --- Lambda -------------------------------------------------------------------------------


def rq_from_ra(ra: ArrayLike) -> np.ndarray:
    """Rq of a Gaussian height distribution from Ra: ``Rq = sqrt(pi/2) Ra`` (1.25 Ra)."""
    return np.sqrt(np.pi / 2.0) * np.asarray(ra, dtype=float)


def film_ratio(film: ArrayLike, rq_1: ArrayLike, rq_2: ArrayLike) -> np.ndarray:
    """``Lambda = h / sqrt(Rq1^2 + Rq2^2)``.

    >>> float(film_ratio(0.5e-6, 0.3e-6, 0.4e-6))
    1.0
    """
    composite = np.hypot(np.asarray(rq_1, dtype=float), np.asarray(rq_2, dtype=float))
    if np.any(~(composite > 0.0)):
        raise InputError("roughness", 0.0, "m", "a composite roughness > 0")
    return np.asarray(film) / composite


def method(registry: dict[str, T], name: str, field: str) -> T:
    """The entry ``name`` of a method registry, or an :class:`InputError` naming the choices."""
    if name not in registry:
        raise InputError(field, name, "", " or ".join(registry))
    return registry[name]
