"""Rheology: pressure-viscosity models, Vogel against ASTM D341, limiting shear stress, the
Bair-Winer law, lubricant data and validity ranges."""

import dataclasses
import warnings

import numpy as np
import pytest

from shaftline.contact import rheology
from shaftline.errors import InputError


def test_roelands_matches_barus_slope_at_zero_pressure():
    # z from alpha (Hamrock 1994 Eq. 4.13) makes d ln(eta)/dp = alpha at p = 0; 1e-4 (finite
    # difference over 1 kPa).
    for eta0, alpha in ((0.005, 1.0e-8), (0.05, 2.2e-8), (0.3, 2.5e-8)):
        dp = 1e3
        slope = (np.log(rheology.roelands(eta0, alpha, dp)) - np.log(eta0)) / dp
        assert slope == pytest.approx(alpha, rel=1e-4)


def test_roelands_below_barus_at_high_pressure():
    # Roelands grows slower than exponential (z < 1 for these oils): the known overestimate of
    # Barus above about 0.5 GPa (Hamrock 1994 Fig. 4.4).
    p = np.array([0.5e9, 1e9, 2e9])
    assert np.all(rheology.roelands(0.01, 1.5e-8, p) < rheology.barus(0.01, 1.5e-8, p))


def test_vogel_through_three_astm_points_follows_astm_d341():
    # Two independent viscosity-temperature laws: Vogel fitted at 40, 70 and 100 degC to the ASTM
    # D341 line of each oil stays within 1.5 % of it between 40 and 100 degC (found: 0.4 %).
    for lubricant in rheology.CONTACT_LUBRICANTS.values():
        points = (40.0, 70.0, 100.0)
        a, b, c = rheology.fit_vogel(points, tuple(float(lubricant.dynamic_viscosity(t)) for t in points))
        t = np.linspace(40.0, 100.0, 61)
        np.testing.assert_allclose(rheology.vogel(t, a, b, c), lubricant.dynamic_viscosity(t), rtol=0.015)


def test_bair_winer_limits():
    # Newtonian at low shear rate, the limiting stress at high (seed 002 Eq. 4).
    assert float(rheology.bair_winer_stress(0.1, 1.0, 5e7)) == pytest.approx(0.1, rel=1e-6)
    assert float(rheology.bair_winer_stress(100.0, 1e9, 5e7)) == pytest.approx(5e7, rel=1e-12)


def test_mil_prf_23699_meets_its_specification():
    # MIL-PRF-23699: 4.90-5.40 mm^2/s at 100 degC, at least 23 mm^2/s at 40 degC.
    oil = rheology.contact_lubricant("MIL-PRF-23699")
    nu = oil.viscosity.kinematic_viscosity(np.array([40.0, 100.0])) * 1e6
    assert nu[0] >= 23.0
    assert 4.90 <= nu[1] <= 5.40


def test_temperature_viscosity_coefficient_matches_log_slope():
    oil = rheology.contact_lubricant("ISO VG 100")
    beta = oil.temperature_viscosity_coefficient(60.0)
    by_hand = np.log(oil.dynamic_viscosity(55.0) / oil.dynamic_viscosity(65.0)) / 10.0
    assert float(beta) == pytest.approx(float(by_hand), rel=1e-3)


def test_validity_ranges_error_or_warn():
    oil = rheology.contact_lubricant("fva_3")
    with pytest.raises(InputError, match=r"temperature = 180 degC: allowed in \[0, 150\] degC"):
        oil.dynamic_viscosity(180.0)
    with pytest.warns(rheology.ExtrapolationWarning, match=r"\[0, 150\] degC"):
        oil.dynamic_viscosity(180.0, extrapolate=True)
    with pytest.raises(InputError, match="pressure"):
        oil.limiting_shear_stress(4e9)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        oil.dynamic_viscosity(np.array([20.0, 90.0]))
    with pytest.raises(InputError, match="lubricant = 'SAE 90': allowed one of fva 3"):
        rheology.contact_lubricant("SAE 90")
    with pytest.raises(InputError, match="pressure_viscosity_model"):
        oil.viscosity_at(1e8, 60.0, "eyring")


