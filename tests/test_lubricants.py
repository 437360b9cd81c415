"""Lubricant properties against reference values.

References: IAPWS (2008) viscosity of water at 20 degC, 1.0016 mPa s (Vogel form within
0.5 % here); Sharqawy et al. (2010) Table 7: sea water of 35 g/kg at 20 degC, 1.08 mPa s
(1 %); ASTM D341 must return its own two reference points (1e-9).
"""

from __future__ import annotations

import numpy as np
import pytest

from shaftline.errors import InputError
from shaftline.lubricants import PRESETS, Lubricant


def test_walther_passes_through_its_points():
    oil = Lubricant.from_two_points("test", 40.0, 68e-6, 100.0, 8.7e-6, 875.0)
    assert oil.kinematic_viscosity(40.0) == pytest.approx(68e-6, rel=1e-9)
    assert oil.kinematic_viscosity(100.0) == pytest.approx(8.7e-6, rel=1e-9)
    # and falls monotonically in between
    values = oil.kinematic_viscosity(np.linspace(40, 100, 13))
    assert np.all(np.diff(values) < 0)


def test_water_and_sea_water():
    assert PRESETS["water"].dynamic_viscosity(20.0) == pytest.approx(1.0016e-3, rel=5e-3)
    assert PRESETS["sea water"].dynamic_viscosity(20.0) == pytest.approx(1.08e-3, rel=1e-2)
    assert PRESETS["sea water"].density(20.0) == pytest.approx(1024.8, rel=1e-3)


@pytest.mark.parametrize("name", ["ISO VG 68", "iso_vg_100", "ISO-VG-150", "SAE 30"])
def test_presets_by_name(name):
    oil = Lubricant.preset(name)
    assert 0.01 < oil.dynamic_viscosity(40.0) < 0.2


def test_unknown_preset():
    with pytest.raises(InputError) as error:
        Lubricant.preset("olive oil")
    assert error.value.field == "name"


def test_viscosity_must_fall_with_temperature():
    with pytest.raises(InputError):
        Lubricant.from_two_points("bad", 40.0, 10e-6, 100.0, 20e-6)


@pytest.mark.parametrize(
    "call, field",
    [
        (lambda: Lubricant.constant(0.0), "viscosity"),
        (lambda: Lubricant.constant(0.02, density=-1.0), "density"),
        (lambda: Lubricant.from_two_points("x", 40.0, 68e-6, 40.0, 8.7e-6), "temperature_2"),
        (lambda: Lubricant.from_two_points("x", 40.0, -68e-6, 100.0, 8.7e-6), "kinematic_viscosity_1"),
        (lambda: Lubricant.from_two_points("x", 40.0, 10e-6, 100.0, 20e-6), "kinematic_viscosity_2"),
        (lambda: Lubricant.from_two_points("x", 40.0, 68e-6, 100.0, 8.7e-6, density_15=0.0), "density_15"),
    ],
)
def test_bad_lubricant_input_names_the_parameter(call, field):
    """Errors name the parameter of the call that checks it; a case reader adds its own path."""
    with pytest.raises(InputError) as error:
        call()
    assert error.value.field == field
