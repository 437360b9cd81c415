"""The alignment example through the command line: tables, JSON, report, bad input."""

from __future__ import annotations

import json
from pathlib import Path

import pytest
from typer.testing import Result

from tests.conftest import invoke

ROOT = Path(__file__).resolve().parents[2]
EXAMPLE = ROOT / "examples" / "single_screw_alignment.toml"


def shaftline(*args: str) -> Result:
    return invoke(*args)


@pytest.fixture(scope="module")
def outputs(tmp_path_factory):
    out = tmp_path_factory.mktemp("align") / "out"
    result = shaftline("align", str(EXAMPLE), "--out", str(out))
    assert result.exit_code == 0, result.stderr
    return result, out


def test_align_prints_tables_and_writes_the_report(outputs):
    result, out = outputs
    assert "Shaft alignment" in result.stdout and "Class-rule checks" in result.stdout
    html = (out / "report.html").read_text()
    assert "Shaft alignment" in html and "Class-rule checks" in html and "Jack-up" in html
    for name in ("elastic_line", "moment_shear", "reactions", "influence", "jack"):
        assert (out / "figures" / f"alignment_{name}.png").stat().st_size > 10_000


def test_alignment_json(outputs):
    _, out = outputs
    alignment = json.loads((out / "results.json").read_text())["alignment"]
    assert [c["name"] for c in alignment["conditions"]] == [
        "cold, ballast, static",
        "cold, laden, static",
        "hot, laden, running",
    ]
    line = alignment["conditions"][0]["elastic_line"]
    assert set(line) >= {"x", "deflection_y", "deflection_z", "rotation_y", "moment_y", "shear_y", "stress"}
    assert len(line["moment_y"]) == len(line["x"])
    matrix = alignment["influence_matrix"]["matrix"]
    assert len(matrix) == 8 and abs(sum(matrix[0])) < 1e-6 * max(map(abs, matrix[0]))
    # the straight engine line unloads main bearing 2; the optimised offsets fix every rule
    assert any(not c["passed"] for c in alignment["rule_checks"])
    assert all(c["passed"] for c in alignment["optimised_offsets"]["rule_checks"])
    assert 0.5 < alignment["jack_up"]["correction_factor"] <= 1.0
    assert alignment["slope_boring_angle"]["cold, ballast, static"] > 0


def test_run_does_the_alignment_too(tmp_path):
    result = shaftline("run", str(EXAMPLE), "--out", str(tmp_path / "run"), "--json", "-")
    assert result.exit_code == 0, result.stderr
    assert "alignment" in json.loads(result.stdout)


@pytest.mark.parametrize(
    "replace, field",
    [
        (('x = "22.2 m"', 'x = "40 m"'), "alignment.bearings[3].x"),
        (
            ('outer_diameter = "620 mm"', 'outer_diameter = "620 mm"\ninner_diameter = "700 mm"'),
            "alignment.shaft.segments[3].inner_diameter",
        ),
        (('"intermediate" = "0.15 mm"', '"intermediat" = "0.15 mm"'), "alignment.conditions[1].offsets_y.intermediat"),
        (('mass = "62 t"', 'mass = "62 m"'), "alignment.propeller.mass"),
    ],
)
def test_bad_alignment_input(tmp_path, replace, field):
    text = EXAMPLE.read_text()
    assert replace[0] in text
    case = tmp_path / "case.toml"
    case.write_text(text.replace(*replace, 1))
    result = shaftline("align", str(case), "--out", str(tmp_path / "out"))
    assert result.exit_code == 2
    assert field in result.stderr
    assert not (tmp_path / "out").exists()


def test_bearing_solve_refuses_a_shaft_only_case(tmp_path):
    result = shaftline("bearing", "solve", str(EXAMPLE))
    assert result.exit_code == 2 and "[bearing]" in result.stderr


