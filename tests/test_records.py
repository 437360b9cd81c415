"""Reports as design records and a terminal that loses nothing (issue 9): the inputs with
their hashes, vector figures, progress while drawing, tables that fit 80 columns, figures
that show what the tables say."""

from __future__ import annotations

import hashlib
import re
from pathlib import Path

import pytest

from shaftline.cases import load_case
from shaftline.pipeline import run_case, write_outputs

ROOT = Path(__file__).resolve().parents[1]
EXAMPLES = ROOT / "examples"


@pytest.fixture(scope="module")
def alignment():
    return run_case(load_case(EXAMPLES / "single_screw_alignment.toml"))


def test_the_report_records_its_inputs(alignment, tmp_path):
    out = write_outputs(alignment, tmp_path / "out")
    html = (out / "report.html").read_text()
    case_file = EXAMPLES / "single_screw_alignment.toml"
    assert hashlib.sha256(case_file.read_bytes()).hexdigest() in html
    assert "the case file as written" in html and "the case as read" in html
    assert "&#34;element_length&#34;: 0.15" in html  # the case as read, SI (escaped quotes)
    assert "&#34;beam_theory&#34;: &#34;timoshenko&#34;" in html  # defaults filled in
    assert re.search(r"\d{4}-\d\d-\d\dT\d\d:\d\d:\d\d", html)  # dated
    assert "@media print" in html
    for name in ("alignment_elastic_line", "alignment_reactions"):
        assert (out / "figures" / f"{name}.svg").read_text().lstrip().startswith("<?xml")
        assert f'src="figures/{name}.svg"' in html


def test_drawing_the_report_says_which_figure(alignment, tmp_path):
    from shaftline.pipeline import report_sections
    from shaftline.report.html import write_report

    said: list[str] = []
    write_report(tmp_path, "t", "", "", report_sections(alignment), "0", progress=said.append)
    assert said and said[0] == f"drawing figure 1 of {len(said)}" and said[-1].endswith(f"{len(said)} of {len(said)}")


def test_terminal_tables_fit_80_columns_without_cutting(alignment):
    from rich.console import Console

    from shaftline.report.terminal import print_blocks

    for name in ("single_screw_alignment", "ferry_wear", "ntua_stern_tube"):
        result = alignment if name == "single_screw_alignment" else run_case(load_case(EXAMPLES / f"{name}.toml"))
        console = Console(record=True, width=80)
        for capability, value in result.capabilities():
            print_blocks(console, capability.summary(value))
        text = console.export_text()
        assert max(len(line) for line in text.splitlines()) <= 80 and "…" not in text, name


def test_rule_checks_as_a_matrix(alignment):
    from shaftline.report.blocks import Table

    capability, value = next(alignment.capabilities())
    matrix = next(b for b in capability.report(value) if isinstance(b, Table) and b.title.startswith("Class-rule"))
    assert [row[0] for row in matrix.rows] == [c.name for c in value.conditions]
    assert matrix.marks is not None
    failed = {(c.condition, c.bearing) for c in value.checks if not c.passed}
    for i, row in enumerate(matrix.rows):
        for j, name in enumerate(matrix.headers[1:], start=1):
            assert (matrix.marks[i][j] == "fail") == ((row[0], name) in failed)


def test_the_elastic_line_draws_each_conditions_bearings(alignment):
    """The bars of the bottom of the bore sit at the base offset plus the condition's offset."""
    from matplotlib.figure import Figure

    from shaftline.shaft import figures

    value = alignment["alignment"]
    line = value.model.line
    ax = Figure().subplots()
    figures.elastic_line(line, value.conditions, ax=ax)
    heights = {
        round(float(y), 6)
        for collection in ax.collections
        for segment in collection.get_segments()
        for y in segment[:, 1]
    }
    hot = next(c for c in line.conditions if c.name == "hot, laden, running")
    engine = next(b for b in line.bearings if b.name == "main bearing 5")
    assert round((engine.offset_y + hot.offsets_y["main bearing 5"]) * 1e3, 6) in heights


def test_the_readme_snippet_runs_from_any_folder(tmp_path, monkeypatch):
    readme = (ROOT / "README.md").read_text()
    snippet = re.search(r"```python\n(from shaftline import example.*?)```", readme, re.S).group(1)
    monkeypatch.chdir(tmp_path)
    exec(compile(snippet, "README.md", "exec"), {})
    assert (tmp_path / "results" / "ntua" / "report.html").exists()


def test_the_cpp_study_gives_settled_amplitudes_with_units():
    """The study table shows its values in engineering units and the settled (second-half)
    amplitudes, and says why; the headline gives the settled range too."""
    from shaftline.cases import parse_case
    from shaftline.cases.files import read_case_file
    from shaftline.report.blocks import Paragraph, Table

    data = read_case_file(EXAMPLES / "cpp_blade_bearing.toml")
    case = parse_case(data, EXAMPLES, overrides={"cpp.motion.revolutions": 6, "cpp.study.revolutions": 6})
    result = run_case(case)
    capability, value = next(result.capabilities())
    blocks = capability.report(value)
    study = next(b for b in blocks if isinstance(b, Table) and b.headers[0].startswith("backlash"))
    assert study.headers[0] == "backlash [mm]" and [row[0] for row in study.rows] == ["0", "0.05", "0.1", "0.2"]
    assert any(isinstance(b, Paragraph) and "settled revolutions" in b.text for b in blocks)
    settled = capability.to_json(value)["motion"]["fretting_amplitude_settled"]
    assert settled["min"] <= settled["mean"] <= settled["max"]
