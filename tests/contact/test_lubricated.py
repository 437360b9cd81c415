"""The chain in one call: broadcasting gives what point-by-point evaluation gives."""

import numpy as np
import pytest

from shaftline.contact.lubricated import ContactModel, Surfaces, evaluate
from shaftline.contact.rheology import contact_lubricant
from shaftline.errors import InputError

SURFACES = Surfaces(roughness_1=0.5e-6, roughness_2=0.125e-6)


@pytest.mark.parametrize("geometry", ["line", "point"])
def test_broadcast_equals_point_by_point(geometry):
    model = ContactModel(contact_lubricant("iso vg 100"), geometry)
    load = (np.array([2e5, 5e5]) if geometry == "line" else np.array([200.0, 800.0]))[:, None, None]
    speed = np.array([2.0, 10.0, 30.0])[None, :, None]
    radius = np.array([0.008, 0.02])[None, None, :]
    kwargs = {"radius_y": radius * 5.0} if geometry == "point" else {}
    state = evaluate(model, SURFACES, load, speed, speed * 1.2, 70.0, radius, **kwargs)
    assert state.friction.shape == (2, 3, 2)
    for i, j, k in np.ndindex(2, 3, 2):
        one = evaluate(
            model,
            SURFACES,
            float(load[i, 0, 0]),
            float(speed[0, j, 0]),
            float(speed[0, j, 0]) * 1.2,
            70.0,
            float(radius[0, 0, k]),
            **({"radius_y": float(radius[0, 0, k]) * 5.0} if geometry == "point" else {}),
        )
        for name in ("peak_pressure", "central_film", "film_ratio", "friction", "power_intensity"):
            assert float(getattr(one, name)) == pytest.approx(float(getattr(state, name)[i, j, k]), rel=1e-12)


def test_pure_rolling_has_no_sliding_friction_power():
    model = ContactModel(contact_lubricant("mil-prf-23699"))
    state = evaluate(model, SURFACES, 3e5, 20.0, 20.0, 90.0, 0.012)
    assert float(state.thermal_correction) == 1.0 and float(state.power_intensity) == 0.0
    assert float(state.full_film_friction) == 0.0  # no shear without sliding (Eq. 5)


def test_film_grows_with_speed_and_viscosity():
    # isothermal films follow U^0.69: 10 times the speed gives 10^0.69 = 4.9 times the film
    model = ContactModel(contact_lubricant("iso vg 100"), thermal_method="none")
    slow = evaluate(model, SURFACES, 3e5, 1.0, 1.0, 60.0, 0.012)
    fast = evaluate(model, SURFACES, 3e5, 10.0, 10.0, 60.0, 0.012)
    assert float(fast.central_film / slow.central_film) == pytest.approx(10**0.69, rel=1e-9)
    cold = evaluate(model, SURFACES, 3e5, 1.0, 1.0, 40.0, 0.012)
    assert float(cold.central_film) > float(slow.central_film)


def test_rolling_speed_must_be_positive():
    model = ContactModel(contact_lubricant("iso vg 100"))
    with pytest.raises(InputError, match="rolling_speed"):
        evaluate(model, SURFACES, 3e5, 1.0, -1.0, 60.0, 0.012)


@pytest.mark.parametrize("geometry", ["line", "point"])
def test_full_film_friction_divides_by_the_contacts_own_mean_pressure(geometry):
    # Seed 002 Eq. 3 defines f_c = tau / p_m and estimates p_m = 2 p_H/3 "for elliptical contacts such
    # as crowned gear teeth"; a line contact's mean Hertz pressure is pi p_H/4 (Johnson Eq. 4.43-4.45).
    # f_c must be the Bair-Winer stress (Eq. 4, eta and tau_L at p_m) over the p_m of the geometry
    # evaluated: pi/4 p_H (line), 2/3 p_H (point), to round-off.
    lub = contact_lubricant("mil-prf-23699")
    model = ContactModel(lub, geometry, extrapolate=True)
    kwargs = {"radius_y": 0.1} if geometry == "point" else {}
    load = 3e5 if geometry == "line" else 500.0
    state = evaluate(model, SURFACES, load, 5.0, 45.0, 90.0, 0.012, **kwargs)
    p_m = float(state.mean_pressure)
    assert p_m / float(state.peak_pressure) == pytest.approx(np.pi / 4 if geometry == "line" else 2 / 3, rel=1e-12)
    tau_l = float(lub.limiting_shear_stress(p_m))
    eta = float(lub.viscosity_at(p_m, 90.0, "roelands"))
    rate = abs(float(state.sliding_speed)) / float(state.central_film)
    expected = tau_l * (1 - np.exp(-eta * rate / tau_l)) / p_m
    assert float(state.full_film_friction) == pytest.approx(expected, rel=1e-12)
