"""Slope-boring design through the case file and the command line (issue 12): `design slopes`,
`design robustness`, `design sweep`, the JSON, the report and the bad inputs.

The example is the seed's search (40 x 40 on 100 x 60); these runs shrink it with the command's
own options or the case overrides to a few generations of a few designs on a 41 x 36 grid.
"""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from shaftline.cases import load_case
from shaftline.errors import InputError
from shaftline.pipeline import results_document, run_case
from tests.conftest import invoke

EXAMPLE = Path(__file__).resolve().parents[1] / "examples" / "ntua_slope_design.toml"


def small_case(tmp_path: Path, extra: str = "", drop: str = "") -> Path:
    text = EXAMPLE.read_text()
    text = text[: text.index("[[design.robustness.named]]")]  # the example's seed design is a reference only
    text = text.replace("axial_nodes = 100", "axial_nodes = 41")
    text = text.replace("circumferential_nodes = 60", "circumferential_nodes = 36")
    text = text.replace("population = 40", "population = 6").replace("generations = 40", "generations = 2")
    if drop:
        text = text.replace(drop, "")
    path = tmp_path / "design.toml"
    path.write_text(text + extra)
    return path


def test_design_slopes_command(tmp_path):
    """The search alone with its options on the command line: every design, the front and its knee in
    the JSON, the front figure and the design maps in the report, nothing of [bearing] solved."""
    out = tmp_path / "out"
    result = invoke(
        "design", "slopes", str(small_case(tmp_path)), "--generations", "3", "--population", "8", "--seed", "4",
        "--out", str(out), "--json", "-",
    )  # fmt: skip
    assert result.exit_code == 0, result.stderr
    document = json.loads(result.stdout)
    assert "bearing" not in document  # [bearing] was built for [design], not solved
    design = document["design"]
    assert design["search"]["evaluations"] == 24 and design["search"]["seed"] == 4
    assert design["variables"] == ["slope_1", "slope_2", "knuckle_1"]
    assert "robustness" not in design
    knee = design["search"]["knee"]
    assert knee is not None and knee["index"] in [row["index"] for row in design["search"]["pareto"]]
    html = (out / "report.html").read_text()
    assert "Slope-boring design" in html and "Non-dominated designs" in html
    for name in ("design_pareto", "design_maps"):
        assert (out / "figures" / f"{name}.png").stat().st_size > 10_000


def test_run_does_search_and_robustness(tmp_path):
    """`run` on the design case: the bearing film, the search and the knee's robustness in the seed's
    seven scenarios, with deviations in % and the verdict."""
    case = load_case(small_case(tmp_path))
    result = run_case(case, options={"design": {"workers": 1}})
    document = results_document(result)
    robustness = document["design"]["robustness"]
    (knee,) = robustness["designs"]
    assert knee["name"] == "knee" and len(knee["scenarios"]) == 7
    hmin = {s["scenario"]: s["min_film_thickness"] for s in knee["scenarios"]}
    assert hmin["+20 degC"] < hmin["+10 degC"] < knee["reference"]["min_film_thickness"] < hmin["-50 % load"]
    assert knee["robust"] == all(s["passes"] for s in knee["scenarios"])
    from shaftline.design.capability import CAPABILITY
    from shaftline.report.blocks import Table

    # the terminal shows the robustness table too, not only the count of robust designs
    (table,) = [b for b in CAPABILITY.summary(result["design"]) if isinstance(b, Table)]
    assert table.title == "h_min [µm] in each scenario (limit 30 µm)" and table.rows[0][0] == "knee"
    assert table.rows[0][-1] == ("robust" if knee["robust"] else "FAILS") and len(table.rows[0]) == 10
    assert document["bearing"]["cases"][0]["sommerfeld_number"] == pytest.approx(0.0617644, rel=1e-4)


