"""Plausibility of case files (issue 9): a value a real shaft line does not have is refused
as a likely unit slip, with the unit that would fit; ``[case] unusual`` lowers single guards.

The slips below are the ones a marine engineer makes: a bare number is SI, so a length in
mm, a speed in rpm, a load in kN, a mass in t or a viscosity in mPa s written without its
unit is off by a factor of 9.5 to 1000. Each expected suggestion is worked out by hand in
the comment beside it from the ranges declared in the schemas (the README's table).
"""

from __future__ import annotations

import copy
import re
import tomllib
from pathlib import Path
from typing import Any

import pytest
from pydantic import ValidationError

from shaftline import registry
from shaftline.cases import parse_case
from shaftline.cases.plausibility import ALTERNATIVES, ImplausibleInput, _walk_table, check_table
from shaftline.errors import InputError
from shaftline.units import to_si
from tests.conftest import MINIMAL_CASE, invoke

EXAMPLES = Path(__file__).resolve().parents[1] / "examples"


def example(name: str) -> dict[str, Any]:
    return tomllib.loads((EXAMPLES / name).read_text(encoding="utf-8"))


NTUA = example("ntua_stern_tube.toml")
ALIGNMENT = example("single_screw_alignment.toml")
CPP = example("cpp_blade_bearing.toml")
FERRY = example("ferry_wear.toml")


def changed(data: dict[str, Any], path: str, value: Any, unusual: list[str] | None = None) -> dict[str, Any]:
    """A copy of ``data`` with the field at the case-file path ``path`` set to ``value``."""
    data = copy.deepcopy(data)
    parts = re.findall(r"[^.\[\]]+|\[\d+\]", path)
    node: Any = data
    for part in parts[:-1]:
        node = node[int(part[1:-1])] if part.startswith("[") else node.setdefault(part, {})
    last = parts[-1]
    if last.startswith("["):
        node[int(last[1:-1])] = value
    else:
        node[last] = value
    if unusual is not None:
        data.setdefault("case", {})["unusual"] = unusual
    return data


def refused(data: dict[str, Any]) -> ImplausibleInput:
    with pytest.raises(ImplausibleInput) as error:
        parse_case(data, EXAMPLES)
    message = str(error.value)
    assert "\n" not in message
    return error.value


@pytest.mark.parametrize("name", sorted(p.name for p in EXAMPLES.glob("*.toml")))
def test_every_example_passes_the_guard_unchanged(name):
    case = parse_case(example(name), EXAMPLES)
    assert case.studies and case.unusual == ()


def test_the_message_names_field_value_range_and_the_likely_unit():
    error = refused(changed(NTUA, "bearing.length", 1050))
    assert str(error) == (
        "bearing.length = 1050 m: plausible 0.02 to 4 m; did you mean 1050 mm? "
        '(if 1050 m is right, add "bearing.length" to [case] unusual)'
    )
    assert error.field == "bearing.length" and error.value == 1050 and error.unit == "m"
    assert error.suggestions == ("1050 mm",)


