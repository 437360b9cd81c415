"""Blade loads over a revolution and the friction torque of the blade bearing
(seed 000, Godjevac 2009, Sect. 3.2, Eq. 3.19-3.37).

Blade axes as in the seed: x along the shaft (thrust), y tangential, z along the spindle
(radially outwards). The blade bearing has a "radial part" (the flange, loaded by the
spindle-axis force and the bending moments) and an "axial part" (the cylindrical seat,
loaded by the forces in the x-y plane); the seed's naming is kept. SI units: N, N m, m, Pa.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from shaftline.errors import InputError, require_positive

AXES = ("x", "y", "z")


@dataclass(frozen=True, eq=False)
class BladeLoads:
    """Loads on one blade at the blade-bearing centre, over blade angles.

    Attributes
    ----------
    angle : ndarray (n,)
        Blade position, rad, 0 at the top, over one revolution.
    hydro_force, hydro_moment : ndarray (n, 3)
        Hydrodynamic force (N) and moment (N m) about x, y, z; the z moment is the
        hydrodynamic spindle torque.
    centrifugal_force, centrifugal_moment : ndarray (3,)
        Centrifugal force and moment (constant over the revolution).
    """

    angle: np.ndarray
    hydro_force: np.ndarray
    hydro_moment: np.ndarray
    centrifugal_force: np.ndarray
    centrifugal_moment: np.ndarray

    def __post_init__(self) -> None:
        angle = np.asarray(self.angle, dtype=float)
        for name in ("hydro_force", "hydro_moment"):
            values = np.asarray(getattr(self, name), dtype=float)
            if values.shape != (angle.size, 3):
                raise InputError(name, str(values.shape), "", f"shape ({angle.size}, 3)")
            if not np.all(np.isfinite(values)):
                raise InputError(name, "NaN", "", "finite values")
            object.__setattr__(self, name, values)
        for name in ("centrifugal_force", "centrifugal_moment"):
            values = np.asarray(getattr(self, name), dtype=float).reshape(3)
            object.__setattr__(self, name, values)
        object.__setattr__(self, "angle", angle)

    @property
    def spindle_torque(self) -> np.ndarray:
        """M_sp = M_hd,z + M_ce,z over the revolution, N m."""
        return self.hydro_moment[:, 2] + self.centrifugal_moment[2]

    @property
    def thrust(self) -> np.ndarray:
        """Blade thrust F_hd,x (positive ahead), N."""
        return self.hydro_force[:, 0]

    @classmethod
    def from_harmonics(
        cls,
        angle: np.ndarray,
        mean_force: np.ndarray,
        mean_moment: np.ndarray,
        harmonics: dict[str, list[tuple[int, float, float]]],
        centrifugal_force: np.ndarray,
        centrifugal_moment: np.ndarray,
    ) -> BladeLoads:
        """Loads as a mean plus harmonics of the blade angle, for users without a propeller code.

        ``harmonics`` maps a component name (``"force_x"``, ..., ``"moment_z"``) to a list of
        (order, amplitude, phase in rad): value += amplitude cos(order * angle + phase).
        """
        angle = np.asarray(angle, dtype=float)
        force = np.tile(np.asarray(mean_force, dtype=float), (angle.size, 1))
        moment = np.tile(np.asarray(mean_moment, dtype=float), (angle.size, 1))
        for key, terms in harmonics.items():
            kind, _, axis = key.partition("_")
            if kind not in ("force", "moment") or axis not in AXES:
                raise InputError(f"harmonics.{key}", key, "", "force_x ... moment_z")
            target = force if kind == "force" else moment
            for order, amplitude, phase in terms:
                if int(order) != order or order < 1:
                    raise InputError(f"harmonics.{key}.order", order, "", "a positive integer")
                target[:, AXES.index(axis)] += amplitude * np.cos(order * angle + phase)
        return cls(angle, force, moment, centrifugal_force, centrifugal_moment)


def centrifugal_point_mass(mass: float, centre_of_gravity: np.ndarray, speed: float) -> tuple[np.ndarray, np.ndarray]:
    """Centrifugal force and moment of a blade lumped at its centre of gravity (x, y, z), m,
    at shaft speed ``speed`` rad/s: F = m w^2 (0, y, z); the moment signs follow seed Eq. 3.9
    (M_y = -m w^2 x z, M_z = m w^2 x y). A blade design's integrals (Eq. 3.3-3.6) are better."""
    require_positive("mass", mass, "kg")
    x, y, z = np.asarray(centre_of_gravity, dtype=float)
    w2 = mass * speed**2
    return np.array([0.0, w2 * y, w2 * z]), np.array([0.0, -w2 * x * z, w2 * x * y])


