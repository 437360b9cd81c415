"""Elastic liner (column/Winkler model) solved together with the film (issue 15 part B).

References: the column model's closed form (docs/theory.md, "Elastic liner"; Johnson, Contact
Mechanics, 1985, Sect. 5.9) checked against the Lame constants; the coupled solution against
that closed form node by node; the film-liner Jacobian against central differences of the
force; the trend of a compliant liner against a rigid bore (Conway & Lee 1975, Lahmar et al.
1998: the deformation lowers the load capacity at a given eccentricity, so under the same load
the journal runs more eccentric, with a lower and flatter pressure peak).
"""

from __future__ import annotations

import json
from dataclasses import replace
from pathlib import Path

import numpy as np
import pytest
import scipy.sparse as sp
from scipy.integrate import quad
from scipy.optimize import brentq

from shaftline.cases import load_case
from shaftline.errors import InputError
from shaftline.film import BearingGeometry, JournalBearing
from shaftline.film.elastic import CoupledOrderings, LinerSystem, film_operator, film_residual_jacobian
from shaftline.film.liner import LINER_PRESETS, Liner
from shaftline.film.options import LinerOptions
from shaftline.film.roughness import (
    BOUNDARY_LIMIT,
    RoughFilm,
    SurfaceRoughness,
    asperity_pressure,
    asperity_pressure_derivative,
)
from shaftline.film.stencil import apply_operator, build_stencil, stencil_derivative
from tests.conftest import invoke

ROOT = Path(__file__).resolve().parents[2]

#: The film-liner iteration's tolerance (max |R| over the clearance): ``LinerOptions.tolerance``.
LINER_TOLERANCE = LinerOptions().tolerance


@pytest.fixture(scope="module")
def ntua():  # noqa: ANN201 - the seed 004 base case
    return load_case(ROOT / "examples" / "ntua_stern_tube.toml").studies["bearing"].cases[0]


@pytest.mark.parametrize("name", sorted(LINER_PRESETS))
def test_column_compliance_is_the_constrained_modulus_of_the_lame_constants(name: str) -> None:
    # Uniaxial strain: sigma_zz = (lambda + 2 mu) eps_zz, with the Lame constants from E and nu.
    liner = Liner.preset(name)
    e, nu = liner.modulus, liner.poisson
    lame = e * nu / ((1 + nu) * (1 - 2 * nu))
    shear = e / (2 * (1 + nu))
    assert liner.deflection(1e6) == pytest.approx(1e6 * liner.thickness / (lame + 2 * shear), rel=1e-12)


def test_column_model_stiffens_without_bound_as_the_liner_becomes_incompressible() -> None:
    # (1 - 2 nu) -> 0: the column model's limit for rubber (docs/theory.md).
    compliances = [Liner(0.01, 7e6, nu).compliance for nu in (0.45, 0.49, 0.499, 0.4999)]
    assert all(b < 0.15 * a for a, b in zip(compliances[1:], compliances[2:], strict=False))
    assert compliances[-1] < 1e-3 * Liner(0.01, 7e6, 0.3).compliance


@pytest.mark.parametrize(
    ("kwargs", "field"),
    [
        ({"thickness": 0.0}, "thickness"),
        ({"thickness": -1e-3}, "thickness"),
        ({"modulus": 0.0}, "modulus"),
        ({"poisson": 0.5}, "poisson"),
        ({"poisson": 0.0}, "poisson"),
        ({"poisson": float("nan")}, "poisson"),
    ],
)
def test_bad_liner_is_refused_naming_the_field(kwargs: dict[str, float], field: str) -> None:
    values = {"thickness": 0.01, "modulus": 2e9, "poisson": 0.3, **kwargs}
    with pytest.raises(InputError) as caught:
        Liner(**values)
    assert caught.value.field == field


