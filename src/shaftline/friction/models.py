"""Friction laws (seed 000, Godjevac 2009, Sect. 4.4; Olsson et al. 1998 for the forms).

Static laws give the friction force from the sliding velocity (and, for Karnopp, the
external force); dynamic laws carry an internal state z, the mean deflection of the
contacting asperities. Signs: the friction force opposes the velocity; it enters an
equation of motion as ``m x'' = F - F_fr``. Units are those of the caller: N and m/s for
a translating contact, N m and rad/s for a rotating one.

Static (all vectorised over velocity):
    Coulomb           F = F_c sgn(v)                                      (Eq. 4.2)
    viscous           F = F_v v
    Stribeck          g(v) = F_c + (F_s - F_c) exp(-(|v|/v_s)^2)         (Eq. 4.14)
    finite slope      F = g(v) sgn(v) for |v| > v_th, (v/v_th) g(v) within (Eq. 4.7; with
                      F_s = F_c, the Coulomb form Eq. 4.8)
    Karnopp           stick (F = F_e, saturated at F_s) for |v| < v_th     (Eq. 4.6)
Dynamic:
    Dahl              z' = v - sigma_0 |v| z / F_c,  F = sigma_0 z        (Eq. 4.12-4.13)
    LuGre             z' = v - sigma_0 |v| z / g(v),
                      F = sigma_0 z + sigma_1 z' + sigma_2 v              (Eq. 4.13-4.15)
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

import numpy as np
from scipy.integrate import solve_ivp

from shaftline.errors import InputError, require_positive


def coulomb(velocity, coulomb_force: float) -> np.ndarray:
    """Coulomb friction F_c sgn(v) (zero at v = 0)."""
    return coulomb_force * np.sign(velocity)


def viscous(velocity, coefficient: float) -> np.ndarray:
    """Viscous friction F_v v."""
    return coefficient * np.asarray(velocity, dtype=float)


def stribeck(velocity, coulomb_force: float, static_force: float, stribeck_velocity: float) -> np.ndarray:
    """Stribeck curve g(v) = F_c + (F_s - F_c) exp(-(|v| / v_s)^2), a magnitude (Eq. 4.14)."""
    require_positive("friction.stribeck_velocity", stribeck_velocity)
    v = np.asarray(velocity, dtype=float)
    return coulomb_force + (static_force - coulomb_force) * np.exp(-((np.abs(v) / stribeck_velocity) ** 2))


def finite_slope(
    velocity,
    coulomb_force: float,
    threshold_velocity: float,
    static_force: float | None = None,
    stribeck_velocity: float | None = None,
    viscous_coefficient: float = 0.0,
) -> np.ndarray:
    """Static law with a finite slope through zero velocity (Eq. 4.7; Eq. 4.8 without Stribeck)."""
    require_positive("friction.threshold_velocity", threshold_velocity)
    v = np.asarray(velocity, dtype=float)
    if static_force is None or stribeck_velocity is None:
        level = np.full_like(v, coulomb_force)
    else:
        level = stribeck(v, coulomb_force, static_force, stribeck_velocity)
    ramp = np.where(np.abs(v) > threshold_velocity, np.sign(v), v / threshold_velocity)
    return ramp * level + viscous_coefficient * v


def karnopp(
    velocity,
    external_force,
    coulomb_force: float,
    static_force: float,
    threshold_velocity: float,
    stribeck_velocity: float | None = None,
) -> np.ndarray:
    """Karnopp (1985): inside |v| < v_th the contact sticks and friction balances the external
    force up to the break-away force (Eq. 4.6)."""
    v = np.asarray(velocity, dtype=float)
    f_e = np.asarray(external_force, dtype=float)
    if stribeck_velocity is None:
        sliding = coulomb_force * np.sign(v)
    else:
        sliding = stribeck(v, coulomb_force, static_force, stribeck_velocity) * np.sign(v)
    sticking = np.clip(f_e, -static_force, static_force)
    return np.where(np.abs(v) >= threshold_velocity, sliding, sticking)


@dataclass(frozen=True)
class Dahl:
    """Dahl's model: bristle stiffness ``stiffness`` (sigma_0) and Coulomb force."""

    stiffness: float
    coulomb_force: float

    def state_rate(self, z: float, velocity: float) -> float:
        return velocity - self.stiffness * abs(velocity) / self.coulomb_force * z

    def force(self, z: float, z_rate: float, velocity: float) -> float:
        return self.stiffness * z


