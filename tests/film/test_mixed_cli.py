"""``[bearing.surface]`` on the command line: the mixed-lubrication results in the JSON and
the report, ``shaftline bearing stribeck``, and bad input (exit 2, one line, nothing written)."""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest

from shaftline.film.stribeck import solved_transition, transition_speed
from tests.conftest import invoke

RIG = """
[case]
name = "rig"

[bearing]
length = "1.2 m"
diameter = "0.323 m"
radial_clearance = "0.55 mm"

[bearing.operation]
speed = "35 rpm"
load = "75 kN"

[bearing.lubricant]
preset = "water"
temperature = "25 degC"

[bearing.surface]
journal_roughness = "0.8 um"
bore_roughness = "1.6 um"
bore_modulus = "2320 MPa"
bore_poisson = 0.327

[bearing.stribeck]
lowest = "20 rpm"
highest = "300 rpm"
points = 8

[bearing.solver]
axial_nodes = 21
circumferential_nodes = 120
"""


@pytest.fixture
def rig(tmp_path: Path) -> Path:
    path = tmp_path / "rig.toml"
    path.write_text(RIG)
    return path


def test_solve_reports_the_mixed_lubrication_results(rig: Path) -> None:
    result = invoke("bearing", "solve", str(rig), "--json", "-", "--workers", "1")
    assert result.exit_code == 0, result.output
    bearing = json.loads(result.stdout)["bearing"]
    base = bearing["cases"][0]
    assert base["lubrication_regime"] == "boundary" and 0.0 < base["min_film_ratio"] < 1.0
    assert 0.0 < base["asperity_load_share"] < 1.0 and base["max_asperity_pressure"] > 0.0
    assert base["boundary_friction_force"] + base["fluid_friction_force"] == pytest.approx(base["friction_force"])
    assert bearing["units"]["max_asperity_pressure"] == "Pa"
    assert "stribeck" not in bearing


@pytest.mark.parametrize(("speed", "verdict"), [("35 rpm", "wear is expected"), ("100 rpm", "wear is possible")])
def test_the_mixed_finding_expects_wear_only_above_the_transition_share(
    tmp_path: Path, speed: str, verdict: str
) -> None:
    """At 35 rpm the asperities carry a few per cent of the load: wear is expected; at 100 rpm,
    still in mixed lubrication by lambda, under 1 % (the share that defines the transition
    speed): light contact, wear possible."""
    path = tmp_path / "rig.toml"
    path.write_text(RIG.replace('speed = "35 rpm"', f'speed = "{speed}"'))
    result = invoke("bearing", "solve", str(path), "--json", "-", "--workers", "1")
    assert result.exit_code == 0, result.output
    base = json.loads(result.stdout)["bearing"]["cases"][0]
    assert (base["asperity_load_share"] >= 0.01) == (verdict == "wear is expected")
    assert verdict in " ".join((result.stdout + " " + result.stderr).split())  # terminal lines wrap


def test_smooth_case_json_has_no_mixed_keys(tmp_path: Path) -> None:
    path = tmp_path / "smooth.toml"
    text = RIG.split("[bearing.surface]")[0] + "[bearing.solver]" + RIG.split("[bearing.solver]")[1]
    path.write_text(text.replace('speed = "35 rpm"', 'speed = "300 rpm"'))
    result = invoke("bearing", "solve", str(path), "--json", "-", "--workers", "1")
    assert result.exit_code == 0, result.output
    bearing = json.loads(result.stdout)["bearing"]
    assert "min_film_ratio" not in bearing["cases"][0] and "asperity_load" not in bearing["units"]


def test_stribeck_verb_writes_curve_and_figures(rig: Path, tmp_path: Path) -> None:
    out = tmp_path / "out"
    result = invoke("bearing", "stribeck", str(rig), "--out", str(out), "--workers", "1")
    assert result.exit_code == 0, result.output
    assert "Stribeck curve of the base case" in result.stdout
    curve = json.loads((out / "results.json").read_text())["bearing"]["stribeck"]
    assert len(curve["speed_rpm"]) == 8 and curve["speed_rpm"][0] == pytest.approx(20.0)
    share = np.array(curve["asperity_load_share"])
    assert share[0] > 0.01 > share[-1]
    assert transition_speed(np.array(curve["speed_rpm"]), share) == pytest.approx(curve["transition_speed_rpm"])
    for name in ("bearing_stribeck.png", "bearing_0_contact.png"):
        assert (out / "figures" / name).stat().st_size > 10_000