def test_liner_thicker_than_a_quarter_of_the_radius_is_refused() -> None:
    with pytest.raises(InputError) as caught:
        BearingGeometry(length=0.1, diameter=0.1, radial_clearance=1e-4, liner=Liner(0.013, 2e9, 0.3))
    assert caught.value.field == "liner.thickness"
    BearingGeometry(length=0.1, diameter=0.1, radial_clearance=1e-4, liner=Liner(0.0125, 2e9, 0.3))


def test_liner_needs_the_reynolds_condition(ntua) -> None:  # noqa: ANN001
    geometry = replace(ntua.geometry, liner=Liner.preset("white_metal"))
    with pytest.raises(InputError) as caught:
        JournalBearing(geometry, ntua.operating, replace(ntua.options, cavitation="half_sommerfeld"))
    assert caught.value.field == "options.cavitation"


def test_coupled_solution_obeys_the_column_law_node_by_node(ntua) -> None:  # noqa: ANN001
    # The converged deformation is the column model's closed form of the converged pressure
    # (film and asperities), to the Newton tolerance (1e-6 of the clearance).
    surface = SurfaceRoughness.preset("turned_steel_white_metal")
    liner = Liner.preset("polymer_composite")
    operating = replace(ntua.operating, speed=np.pi / 30)
    bearing = JournalBearing(replace(ntua.geometry, surface=surface, liner=liner), operating, ntua.options)
    eq = bearing.equilibrium(ntua.load_y, ntua.load_z)
    assert eq.converged
    state = eq.state
    assert state.liner is not None and state.rough is not None
    closed_form = liner.compliance * (state.pressure + state.rough.asperity_pressure)
    c = ntua.geometry.radial_clearance
    assert np.abs(state.liner.deformation - closed_form).max() <= LINER_TOLERANCE * c
    # The film is the rigid gap plus the deformation.
    rigid = bearing.film(state.position)
    np.testing.assert_allclose(state.film, rigid + state.liner.deformation, rtol=0, atol=1e-15)
    # The journal has passed the rigid bore surface into the liner, which leaves a film.
    assert rigid.min() < 0.0 < state.min_film_thickness
    assert state.max_liner_deformation > 1e-6  # micrometres: the test is not of a stiff liner


@pytest.mark.parametrize("rough", [False, True])
def test_film_residual_jacobian_is_the_stencil_derivative(rough: bool) -> None:
    # B = dr/dH assembled face by face against the film's directional derivative
    # (stencil_derivative, as the film's other linearisations use it), for random film changes,
    # with a squeeze rate (rough: the squeeze factor's derivative) on a small periodic grid.
    rng = np.random.default_rng(3)
    shape = (7, 12)
    film = 0.3 + rng.random(shape)
    pressure = rng.random(shape)
    rate = rng.standard_normal(shape)
    film_model = RoughFilm(0.2, 1.0) if rough else None
    jacobian = film_residual_jacobian(film, pressure, 0.5, 0.2, film_model, rate)
    for _ in range(3):
        change = rng.standard_normal(shape)
        dc_theta, dc_z, d_rhs = stencil_derivative(film, change, 0.5, 0.2, film_model, rate)
        expected = apply_operator(dc_theta, dc_z, pressure) - d_rhs
        np.testing.assert_allclose(jacobian @ change.ravel(), expected.ravel(), rtol=1e-12, atol=1e-12)


