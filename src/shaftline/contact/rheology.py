"""Lubricant rheology of a lubricated contact: viscosity against pressure and temperature,
limiting shear stress and the Bair-Winer shear stress, with the lubricant data they need.

Equations (SI; temperatures in degC, pressures in Pa, viscosities in Pa s):

* Barus: ``eta = eta0 exp(alpha p)``.
* Roelands (1966): ``eta = eta0 exp((ln eta0 + 9.67) ((1 + p/p0)^z - 1))``, ``p0 = 1.96e8 Pa``;
  with ``z = alpha p0 / (ln eta0 + 9.67)`` (Hamrock 1994 Eq. 4.11-4.13) the slope
  ``d ln(eta)/dp`` at ``p = 0`` is Barus' alpha.
* Vogel (1921): ``eta = A exp(B / (T + C))``; :func:`fit_vogel` through three points.
* ASTM D341 (Walther) through two points: :class:`shaftline.lubricants.Lubricant`.
* Limiting shear stress: ``tau_L = tau_L0 + gamma_L p`` (Bair & Winer 1979, "A rheological
  model for elastohydrodynamic contacts based on primary laboratory data", J. Lubr. Technol.
  101, 258-265: tau_L grows in proportion to pressure, gamma_L about 0.04-0.1 for
  the oils they measured).
* Bair-Winer shear stress (seed 002 Eq. 4): ``tau = tau_L (1 - exp(-eta gamma_dot / tau_L))``.

The lubricant data (:data:`CONTACT_LUBRICANTS`) say where each number comes from; numbers
marked *assumed* are typical values of the oil class, not measurements of the named oil.
"""

from __future__ import annotations

import math
import warnings
from dataclasses import dataclass, field

import numpy as np

from shaftline.errors import InputError
from shaftline.lubricants import Lubricant

ArrayLike = float | np.ndarray

#: Roelands' reference pressure p0 and the constant ln(eta_inf / 1 Pa s) = -9.67
#: (Roelands 1966; Hamrock 1994 Eq. 4.11).
ROELANDS_PRESSURE = 1.96e8
ROELANDS_LN_ETA_INF = -9.67


class ExtrapolationWarning(UserWarning):
    """A correlation was evaluated outside its validity range because the user asked to
    extrapolate; the message names the range."""


def check_range(
    field_name: str, values: ArrayLike, low: float, high: float, unit: str, extrapolate: bool = False, what: str = ""
) -> np.ndarray:
    """``values`` as an array, or an :class:`InputError` naming the range [low, high] when one
    lies outside it; with ``extrapolate`` a warning instead."""
    array = np.asarray(values, dtype=float)
    outside = ~((array >= low) & (array <= high))
    if np.any(outside):
        value = float(array[outside].flat[0]) if array.ndim else float(array)
        bounds = f"[{low:g}, {high:g}] {unit}".rstrip() + (f" ({what})" if what else "")
        if not extrapolate:
            raise InputError(field_name, value, unit, f"in {bounds}; extrapolate=true to go beyond with a warning")
        warnings.warn(
            f"{field_name} = {value:g} {unit} is outside the validity range {bounds}: extrapolated",
            ExtrapolationWarning,
            stacklevel=3,
        )
    return array


def barus(viscosity: ArrayLike, alpha: ArrayLike, pressure: ArrayLike) -> np.ndarray:
    """Barus viscosity ``eta0 exp(alpha p)``, Pa s.

    >>> round(float(barus(0.01, 2e-8, 1e8)), 5)
    0.07389
    """
    return np.asarray(viscosity) * np.exp(np.asarray(alpha) * np.asarray(pressure))


def roelands_index(viscosity: ArrayLike, alpha: ArrayLike) -> np.ndarray:
    """Roelands pressure-viscosity index z matching Barus' alpha at low pressure."""
    return np.asarray(alpha) * ROELANDS_PRESSURE / (np.log(viscosity) - ROELANDS_LN_ETA_INF)


def roelands(viscosity: ArrayLike, alpha: ArrayLike, pressure: ArrayLike) -> np.ndarray:
    """Roelands viscosity at ``pressure``, Pa s, with z from alpha (:func:`roelands_index`)."""
    eta0 = np.asarray(viscosity, dtype=float)
    ln_ratio = np.log(eta0) - ROELANDS_LN_ETA_INF
    z = roelands_index(eta0, alpha)
    return eta0 * np.exp(ln_ratio * ((1.0 + np.asarray(pressure) / ROELANDS_PRESSURE) ** z - 1.0))


