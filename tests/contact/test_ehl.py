"""EHL film formulas against second, independent sources (docs/validation.md, Sect.
"Lubricated contacts")."""

import numpy as np
import pytest

from shaftline.contact import ehl
from shaftline.errors import InputError

GRID = np.meshgrid(np.logspace(-12, -10, 9), np.linspace(2000, 6000, 5), np.logspace(np.log10(5e-5), np.log10(5e-4), 7))


def test_dowson_toyoda_and_moes_agree_in_the_ehl_range():
    # Moes (1992) fitted other numerical solutions than Dowson & Toyoda (1979): over
    # U 1e-12..1e-10, G 2000..6000, W' 5e-5..5e-4 (gears, rollers) their central films differ by
    # -7.0 % to +6.6 %; 10 % is the scatter of such fits against numerical EHL solutions.
    u, g, w = GRID
    dt, _ = ehl.dowson_toyoda(u, g, w)
    moes, _ = ehl.moes(u, g, w)
    assert np.abs(moes / dt - 1).max() < 0.10


def test_moes_as_a_second_public_transcription_states_it():
    # Gelinck & Schipper's (2000) mixed-lubrication form of Moes' line-contact central film, as a public
    # gear code states it (github.com/Konglingyu1997/Mixed-lubrication-Helical-gear, README.md: groups
    # M = W' Us^-1/2, L = G Us^1/4 with Us = eta0 (u1 + u2)/(E' R), the same four asymptotes, and
    # s = (7 + 8 exp(-2 gamma^-0.4 H_EI/H_RI))/5) reduces to Moes' with the film carrying all the load,
    # gamma = 1. Written out here with gamma kept, it must equal ehl.moes to round-off everywhere, in the
    # rigid, transition and EHL regimes (the point contact's s = 3/2 (1 + exp(-1.2 H_EI/H_RI)), used
    # before, differs by up to 7 % in the transitions).
    gamma = 1.0
    u = np.logspace(-13, -8, 11)[:, None, None]
    w = np.logspace(-7, -3, 9)[None, :, None]
    g = np.array([0.0 + 1e-9, 500.0, 5000.0])[None, None, :]
    us = 2 * u  # eta0 (u1 + u2)/(E' R) from U on the mean speed
    m, lam = w * us**-0.5, g * us**0.25
    ri, ei, rp, ep = 3 / m, 2.621 * m**-0.2, 1.287 * lam ** (2 / 3), 1.311 * m**-0.125 * lam**0.75
    s = (7 + 8 * np.exp(-2 * gamma**-0.4 * ei / ri)) / 5
    h = (
        (
            gamma ** (s / 2) * (ri ** (7 / 3) + gamma ** (-14 / 15) * ei ** (7 / 3)) ** (3 * s / 7)
            + gamma ** (-s / 2) * (rp**-3.5 + ep**-3.5) ** (-2 * s / 7)
        )
        ** (1 / s)
        * gamma**0.5
        * us**0.5
    )
    central, minimum = ehl.moes(u, g, w)
    np.testing.assert_allclose(central, h, rtol=1e-12)
    assert np.all(np.isnan(minimum))


def test_line_regime_map_from_moes_asymptotes():
    # Deep inside each regime the blended film is its asymptote (within 5 %) and the map names it;
    # in M = W'(2U)^-1/2, L = G(2U)^1/4: light load isoviscous (M 0.01, L 0), heavy isoviscous
    # (M 1e3, L 0), light load piezoviscous (M 0.01, L 1e4), heavy piezoviscous (M 1e3, L 20).
    u = 1e-10
    cases = {
        "rigid-isoviscous": (1e-2, 1e-9, lambda m, lam: 3 / m),
        "elastic-isoviscous": (1e3, 1e-9, lambda m, lam: 2.621 * m**-0.2),
        "rigid-piezoviscous": (1e-2, 1e4, lambda m, lam: 1.287 * lam ** (2 / 3)),
        "elastic-piezoviscous": (1e3, 20.0, lambda m, lam: 1.311 * m**-0.125 * lam**0.75),
    }
    for name, (m, lam, asymptote) in cases.items():
        w, g = m * np.sqrt(2 * u), lam / (2 * u) ** 0.25
        central, _ = ehl.moes(u, g, w)
        assert float(central) / (asymptote(m, lam) * np.sqrt(2 * u)) == pytest.approx(1.0, abs=0.05), name
        assert ehl.REGIMES[int(ehl.line_regime(u, g, w))] == name
    # the seed 002 gear flank (contact_ehl.toml: 300 N/mm, Rx 12 mm, 5.9 mPa s, 25.1 m/s, alpha 1.04e-8)
    # and a line-contact elastomer seal (E' 10 MPa, 1 N/mm, R 5 mm, 0.05 Pa s, 1 m/s) fall where the
    # textbooks place them
    e, rx = 226.4e9, 11.97e-3
    gear = ehl.line_regime(5.9e-3 * 25.07 / (e * rx), 1.04e-8 * e, 3e5 / (e * rx))
    assert ehl.REGIMES[int(gear)] == "elastic-piezoviscous"
    e, rx = 1e7, 5e-3
    seal = ehl.line_regime(0.05 * 1.0 / (e * rx), 2e-8 * e, 1e3 / (e * rx))
    assert ehl.REGIMES[int(seal)] == "elastic-isoviscous"