def test_design_sweep_defaults_to_the_seeds_ratios(tmp_path):
    """Issue 12: the psi_x sweep is 0.1 ... 0.6 by default (seed 004 Sect. 5.2): `design sweep` on a
    case without [design.sweep] sweeps them (it used to do nothing and exit 0), and an empty
    [design.sweep] table means them (it was an error)."""
    seed = [0.1, 0.2, 0.3, 0.4, 0.5, 0.6]
    path = small_case(tmp_path)
    # the sweep takes the search options of `design slopes` (each of its searches 4 x 1 here)
    options = ("--generations", "1", "--population", "4", "--seed", "3", "--workers", "1")
    result = invoke("design", "sweep", str(path), *options, "--json", "-")
    assert result.exit_code == 0, result.stderr
    sweep = json.loads(result.stdout)["design"]["sweep"]
    assert [s["psi_x"] for s in sweep] == seed and all(s["pareto"] for s in sweep)
    assert all(len(s["pareto"]) <= 4 for s in sweep)
    path.write_text(path.read_text() + "\n[design.sweep]\n")
    assert list(load_case(path, only=["design"]).studies["design"].ratios) == seed
    assert not load_case(small_case(tmp_path), only=["design"]).studies["design"].ratios  # run: no sweep unless asked


def test_progress_counts_the_evaluations_of_the_search_robustness_and_sweep(tmp_path):
    """What the command line's bar is told (shaftline.registry.Tally): the search's evaluations of
    population x generations with the best h_min so far, then the robustness pairs (the knee at its
    operating point and in the seed's 7 scenarios), then the sweep's evaluations over its ratios;
    counts only grow and each step ends at its total."""
    from shaftline.registry import Tally

    case = load_case(small_case(tmp_path, extra="\n[design.sweep]\nratios = [0.2, 0.4]\n"))
    told: list[object] = []
    run_case(case, only=["design"], options={"design": {"workers": 1}}, progress=told.append)
    tallies = [t for t in told if isinstance(t, Tally)]
    steps = {label: [t for t in tallies if t.label == label] for label in ("design search", "robustness")}
    steps["misalignment sweep"] = [t for t in tallies if t.label == "misalignment sweep"]
    assert [t.done for t in steps["design search"]] == [6, 12] and {t.total for t in steps["design search"]} == {12}
    assert all("best h_min" in t.detail and t.detail.endswith(" µm") for t in steps["design search"])
    assert steps["robustness"][-1].done == steps["robustness"][-1].total == 8
    assert [t.done for t in steps["misalignment sweep"]] == [6, 12, 18, 24]
    assert {t.total for t in steps["misalignment sweep"]} == {24}
    assert "psi_x 0.4 (2 of 2)" in steps["misalignment sweep"][-1].detail
    for step in steps.values():
        assert [t.done for t in step] == sorted(t.done for t in step)


@pytest.mark.parametrize("kept", [True, False])
def test_ctrl_c_in_a_search_says_where_its_evaluations_are(tmp_path, kept):
    """A Ctrl-C that lands in the search (raised here from its progress report, after the first
    generation) becomes shaftline.errors.Interrupted, whose note names the store and how to resume,
    or says how to keep the evaluations next time; the store has the generation done."""
    import pandas as pd

    from shaftline.errors import Interrupted

    store = tmp_path / "store"
    overrides = {"design.search.store": str(store)} if kept else {}
    case = load_case(small_case(tmp_path), only=["design"], overrides=overrides)

    def stop(report: object) -> None:
        if "generation 1/" in str(report):
            raise KeyboardInterrupt

    with pytest.raises(Interrupted) as interrupted:
        run_case(case, options={"design": {"workers": 1, "task": "slopes"}}, progress=stop)
    if kept:
        assert f"kept in {store}: run the same command again" in interrupted.value.note
        assert len(pd.read_parquet(store / "evaluations.parquet")) == 6
    else:
        assert "were not kept: set [design.search] store = DIR in the case" in interrupted.value.note
        assert not store.exists()


