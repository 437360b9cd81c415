"""The bonded elastic layer's surface compliance (film/layer.py) against its references.

Each check names its reference and tolerance (docs/theory.md Sect. 17, "Elastic layer"):
(0) the closed form against an independent solution of the layer's plane-strain equations
(state-space ODE of the layer, matrix exponential); (a) the thin-layer limit: the column model
of film/liner.py; (b) the thick-layer limit: Love's (1929) closed form of a uniform pressure on a
rectangle on a half-space (Johnson 1985, Eq. 3.25); (c) an intermediate thickness against an
independent numerical route (Love's half-space value plus a quadrature of the layer's smooth
correction to it over the Fourier plane): no published table of a bonded layer's surface
deflection was reachable, so this checks the FFT discretisation against an exact integral of the
same (independently checked) closed form.
"""

from __future__ import annotations

import numpy as np
import pytest
import scipy.linalg as sl
from scipy import integrate

from shaftline.film.layer import layer_compliance, layer_factor, layer_operator
from shaftline.film.liner import Liner, constrained_modulus


def _state_space_compliance(k: float, t: float, modulus: float, nu: float) -> float:
    """Surface deflection per unit pressure of one plane wave cos(kx) on a layer bonded at
    y = 0 and loaded at y = t, from the layer's equations themselves: the state (U, V, S, T) of
    u_x = U sin kx, u_y = V cos kx, s_xy = S sin kx, s_yy = T cos kx obeys Hooke's law and
    equilibrium, y' = A y, integrated by the matrix exponential from the bond (U = V = 0) to the
    free face (S = 0, T = -p)."""
    lam = modulus * nu / ((1 + nu) * (1 - 2 * nu))
    mu = modulus / (2 * (1 + nu))
    l2 = lam + 2 * mu
    a = np.array(
        [
            [0.0, k, 1.0 / mu, 0.0],  # U' = S / mu + k V          (s_xy = mu (U' - k V))
            [-lam * k / l2, 0.0, 0.0, 1.0 / l2],  # V' = (T - lam k U) / (lam + 2 mu)
            [k * k * (l2 - lam * lam / l2), 0.0, 0.0, k * lam / l2],  # S' = k s_xx (x-equilibrium)
            [0.0, 0.0, -k, 0.0],  # T' = -k S                 (y-equilibrium)
        ]
    )
    phi = sl.expm(a * t)
    s0t0 = np.linalg.solve(phi[2:, 2:], np.array([0.0, -1.0]))
    return -float(phi[1, 2:] @ s0t0)


@pytest.mark.parametrize("nu", [0.1, 0.327, 0.45, 0.49])
@pytest.mark.parametrize("s", [0.05, 0.5, 1.0, 2.0, 5.0])
def test_closed_form_solves_the_layer_equations(nu: float, s: float) -> None:
    # Reference: the state-space solution above (no closed form in it). Tolerance 1e-10: both
    # are exact; the matrix exponential's round-off at |k| t <= 5 is below 1e-13.
    t, e = 0.02, 2.32e9
    assert float(layer_compliance(s / t, t, e, nu)) == pytest.approx(
        _state_space_compliance(s / t, t, e, nu), rel=1e-10, abs=0.0
    )


def test_limits_of_the_closed_form() -> None:
    # F -> 1 (half-space, Johnson 1985 Sect. 3.2) for a thick layer, to 4 s^2 e^(-2s) / kappa
    # (7e-15 at s = 20); the column
    # law t / M for a thin one (film/liner.py), to O(s^2) = 1e-8; the incompressible thin layer
    # u^ = k^2 t^3 p^ / (3 G) (Johnson 1985 Sect. 5.9), to O(s^2).
    assert float(layer_factor(20.0, 0.3)) == pytest.approx(1.0, abs=1e-14)
    liner = Liner(0.02, 2.32e9, 0.327)
    assert float(layer_compliance(1e-4 / 0.02, 0.02, 2.32e9, 0.327)) == pytest.approx(
        liner.compliance, rel=1e-8, abs=0.0
    )
    assert float(layer_compliance(0.0, 0.02, 2.32e9, 0.327)) == pytest.approx(liner.compliance, rel=1e-14, abs=0.0)
    t, e = 0.01, 7e6
    g = e / 3.0
    for s in (1e-3, 1e-2):
        k = s / t
        assert float(layer_compliance(k, t, e, 0.5)) == pytest.approx(
            k * k * t**3 / (3 * g), rel=2 * s * s + 1e-9, abs=0.0
        )


