"""Turbulent films (docs/theory.md Sect. 17, "Turbulent films"): the Ng-Pan and Constantinescu
linearised coefficients in the film equation, their laminar limit, the short- and long-bearing
limits of the linearised theory, the exact Jacobian, seed 001's water rig at high speed, and
the case fields and their bad input.
"""

from __future__ import annotations

import json
import math
from dataclasses import replace
from pathlib import Path

import numpy as np
import pytest
from scipy.integrate import quad

from shaftline.errors import InputError
from shaftline.film import BearingGeometry, JournalBearing, OperatingPoint, SolverOptions
from shaftline.film.equilibrium.steps import moved
from shaftline.film.geometry import JournalPosition
from shaftline.film.roughness import SurfaceRoughness
from shaftline.film.turbulence import (
    TurbulenceModel,
    couette_shear_factor,
    couette_shear_factor_derivative,
    pressure_flow_coefficients,
    pressure_flow_coefficients_derivative,
    transition_reynolds,
)
from tests.conftest import invoke

# Seed 001's rig (Li et al. 2022): D 323 mm, L/D 3.7, c 0.55 mm; water at 25 degC.
RIG = BearingGeometry(length=1.2, diameter=0.323, radial_clearance=0.55e-3)
WATER = {"viscosity": 0.89e-3, "density": 997.0}
LOAD = 75e3


def _rig(rpm: float, geometry: BearingGeometry = RIG, **options: object) -> JournalBearing:
    operating = OperatingPoint(speed=rpm * math.pi / 30, **WATER)
    return JournalBearing(geometry, operating, SolverOptions(**options))  # type: ignore[arg-type]


@pytest.mark.parametrize("model", ["ng_pan", "constantinescu"])
def test_coefficients_are_laminar_at_zero_reynolds_number_and_their_derivatives_are_exact(
    model: TurbulenceModel,
) -> None:
    """k = 12 and C_f = 1 at Re = 0 (the laminar film); the derivatives used by Newton's
    Jacobian agree with central differences to 1e-7 (a mistyped exponent would not)."""
    kx, kz = pressure_flow_coefficients(0.0, model)
    assert float(kx) == 12.0 and float(kz) == 12.0 and float(couette_shear_factor(0.0)) == 1.0
    re = np.array([300.0, 2000.0, 2e4])
    step = 1e-3 * re
    (kx_p, kz_p), (kx_m, kz_m) = (
        pressure_flow_coefficients(re + step, model),
        pressure_flow_coefficients(re - step, model),
    )
    dkx, dkz = pressure_flow_coefficients_derivative(re, model)
    np.testing.assert_allclose(dkx, (kx_p - kx_m) / (2 * step), rtol=1e-7)
    np.testing.assert_allclose(dkz, (kz_p - kz_m) / (2 * step), rtol=1e-7)
    central = (couette_shear_factor(re + step) - couette_shear_factor(re - step)) / (2 * step)
    np.testing.assert_allclose(couette_shear_factor_derivative(re), central, rtol=1e-7)


def test_ng_pan_and_constantinescu_agree_in_the_turbulent_range() -> None:
    """Two independent theories (law of the wall, Ng & Pan 1965; mixing length, Constantinescu
    1962) fitted to the same physics: between Re 2000 and 20 000 their k_x agree within 8 %
    (measured 0.3-6.9 %); their k_z within 20 % up to Re 5000 (measured 4-15 %) and drift apart
    above (Constantinescu's 39 % lower at 20 000: the axial coefficient is where the theories
    differ most, docs/theory.md). A transcription slip in either set of constants (a factor 10,
    a swapped exponent) breaks these bounds."""
    re = np.geomspace(2000.0, 2e4, 12)
    ng_x, ng_z = pressure_flow_coefficients(re, "ng_pan")
    co_x, co_z = pressure_flow_coefficients(re, "constantinescu")
    assert np.all(np.abs(co_x / ng_x - 1.0) < 0.08)
    low = re <= 5000.0
    assert np.all(np.abs(co_z[low] / ng_z[low] - 1.0) < 0.20)
    assert np.all(np.abs(co_z / ng_z - 1.0) < 0.45)
    assert np.all(ng_x > ng_z) and np.all(co_x > co_z)  # the pressure flow along the motion is damped most