@pytest.mark.parametrize("rough", [False, True])
def test_coupled_matrix_in_a_kept_ordering_is_the_sparse_sum(rough: bool) -> None:
    # The coupled Newton matrix (A + B diag(K/M)) on the free nodes is assembled on the grid's
    # five-point pattern and factorised in an ordering kept per free set (elastic.py): its
    # Newton step must be that of the matrix formed by sparse arithmetic from film_operator
    # and film_residual_jacobian (both checked above), solved densely, to round-off (1e-10 of
    # the step: the matrix's condition number here is ~1e3); the second build of the same
    # free set factorises in the kept order (SuperLU's permutation then the identity).
    rng = np.random.default_rng(5)
    shape = (7, 12)
    film = 0.3 + rng.random(shape)
    pressure = rng.random(shape)
    rate = rng.standard_normal(shape)
    film_model = RoughFilm(0.2, 1.0) if rough else None
    held = rng.random(shape) < 0.3
    diagonal = 1.0 + rng.random(shape)
    coupling = 0.7
    stencil = build_stencil(film, 0.5, 0.2, rate, film_model)
    matrix = film_operator(stencil) + film_residual_jacobian(film, pressure, 0.5, 0.2, film_model, rate) @ sp.diags(
        coupling / diagonal.ravel()
    )
    free = ~held.ravel()
    dense = matrix.toarray()[np.ix_(free, free)]
    residual = rng.standard_normal(shape)
    jacobian = film_residual_jacobian(film, pressure, 0.5, 0.2, film_model, rate)
    expected = np.zeros(free.size)
    expected[free] = np.linalg.solve(dense, (jacobian @ (residual.ravel() / diagonal.ravel()))[free])
    orderings = CoupledOrderings()
    args = (stencil, film, pressure, held, 0.5, 0.2, film_model, rate, coupling, diagonal)
    for build in range(2):
        system = LinerSystem.build(*args, orderings)
        d_pressure, d_deformation = system.step(residual)
        np.testing.assert_allclose(d_pressure, expected, rtol=0, atol=1e-10 * np.abs(expected).max())
        np.testing.assert_allclose(d_deformation, (coupling * expected - residual.ravel()) / diagonal.ravel())
        assert len(orderings) == 1
        assert np.array_equal(system.factor.perm_c, np.arange(free.sum())) == (build == 1)


@pytest.mark.parametrize("rough", [False, True])
def test_film_liner_jacobian_matches_central_differences(ntua, rough: bool) -> None:  # noqa: ANN001
    # Frozen-set derivative of the coupled system (elastic.py) against central differences of the
    # converged force; the step (1e-4 of the clearance) moves no cavitation boundary node on
    # this grid, and the Newton tolerance 1e-6 c leaves differences accurate to ~1e-3.
    surface = SurfaceRoughness.preset("turned_steel_white_metal") if rough else None
    speed = np.pi / 30 if rough else ntua.operating.speed
    geometry = replace(ntua.geometry, surface=surface, liner=Liner.preset("polymer_composite"))
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
    scale = np.abs(numeric).max()
    assert np.abs(jacobian - numeric).max() <= 5e-3 * scale


