"""Flash-temperature method of ISO/TS 6336-20 (formerly ISO/TR 13989-1, after DIN 3990-4) for an
external spur or helical pair, vectorised along the path of contact (docs/theory.md Sect. 19.3).

Blok's flash temperature of a Hertzian band heat source, both bodies of the same thermal contact
coefficient ``B_M = sqrt(lambda rho c)``::

    theta_fl = K mu_m X_J w |sqrt(v_1) - sqrt(v_2)| / (B_M sqrt(b_H)),   K = 0.80

with ``w = X_Gamma w_Bt`` the shared transverse unit load (``w_Bt = F_t / b``, F_t at the
reference circle, as ISO uses it), ``b_H = sqrt(8 w rho_rel / (pi E_r))`` the Hertz half-width
for that load, v the flank speeds across the line of action. This is ISO's general form
(its constant 2.52 in mixed units is K = 0.80); ISO's form for cylindrical gears with the
thermo-elastic, geometry and angle factors (X_M = 50 for steel, X_G, X_alpha_beta) is the same
expression with rounded constants (within 1.1 %, tests/gears/test_scuffing.py). For helical gears the
factor sqrt(cos beta_b) of ISO's angle factor X_alpha_beta is applied.

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

    def __post_init__(self) -> None:
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


def flash_temperature(
    pair: GearPair,
    data: IsoScuffingData,
    friction: float | np.ndarray,
    pinion_torque: float | np.ndarray,
    pinion_speed: float | np.ndarray,
    share: np.ndarray,
    position: np.ndarray,
) -> np.ndarray:
    """Blok's flash temperature along the path (K above the bulk), broadcast like the inputs."""
    rho_1, rho_2 = _transverse_radii(pair, position)
    omega_1 = np.asarray(pinion_speed, dtype=float)
    v_1 = omega_1 * rho_1
    v_2 = omega_1 * pair.teeth_1 / pair.teeth_2 * rho_2
    load = np.asarray(share) * unit_load(pair, pinion_torque)
    rho_rel = rho_1 * rho_2 / (rho_1 + rho_2)
    half_width = np.sqrt(8.0 * load * rho_rel / (math.pi * data.reduced_modulus))
    x_j = approach_factor(pair, data, pinion_torque, position)
    theta = (
        BLOK_CONSTANT
        * np.asarray(friction)
        * x_j
        * load
        * np.abs(np.sqrt(v_1) - np.sqrt(v_2))
        / (data.thermal_contact_coefficient * np.sqrt(half_width))
    )
    return theta * math.sqrt(math.cos(pair.base_helix_angle))


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
