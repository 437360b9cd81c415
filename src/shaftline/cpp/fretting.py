"""Fretting coefficient of a blade bearing (seed 000 Sect. 3.3, Eq. 3.46-3.49; Ch. 6.1 ranking).

k_fret = M_sp / Q_fr: where |k_fret| > 1 the spindle torque overcomes the friction and the
blade carrier can move (gross fretting). With only the total thrust measured, the seed
uses f_fret = Z M_sp / (T R_0.7); its critical values are f_fret where |k_fret| = 1.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from shaftline.errors import InputError


@dataclass(frozen=True, eq=False)
class FrettingCoefficient:
    """Fretting coefficient over a revolution.

    Attributes
    ----------
    angle : ndarray
        rad.
    k : ndarray
        M_sp / Q_fr.
    windows_positive, windows_negative : list of (start, end)
        Blade-angle intervals (rad) where k > 1 and k < -1.
    maximum, minimum : float
        Extremes of k.
    """

    angle: np.ndarray
    k: np.ndarray
    windows_positive: list[tuple[float, float]]
    windows_negative: list[tuple[float, float]]
    maximum: float
    minimum: float

    @property
    def fretting(self) -> bool:
        """Gross fretting both ways in a revolution (the seed's full fretting cycle)."""
        return bool(self.windows_positive and self.windows_negative)


def _windows(angle: np.ndarray, inside: np.ndarray) -> list[tuple[float, float]]:
    if not inside.any():
        return []
    edges = np.diff(np.concatenate([[0], inside.astype(int), [0]]))
    starts, ends = np.flatnonzero(edges == 1), np.flatnonzero(edges == -1) - 1
    return [(float(angle[a]), float(angle[b])) for a, b in zip(starts, ends, strict=True)]


def fretting_coefficient(spindle_torque: np.ndarray, friction: np.ndarray, angle: np.ndarray) -> FrettingCoefficient:
    """k_fret (Eq. 3.46) with the angular windows of gross fretting in each direction."""
    friction = np.asarray(friction, dtype=float)
    if np.any(friction <= 0):
        raise InputError("friction", float(friction.min()), "N m", "> 0 over the revolution")
    k = np.asarray(spindle_torque, dtype=float) / friction
    return FrettingCoefficient(
        angle, k, _windows(angle, k > 1), _windows(angle, k < -1), float(k.max()), float(k.min())
    )


def thrust_fretting_coefficient(
    spindle_torque: np.ndarray, total_thrust: float, blades: int, radius_07: float
) -> np.ndarray:
    """f_fret = Z M_sp / (T R_0.7) (Eq. 3.47)."""
    if total_thrust == 0:
        raise InputError("total_thrust", 0.0, "N", "non-zero")
    return blades * np.asarray(spindle_torque, dtype=float) / (total_thrust * radius_07)


def critical_values(coefficient: FrettingCoefficient, f_fret: np.ndarray) -> tuple[float | None, float | None]:
    """f_fret where the spindle torque first equals the friction torque, positive and negative
    (Eq. 3.48); None where it never does."""

    def at(level: float) -> float | None:
        crossing = np.flatnonzero(np.diff(np.sign(coefficient.k - level)) != 0)
        if crossing.size == 0:
            return None
        i = crossing[0]
        weight = (level - coefficient.k[i]) / (coefficient.k[i + 1] - coefficient.k[i])
        return float(f_fret[i] + weight * (f_fret[i + 1] - f_fret[i]))

    return at(1.0), at(-1.0)


def rank_by_fretting_risk(cases: dict[str, FrettingCoefficient]) -> list[tuple[str, float]]:
    """Propellers ordered from highest to lowest risk by the largest |k_fret| (seed Tables 6.1-6.4)."""
    score = {name: max(abs(c.maximum), abs(c.minimum)) for name, c in cases.items()}
    return sorted(score.items(), key=lambda item: -item[1])