@pytest.mark.parametrize("model", ["column", "layer"])
def test_either_liner_system_gives_the_film_change_of_the_linearised_coupled_equations(
    ntua,  # noqa: ANN001
    model: str,
) -> None:
    # The bearing asks the same of both liner models' Newton systems (elastic.CoupledLiner):
    # the film change dH = dH_r + dD (film_change) with the pressure change dP (response, along
    # film_direction) of a rigid film change dH_r must solve the linearised coupled equations,
    # checked here with matrices built independently of the systems: the film's
    # A dP + B dH = 0 on the free nodes (film_operator, film_residual_jacobian: tested above) and
    # the liner's M dD = K dP + (1 - M) dH_r (column, M = 1 - k p_a') or
    # dD = C (p_ref dP + p_a' c dH) / c (layer, C its operator applied by FFT). Tolerances: 1e-9
    # of the equation's largest term (column: a direct LU solve, round-off ~1e-12 at a condition
    # number ~1e3; layer: GMRES to a relative residual of 1e-10, LAYER_RESPONSE_RTOL).
    surface = SurfaceRoughness.preset("turned_steel_white_metal")
    liner = Liner.preset("polymer_composite", model=model)
    operating = replace(ntua.operating, speed=np.pi / 30)  # 1 rpm: asperity contact, M != 1
    bearing = JournalBearing(replace(ntua.geometry, surface=surface, liner=liner), operating, ntua.options)
    position = bearing.equilibrium(ntua.load_y, ntua.load_z).state.position
    solver = bearing.solver
    evaluation = solver.evaluate(position, warm=False)
    system = solver.liner_system(evaluation)
    c = ntua.geometry.radial_clearance
    d_ey, _ = solver.offset_directions(evaluation)
    _, d_pressure = solver.pressure_changes(evaluation, [(d_ey, None)])
    d_film = system.film_change(d_ey, d_pressure[0])
    d_deformation = system.deformation_change(d_ey, d_pressure[0])
    np.testing.assert_allclose(d_film, d_ey + d_deformation, rtol=0, atol=1e-12 * np.abs(d_film).max())
    # The film equation on the free nodes.
    free = ~(solver.nodes.fixed | evaluation.cavitated).ravel()
    film_nd = evaluation.film / c
    pressure = evaluation.relative_pressure
    jacobian = film_residual_jacobian(film_nd, pressure, solver.d_theta, solver.d_z, solver.flow, None)
    operator_part = film_operator(evaluation.stencil) @ d_pressure[0].ravel()
    film_part = jacobian @ d_film.ravel()
    scale = max(np.abs(operator_part[free]).max(), np.abs(film_part[free]).max())
    assert np.abs((operator_part + film_part)[free]).max() <= 1e-9 * scale
    # The liner equation on every node.
    slope = asperity_pressure_derivative(surface, evaluation.film)
    load = bearing.pressure_scale * d_pressure[0] + c * slope * d_film
    if model == "column":
        compliance = liner.compliance
        expected = compliance * (bearing.pressure_scale * d_pressure[0] + c * slope * d_ey) / c
        expected = expected / (1.0 - compliance * slope)
    else:
        expected = solver.layer_compliance().apply(load) / c
    assert np.abs(d_deformation - expected).max() <= 1e-9 * np.abs(expected).max()
    assert liner.compliance * np.abs(slope).max() > 1e-3  # 1 - M: the asperities' share is tested


def test_fixed_nodes_settled_node_by_node_save_film_solutions(ntua) -> None:  # noqa: ANN001
    # On the fixed-pressure nodes (the bearing's ends) of a column liner the liner equation
    # involves the node's own deformation only, through the asperity pressure (docs/theory.md,
    # "Elastic liner"): solved there by a scalar Newton iteration before each film solution,
    # the equilibrium needs fewer film solutions and reaches the same position (within 1e-6 of
    # the clearance, as from another start: test_lined_equilibrium_does_not_depend_on_its_start)
    # with the column law met node by node. Seed 001's polymer liner at 1 rpm, where the
    # asperities at the aft end carry ~1 MPa. Counted: the equilibrium's ``film_solutions`` (every
    # film solution of the lined grid and of its rigid start; 47 settled against 57 without the
    # node-by-node iteration, ``LinerOptions(fixed_iterations=0)``, as the cavitation solves the
    # test counted before the solver's counters).
    surface = SurfaceRoughness.preset("turned_steel_white_metal")
    geometry = replace(ntua.geometry, surface=surface, liner=Liner.preset("polymer_composite"))
    operating = replace(ntua.operating, speed=np.pi / 30)
    settled = JournalBearing(geometry, operating, ntua.options).equilibrium(ntua.load_y, ntua.load_z)
    unsettled = replace(ntua.options, liner=replace(ntua.options.liner, fixed_iterations=0))
    plain = JournalBearing(geometry, operating, unsettled).equilibrium(ntua.load_y, ntua.load_z)
    assert settled.converged and plain.converged
    assert settled.film_solutions < plain.film_solutions
    c = ntua.geometry.radial_clearance
    assert abs(settled.state.position.ey - plain.state.position.ey) <= 1e-6 * c
    assert abs(settled.state.position.ez - plain.state.position.ez) <= 1e-6 * c
    st = settled.state
    assert st.liner is not None and st.rough is not None
    law = geometry.liner.compliance * (st.pressure + st.rough.asperity_pressure)
    assert np.abs(st.liner.deformation - law).max() <= LINER_TOLERANCE * c


