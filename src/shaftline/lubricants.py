"""Lubricant properties: viscosity against temperature, and density.

Mineral oils follow the ASTM D341 (Walther) relation fitted through two
reference points; fresh water follows the Vogel equation and sea water the
Sharqawy et al. (2010) salinity correction. Temperatures are in degC, dynamic
viscosity in Pa*s, kinematic viscosity in m^2/s, density in kg/m^3.

References
----------
ASTM D341-20, *Standard Practice for Viscosity-Temperature Equations and Charts
for Liquid Petroleum or Hydrocarbon Products*.
Vogel, H. (1921); constants for water from Al-Shemmeri, T., *Engineering Fluid
Mechanics* (2012): mu = 2.414e-5 * 10**(247.8 / (T - 140)), T in K.
Sharqawy, M. H., Lienhard, J. H., Zubair, S. M. (2010), "Thermophysical
properties of seawater", *Desalination and Water Treatment* 16, 354-380, Eq. 22-23.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from shaftline.errors import InputError, require_finite, require_positive

KELVIN = 273.15
#: Volumetric thermal expansion of mineral oils used for density against temperature, 1/K.
OIL_EXPANSION = 6.4e-4
#: Salinity of standard sea water, kg/kg.
SEA_SALINITY = 0.035


@dataclass(frozen=True)
class Lubricant:
    """A Newtonian lubricant with temperature-dependent viscosity.

    Attributes
    ----------
    name : str
        Label shown in reports.
    model : str
        ``"walther"`` (ASTM D341 through two points), ``"water"``, ``"seawater"``
        or ``"constant"``.
    walther_a, walther_b : float
        ASTM D341 constants: ``log10(log10(nu_cSt + 0.7)) = a - b * log10(T_K)``.
    density_15 : float
        Density at 15 degC, kg/m^3 (oils); ignored for water models.
    constant_viscosity : float
        Dynamic viscosity for the ``"constant"`` model, Pa*s.
    """

    name: str
    model: str
    walther_a: float = 0.0
    walther_b: float = 0.0
    density_15: float = 880.0
    constant_viscosity: float = 0.0

    @classmethod
    def from_two_points(
        cls,
        name: str,
        temperature_1: float,
        kinematic_viscosity_1: float,
        temperature_2: float,
        kinematic_viscosity_2: float,
        density_15: float = 880.0,
    ) -> Lubricant:
        """Fit the ASTM D341 relation through two (degC, m^2/s) points."""
        t1 = require_finite("temperature_1", temperature_1, "degC")
        t2 = require_finite("temperature_2", temperature_2, "degC")
        nu1 = require_positive("kinematic_viscosity_1", kinematic_viscosity_1, "m^2/s")
        nu2 = require_positive("kinematic_viscosity_2", kinematic_viscosity_2, "m^2/s")
        require_positive("density_15", density_15, "kg/m^3")
        if t1 == t2:
            raise InputError("temperature_2", t2, "degC", f"different from temperature_1 ({t1})")
        if (t2 - t1) * (nu2 - nu1) >= 0.0:
            raise InputError(
                "kinematic_viscosity_2",
                nu2,
                "m^2/s",
                "a viscosity that falls as temperature rises",
            )
        y1 = math.log10(math.log10(nu1 * 1e6 + 0.7))
        y2 = math.log10(math.log10(nu2 * 1e6 + 0.7))
        x1 = math.log10(t1 + KELVIN)
        x2 = math.log10(t2 + KELVIN)
        b = (y1 - y2) / (x2 - x1)
        a = y1 + b * x1
        return cls(name=name, model="walther", walther_a=a, walther_b=b, density_15=density_15)

    @classmethod
    def constant(cls, viscosity: float, density: float = 880.0, name: str = "constant") -> Lubricant:
        """A lubricant of fixed dynamic viscosity (Pa*s), as at an effective temperature."""
        require_positive("viscosity", viscosity, "Pa*s")
        require_positive("density", density, "kg/m^3")
        return cls(name=name, model="constant", constant_viscosity=viscosity, density_15=density)

    @classmethod
    def preset(cls, name: str) -> Lubricant:
        """A named lubricant from :data:`PRESETS` (case-insensitive)."""
        key = name.strip().lower().replace("_", " ").replace("-", " ")
        key = " ".join(key.split())
        if key not in PRESETS:
            raise InputError("name", name, "", "one of " + ", ".join(sorted(PRESETS)))
        return PRESETS[key]

    def kinematic_viscosity(self, temperature: float | np.ndarray) -> float | np.ndarray:
        """Kinematic viscosity, m^2/s, at ``temperature`` degC."""
        return self.dynamic_viscosity(temperature) / self.density(temperature)

    def dynamic_viscosity(self, temperature: float | np.ndarray) -> float | np.ndarray:
        """Dynamic viscosity, Pa*s, at ``temperature`` degC."""
        t = np.asarray(temperature, dtype=float)
        if self.model == "constant":
            value = np.full_like(t, self.constant_viscosity)
        elif self.model == "walther":
            log_log = self.walther_a - self.walther_b * np.log10(t + KELVIN)
            nu_cst = 10.0 ** (10.0**log_log) - 0.7
            value = nu_cst * 1e-6 * self.density(t)
        elif self.model in ("water", "seawater"):
            value = _water_viscosity(t)
            if self.model == "seawater":
                value = value * _sea_water_factor(t, SEA_SALINITY)
        else:  # pragma: no cover - guarded by constructors
            raise InputError("model", self.model, "", "walther, water, seawater or constant")
        return float(value) if value.ndim == 0 else value

    def density(self, temperature: float | np.ndarray) -> float | np.ndarray:
        """Density, kg/m^3, at ``temperature`` degC."""
        t = np.asarray(temperature, dtype=float)
        if self.model in ("water", "seawater"):
            value = _water_density(t)
            if self.model == "seawater":
                # UNESCO EOS-80 at 20 degC gives 0.76 kg/m^3 per g/kg of salt.
                value = value + 0.76 * SEA_SALINITY * 1000.0
        elif self.model == "constant":
            value = np.full_like(t, self.density_15)
        else:
            value = self.density_15 * (1.0 - OIL_EXPANSION * (t - 15.0))
        return float(value) if value.ndim == 0 else value


def _water_viscosity(temperature: np.ndarray) -> np.ndarray:
    """Vogel equation for pure water, Pa*s (within 2.5 % from 0 to 370 degC)."""
    return 2.414e-5 * 10.0 ** (247.8 / (temperature + KELVIN - 140.0))


def _sea_water_factor(temperature: np.ndarray, salinity: float) -> np.ndarray:
    """Ratio of sea-water to pure-water viscosity, Sharqawy et al. (2010) Eq. 22."""
    a = 1.541 + 1.998e-2 * temperature - 9.52e-5 * temperature**2
    b = 7.974 - 7.561e-2 * temperature + 4.724e-4 * temperature**2
    return 1.0 + a * salinity + b * salinity**2


def _water_density(temperature: np.ndarray) -> np.ndarray:
    """Density of air-free pure water, kg/m^3 (Thiesen-type fit, within 0.01 % 0-40 degC)."""
    t = temperature
    return 1000.0 * (1.0 - (t + 288.9414) / (508929.2 * (t + 68.12963)) * (t - 3.9863) ** 2)


def _oil(name: str, nu40_cst: float, nu100_cst: float, density_15: float) -> Lubricant:
    return Lubricant.from_two_points(name, 40.0, nu40_cst * 1e-6, 100.0, nu100_cst * 1e-6, density_15)


#: Named lubricants. Mineral-oil points are typical datasheet values for oils of
#: viscosity index about 95-100 (ISO 3448 grades fix only the 40 degC midpoint).
PRESETS: dict[str, Lubricant] = {
    "iso vg 68": _oil("ISO VG 68", 68.0, 8.7, 875.0),
    "iso vg 100": _oil("ISO VG 100", 100.0, 11.2, 880.0),
    "iso vg 150": _oil("ISO VG 150", 150.0, 14.7, 885.0),
    "sae 30": _oil("SAE 30", 100.0, 11.0, 890.0),
    "water": Lubricant(name="fresh water", model="water"),
    "fresh water": Lubricant(name="fresh water", model="water"),
    "sea water": Lubricant(name="sea water", model="seawater"),
    "seawater": Lubricant(name="sea water", model="seawater"),
}
