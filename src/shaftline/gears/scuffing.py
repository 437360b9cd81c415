"""Seed 002's scuffing parameter along a gear mesh (Ciulli et al. 2010, Sect. 2.2, Eq. 7).

Along the path of contact A..E the normal load per unit length (the pair's torque shared by
:mod:`shaftline.gears.loading`), the radii of curvature and the surface speeds
(:mod:`shaftline.gears.mesh`) go through :func:`shaftline.contact.lubricated.evaluate` in one
vectorised call: Hertz pressure, film, Lambda, seed 002's friction f = c f_a and the
frictional power intensity ``q = f p_H |Delta u|``. Eq. 7, as read in docs/theory.md Sect. 19.2::

    SP = max(int_A^C q drho, int_C^E q drho) / (C (T_cr - T_0))

(``r_b dtheta = drho``, the pinion's roll along the line of action; A..C the approach, C..E the
recess; W/m over W/(m K) x K). SP < 0.7: no scuffing; SP > 1: scuffing. C is calibrated from a
test at a known failure load step: :func:`calibrate` makes SP = 1 there.

Every input broadcasts: torque and speed arrays of shape (n, 1) or (stages, speeds, 1) against
the last axis of positions.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from shaftline.contact.lubricated import ContactModel, ContactState, Surfaces, evaluate
from shaftline.errors import InputError
from shaftline.gears.loading import iso_load_sharing, normal_load_per_length, tabulated_load_sharing
from shaftline.gears.mesh import GearPair, PathOfContact, path_of_contact

#: SP below which seed 002 (after its reference [3]) expects no scuffing, and above which scuffing.
NO_SCUFFING = 0.7
SCUFFING = 1.0


@dataclass(frozen=True)
class GearMesh:
    """A lubricated gear pair (SI).

    Attributes
    ----------
    pair : GearPair
    model : ContactModel
        Lubricant and methods of the contact chain (line contacts).
    surfaces : Surfaces
        Elastic constants and roughness (Rq) of pinion (1) and wheel (2) flanks.
    accuracy_grade : int
        ISO 1328 grade for the ISO load sharing.
    load_table : tuple of ndarray or None
        (fraction of the path from A, share) replacing the ISO load sharing.
    points : int
        Positions along A..E (the pitch point C is one of them).
    """

    pair: GearPair
    model: ContactModel
    surfaces: Surfaces
    accuracy_grade: int = 7
    load_table: tuple[np.ndarray, np.ndarray] | None = None
    points: int = 200

    def __post_init__(self) -> None:
        if self.model.geometry != "line":
            raise InputError("geometry", self.model.geometry, "", "line (gear flanks)")
        if self.points < 5:
            raise InputError("points", self.points, "", ">= 5")

    def positions(self) -> np.ndarray:
        """rho_1 from A to E with the pitch point C as a node, m."""
        pair = self.pair
        a, c, e = pair.start_of_contact, pair.pitch_point, pair.end_of_contact
        if not a < c < e:
            # C outside the path (heavily shifted pairs): only approach or only recess
            return np.linspace(a, e, self.points)
        approach = max(2, round((self.points - 1) * (c - a) / (e - a)) + 1)
        recess = max(2, self.points - approach + 1)
        return np.concatenate([np.linspace(a, c, approach), np.linspace(c, e, recess)[1:]])

    def load_sharing(self, position: np.ndarray) -> np.ndarray:
        if self.load_table is None:
            return iso_load_sharing(self.pair, position, self.accuracy_grade)
        return tabulated_load_sharing(self.pair, position, *self.load_table)


@dataclass(frozen=True, eq=False)
class MeshState:
    """The mesh at every position of A..E (arrays broadcast: ... x positions).

    Attributes
    ----------
    path : PathOfContact
    share : ndarray
        Load share of one tooth pair, X_Gamma.
    load : ndarray
        Normal load per unit length of contact line, N/m.
    contact : ContactState
        Hertz, film, Lambda, friction and power intensity.
    approach, recess : ndarray
        Integrals of the frictional power intensity over A..C and C..E, W/m (shape without the
        positions axis).
    """

    path: PathOfContact
    share: np.ndarray
    load: np.ndarray
    contact: ContactState
    approach: np.ndarray
    recess: np.ndarray

    @property
    def power_integral(self) -> np.ndarray:
        """The larger of the approach and recess integrals, W/m (the numerator of Eq. 7)."""
        return np.maximum(self.approach, self.recess)


def evaluate_mesh(
    mesh: GearMesh, pinion_torque: float | np.ndarray, pinion_speed: float | np.ndarray, oil_temperature: float
) -> MeshState:
    """Evaluate the contact chain along A..E for pinion torques (N m) and speeds (rad/s).

    ``pinion_torque`` and ``pinion_speed`` broadcast against each other with a trailing axis of
    length 1 (e.g. shapes (stages, 1, 1) and (1, speeds, 1)); the result has the positions as
    its last axis. ``oil_temperature`` is the inlet / oil bath temperature T_0, degC.
    """
    pair = mesh.pair
    rho = mesh.positions()
    path = path_of_contact(pair, np.asarray(pinion_speed, dtype=float), positions=rho)
    share = mesh.load_sharing(rho)
    load = normal_load_per_length(pair, pinion_torque, share)
    state = evaluate(
        mesh.model,
        mesh.surfaces,
        load=load,
        speed_1=path.speed_1,
        speed_2=path.speed_2,
        temperature=oil_temperature,
        radius_x=path.reduced_radius,
    )
    q = state.power_intensity
    c = pair.pitch_point
    # C is a node where q = 0 (no sliding), so the masked trapezoid rules are the two integrals
    approach = np.trapezoid(np.where(rho <= c, q, 0.0), rho, axis=-1)
    recess = np.trapezoid(np.where(rho >= c, q, 0.0), rho, axis=-1)
    return MeshState(path, share, np.broadcast_to(load, q.shape), state, approach, recess)


def scuffing_parameter(
    power_integral: float | np.ndarray, coefficient: float, critical_temperature: float, oil_temperature: float
) -> np.ndarray:
    """SP = max integral / (C (T_cr - T_0)) (seed 002 Eq. 7); C in W/(m K), temperatures degC."""
    if not coefficient > 0:
        raise InputError("thermal_coefficient", coefficient, "W/(m K)", "> 0")
    margin = critical_temperature - oil_temperature
    if not margin > 0:
        raise InputError(
            "critical_temperature", critical_temperature, "degC", f"> the oil temperature {oil_temperature:g} degC"
        )
    return np.asarray(power_integral, dtype=float) / (coefficient * margin)


def calibrate(power_integral_at_failure: float, critical_temperature: float, oil_temperature: float) -> float:
    """C (W/(m K)) that makes SP = 1 at the load step where a test scuffed.

    >>> calibrate(2.0e5, 126.0, 90.0)  # 200 kW/m at failure, 36 K below T_cr
    5555.555555555556
    """
    margin = critical_temperature - oil_temperature
    if not margin > 0:
        raise InputError(
            "critical_temperature", critical_temperature, "degC", f"> the oil temperature {oil_temperature:g} degC"
        )
    if not power_integral_at_failure > 0:
        raise InputError("power_integral", power_integral_at_failure, "W/m", "> 0")
    return float(power_integral_at_failure) / margin
