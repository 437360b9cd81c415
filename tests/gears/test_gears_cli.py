"""``shaftline gears scuffing``: the examples, --calibrate, results.json fields, the report, bad input."""

from __future__ import annotations

import json
import shutil
from pathlib import Path

import pytest

from tests.conftest import assert_refused, invoke

ROOT = Path(__file__).resolve().parents[2]
SEED = ROOT / "examples" / "gears_scuffing.toml"
FZG = ROOT / "examples" / "gears_fzg_a.toml"


def test_seed_example_calibrates_c_and_writes_report_and_json(tmp_path):
    out = tmp_path / "out"
    result = invoke("gears", "scuffing", str(SEED), "--out", str(out), "--json", "-")
    assert result.exit_code == 0, result.stderr
    gears = json.loads(result.stdout)["gears"]
    sp = [row[0] for row in gears["sp"]]
    torques = gears["torques"]
    # calibrated on the record's failure step (400 N m, 10 000 rpm): SP = 1 there, rising with torque
    assert gears["calibration"]["failure_step"] == 4 and gears["calibration"]["torque"] == 400.0
    assert sp[torques.index(400.0)] == pytest.approx(1.0, rel=1e-9)
    assert all(b > a for a, b in zip(sp, sp[1:], strict=False))
    assert gears["pair"]["transverse_contact_ratio"] == pytest.approx(1.638, abs=1e-3)
    assert len(gears["path"]["friction"]) == 200 and gears["iso"]["safety"][0][0] > 1
    assert gears["warnings"]  # the light steps leave Eq. 6's fit range: extrapolated, said so
    for name in ("gears_path", "gears_sp"):
        assert (out / "figures" / f"{name}.png").stat().st_size > 10_000
    assert "Gear scuffing" in (out / "report.html").read_text()


def test_fzg_case_ranks_the_stages_alike_and_calibrate_option_replaces_the_record(tmp_path):
    result = invoke("gears", "scuffing", str(FZG), "--json", "-")
    assert result.exit_code == 0, result.stderr
    gears = json.loads(result.stdout)["gears"]
    sp = [row[0] for row in gears["sp"]]
    safety = [row[0] for row in gears["iso"]["safety"]]
    assert sorted(range(12), key=lambda k: sp[k]) == sorted(range(12), key=lambda k: -safety[k]) == list(range(12))
    assert sp[5] == pytest.approx(1.0)  # the record fails at stage 6
    # ISO at the oil's failure stage (6, as the case assumes): near 1 by both methods (theory 19.3)
    assert safety[5] == pytest.approx(1.0, abs=0.2) and gears["iso_integral"]["safety"][5][0] == pytest.approx(
        1.0, abs=0.2
    )
    # --calibrate: a record failing at stage 8 instead
    record = tmp_path / "stage8.csv"
    rows = [f"{t},2170,90,{int(k == 7)}" for k, t in enumerate([3.3, 13.7, 35.3, 60.8, 94.1, 135.3, 183.4, 239.3])]
    record.write_text("torque_Nm,speed_rpm,oil_temperature_degC,scuffed\n" + "\n".join(rows) + "\n")
    result = invoke("gears", "scuffing", str(FZG), "--calibrate", str(record), "--json", "-")
    assert result.exit_code == 0, result.stderr
    gears = json.loads(result.stdout)["gears"]
    assert gears["calibration"]["failure_step"] == 8 and gears["sp"][7][0] == pytest.approx(1.0)


