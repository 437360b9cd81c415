"""Starting a lined equilibrium where the film-liner iteration does not settle at the first
position (issue 15; docs/theory.md, "Starting a lined equilibrium").

Reference: the equilibrium's own definition, force + load = 0 to the solver's tolerance, with
the film-liner iteration settled (each test first shows that the case's default start does not
settle, so the test exercises the retreat); seed 001's rig (Li et al. 2022, Sect. 2, Tables 1-3)
on its polymer liner, tilted 0.05 mrad (a bent journal in the forward model of issue 13), which
raised LinerConvergenceError before this change (`shaftline bearing solve` ended with exit 3).
"""

from __future__ import annotations

import math
from dataclasses import replace
from pathlib import Path

import pytest

from shaftline.film.bearing import JournalBearing, LinerConvergenceError
from shaftline.film.liner import Liner
from shaftline.film.roughness import SurfaceRoughness
from shaftline.monitor.forward import RigCase, rig_bearing
from tests.conftest import invoke

ROOT = Path(__file__).resolve().parents[2]


def _rig_case(misalignment: float, bend_scale: float) -> RigCase:
    return RigCase(
        surface=SurfaceRoughness.preset("steel_polymer"),
        liner=Liner.preset("polymer_composite"),
        bend_scale=bend_scale,
        misalignment=misalignment,
    )


def _default_start(bearing: JournalBearing, load: float, tilt: float):  # noqa: ANN202
    """The start the equilibrium takes without ``initial`` on this lined rig: the rigid bore's
    equilibrium is below the mean plane there, so the closed-form position."""
    return bearing.initial_position(-load, 0.0, tilt, 0.0)


def test_bent_tilted_rig_on_its_liner_starts_where_the_liner_settles_and_converges() -> None:
    case = _rig_case(5e-5, 0.2)  # issue 15's report: the forward model at 35 rpm
    bearing = rig_bearing(case, 35 * math.pi / 30)
    start = _default_start(bearing, case.load, case.misalignment)
    with pytest.raises(LinerConvergenceError):
        bearing.solver.evaluate(start)
    result = bearing.equilibrium(load_y=-case.load, tilt_y=case.misalignment)
    assert result.converged and not result.contact
    assert result.residual <= bearing.options.tolerance * case.load
    state = result.state
    assert state.liner is not None and state.max_liner_deformation > 0.0
    # The load is carried below the mean plane on the liner (boundary lubrication at the
    # loaded end, as issue 13's forward model reports at 35 rpm).
    assert state.min_film_ratio < 0.0
    assert 0.0 < state.asperity_load_share < 1.0


def test_a_start_that_never_settles_is_a_flagged_result_not_an_exception() -> None:
    # No film-liner step allowed (``LinerOptions(iterations=0)``): no position settles, the start
    # itself is reported.
    case = _rig_case(5e-5, 0.2)
    rig = rig_bearing(case, 35 * math.pi / 30)
    options = replace(rig.options, liner=replace(rig.options.liner, iterations=0))
    bearing = JournalBearing.from_problem(replace(rig.problem, options=options))
    start = _default_start(bearing, case.load, case.misalignment)
    result = bearing.equilibrium(load_y=-case.load, tilt_y=case.misalignment)
    assert not result.converged and not result.contact
    assert result.iterations == 0
    assert (result.state.position.ey, result.state.position.ez) == (start.ey, start.ez)
    assert math.isfinite(result.residual) and result.residual > bearing.options.tolerance * case.load


def test_a_liner_that_does_not_settle_while_finishing_is_reported_not_converged() -> None:
    # Aligned, straight, 15 rpm: an accepted trial's liner, solved to its parent's looser
    # tolerance, does not settle to its own (it raised LinerConvergenceError before).
    case = _rig_case(0.0, 0.0)
    bearing = rig_bearing(case, 15 * math.pi / 30)
    result = bearing.equilibrium(load_y=-case.load, tilt_y=0.0)
    assert not result.converged
    assert result.residual > bearing.options.tolerance * case.load


def test_bearing_solve_of_a_tilted_lined_rig_reports_its_equilibrium(tmp_path: Path) -> None:
    text = (ROOT / "examples" / "seed001_water_rig_liner.toml").read_text()
    assert 'speed = "95 rpm"' in text
    text = text.replace('speed = "95 rpm"', 'speed = "35 rpm"\ntilt_vertical = "0.05 mrad"')
    path = tmp_path / "tilted.toml"
    path.write_text(text)
    result = invoke("bearing", "solve", str(path), "--workers", "1")
    assert result.exit_code == 0, result.output
    assert "converged" in result.output and "│ yes" in result.output.split("converged")[-1].splitlines()[0]