def test_transition_speed_interpolates_in_log_speed() -> None:
    speed = np.array([1.0, 10.0, 100.0])
    # 2 % at 10, 0 % at 100: 1 % halfway in log speed, at sqrt(10 * 100).
    assert transition_speed(speed, np.array([0.5, 0.02, 0.0])) == pytest.approx(np.sqrt(1000.0))
    assert transition_speed(speed, np.array([0.005, 0.0, 0.0])) is None  # lifted off from the start
    assert transition_speed(speed, np.array([0.5, 0.2, 0.1])) is None  # never lifts off


def test_transition_speed_from_the_solved_speeds_only() -> None:
    # A speed that did not converge is no solution: its share does not enter the transition. Solved:
    # 2 % at 10, 0 % at 100 rpm-units; the stalled speed at 30 (share 0.5, nonsense) lies between
    # them, so the transition (at sqrt(1000) from the solved pair) is uncertain.
    speed = np.array([1.0, 10.0, 30.0, 100.0])
    share = np.array([0.5, 0.02, 0.5, 0.0])
    converged = np.array([True, True, False, True])
    contact = np.zeros(4, bool)
    transition, uncertain = solved_transition(speed, share, converged, contact)
    assert transition == pytest.approx(np.sqrt(1000.0)) and uncertain
    # the stalled speed below the solved bracket: the transition stands
    converged = np.array([False, True, True, True])
    share = np.array([0.5, 0.5, 0.02, 0.0])
    transition, uncertain = solved_transition(np.array([1.0, 3.0, 10.0, 100.0]), share, converged, contact)
    assert transition == pytest.approx(np.sqrt(1000.0)) and not uncertain
    # a speed at the film floor counts as carried by the asperities alone (share 1)
    contact = np.array([False, False, True, False])
    share = np.array([0.5, 0.02, 0.0, 0.0])
    transition, uncertain = solved_transition(speed, share, np.array([True, True, False, True]), contact)
    assert transition == pytest.approx(30.0**0.01 * 100.0**0.99) and not uncertain
    # stalled speeds below every solved one, all lifted off: the transition may be among them
    transition, uncertain = solved_transition(
        speed, np.array([0.5, 0.5, 0.0, 0.0]), np.array([False, False, True, True]), np.zeros(4, bool)
    )
    assert transition is None and uncertain


def test_a_real_curve_keeps_its_unsolved_speeds_apart() -> None:
    # seed 001's rigid rig on 120 nodes stalls below about 21 rpm (contact zone unresolved, docs/
    # validation.md "Rigid rough bore at low speed"): on 5, 30, 100 rpm the 5 rpm speed is no
    # solution. It has no regime, the transition (between 30 and 100 rpm, solved) is certain, and
    # the figure draws it as its own series, off the curve (whose line breaks there).
    import matplotlib

    matplotlib.use("Agg")
    from shaftline.cases import load_case
    from shaftline.film import figures
    from shaftline.film.stribeck import stribeck_curve

    case = load_case(Path(__file__).parents[2] / "examples" / "seed001_water_rig.toml").studies["bearing"].cases[0]
    curve = stribeck_curve(case, np.array([5.0, 30.0, 100.0]) * np.pi / 30, backend="serial")
    assert list(curve.stalled) == [True, False, False]
    assert curve.regime[0] is None and curve.regime[1] is not None
    assert curve.transition_speed is not None and 30 < curve.transition_speed * 30 / np.pi < 100
    assert not curve.transition_uncertain
    ax = figures.stribeck(curve)
    labels = {line.get_label(): line for line in ax[0].get_lines()}
    apart = labels["not converged: no solution"]
    assert list(apart.get_xdata()) == pytest.approx([5.0])
    assert np.isnan(labels["friction coefficient"].get_ydata()[0])