#: Pressure-viscosity models (SciPy ``METHODS`` style): ``model(eta0, alpha, p)``.
PRESSURE_VISCOSITY_METHODS = {"barus": barus, "roelands": roelands}


def vogel(temperature: ArrayLike, a: float, b: float, c: float) -> np.ndarray:
    """Vogel viscosity ``A exp(B / (T + C))``, Pa s, T in degC (A in Pa s, B and C in K)."""
    return a * np.exp(b / (np.asarray(temperature, dtype=float) + c))


def fit_vogel(
    temperatures: tuple[float, float, float], viscosities: tuple[float, float, float]
) -> tuple[float, float, float]:
    """Vogel constants (A, B, C) through three (degC, Pa s) points: C from the ratio of the
    log differences (closed form), then B and A."""
    t1, t2, t3 = (float(t) for t in temperatures)
    y1, y2, y3 = (math.log(float(v)) for v in viscosities)
    if not (t1 < t2 < t3) or not (y1 > y2 > y3):
        raise InputError("viscosities", list(viscosities), "Pa s", "three points with viscosity falling as T rises")
    # (y1 - y2)/(y2 - y3) = ((1/(t1+C) - 1/(t2+C)) / (1/(t2+C) - 1/(t3+C))) = (t2-t1)(t3+C) / ((t3-t2)(t1+C))
    r = (y1 - y2) / (y2 - y3) * (t3 - t2) / (t2 - t1)
    c = (t3 - r * t1) / (r - 1.0)
    b = (y1 - y2) / (1.0 / (t1 + c) - 1.0 / (t2 + c))
    a = math.exp(y1 - b / (t1 + c))
    return a, b, c


