"""Turbulent films: the linearised turbulence coefficients of the Reynolds equation.

Large, fast, low-viscosity films (water-lubricated stern tubes) run at local Reynolds numbers
``Re_h = rho U h / mu`` of thousands, beyond the onset of Taylor vortices and into turbulence.
The linearised theories of Constantinescu (1962) and Ng & Pan (1965) keep the form of the
Reynolds equation and replace its laminar 12 by coefficients that grow with the local Reynolds
number (docs/theory.md, Sect. 17, "Turbulent films", gives every source):

    q_x = -h^3 / (k_x mu) dp/dx + U h / 2,   q_z = -h^3 / (k_z mu) dp/dz,
    tau_couette = (mu U / h) C_f(Re_h)

so the pressure flow is scaled by ``12 / k_x`` and ``12 / k_z`` (a per-node factor on the
Poiseuille terms, combined with the Patir-Cheng ``phi_x`` where the surfaces are rough) and the
Couette shear by ``C_f``; the Couette flow is unchanged. Every coefficient tends to its laminar
value as ``Re_h -> 0``.

With ``H = h / c`` the local Reynolds number is ``Re_c H``, ``Re_c = rho omega R c / mu`` the
clearance Reynolds number, so the coefficients are functions of the local film alone, as the
flow factors are: :class:`TurbulentFilm` has the interface of
:class:`~shaftline.film.roughness.RoughFilm` and enters the stencil the same way.

Only numpy and ``math`` are imported at module level.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Literal, get_args

import numpy as np

from shaftline.film.roughness import RoughFilm

__all__ = [
    "TAYLOR_CRITICAL",
    "TURBULENCE_MODELS",
    "TURBULENCE_MODES",
    "TurbulenceMode",
    "TurbulenceModel",
    "TurbulentFilm",
    "clearance_reynolds",
    "couette_shear_factor",
    "couette_shear_factor_derivative",
    "pressure_flow_coefficients",
    "pressure_flow_coefficients_derivative",
    "transition_reynolds",
    "turbulence_active",
]

TurbulenceMode = Literal["off", "on", "auto"]
TURBULENCE_MODES: tuple[TurbulenceMode, ...] = get_args(TurbulenceMode)
TurbulenceModel = Literal["ng_pan", "constantinescu"]
TURBULENCE_MODELS: tuple[TurbulenceModel, ...] = get_args(TurbulenceModel)

#: Taylor (1923): Couette flow between a rotating inner and a resting outer cylinder turns
#: unstable (Taylor vortices) at ``Re_c sqrt(c / R) = 41.3`` (narrow gap). ``auto`` turbulence
#: starts there; Ng & Pan's and Constantinescu's fits describe the turbulent regime beyond.
TAYLOR_CRITICAL = 41.3
#: Ng & Pan (1965), as tabulated for design by Taylor & Dowson (1974):
#: ``k_x = 12 + 0.0136 Re^0.90``, ``k_z = 12 + 0.0043 Re^0.96``.
_NG_PAN = (0.0136, 0.90, 0.0043, 0.96)
#: Constantinescu (1962), as given by Hamrock, Schmid & Jacobson (2004):
#: ``k_x = 12 + 0.53 (k0^2 Re)^0.725``, ``k_z = 12 + 0.296 (k0^2 Re)^0.65``, ``k0 = 0.125 Re^0.07``.
_CONSTANTINESCU = (0.53, 0.725, 0.296, 0.65)
_K0, _K0_EXPONENT = 0.125, 0.07
#: Couette shear factor ``C_f = 1 + 0.0012 Re^0.94`` (Ng & Pan / Taylor & Dowson 1974; the same
#: expression is ISO 7902-1's turbulent friction in a groove).
_COUETTE = (0.0012, 0.94)


def clearance_reynolds(density: float, speed: float, radius: float, clearance: float, viscosity: float) -> float:
    """``Re_c = rho omega R c / mu``: the local Reynolds number of a film one clearance thick.

    Parameters
    ----------
    density : float
        Lubricant density, kg/m^3.
    speed : float
        Shaft speed, rad/s.
    radius, clearance : float
        Journal radius and radial clearance, m.
    viscosity : float
        Dynamic viscosity, Pa s.
    """
    return density * speed * radius * clearance / viscosity


def transition_reynolds(radius: float, clearance: float) -> float:
    """Clearance Reynolds number at which Taylor vortices set in, ``41.3 sqrt(R / c)``, -."""
    return TAYLOR_CRITICAL * math.sqrt(radius / clearance)


def turbulence_active(mode: TurbulenceMode, reynolds: float, radius: float, clearance: float) -> bool:
    """Whether the turbulence coefficients apply: ``"on"`` always, ``"off"`` never, ``"auto"``
    when the largest local Reynolds number of the bore, ``2 Re_c`` (a film of at most 2c),
    exceeds :func:`transition_reynolds`."""
    if mode == "on":
        return True
    if mode == "auto":
        return 2.0 * reynolds > transition_reynolds(radius, clearance)
    return False


def _power(coefficient: float, exponent: float, re: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """``a Re^b`` and its derivative ``a b Re^(b-1)`` (0 at Re = 0, where b > 1 is not used)."""
    value = coefficient * re**exponent
    slope = np.where(re > 0.0, exponent * value / np.where(re > 0.0, re, 1.0), 0.0)
    return value, slope


def _coefficients(re: np.ndarray, model: TurbulenceModel) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """``k_x, k_z`` and their derivatives in ``Re``."""
    re = np.maximum(np.asarray(re, dtype=float), 0.0)
    if model == "ng_pan":
        ax, bx, az, bz = _NG_PAN
        px, dpx = _power(ax, bx, re)
        pz, dpz = _power(az, bz, re)
        return 12.0 + px, 12.0 + pz, dpx, dpz
    if model == "constantinescu":
        # k0^2 Re = 0.125^2 Re^1.14: a power of Re, so each term is c Re^e.
        ax, bx, az, bz = _CONSTANTINESCU
        scale, power = _K0 * _K0, 1.0 + 2.0 * _K0_EXPONENT
        px, dpx = _power(ax * scale**bx, power * bx, re)
        pz, dpz = _power(az * scale**bz, power * bz, re)
        return 12.0 + px, 12.0 + pz, dpx, dpz
    raise ValueError(f"unknown turbulence model {model!r}")


def pressure_flow_coefficients(
    re: np.ndarray | float, model: TurbulenceModel = "ng_pan"
) -> tuple[np.ndarray, np.ndarray]:
    """Turbulence coefficients ``(k_x, k_z)`` of the pressure flow at local Reynolds numbers ``re``.

    12 in laminar flow (``re = 0``); the film's pressure flow is ``12 / k`` of the laminar one.

    Examples
    --------
    >>> kx, kz = pressure_flow_coefficients(np.array([0.0, 5000.0]))
    >>> [round(float(v), 2) for v in kx], [round(float(v), 2) for v in kz]
    ([12.0, 41.01], [12.0, 27.29])
    """
    kx, kz, _, _ = _coefficients(np.asarray(re, dtype=float), model)
    return kx, kz


def pressure_flow_coefficients_derivative(
    re: np.ndarray | float, model: TurbulenceModel = "ng_pan"
) -> tuple[np.ndarray, np.ndarray]:
    """``(dk_x/dRe, dk_z/dRe)``."""
    _, _, dkx, dkz = _coefficients(np.asarray(re, dtype=float), model)
    return dkx, dkz


def couette_shear_factor(re: np.ndarray | float) -> np.ndarray:
    """``C_f = 1 + 0.0012 Re^0.94``: the Couette shear stress over the laminar ``mu U / h``."""
    values = np.maximum(np.asarray(re, dtype=float), 0.0)
    return 1.0 + _COUETTE[0] * values ** _COUETTE[1]


def couette_shear_factor_derivative(re: np.ndarray | float) -> np.ndarray:
    """``dC_f / dRe``."""
    values = np.maximum(np.asarray(re, dtype=float), 0.0)
    return _power(_COUETTE[0], _COUETTE[1], values)[1]


@dataclass(frozen=True)
class TurbulentFilm:
    """The turbulence of a film as the dimensionless film equation needs it (films over c).

    The same interface as :class:`~shaftline.film.roughness.RoughFilm`: face conductances along
    theta (``axial_*``: along z), Couette transport and squeeze factor of face or node films
    ``H``. The pressure-flow conductances are those of ``rough`` (or ``H^3`` for smooth surfaces)
    times ``12 / k_x(Re_c H)`` (``12 / k_z``); transport and squeeze are ``rough``'s (or the
    smooth film's): the linearised theory leaves the Couette flow unchanged.

    Attributes
    ----------
    reynolds : float
        Clearance Reynolds number ``Re_c`` (:func:`clearance_reynolds`).
    model : TurbulenceModel
        ``"ng_pan"`` or ``"constantinescu"``.
    rough : RoughFilm or None
        The surfaces' flow factors (None: smooth).
    """

    reynolds: float
    model: TurbulenceModel = "ng_pan"
    rough: RoughFilm | None = None

    def _factor(self, film: np.ndarray, axial: bool) -> tuple[np.ndarray, np.ndarray]:
        """``12 / k`` at films ``H`` and its derivative in ``H``."""
        # Re_h = Re_c max(H, 0): a rough film past the mean plane (H <= 0) flows laminar (docs/theory.md,
        # "Turbulent films"); _coefficients clamps likewise, with a zero slope there.
        kx, kz, dkx, dkz = _coefficients(self.reynolds * np.maximum(film, 0.0), self.model)
        k, dk = (kz, dkz) if axial else (kx, dkx)
        factor = 12.0 / k
        return factor, -factor / k * dk * self.reynolds

    def _laminar(self, film: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        if self.rough is None:
            return film**3, 3.0 * film**2
        return self.rough.conductance(film), self.rough.conductance_derivative(film)

    def conductance(self, film: np.ndarray) -> np.ndarray:
        """``H^3 phi_x 12 / k_x`` of theta-face films ``H``."""
        return self._laminar(film)[0] * self._factor(film, axial=False)[0]

    def conductance_derivative(self, film: np.ndarray) -> np.ndarray:
        """``d conductance / dH``."""
        base, dbase = self._laminar(film)
        factor, dfactor = self._factor(film, axial=False)
        return dbase * factor + base * dfactor

    def axial_conductance(self, film: np.ndarray) -> np.ndarray:
        """``H^3 phi_z 12 / k_z`` of z-face films ``H``."""
        return self._laminar(film)[0] * self._factor(film, axial=True)[0]

    def axial_conductance_derivative(self, film: np.ndarray) -> np.ndarray:
        """``d axial_conductance / dH``."""
        base, dbase = self._laminar(film)
        factor, dfactor = self._factor(film, axial=True)
        return dbase * factor + base * dfactor

    def transport(self, film: np.ndarray) -> np.ndarray:
        """Couette transport of face films over that of a smooth film (unchanged by turbulence)."""
        return film if self.rough is None else self.rough.transport(film)

    def transport_derivative(self, film: np.ndarray) -> np.ndarray:
        """``d transport / dH``."""
        return np.ones_like(film) if self.rough is None else self.rough.transport_derivative(film)

    def squeeze_factor(self, film: np.ndarray) -> np.ndarray:
        """Squeeze factor of node films (1 on smooth surfaces)."""
        return np.ones_like(film) if self.rough is None else self.rough.squeeze_factor(film)

    def squeeze_factor_derivative(self, film: np.ndarray) -> np.ndarray:
        """``d squeeze_factor / dH``."""
        return np.zeros_like(film) if self.rough is None else self.rough.squeeze_factor_derivative(film)
