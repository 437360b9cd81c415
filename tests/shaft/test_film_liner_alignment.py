"""The coupled alignment with the film model of issue 15: `[alignment.bearings.film]` takes the
`surface` and `liner` tables of `[bearing.surface]` / `[bearing.liner]`, with the same fields and
checks, so a stern tube is aligned on its soft liner (and mixed-lubrication film).

The line and its oil film are those of tests/shaft/test_film_supports_cli.py (seed 004's
bearing in a 14 m line, coarse film grid). References: the standalone bearing's light-load trend
(tests/film/test_liner.py: a soft liner lowers the pressure peak and h_min under the same load).
"""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from tests.conftest import invoke
from tests.shaft.test_film_supports_cli import LINE, OWN_FILM

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"


def solve(tmp_path: Path, extra: str, name: str) -> tuple[int, dict, str]:
    path = tmp_path / f"{name}.toml"
    path.write_text(LINE.replace("FILM", OWN_FILM + extra).replace("MOMENT", "-409948 N*m"))
    out = tmp_path / f"{name}.json"
    result = invoke("align", str(path), "--json", str(out))
    data = json.loads(out.read_text())["alignment"]["film_supports"][0] if out.exists() else {}
    return result.exit_code, data, result.stderr


def test_stern_tube_aligned_on_its_soft_liner(tmp_path: Path) -> None:
    # Seed 004's stern tube at 90 rpm in oil, on a rigid bore and on a rubber liner: the coupled
    # solution converges on both, and the liner acts as on the standalone bearing under light
    # load (the deformation spreads the pressure: a lower peak, and a lower h_min at the ends).
    code, rigid, _ = solve(tmp_path, "", "rigid")
    assert code == 0 and rigid["converged"]
    code, lined, _ = solve(tmp_path, '  liner = { preset = "rubber" }\n', "rubber")
    assert code == 0 and lined["converged"]
    (r,), (s,) = rigid["films"], lined["films"]
    assert r["max_liner_deformation"] == 0.0 and s["max_liner_deformation"] > 10e-6
    # The liner settles at the converged line: its stiffness and damping are there, no note.
    assert len(s["stiffness"]) == len(s["damping"]) == 4 and s["coefficients_note"] == ""
    assert s["max_pressure"] < 0.9 * r["max_pressure"]
    assert s["min_film_thickness"] < r["min_film_thickness"]
    # Both carry the bearing's share of the same line: the film forces agree within 1 %.
    assert s["force_y"] == pytest.approx(r["force_y"], rel=0.01)
    # Smooth surfaces: no asperity load, no film ratio.
    assert s["asperity_load_share"] == 0.0 and s["min_film_ratio"] is None


def test_rough_film_in_the_alignment_reports_its_asperities(tmp_path: Path) -> None:
    # A rough white-metal pair at 90 rpm: full film (lambda far above 3), so the same alignment
    # as the smooth one within 1e-6 of the force, and the film ratio is reported.
    code, smooth, _ = solve(tmp_path, "", "smooth")
    code_rough, rough, _ = solve(tmp_path, '  surface = { preset = "turned_steel_white_metal" }\n', "rough")
    assert code == code_rough == 0
    (a,), (b,) = smooth["films"], rough["films"]
    assert b["min_film_ratio"] > 3.0 and b["asperity_load_share"] < 1e-9
    assert b["force_y"] == pytest.approx(a["force_y"], rel=1e-6)