def test_laminar_limit_reproduces_the_laminar_solver() -> None:
    """As Re -> 0 every coefficient is its laminar value in floating point (12 + 1e-290 is 12),
    so the turbulent path (the flow-factor stencil with a factor of exactly 1) gives the laminar
    solver's equilibrium, smooth and rough: the same film matrices, to rounding. Not bit for
    bit: the last Newton trial's pressure is iterated from the step's linear guess
    (``NewtonOptions.refine_residual``), whose derivative the turbulent path computes with its own
    (here unit) factors, so its last bits may differ (5e-17 of the peak seen); 1e-13 of the
    peak pressure, the clearance and the friction is rounding, far below what a coefficient
    that is not exactly its laminar value would move."""
    rough = replace(RIG, surface=SurfaceRoughness.preset("steel_polymer"))
    for geometry in (RIG, rough):
        operating = OperatingPoint(speed=100 * math.pi / 30, viscosity=0.89e-3, density=1e-300)
        laminar = JournalBearing(geometry, operating, SolverOptions()).equilibrium(load_y=-LOAD)
        turbulent_bearing = JournalBearing(geometry, operating, SolverOptions(turbulence="on"))
        assert turbulent_bearing.turbulent
        turbulent = turbulent_bearing.equilibrium(load_y=-LOAD)
        assert turbulent.state.turbulence is not None
        assert turbulent.state.turbulence.max_reynolds_number < 1e-290
        peak = float(laminar.state.pressure.max())
        np.testing.assert_allclose(turbulent.state.pressure, laminar.state.pressure, rtol=0.0, atol=1e-13 * peak)
        for offset in ("ey", "ez"):
            assert getattr(turbulent.state.position, offset) == pytest.approx(
                getattr(laminar.state.position, offset), rel=0.0, abs=1e-13 * geometry.radial_clearance
            )
        assert turbulent.state.friction_force == pytest.approx(laminar.state.friction_force, rel=1e-13)


def _load_ratio(
    length_ratio: float, eps: float, reynolds: float, nodes: tuple[int, int], model: TurbulenceModel
) -> float:
    """Turbulent over laminar load at a fixed eccentricity, half-Sommerfeld, from the solver."""
    diameter, clearance, viscosity, speed = 0.3, 0.3e-3, 1e-3, 100.0
    density = reynolds * viscosity / (speed * 0.5 * diameter * clearance)
    geometry = BearingGeometry(length=length_ratio * diameter, diameter=diameter, radial_clearance=clearance)
    operating = OperatingPoint(speed=speed, viscosity=viscosity, density=density)
    loads = []
    for mode in ("off", "on"):
        options = SolverOptions(*nodes, cavitation="half_sommerfeld", turbulence=mode, turbulence_model=model)  # type: ignore[arg-type]
        loads.append(
            JournalBearing(geometry, operating, options).solve_at(JournalPosition(-eps * clearance, 0.0)).load_capacity
        )
    return loads[1] / loads[0]


def _short_ratio(eps: float, reynolds: float, model: TurbulenceModel) -> float:
    """Short-bearing limit: d/dz(h^3/(k_z mu) dp/dz) = (U/2) dh/dx with h and k_z constant
    along z gives p = (k_z(Re_h)/12) p_Ocvirk exactly; the load ratio by quadrature over the
    half-Sommerfeld film (pi..2 pi, h = c (1 + eps cos theta))."""

    def load(weight: object) -> float:
        parts = [
            quad(
                lambda t, f=f: weight(t) * f(t) * -math.sin(t) / (1 + eps * math.cos(t)) ** 3,  # type: ignore[operator]
                math.pi,
                2 * math.pi,
            )[0]
            for f in (math.cos, math.sin)
        ]
        return math.hypot(*parts)

    return load(lambda t: float(pressure_flow_coefficients(reynolds * (1 + eps * math.cos(t)), model)[1]) / 12) / load(
        lambda t: 1.0
    )


def _long_ratio(eps: float, reynolds: float, model: TurbulenceModel) -> float:
    """Long-bearing limit: dp/dtheta ~ (k_x/12)(H - H*)/H^3 with H* closing the full film,
    integrated by the trapezoidal rule on 8001 points, negative pressures cut (half-Sommerfeld)."""
    theta = np.linspace(0.0, 2 * math.pi, 8001)
    film = 1 + eps * np.cos(theta)
    loads = []
    for weight in (np.ones_like(film), pressure_flow_coefficients(reynolds * film, model)[0] / 12):
        closing = np.trapezoid(weight / film**2, theta) / np.trapezoid(weight / film**3, theta)
        slope = weight * (film - closing) / film**3
        pressure = np.maximum(np.concatenate([[0.0], np.cumsum(0.5 * (slope[1:] + slope[:-1]) * np.diff(theta))]), 0.0)
        loads.append(
            math.hypot(np.trapezoid(pressure * np.cos(theta), theta), np.trapezoid(pressure * np.sin(theta), theta))
        )
    return loads[1] / loads[0]


