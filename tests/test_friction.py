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
