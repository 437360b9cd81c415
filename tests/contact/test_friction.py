"""Seed 002 friction (Eq. 1-6) as read in docs/theory.md Sect. 15.4: the checks that support
the reading."""

import numpy as np
import pytest

from shaftline.contact import friction
from shaftline.errors import InputError


def test_load_sharing_shape_and_limit():
    # Seed 002 Fig. 1: g rises to 1 at Lambda = 2, exceeds it slightly just beyond and falls;
    # hence g := 1 above 2. Found: g(2) = 0.99971, the crossing at 2.0126, the peak 1.0026 at 2.26.
    lam = np.linspace(0.0, 2.0, 2001)
    g = friction.load_sharing(lam)
    assert np.all(np.diff(g) > 0)
    assert float(g[-1]) == pytest.approx(1.0, abs=5e-4)
    raw = 1.21 * np.linspace(2.0, 3.0, 1001) ** 0.64 / (1 + 0.37 * np.linspace(2.0, 3.0, 1001) ** 1.26)
    assert 1.0 < raw.max() < 1.005
    assert np.all(friction.load_sharing(np.array([2.01, 5.0, 50.0])) == 1.0)
    with pytest.raises(InputError, match="film_ratio"):
        friction.load_sharing(-0.1)


def test_mixed_friction_is_continuous_at_full_film():
    # f_a jumps at Lambda = 2 by at most (1 - g(2)) |f_b - f_c| = 3e-4 x 0.1.
    below = friction.mixed_friction(0.03, 0.1, 2.0 - 1e-9)
    above = friction.mixed_friction(0.03, 0.1, 2.0 + 1e-9)
    assert abs(float(below - above)) < 3e-5
    assert float(friction.mixed_friction(0.03, 0.1, 0.0)) == pytest.approx(0.1)


def test_full_film_friction_limits():
    # Eq. 3 and 5: Newtonian eta S u / (h p_m) at low shear; tau_L / p_m at high (p_m = 2/3 GPa here,
    # the seed's elliptical contact at p_H = 1 GPa).
    p_m = 2e9 / 3
    f_low = friction.full_film_friction(5e7, 0.01, 10.0, 0.01, 1e-6, p_m)
    assert float(f_low) == pytest.approx(0.01 * 0.01 * 10.0 / (1e-6 * p_m), rel=1e-3)
    f_high = friction.full_film_friction(5e7, 1e4, 10.0, 0.5, 1e-6, p_m)
    assert float(f_high) == pytest.approx(1.5 * 5e7 / 1e9, rel=1e-12)


def test_thermal_correction_is_continuous_at_the_traction_peak():
    # The reading of Eq. 6 (c = (0.39 - 0.28 ln X) S^-(0.088 ln X + 0.220), X in Pa s GPa m/s)
    # gives c(S_m) = 1 within 8 % over X = 0.1-1.8 (found: 0.998 to 1.075) - the check that
    # supports the reading and its units; other sign readings or X in Pa s MPa m/s miss by far.
    # The code's c just beyond S_m (where Eq. 6 applies), not a copy of the formula.
    x = np.linspace(0.1, 1.8, 200)
    c_at_peak = friction.thermal_correction(x, friction.peak_slide_roll(x) * (1.0 + 1e-9))
    assert np.all(np.abs(c_at_peak - 1.0) < 0.08)
    assert np.abs(c_at_peak - 1.0).max() > 0.05  # the 7.5 % found: the branch beyond S_m was taken
    # c falls as sliding grows beyond the peak (the friction reduction Eq. 6 models)
    s = np.linspace(0.2, 2.0, 50)
    for value in (0.2, 0.5, 1.0, 1.8):
        c = friction.thermal_correction(value, s)
        assert np.all(np.diff(c[s > friction.peak_slide_roll(value)]) < 0)
    assert float(friction.thermal_correction(0.5, 0.5 * float(friction.peak_slide_roll(0.5)))) == 1.0


def test_thermal_correction_validity():
    with pytest.raises(
        InputError,
        match=r"eta0 p_H u \(oil viscosity x peak Hertz pressure x rolling speed\) = 5 Pa s GPa m/s: "
        r"allowed in \[0.1, 1.8\]",
    ):
        friction.thermal_correction(5.0, 1.0)
    with pytest.warns(UserWarning, match="extrapolated"):
        c = friction.thermal_correction(5.0, 1.0, extrapolate=True)
    assert 0.0 <= float(c) <= 1.0
    # below S_m the fit range does not matter (c = 1)
    assert float(friction.thermal_correction(0.01, 0.5)) == 1.0


def test_seed_friction_regimes():
    # Boundary friction when the film is gone, c f_c in full film.
    kwargs = dict(
        boundary=0.1,
        limiting_stress=6e7,
        viscosity_at_pressure=50.0,
        viscosity=0.01,
        rolling_speed=20.0,
        slide_roll=0.3,
        central_film=4e-7,
        peak_pressure=1e9,
        mean_pressure=np.pi / 4 * 1e9,
    )
    dry = friction.seed_friction(film_ratio=0.0, **kwargs)
    assert float(dry.coefficient) == pytest.approx(0.1 * float(dry.thermal))
    wet = friction.seed_friction(film_ratio=3.0, **kwargs)
    assert float(wet.coefficient) == pytest.approx(float(wet.full_film * wet.thermal))


def test_errors_on_arrays_quote_the_offending_value():
    # the first element is fine: the message must quote the bad one (it quoted the first)
    with pytest.raises(InputError, match=r"film_ratio = -0.5: allowed >= 0"):
        friction.load_sharing(np.array([1.0, -0.5, 2.0]))
    with pytest.raises(InputError, match=r"film_ratio = nan"):
        friction.load_sharing(np.array([1.0, np.nan]))
    with pytest.raises(InputError, match=r"eta0 p_H u = -1 Pa s GPa m/s"):
        friction.thermal_correction(np.array([0.3, -1.0]), 0.5)