@pytest.mark.parametrize("model", ["ng_pan", "constantinescu"])
def test_short_bearing_limit_of_the_linearised_theory(model: TurbulenceModel) -> None:
    """In the short-bearing limit the turbulent pressure is k_z(Re_h)/12 times Ocvirk's
    (Constantinescu's short-bearing result): the solver's load ratio at L/D = 1/16 agrees with
    the quadrature within 0.5 % at Re_c 1000 and 6000 (the load rises 17-140 %). The gap is the
    finite length, O((L/D)^2): it shrinks at least threefold from L/D = 1/8 to 1/16 (measured
    1.3 % -> 0.34 % at eps 0.6, Re_c 6000), which is what bounds the tolerance."""
    for eps, reynolds in ((0.3, 1000.0), (0.6, 6000.0)):
        reference = _short_ratio(eps, reynolds, model)
        assert reference > 1.15
        fine = _load_ratio(1 / 16, eps, reynolds, (21, 120), model)
        assert fine == pytest.approx(reference, rel=5e-3)
    coarse = _load_ratio(1 / 8, 0.6, 6000.0, (21, 120), model)
    assert abs(coarse / reference - 1) > 3 * abs(fine / reference - 1)


@pytest.mark.slow
def test_long_bearing_limit_of_the_linearised_theory() -> None:
    """In the long-bearing limit only k_x acts: the solver's load ratio at L/D = 24 agrees with
    the 1-D quadrature within 2 % at Re_c 6000 (the load rises 3.9 times), and the gap (edge
    leakage, O(D/L)) falls from L/D = 8 to 24 by more than half (measured 4.5 % -> 1.3 %)."""
    reference = _long_ratio(0.6, 6000.0, "ng_pan")
    assert reference > 3.5
    near = _load_ratio(24, 0.6, 6000.0, (97, 90), "ng_pan")
    far = _load_ratio(8, 0.6, 6000.0, (41, 90), "ng_pan")
    assert near == pytest.approx(reference, rel=2e-2)
    assert abs(far / reference - 1) > 2 * abs(near / reference - 1)


@pytest.mark.parametrize("surface", [None, SurfaceRoughness.preset("steel_polymer")])
def test_equilibrium_jacobian_is_exact_with_turbulence(surface: SurfaceRoughness | None) -> None:
    """Newton's Jacobian with the turbulence coefficients (and flow factors) against central
    differences of the force, steps 1e-8 m: within 1e-5 of its norm, as the rough film's."""
    bearing = _rig(350, replace(RIG, surface=surface), turbulence="on")
    position = bearing.equilibrium(load_y=-LOAD).state.position
    solver = bearing.solver
    evaluation = solver.evaluate(position, warm=False)
    jacobian = solver.position_response(evaluation)[0]
    step = 1e-8
    columns = []
    for k in range(2):
        d = np.zeros(2)
        d[k] = step
        plus = solver.evaluate(moved(position, d), warm=False).force
        minus = solver.evaluate(moved(position, -d), warm=False).force
        columns.append((plus - minus) / (2 * step))
    assert np.abs(np.column_stack(columns) - jacobian).max() < 1e-5 * np.abs(jacobian).max()


def test_a_rough_film_past_the_mean_plane_has_a_laminar_reynolds_number_not_a_negative_one() -> None:
    """A rough film whose mean planes overlap (h < 0, boundary lubrication) has no positive gap on
    which Re_h = Re_c h / c could be taken: the reported map is Re_c max(H, 0) (0 there, never
    negative), and the film equation's coefficients there are laminar (12 / k = 1, zero slope),
    continuous with h -> 0+ where Re_h -> 0. Elsewhere Re_h is Re_c H as before. (On the mean gap
    the rough flow uses, h_T <= 0.4 sigma, Re_h would be at most 6 here: laminar either way.)"""
    surface = SurfaceRoughness.preset("steel_polymer")
    bearing = _rig(350, replace(RIG, surface=surface), turbulence="on")
    c = RIG.radial_clearance
    # The journal 0.5 sigma past the mean plane at the bottom of the bore (lambda_min = -0.5).
    position = JournalPosition(ey=-(c + 0.5 * surface.sigma), ez=0.0)
    state = bearing.solve_at(position, warm_start=False)
    film = state.film
    assert film.min() < 0.0 and state.turbulence is not None
    reynolds = state.turbulence.reynolds_number
    assert reynolds.min() == 0.0
    np.testing.assert_array_equal(reynolds[film <= 0.0], 0.0)
    above = film > 0.0
    np.testing.assert_allclose(reynolds[above], bearing.reynolds_number * film[above] / c, rtol=1e-12)
    # The film equation's flow factors (FilmSolver.flow: the roughness's with the turbulence's).
    flow = bearing.solver.flow
    assert flow is not None
    closed = np.array([-0.5, -0.01]) * surface.sigma / c
    rough_flow = replace(RIG, surface=surface)
    laminar = _rig(350, rough_flow).solver.flow
    assert laminar is not None
    np.testing.assert_array_equal(flow.conductance(closed), laminar.conductance(closed))
    np.testing.assert_array_equal(flow.conductance_derivative(closed), laminar.conductance_derivative(closed))
    assert np.all(np.isfinite(state.pressure)) and state.turbulence.max_reynolds_number > 0.0