@pytest.mark.parametrize(
    ("old", "new", "message"),
    [
        ("teeth = [28, 28]", "teeth = [12, 28]", "gears.pair.shift[0] = 0: allowed >= 0.2981: below it 12 teeth"),
        ('centre_distance = "140 mm"', 'centre_distance = "143 mm"', "gears.pair.centre_distance = 0.143 m"),
        ('centre_distance = "140 mm"', "addendum = 0.5", "gears.pair.addendum = 0.5: allowed teeth long enough"),
        (
            'centre_distance = "140 mm"',
            'tip_diameter = ["200 mm", "150 mm"]',
            "gears.pair.tip_diameter[0] = 0.2 m: allowed a pinion tip that meets the wheel flank",
        ),
        # with tips given, the tips set the teeth's length: the message names them, not the addendum
        (
            'centre_distance = "140 mm"',
            'tip_diameter = ["142 mm", "142 mm"]',
            "gears.pair.tip_diameter[0] = 0.142 m: allowed teeth long enough for a transverse contact ratio >= 1",
        ),
        # angles in degrees against the model's limits, with no offer of [case] unusual (which the
        # limits would refuse again) and no unit suggestion for a unit the user wrote; a bare number
        # (radians) gets the unit that fits
        (
            'centre_distance = "140 mm"',
            'helix_angle = "50 deg"',
            "gears.pair.helix_angle = 50 deg: allowed in [0, 45) deg",
        ),
        (
            'pressure_angle = "20 deg"',
            'pressure_angle = "40 deg"',
            "pressure_angle = 40 deg: allowed in (11.5, 34.4) deg",
        ),
        ('pressure_angle = "20 deg"', "pressure_angle = 20", "allowed in (11.5, 34.4) deg; did you mean 20 deg?"),
        # at the open end: the range refuses what the model would (34.4 deg), and passes 34.39
        ('pressure_angle = "20 deg"', 'pressure_angle = "34.4 deg"', "pressure_angle = 34.4 deg: allowed in (11.5"),
        ('lubricant = "MIL-PRF-23699"', 'lubricant = "SAE 90"', "gears.lubricant = 'SAE 90': allowed one of"),
        (
            'oil_temperature = "90 degC"\ncritical_temperature = "126 degC"',
            'oil_temperature = "210 degC"\ncritical_temperature = "260 degC"',
            "gears.oil_temperature = 210 degC: allowed in [-20, 200] degC",
        ),
        ('critical_temperature = "126 degC"', 'critical_temperature = "80 degC"', "gears.critical_temperature"),
        ('calibration = "gears_scuffing_test.csv"', "", "gears.thermal_coefficient = 'missing'"),
        ("[gears.iso]\nfzg_load_stage = 8", "[gears.iso]\nfzg_load_stage = 15", "gears.iso.fzg_load_stage = 15"),
        (
            "[gears.iso]\nfzg_load_stage = 8",
            '[gears.flash]\nmethod = "blok"\n\n[gears.iso]\nfzg_load_stage = 8',
            "gears.flash.method = 'blok'",
        ),
        # the light steps leave the fit range of seed 002 Eq. 6: without extrapolate an error naming it
        ("extrapolate = true", "extrapolate = false", "allowed in [0.1, 1.8] Pa s GPa m/s where S > S_m"),
        ('torques = ["50 N*m",', 'fzg_load_stages = [3]\ntorques = ["50 N*m",', "gears.test.torques = 'both'"),
    ],
)
def test_bad_input_one_line_exit_2_nothing_written(tmp_path, old, new, message):
    text = SEED.read_text()
    assert old in text
    shutil.copy(SEED.parent / "gears_scuffing_test.csv", tmp_path)
    case = tmp_path / "case.toml"
    text = text.replace(old, new, 1)
    if "210 degC" in new:  # beyond the ester's viscosity data, not extrapolated
        text = text.replace("extrapolate = true", "extrapolate = false")
    case.write_text(text)
    out = tmp_path / "out"
    result = invoke("gears", "scuffing", str(case), "--out", str(out))
    assert_refused(result, message, out)


def test_an_angle_beyond_the_models_limit_offers_neither_unusual_nor_another_unit(tmp_path):
    # the gear angles' plausible ranges are the model's limits: a value beyond them written with its
    # unit gets the limit in degrees, and neither "[case] unusual" (which could not let it through) nor
    # a unit suggestion ("50 mrad?"); listing such a field in [case] unusual is refused itself
    text = SEED.read_text().replace('centre_distance = "140 mm"', 'helix_angle = "50 deg"')
    case = tmp_path / "case.toml"
    case.write_text(text)
    shutil.copy(SEED.parent / "gears_scuffing_test.csv", tmp_path)
    result = invoke("gears", "scuffing", str(case), "--out", str(tmp_path / "out"))
    assert_refused(result, "gears.pair.helix_angle = 50 deg: allowed in [0, 45) deg", tmp_path / "out")
    assert "unusual" not in result.stderr and "did you mean" not in result.stderr
    case.write_text(text.replace("[case]\n", '[case]\nunusual = ["gears.pair.helix_angle"]\n', 1))
    result = invoke("gears", "scuffing", str(case), "--out", str(tmp_path / "out"))
    assert_refused(
        result, "case.unusual[0] = 'gears.pair.helix_angle': allowed a field whose range is not", tmp_path / "out"
    )


