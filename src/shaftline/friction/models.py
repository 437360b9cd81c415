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

The Stribeck level, the bristle rate and the finite-slope law are evaluated by the compiled
kernels of :mod:`shaftline.friction.kernels`, which the blade-carrier model of
:mod:`shaftline.cpp` calls too. numba (for those kernels) and scipy (for
:func:`simulate_block`) are imported on first use, not with this module.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

import numpy as np
import numpy.typing as npt

from shaftline.errors import InputError, require_positive

#: A velocity, force or state: a number or an array of them (results follow the input's shape;
#: a scalar input gives a numpy float64).
Values = float | np.ndarray


def _elementwise(kernel: Any, *arguments: npt.ArrayLike, parameters: tuple[float, ...] = ()) -> Values:
    """Call a compiled kernel on broadcast float arrays (or float scalars) and constant parameters.

    Normalising the types keeps numba to two compiled versions of each kernel (float64 scalar
    and 1-D array), whatever the caller passes (ints, lists, 0-d or 2-D arrays).
    """
    arrays = np.broadcast_arrays(*(np.asarray(a, dtype=float) for a in arguments))
    constants = tuple(float(c) for c in parameters)
    if arrays[0].ndim == 0:
        return np.float64(kernel(*(float(a) for a in arrays), *constants))
    shape = arrays[0].shape
    flat = [np.ascontiguousarray(a).reshape(-1) for a in arrays]
    return np.asarray(kernel(*flat, *constants)).reshape(shape)


def _kernels() -> Any:
    from shaftline.friction import kernels

    return kernels


def coulomb(velocity: npt.ArrayLike, coulomb_force: float) -> Values:
    """Coulomb friction F_c sgn(v) (zero at v = 0), Eq. 4.2."""
    return coulomb_force * np.sign(velocity)


def viscous(velocity: npt.ArrayLike, coefficient: float) -> Values:
    """Viscous friction F_v v."""
    return coefficient * np.asarray(velocity, dtype=float)


def stribeck(velocity: npt.ArrayLike, coulomb_force: float, static_force: float, stribeck_velocity: float) -> Values:
    """Stribeck curve g(v) = F_c + (F_s - F_c) exp(-(|v| / v_s)^2), a magnitude (Eq. 4.14).

    Parameters
    ----------
    velocity : float or array_like
        m/s (rad/s).
    coulomb_force, static_force : float
        F_c and F_s, N (N m).
    stribeck_velocity : float
        v_s > 0, m/s (rad/s).
    """
    require_positive("stribeck_velocity", stribeck_velocity)
    return _elementwise(
        _kernels().stribeck_level, velocity, parameters=(coulomb_force, static_force, stribeck_velocity)
    )


def finite_slope(
    velocity: npt.ArrayLike,
    coulomb_force: float,
    threshold_velocity: float,
    static_force: float | None = None,
    stribeck_velocity: float | None = None,
    viscous_coefficient: float = 0.0,
) -> Values:
    """Static law with a finite slope through zero velocity (Eq. 4.7; Eq. 4.8 without Stribeck).

    Parameters
    ----------
    velocity : float or array_like
        m/s (rad/s).
    coulomb_force : float
        F_c, N (N m).
    threshold_velocity : float
        v_th > 0, m/s (rad/s): the law is linear in v within |v| < v_th.
    static_force, stribeck_velocity : float, optional
        F_s and v_s: with both, the level is the Stribeck curve (Eq. 4.7), else F_c (Eq. 4.8).
    viscous_coefficient : float
        F_v, N s/m (N m s/rad).
    """
    require_positive("threshold_velocity", threshold_velocity)
    v = np.asarray(velocity, dtype=float)
    level = (
        coulomb_force
        if static_force is None or stribeck_velocity is None
        else stribeck(v, coulomb_force, static_force, stribeck_velocity)
    )
    return _elementwise(_kernels().finite_slope_force, v, level, parameters=(threshold_velocity,)) + (
        viscous_coefficient * v
    )


