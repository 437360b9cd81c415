"""The report layer: user text is escaped, figures go into the axes they are given, and
writing a report leaves the session's matplotlib state alone."""

from __future__ import annotations

from dataclasses import replace

import matplotlib
import pytest
from matplotlib.figure import Figure

from shaftline.cases import parse_case
from shaftline.pipeline import run_case, write_outputs
from shaftline.report.blocks import Figure as FigureBlock
from shaftline.report.blocks import Paragraph, Section, Table
from shaftline.report.html import render

CASE = {
    "case": {"name": "<script>alert('case')</script> price $x^$", "description": "a & b <i>"},
    "bearing": {
        "length": 0.1,
        "diameter": 0.1,
        "radial_clearance": 1e-4,
        "operation": {"speed": 60.0, "load": 5e3},
        "lubricant": {"viscosity": 0.02},
        "solver": {"axial_nodes": 15, "circumferential_nodes": 48},
        "variants": [{"name": "<img src=x onerror=alert(1)> $\\alpha$", "misalignment_ratio_vertical": 0.2}],
    },
}


@pytest.fixture(scope="module")
def solved():
    return run_case(parse_case(CASE))


def test_user_text_is_escaped_everywhere(solved, tmp_path):
    import matplotlib.pyplot as plt

    backend = matplotlib.get_backend()
    figures_before = plt.get_fignums()
    write_outputs(solved, tmp_path / "out", "case <file>.toml")
    html = (tmp_path / "out" / "report.html").read_text()
    assert "<script>" not in html and "<img src=x" not in html and "<i>" not in html
    assert "&lt;script&gt;" in html and "&lt;img src=x onerror=alert(1)&gt;" in html
    assert "price $x^$" in html  # and the figures with these names in titles and labels were drawn
    assert "case &lt;file&gt;.toml" in html
    # the report drew its figures without pyplot and without switching the backend
    assert matplotlib.get_backend() == backend
    assert plt.get_fignums() == figures_before


def test_blocks_render_as_html():
    section = Section("k", "T & c", [Paragraph("careful", "warn"), Table(["a", "b"], [["x", "1.5 m"]], "t")])
    html = render("title", "", "case.toml", [section], "0")
    assert '<p class="warn">careful</p>' in html
    cells = html.replace('"', "'")
    assert "<td class='text'>x</td>" in cells and "<td class='num'>1.5 m</td>" in cells
    assert "T &amp; c" in html


def test_figure_functions_draw_into_the_given_axes(solved):
    from shaftline.film import figures

    state = solved["bearing"].cases[0].equilibrium.state
    figure = Figure()
    ax = figure.subplots()
    assert figures.axial_profiles(state, "base", ax=ax) is ax
    assert ax.lines[0].get_ydata() == pytest.approx(state.film.min(axis=1) * 1e6)
    assert ax.get_title().startswith("base")
    pair = Figure().subplots(1, 2)
    figures.film_and_pressure_maps(state, ax=pair)
    assert all(axes.collections for axes in pair)
    # h_min in the map's title to 3 significant digits: a film at its floor (0.03 um in the
    # lined rig's alignment) read "h_min = 0.0 um" with one decimal
    floor = replace(state, min_film_thickness=2.768e-8)
    pair = Figure().subplots(1, 2)
    figures.film_and_pressure_maps(floor, ax=pair)
    assert pair[0].get_title() == "h_min = 0.0277 µm"


def test_figure_function_without_axes_makes_its_own(solved):
    import matplotlib.pyplot as plt

    from shaftline.film import figures

    state = solved["bearing"].cases[0].equilibrium.state
    ax = figures.circumferential_profile(state)
    try:
        assert ax.figure.get_size_inches().tolist() == list(figures.circumferential_profile.size)
    finally:
        plt.close(ax.figure)


def test_figure_block_is_drawn(tmp_path, solved):
    from shaftline.film import figures
    from shaftline.report.html import draw_figure

    state = solved["bearing"].cases[0].equilibrium.state
    path = draw_figure(FigureBlock("maps.png", figures.film_and_pressure_maps, (state, "x")), tmp_path / "maps.png")
    assert path.stat().st_size > 10_000


def test_units_survive_the_terminal():
    """rich would read '[kN]' or '[mrad]' as markup and drop it: every header and cell of every
    example's terminal tables is printed as written."""
    import re
    from pathlib import Path

    from rich.console import Console

    from shaftline.cases import load_case
    from shaftline.report.blocks import Table
    from shaftline.report.terminal import print_blocks

    examples = Path(__file__).resolve().parents[1] / "examples"
    for name in ("ntua_stern_tube", "single_screw_alignment", "ferry_wear"):
        result = run_case(load_case(examples / f"{name}.toml"))
        for capability, value in result.capabilities():
            blocks = capability.summary(value)
            console = Console(record=True, width=400)
            print_blocks(console, blocks)
            text = console.export_text()
            labels = [t for b in blocks if isinstance(b, Table) for t in [*b.headers, *(row[0] for row in b.rows)]]
            units = {u for t in labels for u in re.findall(r"\[[^\]]+\]", t)}
            assert units, name
            for unit in units:
                assert unit in text, (name, unit)