def test_measured_jack_curve_from_csv(tmp_path):
    """A measured curve given as CSV in the case: the knee of the model's own curve with
    measurement noise gives back the modelled reaction (2 %)."""
    import numpy as np

    from shaftline.cases import load_case
    from shaftline.shaft.jackup import jack_up
    from shaftline.shaft.study import solve_alignment

    study = load_case(EXAMPLE)["alignment"]
    ju = study.jack_up
    curve = jack_up(study.line, ju.bearing, ju.jack_x, ju.condition)
    noise = np.random.default_rng(7).normal(0.0, 2e-6, curve.lifts.size)
    rows = ["load,lift"] + [f"{p:.3f},{v:.9f}" for p, v in zip(curve.loads, curve.lifts + noise, strict=True)]
    (tmp_path / "jack.csv").write_text("\n".join(rows))
    text = EXAMPLE.read_text().replace('jack_x = "15.2 m"', 'jack_x = "15.2 m"\nmeasured_curve = "jack.csv"')
    (tmp_path / "case.toml").write_text(text)
    run = solve_alignment(load_case(tmp_path / "case.toml")["alignment"])
    assert run.jack_fit is not None
    assert run.jack_fit.reaction == pytest.approx(curve.reaction_before, rel=0.02)
    # and a gap in the file is refused with the row named
    rows[5] = "nan,0.1"
    (tmp_path / "jack.csv").write_text("\n".join(rows))
    from shaftline.errors import InputError

    with pytest.raises(InputError) as error:
        load_case(tmp_path / "case.toml")
    assert "row 6" in str(error.value)


def test_a_load_spread_without_weight_at_a_bearing_is_one_line(tmp_path):
    """Without the shaft's self weight the forward stern-tube bearing has no weight share, so
    the load-spread objective (each reaction over its share) is undefined: one line naming the
    objective, exit 2, nothing written (it was a linprog traceback)."""
    case = tmp_path / "weightless.toml"
    case.write_text(EXAMPLE.read_text().replace("[alignment.shaft]", "[alignment.shaft]\nself_weight = false", 1))
    out = tmp_path / "out"
    result = invoke("align", str(case), "--out", str(out))
    assert result.exit_code == 2
    assert result.stderr.startswith("error: alignment.optimise.objective = 'load_spread': allowed aft_slope here")
    assert "Traceback" not in result.stderr and not out.exists()


def test_the_failed_rule_checks_fit_80_columns_a_line_a_row():
    """The summary's failed class-rule checks (the straight engine line unloads main bearing 2 in all three
    conditions): one row per rule and bearing with its worst value and how many conditions fail, each row on one line
    of an 80-column terminal; the eight-column table of every check, with each rule's source and confidence, folded
    every row over three lines ("reactions-positive" as "reaction|s-positi|ve") and is the report's."""
    from rich.console import Console

    from shaftline.cases import load_case
    from shaftline.pipeline import run_case
    from shaftline.report.blocks import Details, Table
    from shaftline.report.terminal import print_blocks
    from shaftline.shaft.capability import RULE_HEADERS, SUMMARY_RULE_HEADERS

    result = run_case(load_case(EXAMPLE))
    capability, value = next(result.capabilities())
    (table,) = [b for b in capability.summary(value) if isinstance(b, Table) and b.title.startswith("Failed")]
    assert table.headers == SUMMARY_RULE_HEADERS
    failed = [c for c in value.checks if not c.passed]
    for rule_id, bearing, worst, limit, fails in table.rows:
        mine = [c for c in failed if (c.rule.id, c.bearing) == (rule_id, bearing)]
        assert fails == f"{len(mine)} of {len(value.conditions)}"
        values = [c.value for c in mine]
        assert float(worst.split()[0]) == pytest.approx(min(values) if limit.startswith(">") else max(values), rel=1e-3)
    assert sum(int(row[-1].split()[0]) for row in table.rows) == len(failed)
    console = Console(record=True, width=80)
    print_blocks(console, [table])
    lines = console.export_text().splitlines()
    assert max(len(line) for line in lines) <= 80
    assert sum(line.startswith("┃") for line in lines) == 1, lines
    assert sum(line.startswith("│") for line in lines) == len(table.rows), lines
    # the table of every check, with source and confidence, stays in the report (folded away in a Details block)
    details = [b for b in capability.report(value) if isinstance(b, Details)]
    assert any(isinstance(t, Table) and t.headers == RULE_HEADERS for d in details for t in d.blocks)