def test_an_oil_above_its_iso_scuffing_temperature_is_refused(tmp_path):
    # FVA 3 at 170 degC (extrapolated) is above the theta_S of about 158 degC that ISO/TS 6336-20 gives it
    # from its failure stage: S_B = (theta_S - theta_oil)/(theta_B - theta_oil) would be negative (-6 was
    # reported as an ordinary safety factor, exit 0). One line naming the field, exit 2, nothing written.
    text = FZG.read_text()
    for old, new in (
        ('oil_temperature = "90 degC"', 'oil_temperature = "170 degC"'),
        ('critical_temperature = "150 degC"', 'critical_temperature = "250 degC"'),
    ):
        assert old in text
        text = text.replace(old, new)
    if "extrapolate = true" not in text:
        text = text.replace("[gears]\n", "[gears]\nextrapolate = true\n", 1)
    case = tmp_path / "case.toml"
    case.write_text(text)
    shutil.copy(FZG.parent / "gears_fzg_a_test.csv", tmp_path)
    out = tmp_path / "out"
    result = invoke("gears", "scuffing", str(case), "--out", str(out))
    assert_refused(
        result, "gears.oil_temperature = 170 degC: allowed below the scuffing temperature theta_S = 158", out
    )


@pytest.mark.parametrize(
    ("record", "message"),
    [
        ("100,10000,90,0\n200,10000,90,0\n", "a test record with a scuffed step"),
        ("100,10000,90,0\n200,10000,90,2\n", "row 3, scuffed = 2: allowed 0 or 1"),
        ("100,-5,90,0\n", "row 2, speed_rpm = -5: allowed > 0"),
    ],
)
def test_bad_test_record(tmp_path, record, message):
    path = tmp_path / "test.csv"
    path.write_text("torque_Nm,speed_rpm,oil_temperature_degC,scuffed\n" + record)
    out = tmp_path / "out"
    result = invoke("gears", "scuffing", str(SEED), "--calibrate", str(path), "--out", str(out))
    assert result.exit_code == 2, result.stdout
    assert message in result.stderr and len(result.stderr.strip().splitlines()) == 1
    assert not out.exists()


def test_a_load_distribution_table_replaces_isos_load_sharing(tmp_path):
    text = SEED.read_text() + "\n[gears.load_sharing]\nfraction = [0.0, 0.5, 1.0]\nshare = [0.5, 1.0, 0.5]\n"
    shutil.copy(SEED.parent / "gears_scuffing_test.csv", tmp_path)
    case = tmp_path / "case.toml"
    case.write_text(text)
    result = invoke("gears", "scuffing", str(case), "--json", "-")
    assert result.exit_code == 0, result.stderr
    gears = json.loads(result.stdout)["gears"]
    share, rho = gears["path"]["share"], gears["path"]["position"]
    t = [(x - rho[0]) / (rho[-1] - rho[0]) for x in rho]
    assert gears["load_sharing"] == "table"
    assert share == pytest.approx([0.5 + (0.5 - abs(x - 0.5)) for x in t], rel=1e-12)
    bad = text.replace("share = [0.5, 1.0, 0.5]", "share = [0.5, 1.0]")
    case.write_text(bad)
    result = invoke("gears", "scuffing", str(case))
    assert result.exit_code == 2 and "gears.load_sharing.share = 2: allowed 3 values" in result.stderr


def test_thermal_correction_clipped_to_zero_is_a_loud_finding(tmp_path):
    # issue 14 (g): with extrapolate, seed 002's Eq. 6 beyond its fit range (eta0 p_H u above ~4, the
    # ester at 10 degC on the fast, heavy steps) gives c < 0, clipped to 0: friction 0 there and SP
    # understated. That must not pass as a warning: a finding (not acceptable, exit 3) at the top of the
    # output and in results.json, even without --strict.
    text = SEED.read_text().replace('oil_temperature = "90 degC"', 'oil_temperature = "10 degC"')
    text = text.replace('calibration = "gears_scuffing_test.csv"', 'thermal_coefficient = "40000 W/(m*K)"')
    case = tmp_path / "cold.toml"
    case.write_text(text)
    result = invoke("gears", "scuffing", str(case), "--json", str(tmp_path / "r.json"))
    assert result.exit_code == 3, result.stdout
    assert result.stdout.lstrip().startswith("NOT ACCEPTABLE") and "clipped to c = 0" in result.stdout
    document = json.loads((tmp_path / "r.json").read_text())
    clipped = [f for f in document["findings"] if "clipped to c = 0" in f["text"]]
    assert len(clipped) == 1 and clipped[0]["criterion"] is False
    # the same case at 90 degC (the example) clips nothing to 0: no such finding
    warm = text.replace('oil_temperature = "10 degC"', 'oil_temperature = "90 degC"')
    case.write_text(warm)
    result = invoke("gears", "scuffing", str(case), "--json", "-")
    assert "clipped to c = 0" not in result.stdout