def karnopp(
    velocity: npt.ArrayLike,
    external_force: npt.ArrayLike,
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
    """Dahl's model (Eq. 4.12-4.13).

    Attributes
    ----------
    stiffness : float
        sigma_0, N/m (N m/rad).
    coulomb_force : float
        F_c, N (N m).
    """

    stiffness: float
    coulomb_force: float

    def __post_init__(self) -> None:
        require_positive("stiffness", self.stiffness)
        require_positive("coulomb_force", self.coulomb_force)

    def state_rate(self, z: npt.ArrayLike, velocity: npt.ArrayLike) -> Values:
        """z' = v - sigma_0 |v| z / F_c, m/s (rad/s)."""
        return _elementwise(_kernels().lugre_state_rate, z, velocity, parameters=(self.stiffness, self.coulomb_force))

    def force(self, z: npt.ArrayLike, z_rate: npt.ArrayLike, velocity: npt.ArrayLike) -> Values:
        """F = sigma_0 z, N (N m)."""
        return self.stiffness * np.asarray(z, dtype=float)


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
            require_positive(name, getattr(self, name))
        if self.static_force < self.coulomb_force:
            raise InputError("static_force", self.static_force, "", f">= F_c = {self.coulomb_force}")
        for name in ("damping", "viscous"):
            if not getattr(self, name) >= 0:
                raise InputError(name, getattr(self, name), "", ">= 0")

    @classmethod
    def table_4_1(cls, coulomb_force: float) -> LuGre:
        """Seed 000 Table 4.1 (translating contact of the friction experiment)."""
        return cls(1e9, 4e5, 0.0, coulomb_force, 1.1 * coulomb_force, 0.0008)

    @classmethod
    def rotational(cls, translating: LuGre, radius: float, coulomb_torque: float, damping: float) -> LuGre:
        """Seed 000 Sect. 4.6.1: the same steady bristle deflection for the design Coulomb torque
        (sigma_0 = Q_c / (z_ss / r)), the Stribeck velocity divided by the radius, F_s / F_c kept;
        sigma_1 chosen to damp the vibrations (Table 4.2 uses 1e8 N m s/rad)."""
        require_positive("radius", radius, "m")
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

    def g(self, velocity: npt.ArrayLike) -> Values:
        """Stribeck level g(v) (Eq. 4.14), N (N m)."""
        return stribeck(velocity, self.coulomb_force, self.static_force, self.stribeck_velocity)

    def state_rate(self, z: npt.ArrayLike, velocity: npt.ArrayLike) -> Values:
        """z' = v - sigma_0 |v| z / g(v) (Eq. 4.13-4.14), m/s (rad/s)."""
        return _elementwise(
            _lugre_rate,
            z,
            velocity,
            parameters=(self.stiffness, self.coulomb_force, self.static_force, self.stribeck_velocity),
        )

    def force(self, z: npt.ArrayLike, z_rate: npt.ArrayLike, velocity: npt.ArrayLike) -> Values:
        """F = sigma_0 z + sigma_1 z' + sigma_2 v (Eq. 4.15), N (N m)."""
        z, z_rate, velocity = (np.asarray(a, dtype=float) for a in (z, z_rate, velocity))
        return self.stiffness * z + self.damping * z_rate + self.viscous * velocity


def _lugre_rate(z: Any, velocity: Any, stiffness: float, coulomb: float, static: float, v_s: float) -> Any:
    k = _kernels()
    return k.lugre_state_rate(z, velocity, stiffness, k.stribeck_level(velocity, coulomb, static, v_s))


@dataclass(frozen=True, eq=False)
class BlockMotion:
    """Motion of a body pulled over a rough surface (the friction experiment, seed Fig. 4.7).

    Attributes
    ----------
    time : ndarray
        s.
    displacement, velocity : ndarray
        m, m/s.
    friction, applied : ndarray
        Friction force and applied force, N.
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
    bristle is stiff: sigma_0 / m is a frequency of 10^5 rad/s and more).

    Parameters
    ----------
    model : LuGre or Dahl
        Friction law, N and m.
    mass : float
        kg.
    applied : callable
        Applied force F(t), N, of the time in s.
    duration : float
        s.
    samples : int
        Output samples, equally spaced over [0, duration].
    """
    from scipy.integrate import solve_ivp

    require_positive("mass", mass, "kg")
    require_positive("duration", duration, "s")

    def rhs(t: float, y: np.ndarray) -> list[float]:
        x, v, z = y
        z_rate = float(model.state_rate(z, v))
        return [v, (applied(t) - float(model.force(z, z_rate, v))) / mass, z_rate]

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
    friction = np.asarray(model.force(z, model.state_rate(z, v), v))
    return BlockMotion(solution.t, x, v, friction, np.array([applied(t) for t in solution.t]))