@dataclass(frozen=True)
class ContactLubricant:
    """A lubricant with the data a lubricated contact needs.

    Attributes
    ----------
    name : str
    viscosity : Lubricant
        Viscosity against temperature at ambient pressure (ASTM D341 through two points).
    pressure_viscosity : tuple of (degC, 1/Pa)
        Barus' alpha at temperatures; interpolated linearly in T between them, held constant
        beyond the end points.
    limiting_shear_ratio : float
        gamma_L = d tau_L / dp, -.
    limiting_shear_stress_0 : float
        tau_L at ambient pressure, Pa.
    thermal_conductivity : float
        W/(m K).
    temperature_range : tuple of float
        Validity of the viscosity data, degC.
    max_pressure : float
        Validity of the pressure-viscosity and limiting-shear data, Pa.
    source : str
        Where the numbers come from.
    """

    name: str
    viscosity: Lubricant
    pressure_viscosity: tuple[tuple[float, float], ...]
    limiting_shear_ratio: float
    limiting_shear_stress_0: float = 0.0
    thermal_conductivity: float = 0.14
    temperature_range: tuple[float, float] = (0.0, 150.0)
    max_pressure: float = 3.0e9
    source: str = ""
    notes: tuple[str, ...] = field(default=())

    def __post_init__(self) -> None:
        # A lubricant built through the API must carry every datum the contact models read:
        # refused here in one line rather than failing deep inside a model (or, for tau_L = 0,
        # silently giving no fluid friction).
        try:
            points = tuple(tuple(float(value) for value in point) for point in self.pressure_viscosity)
        except (TypeError, ValueError):
            points = ()
        if len(points) == 0 or any(len(point) != 2 for point in points):
            raise InputError(
                "pressure_viscosity",
                str(self.pressure_viscosity),
                "",
                "one or more (temperature degC, alpha 1/Pa) pairs",
            )
        # kept as tuples of floats: the frozen dataclass stays hashable and comparable
        object.__setattr__(self, "pressure_viscosity", points)
        temperatures = [t for t, _ in points]
        rising = all(b > a for a, b in zip(temperatures, temperatures[1:], strict=False))
        if any(not (a > 0.0) for _, a in points) or not rising:
            raise InputError(
                "pressure_viscosity", points, "", "alpha > 0 1/Pa at temperatures rising from pair to pair"
            )
        if not (0.0 <= self.limiting_shear_stress_0 < math.inf):
            raise InputError("limiting_shear_stress_0", self.limiting_shear_stress_0, "Pa", ">= 0, finite")
        if not (0.0 <= self.limiting_shear_ratio < math.inf) or not (
            self.limiting_shear_ratio > 0.0 or self.limiting_shear_stress_0 > 0.0
        ):
            raise InputError(
                "limiting_shear_ratio",
                self.limiting_shear_ratio,
                "",
                ">= 0 and finite, and > 0 where limiting_shear_stress_0 is 0: the Bair-Winer stress needs tau_L(p) > 0",
            )
        if not (self.thermal_conductivity > 0.0):
            raise InputError("thermal_conductivity", self.thermal_conductivity, "W/(m K)", "> 0")
        low, high = self.temperature_range
        if not (low < high):
            raise InputError("temperature_range", list(self.temperature_range), "degC", "low < high")
        if not (self.max_pressure > 0.0):
            raise InputError("max_pressure", self.max_pressure, "Pa", "> 0")

    def check_temperature(self, temperature: ArrayLike, extrapolate: bool = False) -> np.ndarray:
        low, high = self.temperature_range
        return check_range("temperature", temperature, low, high, "degC", extrapolate, f"viscosity data of {self.name}")

    def dynamic_viscosity(self, temperature: ArrayLike, extrapolate: bool = False) -> np.ndarray:
        """Viscosity at ambient pressure, Pa s."""
        t = self.check_temperature(temperature, extrapolate)
        return np.asarray(self.viscosity.dynamic_viscosity(t), dtype=float)

    def alpha(self, temperature: ArrayLike) -> np.ndarray:
        """Pressure-viscosity coefficient (Barus alpha), 1/Pa."""
        ts, alphas = zip(*self.pressure_viscosity, strict=True)
        return np.interp(np.asarray(temperature, dtype=float), ts, alphas)

    def temperature_viscosity_coefficient(self, temperature: ArrayLike) -> np.ndarray:
        """beta = -d ln(eta)/dT, 1/K (central difference over 1 K)."""
        t = np.asarray(temperature, dtype=float)
        upper = np.log(self.viscosity.dynamic_viscosity(t + 0.5))
        lower = np.log(self.viscosity.dynamic_viscosity(t - 0.5))
        return np.asarray(lower - upper, dtype=float)

    def viscosity_at(
        self,
        pressure: ArrayLike,
        temperature: ArrayLike,
        model: str = "roelands",
        extrapolate: bool = False,
        quantity: str = "pressure",
    ) -> np.ndarray:
        """Viscosity at pressure and temperature, Pa s (a key of :data:`PRESSURE_VISCOSITY_METHODS`).
        ``quantity`` names the pressure in an error (a caller passing a derived pressure says
        what it comes from)."""
        if model not in PRESSURE_VISCOSITY_METHODS:
            raise InputError("pressure_viscosity_model", model, "", " or ".join(PRESSURE_VISCOSITY_METHODS))
        p = self._check_pressure(pressure, extrapolate, quantity)
        eta0 = self.dynamic_viscosity(temperature, extrapolate)
        return PRESSURE_VISCOSITY_METHODS[model](eta0, self.alpha(temperature), p)

    def limiting_shear_stress(
        self, pressure: ArrayLike, extrapolate: bool = False, quantity: str = "pressure"
    ) -> np.ndarray:
        """tau_L(p) = tau_L0 + gamma_L p, Pa."""
        p = self._check_pressure(pressure, extrapolate, quantity)
        return self.limiting_shear_stress_0 + self.limiting_shear_ratio * p

    def _check_pressure(self, pressure: ArrayLike, extrapolate: bool, quantity: str) -> np.ndarray:
        """The pressure in Pa, checked against the data's range in GPa (as a user reads it)."""
        pascal = np.asarray(pressure, dtype=float)
        check_range(quantity, pascal / 1e9, 0.0, self.max_pressure / 1e9, "GPa", extrapolate, f"data of {self.name}")
        return pascal


def bair_winer_stress(viscosity: ArrayLike, shear_rate: ArrayLike, limiting_stress: ArrayLike) -> np.ndarray:
    """Shear stress of the Bair-Winer limiting-shear-stress model (seed 002 Eq. 4), Pa:
    Newtonian ``eta gamma_dot`` at low shear rate, ``tau_L`` at high.

    >>> round(float(bair_winer_stress(1.0, 1e3, 1e8)) / 1e3, 3)  # Newtonian: 1 kPa
    1.0
    """
    tau_l = np.asarray(limiting_stress, dtype=float)
    return tau_l * -np.expm1(-np.asarray(viscosity) * np.asarray(shear_rate) / tau_l)


