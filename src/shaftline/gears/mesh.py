"""Involute geometry and kinematics of an external spur or helical gear pair along its path of
contact (ISO 21771:2007 notation; ISO 6336-1/-2 for the path A-E).

Transverse plane: pressure angle ``alpha_t = atan(tan(alpha_n) / cos(beta))``, module
``m_t = m_n / cos(beta)``, pitch radius ``r = z m_t / 2``, base radius ``r_b = r cos(alpha_t)``,
transverse base pitch ``p_bt = pi m_t cos(alpha_t) = 2 pi r_b / z``; base helix angle
``beta_b = asin(sin(beta) cos(alpha_n))``. The working pressure angle follows the sum of the
profile shifts, ``inv(alpha_wt) = inv(alpha_t) + 2 (x1 + x2) tan(alpha_n) / (z1 + z2)``
(``inv(a) = tan(a) - a``), and the working centre distance is
``a_w = (r_b1 + r_b2) / cos(alpha_wt)``. Tip radius ``r_a = r + m_n (h_a* + x)`` unless given.

Along the line of action T1-T2 (length ``a_w sin(alpha_wt)``), with the pinion's radius of
curvature rho_1 measured from T1: contact starts at A (the wheel's tip circle),
``rho_1A = T1T2 - sqrt(r_a2^2 - r_b2^2)``, and ends at E (the pinion's tip circle),
``rho_1E = sqrt(r_a1^2 - r_b1^2)``; ``B = E - p_bt`` and ``D = A + p_bt`` bound the single-tooth
contact (the pair ahead leaves at E when this one is at B), the pitch point C is at
``rho_1C = r_b1 tan(alpha_wt)``. Length of the path
``g_alpha = E - A``, transverse contact ratio ``eps_alpha = g_alpha / p_bt``, overlap ratio
``eps_beta = b sin(beta) / (pi m_n)``.

Kinematics (transverse plane): the flanks move across the line of action with
``v_1 = omega_1 rho_1`` and ``v_2 = omega_2 rho_2`` (``omega_2 = omega_1 z1/z2``); the sliding
speed ``v_2 - v_1`` vanishes at C, the mean (rolling) speed is ``(v_1 + v_2)/2``. The radii of
curvature in the normal plane are ``rho / cos(beta_b)`` (helical teeth), which the contact
functions take as Rx (ISO/TS 6336-20 uses the same normal radius).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from shaftline.errors import InputError, first_offending, require_positive

#: Tolerance on the centre distance against the one the profile shifts give, in normal
#: modules: more is backlash no gear is cut for (or interference when smaller).
CENTRE_DISTANCE_TOLERANCE = 0.05
#: Normal pressure angles the model takes, degrees (open interval): 14.5-30 deg are in use.
PRESSURE_ANGLE_LIMITS_DEG = (11.5, 34.4)
#: Helix angles the model takes, degrees: [0, 45).
HELIX_ANGLE_LIMIT_DEG = 45.0


def involute(angle: float | np.ndarray) -> float | np.ndarray:
    """inv(a) = tan(a) - a."""
    return np.tan(angle) - angle


def inverse_involute(value: float) -> float:
    """The angle whose involute is ``value`` (Newton from Cheng's start, to 1e-15)."""
    angle = (3.0 * value) ** (1.0 / 3.0)
    for _ in range(50):
        step = (math.tan(angle) - angle - value) / math.tan(angle) ** 2
        angle -= step
        if abs(step) < 1e-15:
            break
    return angle


@dataclass(frozen=True)
class GearPair:
    """An external involute gear pair (SI: m, rad).

    Attributes
    ----------
    teeth_1, teeth_2 : int
        Pinion and wheel teeth.
    module : float
        Normal module m_n, m.
    pressure_angle : float
        Normal pressure angle alpha_n, rad.
    face_width : float
        Common face width b, m.
    helix_angle : float
        beta, rad (0: spur).
    shift_1, shift_2 : float
        Profile shift coefficients x.
    addendum : float
        Addendum coefficient h_a* (tip radius r + m_n (h_a* + x)).
    centre_distance : float or None
        Working centre distance; by default the one the shifts give.
    tip_radius_1, tip_radius_2 : float or None
        Tip radii when the teeth are not cut to the standard addendum (shortened tips).
    allow_undercut : bool
        Accept shifts below the undercut limit (teeth cut with undercut on purpose, as the FZG
        type A wheel, x = -0.5 on 24 teeth); interference of the active flanks is still checked.
    """

    teeth_1: int
    teeth_2: int
    module: float
    pressure_angle: float
    face_width: float
    helix_angle: float = 0.0
    shift_1: float = 0.0
    shift_2: float = 0.0
    addendum: float = 1.0
    centre_distance: float | None = None
    tip_radius_1: float | None = None
    tip_radius_2: float | None = None
    allow_undercut: bool = False

    def __post_init__(self) -> None:
        for name in ("teeth_1", "teeth_2"):
            teeth = getattr(self, name)
            if not isinstance(teeth, int) or teeth < 5:
                raise InputError(name, teeth, "", "a whole number >= 5")
        require_positive("module", self.module, "m")
        require_positive("face_width", self.face_width, "m")
        low, high = (math.radians(a) for a in PRESSURE_ANGLE_LIMITS_DEG)
        if not low < self.pressure_angle < high:
            raise InputError(
                "pressure_angle",
                math.degrees(self.pressure_angle),
                "deg",
                "in ({:g}, {:g}) deg".format(*PRESSURE_ANGLE_LIMITS_DEG),
            )
        if not 0.0 <= self.helix_angle < math.radians(HELIX_ANGLE_LIMIT_DEG):
            raise InputError(
                "helix_angle", math.degrees(self.helix_angle), "deg", f"in [0, {HELIX_ANGLE_LIMIT_DEG:g}) deg"
            )
        for name, teeth, shift in (("shift_1", self.teeth_1, self.shift_1), ("shift_2", self.teeth_2, self.shift_2)):
            smallest = self.addendum - teeth * math.sin(self.transverse_pressure_angle) ** 2 / (
                2.0 * math.cos(self.helix_angle)
            )
            if shift < smallest - 1e-9 and not self.allow_undercut:
                raise InputError(
                    name,
                    shift,
                    "",
                    f">= {smallest:.4f}: below it {teeth} teeth are undercut by the cutting rack (ISO 21771)",
                )
        if self.centre_distance is not None:
            nominal = self._shifted_centre_distance()
            if abs(self.centre_distance - nominal) > CENTRE_DISTANCE_TOLERANCE * self.module:
                raise InputError(
                    "centre_distance",
                    self.centre_distance,
                    "m",
                    f"{nominal:.6g} m within {CENTRE_DISTANCE_TOLERANCE:g} module (the teeth and shifts: "
                    f"x1 + x2 = {self.shift_1 + self.shift_2:g})",
                )
        for name, tip, base in (
            ("tip_radius_1", self.tip_radius_1, self.base_radius_1),
            ("tip_radius_2", self.tip_radius_2, self.base_radius_2),
        ):
            if tip is not None and not tip > base:
                raise InputError(name, tip, "m", f"> the base radius {base:.6g} m")
        if self.start_of_contact <= 0.0:
            raise InputError(
                "tip_radius_2",
                self.tip_radius(2),
                "m",
                "a wheel tip that meets the pinion flank above its base circle (no interference)",
            )
        if self.end_of_contact >= self.line_of_action:
            # the pinion's tip would reach past T2: the wheel's flank has no involute there
            # (rho_2 <= 0), the mirror of the check above
            raise InputError(
                "tip_radius_1",
                self.tip_radius(1),
                "m",
                "a pinion tip that meets the wheel flank above its base circle (no interference)",
            )
        if self.transverse_contact_ratio < 1.0:
            # The tips set the teeth's length where they are given, the addendum otherwise; of two
            # given tips, the one furthest below its tip by the addendum rule.
            field, value = "addendum", self.addendum
            short = {
                k: self._addendum_tip_radius(k) - given
                for k, given in ((1, self.tip_radius_1), (2, self.tip_radius_2))
                if given is not None
            }
            if short and max(short.values()) > 0.0:
                # a given tip at or above the rule's leaves the addendum of the other gear to blame
                k = max(short, key=lambda gear: short[gear])
                field, value = f"tip_radius_{k}", self.tip_radius(k)
            raise InputError(
                field,
                value,
                "" if field == "addendum" else "m",
                f"teeth long enough for a transverse contact ratio >= 1 (got {self.transverse_contact_ratio:.3f})",
            )

    # --- geometry ---------------------------------------------------------------------

    @property
    def transverse_pressure_angle(self) -> float:
        return math.atan(math.tan(self.pressure_angle) / math.cos(self.helix_angle))

    @property
    def transverse_module(self) -> float:
        return self.module / math.cos(self.helix_angle)

    @property
    def base_helix_angle(self) -> float:
        return math.asin(math.sin(self.helix_angle) * math.cos(self.pressure_angle))

    def pitch_radius(self, gear: int) -> float:
        return self._teeth(gear) * self.transverse_module / 2.0

    @property
    def base_radius_1(self) -> float:
        return self.pitch_radius(1) * math.cos(self.transverse_pressure_angle)

    @property
    def base_radius_2(self) -> float:
        return self.pitch_radius(2) * math.cos(self.transverse_pressure_angle)

    def tip_radius(self, gear: int) -> float:
        given = self.tip_radius_1 if gear == 1 else self.tip_radius_2
        return self._addendum_tip_radius(gear) if given is None else given

    def _addendum_tip_radius(self, gear: int) -> float:
        """The tip radius the addendum and the profile shift give, m."""
        shift = self.shift_1 if gear == 1 else self.shift_2
        return self.pitch_radius(gear) + self.module * (self.addendum + shift)

    @property
    def base_pitch(self) -> float:
        """Transverse base pitch p_bt, m."""
        return math.pi * self.transverse_module * math.cos(self.transverse_pressure_angle)

    def _shifted_working_pressure_angle(self) -> float:
        inv = involute(self.transverse_pressure_angle) + 2.0 * (self.shift_1 + self.shift_2) * math.tan(
            self.pressure_angle
        ) / (self.teeth_1 + self.teeth_2)
        return inverse_involute(float(inv))

    def _shifted_centre_distance(self) -> float:
        return (self.base_radius_1 + self.base_radius_2) / math.cos(self._shifted_working_pressure_angle())

    @property
    def working_centre_distance(self) -> float:
        return self.centre_distance if self.centre_distance is not None else self._shifted_centre_distance()

    @property
    def working_pressure_angle(self) -> float:
        return math.acos((self.base_radius_1 + self.base_radius_2) / self.working_centre_distance)

    @property
    def line_of_action(self) -> float:
        """Length T1-T2 of the line of action between the base-circle tangency points, m."""
        return self.working_centre_distance * math.sin(self.working_pressure_angle)

    @property
    def start_of_contact(self) -> float:
        """rho_1 at A, m."""
        r_a2, r_b2 = self.tip_radius(2), self.base_radius_2
        return self.line_of_action - math.sqrt(r_a2**2 - r_b2**2)

    @property
    def end_of_contact(self) -> float:
        """rho_1 at E, m."""
        r_a1, r_b1 = self.tip_radius(1), self.base_radius_1
        return math.sqrt(r_a1**2 - r_b1**2)

    @property
    def pitch_point(self) -> float:
        """rho_1 at C, m."""
        return self.base_radius_1 * math.tan(self.working_pressure_angle)

    @property
    def path_length(self) -> float:
        """g_alpha = E - A, m."""
        return self.end_of_contact - self.start_of_contact

    @property
    def transverse_contact_ratio(self) -> float:
        return self.path_length / self.base_pitch

    @property
    def overlap_ratio(self) -> float:
        return self.face_width * math.sin(self.helix_angle) / (math.pi * self.module)

    def points(self) -> dict[str, float]:
        """rho_1 at A, B, C, D, E, m (B and D bound the single-tooth contact when the contact ratio
        is below 2)."""
        a, e = self.start_of_contact, self.end_of_contact
        return {"A": a, "B": e - self.base_pitch, "C": self.pitch_point, "D": a + self.base_pitch, "E": e}

    def _teeth(self, gear: int) -> int:
        if gear not in (1, 2):
            raise ValueError("gear is 1 (pinion) or 2 (wheel)")
        return self.teeth_1 if gear == 1 else self.teeth_2


@dataclass(frozen=True, eq=False)
class PathOfContact:
    """Kinematics along the path of contact (arrays that broadcast: pinion speeds x positions).

    Attributes
    ----------
    position : ndarray
        rho_1, distance from T1 along the line of action, m.
    radius_1, radius_2 : ndarray
        Radii of curvature of pinion and wheel flank in the normal plane, m.
    reduced_radius : ndarray
        (1/rho_1 + 1/rho_2)^-1, m.
    speed_1, speed_2 : ndarray
        Surface speeds across the line of action, m/s.
    rolling_speed, sliding_speed : ndarray
        (v_1 + v_2)/2 and v_2 - v_1, m/s.
    """

    position: np.ndarray
    radius_1: np.ndarray
    radius_2: np.ndarray
    reduced_radius: np.ndarray
    speed_1: np.ndarray
    speed_2: np.ndarray
    rolling_speed: np.ndarray
    sliding_speed: np.ndarray


def path_of_contact(
    pair: GearPair, pinion_speed: float | np.ndarray, points: int = 200, positions: np.ndarray | None = None
) -> PathOfContact:
    """Radii of curvature and surface speeds at ``points`` positions from A to E, for pinion
    speeds (rad/s) broadcast against a last axis of positions (a speed array of shape (n, 1)
    gives (n, points)). ``positions`` (rho_1, m, within A..E) replaces the even spacing."""
    if positions is None and points < 2:
        raise InputError("points", points, "", ">= 2")
    omega_1 = np.asarray(pinion_speed, dtype=float)
    if np.any(~(omega_1 > 0)):
        raise InputError("pinion_speed", first_offending(omega_1, omega_1 > 0), "rad/s", "> 0")
    if positions is None:
        rho_1 = np.linspace(pair.start_of_contact, pair.end_of_contact, points)
    else:
        rho_1 = np.asarray(positions, dtype=float)
    rho_2 = pair.line_of_action - rho_1
    omega_2 = omega_1 * pair.teeth_1 / pair.teeth_2
    v1 = omega_1 * rho_1
    v2 = omega_2 * rho_2
    normal = 1.0 / math.cos(pair.base_helix_angle)
    r1, r2 = rho_1 * normal, rho_2 * normal
    return PathOfContact(rho_1, r1, r2, r1 * r2 / (r1 + r2), v1, v2, 0.5 * (v1 + v2), v2 - v1)
