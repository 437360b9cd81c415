"""Film-supported alignment through the case file and the command line: tables, JSON, report,
the contact fall-back's exit status and the bad inputs issue 11 lists.

The line is a 14 m shaft of the NTUA stern-tube diameter with the seed 004 bearing (L = 1.05 m,
D = 0.52 m, c = 0.45 mm, 90 rpm, 0.07 Pa s) as its aft film bearing, on a coarse film grid so
that each solve takes a fraction of a second; the physics checks are in test_coupled.py.
"""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from tests.conftest import invoke

LINE = """
[case]
name = "film line"

[alignment.shaft]
element_length = "0.25 m"

[[alignment.shaft.segments]]
length = "14 m"
outer_diameter = "0.52 m"

[[alignment.loads]]
name = "propeller"
x = "0 m"
force_y = "-202598.2 N"
moment_vertical = "MOMENT"

[[alignment.bearings]]
name = "aft stern tube"
x = "0.932 m"
length = "1.05 m"
support = "multi_point"
points = 6
vertical_clearance = "0.9 mm"
FILM

[[alignment.bearings]]
name = "fwd stern tube"
x = "6 m"
length = "0.6 m"

[[alignment.bearings]]
name = "intermediate"
x = "13 m"
length = "0.5 m"
offset_y = "-0.5 mm"
"""

OWN_FILM = """
  [alignment.bearings.film]
  speed = "90 rpm"
  lubricant = { viscosity = "0.07 Pa*s", density = "890 kg/m^3" }
  solver = { axial_nodes = 41, circumferential_nodes = 36 }
"""


def write(tmp_path: Path, film: str = OWN_FILM, moment: str = "-409948 N*m", name: str = "line.toml") -> Path:
    path = tmp_path / name
    path.write_text(LINE.replace("FILM", film).replace("MOMENT", moment))
    return path


@pytest.fixture(scope="module")
def solved(tmp_path_factory):
    folder = tmp_path_factory.mktemp("film_line")
    out = folder / "out"
    result = invoke("align", str(write(folder)), "--out", str(out))
    assert result.exit_code == 0, result.stderr
    return result, out


def test_tables_json_and_report(solved):
    result, out = solved
    assert "Film bearings" in result.stdout and "Point supports vs film supports" in result.stdout
    alignment = json.loads((out / "results.json").read_text())["alignment"]
    bearings = {b["name"]: b for b in alignment["conditions"][0]["bearings"]}
    assert bearings["aft stern tube"]["contact"] == "film"
    (coupled,) = alignment["film_supports"]
    assert coupled["converged"] and coupled["message"] == ""
    (film,) = coupled["films"]
    # the film bearing's reaction is its film force, and the film is open (not at its floor)
    assert film["force_y"] == pytest.approx(bearings["aft stern tube"]["reaction_y"], rel=1e-12)
    assert not film["contact"] and film["min_film_thickness"] > 1e-5
    assert alignment["units"]["support_point_y"].startswith("m, the vertical resultant's position from the bearing's")
    assert alignment["units"]["min_film_theta_deg"] == "deg"
    assert len(film["centre_line"]["z"]) == 41 and len(film["line_load"]["y"]) == 41
    assert [b["name"] for b in coupled["point_supports"]] == list(bearings)
    html = (out / "report.html").read_text()
    assert "Film supports (elastohydrodynamic alignment)" in html and "with the declared supports" in html
    for name in ("point_vs_film_0", "journal_0_0", "film_maps_0_0"):
        assert (out / "figures" / f"alignment_{name}.png").stat().st_size > 10_000


def test_the_influence_matrix_of_a_film_line_is_its_tangent_and_says_so(solved):
    """On film supports the JSON's influence matrix is the film-supported line's tangent (the
    film's stiffness included; tests/shaft/test_film_tangent.py checks its numbers), labelled as
    such, with each condition's beside its coupled result and the declared supports' matrix
    beside it; the report's figure caption names which it shows."""
    _, out = solved
    alignment = json.loads((out / "results.json").read_text())["alignment"]
    shown, point = alignment["influence_matrix"], alignment["point_supports_influence_matrix"]
    assert shown["kind"] == "film_tangent" and shown["condition"] == alignment["conditions"][0]["name"]
    assert "film stiffness included" in shown["label"] and point["kind"] == "point"
    assert shown["matrix"] == alignment["film_supports"][0]["influence_matrix"]["matrix"]
    # the aft film bearing's own coefficient: the film in series with the shaft, not the point model's
    aft = shown["bearings"].index("aft stern tube")
    assert abs(shown["matrix"][aft][aft] / point["matrix"][aft][aft] - 1.0) > 0.05
    html = (out / "report.html").read_text()
    assert "influence matrix, film supports: tangent at the coupled equilibrium" in html