@pytest.mark.parametrize("name", ["white_metal", "polymer_composite"])
def test_lined_equilibrium_does_not_depend_on_its_start(ntua, name: str) -> None:  # noqa: ANN001
    # Without ``initial`` a lined equilibrium starts from the rigid bore's and solves the trials'
    # liners only as far as the force residual needs (inexact Newton); from a given start it
    # takes the same path the rigid start saves. Both must reach the same equilibrium: the
    # positions within 1e-6 of the clearance (the force tolerance 1e-8 of the load over a
    # stiffness of about W / h_min, h_min ~ 1e-3 c here, gives ~1e-5 c at worst; they agree far better).
    surface = SurfaceRoughness.preset("turned_steel_white_metal")
    operating = replace(ntua.operating, speed=np.pi / 30)
    geometry = replace(ntua.geometry, surface=surface, liner=Liner.preset(name))
    bearing = JournalBearing(geometry, operating, ntua.options)
    default = bearing.equilibrium(ntua.load_y, ntua.load_z)
    start = replace(default.state.position, ey=-0.5 * ntua.geometry.radial_clearance, ez=0.0)
    given = bearing.equilibrium(ntua.load_y, ntua.load_z, initial=start)
    assert default.converged and given.converged
    c = ntua.geometry.radial_clearance
    assert abs(default.state.position.ey - given.state.position.ey) <= 1e-6 * c
    assert abs(default.state.position.ez - given.state.position.ez) <= 1e-6 * c
    assert default.iterations < given.iterations  # the rigid start saves lined iterations
    # The converged liner is solved to the end on both paths (column law, node by node).
    for eq in (default, given):
        st = eq.state
        assert st.liner is not None and st.rough is not None
        law = geometry.liner.compliance * (st.pressure + st.rough.asperity_pressure)
        assert np.abs(st.liner.deformation - law).max() <= LINER_TOLERANCE * c


def test_a_neighbours_deformation_starts_the_liner_and_leaves_the_equilibrium() -> None:
    # A sweep (the Stribeck curve) starts each speed from its neighbour's position and set; its liner
    # started from the undeformed state, and on seed 001's lined rig the first film-liner iteration
    # of each speed was half the sweep (8.5 -> 4.0 s with the neighbour's deformation; the NTUA lined
    # sweeps are unchanged, 5.6 and 4.5 s). From the neighbour's deformation the same equilibrium
    # comes out (positions within 1e-6 c, as from any start above) with fewer film solutions: the
    # equilibrium's ``film_solutions`` (every film solution it took, 56 against 237 undeformed, as
    # the cavitation solves the test counted before the solver's counters).
    study = load_case(ROOT / "examples" / "seed001_water_rig_liner.toml").studies["bearing"]
    case = study.cases[0]
    neighbour = JournalBearing(case.geometry, replace(case.operating, speed=20 * np.pi / 30), case.options).equilibrium(
        case.load_y, case.load_z
    )
    bearing = JournalBearing(case.geometry, replace(case.operating, speed=24 * np.pi / 30), case.options)
    found = {}
    for name, deformation in (("undeformed", None), ("neighbour", neighbour.state.liner.deformation)):
        found[name] = bearing.equilibrium(
            case.load_y,
            case.load_z,
            initial=neighbour.state.position,
            initial_cavitated=neighbour.state.cavitated,
            initial_deformation=deformation,
        )
    a, b = found["undeformed"], found["neighbour"]
    assert neighbour.converged and a.converged and b.converged
    c = case.geometry.radial_clearance
    assert abs(a.state.position.ey - b.state.position.ey) <= 1e-6 * c
    assert abs(a.state.position.ez - b.state.position.ez) <= 1e-6 * c
    assert b.film_solutions < a.film_solutions
    for bad in (np.full_like(neighbour.state.liner.deformation, np.nan), neighbour.state.liner.deformation.T):
        with pytest.raises(InputError, match="initial_deformation"):
            bearing.equilibrium(case.load_y, case.load_z, initial_deformation=bad)


