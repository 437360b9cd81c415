"""Case files: every bad input gives one clear error naming the field."""

from __future__ import annotations

import copy

import pytest

from shaftline.cases import parse_case
from shaftline.errors import InputError

BASE = {
    "bearing": {"length": "0.1 m", "diameter": "0.1 m", "radial_clearance": "0.1 mm"},
    "operation": {"speed": "600 rpm", "load": "5 kN"},
    "lubricant": {"viscosity": "0.02 Pa*s"},
}


def with_change(path: str, value):
    data = copy.deepcopy(BASE)
    *parents, last = path.split(".")
    node = data
    for part in parents:
        node = node.setdefault(part, {})
    if value is None:
        node.pop(last)
    else:
        node[last] = value
    return data


def test_minimal_case_parses():
    case = parse_case(copy.deepcopy(BASE))
    bearing = case.bearings[0]
    assert bearing.geometry.radial_clearance == pytest.approx(1e-4)
    assert bearing.load_y == pytest.approx(-5e3)
    assert bearing.options.cavitation == "reynolds"


def test_preset_and_temperature():
    data = with_change("lubricant", {"preset": "ISO VG 68", "temperature": "50 degC"})
    bearing = parse_case(data).bearings[0]
    assert 0.02 < bearing.operating.viscosity < 0.06


@pytest.mark.parametrize(
    "path, value, field, fragment",
    [
        ("bearing.radial_clearance", "0 mm", "bearing.radial_clearance", "> 0"),
        ("bearing.radial_clearance", "-0.1 mm", "bearing.radial_clearance", "> 0"),
        ("bearing.length", "0 m", "bearing.length", "> 0"),
        ("bearing.diameter", "-1 m", "bearing.diameter", "> 0"),
        ("bearing.length", "0.5 kg", "bearing.length", "length"),
        ("bearing.length", "1 parsecz", "bearing.length", "unit"),
        ("operation.speed", "0 rpm", "operation.speed", "> 0 when the bearing carries a load"),
        ("lubricant.viscosity", "0 Pa*s", "lubricant.viscosity", "> 0"),
        ("lubricant.viscosity", "-1 cP", "lubricant.viscosity", "> 0"),
        ("bearing.length", float("nan"), "bearing.length", "finite"),
        ("operation.load", "nan kN", "operation.load", "finite"),
        ("bearing.lenght", "1 m", "bearing.lenght", "no such field"),
        ("operation.speed", None, "operation.speed", "required"),
        ("solver", {"axial_nodes": 3}, "solver.axial_nodes", "resolve"),
        ("solver", {"circumferential_nodes": 10}, "solver.circumferential_nodes", "resolve"),
        ("solver", {"cavitation": "magic"}, "solver.cavitation", "reynolds"),
        ("bearing.rotation", "sideways", "bearing.rotation", "clockwise"),
        ("lubricant.preset", "ISO VG 68", "lubricant", "exactly one"),
    ],
)
def test_bad_input_names_the_field(path, value, field, fragment):
    with pytest.raises(InputError) as error:
        parse_case(with_change(path, value))
    assert error.value.field == field
    assert fragment in str(error.value)
    assert "\n" not in str(error.value)


def test_slope_segments_must_sum_to_one():
    data = with_change(
        "bearing.bore", [{"length_fraction": 0.6, "slope": "0.1 mrad"}, {"length_fraction": 0.3, "slope": "0 mrad"}]
    )
    with pytest.raises(InputError) as error:
        parse_case(data)
    assert error.value.field == "bearing.bore.length_fraction"


def test_nan_in_a_list():
    data = with_change("bearing.bent_journal", {"z": [0.0, float("nan")], "dy": [0.0, 0.0]})
    with pytest.raises(InputError) as error:
        parse_case(data)
    assert error.value.field == "bearing.bent_journal.z[1]"


def test_jfo_without_feed_is_refused():
    from shaftline.film import JournalBearing

    data = with_change("solver", {"cavitation": "jfo"})
    bearing_case = parse_case(data).bearings[0]
    with pytest.raises(InputError) as error:
        JournalBearing(bearing_case.geometry, bearing_case.operating, bearing_case.options)
    assert error.value.field == "operation.cavitation_pressure"


def test_film_profile_from_csv(tmp_path):
    rows = ["theta_deg,z,delta"]
    for z in (0.0, 100.0):
        for theta in range(0, 360, 30):
            rows.append(f"{theta},{z},{0.02 if theta == 180 else 0.0}")
    (tmp_path / "wear.csv").write_text("\n".join(rows))
    data = with_change("bearing.film_profile", {"file": "wear.csv", "length_unit": "mm"})
    profile = parse_case(data, tmp_path).bearings[0].geometry.film_profile
    assert profile.delta.shape == (2, 12)
    assert profile.z[-1] == pytest.approx(0.1)
    assert profile.delta.max() == pytest.approx(2e-5)


@pytest.mark.parametrize(
    "text, fragment",
    [
        ("theta_deg,z,delta\n0,0,0\n90,0,nan\n", "row 3, delta"),
        ("theta_deg,z,delta\n0,0,0\n90,0,0\n0,1,0\n", "full grid"),
        ("angle,z,delta\n0,0,0\n", "columns theta_deg, z, delta"),
    ],
)
def test_bad_film_profile_csv(tmp_path, text, fragment):
    (tmp_path / "wear.csv").write_text(text)
    with pytest.raises(InputError) as error:
        parse_case(with_change("bearing.film_profile", {"file": "wear.csv"}), tmp_path)
    assert fragment in str(error.value)