def test_terminal_comparison_shows_the_relative_slope_on_points_and_in_the_film(solved):
    """The terminal's "point supports vs film supports" keeps both relative slopes of the aft
    bearing (the issue's "aft-bearing relative slope"), not the film's alone."""
    from shaftline.report.blocks import fmt

    result, out = solved
    coupled = json.loads((out / "results.json").read_text())["alignment"]["film_supports"][0]
    table = result.stdout.split("Point supports vs film supports")[1]
    aft_row = next(line for line in table.splitlines() if "aft stern" in line)
    point = fmt(coupled["point_supports"][0]["relative_slope"], 1e3)
    film = fmt(coupled["films"][0]["relative_slope"], 1e3)
    assert point != film and point in aft_row and film in aft_row, aft_row


def test_a_film_below_the_limit_at_the_operating_speed_is_null_in_the_json(tmp_path):
    """With a class value above the film at the operating speed there is no minimum speed
    (nan inside Python): the JSON says null and the finding says why; it used to end in a
    traceback (JSON has no nan) with nothing written."""
    path = write(tmp_path)
    path.write_text(path.read_text() + '\n[alignment.minimum_speed]\nclass_value = "400 um"\npoints = 2\n')
    out = tmp_path / "out"
    result = invoke("align", str(path), "--out", str(out))
    assert result.exit_code == 0, result.stderr
    speed = json.loads((out / "results.json").read_text())["alignment"]["minimum_speed"]
    assert speed["speed"] is None and speed["speed_rpm"] is None and speed["bracket"][0] is None
    assert speed["bracket"][1] == pytest.approx(90 * 3.141592653589793 / 30, rel=1e-4)
    assert "below the limit (400 µm) at the operating speed (90 rpm)" in speed["message"]
    assert "below the film limit of 400.00 µm" in result.stdout


def test_line_film_table_serves_film_true(tmp_path):
    """``film = true`` takes [alignment.film]; the clearance defaults to half the bearing's vertical one."""
    shared = """
[alignment.film]
speed = "90 rpm"
lubricant = { viscosity = "0.07 Pa*s", density = "890 kg/m^3" }
solver = { axial_nodes = 41, circumferential_nodes = 36 }
"""
    path = tmp_path / "line.toml"
    path.write_text(LINE.replace("FILM", "film = true").replace("MOMENT", "-409948 N*m") + shared)
    own = invoke("align", str(write(tmp_path, name="own.toml")), "--json", "-")
    result = invoke("align", str(path), "--json", "-")
    assert result.exit_code == 0 and own.exit_code == 0, result.stderr
    films = [json.loads(r.stdout)["alignment"]["film_supports"][0]["films"][0] for r in (result, own)]
    assert films[0]["min_film_thickness"] == pytest.approx(films[1]["min_film_thickness"], rel=1e-12)


def test_film_at_its_floor_is_reported_with_exit_status_3(tmp_path):
    """With the propeller moment the other way the shaft crosses the clearance of the aft bearing:
    the film cannot carry it, the bearing falls back to contact at the bore, and the result is
    flagged (exit 3) with the reason first."""
    result = invoke("align", str(write(tmp_path, moment="409948 N*m")), "--json", "-")
    assert result.exit_code == 3, result.stderr
    document = json.loads(result.stdout)
    (coupled,) = document["alignment"]["film_supports"]
    assert coupled["films"][0]["contact"] and "floor" in coupled["message"]
    bearing = document["alignment"]["conditions"][0]["bearings"][0]
    assert bearing["contact"] in ("bottom", "partial", "top")
    assert any("cannot carry its share" in f["text"] for f in document["findings"])


@pytest.mark.parametrize(
    ("film", "field"),
    [
        ("film = true", "alignment.bearings[0].film"),  # no [alignment.film] to take it from
        (OWN_FILM.replace('speed = "90 rpm"', ""), "alignment.bearings[0].film.speed"),
        (
            OWN_FILM.replace('  lubricant = { viscosity = "0.07 Pa*s", density = "890 kg/m^3" }', ""),
            "alignment.bearings[0].film.lubricant",
        ),
        (OWN_FILM.replace("axial_nodes = 41", "axial_nodes = 6"), "alignment.bearings[0].film.solver.axial_nodes"),
        (
            OWN_FILM + 'radial_clearance = "0.45 mm"\ndiametral_clearance = "0.9 mm"\n',
            "alignment.bearings[0].film.radial_clearance",
        ),
        (  # the bearing's diametral 0.9 mm given as the film's radial clearance: one bore, two clearances
            OWN_FILM + 'radial_clearance = "0.9 mm"\n',
            "alignment.bearings[0].film.radial_clearance = 0.0009 m: allowed 0.00045 m",
        ),
        (  # the mass-conserving model without a feed pressure: the field is the film table's
            OWN_FILM.replace("circumferential_nodes = 36", 'circumferential_nodes = 36, cavitation = "jfo"'),
            "alignment.bearings[0].film.cavitation_pressure",
        ),
    ],
)
def test_bad_film_input_is_one_line(tmp_path, film, field):
    out = tmp_path / "out"
    result = invoke("align", str(write(tmp_path, film=film)), "--out", str(out))
    assert result.exit_code == 2
    lines = result.stderr.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith(f"error: {field}"), result.stderr
    assert not out.exists()