def _martin_and_blok():
    """Rigid cylinder on a plane with the Reynolds condition, solved here by quadrature:
    dP/dX = (X^2 - Xe^2)/(1 + X^2)^3, P(-inf) = P(Xe) = 0. Load gives Martin's
    h0 = C_M eta u R / w' (C_M = 24 int P dX); the largest reduced pressure 1/alpha gives Blok's
    h0 = C_B (alpha eta u)^(2/3) R^(1/3) (C_B = (12 sqrt(2) P(-Xe))^(2/3)); u is the mean speed."""
    from scipy.integrate import quad
    from scipy.optimize import brentq

    def slope(x, xe):
        return (x**2 - xe**2) / (1 + x**2) ** 3

    xe = brentq(lambda xe: quad(slope, -np.inf, xe, args=(xe,))[0], 0.1, 1.0)
    load = quad(lambda x: (xe - x) * slope(x, xe), -np.inf, xe)[0]
    peak = quad(slope, -np.inf, -xe, args=(xe,))[0]
    return 24 * load, (12 * np.sqrt(2) * peak) ** (2 / 3)


def test_rigid_limits_martin_and_blok():
    # The classical rigid solutions come out of the quadrature: Martin (1916) 4.9, Blok (1952) 1.66.
    martin, blok = _martin_and_blok()
    assert martin == pytest.approx(4.9, abs=0.01)
    assert blok == pytest.approx(1.66, abs=0.01)


def test_moes_rigid_asymptotes_against_martin_and_blok():
    # Moes' rigid asymptotes, in the groups as implemented (U on the mean speed), are
    # sqrt(3/2) times Martin's and Blok's films: 6.0 against 4.895 and 2.043 against 1.666
    # (docs/theory.md Sect. 15.2 records this as an open point: use Moes in the EHL range,
    # where it agrees with Dowson-Toyoda). 1 % at M = 1e-4 (rigid-isoviscous, G = 0+) and
    # M = 1e-2, L = 1e8 (rigid-piezoviscous: H_RI and H_EP negligible beside H_RP).
    martin, blok = _martin_and_blok()
    u = 1e-10
    w = 1e-4 * np.sqrt(2 * u)
    central, _ = ehl.moes(u, 1e-9, w)
    assert float(central) / (martin * u / w) == pytest.approx(np.sqrt(1.5), rel=0.01)
    g = 1e8 / (2 * u) ** 0.25
    w = 1e-2 * np.sqrt(2 * u)
    central, _ = ehl.moes(u, g, w)
    assert float(central) / (blok * (g * u) ** (2 / 3)) == pytest.approx(np.sqrt(1.5), rel=0.01)


def test_point_formulas_against_their_regime_map_refits():
    # Hamrock & Dowson (1981) refitted the elastic-piezoviscous and elastic-isoviscous minimum films
    # in the regime-map variables: 3.42 gV^0.49 gE^0.17 and 8.70 gE^0.67 give the 1977/1978 formulas
    # within 2 % and 8 % (different exponents); a slip in a constant shows.
    for k in (1.0, 3.0, 6.0):
        for u, w in ((1e-11, 1e-6), (1e-12, 1e-5)):
            g_e = w ** (8 / 3) / u**2
            g_v = 5000.0 * w**3 / u**2
            _, h_ev = ehl.hamrock_dowson(u, 5000.0, w, k)
            _, h_ei = ehl.hamrock_dowson_soft(u, 0.0, w, k)
            ev = 3.42 * g_v**0.49 * g_e**0.17 * (1 - np.exp(-0.68 * k)) * (u / w) ** 2
            ei = 8.70 * g_e**0.67 * (1 - 0.85 * np.exp(-0.31 * k)) * (u / w) ** 2
            assert ev / h_ev == pytest.approx(1.0, abs=0.02)
            assert ei / h_ei == pytest.approx(1.0, abs=0.08)


