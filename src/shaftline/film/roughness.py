"""Rough surfaces in a thin film: asperity contact and flow factors (mixed lubrication).

Pure functions of the film-thickness ratio ``lam = h / sigma`` (``h`` the nominal gap between
the mean planes of the two surfaces, ``sigma`` their composite RMS roughness), and one
frozen dataclass, :class:`SurfaceRoughness`, with the inputs. docs/theory.md, Sect.
"Mixed lubrication", gives the source of every equation:

- Greenwood-Tripp asperity contact pressure ``p_a = K E* F_5/2(lam)`` with
  ``K = (16 sqrt(2) / 15) pi (sigma beta eta)^2 sqrt(sigma / beta)``, ``E*`` the contact
  modulus ``1/E* = (1 - nu1^2)/E1 + (1 - nu2^2)/E2`` (the factor is derived in docs/theory.md;
  authors who write ``8 sqrt(2)/15`` use ``E' = 2 E*``), and the contact-area ratio
  ``A_c / A = pi^2 (sigma beta eta)^2 F_2(lam)``.
- The Gaussian integrals ``F_n`` exactly, through the parabolic cylinder function
  (``scipy.special.pbdv``), and the usual power-law fit of ``F_5/2`` beside them.
- Patir-Cheng flow factors of isotropic roughness (gamma = 1): pressure ``phi_x``, shear
  ``Phi_s``; the mean gap ``h_T`` of a Gaussian gap in closed form (valid down to ``h -> 0``,
  where the Couette transport is carried by ``h_T``).

Only numpy (and ``math``) is imported at module level: :mod:`shaftline.film.problem` and the
case schema import :class:`SurfaceRoughness` without scipy.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from functools import lru_cache
from typing import Any, Literal, Protocol, get_args

import numpy as np

from shaftline.errors import InputError, require_finite, require_positive

__all__ = [
    "GREENWOOD_TRIPP_FACTOR",
    "PRESETS",
    "RA_TO_RQ",
    "FilmFlow",
    "RoughFilm",
    "SurfacePreset",
    "SurfaceRoughness",
    "BOUNDARY_LIMIT",
    "LAMBDA_SWITCH",
    "asperity_pressure",
    "asperity_pressure_derivative",
    "boundary_flow_factor",
    "boundary_flow_factor_derivative",
    "boundary_shear_factor",
    "contact_area_ratio",
    "gaussian_integral",
    "gaussian_integral_fit",
    "gaussian_integral_table",
    "contact_modulus",
    "lubrication_regime",
    "mean_gap",
    "mean_gap_derivative",
    "pressure_flow_factor",
    "pressure_flow_factor_derivative",
    "shear_flow_factor",
    "shear_flow_factor_derivative",
]

#: ``16 sqrt(2) / 15 * pi``: the Greenwood-Tripp load factor with the contact modulus E*
#: (docs/theory.md, derived from the Hertz load of two misaligned asperities).
GREENWOOD_TRIPP_FACTOR = 16.0 * math.sqrt(2.0) / 15.0 * math.pi
#: Rq / Ra of a Gaussian profile is sqrt(pi / 2) = 1.2533; seed 001 (Li et al. 2022, Eq. 10)
#: quotes 1.20-1.25 for machined surfaces and uses 1.25.
RA_TO_RQ = 1.25
#: Above this ratio h / sigma the asperity pressure and the flow-factor corrections are below
#: 1e-30 of their values at contact; they are taken as zero there (no special function is
#: evaluated on the thick-film nodes).
THICK_FILM_RATIO = 12.0

# Patir & Cheng (1978), J. Lubr. Technol. 100, 12-17, Table 1, gamma = 1: phi_x = 1 - C exp(-r H)
# for H > 0.5. The row as published (C 0.90, r 0.56); a public regression of the whole table over
# gamma (rboman/progs, apps/EHD/EHD/ehd_flow_factors.c: C = 0.89679 - 0.26591 ln(gamma),
# r = 0.43006 - 0.10828 gamma + 0.23821 gamma^2 for gamma < 1) gives 0.8968 and 0.5600 at
# gamma -> 1 (tests/film/test_roughness.py holds the two within 0.004 of phi_x).
_PC_C = 0.90
_PC_R = 0.56
# Patir & Cheng (1979), J. Lubr. Technol. 101, 220-229, Table 2, gamma = 1:
# Phi_s = A1 H^a1 exp(-a2 H + a3 H^2) for H <= 5, A2 exp(-0.25 H) for H > 5. A2 = 1.126 makes
# the two branches meet at H = 5 to 0.03 % (the regression above, A2 = 1.0766 - 0.37758
# ln(gamma), gives 1.077: 4 % lower, a fit across gamma 1/9 to 6).
_PS_A1, _PS_ALPHA1, _PS_ALPHA2, _PS_ALPHA3, _PS_A2 = 1.899, 0.98, 0.92, 0.05, 1.126
_PS_SWITCH = 5.0

SurfacePreset = Literal["turned_steel_white_metal", "ground_steel_white_metal", "steel_polymer"]
PRESET_NAMES: tuple[SurfacePreset, ...] = get_args(SurfacePreset)


@dataclass(frozen=True)
class SurfaceRoughness:
    """Roughness and elasticity of the journal and bore surfaces.

    Attributes
    ----------
    journal_rq, bore_rq : float
        RMS roughness Rq of the journal and bore surfaces, m (> 0 together; either may be 0).
        :meth:`from_ra` takes arithmetic means Ra instead.
    sigma_beta_eta : float
        Roughness parameter ``sigma beta eta`` (composite RMS height x asperity tip radius x
        asperity density), dimensionless, (0, 1).
    sigma_over_beta : float
        Composite RMS height over asperity tip radius, dimensionless, (0, 1).
    contact_modulus : float
        ``E*`` with ``1/E* = (1 - nu_j^2)/E_j + (1 - nu_b^2)/E_b``, Pa.
    boundary_friction : float
        Coefficient of friction on the asperity load, [0, 1).

    Raises
    ------
    InputError
        Naming the attribute, its value, unit and allowed range.

    Examples
    --------
    >>> s = SurfaceRoughness.preset("steel_polymer")
    >>> round(s.sigma * 1e6, 3)  # composite Rq, um: 1.25 sqrt(1.6^2 + 0.8^2)
    2.236
    """

    journal_rq: float
    bore_rq: float
    sigma_beta_eta: float = 0.04
    sigma_over_beta: float = 1e-3
    contact_modulus: float = 2.6e9
    boundary_friction: float = 0.1

    def __post_init__(self) -> None:
        journal = require_finite("journal_rq", self.journal_rq, "m")
        bore = require_finite("bore_rq", self.bore_rq, "m")
        for name, value in (("journal_rq", journal), ("bore_rq", bore)):
            if value < 0.0:
                raise InputError(name, value, "m", ">= 0 (journal and bore together > 0)")
        if journal == 0.0 and bore == 0.0:
            raise InputError("bore_rq", bore, "m", "> 0 where journal_rq is 0 (a rough surface)")
        for name in ("sigma_beta_eta", "sigma_over_beta"):
            value = require_positive(name, getattr(self, name))
            if value >= 1.0:
                raise InputError(name, value, "", "in (0, 1)")
        require_positive("contact_modulus", self.contact_modulus, "Pa")
        mu = require_finite("boundary_friction", self.boundary_friction)
        if not 0.0 <= mu < 1.0:
            raise InputError("boundary_friction", mu, "", "in [0, 1)")

    @classmethod
    def from_ra(
        cls, journal_ra: float, bore_ra: float, ra_to_rq: float = RA_TO_RQ, **kwargs: float
    ) -> SurfaceRoughness:
        """Roughness from arithmetic means Ra (m) and the factor Rq/Ra (1.20-1.25, seed 001)."""
        factor = require_finite("ra_to_rq", ra_to_rq)
        if not 1.0 <= factor <= 1.5:
            raise InputError("ra_to_rq", factor, "", "in [1, 1.5] (1.2533 for a Gaussian profile)")
        return cls(journal_rq=factor * journal_ra, bore_rq=factor * bore_ra, **kwargs)

    @classmethod
    def preset(cls, name: str) -> SurfaceRoughness:
        """A preset surface pair (docs/theory.md lists the source of each number).

        ``"steel_polymer"``: journal sleeve Ra 0.8 um against a polymer-composite liner Ra 1.6 um
        (seed 001, Li et al. 2022, Sect. 5.3), liner E = 2320 MPa, nu = 0.327 (seed 001, Sect. 2)
        on steel 206 GPa, 0.3. ``"turned_steel_white_metal"`` / ``"ground_steel_white_metal"``:
        journal Ra 0.8 / 0.4 um against a bored white-metal bore Ra 0.8 um (assumed shop
        finishes), tin babbitt ASTM B23 grade 2 E = 53 GPa, nu = 0.35 (MakeItFrom's data sheet
        of UNS L13890; see docs/theory.md). All: sigma beta eta = 0.04, sigma / beta = 0.001
        (assumed: no published measurement found; the values of common mixed-lubrication
        practice), boundary friction 0.1 (seed 002, Ciulli et al. 2010: 0.08-0.1 typical).
        """
        if name not in PRESETS:
            raise InputError("preset", name, "", "one of " + ", ".join(PRESET_NAMES))
        journal_ra, bore_ra, e_bore, nu_bore = PRESETS[name]
        modulus = contact_modulus(206e9, 0.3, e_bore, nu_bore)
        return cls.from_ra(journal_ra, bore_ra, contact_modulus=modulus)

    @property
    def sigma(self) -> float:
        """Composite RMS roughness ``sqrt(Rq_j^2 + Rq_b^2)``, m."""
        return math.hypot(self.journal_rq, self.bore_rq)

    @property
    def shear_weight(self) -> float:
        """``(Rq_j^2 - Rq_b^2) / sigma^2``: Patir & Cheng's ``V_r1 - V_r2`` with the journal as the
        moving surface 1 (the shear flow factor is ``shear_weight * Phi_s``)."""
        return (self.journal_rq**2 - self.bore_rq**2) / self.sigma**2

    @property
    def greenwood_tripp_constant(self) -> float:
        """``K E*`` of ``p_a = K E* F_5/2(h / sigma)``, Pa."""
        k = GREENWOOD_TRIPP_FACTOR * self.sigma_beta_eta**2 * math.sqrt(self.sigma_over_beta)
        return k * self.contact_modulus

    @property
    def area_constant(self) -> float:
        """``pi^2 (sigma beta eta)^2`` of ``A_c / A = pi^2 (sigma beta eta)^2 F_2(h / sigma)``."""
        return math.pi**2 * self.sigma_beta_eta**2


def contact_modulus(e1: float, nu1: float, e2: float, nu2: float) -> float:
    """Contact modulus ``E*``, Pa: ``1/E* = (1 - nu1^2)/E1 + (1 - nu2^2)/E2``."""
    return 1.0 / ((1.0 - nu1**2) / e1 + (1.0 - nu2**2) / e2)


#: Tin-based white metal (babbitt), ASTM B23 grade 2 (UNS L13890): Young's modulus 53 GPa and
#: Poisson's ratio 0.35 (MakeItFrom.com material data, which cites ASTM B23; grade 3: 56 GPa).
WHITE_METAL_MODULUS = 53e9
WHITE_METAL_POISSON = 0.35

#: Presets: journal Ra (m), bore Ra (m), bore Young's modulus (Pa) and Poisson's ratio.
PRESETS: dict[str, tuple[float, float, float, float]] = {
    "steel_polymer": (0.8e-6, 1.6e-6, 2320e6, 0.327),
    "turned_steel_white_metal": (0.8e-6, 0.8e-6, WHITE_METAL_MODULUS, WHITE_METAL_POISSON),
    "ground_steel_white_metal": (0.4e-6, 0.8e-6, WHITE_METAL_MODULUS, WHITE_METAL_POISSON),
}


# -- Gaussian integrals -----------------------------------------------------------------------
def gaussian_integral(order: float, lam: np.ndarray | float) -> np.ndarray:
    """``F_n(lam) = int_lam^inf (s - lam)^n phi(s) ds``, ``phi`` the standard normal density.

    Exact for any order ``n > -1`` through the parabolic cylinder function:
    ``F_n(lam) = Gamma(n + 1) / sqrt(2 pi) exp(-lam^2 / 4) D_{-n-1}(lam)``
    (docs/theory.md; ``scipy.special.pbdv``). Zero above :data:`THICK_FILM_RATIO`.

    Examples
    --------
    >>> [round(float(gaussian_integral(n, 0.0)), 4) for n in (0, 1, 1.5, 2, 2.5)]
    [0.5, 0.3989, 0.43, 0.5, 0.6166]
    """
    from scipy.special import gamma, pbdv

    lam = np.asarray(lam, dtype=float)
    out = np.zeros(lam.shape)
    near = lam < THICK_FILM_RATIO
    if np.any(near):
        x = lam[near]
        d, _ = pbdv(-order - 1.0, x)
        out[near] = gamma(order + 1.0) / math.sqrt(2.0 * math.pi) * np.exp(-0.25 * x * x) * d
    return out


def gaussian_integral_fit(lam: np.ndarray | float) -> np.ndarray:
    """The usual power-law fit ``F_5/2(lam) ~ 4.4086e-5 (4 - lam)^6.804`` for ``lam < 4``, 0 above.

    Quoted in many mixed-lubrication papers after Arnell et al. (Tribology: Principles and
    Design Applications, 1991); 11 % below the exact value at contact (0.550 against 0.617)
    and within a few per cent of it around ``lam = 1-2`` (docs/validation.md). The solver uses
    :func:`gaussian_integral`; this fit is offered for comparison with published results.
    """
    lam = np.asarray(lam, dtype=float)
    return np.where(lam < 4.0, 4.4086e-5 * np.clip(4.0 - lam, 0.0, None) ** 6.804, 0.0)


#: Knot spacing of the tables of F_n the solver evaluates (:func:`gaussian_integral_table`).
TABLE_STEP = 0.02
#: Lowest film-thickness ratio ``h / sigma`` the tables of F_n cover (the mean planes 4 sigma
#: past each other); the equilibrium stops at :data:`BOUNDARY_LIMIT` above it.
TABLE_LOWEST = -4.0
#: Lowest film-thickness ratio an equilibrium may reach (boundary lubrication, the mean planes
#: 3 sigma past each other): there the Greenwood-Tripp contact-area ratio
#: ``pi^2 (sigma beta eta)^2 F_2(-3)`` is 16 % with the default sigma beta eta = 0.04 (and F_5/2
#: 30 times its value at h = 0); beyond it the independent-asperity model is not used
#: (docs/theory.md, "Boundary lubrication").
BOUNDARY_LIMIT = -3.0


@lru_cache(maxsize=8)
def gaussian_integral_table(order: float) -> Any:
    """``F_n`` on ``[0, THICK_FILM_RATIO]`` as a cubic Hermite spline through exact values and
    slopes (``dF_n/dlam = -n F_{n-1}``) every :data:`TABLE_STEP`; zero above. The exact function
    costs about 8 us a node (``pbdv``); the table about 0.1 us, and it differs from it by less
    than 1e-9 of ``F_n(0)`` (7e-10 measured; its slope 1e-7; tests/film/test_roughness.py). Its
    derivative (``table(lam, 1)``) is that of the same function, so the equilibrium's Jacobian
    stays exact for what the solver evaluates. Negative ratios (the mean planes past each
    other, boundary lubrication) have their own table, :func:`gaussian_integral_table_below`."""
    from scipy.interpolate import CubicHermiteSpline

    knots = np.arange(0.0, THICK_FILM_RATIO + TABLE_STEP, TABLE_STEP)
    slopes = -order * gaussian_integral(order - 1.0, knots)
    return CubicHermiteSpline(knots, gaussian_integral(order, knots), slopes, extrapolate=True)


@lru_cache(maxsize=8)
def gaussian_integral_table_below(order: float) -> Any:
    """``F_n`` on ``[TABLE_LOWEST, 0]`` as :func:`gaussian_integral_table` (exact values and slopes
    every :data:`TABLE_STEP`): a table of its own so that the table of positive ratios, and with
    it every film above the mean plane, is the one it was (bit for bit). The two meet at 0 in
    value and slope (both exact there)."""
    from scipy.interpolate import CubicHermiteSpline

    count = round(-TABLE_LOWEST / TABLE_STEP)
    knots = np.linspace(TABLE_LOWEST, 0.0, count + 1)
    slopes = -order * gaussian_integral(order - 1.0, knots)
    return CubicHermiteSpline(knots, gaussian_integral(order, knots), slopes, extrapolate=True)


def _tabulated(order: float, lam: np.ndarray, derivative: bool = False) -> np.ndarray:
    """``F_n(lam)`` (or its derivative) from the tables, zero above :data:`THICK_FILM_RATIO`:
    :func:`gaussian_integral_table` for ``lam >= 0``, :func:`gaussian_integral_table_below` for
    negative ratios (held at :data:`TABLE_LOWEST` below it)."""
    lam = np.asarray(lam, dtype=float)
    out = np.zeros(lam.shape)
    near = lam < THICK_FILM_RATIO
    if np.any(near):
        table = gaussian_integral_table(order)
        out[near] = table(np.maximum(lam[near], 0.0), 1 if derivative else 0)
    below = lam < 0.0
    if np.any(below):
        table = gaussian_integral_table_below(order)
        out[below] = table(np.maximum(lam[below], TABLE_LOWEST), 1 if derivative else 0)
    return out


# -- asperity contact ---------------------------------------------------------------------------
def asperity_pressure(surface: SurfaceRoughness, film: np.ndarray) -> np.ndarray:
    """Greenwood-Tripp asperity contact pressure ``K E* F_5/2(h / sigma)``, Pa, for films ``h`` (m)."""
    return surface.greenwood_tripp_constant * _tabulated(2.5, np.asarray(film) / surface.sigma)


def asperity_pressure_derivative(surface: SurfaceRoughness, film: np.ndarray) -> np.ndarray:
    """``d p_a / d h``, Pa/m (<= 0): ``dF_n/dlam = -n F_{n-1}``, so ``-(5/2) K E* F_3/2 / sigma``
    (taken from the same table as :func:`asperity_pressure`)."""
    lam = np.asarray(film) / surface.sigma
    return surface.greenwood_tripp_constant * _tabulated(2.5, lam, derivative=True) / surface.sigma


def contact_area_ratio(surface: SurfaceRoughness, film: np.ndarray) -> np.ndarray:
    """Real over nominal contact area ``pi^2 (sigma beta eta)^2 F_2(h / sigma)`` (Greenwood-Tripp)."""
    return surface.area_constant * _tabulated(2.0, np.asarray(film) / surface.sigma)


# -- flow factors (lam = h / sigma) -------------------------------------------------------------
def pressure_flow_factor(lam: np.ndarray) -> np.ndarray:
    """Patir-Cheng pressure flow factor of isotropic roughness, ``1 - 0.90 exp(-0.56 lam)``.

    Fitted by Patir & Cheng (1978) for ``lam > 0.5``; below, the same expression is kept (it
    stays positive, 0.1 at contact, and the ``h^3`` it multiplies carries the vanishing
    pressure flow), so the film equation stays defined as ``h -> 0``.
    """
    return 1.0 - _PC_C * np.exp(-_PC_R * np.asarray(lam, dtype=float))


def pressure_flow_factor_derivative(lam: np.ndarray) -> np.ndarray:
    """``d phi_x / d lam``."""
    return _PC_C * _PC_R * np.exp(-_PC_R * np.asarray(lam, dtype=float))


def shear_flow_factor(lam: np.ndarray) -> np.ndarray:
    """Patir-Cheng shear flow factor ``Phi_s`` of one rough surface, isotropic (gamma = 1).

    ``1.899 lam^0.98 exp(-0.92 lam + 0.05 lam^2)`` up to ``lam = 5``, ``1.126 exp(-0.25 lam)``
    above (Patir & Cheng 1979); zero at contact. The two branches meet to 0.2 %.
    """
    lam = np.maximum(np.asarray(lam, dtype=float), 0.0)
    short = np.minimum(lam, _PS_SWITCH)  # the fit's own range: its exp(0.05 lam^2) overflows far above
    low = _PS_A1 * short**_PS_ALPHA1 * np.exp(-_PS_ALPHA2 * short + _PS_ALPHA3 * short * short)
    return np.where(lam <= _PS_SWITCH, low, _PS_A2 * np.exp(-0.25 * lam))


def shear_flow_factor_derivative(lam: np.ndarray) -> np.ndarray:
    """``d Phi_s / d lam``."""
    lam = np.maximum(np.asarray(lam, dtype=float), 1e-300)
    short = np.minimum(lam, _PS_SWITCH)
    low = shear_flow_factor(short) * (_PS_ALPHA1 / short - _PS_ALPHA2 + 2.0 * _PS_ALPHA3 * short)
    return np.where(lam <= _PS_SWITCH, low, -0.25 * _PS_A2 * np.exp(-0.25 * lam))


def mean_gap(lam: np.ndarray) -> np.ndarray:
    """Mean local gap over sigma, ``h_T / sigma = lam Phi(lam) + phi(lam)`` (Gaussian heights).

    The expected value of ``max(h + delta, 0)`` with ``delta ~ N(0, sigma^2)``: exact for all
    ``lam`` (``1/sqrt(2 pi)`` at ``h = 0``, ``lam`` plus a term below ``1e-3`` above
    ``lam = 3``). It carries the Couette transport and the squeeze (``dh_T/dh = Phi(lam)``).
    """
    from scipy.special import ndtr

    lam = np.asarray(lam, dtype=float)
    return lam * ndtr(lam) + np.exp(-0.5 * lam * lam) / math.sqrt(2.0 * math.pi)


def mean_gap_derivative(lam: np.ndarray) -> np.ndarray:
    """``d(h_T/sigma) / d lam = Phi(lam)``, the standard normal distribution function."""
    from scipy.special import ndtr

    return np.asarray(ndtr(np.asarray(lam, dtype=float)))


def lubrication_regime(lam: float) -> str:
    """``"boundary"`` below ``lam = 1``, ``"mixed"`` up to 3, ``"full film"`` above (seed 001, Eq. 10)."""
    if lam < 1.0:
        return "boundary"
    if lam <= 3.0:
        return "mixed"
    return "full film"


# -- flow below the mean plane (boundary lubrication) ------------------------------------------
#: Film-thickness ratio below which the flow continues past Patir & Cheng's fits (which hold for
#: ``lam > 0.5`` and were kept down to the former film floor 0.02 sigma): at and above it the
#: flow is the one of before, bit for bit, so every equilibrium that stayed above the floor is
#: unchanged. docs/theory.md, "Boundary lubrication".
LAMBDA_SWITCH = 0.02
#: Share of the pressure flow factor on the mean gap at :data:`LAMBDA_SWITCH` that is left far
#: below it: the regularisation of a gap past its percolation threshold (no connected path for
#: the pressure flow, Harp & Salant 2001) that keeps the film equation's matrix definite.
PERCOLATED_SHARE = 0.5


def _normal_cdf(lam: float) -> float:
    return 0.5 * (1.0 + math.erf(lam / math.sqrt(2.0)))


def _switch_constants() -> tuple[float, float, float, float]:
    """``(psi_s, k, Phi_s(lam_s), q)``: the continuation below :data:`LAMBDA_SWITCH` matched in
    value and slope to ``lam^3 phi_x`` and ``Phi_s`` there (docs/theory.md)."""
    lam = LAMBDA_SWITCH
    cdf = _normal_cdf(lam)
    gap = lam * cdf + math.exp(-0.5 * lam * lam) / math.sqrt(2.0 * math.pi)
    phi_x = 1.0 - _PC_C * math.exp(-_PC_R * lam)
    slope_phi_x = _PC_C * _PC_R * math.exp(-_PC_R * lam)
    psi_s = lam**3 * phi_x / gap**3
    # d ln(lam^3 phi_x)/dlam = d ln(h_T^3 psi)/dlam at lam_s fixes psi's log-slope.
    log_slope_psi = 3.0 / lam + slope_phi_x / phi_x - 3.0 * cdf / gap
    k = log_slope_psi / (1.0 - PERCOLATED_SHARE)
    shear = _PS_A1 * lam**_PS_ALPHA1 * math.exp(-_PS_ALPHA2 * lam + _PS_ALPHA3 * lam * lam)
    log_slope_shear = _PS_ALPHA1 / lam - _PS_ALPHA2 + 2.0 * _PS_ALPHA3 * lam
    q = log_slope_shear * gap / cdf
    return psi_s, k, shear, q


_PSI_S, _PSI_K, _SHEAR_S, _SHEAR_Q = _switch_constants()
_GAP_S = LAMBDA_SWITCH * _normal_cdf(LAMBDA_SWITCH) + math.exp(-0.5 * LAMBDA_SWITCH**2) / math.sqrt(2.0 * math.pi)


def boundary_flow_factor(lam: np.ndarray) -> np.ndarray:
    """Pressure flow factor on the mean gap below :data:`LAMBDA_SWITCH`,
    ``psi = psi_s (a + (1 - a) exp(k (lam - lam_s)))`` with ``a`` = :data:`PERCOLATED_SHARE`:
    the pressure flow there is ``h_T^3 psi`` (over ``sigma^3``), equal in value and slope to
    ``h^3 phi_x`` at ``lam_s`` and tending to ``a psi_s h_T^3`` as the gap closes."""
    lam = np.asarray(lam, dtype=float)
    return _PSI_S * (
        PERCOLATED_SHARE + (1.0 - PERCOLATED_SHARE) * np.exp(_PSI_K * np.minimum(lam - LAMBDA_SWITCH, 0.0))
    )


def boundary_flow_factor_derivative(lam: np.ndarray) -> np.ndarray:
    """``d psi / d lam`` (of :func:`boundary_flow_factor`, on its range ``lam <= lam_s``)."""
    lam = np.asarray(lam, dtype=float)
    return _PSI_S * (1.0 - PERCOLATED_SHARE) * _PSI_K * np.exp(_PSI_K * np.minimum(lam - LAMBDA_SWITCH, 0.0))


def boundary_shear_factor(gap: np.ndarray) -> np.ndarray:
    """``Phi_s`` below :data:`LAMBDA_SWITCH` as a power of the mean gap, ``Phi_s(lam_s) (h_T /
    h_T(lam_s))^q`` (value and slope matched at ``lam_s``): it vanishes with the mean gap, faster
    than it, so the transport ``h_T + w Phi_s`` (|w| <= 1) stays positive."""
    return _SHEAR_S * (np.minimum(np.asarray(gap, dtype=float), _GAP_S) / _GAP_S) ** _SHEAR_Q


class FilmFlow(Protocol):
    """What the film equation takes from a non-smooth flow model (:class:`RoughFilm`, or a
    turbulent film, :class:`shaftline.film.turbulence.TurbulentFilm`): the pressure-flow
    conductances of theta and z faces, the Couette transport of theta faces and the squeeze
    factor of nodes, each a function of the local dimensionless film ``H``, with derivatives."""

    def conductance(self, film: np.ndarray) -> np.ndarray: ...
    def conductance_derivative(self, film: np.ndarray) -> np.ndarray: ...
    def axial_conductance(self, film: np.ndarray) -> np.ndarray: ...
    def axial_conductance_derivative(self, film: np.ndarray) -> np.ndarray: ...
    def transport(self, film: np.ndarray) -> np.ndarray: ...
    def transport_derivative(self, film: np.ndarray) -> np.ndarray: ...
    def squeeze_factor(self, film: np.ndarray) -> np.ndarray: ...
    def squeeze_factor_derivative(self, film: np.ndarray) -> np.ndarray: ...


@dataclass(frozen=True)
class RoughFilm:
    """The roughness as the dimensionless film equation needs it (films over the clearance c).

    Attributes
    ----------
    sigma : float
        Composite RMS roughness over the radial clearance, ``sigma / c``.
    shear_weight : float
        :attr:`SurfaceRoughness.shear_weight` (journal the moving surface).
    """

    sigma: float
    shear_weight: float

    def conductance(self, film: np.ndarray) -> np.ndarray:
        """``H^3 phi_x(H / sigma)`` of face films ``H``; below ``lam_s`` (:data:`LAMBDA_SWITCH`,
        films down to the boundary regime, ``H <= 0`` included) ``(h_T/c)^3 psi`` on the mean gap
        (:func:`boundary_flow_factor`): positive for every film."""
        lam = film / self.sigma
        above = film**3 * pressure_flow_factor(lam)
        if np.all(lam >= LAMBDA_SWITCH):
            return above
        gap = self.sigma * mean_gap(lam)
        return np.where(lam >= LAMBDA_SWITCH, above, gap**3 * boundary_flow_factor(lam))

    def conductance_derivative(self, film: np.ndarray) -> np.ndarray:
        """``d(H^3 phi_x) / dH`` (below ``lam_s``: ``d((h_T/c)^3 psi) / dH``)."""
        lam = film / self.sigma
        above = 3.0 * film**2 * pressure_flow_factor(lam) + film**3 * pressure_flow_factor_derivative(lam) / self.sigma
        if np.all(lam >= LAMBDA_SWITCH):
            return above
        gap = self.sigma * mean_gap(lam)
        below = 3.0 * gap**2 * mean_gap_derivative(lam) * boundary_flow_factor(lam) + gap**3 * (
            boundary_flow_factor_derivative(lam) / self.sigma
        )
        return np.where(lam >= LAMBDA_SWITCH, above, below)

    def axial_conductance(self, film: np.ndarray) -> np.ndarray:
        """``H^3 phi_z`` of z-face films: ``phi_z = phi_x`` for isotropic roughness."""
        return self.conductance(film)

    def axial_conductance_derivative(self, film: np.ndarray) -> np.ndarray:
        """``d(H^3 phi_z) / dH``."""
        return self.conductance_derivative(film)

    def transport(self, film: np.ndarray) -> np.ndarray:
        """Couette transport of face films ``H`` over that of a smooth film, ``h_T/c + (sigma/c) w Phi_s``
        (``Phi_s`` continued below ``lam_s`` by :func:`boundary_shear_factor`)."""
        lam = film / self.sigma
        gap = mean_gap(lam)
        shear = shear_flow_factor(lam)
        if not np.all(lam >= LAMBDA_SWITCH):
            shear = np.where(lam >= LAMBDA_SWITCH, shear, boundary_shear_factor(gap))
        return self.sigma * (gap + self.shear_weight * shear)

    def transport_derivative(self, film: np.ndarray) -> np.ndarray:
        """``d transport / dH``."""
        lam = film / self.sigma
        slope = shear_flow_factor_derivative(lam)
        if not np.all(lam >= LAMBDA_SWITCH):
            gap = mean_gap(lam)
            below = _SHEAR_Q * boundary_shear_factor(gap) * mean_gap_derivative(lam) / gap
            slope = np.where(lam >= LAMBDA_SWITCH, slope, below)
        return mean_gap_derivative(lam) + self.shear_weight * slope

    def squeeze_factor(self, film: np.ndarray) -> np.ndarray:
        """``dh_T / dh = Phi(H / sigma)`` of node films: the squeeze acts on the mean gap."""
        return mean_gap_derivative(film / self.sigma)

    def squeeze_factor_derivative(self, film: np.ndarray) -> np.ndarray:
        """``d Phi(H / sigma) / dH = phi(H / sigma) / sigma``."""
        lam = film / self.sigma
        return np.exp(-0.5 * lam * lam) / (math.sqrt(2.0 * math.pi) * self.sigma)
