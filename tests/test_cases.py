"""Case files: every bad input gives one clear error naming the field by its path."""

from __future__ import annotations

import copy

import numpy as np
import pytest

from shaftline.cases import parse_case
from shaftline.errors import InputError

BASE = {
    "bearing": {
        "length": "0.1 m",
        "diameter": "0.1 m",
        "radial_clearance": "0.1 mm",
        "operation": {"speed": "600 rpm", "load": "5 kN"},
        "lubricant": {"viscosity": "0.02 Pa*s"},
    }
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
    study = parse_case(copy.deepcopy(BASE))["bearing"]
    case = study.cases[0]
    assert case.geometry.radial_clearance == pytest.approx(1e-4)
    assert case.load_y == pytest.approx(-5e3)
    assert case.options.cavitation == "reynolds"
    assert case.operating.speed == pytest.approx(20 * 3.141592653589793)


def test_preset_and_temperature():
    data = with_change("bearing.lubricant", {"preset": "ISO VG 68", "temperature": "50 degC"})
    case = parse_case(data)["bearing"].cases[0]
    assert 0.02 < case.operating.viscosity < 0.06


def test_defaults_come_from_the_domain():
    """The schema's defaults are the domain dataclasses' (one source, no drift)."""
    from shaftline.cases.loader import case_model
    from shaftline.cpp.motion import CarrierModel
    from shaftline.film.bearing import SolverOptions

    model = case_model()
    solver = model.model_fields["bearing"].annotation.__args__[0].model_fields["solver"].default
    for name in ("axial_nodes", "circumferential_nodes", "cavitation", "min_film_floor", "tolerance"):
        assert getattr(solver, name) == getattr(SolverOptions(), name)
    from shaftline.cpp.case import MotionSection

    for name in ("stiffness", "damping", "stribeck_velocity", "threshold_velocity", "friction"):
        assert MotionSection.model_fields[name].default == CarrierModel.__dataclass_fields__[name].default


@pytest.mark.parametrize(
    "path, value, field, fragment",
    [
        ("bearing.radial_clearance", "0 mm", "bearing.radial_clearance", "> 0"),
        ("bearing.radial_clearance", "-0.1 mm", "bearing.radial_clearance", "-0.0001 m: allowed > 0"),
        ("bearing.length", "0 m", "bearing.length", "> 0"),
        ("bearing.diameter", "-1 m", "bearing.diameter", "> 0"),
        ("bearing.length", "0.5 kg", "bearing.length", "quantity of length"),
        ("bearing.length", "1 parsecz", "bearing.length", "unit"),
        ("bearing.operation.speed", "0 rpm", "bearing.operation.speed", "> 0 when the bearing carries a load"),
        ("bearing.operation.speed", "-10 rpm", "bearing.operation.speed", ">= 0"),
        ("bearing.lubricant.viscosity", "0 Pa*s", "bearing.lubricant.viscosity", "> 0"),
        ("bearing.lubricant.viscosity", "-1 cP", "bearing.lubricant.viscosity", "> 0"),
        ("bearing.length", float("nan"), "bearing.length", "finite"),
        ("bearing.operation.load", "nan kN", "bearing.operation.load", "finite"),
        ("bearing.lenght", "1 m", "bearing.lenght", "did you mean 'length'"),
        ("bearing.operation.speed", None, "bearing.operation.speed", "required"),
        ("bearing.solver", {"axial_nodes": 3}, "bearing.solver.axial_nodes", ">= 5"),
        ("bearing.solver", {"circumferential_nodes": 10}, "bearing.solver.circumferential_nodes", ">= 16"),
        ("bearing.solver", {"cavitation": "magic"}, "bearing.solver.cavitation", "'reynolds'"),
        ("bearing.rotation", "sideways", "bearing.rotation", "clockwise"),
        ("bearing.lubricant.preset", "ISO VG 68", "bearing.lubricant.viscosity", "exactly one"),
        ("bearing.lubricant", {"preset": "ISO VG 69", "temperature": 40}, "bearing.lubricant.preset", "iso vg 68"),
        ("bearing.operation", {"speed": 10, "load": 0}, "bearing.operation.load", "> 0"),
        ("bearing.bore", [{"length_fraction": 1.0}], "bearing.bore[0].slope", "either slope or slope_ratio"),
        ("bearing.variants", [{"name": "x"}, {"name": "x"}], "bearing.variants[1].name", "not used"),
        ("bearing.variants", [{"name": "unnamed case"}], "bearing.variants[0].name", "other than the case's"),
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
    assert error.value.field.startswith("bearing.bore")
    assert "sum" in str(error.value)


def test_variant_bore_errors_name_the_variant():
    data = with_change("bearing.variants", [{"name": "v", "bore": [{"length_fraction": 0.5, "slope": 0.0}]}])
    with pytest.raises(InputError) as error:
        parse_case(data)
    assert error.value.field.startswith("bearing.variants[0].bore")


def test_nan_in_a_list():
    data = with_change("bearing.bent_journal", {"z": [0.0, float("nan")], "dy": [0.0, 0.0]})
    with pytest.raises(InputError) as error:
        parse_case(data)
    assert error.value.field == "bearing.bent_journal.z[1]"


def test_jfo_without_feed_is_refused():
    with pytest.raises(InputError) as error:
        parse_case(with_change("bearing.solver", {"cavitation": "jfo"}))
    assert error.value.field == "bearing.operation.cavitation_pressure"


def test_the_old_layout_says_where_tables_went():
    old = {
        "bearing": {"length": 0.1, "diameter": 0.1, "radial_clearance": 1e-4},
        "operation": {"speed": 60, "load": 5e3},
        "lubricant": {"viscosity": 0.02},
    }
    with pytest.raises(InputError) as error:
        parse_case(old)
    assert error.value.field == "operation" and "[bearing.operation]" in str(error.value)
    with pytest.raises(InputError) as error:
        parse_case({"shaft": {"segments": []}})
    assert "[alignment.shaft]" in str(error.value)


def test_nothing_to_solve():
    with pytest.raises(InputError) as error:
        parse_case({"case": {"name": "empty"}})
    assert "[bearing]" in str(error.value) and "[alignment]" in str(error.value)


def test_overrides_replace_fields_before_validation():
    case = parse_case(copy.deepcopy(BASE), overrides={"bearing.operation.load": "7 kN"})
    assert case["bearing"].cases[0].load_y == pytest.approx(-7e3)


def test_film_profile_from_csv(tmp_path):
    rows = ["theta_deg,z,delta"]
    for z in (0.0, 100.0):
        for theta in range(0, 360, 30):
            rows.append(f"{theta},{z},{0.02 if theta == 180 else 0.0}")
    (tmp_path / "wear.csv").write_text("\n".join(rows))
    data = with_change("bearing.film_profile", {"file": "wear.csv", "length_unit": "mm"})
    profile = parse_case(data, tmp_path)["bearing"].cases[0].geometry.film_profile
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


WEAR = {
    "wear": {
        "design_pitch_angle": "28 deg",
        "bearing_radius": "0.392 m",
        "contact_pressure": "21 MPa",
        "allowable_depth": "0.2 mm",
        "wear_rate": "0.54e-7 mm^3/(N*m)",
        "pitch_travel_per_voyage": 9.54,
        "service": {"voyages_per_day": 10, "days_per_year": 340, "years": 5},
    }
}


def test_percent_fields_take_percent_signs():
    """dead_band is in % of design pitch: '0.5 %' is 0.5, as the number 0.5 is (pint alone
    would make it 0.005, a dead band 100 times too fine)."""
    data = copy.deepcopy(WEAR)
    data["wear"]["dead_band"] = "0.5 %"
    assert parse_case(data)["wear"].dead_band == pytest.approx(0.5)


@pytest.mark.parametrize(
    "change, field, fragment",
    [
        ({"design_pitch_angle": "90 deg"}, "wear.design_pitch_angle", "in (0, 1.5708)"),
        ({"design_pitch_angle": 28}, "wear.design_pitch_angle", "in (0, 1.5708)"),  # radians
        ({"pitch_travel_per_voyage": 0}, "wear.pitch_travel_per_voyage", "> 0"),
        ({"fretting": {"amplitude": "-0.3 mm", "shaft_speed": "150 rpm"}}, "wear.fretting.amplitude", "> 0"),
        (
            {"weibull": {"wear_depths": ["0.1 mm"] * 3, "test_pressure": "48 MPa", "test_distance": "10 km"}},
            "wear.weibull.wear_depths",
            "not all equal",
        ),
        ({"dead_band": "0.5 mm"}, "wear.dead_band", "quantity of percent"),
    ],
)
def test_wear_inputs(change, field, fragment):
    data = copy.deepcopy(WEAR)
    data["wear"].update(change)
    with pytest.raises(InputError) as error:
        parse_case(data)
    assert error.value.field == field and fragment in str(error.value)


@pytest.mark.parametrize(
    "path, value, message",
    [
        ("bearing.lenght", "1 m", "bearing.lenght = '1 m': allowed no such field; did you mean 'length'?"),
        (
            "bearing.lubrication",
            {"viscosity": 0.02},
            "bearing.lubrication = '{...}': allowed no such field; did you mean",
        ),
        ("bearing.lubricant.density", "900 kg/m^3", "bearing.lubricant.density"),  # with a preset: see below
        ("bearin", {}, "bearin = '{...}': allowed one of the tables"),
    ],
)
def test_misspelt_keys_are_named(path, value, message):
    data = with_change(path, value)
    if path == "bearing.lenght":
        data["bearing"].pop("length")
    if path == "bearing.lubrication":
        data["bearing"].pop("lubricant")
    if path == "bearing.lubricant.density":
        data["bearing"]["lubricant"] = {"preset": "ISO VG 68", "temperature": 40, "density": 900}
    with pytest.raises(InputError) as error:
        parse_case(data)
    assert str(error.value).startswith(message)


def test_a_variants_own_tilt_is_named_when_it_does_not_fit():
    from shaftline.pipeline import run_case

    data = with_change("bearing.variants", [{"name": "tilted", "tilt_vertical": "3 mrad"}])
    with pytest.raises(InputError) as error:
        run_case(parse_case(data))
    assert error.value.field == "bearing.variants[0].tilt_vertical"


def test_all_moved_tables_are_named():
    with pytest.raises(InputError) as error:
        parse_case({"bearing": {}, "operation": {}, "lubricant": {}, "shaft": {}})
    text = str(error.value)
    for old, new in (
        ("operation", "bearing.operation"),
        ("lubricant", "bearing.lubricant"),
        ("shaft", "alignment.shaft"),
    ):
        assert f"[{old}] under [{new}]" in text


def test_booleans_are_not_numbers():
    import tomllib
    from pathlib import Path

    example = tomllib.loads((Path(__file__).parents[1] / "examples" / "cpp_blade_bearing.toml").read_text())
    example["cpp"]["loads"]["harmonics"][0]["amplitude"] = True
    with pytest.raises(InputError) as error:
        parse_case(example, only=["cpp"])
    assert error.value.field == "cpp.loads.harmonics[0].amplitude"


def test_input_fingerprints_are_read_in_blocks(tmp_path):
    """The report's SHA-256 of each input file equals hashlib's of its bytes, and fingerprinting a
    64 MiB input (a recording ``monitor identify`` names is an input) holds at most a few blocks of
    it in memory: read whole, an hour's recording of 4.4 GiB would take that much memory."""
    import hashlib
    import tracemalloc

    from shaftline.cases.loader import FINGERPRINT_BLOCK, _fingerprints

    path = tmp_path / "recording.bin"
    data = np.random.default_rng(1).bytes(64 << 20)
    path.write_bytes(data)
    expected = hashlib.sha256(data).hexdigest()
    del data
    tracemalloc.start()
    try:
        (found,) = _fingerprints([path, tmp_path / "missing.csv"])
        _, peak = tracemalloc.get_traced_memory()
    finally:
        tracemalloc.stop()
    assert found == (str(path), expected, 64 << 20)
    assert peak < 3 * FINGERPRINT_BLOCK, peak