@pytest.mark.parametrize(
    ("table", "field"),
    [
        ('liner = { thickness = "0 mm", modulus = "2 GPa", poisson = 0.3 }', "liner.thickness"),
        ('liner = { thickness = "100 mm", modulus = "2 GPa", poisson = 0.3 }', "liner.thickness"),
        ('liner = { preset = "rubber", modulus = "0 MPa" }', "liner.modulus"),
        ('liner = { preset = "rubber", poisson = 0.5 }', "liner.poisson"),
        ('liner = { preset = "rubber", poisson = 0 }', "liner.poisson"),
        ('liner = { thickness = "10 mm", modulus = "2 GPa" }', "liner.poisson"),
        ('surface = { preset = "steel_polymer", bore_roughness = "400 um" }', "surface.bore_roughness"),
        ('surface = { journal_roughness = "0.8 um" }', "surface.bore_roughness"),
    ],
)
def test_bad_liner_or_surface_in_the_alignment_is_one_line(tmp_path: Path, table: str, field: str) -> None:
    code, data, stderr = solve(tmp_path, f"  {table}\n", "bad")
    assert code == 2 and not data
    lines = [line for line in stderr.splitlines() if line.strip()]
    assert len(lines) == 1 and lines[0].startswith(f"error: alignment.bearings[0].film.{field} = "), lines


@pytest.mark.slow
def test_seed001_rig_alignment_example(tmp_path: Path) -> None:
    """``shaftline align examples/seed001_rig_alignment_liner.toml``: the rig's stern bearing on its
    water film and polymer liner at 175 rpm. The overhung counterweight tilts the journal in its
    1.2 m bearing and the water film cannot carry the aft edge. While the film stopped at the mean
    plane the coupled iteration stalled there (contact, exit 3: the edge's asperities capped at
    K E* F_5/2(0)); with the film carried below the mean plane (docs/theory.md, "Boundary
    lubrication") the aft edge runs in boundary lubrication, its asperities past the mean plane
    and the liner compressed under them, and the line converges (exit 0): lambda_min between the
    boundary limit -3 and 0 (-2.3 computed), asperities carrying more than 1 % of the load (8.4 %),
    the liner deformed by tens of micrometres (44), the film carrying the stern bearing's share."""
    out = tmp_path / "r.json"
    result = invoke("align", str(EXAMPLES / "seed001_rig_alignment_liner.toml"), "--json", str(out))
    assert result.exit_code == 0, result.stderr
    support = json.loads(out.read_text())["alignment"]["film_supports"][0]
    assert support["converged"]
    (film,) = support["films"]
    assert not film["contact"]
    assert -3.0 < film["min_film_ratio"] < 0.0  # boundary lubrication at the aft edge
    assert 0.01 < film["asperity_load_share"] < 0.5
    assert 5e-6 < film["max_liner_deformation"] < 100e-6
    assert "Film supports, base: converged in" in " ".join(result.stdout.split())


def test_turbulence_in_the_alignment_film_is_reported(tmp_path: Path) -> None:
    # `turbulence` in [alignment.bearings.film.solver] changes the film, so its largest local
    # Reynolds number and flag are written as in `bearing solve` (the JSON had neither). Oil at
    # 90 rpm with turbulence on: Re_h = rho omega R h / mu with h between 0 and 2c, so the largest
    # is within (Re_c, 2 Re_c], Re_c = 890 * 9.42 * 0.26 * 0.45e-3 / 0.07 = 14.0 (the film's
    # h_max is c (1 + e) at e > 0). A laminar film keeps its keys.
    code, laminar, _ = solve(tmp_path, "", "laminar")
    assert code == 0 and "max_reynolds_number" not in laminar["films"][0]
    turbulent = OWN_FILM.replace("circumferential_nodes = 36 }", 'circumferential_nodes = 36, turbulence = "on" }')
    path = tmp_path / "turbulent.toml"
    path.write_text(LINE.replace("FILM", turbulent).replace("MOMENT", "-409948 N*m"))
    out = tmp_path / "turbulent.json"
    result = invoke("align", str(path), "--json", str(out))
    assert result.exit_code == 0, result.stderr
    (film,) = json.loads(out.read_text())["alignment"]["film_supports"][0]["films"]
    clearance_re = 890 * 90 * 2 * 3.141592653589793 / 60 * 0.26 * 0.45e-3 / 0.07
    assert film["turbulent"] is True and clearance_re < film["max_reynolds_number"] <= 2 * clearance_re
    text = " ".join(result.stdout.split())
    assert f"largest local Reynolds number {film['max_reynolds_number']:.4g}, turbulent" in text


