"""The film solved with an elastic-layer liner (film/elastic.py LayerSystem, bearing.py;
docs/theory.md Sect. 17, "Elastic layer").

References: the layer's compliance operator itself (the converged deformation is the operator
applied to the converged pressure, node by node); central differences of the converged force
(the equilibrium's Jacobian); the column model as the layer's thin limit (a liner thin against
the pressure zone solves to the column model's equilibrium); and the bad-input rules.
"""

from __future__ import annotations

import json
from dataclasses import replace
from pathlib import Path

import numpy as np
import pytest

from shaftline.cases import load_case
from shaftline.errors import InputError
from shaftline.film import JournalBearing
from shaftline.film.layer import layer_operator
from shaftline.film.liner import Liner
from shaftline.film.roughness import SurfaceRoughness, gaussian_integral
from tests.conftest import invoke
from tests.film.test_liner import LINER_TOLERANCE, RIG

ROOT = Path(__file__).resolve().parents[2]


@pytest.fixture(scope="module")
def ntua():  # noqa: ANN201 - the seed 004 base case
    return load_case(ROOT / "examples" / "ntua_stern_tube.toml").studies["bearing"].cases[0]


def test_coupled_solution_obeys_the_layer_compliance_node_by_node(ntua) -> None:  # noqa: ANN001
    # The converged deformation is the layer operator (built afresh here) applied to the
    # converged film and asperity pressure, to the liner tolerance of the converged equilibrium
    # (at most 1e-9 of the clearance); the film is the rigid gap plus that deformation.
    surface = SurfaceRoughness.preset("turned_steel_white_metal")
    liner = Liner.preset("polymer_composite", model="layer")
    operating = replace(ntua.operating, speed=np.pi / 30)
    bearing = JournalBearing(replace(ntua.geometry, surface=surface, liner=liner), operating, ntua.options)
    eq = bearing.equilibrium(ntua.load_y, ntua.load_z)
    assert eq.converged
    state = eq.state
    assert state.liner is not None and state.rough is not None
    nz, nt = state.film.shape
    layer = layer_operator(
        (nz, nt),
        ntua.geometry.radius,
        ntua.geometry.length / (nz - 1),
        liner.thickness,
        liner.modulus,
        liner.poisson,
        half_end_cells=True,
    )
    expected = layer.apply(state.pressure + state.rough.asperity_pressure)
    c = ntua.geometry.radial_clearance
    assert np.abs(state.liner.deformation - expected).max() <= LINER_TOLERANCE * c
    rigid = bearing.film(state.position)
    np.testing.assert_allclose(state.film, rigid + state.liner.deformation, rtol=0, atol=1e-15)
    assert state.max_liner_deformation > 1e-6  # micrometres: not a stiff liner
    # The layer spreads the load: the deformation is not the column law of the local pressure.
    column = liner.compliance * (state.pressure + state.rough.asperity_pressure)
    assert np.abs(state.liner.deformation - column).max() > 0.05 * column.max()


@pytest.mark.parametrize("rough", [False, True])
def test_film_layer_jacobian_matches_central_differences(ntua, rough: bool) -> None:  # noqa: ANN001
    # The equilibrium's Jacobian with the layer following (LayerSystem.response, GMRES to 1e-10)
    # against central differences of the converged force, as for the column model
    # (tests/film/test_liner.py): a step of 1e-4 of the clearance moves no cavitation boundary
    # node here, so the differences are accurate to ~1e-3; tolerance 5e-3 of the largest entry.
    surface = SurfaceRoughness.preset("turned_steel_white_metal") if rough else None
    speed = np.pi / 30 if rough else ntua.operating.speed
    geometry = replace(ntua.geometry, surface=surface, liner=Liner.preset("polymer_composite", model="layer"))
    bearing = JournalBearing(geometry, replace(ntua.operating, speed=speed), ntua.options)
    eq = bearing.equilibrium(ntua.load_y, ntua.load_z)
    position = eq.state.position
    solver = bearing.solver
    evaluation = solver.evaluate(position, warm=False)
    jacobian = solver.position_response(evaluation)[0]
    step = 1e-4 * ntua.geometry.radial_clearance
    columns = []
    for axis in ("ey", "ez"):
        forces = []
        for sign in (1.0, -1.0):
            moved = replace(position, **{axis: getattr(position, axis) + sign * step})
            forces.append(solver.evaluate(moved, warm=False, deformation=evaluation.deformation).force)
        columns.append((forces[0] - forces[1]) / (2 * step))
    numeric = np.column_stack(columns)
    assert np.abs(jacobian - numeric).max() <= 5e-3 * np.abs(numeric).max()