@pytest.mark.parametrize(("name", "tolerance"), [("iso vg 100", 0.03), ("fva 3", 0.05)])
def test_mineral_alpha_from_the_published_oil_of_the_same_viscosity(name, tolerance):
    # Issue 14 (e): alpha of the ISO VG 100 class is taken from Stachowiak & Batchelor, Engineering
    # Tribology, Table 2.3 (adapted there from Jones et al.), the 'heavy machine oil' with 153, 34 and
    # 9.1 mPa s at 30, 60, 100 degC and alpha 23.7, 20.5, 15.8 GPa^-1. The choice is justified only if
    # the oil here has that viscosity: ISO VG 100's ASTM D341 line gives 153.5, 34.1, 9.3 mPa s (within
    # 3 %), FVA 3's 146.6, 32.6, 9.0 (5 %) - the tolerances, measured, that a wrong pick would break
    # (the table's other heavy machine oils miss by 19-27 % at one of the temperatures or more). alpha
    # must be the table's at its temperatures.
    lubricant = rheology.contact_lubricant(name)
    for temperature, viscosity, alpha in ((30.0, 0.153, 2.37e-8), (60.0, 0.034, 2.05e-8), (100.0, 0.0091, 1.58e-8)):
        assert float(lubricant.dynamic_viscosity(temperature)) == pytest.approx(viscosity, rel=tolerance)
        assert float(lubricant.alpha(temperature)) == pytest.approx(alpha, rel=1e-12)


#: The correlation alpha = s nu^t (nu in mm^2/s, alpha in 1/GPa) that the FEUP gear group's papers
#: attribute to Gold, Schmidt, Dicke, Loos & Assmann (2001, J. Synth. Lubr. 18: the attribution is
#: recalled, the paper was not seen here), as two public gear codes of that group transcribe it
#: (github.com/cfernandesFEUP/GEARpie, CLASSES/LUBRICANT_LIBRARY.py; .../Gear-Calculation,
#: GearC/oils.py): both put the digits of s and t in other places (0.1390/0.9904, 1.390/0.9904) and
#: pair the ester and PAO constants the other way round, so both ester pairings are tried; the
#: mineral pair is the one both agree on once the digits are read as (9.904, 0.1390).
_GOLD = {"mineral": ((9.904, 0.1390),), "ester": ((6.605, 0.1360), (7.382, 0.1335))}


@pytest.mark.parametrize(
    ("name", "base"), [("MIL-PRF-23699", "ester"), ("FVA 3", "mineral"), ("ISO VG 100", "mineral")]
)
def test_alpha_tables_against_golds_correlation(name, base):
    # A second, independent source for the tabulated alpha (issue 14, closing work, gap 3): the
    # tables (Jones et al. 1975 via Hamrock for the ester, Stachowiak & Batchelor Table 2.3 for the
    # mineral oils) sit 9-27 % above Gold's correlation at 30-100 degC (measured), the same sign for
    # all three oils - the definitions of alpha behind a table and a correlation differ (initial slope,
    # secant over a pressure range). The band 1.0-1.4 catches a unit or digit slip (a factor 10) and a
    # wrong base oil (the mineral table's alpha on the ester would be 1.7-2.2 times the correlation);
    # it is not a check to a few per cent, and it does not source the ester's table itself.
    lubricant = rheology.contact_lubricant(name)
    for temperature in (30.0, 40.0, 60.0, 90.0, 100.0):
        nu = float(lubricant.viscosity.kinematic_viscosity(temperature)) * 1e6
        alpha = float(lubricant.alpha(temperature)) * 1e9
        for s, t in _GOLD[base]:
            assert 1.0 < alpha / (s * nu**t) < 1.4, (temperature, s)


