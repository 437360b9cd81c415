"""``shaftline contact ehl``: the example, results.json fields, the report, bad input."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from tests.conftest import assert_refused, invoke

ROOT = Path(__file__).resolve().parents[2]
EXAMPLE = ROOT / "examples" / "contact_ehl.toml"


def test_example_runs_with_report_and_json(tmp_path):
    out = tmp_path / "out"
    result = invoke("contact", "ehl", str(EXAMPLE), "--out", str(out), "--json", "-")
    assert result.exit_code == 0, result.stderr
    contact = json.loads(result.stdout)["contact"]
    op = contact["operating"]
    # Hertz at the example's 300 N/mm on R = 11.97 mm, E' = 226.4 GPa: p_H = sqrt(w' E' / (2 pi R))
    assert op["peak_pressure"] == pytest.approx(
        (3e5 * contact["reduced_modulus"] / (2 * 3.14159265 * 0.01197)) ** 0.5, rel=1e-4
    )
    assert op["slide_roll"] == pytest.approx(0.1, abs=2e-3)
    assert 0 < op["central_film"] < 2e-6 and op["minimum_film"] < op["central_film"]
    assert contact["lubrication"] in ("mixed", "full film", "boundary-dominated")
    assert len(contact["speed_sweep"]["friction"]) == len(contact["speed_sweep"]["factor"])
    # friction over the speed sweep: boundary at the slowest point, below it at the operating point
    assert contact["speed_sweep"]["friction"][0] > 2 * op["friction"]
    assert "MIL-PRF-23699" in contact["lubricant"]["name"]
    for name in ("contact_stribeck", "contact_sweeps"):
        assert (out / "figures" / f"{name}.png").stat().st_size > 10_000
    assert "Lubricated contact" in (out / "report.html").read_text()


@pytest.mark.parametrize(
    ("old", "new", "message"),
    [
        ('lubricant = "MIL-PRF-23699"', 'lubricant = "SAE 90"', "contact.lubricant = 'SAE 90': allowed one of"),
        (
            'temperature = "90 degC"',
            'temperature = "190 degC"',
            "contact.temperature = 190 degC: allowed in [-20, 200]",
        ),
        (
            'temperature = "90 degC"',
            'temperature = "220 degC"',
            "contact.temperature = 220 degC: allowed in [-20, 200] degC",
        ),
        ('load_per_length = "300 N/mm"', 'load = "3 kN"', "contact.load"),
        ('radius = "23.94 mm"\nspeed = "23.8 m/s"', 'radius = "23.94 mm"\nspeed = "-1 m/s"', "contact.body_1.speed"),
        ('roughness_ra = "0.4 um"', 'roughness_ra = "0.4 um"\nroughness_rq = "0.5 um"', "contact.body_1.roughness_ra"),
        ("speed_factors = [0.002, 2.0]", "speed_factors = [2.0, 0.002]", "contact.sweep.speed_factors"),
        ('geometry = "line"', 'geometry = "line"\nfilm_method = "hamrock_dowson"', "contact.film_method"),
    ],
)
def test_bad_input_one_line_exit_2_nothing_written(tmp_path, old, new, message):
    text = EXAMPLE.read_text()
    assert old in text
    case = tmp_path / "case.toml"
    case.write_text(text.replace(old, new))
    out = tmp_path / "out"
    result = invoke("contact", "ehl", str(case), "--out", str(out))
    if "190 degC" in new:
        # inside the ester's data range: runs
        assert result.exit_code == 0, result.stderr
        return
    assert_refused(result, message, out)


@pytest.mark.parametrize(
    ("replacements", "message"),
    [
        # in the ester's data range but so cold and fast that Gupta's thermal factor would turn the film
        # negative (Eq. 6 extrapolated so that the film is reached): the fit's limit is named, with the
        # case-file fields it comes from
        (
            [
                ('temperature = "90 degC"', 'temperature = "-20 degC"\nextrapolate = true'),
                ('speed = "23.8 m/s"', 'speed = "69.6 m/s"'),
                ('speed = "26.3 m/s"', 'speed = "76.9 m/s"'),
            ],
            "contact.thermal loading L = beta eta0 u^2 / k_f (from the temperature and the speeds) = 3232: "
            "allowed < 980.5, where Gupta's thermal reduction stays positive",
        ),
        # a load beyond the lubricant's pressure data: named as the mean Hertz pressure, in GPa, with
        # the fields it comes from
        (
            [('load_per_length = "300 N/mm"', 'load_per_length = "6000 N/mm"')],
            "contact.mean Hertz pressure p_m (from the load and the radii) = 3.33",
        ),
    ],
)
def test_a_derived_quantity_out_of_range_names_the_fields_it_comes_from(tmp_path, replacements, message):
    text = EXAMPLE.read_text()
    for old, new in replacements:
        assert old in text
        text = text.replace(old, new)
    case = tmp_path / "case.toml"
    case.write_text(text)
    out = tmp_path / "out"
    result = invoke("contact", "ehl", str(case), "--out", str(out))
    assert_refused(result, message, out)


def test_extrapolate_turns_the_range_error_into_a_warning(tmp_path):
    text = EXAMPLE.read_text().replace('temperature = "90 degC"', 'temperature = "220 degC"\nextrapolate = true')
    case = tmp_path / "case.toml"
    case.write_text(text)
    result = invoke("contact", "ehl", str(case), "--out", str(tmp_path / "out"))
    assert result.exit_code == 0, result.stderr
    assert "Extrapolated" in result.stdout
    warnings = json.loads((tmp_path / "out" / "results.json").read_text())["contact"]["warnings"]
    assert warnings and "[-20, 200] degC" in warnings[0]


def test_boundary_dominated_contact_is_a_design_finding(tmp_path):
    # 0.5 m/s leaves a film of a few nm: the film carries less than half the load (g < 0.5)
    text = (
        EXAMPLE.read_text()
        .replace('speed = "23.8 m/s"', 'speed = "0.45 m/s"')
        .replace('speed = "26.3 m/s"', 'speed = "0.5 m/s"')
    )
    case = tmp_path / "case.toml"
    case.write_text(text)
    result = invoke("contact", "ehl", str(case), "--json", "-")
    assert result.exit_code == 0, result.stderr
    document = json.loads(result.stdout)
    assert document["contact"]["lubrication"] == "boundary-dominated"
    assert any("boundary-dominated" in f["text"] and f["criterion"] for f in document["findings"])
    strict = invoke("contact", "ehl", str(case), "--strict", "--json", "-")
    assert strict.exit_code == 3


def test_thermal_correction_clipped_to_zero_is_not_acceptable(tmp_path):
    # issue 14 (g): the ester at 0 degC gives an eta0 p_H u beyond Eq. 6's fit range, where its c is
    # negative; extrapolate clips it to 0 and the friction comes out 0. A finding
    # that makes the run not acceptable (exit 3 without --strict), first in the output and in the JSON.
    text = EXAMPLE.read_text().replace('temperature = "90 degC"', 'temperature = "0 degC"\nextrapolate = true')
    case = tmp_path / "case.toml"
    case.write_text(text)
    result = invoke("contact", "ehl", str(case), "--json", str(tmp_path / "r.json"))
    assert result.exit_code == 3, result.stdout
    assert result.stdout.lstrip().startswith("NOT ACCEPTABLE") and "clipped to c = 0" in result.stdout
    document = json.loads((tmp_path / "r.json").read_text())
    assert document["contact"]["operating"]["friction"] == 0.0
    assert any("clipped to c = 0" in f["text"] and not f["criterion"] for f in document["findings"])
