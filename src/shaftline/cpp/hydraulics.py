"""Hydraulics of the pitch mechanism (seed 000 Sect. 3.2.4 and 4.6).

M_hyd = F_hyd e cos(theta)                                   (Eq. 3.38)
F_hyd = Z (M_sp_mean +- Q_fr_mean) / (e cos theta) + F_other (Eq. 3.40; + ahead, - astern)
p_hyd = F_hyd / A_yoke + p_cbv                               (Eq. 3.41)
k_oil = beta A / l, l = V / A                                (Eq. 4.21-4.23)
"""

from __future__ import annotations

import numpy as np

from shaftline.errors import require_positive


def oil_spring_stiffness(
    bulk_modulus: float, oil_volume: float, yoke_area: float, column_length: float | None = None
) -> float:
    """Stiffness of the oil column behind the yoke, N/m (Eq. 4.23): beta A / l with l = V / A
    unless ``column_length`` is given. The seed rounds l = 0.250 m^3 / 0.95 m^2 = 0.263 m to
    0.25 m, hence its 5.7e9 N/m; the exact column gives 5.4e9 N/m."""
    require_positive("bulk_modulus", bulk_modulus, "Pa")
    require_positive("oil_volume", oil_volume, "m^3")
    require_positive("yoke_area", yoke_area, "m^2")
    length = oil_volume / yoke_area if column_length is None else column_length
    require_positive("column_length", length, "m")
    return bulk_modulus * yoke_area / length


def hydraulic_pressures(
    spindle_torque_mean: float,
    friction_torque_mean: float,
    blades: int,
    eccentricity: float,
    pitch_angle: float,
    yoke_area: float,
    other_friction: float = 0.0,
    counterbalance_pressure: float = 0.0,
) -> dict[str, float]:
    """Actuating pressures ahead and astern and the holding pressure, Pa (Eq. 3.40-3.41)."""
    require_positive("eccentricity", eccentricity, "m")
    require_positive("yoke_area", yoke_area, "m^2")
    arm = eccentricity * np.cos(pitch_angle)
    ahead = blades * (spindle_torque_mean + friction_torque_mean) / arm + other_friction
    astern = blades * (spindle_torque_mean - friction_torque_mean) / arm - other_friction
    holding = blades * spindle_torque_mean / arm
    return {
        "ahead": float(ahead / yoke_area + counterbalance_pressure),
        "astern": float(astern / yoke_area - counterbalance_pressure),
        "holding": float(holding / yoke_area),
    }