def test_water_stern_tube_at_high_speed_is_turbulent_and_lifts_the_journal() -> None:
    """Seed 001's rig with water at 350 rpm: Re_c = 3650, local Re_h up to 7200, far above
    the Taylor onset 41.3 sqrt(R/c) = 708 (Lv et al. 2018-19, cited by seed 001, report local
    turbulence in such bearings). ``auto`` applies the coefficients; the damped pressure flow
    carries the load on a thicker film (h_min +20 % or more, measured 9.5 -> 13.1 um) and the
    turbulent Couette shear raises the friction (+30 % or more, measured +46 %). At half the
    speed (Re_h up to 3600) the film gains less (measured +9 % against +39 %)."""
    laminar = _rig(350).equilibrium(load_y=-LOAD).state
    bearing = _rig(350, turbulence="auto")
    assert bearing.turbulent
    turbulent = bearing.equilibrium(load_y=-LOAD).state
    assert turbulent.turbulence is not None
    assert turbulent.turbulence.turbulent and turbulent.turbulence.max_reynolds_number > 5000
    assert turbulent.turbulence.max_reynolds_number == pytest.approx(
        bearing.reynolds_number * turbulent.film.max() / RIG.radial_clearance
    )
    assert turbulent.min_film_thickness > 1.2 * laminar.min_film_thickness
    assert turbulent.friction_coefficient > 1.3 * laminar.friction_coefficient
    assert 2 * bearing.reynolds_number > 5 * transition_reynolds(RIG.radius, RIG.radial_clearance)
    slower = _rig(175, turbulence="auto").equilibrium(load_y=-LOAD).state
    gain = slower.min_film_thickness / _rig(175).equilibrium(load_y=-LOAD).state.min_film_thickness
    assert 1.0 < gain < turbulent.min_film_thickness / laminar.min_film_thickness


def test_auto_stays_laminar_below_the_transition_and_off_reports_nothing() -> None:
    bearing = _rig(20, turbulence="auto")
    assert not bearing.turbulent
    state = bearing.equilibrium(load_y=-LOAD).state
    turbulence = state.turbulence
    assert turbulence is not None and not turbulence.turbulent
    assert turbulence.reynolds_number.shape == state.film.shape and turbulence.max_reynolds_number > 0
    off = _rig(20).equilibrium(load_y=-LOAD).state
    assert off.turbulence is None  # no Reynolds number map, no largest Reynolds number
    np.testing.assert_array_equal(state.pressure, off.pressure)


def test_bad_turbulence_options_name_the_field() -> None:
    with pytest.raises(InputError, match="turbulence"):
        SolverOptions(turbulence="maybe")  # type: ignore[arg-type]
    with pytest.raises(InputError, match="turbulence_model"):
        SolverOptions(turbulence_model="hirs")  # type: ignore[arg-type]


RIG_CASE = """
[case]
name = "rig"

[bearing]
length = "1.2 m"
diameter = "0.323 m"
radial_clearance = "0.55 mm"

[bearing.operation]
speed = "350 rpm"
load = "75 kN"

[bearing.lubricant]
{lubricant}

[bearing.solver]
axial_nodes = 21
circumferential_nodes = 60
turbulence = "{mode}"
"""


