"""The effective-temperature heat balance (issue 15; docs/theory.md "Oil temperature")."""

from __future__ import annotations

import math

import pytest

from shaftline.errors import InputError
from shaftline.film.thermal import ThermalOptions, bearing_film, specific_heat, thermal_balance
from shaftline.lubricants import Lubricant

OIL = Lubricant.preset("ISO VG 68")


def test_cragoe_specific_heat_of_a_mineral_oil():
    """Cragoe (1929): c_p = (1.684 + 0.003389 T)/sqrt(d15) kJ/(kg K); for d15 = 0.876 at
    40 degC, 1.945 kJ/(kg K) (by hand: 1.8196 / 0.9359); mineral oils lie at 1.8-2.1."""
    oil = Lubricant("oil", "walther", 10.0, 3.8, density_15=0.876 * 999.1)
    assert specific_heat(oil, 40.0) == pytest.approx(1945.0, rel=2e-3)
    assert specific_heat(Lubricant.preset("sea water"), 20.0) == 4182.0


def test_a_petroff_film_balances_where_the_heat_fits():
    """A film whose friction power is proportional to viscosity and whose leakage is fixed
    (a lightly loaded, Petroff bearing): the effective temperature returned satisfies
    T = T_in + dT/2 to the tolerance, and a hotter inlet gives a hotter, thinner film."""
    leakage = 2e-5  # m^3/s

    def film(viscosity: float) -> tuple[float, float]:
        return 4e5 * viscosity, leakage

    options = ThermalOptions(inlet_temperature=40.0, heat_to_lubricant=0.8, tolerance=0.01)
    result = thermal_balance(film, OIL, options)
    assert result.converged
    t = result.effective_temperature
    heat = float(OIL.density(t)) * specific_heat(OIL, t) * leakage
    rise = 0.8 * 4e5 * float(OIL.dynamic_viscosity(t)) / heat
    assert t == pytest.approx(40.0 + 0.5 * rise, abs=0.05)
    assert result.outlet_temperature == pytest.approx(40.0 + rise, abs=0.1)
    assert result.temperature_rise == pytest.approx(rise, abs=0.1)
    hotter = thermal_balance(film, OIL, ThermalOptions(inlet_temperature=50.0, heat_to_lubricant=0.8))
    assert hotter.effective_temperature > t and hotter.viscosity < result.viscosity
    # All of the heat into the oil (the adiabatic bound) runs hotter than 80 % of it.
    adiabatic = thermal_balance(film, OIL, ThermalOptions(inlet_temperature=40.0))
    assert adiabatic.effective_temperature > t


def test_a_film_that_would_run_beyond_the_oil_data_is_flagged():
    def film(viscosity: float) -> tuple[float, float]:
        return 1e9 * viscosity, 1e-7

    result = thermal_balance(film, OIL, ThermalOptions(inlet_temperature=40.0))
    assert not result.converged and result.effective_temperature == 150.0


def test_bad_inputs_name_the_field():
    with pytest.raises(InputError) as error:
        ThermalOptions(inlet_temperature=40.0, heat_to_lubricant=1.5)
    assert error.value.field == "heat_to_lubricant"
    with pytest.raises(InputError) as error:
        thermal_balance(lambda v: (1.0, 1.0), Lubricant.constant(0.05), ThermalOptions(inlet_temperature=40.0))
    assert error.value.field == "lubricant"
    with pytest.raises(InputError) as error:
        thermal_balance(lambda v: (1.0, 1.0), Lubricant.preset("sea water"), ThermalOptions(inlet_temperature=120.0))
    assert error.value.field == "inlet_temperature"


def test_the_stern_tube_bearing_warms_its_oil():
    """The NTUA stern tube (examples/ntua_stern_tube.toml geometry, 100 x 60 reduced to 40 x 24)
    in ISO VG 68 from a 40 degC inlet: the film runs warmer than the inlet, and its power and
    leakage at the effective temperature are the film's own there."""
    from pathlib import Path

    from shaftline.cases import load_case
    from shaftline.film.bearing import JournalBearing
    from shaftline.film.problem import BearingProblem

    root = Path(__file__).resolve().parents[2]
    case = load_case(root / "examples" / "ntua_stern_tube.toml")["bearing"].cases[0]
    from dataclasses import replace

    options = replace(case.options, axial_nodes=40, circumferential_nodes=24)
    problem = BearingProblem(case.geometry, case.operating, options)
    film = bearing_film(problem, case.load_y, case.load_z, tilt_y=case.tilt_y)
    result = thermal_balance(film, OIL, ThermalOptions(inlet_temperature=40.0, heat_to_lubricant=0.8))
    assert result.converged and 40.0 < result.effective_temperature < result.outlet_temperature < 150.0
    check = JournalBearing(case.geometry, replace(case.operating, viscosity=result.viscosity), options).equilibrium(
        case.load_y, case.load_z, tilt_y=case.tilt_y
    )
    assert check.state.power_loss == pytest.approx(result.power_loss, rel=1e-6)
    assert math.isfinite(result.side_leakage) and result.side_leakage > 0.0
