"""A rigid rough bore at low speed (issue 15): the equilibrium's pseudo-transient settling where
Newton stalls, the contact zone's resolution that it needs, and warm and cold starts that reach
the same equilibrium (docs/theory.md Sect. 17, "Boundary lubrication", "Settling";
docs/validation.md, "Rigid rough bore at low speed")."""

from __future__ import annotations

import math
from dataclasses import replace
from pathlib import Path

import numpy as np
import pytest

import shaftline.film.equilibrium.newton as newton_module
from shaftline.cases import load_case
from shaftline.film import Equilibrium, JournalBearing
from shaftline.film.geometry import JournalPosition
from shaftline.film.study import BearingCase

ROOT = Path(__file__).resolve().parents[2]


def _with_options(bearing: JournalBearing, **changes: object) -> JournalBearing:
    """``bearing`` with some of its solver options replaced (``settling=``, ``newton=``...)."""
    return JournalBearing.from_problem(replace(bearing.problem, options=replace(bearing.options, **changes)))


def _rig(rpm: float, axial: int = 41, circumferential: int = 120) -> tuple[JournalBearing, float, float]:
    """examples/seed001_water_rig.toml (rigid, rough polymer pair, 75 kN) at ``rpm`` on the grid."""
    case = load_case(ROOT / "examples" / "seed001_water_rig.toml").studies["bearing"].cases[0]
    options = replace(case.options, axial_nodes=axial, circumferential_nodes=circumferential)
    operating = replace(case.operating, speed=rpm * math.pi / 30)
    return JournalBearing(case.geometry, operating, options), case.load_y, case.load_z


@pytest.mark.parametrize("circumferential", [120, 240, 480])
def test_contact_zone_nodes_count_the_film_within_sigma_of_its_minimum(circumferential: int) -> None:
    """Near its minimum an aligned journal's film is h_min + c eps (1 - cos theta), so the film is
    within sigma of its minimum over |theta| <= arccos(1 - sigma / (c eps)): 2 x 5.2 degrees on
    seed 001's rig (sigma/c = 0.0041). The count is that width over the grid step, to the one
    node a sampled interval can gain or lose at either end."""
    bearing, _, _ = _rig(15, axial=11, circumferential=circumferential)
    surface = bearing.geometry.surface
    assert surface is not None
    c = bearing.geometry.radial_clearance
    eps = 1.0 - 0.1 * surface.sigma / c  # lambda_min 0.1
    position = JournalPosition(ey=-eps * c * math.cos(0.3), ez=-eps * c * math.sin(0.3))
    half_width = math.acos(1.0 - surface.sigma / (c * eps))
    expected = 2.0 * half_width / (2.0 * math.pi / circumferential)
    assert abs(bearing.contact_zone_nodes(bearing.film(position)) - expected) <= 2.0
    smooth = JournalBearing(replace(bearing.geometry, surface=None), bearing.operating, bearing.options)
    assert smooth.contact_zone_nodes(smooth.film(position)) == 0


@pytest.mark.slow
def test_warm_and_cold_starts_reach_the_same_boundary_equilibrium_of_a_resolved_rigid_bore() -> None:
    """Seed 001's rigid rig on 11 x 480 nodes (0.75 degree: 14 nodes across the contact zone) at
    3.5 and 7.7 rpm. From the closed-form start Newton stalls (residual 1-2 % of the load; checked
    below with the settling switched off), warm-started from the 20 rpm equilibrium it converges;
    with the settling the cold start converges too, to the same position within 1e-7 c (the force
    tolerance 1e-8 of the load over the film's stiffness, about 20 W/c, is 1e-9 c). The film at
    these speeds sits just above the mean plane with the asperities carrying about a tenth of the
    load, thinner at the lower speed (docs/validation.md: 0.062 and 0.091 sigma, 9-10 %)."""
    base, load_y, load_z = _rig(20.08, axial=11, circumferential=480)
    start = base.equilibrium(load_y, load_z)
    assert start.converged and not start.contact
    c = base.geometry.radial_clearance
    films = []
    for rpm in (3.5, 7.74):
        bearing, _, _ = _rig(rpm, axial=11, circumferential=480)
        cold = bearing.equilibrium(load_y, load_z)
        warm = bearing.equilibrium(
            load_y, load_z, initial=start.state.position, initial_cavitated=start.state.cavitated
        )
        assert cold.converged and not cold.contact, rpm
        assert warm.converged and not warm.contact, rpm
        a, b = cold.state.position, warm.state.position
        assert math.hypot(a.ey - b.ey, a.ez - b.ez) < 1e-7 * c, rpm
        assert 0.0 < cold.state.min_film_ratio < 0.2 and 0.05 < cold.state.asperity_load_share < 0.15
        films.append(cold.state.min_film_thickness)
        # Without the settling (no grid resolves a zone of 10**6 nodes) the cold start stalls
        # (what the test guards).
        unsettled = _with_options(bearing, settling=replace(bearing.options.settling, zone_nodes=10**6))
        newton = unsettled.equilibrium(load_y, load_z)
        assert not newton.converged, rpm
    assert films[0] < films[1] < start.state.min_film_thickness


