"""Mixed lubrication in the film solver: rough surfaces (Patir-Cheng flow factors) and
asperity contact (Greenwood-Tripp) on a rigid bore (docs/theory.md, "Mixed lubrication").

The bearing is seed 001's water-lubricated test bearing (Li et al. 2022, Table 1 and Sect. 2:
D = 323 mm, L/D = 3.7, c = 0.55 mm, polymer liner Ra 1.6 um against a sleeve of Ra 0.8 um),
rigid and aligned, with water at 1 mPa s and a 20 kN load (52 kPa mean pressure; the seed
does not print its load), on the default 41 x 120 grid.
"""

from __future__ import annotations

import math
from dataclasses import replace

import numpy as np
import pytest

from shaftline.errors import InputError
from shaftline.film import BearingGeometry, JournalBearing, OperatingPoint, SolverOptions
from shaftline.film.equilibrium.steps import moved
from shaftline.film.roughness import SurfaceRoughness

POLYMER = SurfaceRoughness.preset("steel_polymer")
RIG = BearingGeometry(length=3.7 * 0.323, diameter=0.323, radial_clearance=0.55e-3, surface=POLYMER)
LOAD = 20e3


def _rig(rpm: float, geometry: BearingGeometry = RIG, **options: float) -> JournalBearing:
    operating = OperatingPoint(speed=rpm * 2 * math.pi / 60, viscosity=1.0e-3, density=1000.0)
    return JournalBearing(geometry, operating, SolverOptions(**options))  # type: ignore[arg-type]


@pytest.fixture(scope="module")
def sweep() -> dict[float, object]:
    """Equilibria of the rig from 5 to 400 rpm."""
    return {rpm: _rig(rpm).equilibrium(load_y=-LOAD).state for rpm in (5, 10, 15, 25, 35, 60, 95, 215, 400)}


def test_thick_film_reproduces_the_smooth_solver() -> None:
    """A rough film with h >> sigma is the smooth film: the flow-factor corrections are below
    0.9 exp(-0.56 lambda) (pressure) and 1.13 exp(-lambda/4) sigma/h (shear), < 1e-10 at the
    lambda_min of 87 here (215 rpm, sigma = 0.28 um), the mean gap is h to rounding and the
    asperity pressure is zero above lambda = 12: the results agree to 1e-9 (measured 1e-12)."""
    smooth_geometry = replace(RIG, surface=None)
    rough_geometry = replace(RIG, surface=SurfaceRoughness.from_ra(0.1e-6, 0.2e-6))
    smooth = _rig(215, smooth_geometry).equilibrium(load_y=-LOAD).state
    rough = _rig(215, rough_geometry).equilibrium(load_y=-LOAD).state
    assert rough.min_film_ratio > 80
    for name in ("eccentricity_ratio", "attitude_angle", "min_film_thickness", "max_pressure", "friction_force"):
        assert getattr(rough, name) == pytest.approx(getattr(smooth, name), rel=1e-9), name
    assert rough.rough.asperity_load == 0.0 and rough.rough.boundary_friction_force == 0.0
    assert rough.rough.lubrication_regime == "full film"


def test_smooth_state_reports_no_contact_and_all_fluid_friction() -> None:
    state = _rig(60, replace(RIG, surface=None)).equilibrium(load_y=-LOAD).state
    # No rough part (asperity pressure, film ratio, regime, and the friction split: a smooth film's
    # friction is all the film's shear) and none of its load or film ratio.
    assert state.rough is None and not state.contact
    assert state.asperity_load_share == 0.0 and state.min_film_ratio == math.inf


def test_asperities_carry_part_of_a_slow_heavy_load_and_less_as_speed_rises(sweep: dict[float, object]) -> None:
    """At 5-15 rpm the asperities carry a share of the load (lambda_min below 1: boundary);
    the share falls with speed and vanishes in the full film (lambda_min > 3 from 60 rpm)."""
    shares = [sweep[rpm].asperity_load_share for rpm in sorted(sweep)]  # type: ignore[attr-defined]
    assert shares[0] > 0.1 and sweep[15].asperity_load_share > 0.01  # type: ignore[attr-defined]
    assert all(a > b for a, b in zip(shares[:6], shares[1:6], strict=False))
    assert sweep[15].rough.lubrication_regime == "boundary"  # type: ignore[attr-defined]
    assert sweep[35].rough.lubrication_regime == "mixed"  # type: ignore[attr-defined]
    assert sweep[95].rough.lubrication_regime == "full film"  # type: ignore[attr-defined]
    assert abs(sweep[400].asperity_load_share) < 1e-9  # type: ignore[attr-defined]
    for state in sweep.values():
        # The friction split adds up; the boundary part is the boundary coefficient on the asperities.
        rough = state.rough  # type: ignore[attr-defined]
        assert rough.fluid_friction_force + rough.boundary_friction_force == pytest.approx(state.friction_force)  # type: ignore[attr-defined]
        assert rough.boundary_friction_force <= POLYMER.boundary_friction * rough.asperity_load * 1.5 + 1e-9