def test_point_regime_map_places_known_contacts():
    # Textbook placements (Hamrock 1994 Ch. 22; Hamrock, Schmid & Jacobson, Fundamentals of Machine
    # Elements): rolling-bearing and gear contacts of steel are elastic-piezoviscous, elastomer
    # contacts elastic-isoviscous, lightly loaded fast contacts rigid-isoviscous. With Hamrock &
    # Dowson's earlier rigid-piezoviscous formula 1.66 gV^(2/3) the ball below fell on the
    # rigid-piezoviscous side; the Esfahanian & Hamrock (1991) revision places it as the books do.
    def regime(u, g, w, k):
        return ehl.REGIMES[int(ehl.point_regime(u, g, w, k)[0])]

    # steel ball on an inner race: 1 kN, Rx 5 mm, 0.05 Pa s, 10 m/s, alpha 2e-8, E' 230 GPa
    e, rx = 2.3e11, 5e-3
    assert regime(0.05 * 10 / (e * rx), 2e-8 * e, 1000 / (e * rx**2), 6.0) == "elastic-piezoviscous"
    # a crowned gear flank: 200 N, Rx 12 mm, 0.006 Pa s, 70 m/s, alpha 1e-8
    rx = 12e-3
    assert regime(0.006 * 70 / (e * rx), 1e-8 * e, 200 / (e * rx**2), 4.0) == "elastic-piezoviscous"
    # an elastomer seal lip on a shaft: E' 10 MPa, 1 N, Rx 10 mm, 0.05 Pa s, 1 m/s
    e, rx = 1e7, 1e-2
    assert regime(0.05 * 1 / (e * rx), 2e-8 * e, 1.0 / (e * rx**2), 1.0) == "elastic-isoviscous"
    # a lightly loaded fast steel contact: W = 1e-10, U = 1e-8
    assert regime(1e-8, 5000.0, 1e-10, 1.0) == "rigid-isoviscous"


def test_point_regime_film_is_continuous():
    # Boundaries are where neighbouring formulas agree: the map's film has no jump along a sweep.
    u = 1e-11
    w = np.logspace(-8, -3, 4001)
    _, h = ehl.point_regime(u, 5000.0, w, 2.0)
    # the steepest formula goes as W^-2 (rigid-isoviscous): a step in ln W moves ln h by at most
    # twice the step; a jump at a boundary would exceed it
    step = np.log(w[1] / w[0])
    assert np.abs(np.diff(np.log(h))).max() < 2.0 * step * 1.001


def test_gupta_reduces_to_murch_wilson_in_pure_rolling():
    # Two independent thermal reductions: Gupta et al. (1992) at S = 0 and small p0/E' against
    # Murch & Wilson (1975): within 2.5 % for L = 0.01-5 (found); 5 % allowed.
    loading = np.logspace(-2, np.log10(5.0), 30)
    ratio = ehl.gupta(loading, 0.0, 0.003) / ehl.murch_wilson(loading)
    assert np.abs(ratio - 1).max() < 0.05
    # sliding reduces the film further (Gupta: the (1 + 2.23 S^0.83) term)
    assert np.all(ehl.gupta(loading, 0.5, 0.003) < ehl.gupta(loading, 0.0, 0.003))


def test_gupta_beyond_its_positive_range_is_an_input_error():
    # The numerator 1 - 13.2 (p0/E') L^0.42 vanishes at L = (13.2 p0/E')^(-1/0.42): 1100 at p0/E' = 0.004.
    # Just below the factor is small and positive; beyond, the fit would give a negative film.
    limit = (13.2 * 0.004) ** (-1 / 0.42)
    assert limit == pytest.approx(1100, rel=1e-3)
    assert 0 < float(ehl.gupta(0.99 * limit, 0.1, 0.004)) < 0.01
    with pytest.raises(
        InputError,
        match=r"thermal loading L = beta eta0 u\^2 / k_f \(from the temperature and the speeds\) = 1111: "
        r"allowed < 1100, where Gupta",
    ):
        ehl.gupta(np.array([1.0, 1.01 * limit]), 0.1, 0.004)
    assert float(ehl.murch_wilson(1.01 * limit)) > 0  # the pure-rolling alternative has no limit