def test_soft_liner_lowers_and_flattens_the_pressure_under_the_same_load(ntua) -> None:  # noqa: ANN001
    # Seed 004's bearing at 90 rpm with its misalignment: rigid, white metal, polymer, rubber.
    # Published trend (Conway & Lee 1975; Lahmar et al. 1998): a more compliant liner carries the
    # same load at a larger eccentricity with a lower pressure peak; h_min falls with it (the
    # column model holds the film at the edges, at ambient pressure, to the rigid gap).
    results = []
    for liner in (None, Liner.preset("white_metal"), Liner.preset("polymer_composite"), Liner.preset("rubber")):
        bearing = JournalBearing(replace(ntua.geometry, liner=liner), ntua.operating, ntua.options)
        eq = bearing.equilibrium(ntua.load_y, ntua.load_z, tilt_y=ntua.tilt_y, tilt_z=ntua.tilt_z)
        assert eq.converged
        results.append(eq.state)
    p_max = [s.max_pressure for s in results]
    e = [s.eccentricity_ratio for s in results]
    assert all(b < a for a, b in zip(p_max, p_max[1:], strict=False)), p_max
    assert all(b > a for a, b in zip(e, e[1:], strict=False)), e
    # Same load carried.
    for s in results:
        assert s.load_capacity == pytest.approx(results[0].load_capacity, rel=1e-6)
    # Magnitudes: white metal changes p_max by < 0.1 %, rubber by more than 10 %.
    assert p_max[1] == pytest.approx(p_max[0], rel=1e-3)
    assert p_max[3] < 0.9 * p_max[0]


def dry_column_contact_peak(liner: Liner, load: float, radius: float, length: float, clearance: float) -> float:
    """Peak pressure (Pa) of an aligned journal pressed dry into a column-model liner: at a
    journal offset e > c the liner is compressed by e cos(theta) - c over |theta| < arccos(c/e),
    carrying (e cos(theta) - c)/k there (the column law, Johnson 1985 Sect. 5.9, thin layer), so
    W = L R int (e cos - c)/k cos d(theta) fixes e, and the peak is (e - c)/k."""
    k = liner.compliance

    def carried(e: float) -> float:
        half = np.arccos(clearance / e)
        return length * radius * quad(lambda t: (e * np.cos(t) - clearance) / k * np.cos(t), -half, half)[0]

    e = brentq(lambda e: carried(e) - load, clearance * (1 + 1e-12), 2 * clearance)
    return (e - clearance) / k


