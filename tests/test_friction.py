"""Friction laws (seed 000 Sect. 4.4) and the friction experiment (Sect. 4.3, Appendix B).

The experiment: a 2800 kg body (27 kN normal load), mu = 0.1, tangential force rising at
0.003 N/s per N of normal load. With the LuGre parameters of Table 4.1 as printed the model
breaks away at 22.6 um; the seed's Fig. 4.17 reports about 140 um. The seed's own Eq. 4.28
(bristle deflection F_c / sigma_0 = 2.7 um) confirms sigma_0 = 1e9 N/m, and the LuGre
break-away displacement is a small multiple of that bristle length, so we could not
reproduce 140 um (it would take sigma_0 of about 1.2e8 N/m); docs/validation.md records it.
The tests check what the seed states and we can reproduce.
"""

from __future__ import annotations

import numpy as np
import pytest

from shaftline.friction import LuGre, coulomb, finite_slope, karnopp, simulate_block, stribeck

MASS, MU, G = 2800.0, 0.1, 9.80665
COULOMB = MU * MASS * G
RATE = 0.003 * MASS * G


def test_static_laws():
    v = np.array([-1.0, -1e-4, 0.0, 1e-4, 1.0])
    assert np.allclose(coulomb(v, 10.0), [-10, -10, 0, 10, 10])
    assert stribeck(0.0, 10.0, 11.0, 0.01) == pytest.approx(11.0)
    assert stribeck(1.0, 10.0, 11.0, 0.01) == pytest.approx(10.0)
    # Eq. 4.8: linear through zero inside the threshold, Coulomb outside
    assert np.allclose(finite_slope(v, 10.0, 1e-3), [-10, -1, 0, 1, 10])
    # Karnopp: sticks inside the threshold, balancing the external force up to F_s
    assert np.allclose(karnopp([0.0, 0.0, 0.5], [5.0, 20.0, 5.0], 10.0, 11.0, 1e-3), [5.0, 11.0, 10.0])


def test_lugre_table_4_1_bristle_deflection_eq_4_28():
    model = LuGre.table_4_1(2700.0)
    assert model.bristle_deflection == pytest.approx(2.7e-6)


def test_rotational_rescaling_sect_4_6_1():
    """Same bristle deflection in rotation, v_s / r: for a mean design Coulomb torque that gives
    sigma_0 = 5e10 N m/rad (Table 4.2) at r = 0.392 m, the torque is 5e10 * 2.7 um / 0.392 m."""
    translating = LuGre.table_4_1(2700.0)
    torque = 5e10 * 2.7e-6 / 0.392
    rotating = LuGre.rotational(translating, 0.392, torque, damping=1e8)
    assert rotating.stiffness == pytest.approx(5e10)
    assert rotating.stribeck_velocity == pytest.approx(0.0008 / 0.392)  # 0.002 rad/s in Table 4.2
    assert rotating.static_force / rotating.coulomb_force == pytest.approx(1.1)


@pytest.fixture(scope="module")
def experiment():
    return simulate_block(LuGre.table_4_1(COULOMB), MASS, lambda t: RATE * t, 1.15 * 1.1 * COULOMB / RATE)


def test_experiment_breaks_away_at_the_static_force(experiment):
    _, _, force = experiment.breakaway()
    assert force == pytest.approx(1.1 * COULOMB, rel=0.01)
    # gross sliding follows at the Coulomb level
    assert experiment.friction[-1] == pytest.approx(COULOMB, rel=0.01)
    assert experiment.velocity[-1] > 1e-2


def test_experiment_pre_sliding_displacement(experiment):
    """Pre-sliding before break-away: a few bristle lengths with Table 4.1 (22.6 um; the seed's
    figure says 140 um, see the module docstring), far below gross sliding."""
    _, displacement, _ = experiment.breakaway()
    assert 5 * 2.7e-6 < displacement < 15 * 2.7e-6
    assert displacement == pytest.approx(22.6e-6, rel=0.05)


def test_appendix_b_sensitivities():
    """Appendix B: 'an increase of sigma_0 reduces the pre-sliding displacement while an
    increase of v_s increases it'."""

    def presliding(**change):
        base = dict(
            stiffness=1e9,
            damping=4e5,
            viscous=0.0,
            coulomb_force=COULOMB,
            static_force=1.1 * COULOMB,
            stribeck_velocity=0.0008,
        )
        model = LuGre(**{**base, **change})
        return simulate_block(model, MASS, lambda t: RATE * t, 1.15 * 1.1 * COULOMB / RATE, 800).breakaway()[1]

    reference = presliding()
    assert presliding(stiffness=3e9) < reference < presliding(stiffness=3e8)
    assert presliding(stribeck_velocity=0.008) > reference