def test_fva_3_viscosity_against_a_second_public_source():
    # FVA 3's viscosity (95 and 10.7 mm^2/s at 40/100 degC, 885 kg/m^3, "as commonly quoted", no data
    # sheet found) against the ASTM D341 constants of 'FVA3' in a public gear code of the FEUP gear
    # group (github.com/cfernandesFEUP/Gear-Calculation, GearC/oils.py: log log(nu + 0.7) = 9.2384 -
    # 3.5810 log T, 900 kg/m^3 at 15 degC): 99.4 / 10.99 mm^2/s. Two quotes of one reference oil, 2.6-4.4 %
    # apart from 40 to 100 degC (measured; 2.8 % at the FZG test's 90 degC), so 5 %: a different oil (the
    # neighbouring ISO grades are 1.5 times apart) or a unit slip would fail. The data stay as they were
    # (docs/theory.md 15.3): neither source is the FVA data sheet.
    fva = rheology.contact_lubricant("FVA 3")
    for temperature in (40.0, 60.0, 90.0, 100.0):
        feup = -0.7 + 10 ** (10 ** (9.2384 - 3.5810 * np.log10(temperature + 273.15)))
        ours = float(fva.viscosity.kinematic_viscosity(temperature)) * 1e6
        assert ours == pytest.approx(feup, rel=0.05), temperature
    assert float(fva.viscosity.density(15.0)) == pytest.approx(900.0, rel=0.02)


@pytest.mark.parametrize(
    ("change", "field"),
    [
        ({"pressure_viscosity": ()}, "pressure_viscosity"),
        ({"pressure_viscosity": ((40.0, 2e-8), (40.0, 1e-8))}, "pressure_viscosity"),
        ({"pressure_viscosity": ((40.0, 0.0),)}, "pressure_viscosity"),
        ({"limiting_shear_ratio": 0.0}, "limiting_shear_ratio"),
        ({"limiting_shear_ratio": -0.01, "limiting_shear_stress_0": 1e6}, "limiting_shear_ratio"),
        ({"limiting_shear_stress_0": -1.0}, "limiting_shear_stress_0"),
        ({"thermal_conductivity": 0.0}, "thermal_conductivity"),
        ({"temperature_range": (100.0, 20.0)}, "temperature_range"),
        ({"max_pressure": 0.0}, "max_pressure"),
        ({"pressure_viscosity": np.array([40.0, 2e-8])}, "pressure_viscosity"),
        ({"limiting_shear_ratio": float("inf")}, "limiting_shear_ratio"),
    ],
)
def test_a_lubricant_lacking_data_is_refused_where_it_is_made(change, field):
    # Through the API a lubricant without its pressure-viscosity data failed deep in a model
    # (ValueError: not enough values to unpack), and tau_L = 0 silently gave no fluid friction.
    with pytest.raises(InputError) as error:
        dataclasses.replace(rheology.contact_lubricant("FVA 3"), **change)
    assert error.value.field == field


def test_a_lubricant_may_give_its_data_as_arrays_or_a_constant_limiting_stress():
    # numpy arrays for the alpha table (as a user reading a file would pass them) and tau_L = tau_L0
    # with gamma_L = 0 (a constant limiting stress, still > 0) are valid lubricants
    oil = rheology.contact_lubricant("FVA 3")
    as_array = dataclasses.replace(oil, pressure_viscosity=np.array(oil.pressure_viscosity))
    assert float(as_array.alpha(60.0)) == float(oil.alpha(60.0))
    assert as_array == oil and hash(as_array) == hash(oil)  # kept as tuples: a frozen value
    constant = dataclasses.replace(oil, limiting_shear_ratio=0.0, limiting_shear_stress_0=5e6)
    assert float(constant.limiting_shear_stress(1e9)) == 5e6