def test_no_bar_codes_in_what_a_pipe_gets(tmp_path):
    """Standard error is not a terminal here (as in a pipe or a batch log): the run leaves no
    bar, spinner or cursor codes there, and the JSON on standard output is whole."""
    result = invoke("design", "slopes", str(small_case(tmp_path)), "--workers", "1", "--json", "-")
    assert result.exit_code == 0, result.stderr
    assert json.loads(result.stdout)["design"]["search"]["evaluations"] == 12
    for code in ("\x1b", "━", "\r", "design search:"):
        assert code not in result.stderr and code not in result.stdout


def test_design_sweep_verb(tmp_path):
    path = small_case(tmp_path, extra="\n[design.sweep]\nratios = [0.2, 0.4]\n")
    result = invoke("design", "sweep", str(path), "--json", "-")
    assert result.exit_code == 0, result.stderr
    design = json.loads(result.stdout)["design"]
    assert [s["psi_x"] for s in design["sweep"]] == [0.2, 0.4] and "search" not in design


def test_design_alone_builds_the_bearing_it_needs(tmp_path):
    """`only=["design"]` (a design verb) builds [bearing] for [design] but does not hand it over
    to be solved."""
    case = load_case(small_case(tmp_path), only=["design"])
    assert list(case.studies) == ["design"]
    assert case.studies["design"].problem.film.options.axial_nodes == 41


@pytest.mark.parametrize(
    ("change", "field"),
    [
        ("slope_bounds = [[0.5, 0.1], [0.0, 0.3]]", "design.slope_bounds[0]"),
        ("knuckle_bounds = [[0.0, 0.5]]", "design.knuckle_bounds[0]"),
        ("knuckle_bounds = [[0.2, 0.5], [0.6, 0.8]]", "design.knuckle_bounds"),
        ("segments = 3\nknuckle_bounds = [[0.6, 0.9], [0.1, 0.4]]", "design.knuckle_bounds[1]"),
        ("segments = 0", "design.segments"),
        ('objectives = ["min_film_thickness", "max_pressure", "hmin"]', "design.objectives[2]"),
    ],
)
def test_bad_design_input_is_one_line(tmp_path, change, field):
    key = change.split(" = ")[0]
    text = small_case(tmp_path).read_text()
    if key == "objectives":
        text = text.replace('objectives = ["min_film_thickness", "max_pressure"]', change)
    else:
        text = text.replace("segments = 2", change if key == "segments" else f"segments = 2\n{change}")
    path = tmp_path / "bad.toml"
    path.write_text(text)
    out = tmp_path / "out"
    result = invoke("design", "slopes", str(path), "--out", str(out))
    assert result.exit_code == 2
    lines = result.stderr.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith(f"error: {field}"), result.stderr
    assert not out.exists()


def test_design_needs_a_bearing_without_a_bore(tmp_path):
    text = small_case(tmp_path).read_text()
    design_only = text[text.index("[design]") :]
    path = tmp_path / "alone.toml"
    path.write_text('[case]\nname = "x"\n\n' + design_only)
    result = invoke("design", "slopes", str(path))
    assert result.exit_code == 2 and "a [bearing] or [alignment] table for [design]" in result.stderr
    bored = text.replace(
        "[bearing.operation]", "[[bearing.bore]]\nlength_fraction = 1.0\nslope_ratio = 0.3\n\n[bearing.operation]"
    )
    path.write_text(bored)
    result = invoke("design", "slopes", str(path))
    assert result.exit_code == 2 and result.stderr.startswith("error: bearing.bore = 'given'")


def _with_lubricant(tmp_path: Path, lubricant: str, extra: str = "") -> Path:
    text = small_case(tmp_path).read_text()
    text = text[: text.index("[bearing.lubricant]")] + lubricant + "\n" + text[text.index("[bearing.solver]") :]
    path = tmp_path / "lubricant.toml"
    path.write_text(text + extra)
    return path


