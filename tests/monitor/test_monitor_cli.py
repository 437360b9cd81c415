"""``shaftline monitor simulate`` on examples/monitor_rig.toml, and the [monitor] table's checks."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from shaftline.monitor.case import SimulateSection
from shaftline.monitor.forward import RigCase
from tests.conftest import invoke

ROOT = Path(__file__).resolve().parents[2]
EXAMPLE = ROOT / "examples" / "monitor_rig.toml"


@pytest.mark.slow
def test_simulate_example_writes_recordings_figures_and_json(simulated_example):
    """The example end to end (about 10 s): identified regime lengths equal the truth to the bound of
    tests/monitor/test_forward.py (about a mm), film errors below 0.01 µm, recordings and figures written; the
    bearing solver placed every journal (liner and asperities), the loaded end in boundary lubrication."""
    result, out = simulated_example  # the example's run, shared with test_identify_cli's
    assert result.exit_code == 0, result.stderr
    monitor = json.loads(result.stdout)["monitor"]
    assert [round(p["speed"] * 30 / 3.141592653589793) for p in monitor["points"]] == [35, 65, 95, 135, 175, 215]
    assert all(p["truth"]["solver"]["status"] == "ok" for p in monitor["points"])
    assert all(p["truth"]["solver"]["max_liner_deformation"] > 0 for p in monitor["points"])
    for point in monitor["points"]:
        truth = point["truth"]
        for name, value in point["regime_lengths"].items():
            assert value == pytest.approx(truth["regime_lengths"][name], abs=2e-3)
        assert truth["film_error"] < 0.01e-6 and truth["min_film_error"] < 0.01e-6
        assert [round(s["correction"] * 1e6, 2) for s in point["sections"]] == [0.0, 0.0, 0.0]
    header = (out / "data" / "recording_135rpm.csv").read_text().splitlines()[0]
    assert header == "time_s,D1_1,D1_2,D1_3,D2_1,D2_2,D2_3,D3_1,D3_2,D3_3,keyphasor"
    for name in ("monitor_min_film", "monitor_film_map", "monitor_orbit_0", "monitor_centre_line"):
        assert (out / "figures" / f"{name}.png").stat().st_size > 10_000


def test_clearance_in_the_wrong_unit_is_one_line(tmp_path):
    case = tmp_path / "case.toml"
    case.write_text(EXAMPLE.read_text().replace('radial_clearance = "0.55 mm"', 'radial_clearance = "0.55 m"'))
    result = invoke("monitor", "simulate", str(case))
    assert result.exit_code == 2
    message = result.stderr.strip()
    assert "\n" not in message and "monitor.radial_clearance = 0.55 m" in message


def test_sections_out_of_order_name_the_section(tmp_path):
    case = tmp_path / "case.toml"
    case.write_text(EXAMPLE.read_text().replace('position = "856 mm"', 'position = "400 mm"'))
    result = invoke("monitor", "simulate", str(case))
    assert result.exit_code == 2
    assert "monitor.sections[2].position = 0.4 m: allowed > 0.4295" in result.stderr


def test_simulate_defaults_are_the_forward_models():
    for name in (
        "load",
        "misalignment",
        "bend_scale",
        "overhung_mass",
        "whirl",
        "whirl_speed",
        "noise",
        "sleeve_wear",
        "sample_rate",
        "revolutions",
        "seed",
    ):
        assert SimulateSection.model_fields[name].default == pytest.approx(getattr(RigCase(), name)), name
    for name in ("duration", "surface", "liner"):  # none: revolutions, smooth, rigid
        assert SimulateSection.model_fields[name].default is None and getattr(RigCase(), name) is None, name
    assert tuple(SimulateSection.model_fields["runout"].default) == pytest.approx(RigCase().runout)


def test_shaft_model_case_gives_the_rigs_bending_shape():
    """examples/monitor_rig_shaft.toml (the rig as an [alignment] case) against forward.rig_shaft_line: the same
    shape to round-off, so the example's identification uses the shape its forward model bent the journal with."""
    from shaftline.cases import load_case
    from shaftline.monitor.forward import rig_bending_shape

    study = load_case(EXAMPLE).studies["monitor"]
    z, shape = rig_bending_shape()
    assert study.shape[0] == pytest.approx(z, abs=1e-15)
    assert study.shape[1] == pytest.approx(shape, abs=1e-15)
    assert study.rig.shape is study.shape  # the forward model bends the journal with the same shape