def test_stribeck_figure_titles_fit_and_contact_speeds_are_marked_on_both_panels():
    # The Stribeck figure of the seed 001 rig (examples/seed001_water_rig.toml, `bearing
    # stribeck`) cut its left title at the figure's edge (the regime colours were spelled out in
    # it) and drew the contact speeds' h_min (films at the floor, one fitted below zero) as
    # ordinary points of the curve. Now: titles inside the figure, the regimes in the legend, and
    # the contact speeds marked x on both panels. A synthetic curve: 6 speeds, the two lowest
    # in contact.
    import numpy as np

    from shaftline.film import figures
    from shaftline.film.stribeck import StribeckCurve

    n = 6
    contact = np.array([True, True, False, False, False, False])
    curve = StribeckCurve(
        speed=np.geomspace(0.4, 40.0, n),
        friction_coefficient=np.array([0.04, 0.03, 0.01, 0.003, 0.001, 0.0012]),
        asperity_load_share=np.array([0.5, 0.3, 0.05, 0.008, 0.0, 0.0]),
        min_film_thickness=np.array([1e-8, -2e-8, 2e-7, 1e-6, 3e-6, 8e-6]),
        min_film_ratio=np.array([0.005, -0.01, 0.1, 0.5, 1.5, 4.0]),
        regime=("boundary", "boundary", "boundary", "boundary", "mixed", "full film"),
        converged=~contact,
        contact=contact,
        transition_speed=3.0,
    )
    canvas = Figure(figsize=figures.stribeck.size, layout="constrained")
    ax = canvas.subplots(*figures.stribeck.layout)
    figures.stribeck(curve, "seed 001 rig, 35 rpm, a case name of some length", ax=ax)
    canvas.draw_without_rendering()
    box = canvas.bbox
    for axes in ax:
        title = axes.title.get_window_extent()
        assert box.x0 <= title.x0 and title.x1 <= box.x1, axes.get_title()
        labels = axes.get_legend_handles_labels()[1]
        marked = [line for line in axes.lines if line.get_label() == "contact: load not carried"]
        assert len(marked) == 1 and list(marked[0].get_xdata()) == pytest.approx(curve.speed[:2] * 30 / np.pi)
        assert [text.get_text() for text in axes.get_legend().get_texts()][-3:] == [
            "boundary (λ < 1)",
            "mixed (1-3)",
            "full film (λ > 3)",
        ], labels
    # The h_min line joins the equilibria only (as the friction line): it has no value (NaN, a
    # break in the line) at the speeds in contact.
    (line,) = [line for line in ax[1].lines if line.get_label() == "h_min"]
    values = np.asarray(line.get_ydata(), dtype=float)
    assert np.isnan(values[:2]).all() and np.isfinite(values[2:]).all()
    assert list(np.asarray(line.get_xdata())[2:]) == pytest.approx(curve.speed[2:] * 30 / np.pi)


def test_a_title_cut_at_the_figures_edge_is_wrapped():
    # Two-panel figures of the bearing report (asperity contact, liner) put the case name ahead
    # of the left panel's title and cut it at the figure's edge ("d 001 rig, soft liner, ...").
    # The report wraps such a title (fit_titles, called by draw_figure before saving) and leaves
    # the titles that fit as they are.
    from shaftline.report.plotting import fit_titles

    canvas = Figure(figsize=(11, 4.2), layout="constrained")
    left, right = canvas.subplots(1, 2)
    long = "seed 001 rig, soft liner, 95 rpm: asperities carry 0.36 % of the load of the bearing"
    left.set_title(long)
    right.set_title("λ_min = 0.10 (boundary)")
    canvas.draw_without_rendering()
    assert left.title.get_window_extent().x0 < canvas.bbox.x0  # cut before
    fit_titles(canvas)
    canvas.draw_without_rendering()
    assert "\n" in left.title.get_text() and left.title.get_text().replace("\n", " ") == long
    extent = left.title.get_window_extent()
    assert canvas.bbox.x0 <= extent.x0 and extent.x1 <= canvas.bbox.x1
    assert not extent.overlaps(right.title.get_window_extent())
    assert right.title.get_text() == "λ_min = 0.10 (boundary)"