def test_a_constant_viscosity_leaves_the_default_temperature_scenarios_out_with_a_warning(tmp_path):
    """examples/ntua_stern_tube.toml's lubricant (viscosity = "0.07 Pa*s") with the default
    scenarios: the two temperature scenarios, which need a viscosity that follows temperature, are
    left out, and said so before the results in the terminal, at the top of the report, in the
    robustness section and in the JSON; the five others run."""
    path = _with_lubricant(tmp_path, '[bearing.lubricant]\nviscosity = "0.07 Pa*s"\ndensity = "890 kg/m^3"\n')
    out = tmp_path / "out"
    shown = invoke("design", "robustness", str(path), "--workers", "1", "--out", str(out))
    assert shown.exit_code == 0, shown.stderr
    assert shown.stdout.startswith("warning: [design.robustness]: the seed's default scenarios +10 degC and +20 degC")
    assert "constant viscosity, which does not follow temperature" in " ".join(shown.stdout.split())
    document = json.loads((out / "results.json").read_text())
    assert len(document["warnings"]) == 1 and "+10 degC and +20 degC were left out" in document["warnings"][0]
    robustness = document["design"]["robustness"]
    assert [s["name"] for s in robustness["scenarios"]] == ["+20 % speed", "-30 % speed", "+50 % load",
                                                           "-50 % load", "+20 % load"]  # fmt: skip
    assert [item["scenario"] for item in robustness["left_out"]] == ["+10 degC", "+20 degC"]
    html = (out / "report.html").read_text()
    assert html.index("Left out of the defaults") < html.index("Slope-boring design")  # at the top
    assert "The default scenario +20 degC is left out" in html


def test_a_temperature_scenario_asked_for_with_a_constant_viscosity_is_an_input_error(tmp_path):
    """A temperature scenario the case lists itself is not left out: one line naming it, exit 2,
    nothing written."""
    scenarios = (
        '\n[[design.robustness.scenarios]]\nname = "slow"\nspeed_factor = 0.7\n'
        '\n[[design.robustness.scenarios]]\nname = "hot"\ntemperature_change = "10 K"\n'
    )
    path = _with_lubricant(tmp_path, '[bearing.lubricant]\nviscosity = "0.07 Pa*s"\n', scenarios)
    out = tmp_path / "out"
    result = invoke("design", "robustness", str(path), "--out", str(out))
    assert result.exit_code == 2 and not out.exists()
    (line,) = result.stderr.strip().splitlines()
    assert line.startswith("error: design.robustness.scenarios[1].temperature_change = 10 K: allowed 0 here: the ")
    assert "constant viscosity" in line


def test_a_listed_temperature_scenario_outside_the_viscosity_model_is_refused_before_solving(tmp_path):
    """Issue 12's bad input "a scenario that makes the viscosity fall outside the lubricant's
    range": one line naming the scenario, with the range and the temperature it would reach, told
    when the case is read (not after the search), exit 2, nothing written."""
    cold = '\n[[design.robustness.scenarios]]\nname = "arctic"\ntemperature_change = "-70 K"\n'
    path = small_case(tmp_path, extra=cold)
    out = tmp_path / "out"
    result = invoke("design", "robustness", str(path), "--out", str(out))
    assert result.exit_code == 2 and not out.exists()
    assert result.stderr.strip() == (
        "error: design.robustness.scenarios[0].temperature_change = -70 K: allowed a film temperature from -20 to "
        "150 degC, where the viscosity of SAE 30 (seed 004's viscosities) is known (40 - 70 = -30 degC is outside)"
    )
    with pytest.raises(InputError):  # when read: the search has not begun
        load_case(path, only=["design"])


def test_a_default_temperature_scenario_outside_the_viscosity_model_is_left_out(tmp_path):
    """Water at 90 degC: +10 degC stays (100 degC, the edge of the water model), +20 degC would
    take it to 110 degC, where the model does not hold, and is left out with the reason."""
    path = _with_lubricant(tmp_path, '[bearing.lubricant]\npreset = "water"\ntemperature = "90 degC"\n')
    case = load_case(path, only=["design"])
    study = case.studies["design"]
    assert [s.name for s in study.scenarios][-1] == "+10 degC"
    (left,) = study.left_out
    assert left[0] == "+20 degC" and "90 + 20 = 110 degC is outside the 0 to 100 degC" in left[1]
    assert len(case.warnings) == 1 and "default scenario +20 degC was left out" in case.warnings[0]