@dataclass(frozen=True)
class BladeBearing:
    """Blade-bearing geometry and friction.

    Attributes
    ----------
    radius : float
        r, radius of the radial part (flange), m.
    friction_coefficient : float
        mu, in (0, 1).
    axial_radius, carrier_radius : float
        r' (bearing bore) and r'' (blade carrier) of the axial part, m, r' > r''.
    thickness : float
        b, length of the axial contact, m.
    youngs_modulus : float
        E of the contact, Pa.
    """

    radius: float
    friction_coefficient: float
    axial_radius: float
    carrier_radius: float
    thickness: float
    youngs_modulus: float = 120e9

    def __post_init__(self) -> None:
        for name in ("radius", "axial_radius", "carrier_radius", "thickness", "youngs_modulus"):
            require_positive(name, getattr(self, name))
        if not 0.0 < self.friction_coefficient < 1.0:
            raise InputError("friction_coefficient", self.friction_coefficient, "", "in (0, 1)")
        if not self.axial_radius > self.carrier_radius:
            raise InputError(
                "carrier_radius",
                self.carrier_radius,
                "m",
                f"< axial_radius ({self.axial_radius}): a clearance fit",
            )


@dataclass(frozen=True, eq=False)
class FrictionTorque:
    """Friction torque of the blade bearing over the revolution (N m), with its parts."""

    angle: np.ndarray
    radial: np.ndarray
    axial: np.ndarray
    distribution_factor: np.ndarray  # u of Eq. 3.26
    contact_angle: np.ndarray  # alpha of Eq. 3.37, rad

    @property
    def total(self) -> np.ndarray:
        return self.radial + self.axial


def radial_friction_torque(
    force: np.ndarray, moment: np.ndarray, radius: float, mu: float
) -> tuple[np.ndarray, np.ndarray]:
    """Q_fr,rad of the flange, Eq. 3.26-3.31, and the load distribution factor u = F r / (2 M).

    u >= 1: the whole ring is loaded, Q = mu r F (Eq. 3.27); u < 1: the moment lifts part of
    it, Q = (4/pi) mu M (sqrt(1 - u^2) + u asin u) (Eq. 3.31). Both are r mu * integral |q| r dphi
    of the line load q = F/(2 pi r) + 2 M sin(phi)/(2 pi r^2) (Eq. 3.23-3.25).
    """
    force = np.abs(np.asarray(force, dtype=float))
    moment = np.abs(np.asarray(moment, dtype=float))
    with np.errstate(divide="ignore", invalid="ignore"):
        u = np.where(moment > 0, force * radius / (2 * moment), np.inf)
    if np.any((force == 0) & (moment == 0)):
        raise InputError("force", 0.0, "N", "non-zero where the moment is zero (a loaded bearing; u undefined)")
    full = mu * radius * force
    partial = (
        4 / np.pi * mu * moment * (np.sqrt(np.clip(1 - u**2, 0, None)) + np.minimum(u, 1) * np.arcsin(np.minimum(u, 1)))
    )
    return np.where(u >= 1, full, partial), u


def axial_friction_torque(force: np.ndarray, bearing: BladeBearing) -> tuple[np.ndarray, np.ndarray]:
    """Q_fr,ax of the cylindrical seat, Eq. 3.36-3.37 (contact of a pin in a bore).

    The seed lists E in N/mm^2 and b in m; the arcsin argument is dimensionless only in
    consistent units, so SI is used throughout.
    """
    mu = bearing.friction_coefficient
    force = np.abs(np.asarray(force, dtype=float))
    r1, r2 = bearing.axial_radius, bearing.carrier_radius
    argument = 2.31 * force / (bearing.youngs_modulus * bearing.thickness * np.sqrt(1 + mu**2)) * (r1 / r2) / (r1 - r2)
    if np.any(argument > 1):
        raise InputError(
            "bearing.thickness",
            bearing.thickness,
            "m",
            "a seat stiff enough that the contact angle stays below 90 deg (Eq. 3.37)",
        )
    alpha = np.arcsin(np.sqrt(argument))
    s2 = np.sin(alpha) ** 2
    factor = 1 + 0.0477 * s2 + 0.5744 * s2**2 - 1.051 * s2**3 + 0.6982 * s2**4
    return force * r1 * factor * mu / np.sqrt(1 + mu**2), alpha


def friction_torque(loads: BladeLoads, bearing: BladeBearing) -> FrictionTorque:
    """Total blade-bearing friction torque over the revolution (Eq. 3.19-3.37)."""
    f_ce, m_ce = loads.centrifugal_force, loads.centrifugal_moment
    f_hd, m_hd = loads.hydro_force, loads.hydro_moment
    radial_force = -f_ce[2] - f_hd[:, 2]  # Eq. 3.19
    moment_x = -m_hd[:, 0]  # Eq. 3.20
    moment_y = m_hd[:, 1] + m_ce[1]  # Eq. 3.21
    moment = np.hypot(moment_x, moment_y)  # Eq. 3.22
    radial, u = radial_friction_torque(radial_force, moment, bearing.radius, bearing.friction_coefficient)
    axial_force = np.hypot(f_hd[:, 0], f_hd[:, 1] + f_ce[1])  # Eq. 3.32-3.34
    axial, alpha = axial_friction_torque(axial_force, bearing)
    return FrictionTorque(loads.angle, radial, axial, u, alpha)
