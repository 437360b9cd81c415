"""Results that write themselves: the state's and the study's ``to_dict`` with units from the
fields' metadata, a study as a pandas table, the Stribeck curve as a table and a figure."""

from __future__ import annotations

import json
import math

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import pytest  # noqa: E402

from shaftline.cases import load_case  # noqa: E402
from shaftline.film.results import BearingState  # noqa: E402
from shaftline.film.stribeck import stribeck_curve  # noqa: E402
from shaftline.pipeline import dumps, results_document, run_case  # noqa: E402
from tests.conftest import MINIMAL_CASE  # noqa: E402

SPEEDS_RPM = (60.0, 200.0, 600.0)


@pytest.fixture(scope="module")
def study_result(tmp_path_factory):
    path = tmp_path_factory.mktemp("export") / "case.toml"
    path.write_text(MINIMAL_CASE)
    result = run_case(load_case(path))
    return result, json.loads(dumps(results_document(result)))


def test_the_state_writes_what_results_json_holds(study_result):
    """``BearingState.to_dict`` is the state's part of each case in results.json, key for key and
    number for number, and every key it writes has a unit in the study's units."""
    result, document = study_result
    study = result.results["bearing"]
    case = document["bearing"]["cases"][0]
    written = json.loads(dumps(study.cases[0].equilibrium.state.to_dict()))
    assert written and all(case[key] == value for key, value in written.items())
    assert set(written) <= set(document["bearing"]["units"])


def test_the_units_follow_the_parts_a_state_has():
    smooth, rough = BearingState.units(), BearingState.units(rough=True)
    assert "min_film_thickness" in smooth and smooth["min_film_thickness"] == "m"
    assert "asperity_load_share" in rough and "asperity_load_share" not in smooth
    assert smooth["attitude_angle_deg"] == "deg"


def test_a_study_is_a_table_with_one_row_per_case(study_result):
    result, document = study_result
    table = result.results["bearing"].to_pandas()
    assert list(table.index) == [case["name"] for case in document["bearing"]["cases"]]
    row = document["bearing"]["cases"][0]
    assert table["min_film_thickness"].iloc[0] == row["min_film_thickness"]
    # Every number of the table is a result with a unit in the study's units.
    numbers = set(table.select_dtypes("number").columns)
    assert numbers and numbers <= set(result.results["bearing"].units())


def test_the_stribeck_curve_is_a_table_and_a_figure(study_result):
    result, _ = study_result
    case = result.results["bearing"].cases[0].case
    curve = stribeck_curve(case, [rpm * math.pi / 30 for rpm in SPEEDS_RPM], backend="serial")
    table = curve.to_pandas()
    assert [math.isclose(a, b) for a, b in zip(table.index, SPEEDS_RPM, strict=True)] == [True] * 3
    written = curve.to_dict()
    assert list(table["min_film_thickness"]) == written["min_film_thickness"]
    assert list(table["min_film_thickness"]) == list(curve.min_film_thickness)
    figure, axes = plt.subplots(2, 1)
    assert curve.plot(ax=tuple(axes)) is not None
    assert axes[0].has_data()
    plt.close(figure)
