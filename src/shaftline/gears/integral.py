"""Integral-temperature method of ISO/TS 6336-21 (formerly ISO/TR 13989-2) for an external spur or
helical pair without tip relief, pinion driving (docs/theory.md Sect. 19.5).

The flash temperature at the pinion tip E, weighted over the path by the contact ratio factor,
is the integral flash temperature; with the bulk temperature it gives the integral temperature,
compared with the one the oil reached at its FZG A/8.3/90 failure stage::

    mu_mC = 0.045 (w_Bt K_Bgamma / (v_SigmaC rho_redC))^0.2 eta_oil^-0.05 X_R X_L
            (w_Bt >= 150 N/mm in it; N/mm, m/s, mm, mPa s),
    v_SigmaC = 2 v tan(alpha_wt) cos(alpha_t),  rho_redC = u/(1 + u)^2 a sin(alpha_wt)/cos(beta_b),
    X_R = 2.2 (Ra/rho_redC)^0.25,  K_Bgamma = 1 (eps_gamma <= 2) ... 1.3 (>= 3.5)
    theta_flaE = mu_mC X_M X_BE X_alphabeta (K_Bgamma w_Bt)^0.75 v^0.5 / a^0.25 X_E / (X_Q X_Ca)
    X_BE = 0.51 sqrt(u + 1) (sqrt(rho_E1) - sqrt(rho_E2/u)) / (rho_E1 rho_E2)^0.25
    X_alphabeta = 1.22 sin^0.25(alpha_wt) cos^0.25(alpha_n) cos^0.25(beta) / (cos^0.5(alpha_wt) cos^0.5(alpha_t))
    theta_flaint = X_eps theta_flaE,  theta_M = theta_oil + 0.7 X_S theta_flaint,
    theta_int = theta_M + 1.5 theta_flaint,
    theta_intS = 80 + 0.23 T_1T X_L + 1.5 X_WrelT 0.2 T_1T (100/nu_40)^0.02 X_L,  T_1T = 3.726 S_FZG^2,
    S_intS = theta_intS / theta_int     (< 1 high risk, 1-2 critical, > 2 low risk).

X_M = 50 (steel), X_E = 1 (run in), X_Ca = 1 (no tip relief), X_Q from the ratio of the
addendum contact ratios, X_eps from them (Eq. 39-44). Source: ISO/TR 13989-2:2000 as transcribed
in the public implementation cited in :mod:`shaftline.gears.flash`; the standard's text was not
available here.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from shaftline.gears.flash import (
    LUBRICANT_COEFFICIENTS,
    LUBRICATION_METHODS,
    IsoScuffingData,
    angle_factor,
    thermoelastic_factor,
    unit_load,
)
from shaftline.gears.mesh import GearPair


def contact_ratio_factor(eps_1: float, eps_2: float) -> float:
    """X_eps from the addendum contact ratios of pinion and wheel (ISO/TR 13989-2 Eq. 39-44)."""
    eps = eps_1 + eps_2
    k = 1.0 / (2.0 * eps * eps_1)
    if eps < 1.0:
        return k * (eps_1**2 + eps_2**2)
    if eps < 2.0:
        if eps_1 < 1.0 and eps_2 < 1.0:
            return k * (0.70 * (eps_1**2 + eps_2**2) - 0.22 * eps + 0.52 - 0.60 * eps_1 * eps_2)
        if eps_1 >= 1.0:
            return k * (0.18 * eps_1**2 + 0.70 * eps_2**2 + 0.82 * eps_1 - 0.52 * eps_2 - 0.30 * eps_1 * eps_2)
        return k * (0.70 * eps_1**2 + 0.18 * eps_2**2 - 0.52 * eps_1 + 0.82 * eps_2 - 0.30 * eps_1 * eps_2)
    if eps_1 >= eps_2:
        return k * (0.44 * eps_1**2 + 0.59 * eps_2**2 + 0.30 * eps_1 - 0.30 * eps_2 - 0.15 * eps_1 * eps_2)
    return k * (0.59 * eps_1**2 + 0.44 * eps_2**2 - 0.30 * eps_1 + 0.30 * eps_2 - 0.15 * eps_1 * eps_2)


def helical_load_factor(total_contact_ratio: float) -> float:
    """K_Bgamma (Eq. 5)."""
    if total_contact_ratio <= 2.0:
        return 1.0
    if total_contact_ratio >= 3.5:
        return 1.3
    return 1.0 + 0.2 * math.sqrt((total_contact_ratio - 2.0) * (5.0 - total_contact_ratio))


@dataclass(frozen=True, eq=False)
class IntegralRating:
    """The integral-temperature rating at every torque and speed (degC, K).

    Attributes
    ----------
    friction : ndarray
        mu_mC.
    flash_tip, flash_integral : ndarray
        theta_flaE and theta_flaint, K.
    bulk, integral : ndarray
        theta_M and theta_int, degC.
    scuffing_integral : float
        theta_intS, degC.
    safety : ndarray
        S_intS.
    """

    friction: np.ndarray
    flash_tip: np.ndarray
    flash_integral: np.ndarray
    bulk: np.ndarray
    integral: np.ndarray
    scuffing_integral: float
    safety: np.ndarray


def integral_temperature(
    pair: GearPair,
    data: IsoScuffingData,
    pinion_torque: float | np.ndarray,
    pinion_speed: float | np.ndarray,
    oil_temperature: float,
    viscosity: float,
    viscosity_40: float,
) -> IntegralRating:
    """The integral-temperature rating for pinion torques (N m) and speeds (rad/s) that broadcast;
    viscosity at the oil temperature (Pa s) and kinematic viscosity at 40 degC (m^2/s)."""
    alpha_wt, alpha_t = pair.working_pressure_angle, pair.transverse_pressure_angle
    u = pair.teeth_2 / pair.teeth_1
    a = pair.working_centre_distance * 1e3  # mm
    w = unit_load(pair, pinion_torque) * 1e-3  # N/mm
    v = np.asarray(pinion_speed, dtype=float) * pair.pitch_radius(1)
    k_bg = helical_load_factor(pair.transverse_contact_ratio + pair.overlap_ratio)
    v_sum = 2.0 * np.minimum(v, 50.0) * math.tan(alpha_wt) * math.cos(alpha_t)
    rho_red = u / (1.0 + u) ** 2 * a * math.sin(alpha_wt) / math.cos(pair.base_helix_angle)
    roughness = 2.2 * (data.roughness_ra * 1e6 / rho_red) ** 0.25
    x_l = LUBRICANT_COEFFICIENTS[data.base_oil]
    mu = 0.045 * (np.maximum(w, 150.0) * k_bg / (v_sum * rho_red)) ** 0.2 * (viscosity * 1e3) ** -0.05 * roughness * x_l
    # thermo-elastic factor X_M (50 for steel) from the data's E_r and B_M, ISO's mixed units
    x_m = thermoelastic_factor(data)
    x_ab = angle_factor(alpha_wt, pair.pressure_angle, pair.helix_angle, alpha_t)
    rho_e1 = pair.end_of_contact * 1e3
    rho_e2 = pair.line_of_action * 1e3 - rho_e1
    x_be = 0.51 * math.sqrt(u + 1.0) * (math.sqrt(rho_e1) - math.sqrt(rho_e2 / u)) / (rho_e1 * rho_e2) ** 0.25
    # addendum contact ratios: recess (pinion tip, C..E) and approach (wheel tip, A..C)
    eps_1 = (pair.end_of_contact - pair.pitch_point) / pair.base_pitch
    eps_2 = (pair.pitch_point - pair.start_of_contact) / pair.base_pitch
    ratio = eps_2 / eps_1  # pinion driving: approach over recess
    x_q = 1.0 if ratio <= 1.5 else 0.6 if ratio >= 3.0 else 1.4 - 4.0 / 15.0 * ratio
    flash_tip = mu * x_m * x_be * x_ab * (k_bg * w) ** 0.75 * np.sqrt(v) / a**0.25 / x_q
    flash_integral = contact_ratio_factor(eps_1, eps_2) * flash_tip
    bulk = oil_temperature + 0.7 * LUBRICATION_METHODS[data.lubrication] * flash_integral
    integral = bulk + 1.5 * flash_integral
    t_1t = 3.726 * data.fzg_load_stage**2
    scuffing = (
        80.0
        + 0.23 * t_1t * x_l
        + data.structural_factor * 1.5 * 0.2 * t_1t * (100.0 / (viscosity_40 * 1e6)) ** 0.02 * x_l
    )
    return IntegralRating(
        np.asarray(mu), flash_tip, flash_integral, bulk, integral, float(scuffing), scuffing / integral
    )