def test_thin_layer_solves_to_the_column_equilibrium(ntua) -> None:  # noqa: ANN001
    # (a) in the coupled solution: a 1 mm polymer liner (E 2320 MPa, nu 0.327) is thin against
    # the pressure zone (hundreds of mm) and the grid (5.9 mm x 10 mm on 100 x 60 of the NTUA
    # bearing), so the layer's deformation is the column law but within about t of the ends and
    # of the pressure's steepest features. Reference: the column model's equilibrium; tolerance
    # 1 % on h_min, p_max and the largest deformation (the layer's next term, of order
    # (k t)^2 at the grid's shortest waves, is a few 1e-3).
    thin = (0.001, 2.32e9, 0.327)
    results = {}
    for model in ("column", "layer"):
        geometry = replace(ntua.geometry, liner=Liner(*thin, model=model))
        eq = JournalBearing(geometry, ntua.operating, ntua.options).equilibrium(ntua.load_y, ntua.load_z)
        assert eq.converged
        results[model] = eq.state
    column, layer = results["column"], results["layer"]
    assert layer.max_pressure == pytest.approx(column.max_pressure, rel=1e-2)
    assert layer.min_film_thickness == pytest.approx(column.min_film_thickness, rel=1e-2)
    assert layer.max_liner_deformation == pytest.approx(column.max_liner_deformation, rel=1e-2)


def test_layer_model_input() -> None:
    # nu = 0.5 (incompressible rubber) only with the layer model; an unknown model is refused.
    Liner(0.01, 7e6, 0.5, model="layer")
    with pytest.raises(InputError) as caught:
        Liner(0.01, 7e6, 0.5)
    assert caught.value.field == "poisson"
    with pytest.raises(InputError) as caught:
        Liner(0.01, 7e6, 0.6, model="layer")
    assert caught.value.field == "poisson"
    with pytest.raises(InputError) as caught:
        Liner(0.01, 7e6, 0.4, model="plate")  # type: ignore[arg-type]
    assert caught.value.field == "model"
    assert Liner(0.01, 7e6, 0.5, model="layer").compliance == 0.0  # the column limit of rubber


def test_rubber_layer_liner_deforms_where_the_column_model_cannot(ntua) -> None:  # noqa: ANN001
    # An incompressible rubber liner (10 mm, 7 MPa, nu 0.5): the column model has no deformation
    # at all (M infinite); the layer bulges under the pressure gradients (8.5 um here, 5 % of the
    # film: u^ = k^2 t^3 p^ / 3G is small for waves long against t) and carries the same load
    # with a lower peak and a thinner film than the rigid bore (the light-load trend of
    # compliant bearings, docs/theory.md "Elastic liner"). Bounds: half the computed changes.
    rubber = Liner(0.01, 7e6, 0.5, model="layer")
    rigid = JournalBearing(ntua.geometry, ntua.operating, ntua.options).equilibrium(ntua.load_y, ntua.load_z)
    eq = JournalBearing(replace(ntua.geometry, liner=rubber), ntua.operating, ntua.options).equilibrium(
        ntua.load_y, ntua.load_z
    )
    assert eq.converged
    assert eq.state.max_liner_deformation > 0.025 * eq.state.min_film_thickness
    assert eq.state.max_pressure < 0.98 * rigid.state.max_pressure
    assert eq.state.min_film_thickness < 0.93 * rigid.state.min_film_thickness