def test_a_transition_among_unsolved_speeds_is_not_acceptable() -> None:
    # The curve's finding is advisory while the transition rests on solved speeds, and makes the run
    # not acceptable (criterion False: exit 3 without --strict) when it does not.
    from shaftline.cases import load_case
    from shaftline.film.capability import _stribeck_findings
    from shaftline.film.stribeck import StribeckCurve

    case = load_case(Path(__file__).parents[2] / "examples" / "seed001_water_rig.toml").studies["bearing"].cases[0]
    rpm = np.array([10.0, 30.0, 100.0])
    zeros = np.zeros(3)
    flags = {"converged": np.array([True, False, True]), "contact": np.zeros(3, bool)}
    for uncertain in (False, True):
        curve = StribeckCurve(
            rpm * np.pi / 30,
            zeros,
            zeros,
            zeros,
            zeros,
            (None,) * 3,
            **flags,
            transition_speed=5.0,
            transition_uncertain=uncertain,
        )
        (finding,) = _stribeck_findings(curve, case)
        assert finding.criterion is not uncertain
        assert ("transition speed rests on them" in " ".join(finding.text.split())) is uncertain


@pytest.mark.parametrize(
    ("replace", "field"),
    [
        (('bore_roughness = "1.6 um"', 'bore_roughness = "-1.6 um"'), "bearing.surface.bore_roughness"),
        (('bore_roughness = "1.6 um"', 'bore_roughness = "300 um"'), "bearing.surface.bore_roughness"),
        (('bore_roughness = "1.6 um"', 'bore_roughness = "0 um"\njournal_roughness = "0 um"'), None),
        (("bore_poisson = 0.327", "bore_poisson = 0.5"), "bearing.surface.bore_poisson"),
        (('bore_modulus = "2320 MPa"', 'bore_modulus = "-2320 MPa"'), "bearing.surface.bore_modulus"),
        (('bore_modulus = "2320 MPa"\n', ""), "bearing.surface.bore_modulus"),
        (('highest = "300 rpm"', 'highest = "10 rpm"'), "bearing.stribeck.highest"),
        (("[bearing.surface]", 'surface_roughness = "2 um"\n[bearing.surface]'), "bearing.surface_roughness"),
        # measured asperity radius and density: one of each pair, density with a radius, in range
        (
            ("bore_poisson = 0.327", 'bore_poisson = 0.327\nasperity_radius = "50 um"\nsigma_over_beta = 0.01'),
            "bearing.surface.asperity_radius",
        ),
        (("bore_poisson = 0.327", 'bore_poisson = 0.327\nasperity_radius = "1 um"'), "bearing.surface.asperity_radius"),
        (
            ("bore_poisson = 0.327", 'bore_poisson = 0.327\nasperity_density = "2000 1/mm^2"'),
            "bearing.surface.asperity_density",
        ),
        (
            (
                "bore_poisson = 0.327",
                'bore_poisson = 0.327\nasperity_radius = "50 um"\nasperity_density = "1e8 1/mm^2"',
            ),
            "bearing.surface.asperity_density",
        ),
    ],
)
def test_bad_surface_input_exit_2_one_line_no_output(
    rig: Path, tmp_path: Path, replace: tuple[str, str], field: str | None
) -> None:
    text = RIG.replace(*replace)
    if field == "bearing.surface_roughness":
        # surface_roughness belongs to [bearing], before its sub-tables.
        text = RIG.replace('radial_clearance = "0.55 mm"', 'radial_clearance = "0.55 mm"\nsurface_roughness = "2 um"')
    if field is None:
        text = text.replace('journal_roughness = "0.8 um"\n', "", 1)
        field = "bearing.surface.bore_roughness"
    rig.write_text(text)
    out = tmp_path / "out"
    result = invoke("bearing", "stribeck", str(rig), "--out", str(out), "--json", str(tmp_path / "r.json"))
    assert result.exit_code == 2, result.output
    lines = [line for line in result.stderr.splitlines() if line.strip()]
    assert len(lines) == 1 and lines[0].startswith(f"error: {field} = "), lines
    assert result.stdout == ""
    assert not out.exists() and not (tmp_path / "r.json").exists()