_JONES = (
    "Jones, Johnson, Winer & Sanborn (1975), NASA TN D-8024, pressure-viscosity measurements to 149 degC, "
    "as tabulated by Hamrock (1994) Table 4.3"
)
_BAIR = "Bair & Winer (1979), limiting shear stress proportional to pressure, 0.04-0.1 for the oils measured"
_STACHOWIAK = (
    "Stachowiak & Batchelor, Engineering Tribology, Table 2.3 (adapted there from Jones et al.): the 'heavy machine "
    "oil' of 153, 34 and 9.1 mPa s at 30, 60 and 100 degC, the viscosity of this oil to 4 %, has alpha 23.7, 20.5 "
    "and 15.8 GPa^-1"
)
#: Pressure-viscosity coefficient of the mineral ISO VG 100 class (ISO VG 100, FVA 3): the table's oil
#: whose viscosity matches theirs at its three temperatures (tests/contact/test_rheology.py).
_MINERAL_VG100_ALPHA = ((30.0, 2.37e-8), (60.0, 2.05e-8), (100.0, 1.58e-8))


def _lubricant(
    name: str,
    nu40_cst: float,
    nu100_cst: float,
    density_15: float,
    alphas: tuple[tuple[float, float], ...],
    gamma_l: float,
    conductivity: float,
    temperature_range: tuple[float, float],
    source: str,
) -> ContactLubricant:
    base = Lubricant.from_two_points(name, 40.0, nu40_cst * 1e-6, 100.0, nu100_cst * 1e-6, density_15)
    return ContactLubricant(
        name=name,
        viscosity=base,
        pressure_viscosity=alphas,
        limiting_shear_ratio=gamma_l,
        thermal_conductivity=conductivity,
        temperature_range=temperature_range,
        source=source,
    )


#: Lubricants for contacts, by lower-case name. The viscosity points are ASTM D341 fits
#: through 40 and 100 degC; validity is 0-150 degC (mineral) and -20-200 degC (ester),
#: extrapolation of the Walther relation beyond the points being the use ASTM D341 makes of it.
CONTACT_LUBRICANTS: dict[str, ContactLubricant] = {
    "mil-prf-23699": _lubricant(
        "MIL-PRF-23699 (polyol ester)",
        25.0,
        5.1,
        1000.0,
        ((38.0, 1.3e-8), (99.0, 1.0e-8), (149.0, 0.85e-8)),
        0.08,
        0.15,
        (-20.0, 200.0),
        "viscosity: MIL-PRF-23699 requires 4.90-5.40 mm^2/s at 100 degC and at least 23 mm^2/s at 40 degC; "
        "25 and 5.1 mm^2/s assumed (typical qualified oils); density 1000 kg/m^3 assumed (esters 990-1005). "
        f"alpha: the order of formulated esters in {_JONES} (rounded; not checked against the original). "
        f"gamma_L 0.08 assumed ({_BAIR}). Seed 002 gives its own tau_L and eta formulas in an appendix that "
        "the extracted text lacks.",
    ),
    "iso vg 100": _lubricant(
        "ISO VG 100 mineral gear oil",
        100.0,
        11.2,
        880.0,
        _MINERAL_VG100_ALPHA,
        0.07,
        0.13,
        (0.0, 150.0),
        "viscosity: ISO 3448 grade midpoint 100 mm^2/s at 40 degC, 11.2 mm^2/s at 100 degC for VI about 95 "
        f"(shaftline.lubricants preset); alpha: {_STACHOWIAK}; gamma_L 0.07 assumed ({_BAIR}).",
    ),
    "fva 3": _lubricant(
        "FVA 3 reference mineral oil (FZG)",
        95.0,
        10.7,
        885.0,
        _MINERAL_VG100_ALPHA,
        0.07,
        0.13,
        (0.0, 150.0),
        "FVA reference oil 3 (paraffinic mineral oil without additives, ISO VG 100 class): 95 and 10.7 mm^2/s at "
        "40/100 degC and 885 kg/m^3 as commonly quoted in FZG test reports; assumed, not checked against the "
        f"FVA data sheet here. alpha as for ISO VG 100 mineral oil ({_STACHOWIAK}; this oil's viscosity is "
        "within 5 % of that oil's too); gamma_L assumed as for ISO VG 100.",
    ),
}


def contact_lubricant(name: str) -> ContactLubricant:
    """A lubricant of :data:`CONTACT_LUBRICANTS` by name (case-insensitive, '_' as ' ')."""
    key = " ".join(name.strip().lower().replace("_", " ").split())
    if key not in CONTACT_LUBRICANTS:
        raise InputError("lubricant", name, "", "one of " + ", ".join(sorted(CONTACT_LUBRICANTS)))
    return CONTACT_LUBRICANTS[key]