def test_friction_coefficient_falls_then_rises_stribeck(sweep: dict[float, object]) -> None:
    """Stribeck: boundary friction dominates at low speed, viscous shear at high speed, with a
    minimum in between (here at 35-95 rpm, where lambda_min passes 3)."""
    speeds = sorted(sweep)
    f = np.array([sweep[rpm].friction_coefficient for rpm in speeds])  # type: ignore[attr-defined]
    low = int(np.argmin(f))
    assert 0 < low < len(f) - 1
    assert np.all(np.diff(f[: low + 1]) < 0) and np.all(np.diff(f[low:]) > 0)
    assert f[0] > 5 * f[low]


def test_rough_film_is_not_stopped_at_the_film_floor() -> None:
    """A floor of 1 % of the clearance (5.5 um, lambda = 2.5) would stop a smooth search; the
    rough film goes below it to the equilibrium its asperities help carry."""
    bearing = _rig(15, min_film_floor=0.01)
    eq = bearing.equilibrium(load_y=-LOAD)
    assert eq.converged and not eq.contact
    assert eq.state.min_film_thickness < 0.01 * RIG.radial_clearance


def test_equilibrium_jacobian_is_exact_with_flow_factors_and_asperities() -> None:
    """The Newton Jacobian (frozen cavitated set) against central differences of the force
    with steps 1e-8 and 3e-9 m: their difference shrinks as h^2, and the finer one agrees with
    the analytic Jacobian to 2e-6 of its norm (1e-5 with the coarser)."""
    bearing = _rig(15)
    position = bearing.equilibrium(load_y=-LOAD).state.position
    solver = bearing.solver
    evaluation = solver.evaluate(position, warm=False)
    jacobian = solver.position_response(evaluation)[0]
    for step, tolerance in ((1e-8, 1e-5), (3e-9, 2e-6)):
        columns = []
        for k in range(2):
            d = np.zeros(2)
            d[k] = step
            plus = solver.evaluate(moved(position, d), warm=False).force
            minus = solver.evaluate(moved(position, -d), warm=False).force
            columns.append((plus - minus) / (2 * step))
        assert np.abs(np.column_stack(columns) - jacobian).max() < tolerance * np.abs(jacobian).max()


def test_damping_acts_on_the_mean_gap() -> None:
    """The squeeze of a rough film acts on the mean gap (dh_T/dt = Phi(h/sigma) dh/dt): the
    damping of linearise equals central differences of the force in the journal velocity to
    1e-6 (the force is linear in the velocity, so they agree to rounding)."""
    bearing = _rig(15)
    position = replace(bearing.equilibrium(load_y=-LOAD).state.position, vy=1e-6)
    lin = bearing.linearise(position)
    step = 1e-7
    columns = []
    for name in ("vy", "vz"):
        up = replace(position, **{name: getattr(position, name) + step})
        down = replace(position, **{name: getattr(position, name) - step})
        columns.append(
            (bearing.solver.evaluate(up, warm=False).force - bearing.solver.evaluate(down, warm=False).force)
            / (2 * step)
        )
    np.testing.assert_allclose(lin.velocity_derivative, np.column_stack(columns), rtol=1e-6)


def test_film_load_rows_include_the_asperities() -> None:
    bearing = _rig(10)
    state = bearing.equilibrium(load_y=-LOAD).state
    z = bearing.axial_stations
    line = np.full(z.size, state.position.ey)
    load = bearing.film_load(line, np.full(z.size, state.position.ez))
    # To 1e-9 of the force's magnitude: the horizontal component is round-off (1e-8 N of 2e4 N),
    # which a relative test per component would compare digit by digit.
    np.testing.assert_allclose(
        load.row_force.sum(axis=1), [state.force_y, state.force_z], rtol=0.0, atol=1e-9 * state.load_capacity
    )
    assert load.state.rough.asperity_load > 0.05 * LOAD


def test_mass_conserving_model_with_roughness_is_refused() -> None:
    operating = OperatingPoint(speed=2.0, viscosity=1e-3, aft_pressure=1e5, fore_pressure=1e5)
    with pytest.raises(InputError) as info:
        JournalBearing(RIG, operating, SolverOptions(cavitation="jfo"))
    assert info.value.field == "options.cavitation"
    assert "[bearing.surface] in a case" in str(info.value)  # names what the user wrote


def test_rough_pressure_does_not_depend_on_the_path() -> None:
    """The rough stencil is again a symmetric M-matrix (positive conductances H^3 phi_x), so its
    Reynolds-condition problem has one solution (tests/film/test_solver_paths.py): cold and
    warm starts match the plain active-set reference solved by spsolve to 1e-9 of the largest
    pressure, in the boundary regime (15 rpm, lambda_min 0.9)."""
    from tests.film.test_solver_paths import TOLERANCE, _reference, _relative

    bearing = _rig(15)
    position = bearing.equilibrium(load_y=-LOAD).state.position
    nearby = replace(position, ey=0.999 * position.ey, ez=position.ez + 2e-6)
    reference = _reference(bearing, position)
    cold = bearing.solve_at(position, warm_start=False)
    assert cold.rough.lubrication_regime == "boundary"
    assert _relative(bearing, cold.pressure, reference) <= TOLERANCE
    bearing.solve_at(nearby, warm_start=False)
    warm = bearing.solve_at(position, warm_start=True)
    assert np.array_equal(warm.pressure, cold.pressure)