def test_a_misspelt_key_in_a_bearings_own_film_table_gets_a_suggestion(tmp_path):
    result = invoke("align", str(write(tmp_path, film=OWN_FILM + '  clearence = "0.45 mm"\n')))
    assert result.exit_code == 2
    assert result.stderr.strip() == (
        "error: alignment.bearings[0].film.clearence = '0.45 mm': allowed no such field; "
        "did you mean 'radial_clearance'?"
    )


def test_film_needs_a_clearance_and_no_spring(tmp_path):
    path = write(tmp_path, film=OWN_FILM)
    text = path.read_text()
    no_clearance = text.replace('vertical_clearance = "0.9 mm"\n', "", 1)
    path.write_text(no_clearance)
    result = invoke("align", str(path))
    assert result.exit_code == 2 and "film.radial_clearance" in result.stderr
    spring = text.replace('support = "multi_point"\npoints = 6', 'support = "spring"\nstiffness = "1e9 N/m"', 1)
    path.write_text(spring)
    result = invoke("align", str(path))
    assert result.exit_code == 2 and "bearings[0].support" in result.stderr


def test_ntua_shaft_line_example(tmp_path):
    """``shaftline align examples/ntua_shaft_line.toml``: the alignment with the film-supported stern
    tube, the point-vs-film comparison and the minimum speed in one run and one report (``run``
    adds the slope-boring search of its [design] table, tests/test_design_cli.py). The case
    file is the line of ``shaftline.shaft.ntua.ntua_shaft_line(0.3)`` (offsets rounded to 1 µm in
    the file, so the film agrees to 0.5 %, about 0.4 µm in h_min); the minimum speed is about
    61.5 rpm (docs/validation.md)."""
    from shaftline.shaft.coupled import CoupledAlignment
    from shaftline.shaft.ntua import ntua_shaft_line

    out = tmp_path / "out"
    example = Path(__file__).resolve().parents[2] / "examples" / "ntua_shaft_line.toml"
    result = invoke("align", str(example), "--out", str(out), "--json", "-")  # `run` adds the 40 x 40 design
    assert result.exit_code == 0, result.stderr
    alignment = json.loads(result.stdout)["alignment"]
    (film,) = alignment["film_supports"][0]["films"]
    line, support = ntua_shaft_line(0.3)
    reference = CoupledAlignment(line, [support]).solve().films[0]
    assert film["min_film_thickness"] == pytest.approx(reference.state.min_film_thickness, rel=5e-3)
    assert film["support_point_y"] == pytest.approx(reference.support_point_y, rel=5e-3)
    speed = alignment["minimum_speed"]
    assert 55.0 < speed["speed_rpm"] < 70.0 and speed["governing"] == "aft stern tube"
    assert speed["limit"] == pytest.approx(30e-6)
    html = (out / "report.html").read_text()
    assert "Minimum speed for hydrodynamic operation" in html and "Point supports vs film supports" in html
    assert (out / "figures" / "alignment_lift_off.png").stat().st_size > 10_000


def test_coupled_solve_that_does_not_converge_is_flagged(tmp_path):
    """One Newton iteration allowed: the result is written, flagged not converged with its last
    residual and what to try, and the exit status is 3 (not an input error)."""
    path = write(tmp_path)
    path.write_text(path.read_text() + "\n[alignment.coupling]\nmax_iterations = 1\n")
    out = tmp_path / "out"
    result = invoke("align", str(path), "--out", str(out))
    assert result.exit_code == 3, result.stderr
    coupled = json.loads((out / "results.json").read_text())["alignment"]["film_supports"][0]
    assert not coupled["converged"] and "not converged in 1 iterations" in coupled["message"]
    assert "max_iterations" in coupled["message"]
    assert "NOT CONVERGED" in (out / "report.html").read_text()