@dataclass(frozen=True)
class LuGre:
    """LuGre model (Canudas de Wit et al. 1995; seed 000 Eq. 4.13-4.15, Tables 4.1-4.2).

    Attributes
    ----------
    stiffness : float
        sigma_0, N/m (N m/rad for rotation).
    damping : float
        sigma_1, N s/m.
    viscous : float
        sigma_2, N s/m.
    coulomb_force, static_force : float
        F_c and F_s.
    stribeck_velocity : float
        v_s, m/s (rad/s).
    """

    stiffness: float
    damping: float
    viscous: float
    coulomb_force: float
    static_force: float
    stribeck_velocity: float

    def __post_init__(self) -> None:
        for name in ("stiffness", "coulomb_force", "stribeck_velocity"):
            require_positive(f"friction.lugre.{name}", getattr(self, name))
        if self.static_force < self.coulomb_force:
            raise InputError("friction.lugre.static_force", self.static_force, "", f">= F_c = {self.coulomb_force}")
        if self.damping < 0 or self.viscous < 0:
            raise InputError("friction.lugre.damping", self.damping, "", ">= 0")

    @classmethod
    def table_4_1(cls, coulomb_force: float) -> LuGre:
        """Seed 000 Table 4.1 (translating contact of the friction experiment)."""
        return cls(1e9, 4e5, 0.0, coulomb_force, 1.1 * coulomb_force, 0.0008)

    @classmethod
    def rotational(cls, translating: LuGre, radius: float, coulomb_torque: float, damping: float) -> LuGre:
        """Seed 000 Sect. 4.6.1: the same steady bristle deflection for the design Coulomb torque
        (sigma_0 = Q_c / (z_ss / r)), the Stribeck velocity divided by the radius, F_s / F_c kept;
        sigma_1 chosen to damp the vibrations (Table 4.2 uses 1e8 N m s/rad)."""
        require_positive("friction.radius", radius, "m")
        bristle = translating.coulomb_force / translating.stiffness / radius  # rad
        ratio = translating.static_force / translating.coulomb_force
        return cls(
            coulomb_torque / bristle,
            damping,
            0.0,
            coulomb_torque,
            ratio * coulomb_torque,
            translating.stribeck_velocity / radius,
        )

    @property
    def bristle_deflection(self) -> float:
        """Steady-sliding deflection z_ss = F_c / sigma_0 (Eq. 4.28)."""
        return self.coulomb_force / self.stiffness

    def g(self, velocity):
        return stribeck(velocity, self.coulomb_force, self.static_force, self.stribeck_velocity)

    def state_rate(self, z, velocity):
        return velocity - self.stiffness * np.abs(velocity) / self.g(velocity) * z

    def force(self, z, z_rate, velocity):
        return self.stiffness * z + self.damping * z_rate + self.viscous * velocity


@dataclass(frozen=True)
class BlockMotion:
    """Motion of a body pulled over a rough surface (the friction experiment, seed Fig. 4.7).

    Attributes: time (s), displacement (m), velocity (m/s), friction (N), applied (N).
    """

    time: np.ndarray
    displacement: np.ndarray
    velocity: np.ndarray
    friction: np.ndarray
    applied: np.ndarray

    def breakaway(self) -> tuple[float, float, float]:
        """(time, displacement, force) when the friction force peaks before gross sliding."""
        k = int(np.argmax(self.friction))
        return float(self.time[k]), float(self.displacement[k]), float(self.friction[k])


def simulate_block(
    model: LuGre | Dahl,
    mass: float,
    applied: Callable[[float], float],
    duration: float,
    samples: int = 2000,
) -> BlockMotion:
    """m x'' = F(t) - F_fr with a dynamic friction law; implicit Radau integration (the LuGre
    bristle is stiff: sigma_0 / m is a frequency of 10^5 rad/s and more)."""
    require_positive("friction.mass", mass, "kg")
    require_positive("friction.duration", duration, "s")

    def rhs(t, y):
        x, v, z = y
        z_rate = model.state_rate(z, v)
        return [v, (applied(t) - model.force(z, z_rate, v)) / mass, z_rate]

    scale = model.coulomb_force / model.stiffness
    solution = solve_ivp(
        rhs,
        (0.0, duration),
        [0.0, 0.0, 0.0],
        method="Radau",
        rtol=1e-8,
        atol=[1e-6 * scale, 1e-6 * scale, 1e-9 * scale],
        max_step=duration / 400,
        t_eval=np.linspace(0.0, duration, samples),
    )
    x, v, z = solution.y
    friction = np.array([model.force(zk, model.state_rate(zk, vk), vk) for zk, vk in zip(z, v, strict=True)])
    return BlockMotion(solution.t, x, v, friction, np.array([applied(t) for t in solution.t]))