@pytest.mark.parametrize(
    "data, path, value, field, suggestion",
    [
        # [bearing]: 900 rad/s is 8594 rpm (> 1500); 900 rpm = 94 rad/s is inside
        (NTUA, "bearing.operation.speed", 900, "bearing.operation.speed", "did you mean 900 rpm?"),
        # 70 Pa s is oil at 70 cP written bare; 70 mPa s is inside (0.1 mPa s to 5 Pa s)
        (NTUA, "bearing.lubricant.viscosity", 70, "bearing.lubricant.viscosity", "did you mean 70 mPa*s?"),
        # seed 004's own slip: "0.07 mPa s" for 0.07 Pa s (7e-5 Pa s < 1e-4)
        (NTUA, "bearing.lubricant.viscosity", "0.07 mPa*s", "bearing.lubricant.viscosity", "did you mean 0.07 Pa*s?"),
        # 0.3 rad is 300 mrad (> 10 mrad); 0.3 mrad and 0.3 deg (5.2 mrad) are inside
        (
            {**NTUA, "bearing": {**NTUA["bearing"], "operation": {"speed": "90 rpm", "load": "309.86 kN"}}},
            "bearing.operation.tilt_vertical",
            0.3,
            "bearing.operation.tilt_vertical",
            "did you mean 0.3 mrad or 0.3 deg?",
        ),
        # 212 degC for the 100 degC reference point; 212 degF = 100 degC
        (
            changed(NTUA, "bearing.lubricant", {"preset": "SAE 30", "temperature": 40}),
            "bearing.lubricant",
            {
                "kinematic_viscosity_1": "100 cSt",
                "temperature_1": 40,
                "kinematic_viscosity_2": "11 cSt",
                "temperature_2": 212,
                "temperature": 45,
            },
            "bearing.lubricant.temperature_2",
            "did you mean 212 degF?",
        ),
        # [alignment]: a station in mm (22.2 km > 300 m); 22200 mm and 22200 cm (222 m) are inside,
        # 22200 um (22 mm) is a thousandth of the range's size and is not offered
        (ALIGNMENT, "alignment.bearings[3].x", 22200, "alignment.bearings[3].x", "did you mean 22200 mm or 22200 cm?"),
        (
            ALIGNMENT,
            "alignment.conditions[1].offsets_y.intermediate",
            0.15,
            "alignment.conditions[1].offsets_y.intermediate",
            "did you mean 0.15 mm or 0.15 cm?",
        ),
        # 206 Pa for 206 GPa
        (ALIGNMENT, "alignment.shaft.youngs_modulus", 206, "alignment.shaft.youngs_modulus", "did you mean 206 GPa?"),
        # [cpp]: 250 m^3 of oil for 250 l; 250 cm^3 (0.25 l) is plausible for a small hub
        (CPP, "cpp.hydraulics.oil_volume", 250, "cpp.hydraulics.oil_volume", "did you mean 250 l or 250 cm^3?"),
        # 300 rad/s = 2865 rpm (> 1500 rpm)
        (CPP, "cpp.shaft_speed", 300, "cpp.shaft_speed", "did you mean 300 rpm?"),
        # [wear]: 0.54e-7 mm^3/(N m) written bare (5.4e-8 m^3/(N m) > 1e-11)
        (FERRY, "wear.wear_rate", 0.54e-7, "wear.wear_rate", "did you mean 5.4e-08 mm^3/(N*m)?"),
        # a 100 min voyage written bare is 100 s (< 180 s); 100 h is plausible as well
        (FERRY, "wear.service.voyage_duration", 100, "wear.service.voyage_duration", "did you mean 100 min or 100 h?"),
        # a percentage written as a share: 0.005 % (< 0.01 %) for 0.5 %
        (FERRY, "wear.dead_band", 0.005, "wear.dead_band", "did you mean 0.5 % (0.005 as a share)?"),
        # an entry of a list is named by its index
        (
            FERRY,
            "wear.weibull.wear_depths[2]",
            0.06,
            "wear.weibull.wear_depths[2]",
            "did you mean 0.06 mm or 0.06 cm?",
        ),
    ],
)
def test_a_unit_slip_is_refused_with_the_unit_that_fits(data, path, value, field, suggestion):
    error = refused(changed(data, path, value))
    assert error.field == field
    assert suggestion in str(error)


@pytest.mark.parametrize(
    "data, path, value, field, fragment",
    [
        # c/R: 0.45 in = 11.4 mm on R = 0.26 m gives 0.044 (> 0.02); 0.45 mm (1.7e-3) and
        # 0.45 cm (0.017) give plausible ratios
        (
            changed(NTUA, "bearing.radial_clearance", "0.45 in"),
            "bearing.diametral_clearance",
            None,
            "bearing.radial_clearance",
            "c/R = 0.044 with bearing.diameter = 0.52 m, plausible 0.0001 to 0.02; did you mean 0.45 mm or 0.45 cm?",
        ),
        # the same with the diametral clearance: 0.9 in on D = 0.52 m
        (
            NTUA,
            "bearing.diametral_clearance",
            "0.9 in",
            "bearing.diametral_clearance",
            "c/R = 0.044 with bearing.diameter = 0.52 m, plausible 0.0001 to 0.02; did you mean 0.9 mm or 0.9 cm?",
        ),
        # L/D: 25 mm on D = 0.52 m is 0.048 (< 0.2); 25 cm (0.48) and 25 in (1.22) fit
        (
            NTUA,
            "bearing.length",
            "25 mm",
            "bearing.length",
            "L/D = 0.0481 with bearing.diameter = 0.52 m, plausible 0.2 to 6; did you mean 25 cm or 25 in?",
        ),
        # W/(L D): 309.86 N on 1.05 m x 0.52 m is 568 Pa (< 1 kPa); 309.86 kN is 0.57 MPa
        (
            NTUA,
            "bearing.operation.load",
            309.86,
            "bearing.operation.load",
            "W/(L D) = 568 Pa with bearing.length = 1.05 m, bearing.diameter = 0.52 m, plausible 1000 to 5e+06 Pa; "
            "did you mean 309.86 kN?",
        ),
        # propeller mass for the shaft at it: 62 kg on d = 0.695 m gives 0.0235 (< 2); 62 t gives 23.5
        (
            ALIGNMENT,
            "alignment.propeller.mass",
            62,
            "alignment.propeller.mass",
            "plausible 2 to 200; did you mean 62 t?",
        ),
        # blade mass for the propeller: 2.6 kg on D = 4.5 m gives 3.8e-6 (< 3e-4); 2.6 t gives 3.8e-3
        (CPP, "cpp.loads.blade_mass", 2.6, "cpp.loads.blade_mass", "did you mean 2.6 t?"),
    ],
)
def test_every_cross_field_check_refuses_a_slip(data, path, value, field, fragment):
    if value is None:  # the change is made already; drop the other clearance
        data = copy.deepcopy(data)
        data["bearing"].pop("diametral_clearance")
    else:
        data = changed(data, path, value)
    error = refused(data)
    assert error.field == field
    assert fragment in str(error)