def test_thin_layer_is_the_column_model() -> None:
    # (a) Reference: the column (Winkler) model u = p t / M of film/liner.py. A smooth pressure
    # on a bore whose liner is thin against the pressure's wavelengths (t = 1.5 mm, wavelengths
    # >= 0.4 m: s <= 0.03) and zero at the ends; the layer's next term is of relative order
    # s^2 ~ 1e-3, so the tolerance is 2e-3 of the largest deflection.
    nz, nt, radius, length = 61, 96, 0.16, 1.2
    t, e, nu = 0.0015, 2.32e9, 0.327
    z = np.linspace(0.0, length, nz)[:, None]
    theta = np.arange(nt)[None, :] * 2 * np.pi / nt
    pressure = 2e6 * np.sin(np.pi * z / length) ** 2 * (1.0 + np.cos(theta))
    layer = layer_operator((nz, nt), radius, length / (nz - 1), t, e, nu)
    column = pressure * t / constrained_modulus(e, nu)
    u = layer.apply(pressure)
    assert np.abs(u - column).max() < 2e-3 * column.max()


def _love(x: np.ndarray, y: np.ndarray, a: float, b: float, modulus: float, nu: float) -> np.ndarray:
    """Love (1929): surface deflection of a half-space under a unit pressure on |x| <= a,
    |y| <= b (Johnson 1985, Eq. 3.25), (1 - nu^2)/(pi E) times the integral of 1/r over the
    rectangle, whose primitive is X asinh(Y/|X|) + Y asinh(X/|Y|)."""

    def primitive(xx: np.ndarray, yy: np.ndarray) -> np.ndarray:
        with np.errstate(divide="ignore", invalid="ignore"):
            first = np.where(xx != 0, xx * np.arcsinh(yy / np.where(xx != 0, np.abs(xx), 1.0)), 0.0)
            second = np.where(yy != 0, yy * np.arcsinh(xx / np.where(yy != 0, np.abs(yy), 1.0)), 0.0)
        return first + second

    integral = primitive(x + a, y + b) - primitive(x - a, y + b) - primitive(x + a, y - b) + primitive(x - a, y - b)
    return (1 - nu**2) / (np.pi * modulus) * integral


def test_thick_layer_is_loves_half_space() -> None:
    # (b) Reference: Love's closed form of a uniform pressure on a rectangle (12 x 8 cells of
    # 1 mm) on a half-space. The layer is 10 times the grid's period thick, so at every
    # wavenumber but zero F = 1 to e^(-60); its k = 0 mode (the column offset of a finite
    # layer) and the periodic images of the load shift the whole field by a near-constant, so
    # the deflections are compared relative to the node 24 cells from the load. Tolerance 5e-4
    # of the centre deflection: the alias truncation leaves below 3e-4 of a cell's
    # self-compliance, and the images' curvature over the compared region goes as
    # (load / period)^3: 1.5e-3, 1.7e-4, 2.5e-5 of it on periods of 96, 192, 384 cells (measured).
    nz, nt, dx = 128, 192, 1e-3
    radius = nt * dx / (2 * np.pi)
    e, nu = 210e9, 0.3
    layer = layer_operator((nz, nt), radius, dx, 10 * nt * dx, e, nu)
    pressure = np.zeros((nz, nt))
    pressure[20:32, 30:38] = 1e6  # 12 rows (z) by 8 columns (x)
    u = layer.apply(pressure)
    zc, xc = 25.5, 33.5  # centre of the loaded rectangle, in nodes
    z = (np.arange(nz)[:, None] - zc) * dx
    x = (np.arange(nt)[None, :] - xc) * dx
    love = 1e6 * _love(x, z, 4 * dx, 6 * dx, e, nu)
    ref = (int(zc) + 24, int(xc))
    region = (slice(14, 38), slice(24, 44))
    difference = (u - u[ref]) - (love - love[ref])
    centre = love[25, 33] - love[ref]
    assert np.abs(difference[region]).max() < 5e-4 * centre