def test_soft_liner_raises_the_film_and_lowers_the_peak_under_heavy_load(ntua) -> None:  # noqa: ANN001
    # The trend turns with the load. Lightly loaded (90 rpm, test above) the liner costs load
    # capacity: h_min falls a little. Heavily loaded (seed 004's bearing aligned at 0.5 rpm, rough
    # turned-steel / white-metal surfaces, lambda_min 0.2 on the rigid bore, asperities carrying a
    # third of the load) seed 001's polymer liner spreads the contact: h_min rises, the peak
    # falls and the asperity share drops by more than an order of magnitude (the trend of soft EHL
    # journal bearings the issue names). Magnitude: with the film thin against the deformation
    # (3.6 um against 18 um) the pressure tends to that of the dry contact on the same liner (the
    # soft-EHL limit: Essink et al., J. Fluid Mech. 915 (2021) A49, the large-deformation regime
    # of thin layers), whose peak is the column law's closed form: within 10 % (the film's share
    # of the gap, h / u ~ 0.2, is what separates the two).
    surface = SurfaceRoughness.preset("turned_steel_white_metal")
    operating = replace(ntua.operating, speed=0.5 * np.pi / 30)
    liner = Liner.preset("polymer_composite")
    states = []
    for lining in (None, liner):
        bearing = JournalBearing(replace(ntua.geometry, surface=surface, liner=lining), operating, ntua.options)
        eq = bearing.equilibrium(ntua.load_y, ntua.load_z)
        assert eq.converged and not eq.contact
        states.append(eq.state)
    rigid, lined = states
    assert rigid.min_film_ratio < 0.5 and rigid.asperity_load_share > 0.2  # heavily loaded indeed
    assert lined.min_film_thickness > 1.5 * rigid.min_film_thickness
    assert lined.max_pressure < 0.6 * rigid.max_pressure
    assert lined.asperity_load_share < 0.05 * rigid.asperity_load_share
    geometry = ntua.geometry
    peak = dry_column_contact_peak(liner, -ntua.load_y, geometry.radius, geometry.length, geometry.radial_clearance)
    assert lined.max_pressure == pytest.approx(peak, rel=0.1)
    # The column model's own limit: the edges (ambient pressure) keep the thinnest film; inside,
    # the film is several times thicker than on the rigid bore.
    nz = lined.film.shape[0]
    assert lined.film[nz // 2].min() > 4.0 * rigid.film[nz // 2].min()


@pytest.mark.slow
def test_lined_rig_at_low_speed_is_carried_by_the_end_rows_asperities() -> None:
    # Seed 001's rig on its liner at 35 rpm (docs/theory.md, "Elastic liner" and "Boundary
    # lubrication"): at the bearing's end rows the film pressure is ambient, so the column model
    # deforms the liner there only under the asperity pressure. While the film stopped at the mean
    # plane that pressure was capped at K E* F_5/2(0), the eccentricity at 1 + k p_a,max / c, and
    # the rig ended in contact. With the film below the mean plane the end rows' asperities carry
    # what the film does not: the equilibrium converges with its thinnest film on an end row below
    # the mean plane, its asperities above the former cap, the journal past the former limit (by
    # more than the floor's film, 1e-3 c) and within the boundary limit's.
    case = load_case(ROOT / "examples" / "seed001_water_rig_liner.toml").studies["bearing"].cases[0]
    bearing = JournalBearing(case.geometry, replace(case.operating, speed=35 * np.pi / 30), case.options)
    eq = bearing.equilibrium(case.load_y, case.load_z)
    assert eq.converged and not eq.contact
    state = eq.state
    surface, liner = case.geometry.surface, case.geometry.liner
    assert surface is not None and liner is not None and state.rough is not None
    row, _ = np.unravel_index(np.argmin(state.film), state.film.shape)
    assert row in (0, state.film.shape[0] - 1)  # the thinnest film is on an end row
    assert state.film.min() < 0.0
    cap = float(asperity_pressure(surface, np.zeros(1))[0])
    assert state.rough.asperity_pressure[row].max() > cap
    c = case.geometry.radial_clearance
    assert state.eccentricity_ratio > 1.0 + liner.compliance * cap / c + 1e-3
    limit = float(asperity_pressure(surface, np.array([BOUNDARY_LIMIT * surface.sigma]))[0])
    assert state.eccentricity_ratio < 1.0 + liner.compliance * limit / c
    # The interior still has a film of micrometres: the boundary regime is the ends' alone.
    assert state.film[state.film.shape[0] // 2].min() > 1e-6


def test_stiff_liner_reproduces_the_rigid_bore(ntua) -> None:  # noqa: ANN001
    # A 0.1 mm liner of 500 GPa deflects 1e-16 m/Pa: 0.1 nm at the 1.2 MPa peak, 1e-6 of h_min.
    stiff = Liner(1e-4, 5e11, 0.3)
    rigid = JournalBearing(ntua.geometry, ntua.operating, ntua.options).equilibrium(ntua.load_y, ntua.load_z)
    lined = JournalBearing(replace(ntua.geometry, liner=stiff), ntua.operating, ntua.options).equilibrium(
        ntua.load_y, ntua.load_z
    )
    assert lined.state.min_film_thickness == pytest.approx(rigid.state.min_film_thickness, rel=1e-5)
    assert lined.state.max_pressure == pytest.approx(rigid.state.max_pressure, rel=1e-5)
    assert rigid.state.liner is None


def test_linearisation_with_a_liner_is_that_of_the_equilibrium(ntua) -> None:  # noqa: ANN001
    bearing = JournalBearing(
        replace(ntua.geometry, liner=Liner.preset("polymer_composite")), ntua.operating, ntua.options
    )
    eq = bearing.equilibrium(ntua.load_y, ntua.load_z)
    lin = bearing.linearise(eq.state.position)
    np.testing.assert_allclose(lin.force, [eq.state.force_y, eq.state.force_z], rtol=1e-5)
    assert lin.stiffness[0, 0] > 0


RIG = """
[case]
name = "rig"

[bearing]
length = "1.2 m"
diameter = "0.323 m"
radial_clearance = "0.55 mm"

[bearing.operation]
speed = "175 rpm"
load = "20 kN"

[bearing.lubricant]
preset = "water"
temperature = "25 degC"

[bearing.liner]
preset = "polymer_composite"

[bearing.solver]
axial_nodes = 21
circumferential_nodes = 60
"""


def test_liner_results_in_json_and_report(tmp_path: Path) -> None:
    case = tmp_path / "rig.toml"
    case.write_text(RIG)
    out = tmp_path / "out"
    result = invoke("bearing", "solve", str(case), "--out", str(out), "--workers", "1")
    assert result.exit_code == 0, result.output
    bearing = json.loads((out / "results.json").read_text())["bearing"]
    base = bearing["cases"][0]
    assert bearing["units"]["max_liner_deformation"] == "m"
    deformation = np.array(base["liner_deformation_map"])
    assert deformation.shape == (21, 60)
    assert base["max_liner_deformation"] == pytest.approx(deformation.max(), rel=1e-6)
    assert 1e-7 < base["max_liner_deformation"] < 1e-4
    assert (out / "figures" / "bearing_0_liner.png").exists()
    assert "max liner deformation" in result.stdout


@pytest.mark.parametrize(
    ("old", "new", "field"),
    [
        ('preset = "polymer_composite"', 'thickness = "0 mm"\nmodulus = "2 GPa"\npoisson = 0.3', "thickness"),
        ('preset = "polymer_composite"', 'thickness = "50 mm"\nmodulus = "2 GPa"\npoisson = 0.3', "thickness"),
        ('preset = "polymer_composite"', 'preset = "polymer_composite"\npoisson = 0.5', "poisson"),
        ('preset = "polymer_composite"', 'preset = "polymer_composite"\nmodulus = "0 MPa"', "modulus"),
        ('preset = "polymer_composite"', 'thickness = "10 mm"\nmodulus = "2 GPa"', "poisson"),
    ],
)
def test_bad_liner_table_is_one_line_exit_2(tmp_path: Path, old: str, new: str, field: str) -> None:
    case = tmp_path / "rig.toml"
    case.write_text(RIG.replace(old, new))
    result = invoke("bearing", "solve", str(case), "--json", str(tmp_path / "r.json"))
    assert result.exit_code == 2, result.output
    lines = [line for line in result.stderr.splitlines() if line.strip()]
    assert len(lines) == 1 and lines[0].startswith(f"error: bearing.liner.{field} = "), lines
    assert not (tmp_path / "r.json").exists()


def test_the_white_metal_liner_has_the_white_metal_surfaces_elastic_data():
    """One material, one set of data: the liner preset and the roughness presets both take tin
    babbitt ASTM B23 grade 2 (E 53 GPa, nu 0.35)."""
    liner = Liner.preset("white_metal")
    assert (liner.modulus, liner.poisson) == (53.0e9, 0.35)