def test_an_absolute_suggestion_also_passes_the_ratio_checks_of_its_field():
    """450 (um meant) is 450 m: of the usual units only um gives a clearance whose c/R fits
    (450 mm is itself beyond 20 mm)."""
    data = changed(NTUA, "bearing.radial_clearance", 450)
    data["bearing"].pop("diametral_clearance")
    assert refused(data).suggestions == ("450 µm",)


def test_a_slip_in_another_field_of_a_ratio_is_suggested_when_that_field_is_a_bare_number():
    """W/(L D) with L = 0.105 m written bare: the load as written gives 5.7 MPa (> 5 MPa)."""
    data = changed(NTUA, "bearing.length", 0.105)
    error = refused(data)
    assert error.field == "bearing.operation.load"
    # the load in N would fit (5.7 kPa), and so would the length in ft (0.032 m gives 1.9e7 Pa,
    # no), or cm (0.00105 m, beyond 0.02 m: no); only the load's unit fits
    assert error.suggestions == ("309.8599 N",)


def test_unusual_lowers_exactly_the_fields_listed():
    long = changed(NTUA, "bearing.length", "5 m")  # L = 5 m is beyond 4 m, L/D = 9.6 beyond 6
    assert refused(long).field == "bearing.length"
    case = parse_case(changed(long, "case.unusual", ["bearing.length"]))
    assert case.unusual == ("bearing.length",)
    assert case["bearing"].cases[0].geometry.length == 5.0
    # the other fields keep their guard
    with pytest.raises(ImplausibleInput) as error:
        parse_case(changed(long, "bearing.diameter", 520, unusual=["bearing.length"]))
    assert error.value.field == "bearing.diameter"


def test_unusual_lowers_one_entry_of_a_list_or_a_whole_list():
    data = changed(ALIGNMENT, "alignment.bearings[3].offset_y", -0.08)  # an 80 mm drop
    data = changed(data, "alignment.bearings[4].offset_y", -0.08)
    with pytest.raises(ImplausibleInput) as error:
        parse_case(changed(data, "case.unusual", ["alignment.bearings[3].offset_y"]), EXAMPLES)
    assert error.value.field == "alignment.bearings[4].offset_y"
    deep = changed(FERRY, "wear.weibull.wear_depths[0]", "12 mm")
    deep = changed(deep, "wear.weibull.wear_depths[1]", "15 mm")
    assert parse_case(changed(deep, "case.unusual", ["wear.weibull.wear_depths"]), EXAMPLES).unusual == (
        "wear.weibull.wear_depths",
    )
    with pytest.raises(ImplausibleInput) as error:
        parse_case(changed(deep, "case.unusual", ["wear.weibull.wear_depths[0]"]), EXAMPLES)
    assert error.value.field == "wear.weibull.wear_depths[1]"


def test_unusual_lowers_the_cross_field_checks_that_name_the_field():
    light = changed(ALIGNMENT, "alignment.propeller.mass", "62 kg")
    assert refused(light).field == "alignment.propeller.mass"
    case = parse_case(changed(light, "case.unusual", ["alignment.propeller.mass"]), EXAMPLES)
    assert case["alignment"].line.propeller.mass == 62.0