def test_layer_model_from_the_case_table(tmp_path: Path) -> None:
    # [bearing.liner] model = "layer"; poisson 0.5 with the column model is one line, exit 2.
    rig = RIG
    case = tmp_path / "rig.toml"
    case.write_text(rig.replace('preset = "polymer_composite"', 'preset = "polymer_composite"\nmodel = "layer"'))
    loaded = load_case(case).studies["bearing"].cases[0]
    assert loaded.geometry.liner is not None and loaded.geometry.liner.model == "layer"
    case.write_text(rig.replace('preset = "polymer_composite"', 'preset = "rubber"\npoisson = 0.5'))
    result = invoke("bearing", "solve", str(case), "--json", str(tmp_path / "r.json"))
    assert result.exit_code == 2, result.output
    lines = [line for line in result.stderr.splitlines() if line.strip()]
    assert len(lines) == 1 and lines[0].startswith("error: bearing.liner.poisson = "), lines
    case.write_text(rig.replace('preset = "polymer_composite"', 'preset = "rubber"\npoisson = 0.5\nmodel = "layer"'))
    assert load_case(case).studies["bearing"].cases[0].geometry.liner.poisson == 0.5


@pytest.mark.slow
def test_layer_on_the_lined_rig_lifts_the_end_film_and_runs_the_low_speed_ends_in_boundary() -> None:
    # Seed 001's rig on its 20 mm polymer liner, column against layer (docs/validation.md,
    # "Elastic layer on seed 001's rig"). At 135 rpm (the column model's thinnest film on an end
    # row) on 161 axial rows (dz = 0.375 t, the layer's ends resolved): the layer moves the end
    # rows under the nearby film pressure and lifts h_min (1.50 against 1.08 um) and the
    # mid-plane film (6.25 against 5.62 um). At 35 rpm on the example's grid both ended in contact
    # on an end row while the film stopped at the mean plane; with the film below it (docs/theory.md,
    # "Boundary lubrication") the layer converges with the end row's film below the mean plane
    # (lambda -0.74) and its asperities above the former cap K E* F_5/2(0). Bounds: half the
    # computed margins.
    case = load_case(ROOT / "examples" / "seed001_water_rig_liner.toml").studies["bearing"].cases[0]
    assert case.geometry.liner is not None
    fine = replace(case.options, axial_nodes=161)
    states = {}
    for model in ("column", "layer"):
        geometry = replace(case.geometry, liner=replace(case.geometry.liner, model=model))
        bearing = JournalBearing(geometry, replace(case.operating, speed=135 * np.pi / 30), fine)
        states[model] = bearing.equilibrium(case.load_y, case.load_z)
    column, layer = states["column"], states["layer"]
    assert column.converged and layer.converged
    assert layer.state.min_film_thickness > 1.2 * column.state.min_film_thickness
    assert layer.state.film[80].min() > 1.05 * column.state.film[80].min()
    geometry = replace(case.geometry, liner=replace(case.geometry.liner, model="layer"))
    slow = JournalBearing(geometry, replace(case.operating, speed=35 * np.pi / 30), case.options)
    eq = slow.equilibrium(case.load_y, case.load_z)
    assert eq.converged and not eq.contact
    row, _ = np.unravel_index(np.argmin(eq.state.film), eq.state.film.shape)
    assert row in (0, eq.state.film.shape[0] - 1)
    assert eq.state.min_film_ratio < -0.3
    surface = case.geometry.surface
    assert surface is not None
    cap = float(surface.greenwood_tripp_constant * gaussian_integral(2.5, 0.0))
    assert eq.state.rough.max_asperity_pressure > 1.5 * cap


def test_under_resolved_layer_is_noted(tmp_path: Path) -> None:
    # An axial step above half the liner thickness leaves the layer's ends unresolved (the rig
    # at 135 rpm: end film 0.58 um on 41 rows, 1.50 on 161): a note naming the nodes needed.
    case = tmp_path / "rig.toml"
    case.write_text(RIG.replace('preset = "polymer_composite"', 'preset = "polymer_composite"\nmodel = "layer"'))
    result = invoke("bearing", "solve", str(case), "--json", "-", "--workers", "1")
    assert result.exit_code == 0, result.output
    (note,) = [text for text in json.loads(result.stdout)["warnings"] if "liner.model = layer" in text]
    assert "axial step of 60 mm" in note and "axial_nodes to 121 or more" in note
    fine = RIG.replace("axial_nodes = 21", "axial_nodes = 121")
    case.write_text(fine.replace('preset = "polymer_composite"', 'preset = "polymer_composite"\nmodel = "layer"'))
    result = invoke("bearing", "solve", str(case), "--json", "-", "--workers", "1")
    assert result.exit_code == 0, result.output
    assert "warnings" not in json.loads(result.stdout)
