"""Flash-temperature method of ISO/TS 6336-20 (formerly ISO/TR 13989-1, after DIN 3990-4) for an
external spur or helical pair, vectorised along the path of contact (docs/theory.md Sect. 19.3).

Two forms of the flash temperature, chosen by name from :data:`FLASH_METHODS` (SciPy ``METHODS``
style; docs/theory.md Sect. 19.3 for the evidence behind the default):

* ``"iso_cylindrical"`` (default) - ISO's form for cylindrical gears (ISO/TR 13989-1 Eq. A.5-A.8,
  the form both public transcriptions rate with)::

      theta_fl = mu_m X_M X_J X_G (X_Gamma w_Bt)^0.75 v_t^0.5 / a^0.25     (N/mm, m/s, mm)
      X_G = 0.51 X_alpha_beta (u + 1)^0.5 |(1 + Gamma)^0.5 - (1 - Gamma/u)^0.5| / ((1 + Gamma)(u - Gamma))^0.25

  with X_M = E_r^0.25 / B_M (50 for steel) and the angle factor X_alpha_beta in its full form (ISO's
  Table A.1). On spur gears this is Blok's formula on the *normal* load w_Bt / cos(alpha_t) with
  Blok's Hertzian constant 0.51 x 1.22 x (8/pi)^0.25 = 0.786 (= 1.11/sqrt(2)).
* ``"iso_general"`` - ISO's general Eq. (5) as transcribed (constant 2.52 in mixed units), Blok's
  formula on the *transverse* unit load at the reference circle::

      theta_fl = K mu_m X_J w |sqrt(v_1) - sqrt(v_2)| / (B_M sqrt(b_H)),   K = 0.80

  with ``w = X_Gamma w_Bt``, ``w_Bt = F_t / b``, ``b_H = sqrt(8 w rho_rel / (pi E_r))`` and the
  factor sqrt(cos beta_b) of the 6336-20 transcription's angle factor for helical gears. On 20 deg
  spur gears it is cos(alpha_t)^0.75 x 0.80/0.786 = 0.971 of the cylindrical form (S_B up to 2.9 % higher);
  it was the only form before issue 14's closing work and is kept for comparison.

Mean friction coefficient (ISO's method, constant along the path)::

    mu_m = 0.060 (w_Bt / (v_SigmaC rho_relC))^0.2 X_L X_R    (N/mm, m/s, mm)
    v_SigmaC = 2 min(v_t, 50) sin(alpha_wt),  X_R = Ra^0.25 (Ra the mean of both flanks, um),
    X_L = c_oil eta_oil^-0.05 (mPa s; c_oil 1.0 mineral, 0.8 PAO, 1.3 phosphate ester, ...)

Approach factor (pinion driving, no tip relief on the wheel): ``X_J = 1 + (C_eff - C_a2)/50 um
x (-Gamma/(Gamma_E - Gamma_A))^3`` in the approach (Gamma < 0), 1 elsewhere, with
``C_eff = F_t/(b cos alpha_t c_gamma)`` and ``Gamma = rho_1/rho_1C - 1``.

Bulk temperature ``theta_M = theta_oil + 0.47 X_S X_mp theta_flm`` (theta_flm the mean flash
temperature along the path, X_S 1.0 dip, 1.2 spray, 0.2 immersed; X_mp 1 for one mating gear),
contact temperature ``theta_B = theta_M + theta_fl``, scuffing temperature from the oil's FZG
A/8.3/90 failure load stage ``theta_S = 80 + (0.85 + 1.4 X_W) X_L S_FZG^2`` (degC), safety
factor ``S_B = (theta_S - theta_oil) / (theta_Bmax - theta_oil)``.

Source of the coefficients: ISO/TR 13989-1:2000 Eq. (1), (5), (11), (22)-(28), (45)-(48), (99),
(100) as transcribed in a public implementation (MechanicalCalculatorWeb, Iso13989FlashTemperature);
the standard's own text was not available here. Assumptions are listed in docs/theory.md 19.3.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from shaftline.errors import InputError
from shaftline.gears.mesh import GearPair

#: Blok's constant as ISO's Eq. (5) has it. Jaeger's moving band source gives 0.798 for a uniform
#: flux over the Hertzian width and 0.786 (Blok's 1.11 on sqrt(2 b_H)) for the semi-elliptical one:
#: ISO's 0.80 is Blok's value rounded up (tests/gears/test_scuffing.py, docs/theory.md 19.3).
BLOK_CONSTANT = 0.80

#: Thermal contact coefficient of martensitic steel, ISO's 435 N/(mm^0.5 m^0.5 s^0.5 K) in SI
#: (x sqrt(1000)): sqrt(lambda rho c), N/(m s^0.5 K).
STEEL_THERMAL_CONTACT_COEFFICIENT = 435.0 * math.sqrt(1000.0)

#: Lubricant factor coefficients of ISO/TR 13989-1 Eq. (27), by base oil.
LUBRICANT_COEFFICIENTS = {
    "mineral": 1.0,
    "polyalphaolefin": 0.8,
    "polyglycol non-water-soluble": 0.7,
    "polyglycol water-soluble": 0.6,
    "phosphate ester": 1.3,
    "traction fluid": 1.5,
}

#: Lubrication method factor X_S (Eq. 22).
LUBRICATION_METHODS = {"dip": 1.0, "spray": 1.2, "immersed": 0.2}


@dataclass(frozen=True)
class IsoScuffingData:
    """Data of ISO's flash-temperature method beside the geometry (SI unless stated).

    Attributes
    ----------
    fzg_load_stage : float
        Load stage at which the oil scuffs in the FZG A/8.3/90 test (ISO 14635-1), 1-12 (14).
    base_oil : str
        A key of :data:`LUBRICANT_COEFFICIENTS`.
    roughness_ra : float
        Mean arithmetic roughness of the two flanks, m.
    structural_factor : float
        X_W (1.0 through-hardened and case-carburized steel with 10-20 % retained austenite).
    thermal_contact_coefficient : float
        B_M, N/(m s^0.5 K).
    lubrication : str
        dip, spray or immersed (X_S).
    mesh_stiffness : float
        c_gamma, N/m^2 (20 N/(mm um)).
    tip_relief_wheel : float
        C_a2, m (0: unmodified).
    reduced_modulus : float
        E_r = 2 / ((1 - nu1^2)/E1 + (1 - nu2^2)/E2), Pa.
    flash_method : str
        A key of :data:`FLASH_METHODS`: ``"iso_cylindrical"`` (ISO's form for cylindrical gears,
        Eq. A.5, default) or ``"iso_general"`` (ISO's general Eq. 5 on the transverse load).
    """

    fzg_load_stage: float
    base_oil: str = "mineral"
    roughness_ra: float = 0.5e-6
    structural_factor: float = 1.0
    thermal_contact_coefficient: float = STEEL_THERMAL_CONTACT_COEFFICIENT
    lubrication: str = "dip"
    mesh_stiffness: float = 20e9
    tip_relief_wheel: float = 0.0
    reduced_modulus: float = 206e9 / (1 - 0.3**2)
    flash_method: str = "iso_cylindrical"

    def __post_init__(self) -> None:
        if self.flash_method not in FLASH_METHODS:
            raise InputError("flash_method", self.flash_method, "", "one of " + ", ".join(FLASH_METHODS))
        if not 1.0 <= self.fzg_load_stage <= 14.0:
            raise InputError("fzg_load_stage", self.fzg_load_stage, "", "an FZG A/8.3/90 load stage 1-14")
        if self.base_oil not in LUBRICANT_COEFFICIENTS:
            raise InputError("base_oil", self.base_oil, "", "one of " + ", ".join(LUBRICANT_COEFFICIENTS))
        if self.lubrication not in LUBRICATION_METHODS:
            raise InputError("lubrication", self.lubrication, "", "one of " + ", ".join(LUBRICATION_METHODS))
        if not 0.0 < self.roughness_ra < 2e-5:
            raise InputError("roughness_ra", self.roughness_ra, "m", "in (0, 20e-6) m")


def lubricant_factor(data: IsoScuffingData, viscosity: float | np.ndarray) -> np.ndarray:
    """X_L = c_oil eta^-0.05 with eta in mPa s (viscosity in Pa s)."""
    return LUBRICANT_COEFFICIENTS[data.base_oil] * (np.asarray(viscosity) * 1e3) ** -0.05


def scuffing_temperature(data: IsoScuffingData, viscosity: float | np.ndarray) -> np.ndarray:
    """theta_S = 80 + (0.85 + 1.4 X_W) X_L S_FZG^2, degC."""
    return 80.0 + (0.85 + 1.4 * data.structural_factor) * lubricant_factor(data, viscosity) * data.fzg_load_stage**2


def unit_load(pair: GearPair, pinion_torque: float | np.ndarray) -> np.ndarray:
    """w_Bt = F_t / b with F_t = T_1 / r_1 at the reference circle, N/m."""
    return np.asarray(pinion_torque, dtype=float) / (pair.pitch_radius(1) * pair.face_width)


def pitch_line_velocity(pair: GearPair, pinion_speed: float | np.ndarray) -> np.ndarray:
    """v_t = omega_1 r_1, m/s."""
    return np.asarray(pinion_speed, dtype=float) * pair.pitch_radius(1)


def _transverse_radii(pair: GearPair, position: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    rho_1 = np.asarray(position, dtype=float)
    return rho_1, pair.line_of_action - rho_1


def mean_friction(
    pair: GearPair,
    data: IsoScuffingData,
    pinion_torque: float | np.ndarray,
    pinion_speed: float | np.ndarray,
    viscosity: float | np.ndarray,
) -> np.ndarray:
    """ISO's mean coefficient of friction mu_m (constant along the path); viscosity at the oil
    temperature, Pa s."""
    w = unit_load(pair, pinion_torque) * 1e-3  # N/mm
    v_sum = 2.0 * np.minimum(pitch_line_velocity(pair, pinion_speed), 50.0) * math.sin(pair.working_pressure_angle)
    c = pair.pitch_point
    rho_rel = c * (pair.line_of_action - c) / pair.line_of_action * 1e3  # mm
    roughness = (data.roughness_ra * 1e6) ** 0.25
    return 0.060 * (w / (v_sum * rho_rel)) ** 0.2 * lubricant_factor(data, viscosity) * roughness


def approach_factor(
    pair: GearPair, data: IsoScuffingData, pinion_torque: float | np.ndarray, position: np.ndarray
) -> np.ndarray:
    """X_J along the path, pinion driving (the wheel's tip enters at A)."""
    gamma = np.asarray(position) / pair.pitch_point - 1.0
    gamma_a = pair.start_of_contact / pair.pitch_point - 1.0
    gamma_e = pair.end_of_contact / pair.pitch_point - 1.0
    # optimal tip relief C_eff = F_t / (b cos alpha_t c_gamma), m
    c_eff = unit_load(pair, pinion_torque) / (math.cos(pair.transverse_pressure_angle) * data.mesh_stiffness)
    excess = (c_eff - data.tip_relief_wheel) / 50e-6
    x_j = 1.0 + excess * (np.maximum(-gamma, 0.0) / (gamma_e - gamma_a)) ** 3
    return np.maximum(x_j, 1.0)


def angle_factor(
    working_pressure_angle: float, normal_pressure_angle: float, helix_angle: float, transverse_pressure_angle: float
) -> float:
    """ISO's angle factor X_alphabeta (ISO/TR 13989-1 Eq. A.8, ISO/TR 13989-2), angles in rad::

        X_alphabeta = 1.22 (sin a_wt cos a_n cos beta)^0.25 / (cos a_wt cos a_t)^0.5

    The cos a_n, cos a_t terms carry the normal load F_t/cos a_t of Blok's formula; with them the
    factor reproduces ISO's Table A.1 (0.978 at a_wt = 20 deg, 1.007 at 22 deg for a_n = 20 deg),
    without them it is 1.6 % low (docs/theory.md Sect. 19.3, tests/gears/test_scuffing.py).

    Examples
    --------
    >>> round(angle_factor(math.radians(20), math.radians(20), 0.0, math.radians(20)), 3)
    0.978
    """
    return (
        1.22
        * (math.sin(working_pressure_angle) * math.cos(normal_pressure_angle) * math.cos(helix_angle)) ** 0.25
        / math.sqrt(math.cos(working_pressure_angle) * math.cos(transverse_pressure_angle))
    )


def thermoelastic_factor(data: IsoScuffingData) -> float:
    """X_M = E_r^0.25 / B_M in ISO's mixed units (N/mm^2, N/(mm^0.5 m^0.5 s^0.5 K)): 50 for steel."""
    return 1000.0 * (data.reduced_modulus * 1e-6) ** 0.25 / (data.thermal_contact_coefficient / math.sqrt(1000.0))


def _general_form(
    pair: GearPair,
    data: IsoScuffingData,
    friction: np.ndarray,
    load: np.ndarray,
    pinion_speed: np.ndarray,
    position: np.ndarray,
) -> np.ndarray:
    # Blok with K = 0.80 on the transverse unit load (ISO's general Eq. 5 as transcribed), SI
    rho_1, rho_2 = _transverse_radii(pair, position)
    v_1 = pinion_speed * rho_1
    v_2 = pinion_speed * pair.teeth_1 / pair.teeth_2 * rho_2
    rho_rel = rho_1 * rho_2 / (rho_1 + rho_2)
    half_width = np.sqrt(8.0 * load * rho_rel / (math.pi * data.reduced_modulus))
    theta = (
        BLOK_CONSTANT
        * friction
        * load
        * np.abs(np.sqrt(v_1) - np.sqrt(v_2))
        / (data.thermal_contact_coefficient * np.sqrt(half_width))
    )
    return theta * math.sqrt(math.cos(pair.base_helix_angle))


def _cylindrical_form(
    pair: GearPair,
    data: IsoScuffingData,
    friction: np.ndarray,
    load: np.ndarray,
    pinion_speed: np.ndarray,
    position: np.ndarray,
) -> np.ndarray:
    # ISO/TR 13989-1 Eq. (A.5)-(A.8) in its mixed units (N/mm, m/s, mm), as the standard writes it
    u = pair.teeth_2 / pair.teeth_1
    gamma = np.asarray(position, dtype=float) / pair.pitch_point - 1.0
    x_ab = angle_factor(
        pair.working_pressure_angle, pair.pressure_angle, pair.helix_angle, pair.transverse_pressure_angle
    )
    # |sqrt(1 + Gamma) - sqrt(1 - Gamma/u)| is |sqrt(rho_1) - sqrt(rho_2/u)| / sqrt(rho_1C)
    x_g = (
        0.51
        * x_ab
        * math.sqrt(u + 1.0)
        * np.abs(np.sqrt(1.0 + gamma) - np.sqrt(1.0 - gamma / u))
        / ((1.0 + gamma) * (u - gamma)) ** 0.25
    )
    v_t = pinion_speed * pair.pitch_radius(1)
    a = pair.working_centre_distance * 1e3
    return friction * thermoelastic_factor(data) * x_g * (load * 1e-3) ** 0.75 * np.sqrt(v_t) / a**0.25


#: Forms of the flash temperature (SciPy ``METHODS`` style): ``form(pair, data, mu_m, X_Gamma w_Bt,
#: omega_1, rho_1)`` -> theta_fl / X_J, K. The default is the standard's form for cylindrical gears
#: (docs/theory.md Sect. 19.3 gives the evidence).
FLASH_METHODS = {"iso_cylindrical": _cylindrical_form, "iso_general": _general_form}


def flash_temperature(
    pair: GearPair,
    data: IsoScuffingData,
    friction: float | np.ndarray,
    pinion_torque: float | np.ndarray,
    pinion_speed: float | np.ndarray,
    share: np.ndarray,
    position: np.ndarray,
) -> np.ndarray:
    """Flash temperature along the path (K above the bulk) by ``data.flash_method``, broadcast like
    the inputs: friction mu_m, pinion torque (N m), speed (rad/s), shares X_Gamma at positions rho_1 (m)."""
    load = np.asarray(share) * unit_load(pair, pinion_torque)
    x_j = approach_factor(pair, data, pinion_torque, position)
    form = FLASH_METHODS[data.flash_method]
    speed = np.asarray(pinion_speed, dtype=float)
    return x_j * form(pair, data, np.asarray(friction, dtype=float), load, speed, np.asarray(position, dtype=float))


@dataclass(frozen=True, eq=False)
class IsoScuffing:
    """ISO's flash-temperature rating at every torque and speed (arrays; temperatures degC, K).

    Attributes
    ----------
    friction : ndarray
        mu_m.
    flash : ndarray
        theta_fl along the path (last axis), K.
    bulk : ndarray
        theta_M, degC.
    contact_max : ndarray
        theta_Bmax, degC.
    scuffing_temperature : ndarray
        theta_S, degC.
    safety : ndarray
        S_B.
    """

    friction: np.ndarray
    flash: np.ndarray
    bulk: np.ndarray
    contact_max: np.ndarray
    scuffing_temperature: np.ndarray
    safety: np.ndarray

    @property
    def flash_max(self) -> np.ndarray:
        return np.asarray(self.flash.max(axis=-1))


def iso_scuffing(
    pair: GearPair,
    data: IsoScuffingData,
    pinion_torque: float | np.ndarray,
    pinion_speed: float | np.ndarray,
    oil_temperature: float,
    viscosity: float,
    share: np.ndarray,
    position: np.ndarray,
) -> IsoScuffing:
    """The flash-temperature rating; torque (N m) and speed (rad/s) with a trailing axis of 1
    broadcast against the positions (m) and shares X_Gamma of the path."""
    mu = mean_friction(pair, data, pinion_torque, pinion_speed, viscosity)
    flash = flash_temperature(pair, data, mu, pinion_torque, pinion_speed, share, position)
    rho = np.asarray(position, dtype=float)
    # theta_flm: the mean over the path (ISO samples it evenly in Gamma, i.e. in rho_1)
    mean_flash = np.trapezoid(flash, rho, axis=-1) / (rho[-1] - rho[0])
    bulk = oil_temperature + 0.47 * LUBRICATION_METHODS[data.lubrication] * mean_flash
    contact_max = bulk + flash.max(axis=-1)
    theta_s = scuffing_temperature(data, viscosity)
    if np.any(~(np.asarray(theta_s) > oil_temperature)):
        # S_B = (theta_S - theta_oil)/(theta_Bmax - theta_oil) would be negative or zero: an oil
        # at or above its own scuffing temperature is outside what the method rates.
        raise InputError(
            "oil_temperature",
            oil_temperature,
            "degC",
            f"below the scuffing temperature theta_S = {float(np.min(theta_s)):.0f} degC that ISO/TS 6336-20 gives "
            "this oil from its FZG failure load stage; at or above it the method rates no load",
        )
    safety = (theta_s - oil_temperature) / (contact_max - oil_temperature)
    mu = np.asarray(mu)
    if mu.ndim and mu.shape[-1] == 1:
        mu = mu[..., 0]
    return IsoScuffing(
        mu,
        flash,
        bulk,
        contact_max,
        np.asarray(theta_s),
        safety,
    )