@pytest.mark.parametrize(
    "data, path, fragment",
    [
        (NTUA, "bearing.lenght", "a field of the case with a plausible range; did you mean 'bearing.length'?"),
        (NTUA, "bearing.operation", "a field, not a table"),
        (NTUA, "bearing", "a field, not a table"),
        (NTUA, "bearing.*", "no wildcards"),
        (ALIGNMENT, "alignment.bearings[*].x", "no wildcards"),
        (ALIGNMENT, "alignment.bearings[9].x", "a field of the case with a plausible range"),
        (NTUA, "bearing.rotation", "a field of the case with a plausible range"),  # no range to lower
        (NTUA, "bearing.radial_clearance", "a field of the case with a plausible range"),  # not given
        (NTUA, "alignment.propeller.mass", "a field of a table of the case ([bearing])"),
    ],
)
def test_unusual_refuses_paths_that_name_no_guarded_field(data, path, fragment):
    good = "bearing.diameter" if "bearing" in data else "alignment.propeller.mass"  # the first entry is fine
    with pytest.raises(InputError) as error:
        parse_case(changed(data, "case.unusual", [good, path]), EXAMPLES)
    assert error.value.field == "case.unusual[1]"
    assert error.value.value == path
    assert fragment in str(error.value)


def test_alternative_units_read_back_to_their_factor():
    """Each suggested text is one a user can paste: units.to_si reads it as the value the
    suggestion was checked with."""
    for kind, alternatives in ALTERNATIVES.items():
        for alternative in alternatives:
            si = 2.5 * alternative.factor + alternative.offset
            text = alternative.text("2.5", si).split(" (")[0]  # "250 % (2.5 as a share)" -> "250 %"
            assert to_si(text, kind) == pytest.approx(si, rel=1e-9), (kind, text)


def _ranges(data: dict[str, Any]):
    for key, capability in registry.capabilities().items():
        if key in data:
            section = capability.schema().model_validate(data[key])
            yield key, section, _walk_table(section, data[key], key)


#: Kinds with common units a factor of 1000 apart (mm and m, kN and N, t and kg, kPa and MPa,
#: l and m^3, mrad and rad, t m^2 and kg m^2, ...). Speeds (rpm, rad/s, Hz), temperatures,
#: counts, shares and percentages have none; wear rates slip by 1e9 (mm^3 for m^3).
SLIP_KINDS = {
    "length", "force", "moment", "mass", "pressure", "viscosity", "kinematic_viscosity", "density", "volume",
    "area", "stiffness", "force_per_length", "inertia", "angle", "frequency", "time", "acceleration",
}  # fmt: skip

#: Example values whose slip by the factor is itself a real value: an absolute range cannot
#: tell them apart, and no cross-field check covers them (yet). By example file.
NOT_CAUGHT = {
    "ferry_wear.toml": {
        # the end of a window into a voyage: 4200 s x 1000 is 49 days, a long voyage (a slipped
        # start is refused as it falls after the end)
        ("wear.mimo.end", 1000.0): "a long voyage",
    },
    "cpp_blade_bearing.toml": {
        # small components of a blade load: x 1000 is a load of the largest propellers
        ("cpp.loads.mean_force[2]", 1000.0): "8 MN",
        ("cpp.loads.mean_moment[0]", 1000.0): "40 MN m",
        ("cpp.loads.mean_moment[2]", 1000.0): "5 MN m",
        ("cpp.hydraulics.other_friction", 1000.0): "20 MN",
        # a thousandth of a large ship's value is one of a small craft
        ("cpp.hydraulics.oil_volume", 1e-3): "a 0.25 l hub",
        ("cpp.motion.inertia", 1e-3): "0.65 kg m^2",
    },
    "single_screw_alignment.toml": {
        ("alignment.masses[0].mass", 1e-3): "a 14 kg coupling",
        ("alignment.bearings[2].stiffness", 1e-3): "a soft 2.5 kN/mm support",
        # a shaft piece of a few mm is a step or a flange; the bearings then fall off the shaft,
        # which the model refuses (tests/shaft)
        ("alignment.shaft.segments[1].length", 1e-3): "7.6 mm",
        ("alignment.shaft.segments[3].length", 1e-3): "12 mm",
        ("alignment.shaft.segments[6].length", 1e-3): "6.6 mm",
    },
    "contact_ehl.toml": {
        # steel's 206 GPa / 1000 is a polymer's modulus (nylon, PEEK, PE: 0.2-4 GPa)
        ("contact.body_1.youngs_modulus", 1e-3): "a 206 MPa polymer",
        ("contact.body_2.youngs_modulus", 1e-3): "a 206 MPa polymer",
    },
    # pinion torques span 0.1 N m (instrument gears) to MN m (marine main gears): x 1000 or / 1000
    # of a test step is another gear's torque; a check against the pair's size is not coded (yet)
    "gears_scuffing.toml": {
        **{(f"gears.test.torques[{k}]", 1000.0): "a torque of larger gears" for k in range(10)},
        **{(f"gears.test.torques[{k}]", 1e-3): "a torque of small gears" for k in range(1, 10)},
    },
    "ntua_shaft_line.toml": {
        ("alignment.shaft.segments[0].length", 1e-3): "14.5 mm: the bearings fall off the shaft (refused by the model)",
    },
    "seed001_rig_alignment_liner.toml": {
        ("alignment.shaft.segments[0].length", 1e-3): "6 mm: the bearings fall off the shaft (refused by the model)",
        ("alignment.masses[0].x", 1000.0): "200 m: off the 6 m shaft (refused by the model)",
        ("alignment.masses[0].mass", 1e-3): "a 7.5 kg coupling",
    },
    "monitor_rig_shaft.toml": {
        ("alignment.shaft.segments[0].length", 1e-3): "6 mm: the bearings fall off the shaft (refused by the model)",
        ("alignment.masses[0].x", 1000.0): "200 m: off the 6 m shaft (refused by the model)",
        ("alignment.masses[0].mass", 1e-3): "a 7.5 kg coupling",
        # the rig's 1e9 N/m springs (seed 001's FE model): 1e12 is a rigid support, 1e6 a soft mount
        ("alignment.bearings[0].stiffness", 1000.0): "a rigid support",
        ("alignment.bearings[0].stiffness", 1e-3): "a soft 1 kN/mm mount",
    },
}


