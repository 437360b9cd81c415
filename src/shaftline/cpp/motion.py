"""Fretting motion of the blade carrier (seed 000 Sect. 4.6, Eq. 4.20-4.29).

    (I_blade + I_water) phi'' = M_sp(t) - Q_fr - M_hyd

M_sp(t) and the Coulomb friction torque Q_c(t) follow the blade's position in the
wake (tables over a revolution, periodic). Friction is either LuGre (Eq. 4.13-4.15,
parameters of Table 4.2 rescaled to the Coulomb torque) or the finite-slope static law of
Eq. 4.8. The hydraulic reaction is the oil spring behind the yoke acting through the
pin: yoke travel r_pin (sin phi - sin phi_0) less half the backlash on either side
(dead zone), force k_oil times that, moment force * r_pin cos phi (Eq. 4.25-4.27).

The system is stiff (sigma_0 = 5e10 N m/rad against a blade inertia of the order of
10^3 kg m^2): scipy's Radau with the analytic Jacobian.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from scipy.integrate import solve_ivp

from shaftline.errors import InputError, require_positive


@dataclass(frozen=True)
class CarrierModel:
    """Inputs of the blade-carrier motion (SI).

    Attributes
    ----------
    inertia : float
        Blade + carrier inertia about the spindle axis, kg m^2.
    water_inertia : float
        Entrained-water inertia, kg m^2.
    speed : float
        Shaft speed, rad/s.
    angle : ndarray
        Blade angles of the tables, rad (one revolution).
    spindle_torque, coulomb_torque : ndarray
        M_sp and Q_c at those angles, N m (Q_c > 0).
    oil_stiffness : float
        k_oil, N/m.
    pin_radius : float
        Pin eccentricity r_pin (e of Eq. 3.38), m.
    pitch_angle : float
        phi_0, rad.
    backlash : float
        Total free play in the pin-slot-yoke chain, m (dead zone of the spring).
    bearing_radius : float
        Radius at which fretting amplitudes are reported, m.
    friction : str
        ``"lugre"`` or ``"static"`` (Eq. 4.8).
    stiffness, damping : float
        LuGre sigma_0 (N m/rad) and sigma_1 (N m s/rad), Table 4.2.
    static_ratio : float
        F_s / F_c (1.1).
    stribeck_velocity : float
        v_s, rad/s (0.002).
    threshold_velocity : float
        v_th of the static law, rad/s.
    holding_moment : float
        Mean hydraulic moment on the blade from the holding pressure, N m (Eq. 4.24; the
        seed takes it zero, which balances the mean spindle torque).
    """

    inertia: float
    water_inertia: float
    speed: float
    angle: np.ndarray
    spindle_torque: np.ndarray
    coulomb_torque: np.ndarray
    oil_stiffness: float
    pin_radius: float
    pitch_angle: float
    backlash: float = 0.0
    bearing_radius: float = 0.392
    friction: str = "lugre"
    stiffness: float = 5e10
    damping: float = 1e8
    static_ratio: float = 1.1
    stribeck_velocity: float = 0.002
    threshold_velocity: float = 1e-5
    holding_moment: float = 0.0

    def __post_init__(self) -> None:
        for name in (
            "inertia",
            "speed",
            "oil_stiffness",
            "pin_radius",
            "bearing_radius",
            "stiffness",
            "stribeck_velocity",
            "threshold_velocity",
        ):
            require_positive(f"cpp.motion.{name}", getattr(self, name))
        if self.backlash < 0 or self.water_inertia < 0 or self.damping < 0:
            raise InputError("cpp.motion.backlash", self.backlash, "m", ">= 0 (and inertia, damping >= 0)")
        if self.friction not in ("lugre", "static"):
            raise InputError("cpp.motion.friction", self.friction, "", "lugre or static")
        if np.any(np.asarray(self.coulomb_torque) <= 0):
            raise InputError("cpp.motion.coulomb_torque", float(np.min(self.coulomb_torque)), "N m", "> 0")


@dataclass(frozen=True)
class CarrierMotion:
    """Motion over the simulated revolutions.

    Attributes
    ----------
    time, blade_angle, rotation, rotation_rate, hydraulic_force : ndarray
        s, rad (blade position), rad (carrier rotation from the set pitch), rad/s, N.
    revolutions : int
    amplitude : ndarray
        Peak-to-peak carrier displacement at the bearing radius per revolution, m.
    sliding_per_revolution : ndarray
        Sliding distance at the bearing radius per revolution, m.
    force_fluctuation : ndarray
        Peak-to-peak oil-spring (yoke) force per revolution, N; divided by the yoke area it is
        the pressure fluctuation a pressure signal would show (Sect. 4.8).
    """

    time: np.ndarray
    blade_angle: np.ndarray
    rotation: np.ndarray
    rotation_rate: np.ndarray
    hydraulic_force: np.ndarray
    revolutions: int
    amplitude: np.ndarray
    sliding_per_revolution: np.ndarray
    force_fluctuation: np.ndarray


def simulate_carrier(
    model: CarrierModel,
    revolutions: int = 10,
    samples_per_revolution: int = 720,
    steps_per_revolution: int = 7200,
    method: str = "compiled",
) -> CarrierMotion:
    """Integrate the carrier motion over ``revolutions`` shaft turns.

    ``method="compiled"`` (default): backward Euler with ``steps_per_revolution`` fixed steps in
    a numba kernel; ``"radau"``: scipy's adaptive Radau IIA (reference, slow).
    """
    if method == "compiled":
        return _simulate_compiled(model, revolutions, samples_per_revolution, steps_per_revolution)
    if method != "radau":
        raise InputError("cpp.motion.method", method, "", "compiled or radau")
    if int(revolutions) != revolutions or revolutions < 1:
        raise InputError("cpp.motion.revolutions", revolutions, "", "a positive integer")
    period = 2 * np.pi / model.speed
    table_angle = np.concatenate([model.angle, [model.angle[0] + 2 * np.pi]])
    table_sp = np.concatenate([model.spindle_torque, model.spindle_torque[:1]])
    table_qc = np.concatenate([model.coulomb_torque, model.coulomb_torque[:1]])
    total_inertia = model.inertia + model.water_inertia
    half_play = 0.5 * model.backlash
    r_pin = model.pin_radius
    sin0 = np.sin(model.pitch_angle)

    def tables(t):
        psi = (model.speed * t - model.angle[0]) % (2 * np.pi) + model.angle[0]
        return np.interp(psi, table_angle, table_sp) - model.holding_moment, np.interp(psi, table_angle, table_qc)

    def spring(phi):
        travel = r_pin * (np.sin(model.pitch_angle + phi) - sin0)
        engaged = np.sign(travel) * max(abs(travel) - half_play, 0.0)
        force = model.oil_stiffness * engaged
        stiffness = model.oil_stiffness * r_pin * np.cos(model.pitch_angle + phi) if abs(travel) > half_play else 0.0
        return (
            force,
            force * r_pin * np.cos(model.pitch_angle + phi),
            stiffness * r_pin * np.cos(model.pitch_angle + phi),
        )

    if model.friction == "lugre":
        s0, s1 = model.stiffness, model.damping

        def rhs(t, y):
            phi, w, z = y
            m_sp, q_c = tables(t)
            g = q_c * (1 + (model.static_ratio - 1) * np.exp(-((w / model.stribeck_velocity) ** 2)))
            z_rate = w - s0 * abs(w) / g * z
            _, m_hyd, _ = spring(phi)
            return [w, (m_sp - s0 * z - s1 * z_rate - m_hyd) / total_inertia, z_rate]

        def jacobian(t, y):
            phi, w, z = y
            _, q_c = tables(t)
            g = q_c * (1 + (model.static_ratio - 1) * np.exp(-((w / model.stribeck_velocity) ** 2)))
            dz_dz = -s0 * abs(w) / g
            dz_dw = 1 - s0 * np.sign(w) / g * z  # the Stribeck slope of g is left out (small)
            _, _, k_hyd = spring(phi)
            return np.array(
                [
                    [0.0, 1.0, 0.0],
                    [-k_hyd / total_inertia, -s1 * dz_dw / total_inertia, -(s0 + s1 * dz_dz) / total_inertia],
                    [0.0, dz_dw, dz_dz],
                ]
            )

        start = [0.0, 0.0, 0.0]
    else:
        v_th = model.threshold_velocity

        def rhs(t, y):
            phi, w = y
            m_sp, q_c = tables(t)
            q_fr = q_c * (np.sign(w) if abs(w) >= v_th else w / v_th)
            _, m_hyd, _ = spring(phi)
            return [w, (m_sp - q_fr - m_hyd) / total_inertia]

        def jacobian(t, y):
            phi, w = y
            _, q_c = tables(t)
            slope = q_c / v_th if abs(y[1]) < v_th else 0.0
            _, _, k_hyd = spring(phi)
            return np.array([[0.0, 1.0], [-k_hyd / total_inertia, -slope / total_inertia]])

        start = [0.0, 0.0]
    t_eval = np.linspace(0.0, revolutions * period, revolutions * samples_per_revolution + 1)
    solution = solve_ivp(
        rhs,
        (0.0, t_eval[-1]),
        start,
        method="Radau",
        jac=jacobian,
        t_eval=t_eval,
        rtol=1e-6,
        atol=[1e-10, 1e-8] + ([1e-12] if model.friction == "lugre" else []),
        max_step=period / 90,
    )
    if solution.status != 0:  # pragma: no cover - Radau reports failure for pathological input
        raise RuntimeError(f"carrier motion integration failed: {solution.message}")
    phi, w = solution.y[0], solution.y[1]
    force = np.array([spring(p)[0] for p in phi])
    return _motion(model, solution.t, phi, w, force, revolutions, samples_per_revolution)


def _simulate_compiled(model: CarrierModel, revolutions: int, samples: int, steps: int) -> CarrierMotion:
    from shaftline.cpp._kernel import integrate

    if int(revolutions) != revolutions or revolutions < 1:
        raise InputError("cpp.motion.revolutions", revolutions, "", "a positive integer")
    if steps % samples:
        raise InputError("cpp.motion.steps_per_revolution", steps, "", f"a multiple of {samples} samples")
    period = 2 * np.pi / model.speed
    step = period / steps
    phi, w, force = integrate(
        np.asarray(model.angle, float),
        np.asarray(model.spindle_torque, float),
        np.asarray(model.coulomb_torque, float),
        model.speed,
        model.inertia + model.water_inertia,
        model.oil_stiffness,
        model.pin_radius,
        model.pitch_angle,
        0.5 * model.backlash,
        model.friction == "lugre",
        model.stiffness,
        model.damping,
        model.static_ratio,
        model.stribeck_velocity,
        model.threshold_velocity,
        step,
        revolutions * steps,
        steps // samples,
        model.holding_moment,
    )
    time = np.arange(phi.size) * step * (steps // samples)
    return _motion(model, time, phi, w, force, revolutions, samples)


def _motion(model, time, phi, w, force, revolutions, per) -> CarrierMotion:
    amplitude, sliding, fluctuation = [], [], []
    for k in range(revolutions):
        part = slice(k * per, (k + 1) * per + 1)
        amplitude.append(model.bearing_radius * np.ptp(phi[part]))
        sliding.append(model.bearing_radius * np.abs(np.diff(phi[part])).sum())
        fluctuation.append(np.ptp(force[part]))
    return CarrierMotion(
        time,
        (model.speed * time) % (2 * np.pi),
        phi,
        w,
        force,
        revolutions,
        np.array(amplitude),
        np.array(sliding),
        np.array(fluctuation),
    )


#: Parameters a study may vary: model fields, or "spindle_scale" (multiplies the spindle torque,
#: as seed Sect. 4.7.2 does with 0.8 and 1.2).
STUDY_PARAMETERS = ("holding_moment", "spindle_scale", "backlash", "friction", "oil_stiffness", "water_inertia")


def parameter_study(model: CarrierModel, parameter: str, values: list, revolutions: int = 10) -> list[CarrierMotion]:
    """Fretting motion for each value of one parameter (seed Sect. 4.7)."""
    from dataclasses import replace

    if parameter not in STUDY_PARAMETERS:
        raise InputError("cpp.study.parameter", parameter, "", "one of " + ", ".join(STUDY_PARAMETERS))
    if not values:
        raise InputError("cpp.study.values", "[]", "", "at least one value")
    results = []
    for value in values:
        if parameter == "spindle_scale":
            changed = replace(model, spindle_torque=float(value) * np.asarray(model.spindle_torque))
        else:
            changed = replace(model, **{parameter: value})
        results.append(simulate_carrier(changed, revolutions))
    return results