def test_flash_method_chooses_isos_form_and_is_reported(tmp_path):
    # [gears.flash] method: the default is ISO's form for cylindrical gears (Eq. A.5); "iso_general"
    # gives the general Eq. (5) on the transverse load, whose flash temperature is 2.9 % lower on the
    # FZG type A gears (docs/theory.md 19.3): S_B at the assumed failure stage 6 0.951 against 0.979
    # (the numbers before issue 14's closing work). Only ISO's S_B moves: SP and S_intS are the same.
    runs = {}
    for method in (None, "iso_cylindrical", "iso_general"):
        text = FZG.read_text() + ("" if method is None else f'\n[gears.flash]\nmethod = "{method}"\n')
        case = tmp_path / f"{method}.toml"
        case.write_text(text)
        shutil.copy(FZG.parent / "gears_fzg_a_test.csv", tmp_path)
        result = invoke("gears", "scuffing", str(case), "--json", "-")
        assert result.exit_code == 0, result.stderr
        runs[method] = json.loads(result.stdout)["gears"]
    assert runs[None]["iso"]["flash_method"] == "iso_cylindrical"
    assert runs[None]["iso"]["safety"] == runs["iso_cylindrical"]["iso"]["safety"]
    cylindrical = [row[0] for row in runs[None]["iso"]["safety"]]
    general = [row[0] for row in runs["iso_general"]["iso"]["safety"]]
    assert cylindrical[5] == pytest.approx(0.951, abs=5e-4) and general[5] == pytest.approx(0.979, abs=5e-4)
    assert all(1.0 < g / c < 1.03 for g, c in zip(general, cylindrical, strict=True))
    assert runs[None]["sp"] == runs["iso_general"]["sp"]
    assert runs[None]["iso_integral"]["safety"] == runs["iso_general"]["iso_integral"]["safety"]


def test_flash_method_without_iso_rating_is_refused(tmp_path):
    text = FZG.read_text()
    text = text[: text.index("[gears.iso]")] + '[gears.flash]\nmethod = "iso_general"\n'
    case = tmp_path / "case.toml"
    case.write_text(text)
    shutil.copy(FZG.parent / "gears_fzg_a_test.csv", tmp_path)
    result = invoke("gears", "scuffing", str(case), "--out", str(tmp_path / "out"))
    assert result.exit_code == 2, result.stdout
    assert "gears.flash.method = 'iso_general'" in result.stderr and "[gears.iso]" in result.stderr
    assert len(result.stderr.strip().splitlines()) == 1


@pytest.mark.parametrize("example", [SEED, FZG])
def test_the_terminal_tables_fit_80_columns_a_line_a_row(example):
    # The summary's tables (seed 002's SP, then ISO's ratings at the same steps) print each row and
    # the header on one line of an 80-column terminal: the single table of nine or ten columns
    # wrapped every row (the FZG stages over three lines, "uncertain" folded to "uncert|ain").
    from rich.console import Console

    from shaftline.cases import load_case
    from shaftline.pipeline import run_case
    from shaftline.report.blocks import Table
    from shaftline.report.terminal import print_blocks

    result = run_case(load_case(example))
    capability, value = next(result.capabilities())
    tables = [b for b in capability.summary(value) if isinstance(b, Table)]
    if len(value.study.speeds) == 1:
        # one speed (FZG): seed 002's table and ISO's
        assert len(tables) == 2 and tables[1].headers[-2:] == ["S_B", "S_intS"]
    else:
        # several (the seed's five): the SP/S_B matrix, all five speeds in one table
        assert len(tables) == 1 and len(tables[0].headers) == 1 + len(value.study.speeds)
    for table in tables:
        console = Console(record=True, width=80)
        print_blocks(console, [table])
        lines = console.export_text().splitlines()
        assert max(len(line) for line in lines) <= 80
        assert sum(line.startswith("┃") for line in lines) == 1, lines  # the header
        assert sum(line.startswith("│") for line in lines) == len(table.rows), lines