@pytest.mark.parametrize(
    ("old", "new", "message"),
    [
        ('shaft_bearing = "stern"', 'shaft_bearing = "aft"', "monitor.shaft_bearing = 'aft': allowed one of stern"),
        ('shaft_bearing = "stern"\n', "", "monitor.shaft_bearing = 'missing'"),
        (
            'shaft_model = "monitor_rig_shaft.toml"',
            'shaft_model = "monitor_rig.toml"',
            "monitor.shaft_model = 'monitor_rig.toml': allowed a case file with an [alignment] table",
        ),
    ],
)
def test_shaft_model_errors_are_one_line(tmp_path, old, new, message):
    for name in ("monitor_rig.toml", "monitor_rig_shaft.toml"):
        text = (ROOT / "examples" / name).read_text()
        (tmp_path / name).write_text(text.replace(old, new) if name == "monitor_rig.toml" else text)
    result = invoke("monitor", "simulate", str(tmp_path / "monitor_rig.toml"))
    assert result.exit_code == 2
    assert message in result.stderr and len(result.stderr.strip().splitlines()) == 1


def _example_study(tmp_path: Path, text: str):
    """The study of the example case with ``text`` as its file (shaft model beside it)."""
    from shaftline.cases import load_case
    from shaftline.monitor.capability import FilmMonitor

    (tmp_path / "monitor_rig_shaft.toml").write_text((ROOT / "examples" / "monitor_rig_shaft.toml").read_text())
    path = tmp_path / "monitor_rig.toml"
    path.write_text(text)
    return FilmMonitor(), load_case(path).studies["monitor"]


def test_the_simulated_surfaces_are_the_monitor_tables(tmp_path):
    """Beside the steel_polymer preset the solver's roughness is the [monitor] table's (Rq = rq_factor x Ra), so
    that the solver's surfaces are those the regimes are judged on; given in the table, the table's own."""
    text = EXAMPLE.read_text().replace('roughness_bearing = "1.6 um"', 'roughness_bearing = "2.0 um"')
    text = text.replace("rq_factor = 1.25", "rq_factor = 1.2")
    _, study = _example_study(tmp_path, text)
    assert study.rig.surface.bore_rq == pytest.approx(1.2 * 2.0e-6, rel=1e-12)
    assert study.rig.surface.journal_rq == pytest.approx(1.2 * 0.8e-6, rel=1e-12)
    assert study.rig.liner.thickness == pytest.approx(0.020) and study.rig.liner.modulus == pytest.approx(2320e6)
    own = text.replace('preset = "steel_polymer"', 'preset = "steel_polymer"\nbore_roughness = "1.0 um"')
    _, study = _example_study(tmp_path, own)
    assert study.rig.surface.bore_rq == pytest.approx(1.25 * 1.0e-6, rel=1e-12)  # the table's Ra, RA_TO_RQ


@pytest.mark.parametrize(
    ("old", "new", "message"),
    [
        ('preset = "polymer_composite"', 'preset = "polymer_composite"\nthickness = "60 mm"',
         "monitor.simulate.liner.thickness = 0.06 m"),
        ('preset = "steel_polymer"', 'preset = "steel_polymer"\nbore_roughness = "400 um"',
         "monitor.simulate.surface.bore_roughness = 0.0004 m"),
        ('duration = "16 s"', 'duration = "6 s"',  # 1.5 turns at the slow roll: stopped on 'monitor.marks = 1'
         "monitor.simulate.duration = 6 s: allowed >= 8 s: two revolutions at the slowest speed (15 rpm)"),
    ],
)  # fmt: skip
def test_bad_simulated_surfaces_and_liners_are_one_line(tmp_path, old, new, message):
    """A liner thicker than a quarter of the bore radius, a roughness beyond half the clearance, recordings shorter
    than two turns at the slowest speed: one line naming the field, exit 2, before any solver runs."""
    for name in ("monitor_rig.toml", "monitor_rig_shaft.toml"):
        text = (ROOT / "examples" / name).read_text()
        (tmp_path / name).write_text(text.replace(old, new) if name == "monitor_rig.toml" else text)
    result = invoke("monitor", "simulate", str(tmp_path / "monitor_rig.toml"), "--out", str(tmp_path / "out"))
    assert result.exit_code == 2, result.stderr
    assert message in result.stderr and len(result.stderr.strip().splitlines()) == 1
    assert not (tmp_path / "out").exists()


def test_a_speed_the_solver_did_not_converge_at_is_not_acceptable(tmp_path):
    """A simulated journal the solver left short of the load is a finding that is not a rule check (exit 3
    without --strict), naming the speed; a converged one gives none."""
    from dataclasses import replace

    text = EXAMPLE.read_text().replace(
        'speeds = ["35 rpm", "65 rpm", "95 rpm", "135 rpm", "175 rpm", "215 rpm"]', 'speeds = ["175 rpm"]'
    )
    capability, study = _example_study(tmp_path, text)
    result = capability.solve(study, task="simulate")
    assert capability.findings(result) == []
    (point,) = result.points
    short = replace(point.recording, solver_status="not converged")
    stalled = replace(result, points=(replace(point, recording=short),))
    (finding,) = capability.findings(stalled)
    assert not finding.criterion and finding.text.startswith("At 175 rpm the bearing solver did not converge")