def test_public_laws_keep_their_closed_forms():
    """The public laws now run the compiled kernels; they must still be the formulas of
    Eq. 4.13-4.15 and 4.7 written out in numpy here (float64 round-off, rel 1e-14)."""
    rng = np.random.default_rng(7)
    v = rng.normal(scale=2e-3, size=50)
    z = rng.normal(scale=3e-6, size=50)
    g = 2700.0 + 270.0 * np.exp(-((np.abs(v) / 0.0008) ** 2))
    assert np.allclose(stribeck(v, 2700.0, 2970.0, 0.0008), g, rtol=1e-14, atol=0)
    model = LuGre.table_4_1(2700.0)
    assert np.allclose(model.state_rate(z, v), v - 1e9 * np.abs(v) / g * z, rtol=1e-12, atol=1e-18)
    ramp = np.where(np.abs(v) > 1e-3, np.sign(v), v / 1e-3)
    assert np.allclose(finite_slope(v, 2700.0, 1e-3, 2970.0, 0.0008, 5.0), ramp * g + 5.0 * v, rtol=1e-14, atol=0)
    # scalars in, numpy scalars out; shapes follow the input
    assert isinstance(stribeck(1e-3, 2700.0, 2970.0, 0.0008), np.floating)
    assert model.state_rate(z.reshape(5, 10), v.reshape(5, 10)).shape == (5, 10)
    assert model.state_rate(1e-6, v).shape == v.shape


@pytest.mark.parametrize("velocity", [-3e-3, -1e-3, -2e-4, 1e-5, 4e-4, 8e-4, 2e-3])
def test_kernel_derivatives_match_finite_differences(velocity):
    """The partial derivatives the implicit integrators use (Stribeck slope, LuGre bristle rate,
    finite-slope law) against central differences; step 1e-6 relative, so the truncation
    error (1e-12 relative) and round-off (1e-10 relative) stay far below the 1e-6 tolerance."""
    from shaftline.friction import kernels as k

    f_c, f_s, v_s, sigma_0, v_th = 2700.0, 2970.0, 0.0008, 1e9, 1e-4
    h = 1e-6 * abs(velocity)

    def level(v):
        return k.stribeck_level(v, f_c, f_s, v_s)

    slope = k.stribeck_level_slope(velocity, f_c, f_s, v_s)
    assert slope == pytest.approx((level(velocity + h) - level(velocity - h)) / (2 * h), rel=1e-6, abs=1e-3)
    z = 0.7 * f_c / sigma_0

    def rate(z_, v):
        return k.lugre_state_rate(z_, v, sigma_0, level(v))

    d_dz, d_dv = k.lugre_state_rate_partials(z, velocity, sigma_0, level(velocity), slope)
    hz = 1e-6 * z
    assert d_dz == pytest.approx((rate(z + hz, velocity) - rate(z - hz, velocity)) / (2 * hz), rel=1e-6)
    assert d_dv == pytest.approx((rate(z, velocity + h) - rate(z, velocity - h)) / (2 * h), rel=1e-6, abs=1e-9)

    def law(v):
        return k.finite_slope_force(v, level(v), v_th)

    law_slope = k.finite_slope_force_slope(velocity, level(velocity), slope, v_th)
    assert law_slope == pytest.approx((law(velocity + h) - law(velocity - h)) / (2 * h), rel=1e-6, abs=1e-3)


def test_importing_the_laws_is_cheap():
    """numba and scipy load on first use, not on import (the command line starts in < 0.5 s)."""
    import os
    import subprocess
    import sys
    from pathlib import Path

    import shaftline

    code = (
        "import sys, shaftline.friction, shaftline.friction.models; "
        "print(sorted({m.split('.')[0] for m in sys.modules} & {'numba', 'scipy'}))"
    )
    # the same sources as this test process, whatever is installed
    env = {**os.environ, "PYTHONPATH": str(Path(shaftline.__file__).parents[1])}
    result = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True, env=env)
    assert result.stdout.strip() == "[]"