def test_seed001_rig_example_moves_from_boundary_towards_full_film() -> None:
    """examples/seed001_water_rig.toml (75 kN, water at 25 degC) at the seed's 35, 95 and
    175 rpm: boundary or mixed lubrication at 35 rpm with the asperities carrying load, and
    lambda_min and the film rising, the asperity share falling, as the speed rises - the trend
    seed 001 reports (Sect. 5.3, Table 4: the boundary and mixed zones shrink from 35 to
    175 rpm). Magnitudes are not compared: the model is rigid and aligned, the rig's liner is
    soft and its shaft bent (issue 15 part B)."""
    from pathlib import Path

    from shaftline.cases import load_case

    example = Path(__file__).resolve().parents[2] / "examples" / "seed001_water_rig.toml"
    case = load_case(example).studies["bearing"].cases[0]
    states = []
    for rpm in (35, 95, 175):
        operating = replace(case.operating, speed=rpm * math.pi / 30)
        bearing = JournalBearing(case.geometry, operating, case.options)
        eq = bearing.equilibrium(case.load_y, case.load_z)
        assert eq.converged and not eq.contact
        states.append(eq.state)
    assert states[0].rough.lubrication_regime in ("boundary", "mixed") and states[0].asperity_load_share > 0.01
    assert states[0].min_film_ratio < states[1].min_film_ratio < states[2].min_film_ratio
    assert states[0].asperity_load_share > states[1].asperity_load_share > states[2].asperity_load_share


def test_stribeck_curve_is_the_same_on_a_pool_and_a_rough_bearing_pickles() -> None:
    """Chunks depend on the speeds only, so a pool of two gives the serial curve bit for bit;
    a rough bearing sent to another process (pickled: problem only) solves the same."""
    import pickle

    from shaftline.film.stribeck import stribeck_curve
    from shaftline.film.study import BearingCase

    case = BearingCase("rig", RIG, OperatingPoint(speed=1.0, viscosity=1e-3, density=1000.0), SolverOptions(), -LOAD)
    speeds = np.array([10, 25, 60, 150]) * math.pi / 30
    serial = stribeck_curve(case, speeds, workers=1, chunk_size=2)
    pooled = stribeck_curve(case, speeds, workers=2, chunk_size=2)
    for name in ("friction_coefficient", "asperity_load_share", "min_film_thickness"):
        assert np.array_equal(getattr(serial, name), getattr(pooled, name)), name
    assert serial.regime == ("boundary", "mixed", "full film", "full film")
    bearing = _rig(15)
    copy = pickle.loads(pickle.dumps(bearing))
    a = bearing.equilibrium(load_y=-LOAD).state
    b = copy.equilibrium(load_y=-LOAD).state
    assert a.rough.asperity_load == b.rough.asperity_load and a.friction_force == b.friction_force


def test_stribeck_curve_runs_serially_below_the_work_estimate(monkeypatch: pytest.MonkeyPatch) -> None:
    """By default a curve of little work (30 speeds on 41 x 120: estimated 3 s) runs serially
    (the pool was twice as slow there, docs/validation.md); one of much work (500 speeds on
    161 x 240: 390 s) goes to the pool; an explicit workers, backend or scheduler is obeyed."""
    from shaftline import parallel
    from shaftline.film import stribeck
    from shaftline.film.study import BearingCase

    asked: list[str | None] = []

    def record(function: object, items: object, *, backend: str | None = None, **options: object) -> object:
        asked.append(backend)
        raise RuntimeError("recorded")

    monkeypatch.setattr(parallel, "map", record)
    operating = OperatingPoint(speed=1.0, viscosity=1e-3, density=1000.0)
    small = BearingCase("rig", RIG, operating, SolverOptions(), -LOAD)
    large = BearingCase("rig", RIG, operating, SolverOptions(axial_nodes=161, circumferential_nodes=240), -LOAD)
    assert stribeck.estimated_seconds(small, 30) < stribeck.POOL_MIN_SECONDS < stribeck.estimated_seconds(large, 500)
    for case, count, options in (
        (small, 30, {}),
        (large, 500, {}),
        (small, 30, {"workers": 2}),
        (small, 30, {"backend": "process"}),
    ):
        with pytest.raises(RuntimeError, match="recorded"):
            stribeck.stribeck_curve(case, np.geomspace(1.0, 40.0, count), **options)  # type: ignore[arg-type]
    assert asked == ["serial", None, None, "process"]