@pytest.mark.parametrize("name", sorted(p.name for p in EXAMPLES.glob("*.toml")))
def test_a_factor_1000_slip_of_an_example_value_is_caught(name):
    """The ranges catch a slip of a factor of 1000 of the examples' values: each value of a
    kind in SLIP_KINDS times 1000, and divided by 1000 unless its range holds zero (then a
    small value is plausible), is refused, but for the listed values a real machine has."""
    data = example(name)
    missed = []
    for key, section, walk in _ranges(data):
        for item in walk.values:
            if item.quantity.kind not in SLIP_KINDS or item.value == 0:
                continue
            factors = [1000.0] if item.plausible.low <= 0 <= item.plausible.high else [1000.0, 1e-3]
            for factor in factors:
                slipped = changed({key: data[key]}, item.path, item.value * factor)[key]
                try:
                    check_table(type(section).model_validate(slipped), slipped, key)
                except (ImplausibleInput, ValidationError):  # beyond the hard bounds: refused as well
                    continue
                missed.append((item.path, factor))
    expected = list(NOT_CAUGHT.get(name, {}))
    assert sorted(missed) == sorted(expected)


def test_schema_json_gives_the_plausible_range():
    from shaftline.cases.docs import json_schema

    schema = json_schema()
    bearing = schema["$defs"]["BearingSection"]["properties"]["length"]
    assert bearing["x-plausible"] == [0.02, 4.0] and bearing["x-unit"] == "m"
    assert "seed 004" in bearing["x-plausible-source"]


def test_the_command_line_refuses_a_slip_in_one_line(tmp_path):
    case = tmp_path / "case.toml"
    case.write_text(MINIMAL_CASE.replace('length = "0.1 m"', "length = 100"))
    result = invoke("bearing", "solve", str(case))
    assert result.exit_code == 2
    lines = [line for line in result.stderr.splitlines() if line.strip()]
    # 100 cm would be a plausible length but gives L/D = 10 on the 0.1 m journal: not offered
    assert lines == [
        "error: bearing.length = 100 m: plausible 0.02 to 4 m; did you mean 100 mm? "
        '(if 100 m is right, add "bearing.length" to [case] unusual)'
    ]
    assert result.stdout == ""


def test_speed_range_is_in_rpm_as_documented():
    """The speed range is declared in rad/s from 0.1 and 1500 rpm, as its source says."""
    from shaftline.cases.types import SHAFT_SPEED

    assert SHAFT_SPEED.low == pytest.approx(to_si("0.1 rpm", "speed"))
    assert SHAFT_SPEED.high == pytest.approx(to_si("1500 rpm", "speed"))