def test_the_report_shows_every_speed_of_the_study():
    # The seed example rates five pinion speeds (10 000, 2 000, 6 000, 14 000, 18 000 rpm): after
    # the SP/S_B matrix of all speeds, the report has seed 002's SP table and ISO's table for each
    # in the study's order, each titled with its speed and holding that speed's SP and S_B
    # (formatted as the table does). The summary showed the first speed's only (it now has the
    # matrix, tested below).
    from shaftline.cases import load_case
    from shaftline.pipeline import run_case
    from shaftline.report.blocks import Table

    result = run_case(load_case(SEED))
    capability, value = next(result.capabilities())
    matrix, *tables = [b for b in capability.report(value) if isinstance(b, Table)]
    assert matrix.title.startswith("SP/S_B by torque step and pinion speed")
    rpm = [10000, 2000, 6000, 14000, 18000]
    assert len(tables) == 2 * len(rpm)
    for j, (sp_table, iso_table) in enumerate(zip(tables[0::2], tables[1::2], strict=True)):
        assert f", {rpm[j]} rpm: seed 002's SP" in sp_table.title
        assert iso_table.title.endswith(f", {rpm[j]} rpm")
        column = sp_table.headers.index("SP")
        assert [row[column] for row in sp_table.rows] == [f"{v:.2f}" for v in value.sp[:, j]]
        column = iso_table.headers.index("S_B")
        assert [row[column] for row in iso_table.rows] == [f"{v:.2f}" for v in value.iso.safety[:, j]]
    # the speeds differ in SP: the tables are not one table repeated
    assert len({tuple(row[-2] for row in t.rows) for t in tables[0::2]}) == len(rpm)


@pytest.mark.parametrize("speeds", [5, 12])
def test_the_summary_rates_many_speeds_in_one_compact_matrix(tmp_path, speeds):
    # Several pinion speeds: the summary gives SP and ISO's S_B as one load-step x speed matrix,
    # each cell "SP/S_B" of that step and speed (two decimals below 10, one below 100), marked
    # where SP > 1 or S_B < 1, instead of two tables per speed (the seed's five speeds took 173
    # lines). Each table fits 80 columns a line a row; twelve speeds do not fit one table, so they
    # are split over several, each speed once and in rising order (the seed's case lists its test
    # speed, 10 000 rpm, first).
    from rich.console import Console

    from shaftline.cases import load_case
    from shaftline.pipeline import run_case
    from shaftline.report.blocks import Paragraph, Table
    from shaftline.report.terminal import print_blocks

    rpm = [10000, 2000, 6000, 14000, 18000] if speeds == 5 else [1000 * (k + 1) for k in range(12)]
    text = SEED.read_text().replace(
        'speeds = ["10000 rpm", "2000 rpm", "6000 rpm", "14000 rpm", "18000 rpm"]',
        "speeds = [" + ", ".join(f'"{r} rpm"' for r in rpm) + "]",
    )
    shutil.copy(SEED.parent / "gears_scuffing_test.csv", tmp_path)
    case = tmp_path / "speeds.toml"
    case.write_text(text)
    result = run_case(load_case(case))
    capability, value = next(result.capabilities())
    summary = capability.summary(value)
    tables = [b for b in summary if isinstance(b, Table)]
    assert (len(tables) == 1) == (speeds == 5) and len(tables) <= 3
    seen = []
    lines_total = 0
    for table in tables:
        assert table.headers[0] == "T [N m]"
        assert [row[0] for row in table.rows] == [f"{t:g}" for t in value.study.torques]
        for header in table.headers[1:]:
            seen.append(header)
            j = rpm.index(int(header.removesuffix(" rpm")))
            column = table.headers.index(header)
            expected = []
            for k in range(len(value.study.torques)):
                sp, sb = float(value.sp[k, j]), float(value.iso.safety[k, j])
                short = [f"{v:.2f}" if v < 10 else f"{v:.1f}" for v in (sp, sb)]
                expected.append("/".join(short))
                assert table.marks[k][column] == ("fail" if sp > 1.0 or sb < 1.0 else "")
            assert [row[column] for row in table.rows] == expected
        console = Console(record=True, width=80)
        print_blocks(console, [table])
        lines = console.export_text().splitlines()
        lines_total += len(lines)
        assert max(len(line) for line in lines) <= 80
        assert sum(line.startswith("┃") for line in lines) == 1, lines
        assert sum(line.startswith("│") for line in lines) == len(table.rows), lines
    assert seen == [f"{r} rpm" for r in sorted(rpm)]
    assert any("fail" in row for table in tables for row in table.marks)  # the heavy fast steps scuff
    assert lines_total <= 20 * len(tables)
    assert any(isinstance(b, Paragraph) and b.text.startswith("SP > 1 scuffing") for b in summary)