def test_stern_tube_aligned_on_a_layer_liner(tmp_path: Path) -> None:
    # The same line on seed 001's polymer liner as a bonded elastic layer ([...film.liner] model
    # = "layer", docs/theory.md "Elastic layer"): the alignment's film rows and their
    # derivatives go through the layer's coupled solve. Reference: the column model, the
    # layer's long-wave limit; the 20 mm liner is thin against this bearing's pressure zone, so
    # the two agree within 1 % on p_max, h_min and the deformation (computed: 0.02 %, 0.04 %,
    # 0.7 %), and carry the same share within 1e-3.
    code, column, _ = solve(tmp_path, '  liner = { preset = "polymer_composite" }\n', "column")
    assert code == 0 and column["converged"]
    code, layer, _ = solve(tmp_path, '  liner = { preset = "polymer_composite", model = "layer" }\n', "layer")
    assert code == 0 and layer["converged"]
    (c,), (s,) = column["films"], layer["films"]
    assert s["max_liner_deformation"] > 1e-6
    for key in ("max_pressure", "min_film_thickness", "max_liner_deformation"):
        assert s[key] == pytest.approx(c[key], rel=0.01)
    assert s["force_y"] == pytest.approx(c["force_y"], rel=1e-3)


@pytest.mark.parametrize(
    ("solver", "expected"),
    [
        ('turbulence_model = "constantinescu"', "alignment.bearings[0].film.solver.turbulence_model = constantinescu"),
        ('turbulence = "on"', "alignment.bearings[0].film.solver.turbulence = on with a film whose largest local"),
        ('turbulence = "off"', None),
    ],
)
def test_turbulence_notes_in_the_alignment_film_as_in_the_bearing(tmp_path: Path, solver: str, expected) -> None:
    # `[alignment.bearings.film.solver]` notes what `[bearing.solver]` notes (tests/film/
    # test_turbulence.py): a turbulence_model named with turbulence left off has no effect, and
    # turbulence on for this oil film (largest Re_h 28 against the onset 41.3 sqrt(R/c) = 993)
    # is far below transition. Named under the film's table; turbulence off named is no note.
    film = OWN_FILM.replace("circumferential_nodes = 36 }", f"circumferential_nodes = 36, {solver} }}")
    path = tmp_path / "line.toml"
    path.write_text(LINE.replace("FILM", film).replace("MOMENT", "-409948 N*m"))
    out = tmp_path / "line.json"
    result = invoke("align", str(path), "--json", str(out))
    assert result.exit_code == 0, result.stderr
    warnings = json.loads(out.read_text()).get("warnings", [])
    if expected is None:
        assert warnings == []
    else:
        assert len(warnings) == 1 and warnings[0].startswith(expected), warnings


@pytest.mark.slow
def test_a_trial_the_layer_liner_cannot_hold_is_rejected_not_fatal(tmp_path: Path) -> None:
    # A 10 mm rubber liner as a bonded layer (nu 0.49: it bulges at the bearing ends, which the
    # column model does not hold) in the same line: a line-search trial pushes the film past what
    # the layer holds and the film-liner iteration fails (LinerConvergenceError). That trial is
    # rejected like a film cutting the bore; the iteration goes on to the film's floor at the
    # forward end and the bearing falls back to contact, with the results written and the
    # rejected trial named in the message. It ended "not solved" (exit 3, nothing written).
    liner = '  liner = { preset = "rubber", thickness = "10 mm", model = "layer" }\n'
    code, data, stderr = solve(tmp_path, liner, "rubber_layer")
    assert code == 3 and data, stderr
    assert "not solved" not in stderr
    (film,) = data["films"]
    assert film["contact"] and film["max_liner_deformation"] > 50e-6
    assert "asked more of the elastic liner than it holds" in data["message"]
    assert "rejected as a film cutting the bore" in data["message"]