def test_every_design_in_the_report_folder_and_a_resumable_store(tmp_path):
    """`--out` gets every evaluated design (CSV and Parquet, linked from the report); `--store` keeps
    them as the search goes, and a second run on it takes them back (the same numbers) and
    carries on with more generations."""
    import pandas as pd

    case, out, store = small_case(tmp_path), tmp_path / "out", tmp_path / "store"
    first = invoke("design", "slopes", str(case), "--generations", "2", "--store", str(store), "--out", str(out))
    assert first.exit_code == 0, first.stderr
    table = pd.read_csv(out / "data" / "design_evaluations.csv")
    assert len(table) == 12
    assert all(
        status in ("ok", "contact", "not converged") or status.startswith("failed") for status in table["status"]
    )
    assert "data/design_evaluations.csv" in (out / "report.html").read_text()
    assert pd.read_parquet(out / "data" / "design_evaluations.parquet").equals(
        pd.read_parquet(store / "evaluations.parquet")
    )
    again = invoke("design", "slopes", str(case), "--generations", "3", "--store", str(store), "--json", "-")
    assert again.exit_code == 0, again.stderr
    assert json.loads(again.stdout)["design"]["search"]["evaluations"] == 18
    stored = pd.read_parquet(store / "evaluations.parquet")
    assert stored["min_film_thickness"][:12].tolist() == table["min_film_thickness"].tolist()
    other = invoke("design", "slopes", str(case), "--seed", "9", "--store", str(store))
    assert other.exit_code == 2 and "store" in other.stderr and "seed" in other.stderr


SHAFT_LINE = Path(__file__).resolve().parents[1] / "examples" / "ntua_shaft_line.toml"


def test_design_on_the_coupled_alignment(tmp_path):
    """[design] on a film bearing of [alignment]: the operating point is the coupled solution (its
    film force as the load, its bent journal held, its chord as psi_x), searched and reported the
    same way; the knee's film is in the comparison beside no slope."""
    text = SHAFT_LINE.read_text().replace(
        "axial_nodes = 100, circumferential_nodes = 60", "axial_nodes = 41, circumferential_nodes = 36"
    )
    path = tmp_path / "line.toml"
    path.write_text(text)
    out = tmp_path / "out"
    result = invoke(
        "design", "slopes", str(path), "--generations", "2", "--population", "6", "--out", str(out), "--json", "-"
    )
    assert result.exit_code == 0, result.stderr
    design = json.loads(result.stdout)["design"]
    assert design["shaft"] == "coupled"
    assert 0.1 < design["misalignment_ratio"] < 0.3  # the coupled chord, below the 0.3 of the point supports
    assert 300e3 < -design["load"][0] < 315e3  # the film force of the coupled solution (309.86 kN on points)
    assert "knee" in design["comparison"] and "no slope" in design["comparison"]
    assert "the coupled alignment (aft stern tube)" in (out / "report.html").read_text()