def test_measured_asperity_radius_and_density_give_greenwood_trips_parameters(rig: Path) -> None:
    # beta and eta measured (Greenwood & Williamson 1966's inputs) in place of sigma beta eta and
    # sigma / beta: with sigma the composite Rq, sigma / beta = sigma / beta and sigma beta eta =
    # sigma beta eta exactly (1.25 * hypot(0.8, 1.6) um = 2.236 um; beta 50 um, eta 400 per mm^2).
    from shaftline.cases import load_case

    rig.write_text(
        RIG.replace(
            "bore_poisson = 0.327", 'bore_poisson = 0.327\nasperity_radius = "50 um"\nasperity_density = "400 1/mm^2"'
        )
    )
    surface = load_case(rig).studies["bearing"].cases[0].geometry.surface
    assert surface is not None
    sigma = surface.sigma
    assert sigma == pytest.approx(1.25 * np.hypot(0.8e-6, 1.6e-6), rel=1e-12)  # Rq = 1.25 Ra (seed 001 Eq. 10)
    assert surface.sigma_over_beta == pytest.approx(sigma / 50e-6, rel=1e-12)
    assert surface.sigma_beta_eta == pytest.approx(sigma * 50e-6 * 400e6, rel=1e-12)


def test_a_roughness_near_the_clearance_is_refused(rig: Path, tmp_path: Path) -> None:
    """Composite Rq at least half the radial clearance: no film (0.55 mm clearance, 0.25 mm Ra)."""
    rig.write_text(
        RIG.replace('radial_clearance = "0.55 mm"', 'radial_clearance = "20 um"').replace(
            'bore_roughness = "1.6 um"', 'bore_roughness = "15 um"'
        )
    )
    result = invoke("bearing", "solve", str(rig), "--json", str(tmp_path / "r.json"))
    assert result.exit_code == 2, result.output
    assert result.stderr.strip().startswith("error: bearing.surface.bore_roughness = ")
    assert "half the radial clearance" in result.stderr
    assert not (tmp_path / "r.json").exists()


def test_stribeck_of_a_smooth_case_has_no_regimes(tmp_path: Path) -> None:
    """Without [bearing.surface] the sweep runs (friction and h_min against speed) and has no
    regime or transition speed: nothing in it says where asperities would touch."""
    path = tmp_path / "smooth.toml"
    text = RIG.split("[bearing.surface]")[0] + "[bearing.stribeck]" + RIG.split("[bearing.stribeck]")[1]
    path.write_text(
        text.replace('speed = "35 rpm"', 'speed = "300 rpm"')
        .replace('lowest = "20 rpm"', 'lowest = "150 rpm"')
        .replace("points = 8", "points = 3")
    )
    out = tmp_path / "out"
    result = invoke("bearing", "stribeck", str(path), "--out", str(out), "--workers", "1")
    assert result.exit_code == 0, result.output
    curve = json.loads((out / "results.json").read_text())["bearing"]["stribeck"]
    assert curve["transition_speed_rpm"] is None and curve["lubrication_regime"] == [None, None, None]
    assert curve["min_film_ratio"] == [None, None, None]  # infinite for smooth surfaces
    assert (out / "figures" / "bearing_stribeck.png").stat().st_size > 10_000


def test_a_symmetric_films_load_centre_shows_as_zero(rig: Path) -> None:
    # The aligned rig's film is symmetric about mid-length: its load centre is rounding (the
    # JSON's value, below 1e-9 m), which the table printed as "-2.425e-17" m on
    # examples/seed001_water_rig.toml. The table shows 0; the JSON keeps the value.
    data = invoke("bearing", "solve", str(rig), "--json", "-", "--workers", "1")
    offset = json.loads(data.stdout)["bearing"]["cases"][0]["load_centre_offset"]
    assert abs(offset) < 1e-9
    table = invoke("bearing", "solve", str(rig), "--workers", "1")
    assert table.exit_code == 0, table.output
    (row,) = [line for line in table.stdout.splitlines() if "load centre from L/2" in line]
    assert row.split("│")[2].strip() == "0", row