def test_intermediate_layer_against_quadrature() -> None:
    # (c) Reference: an independent route. The centre deflection of a uniform pressure on a
    # rectangle (15 x 23 cells of 0.5 mm: 7.5 x 11.5 mm) on a layer 4 mm thick (a layer between
    # the limits: 0.31 of the half-space's deflection) is Love's half-space value plus the
    # layer's correction, the inverse Fourier transform of 2(1 - nu^2)/E (F(kt) - 1)/k times
    # the rectangle's transform, integrated by adaptive quadrature in polar wavenumbers up to
    # k t = 40 (the correction decays as e^(-2kt): no aliases, no padding, no FFT). Tolerance
    # 1e-4: the FFT route's alias truncation and periodic images (the layer confines the kernel
    # to a few t; 24 t to the next image) leave 3e-6 here (6e-8 on a grid twice as long).
    nz, nt, dx = 48, 96, 0.5e-3
    radius = nt * dx / (2 * np.pi)
    e, nu, t = 2.32e9, 0.327, 4e-3
    a, b = 7.5 * dx, 11.5 * dx  # half-widths along theta (x) and z
    layer = layer_operator((nz, nt), radius, dx, t, e, nu)
    pressure = np.zeros((nz, nt))
    pressure[12:35, 40:55] = 1e6  # 23 rows, 15 columns centred on node (23, 47)
    fft_centre = float(layer.apply(pressure)[23, 47])

    def correction(k: float) -> float:
        def transform(phi: float) -> float:
            kx, ky = k * np.cos(phi), k * np.sin(phi)
            return 4.0 * np.sinc(kx * a / np.pi) * a * np.sinc(ky * b / np.pi) * b

        ring = 4.0 * integrate.quad(transform, 0.0, 0.5 * np.pi, limit=200, epsabs=0, epsrel=1e-9)[0]
        kernel = 2 * (1 - nu**2) / e * (float(layer_factor(k * t, nu)) - 1.0) / k
        return kernel * k * ring

    corr = 1e6 * integrate.quad(correction, 0.0, 40.0 / t, limit=400, epsabs=0, epsrel=1e-9)[0] / (4 * np.pi**2)
    love = 1e6 * float(_love(np.array(0.0), np.array(0.0), a, b, e, nu))
    assert fft_centre == pytest.approx(love + corr, rel=1e-4, abs=0.0)
    assert -0.8 * love < corr < -0.5 * love  # really between the limits


def test_incompressible_rubber_layer() -> None:
    # nu = 0.5 is allowed in the layer model (the column model's M is infinite there): a rubber
    # liner deflects by bulging. Reference: the state-space solution at nu = 0.49999 (it needs
    # 1 - 2 nu > 0; the closed form is continuous in nu), to 1e-3: the compressible share it
    # adds, about the column compliance 3e-5 t/E, is below 1e-3 of the deflection at s >= 0.3.
    t, e = 0.01, 7e6
    for s in (0.3, 1.0, 3.0):
        assert float(layer_compliance(s / t, t, e, 0.5)) == pytest.approx(
            _state_space_compliance(s / t, t, e, 0.49999), rel=1e-3, abs=0.0
        )
    layer = layer_operator((41, 64), 0.16, 0.02, t, e, 0.5)
    u = layer.apply(np.full((41, 64), 1e5))
    assert np.all(np.isfinite(u))
    assert abs(u[20, 0]) < 1e-3 * u.max()  # uniform pressure far from the ends: no deflection
    assert u.max() > 0.0  # near the ends the rubber bulges