def test_sweep_on_the_coupled_alignment_is_of_the_linear_shaft_at_its_operating_point(tmp_path):
    """[design.sweep] on an [alignment] film bearing (docs/theory.md §14): each psi_x is a search
    on a straight journal tilted by psi_x 2c/L, under the coupled film force, at the coupled speed,
    viscosity and horizontal tilt; the report and the JSON say it is the linear shaft."""
    text = SHAFT_LINE.read_text().replace(
        "axial_nodes = 100, circumferential_nodes = 60", "axial_nodes = 41, circumferential_nodes = 36"
    )
    text = text.replace("population = 40", "population = 6").replace("generations = 40", "generations = 2")
    path = tmp_path / "line.toml"
    path.write_text(text + "\n[design.sweep]\nratios = [0.2, 0.5]\n")
    case = load_case(path, only=["design"])
    result = run_case(case, options={"design": {"task": "sweep", "workers": 1}})["design"]
    coupled = result.problem  # the operating point: the coupled film force and journal
    g = coupled.film.geometry
    assert g.bent_journal is not None and result.search is None
    for ratio, searched in zip((0.2, 0.5), result.sweep.searches, strict=True):
        swept = searched.problem
        assert swept.tilt_y == pytest.approx(ratio * 2 * g.radial_clearance / g.length)
        assert swept.film.geometry.bent_journal is None  # straight: the linear shaft
        assert (swept.load_y, swept.load_z, swept.tilt_z) == (coupled.load_y, coupled.load_z, coupled.tilt_z)
        assert swept.film.operating == coupled.film.operating
        assert len(searched.evaluations) == 12 and len(searched.pareto) >= 1
    out = tmp_path / "out"
    shown = invoke("design", "sweep", str(path), "--workers", "1", "--out", str(out), "--json", "-")
    assert shown.exit_code == 0, shown.stderr
    design = json.loads(shown.stdout)["design"]
    assert design["sweep_shaft"] == "linear" and [s["psi_x"] for s in design["sweep"]] == [0.2, 0.5]
    assert "on the linear shaft at the coupled operating point of aft stern tube" in (out / "report.html").read_text()


@pytest.mark.parametrize(
    ("extra", "message"),
    [
        ('shaft = "linear"\n', "design.shaft = 'linear'"),
        ('bearing = "intermediate"\n', "design.bearing = 'intermediate'"),
    ],
)
def test_bad_design_on_an_alignment(tmp_path, extra, message):
    text = SHAFT_LINE.read_text()
    if extra.startswith("["):
        text += "\n" + extra
    else:
        text = text.replace('bearing = "aft stern tube"\n', "").replace("[design]\n", "[design]\n" + extra, 1)
    path = tmp_path / "line.toml"
    path.write_text(text)
    result = invoke("design", "slopes", str(path))
    assert result.exit_code == 2 and result.stderr.startswith(f"error: {message}"), result.stderr