def test_a_start_the_liner_cannot_hold_is_a_clear_solver_failure(tmp_path: Path, monkeypatch) -> None:
    # A liner that settles at no starting line (forced here: every film-liner iteration fails)
    # ends in one line naming the bearing and what to try, not the bare residual of the liner
    # iteration ("not solved: 0.000399...").
    from shaftline.film.bearing import JournalBearing, LinerConvergenceError

    def failing(self, *args, **kwargs):
        raise LinerConvergenceError(4e-4)

    monkeypatch.setattr(JournalBearing, "film_load", failing)
    code, data, stderr = solve(tmp_path, '  liner = { preset = "rubber" }\n', "never")
    assert code == 3 and not data
    text = " ".join(stderr.split())
    assert text.startswith("not solved: film-supported alignment: the elastic liner of aft stern tube does not settle")


def test_under_resolved_layer_liner_in_the_alignment_is_noted(tmp_path: Path) -> None:
    # `[alignment.bearings.film.liner]` with model = "layer" gets the note `[bearing.liner]` gets
    # (tests/film/test_layer_film.py) when the axial step is above half the liner thickness,
    # named under its own table: 1.05 m on 41 rows is a 26.25 mm step against a 10 mm rubber
    # liner, which needs ceil(1.05 / 0.005) + 1 = 211 rows. On 211 rows (5 mm) and with the
    # column model (no end effect to resolve) there is no note.
    from shaftline.cases.loader import load_case

    def notes(film: str) -> list[str]:
        path = tmp_path / "line.toml"
        path.write_text(LINE.replace("FILM", film).replace("MOMENT", "-409948 N*m"))
        return [text for text in load_case(path).warnings if "liner.model = layer" in text]

    layer = OWN_FILM + '  liner = { preset = "rubber", model = "layer" }\n'
    (note,) = notes(layer)
    assert note.startswith("alignment.bearings[0].film.liner.model = layer with an axial step of 26.3 mm")
    assert "set alignment.bearings[0].film.solver.axial_nodes to 211 or more" in note
    assert notes(layer.replace("axial_nodes = 41", "axial_nodes = 211")) == []
    assert notes(OWN_FILM + '  liner = { preset = "rubber" }\n') == []


def test_coefficients_a_soft_liner_cannot_give_are_noted_not_fatal(tmp_path: Path, monkeypatch) -> None:
    # The film's stiffness and damping are taken at the converged journal line after the coupled
    # iteration (coupled.film_coefficients); a soft liner whose film-liner iteration does not
    # settle there (forced here: that call fails as the liner iteration does) ended the whole run
    # "not solved" (exit 3, nothing written). The alignment stands: the coefficients are null in
    # the JSON (NaN is refused there) with the reason, and the summary and the report say so, the
    # report in place of the coefficients' table.
    import shaftline.shaft.coupled as coupled
    from shaftline.cases.loader import load_case
    from shaftline.film.bearing import LinerConvergenceError
    from shaftline.pipeline import dumps, results_document, run_case
    from shaftline.report.blocks import Paragraph, Table

    def failing(*args, **kwargs):
        raise LinerConvergenceError(4e-4)

    monkeypatch.setattr(coupled, "film_coefficients", failing)
    path = tmp_path / "soft.toml"
    path.write_text(
        LINE.replace("FILM", OWN_FILM + '  liner = { preset = "rubber" }\n').replace("MOMENT", "-409948 N*m")
    )
    result = run_case(load_case(path))
    data = json.loads(dumps(results_document(result)))["alignment"]["film_supports"][0]
    assert data["converged"]
    (film,) = data["films"]
    assert film["stiffness"] is None and film["damping"] is None
    assert film["coefficients_note"].startswith("stiffness and damping not available: the elastic liner's")
    assert "liner residual 0.0004 of the clearance" in film["coefficients_note"]
    ((capability, value),) = [(c, v) for c, v in result.capabilities() if c.key == "alignment"]
    summary = " ".join(b.text for b in capability.summary(value) if isinstance(b, Paragraph))
    assert "aft stern tube: stiffness and damping not available" in summary
    report = capability.report(value)
    warnings = [b.text for b in report if isinstance(b, Paragraph) and b.style == "warn"]
    assert any(t.startswith("Film stiffness and damping, aft stern tube") for t in warnings), warnings
    assert not any(isinstance(b, Table) and b.title.startswith("Film stiffness K") for b in report)
