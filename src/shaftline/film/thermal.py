"""Effective film temperature of a plain bearing from its heat balance (issue 15).

The film's viscosity depends on its temperature and the friction power heats the film: the
bearing runs at the temperature where the two agree. The balance is that of ISO 7902-1
(hydrodynamic plain journal bearings, steady state) and of Raimondi & Boyd's effective
temperature: a share ``heat_to_lubricant`` of the friction power ``P_f`` leaves with the
lubricant that flows out of the film ends (side leakage ``Q``), the rest by conduction through
the bush, housing and shaft, so the lubricant warms by

    dT = heat_to_lubricant * P_f / (rho * c_p * Q),

and the film works at the effective temperature ``T_eff = T_in + dT / 2`` (the mean of inlet
and outlet; ISO 7902-1 takes the same mean for a bearing cooled by its lubricant), its hottest
lubricant leaving at ``T_out = T_in + dT``. Since ``P_f`` and ``Q`` come from the film at the
viscosity ``eta(T_eff)``, the effective temperature is the root of

    g(T) = T_in + dT(eta(T)) / 2 - T = 0,

which is found by Brent's method (scipy.optimize.brentq) on ``[T_in, T_top]``: ``g(T_in) >= 0``
always (the film cannot cool its inlet), and ``T_top`` is the top of the lubricant's viscosity
model. When ``g(T_top) > 0`` the film would run hotter than the model knows: the result says
so (``converged = False``) rather than extrapolating.

Specific heat: oils by Cragoe's relation (US Bureau of Standards Misc. Pub. 97, 1929),
``c_p = (1.684 + 0.003389 T) / sqrt(d15)`` kJ/(kg K) with T in degC and d15 the relative density
at 15 degC; water 4182 J/(kg K) (IAPWS-95 at 20 degC; within 1 % from 5 to 90 degC).
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass, field

from shaftline.errors import InputError, require_finite
from shaftline.film.problem import BearingProblem
from shaftline.lubricants import Lubricant

__all__ = [
    "TEMPERATURE_RANGES",
    "bearing_film",
    "ThermalOptions",
    "ThermalResult",
    "specific_heat",
    "thermal_balance",
]

#: Temperatures over which each viscosity model holds, degC (ASTM D341 is stated for mineral
#: oils from about -20 to 150 degC; the water correlations from 0 to 100 degC).
TEMPERATURE_RANGES = {"walther": (-20.0, 150.0), "water": (0.0, 100.0), "seawater": (0.0, 100.0)}

#: Specific heat of water, J/(kg K).
WATER_SPECIFIC_HEAT = 4182.0


def specific_heat(lubricant: Lubricant, temperature: float) -> float:
    """Specific heat at constant pressure, J/(kg K), at ``temperature`` degC (module doc)."""
    if lubricant.model in ("water", "seawater"):
        return WATER_SPECIFIC_HEAT
    relative_density = lubricant.density_15 / 999.1  # water at 15 degC
    return 1000.0 * (1.684 + 0.003389 * temperature) / math.sqrt(relative_density)


@dataclass(frozen=True)
class ThermalOptions:
    """Inputs of the heat balance.

    Attributes
    ----------
    inlet_temperature : float
        Temperature of the lubricant reaching the film, degC (the stern-tube header tank or
        the sea-cooled oil, the sea for a water-lubricated bearing).
    heat_to_lubricant : float
        Share of the friction power carried away by the lubricant, in (0, 1]; 1 puts all of it
        into the oil (the conservative, adiabatic bound); the rest is conducted away.
    tolerance : float
        Effective temperature tolerance, K.
    """

    inlet_temperature: float
    heat_to_lubricant: float = 1.0
    tolerance: float = 0.05

    def __post_init__(self) -> None:
        require_finite("inlet_temperature", self.inlet_temperature, "degC")
        share = require_finite("heat_to_lubricant", self.heat_to_lubricant, "")
        if not 0.0 < share <= 1.0:
            raise InputError("heat_to_lubricant", share, "", "a share in (0, 1]")
        tolerance = require_finite("tolerance", self.tolerance, "K")
        if not 0.0 < tolerance <= 5.0:
            raise InputError("tolerance", tolerance, "K", "in (0, 5]")


@dataclass(frozen=True)
class ThermalResult:
    """The heat balance's result.

    Attributes
    ----------
    inlet_temperature : float
        Temperature of the lubricant reaching the film, degC.
    effective_temperature : float
        Temperature the film works at, degC.
    outlet_temperature : float
        Temperature of the lubricant leaving the film (the hottest lubricant), degC.
    viscosity : float
        Dynamic viscosity at the effective temperature, Pa s.
    power_loss, side_leakage : float
        Friction power, W, and side leakage, m^3/s, of the film at that viscosity.
    converged : bool
        False when the balance lies above the top of the viscosity model's range (the film
        would run hotter than the lubricant data reach); the numbers are then those at the top.
    evaluations : int
        Film solutions used.
    history : list of (T, P_f, Q)
        Every film solution: temperature (degC), friction power (W), side leakage (m^3/s).
    """

    inlet_temperature: float
    effective_temperature: float
    outlet_temperature: float
    viscosity: float
    power_loss: float
    side_leakage: float
    converged: bool
    evaluations: int
    history: list[tuple[float, float, float]] = field(repr=False)

    @property
    def temperature_rise(self) -> float:
        """Outlet above inlet, K."""
        return self.outlet_temperature - self.inlet_temperature


def thermal_balance(
    film: Callable[[float], tuple[float, float]],
    lubricant: Lubricant,
    options: ThermalOptions,
) -> ThermalResult:
    """Effective temperature at which the film's friction heat and the lubricant agree.

    Parameters
    ----------
    film : callable
        ``film(viscosity) -> (power_loss, side_leakage)``: the film solved at a dynamic
        viscosity (Pa s), e.g. the load equilibrium of a bearing, giving its friction power (W)
        and side leakage (m^3/s).
    lubricant : Lubricant
        Its viscosity and density against temperature (not ``"constant"``).
    options : ThermalOptions

    Returns
    -------
    ThermalResult

    Raises
    ------
    InputError
        ``"lubricant"`` for a constant-viscosity lubricant (no temperature dependence to
        balance), ``"inlet_temperature"`` outside the viscosity model's range.
    """
    if lubricant.model == "constant":
        raise InputError("lubricant", lubricant.name, "", "a lubricant whose viscosity follows temperature")
    low, high = TEMPERATURE_RANGES[lubricant.model]
    t_in = options.inlet_temperature
    if not low <= t_in < high:
        raise InputError("inlet_temperature", t_in, "degC", f"{low:g} to {high:g} degC, the range of {lubricant.name}")
    history: list[tuple[float, float, float]] = []
    cache: dict[float, float] = {}

    def rise(temperature: float) -> float:
        """dT (K) of the film at ``temperature``."""
        if temperature not in cache:
            viscosity = float(lubricant.dynamic_viscosity(temperature))
            power, leakage = film(viscosity)
            heat = float(lubricant.density(temperature)) * specific_heat(lubricant, temperature)
            history.append((temperature, float(power), float(leakage)))
            cache[temperature] = options.heat_to_lubricant * power / (heat * leakage) if leakage > 0.0 else math.inf
        return cache[temperature]

    def imbalance(temperature: float) -> float:
        return t_in + 0.5 * rise(temperature) - temperature

    top = high
    converged = imbalance(top) <= 0.0
    if converged:
        from scipy.optimize import brentq

        # g(T_in) = dT/2 >= 0 and g(top) <= 0 bracket the root.
        effective = float(brentq(imbalance, t_in, top, xtol=options.tolerance, rtol=1e-12, maxiter=60))
    else:
        effective = top
    temperature_rise = rise(effective)
    power, leakage = next((p, q) for t, p, q in reversed(history) if t == effective)
    return ThermalResult(
        inlet_temperature=t_in,
        effective_temperature=effective,
        outlet_temperature=t_in + temperature_rise,
        viscosity=float(lubricant.dynamic_viscosity(effective)),
        power_loss=power,
        side_leakage=leakage,
        converged=converged,
        evaluations=len(history),
        history=history,
    )


def bearing_film(
    problem: BearingProblem, load_y: float, load_z: float = 0.0, tilt_y: float = 0.0, tilt_z: float = 0.0
) -> Callable[[float], tuple[float, float]]:
    """``film(viscosity) -> (power_loss, side_leakage)`` of a bearing at its load equilibrium,
    for :func:`thermal_balance`: the problem with that viscosity, each equilibrium started
    from the last one's journal position (the balance's evaluations are close together)."""
    from dataclasses import replace

    from shaftline.film.bearing import JournalBearing

    last: list = []

    def film(viscosity: float) -> tuple[float, float]:
        operating = replace(problem.operating, viscosity=viscosity)
        bearing = JournalBearing(problem.geometry, operating, problem.options)
        found = bearing.equilibrium(load_y, load_z, tilt_y=tilt_y, tilt_z=tilt_z, initial=last[-1] if last else None)
        last[:] = [found.state.position]
        return found.state.power_loss, found.state.side_leakage

    return film