def test_ctrl_c_keeps_the_evaluations_and_the_search_resumes(tmp_path):
    """SIGINT to a long search (a real process, as a user's Ctrl-C): exit 130, a line saying where
    the evaluations are, nothing in --out; the store has whole generations, and the same search
    started again on it takes them back and goes on."""
    import signal
    import subprocess
    import sys
    import time

    import pandas as pd

    case, store, out = small_case(tmp_path), tmp_path / "store", tmp_path / "out"
    command = [sys.executable, "-m", "shaftline.cli", "design", "slopes", str(case), "--generations", "500",
               "--population", "6", "--workers", "1", "--store", str(store), "--out", str(out)]  # fmt: skip
    process = subprocess.Popen(command, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    deadline = time.monotonic() + 120.0
    while not (store / "evaluations.parquet").exists() and time.monotonic() < deadline:
        time.sleep(0.2)
    time.sleep(1.0)
    process.send_signal(signal.SIGINT)
    _, stderr = process.communicate(timeout=60)
    assert process.returncode == 130, stderr
    assert f"kept in {store}" in stderr and not out.exists()
    done = pd.read_parquet(store / "evaluations.parquet")
    assert len(done) % 6 == 0 and 0 < len(done) < 3000
    generations = len(done) // 6 + 1
    again = invoke("design", "slopes", str(case), "--generations", str(generations), "--population", "6",
                   "--store", str(store), "--json", "-")  # fmt: skip
    assert again.exit_code == 0, again.stderr
    assert json.loads(again.stdout)["design"]["search"]["evaluations"] == 6 * generations
    resumed = pd.read_parquet(store / "evaluations.parquet")
    assert resumed["min_film_thickness"][: len(done)].tolist() == done["min_film_thickness"].tolist()


def test_robustness_of_named_designs_and_of_a_file(tmp_path):
    """Named designs need no search: `design robustness` evaluates them alone; `--designs FILE` takes
    them from a CSV (here the front of an earlier search's design_evaluations.csv)."""
    extra = """
[[design.robustness.named]]
name = "seed double slope"
slopes = [0.31, 0.11]
knuckles = [0.61]
"""
    path = small_case(tmp_path, extra=extra)
    path.write_text(path.read_text().replace('designs = "knee"', 'designs = "named"'))
    result = invoke("design", "robustness", str(path), "--json", "-")
    assert result.exit_code == 0, result.stderr
    design = json.loads(result.stdout)["design"]
    assert "search" not in design
    (seed,) = design["robustness"]["designs"]
    assert seed["name"] == "seed double slope" and seed["x"] == [0.31, 0.11, 0.61]
    out = tmp_path / "first"
    assert invoke("design", "slopes", str(small_case(tmp_path)), "--out", str(out)).exit_code == 0
    front = out / "data" / "design_evaluations.csv"
    import pandas as pd

    table = pd.read_csv(front)
    result = invoke("design", "robustness", str(small_case(tmp_path)), "--designs", str(front), "--json", "-")
    assert result.exit_code == 0, result.stderr
    chosen = json.loads(result.stdout)["design"]["robustness"]["designs"]
    # named by their data row in the file (the knee as such), so that each can be found there
    expected = ["knee" if table["knee"][k] else f"row {k + 1}" for k in table.index[table["pareto"]]]
    assert [d["name"] for d in chosen] == expected and "knee" in expected
    for d in chosen:
        row = table[table["knee"]] if d["name"] == "knee" else table.iloc[[int(d["name"][4:]) - 1]]
        assert d["x"] == row[["slope_1", "slope_2", "knuckle_1"]].iloc[0].tolist()
    bad = tmp_path / "bad.csv"
    bad.write_text("name,slope_1\\nx,0.3\\n")
    result = invoke("design", "robustness", str(small_case(tmp_path)), "--designs", str(bad))
    assert result.exit_code == 2 and result.stderr.startswith("error: --designs"), result.stderr


@pytest.mark.parametrize("knuckles", [[1.5], [0.0]])
def test_a_named_knuckle_off_the_bearing_is_refused(tmp_path, knuckles):
    """The bore clips a knuckle to the bearing's ends: 1.5 L would silently be a single slope."""
    extra = f"""
[[design.robustness.named]]
name = "off"
slopes = [0.3, 0.1]
knuckles = {knuckles}
"""
    path = small_case(tmp_path, extra=extra)
    path.write_text(path.read_text().replace('designs = "knee"', 'designs = "named"'))
    out = tmp_path / "out"
    result = invoke("design", "robustness", str(path), "--out", str(out))
    assert result.exit_code == 2
    lines = result.stderr.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith("error: design.robustness.named[0].knuckles[0]"), result.stderr
    assert not out.exists()


def test_a_front_on_a_bound_is_a_finding(tmp_path):
    """A fore slope held to [0, 0.05] (the journal wants 0.3): the search moves the knuckle as far forward as
    it may go instead, so the front sits on the knuckle's upper bound, which is said as a design
    criterion (exit 0, 3 with --strict)."""
    path = small_case(tmp_path)
    path.write_text(path.read_text().replace("segments = 2", "segments = 2\nslope_bounds = [[0.0, 0.6], [0.0, 0.05]]"))
    options = ("--generations", "8", "--population", "12")
    result = invoke("design", "slopes", str(path), *options, "--json", "-")
    assert result.exit_code == 0, result.stderr
    texts = [f["text"] for f in json.loads(result.stdout)["findings"]]
    assert any("upper bound of knuckle_1 (0.9)" in t for t in texts), texts
    assert invoke("design", "slopes", str(path), *options, "--strict").exit_code == 3