def test_case_reports_the_reynolds_number_and_notes_an_oil_far_below_transition(tmp_path: Path) -> None:
    """JSON: max_reynolds_number, turbulent and the Re_h map; report: the map's figure. An oil
    (ISO VG 100 at 40 degC, Re_c about 30) with turbulence on is a note, not an error."""
    path = tmp_path / "rig.toml"
    path.write_text(RIG_CASE.format(lubricant='preset = "water"\ntemperature = "25 degC"', mode="auto"))
    out = tmp_path / "report"
    result = invoke("bearing", "solve", str(path), "--json", "-", "--workers", "1", "--out", str(out))
    assert result.exit_code == 0, result.output
    document = json.loads(result.stdout)
    case = document["bearing"]["cases"][0]
    assert case["turbulent"] is True and case["max_reynolds_number"] > 5000
    reynolds = np.array(case["reynolds_number_map"])
    assert reynolds.shape == (21, 60) and reynolds.max() == pytest.approx(case["max_reynolds_number"], rel=1e-6)
    assert "warnings" not in document
    assert (out / "figures" / "bearing_0_reynolds.png").exists()
    # the terminal table gives the flag with the Taylor onset auto used: 41.3 sqrt(R/c) = 708
    terminal = invoke("bearing", "solve", str(path), "--workers", "1")
    assert terminal.exit_code == 0, terminal.output
    assert "turbulentfilm(TayloronsetRe_h)│yes(708)" in terminal.stdout.replace(" ", "")

    path.write_text(RIG_CASE.format(lubricant='preset = "ISO VG 100"\ntemperature = "40 degC"', mode="on"))
    result = invoke("bearing", "solve", str(path), "--json", "-", "--workers", "1")
    assert result.exit_code == 0, result.output
    document = json.loads(result.stdout)
    assert any("far below the transition" in text for text in document["warnings"])
    assert document["bearing"]["cases"][0]["max_reynolds_number"] < 100

    path.write_text(RIG_CASE.format(lubricant='preset = "water"\ntemperature = "25 degC"', mode="sometimes"))
    result = invoke("bearing", "solve", str(path), "--json", "-")
    assert result.exit_code == 2 and "turbulence" in result.output


def test_stribeck_curve_reports_the_reynolds_number_per_speed(tmp_path: Path) -> None:
    """``bearing stribeck`` with turbulence auto: the largest Re_h at each speed, rising with
    speed (Re_h = rho omega R h / mu, and the film thickens), and where auto applied the
    coefficients (above 41.3 sqrt(R/c) = 708 for the largest film, 2 Re_c)."""
    path = tmp_path / "rig.toml"
    text = RIG_CASE.format(lubricant='preset = "water"\ntemperature = "25 degC"', mode="auto")
    path.write_text(text + '\n[bearing.stribeck]\nlowest = "20 rpm"\nhighest = "350 rpm"\npoints = 4\n')
    result = invoke("bearing", "stribeck", str(path), "--json", "-", "--workers", "1")
    assert result.exit_code in (0, 3), result.output
    curve = json.loads(result.stdout)["bearing"]["stribeck"]
    reynolds = np.array(curve["max_reynolds_number"])
    assert np.all(np.diff(reynolds) > 0) and reynolds[-1] > 5000
    speeds = np.array(curve["speed_rpm"])
    onset = transition_reynolds(RIG.radius, RIG.radial_clearance)
    clearance_re = 2 * WATER["density"] * speeds * math.pi / 30 * RIG.radius * RIG.radial_clearance / 0.89e-3
    assert curve["turbulent"] == list(clearance_re > onset)
    assert curve["turbulent"][0] is False and curve["turbulent"][-1] is True

    # The terminal table (also the report's) says where the coefficients started and the
    # largest Re_h of the sweep, from the same curve as the JSON.
    result = invoke("bearing", "stribeck", str(path), "--workers", "1")
    assert result.exit_code in (0, 3), result.output
    first = speeds[np.argmax(curve["turbulent"])]
    assert f"turbulent film from [rpm] │ {first:.4g}".replace(" ", "") in result.stdout.replace(" ", "")
    assert "largest local Reynolds number [-]" in result.stdout


def test_a_turbulence_model_with_turbulence_off_is_noted(tmp_path: Path) -> None:
    """`turbulence_model` named while `turbulence` stays at its default (off) changes nothing: the
    case's warnings say so (it was silently laminar); the default model unnamed is no note."""
    path = tmp_path / "rig.toml"
    water = 'preset = "water"\ntemperature = "25 degC"'
    path.write_text(RIG_CASE.format(lubricant=water, mode="off") + 'turbulence_model = "constantinescu"\n')
    result = invoke("bearing", "solve", str(path), "--json", "-", "--workers", "1")
    assert result.exit_code == 0, result.output
    document = json.loads(result.stdout)
    assert any("turbulence_model = constantinescu has no effect" in text for text in document["warnings"])
    assert "max_reynolds_number" not in document["bearing"]["cases"][0]
    path.write_text(RIG_CASE.format(lubricant=water, mode="off"))
    result = invoke("bearing", "solve", str(path), "--json", "-", "--workers", "1")
    assert result.exit_code == 0 and "warnings" not in json.loads(result.stdout)