def test_film_ratio_and_roughness():
    assert float(ehl.rq_from_ra(0.4e-6)) == pytest.approx(0.4e-6 * 1.2533, rel=1e-4)
    with pytest.raises(InputError, match="roughness"):
        ehl.film_ratio(1e-6, 0.0, 0.0)
    with pytest.raises(InputError, match="film_method"):
        ehl.method(ehl.LINE_FILM_METHODS, "grubin", "film_method")


def test_hamrock_dowson_reproduces_a_published_worked_answer():
    # A textbook exercise with its printed answer (quoted at https://tutorbin.com/questions-and-answers/
    # a-steel-ball-starts-rolling-from-rest-down-a-steel-plate-inclined-at-4; the book is not named there, its
    # data and conventions are Stachowiak & Batchelor's, Engineering Tribology): a steel ball, d 30 mm, rho 7800,
    # E 210 GPa, nu 0.3, rolls from rest down a plate at 45 deg through oil of 50 cP, alpha 2.2e-8 1/Pa;
    # the minimum film after 1 cm and 1 m is 0.059 and 0.281 um. Worked here: load m g cos 45 (0.765 N),
    # rolling speed sqrt(2 a s) with a = 5/7 g sin 45 (a rolling sphere). The answer is reproduced with
    # Hamrock & Dowson's minimum-film formula taken in the book's conventions: the reduced radius
    # 1/R' = 1/Rx + 1/Ry (7.5 mm) in U, W and H, the entraining speed (U_A + U_B)/2 with the plate at
    # rest and the ball's surface at the rolling speed, and k = 1.0339 (its fit at Ry/Rx = 1).
    # Tolerance 1 %: the answer is printed to 2-3 figures (0.059 +- 0.0005 is 0.85 %). Found: 0.0587,
    # 0.2812. A slip in a constant or exponent of the formula (3.63, 0.68, 0.49, -0.073, 0.68) shows:
    # the two answers fix the speed exponent (ratio 100^0.34) and the level.
    e_reduced = 2.1e11 / (1 - 0.3**2)
    radius = 0.015 / 2  # R' of a ball (R = 15 mm) on a flat
    mass = 7800 * 4 / 3 * np.pi * 0.015**3
    load = mass * 9.81 * np.cos(np.pi / 4)
    accel = 5 / 7 * 9.81 * np.sin(np.pi / 4)
    for distance, answer in ((0.01, 0.059e-6), (1.0, 0.281e-6)):
        speed = np.sqrt(2 * accel * distance) / 2
        u = ehl.speed_parameter(0.05, speed, e_reduced, radius)
        g = ehl.material_parameter(2.2e-8, e_reduced)
        w = ehl.point_load_parameter(load, e_reduced, radius)
        _, h_min = ehl.hamrock_dowson(u, g, w, 1.0339)
        assert float(h_min) * radius == pytest.approx(answer, rel=0.01)


def test_moes_blend_exponent_is_minus_two_s_over_seven():
    # Issue 14 (b) quotes the blend as (H_RP^-7/2 + H_EP^-7/2)^(-s/7); the code has -2s/7. The check that
    # decides: H^s = A + B must give H = H_EP deep in the elastic-piezoviscous regime, i.e. B = H_EP^s,
    # and (H_EP^-7/2)^(-2s/7) = H_EP^s while (H_EP^-7/2)^(-s/7) = H_EP^(s/2) (dimensionally another power).
    # At M = 1e3, L = 20 the coded blend is H_EP within 5 %; the -s/7 variant misses it by a factor.
    u = 1e-10
    m, lam = 1e3, 20.0
    w, g = m * np.sqrt(2 * u), lam / (2 * u) ** 0.25
    h_ri, h_rp, h_ei, h_ep, root = ehl._moes_asymptotes(u, g, w)
    s = (7 + 8 * np.exp(-2 * h_ei / h_ri)) / 5
    iso = (h_ri ** (7 / 3) + h_ei ** (7 / 3)) ** (3 * s / 7)
    coded = (iso + (h_rp**-3.5 + h_ep**-3.5) ** (-2 * s / 7)) ** (1 / s)
    quoted = (iso + (h_rp**-3.5 + h_ep**-3.5) ** (-s / 7)) ** (1 / s)
    central, _ = ehl.moes(u, g, w)
    assert float(central) == pytest.approx(float(coded * root), rel=1e-12)
    assert float(coded / h_ep) == pytest.approx(1.0, abs=0.05)
    assert abs(float(quoted / h_ep) - 1.0) > 0.3