def test_an_unresolved_contact_zone_is_not_settled(monkeypatch: pytest.MonkeyPatch) -> None:
    """On the example's own 3 degree grid (3-4 nodes across the contact zone) the film pressure of
    the contact is a spike on one node and the discrete force jumps as the minimum moves between
    nodes: the settling is not tried and the stalled equilibrium is reported not converged (not
    contact: its film is far above the boundary limit), as quickly as before. (The settling is
    spied on where the Newton iteration calls it: :func:`shaftline.film.equilibrium.settling.settle`.)"""
    bearing, load_y, load_z = _rig(3.5)
    called = []
    settle = newton_module.settle

    def spy(*args, **kwargs):  # type: ignore[no-untyped-def]
        called.append(True)
        return settle(*args, **kwargs)

    monkeypatch.setattr(newton_module, "settle", spy)
    eq = bearing.equilibrium(load_y, load_z)
    assert not eq.converged and not eq.contact
    assert not called
    assert bearing.contact_zone_nodes(eq.state.film) < bearing.options.settling.zone_nodes
    assert eq.state.min_film_ratio > -1.0
    assert np.isfinite(eq.residual)


def _ntua_rough(index: int) -> tuple[JournalBearing, BearingCase]:
    """benchmarks/bench_mixed.py's NTUA Stribeck curve: examples/ntua_stern_tube.toml (100 x 60,
    psi 0.3) with the turned-steel / white-metal roughness, rigid, at the curve's speed ``index``."""
    from shaftline.film.roughness import SurfaceRoughness

    study = load_case(ROOT / "examples" / "ntua_stern_tube.toml").studies["bearing"]
    case = study.cases[0]
    geometry = replace(case.geometry, surface=SurfaceRoughness.preset("turned_steel_white_metal"))
    operating = replace(case.operating, speed=study.stribeck_speeds[index])
    return JournalBearing(geometry, operating, case.options), case


def test_a_crawling_newton_iteration_stops_with_the_status_it_ends_with_anyway() -> None:
    """The NTUA rigid rough bore at 12.36 rpm (the curve's third speed) from a cold start: below
    the mean plane with one node in its contact zone, the line search cuts every Newton step to
    1/16 or 1/8 and the residual falls 1-3 % an iteration, above the 1 % of the stall rule. The
    crawl rule (``NewtonOptions.crawl_iterations`` such steps in a row, each leaving over
    ``crawl_reduction`` of the residual) stops it after 22 iterations; without it the iteration spends all 60 and ends
    with the same status: not converged, not in contact."""
    bearing, case = _ntua_rough(2)
    assert bearing.operating.speed * 30 / math.pi == pytest.approx(12.364, abs=1e-3)

    def solve(b: JournalBearing) -> Equilibrium:
        return b.equilibrium(case.load_y, case.load_z, tilt_y=case.tilt_y, tilt_z=case.tilt_z)

    stopped = solve(bearing)
    assert not stopped.converged and not stopped.contact
    assert stopped.iterations <= 2 * bearing.options.newton.crawl_iterations + 2
    spent = solve(_with_options(bearing, newton=replace(bearing.options.newton, crawl_iterations=10**6)))
    assert spent.iterations == bearing.options.max_iterations
    assert not spent.converged and not spent.contact


def test_an_unresolved_contact_zone_says_what_grid_would_resolve_it(tmp_path: Path) -> None:
    """The example's rig at 3.5 rpm on its 3 degree grid does not converge (above): the finding
    at the top of the output says why and what to change — the contact zone's 4 of 120 nodes,
    the 10 the settling needs, and about 400 nodes round the bore (4 nodes are 3 cells; the
    zone is 3.4 cells wide, 11 nodes on 400, where this case converges: docs/validation.md) —
    and the run exits 3 (not acceptable)."""
    from tests.conftest import invoke

    text = (ROOT / "examples" / "seed001_water_rig.toml").read_text()
    case = tmp_path / "rig.toml"
    case.write_text(text.replace('speed = "35 rpm"', 'speed = "3.5 rpm"'))
    result = invoke("bearing", "solve", str(case), "--out", str(tmp_path / "out"))
    assert result.exit_code == 3
    said = " ".join(result.stdout.split())
    assert "NOT ACCEPTABLE" in said and "did not converge" in said
    assert "spans 4 of the 120 nodes" in said and "(at least 10 needed)" in said
    assert "circumferential_nodes to about 400" in said


def test_a_stribeck_curve_names_its_stalled_speeds_and_the_grid_that_resolves_them() -> None:
    """Speeds of a Stribeck curve that stalled above the contact limit are said in an advisory
    finding (the rest of the curve stands): their range and, for a rigid rough bore, the width
    of the contact zone near ε = 1, 2 sqrt(2σ/c) = 10.3° on the rig (σ/c = 0.00407), 3.44 of its
    120 nodes, and the 384 nodes (11 across it) that resolve it. Speeds in contact are not
    counted; a curve without stalled speeds gives no finding."""
    from shaftline.film.capability import _stribeck_findings
    from shaftline.film.stribeck import StribeckCurve

    case = load_case(ROOT / "examples" / "seed001_water_rig.toml").studies["bearing"].cases[0]
    rpm = np.array([3.5, 7.0, 14.0, 35.0, 70.0])
    flags = {
        "converged": np.array([False, False, False, True, True]),
        "contact": np.array([True, False, False, False, False]),
    }
    zeros = np.zeros(rpm.size)
    curve = StribeckCurve(
        rpm * math.pi / 30, zeros, zeros, zeros, zeros, (None,) * rpm.size, transition_speed=None, **flags
    )
    (finding,) = _stribeck_findings(curve, case)
    assert finding.criterion
    said = " ".join(finding.text.split())
    assert "2 of 5 speeds (7 to 14 rpm) did not converge" in said
    assert "10° wide, 3.4 of the 120 nodes" in said and "circumferential_nodes of about 384" in said
    converged = StribeckCurve(
        rpm * math.pi / 30,
        zeros,
        zeros,
        zeros,
        zeros,
        (None,) * rpm.size,
        np.ones(rpm.size, bool),
        flags["contact"],
        None,
    )
    assert _stribeck_findings(converged, case) == []
