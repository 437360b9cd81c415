"""Slow-roll runout compensation in ``monitor identify`` (issue 13: the forward model adds runout,
the identification must remove it).

The forward model of seed 001's rig with a runout of 2 um 1X + 1 um 2X on every probe (random
phases, the machine's: the same at every speed; Bently Nevada practice counts a few um of
mechanical and electrical runout as usual) is recorded at 120 rpm and at a slow roll of 15 rpm.
The runout measured on the slow-roll file is subtracted from the recording.

Bounds (as tests/monitor/test_forward.py, docs/validation.md): a sample's film within 5 standard
deviations of the probe noise and quantisation carried through the least squares, plus the
residual runout, or 2 % of the film if larger. The residual runout: a keyphasor mark is found up
to one sample late in each recording, so the two phases differ by up to one sample at 120 rpm
(0.0061 rad) plus one at 15 rpm (0.0008 rad), times the runout's largest slope (2 um x 1 + 1 um x 2
per rad = 4 um/rad): 0.028 um; the profile's own error, 5 standard deviations of its bin means
(noise and quantisation of the coarse probes, sqrt(0.05^2 + 0.15^2/12) um over sqrt(448) samples a
bin: 0.0031 um) plus the bias of a quantiser dithered by noise of a third of its step,
q exp(-2 pi^2 sigma^2/q^2)/pi = 0.0054 um (Widrow and Kollar 2008, Ch. 5): 0.049 um a gap. A gap
error reaches the film through the least squares by at most sqrt(p) times its root-sum-square gain
(Cauchy-Schwarz), the factor used here. Linear interpolation between 128 bins adds 0.0003 um.
"""

from __future__ import annotations

import json
import math
from pathlib import Path

import numpy as np
import pandas as pd
import pytest

from shaftline.monitor.forward import RigCase, simulate
from shaftline.monitor.identification import film_noise_std
from shaftline.monitor.orbits import revolution_marks, whole_revolutions
from shaftline.monitor.processing import slow_roll_runout
from shaftline.monitor.study import FILM_ANGLES, identify_window
from shaftline.monitor.trends import TrendStore
from tests.conftest import invoke
from tests.monitor.test_identify_cli import case_file, rows

RPM = 2 * math.pi / 60
RUNOUT = (2e-6, 1e-6)
SPEED, SLOW = 120 * RPM, 15 * RPM
SLOPE = RUNOUT[0] + 2 * RUNOUT[1]  # largest slope of the runout against shaft phase, m/rad
NOISE, STEP = 0.05e-6, 0.15e-6  # the forward model's noise and the coarse probes' resolution
PROFILE_STD = math.sqrt(NOISE**2 + STEP**2 / 12) / math.sqrt(7 * 8192 / 128)  # 7 turns of 8192 samples
QUANTISER_BIAS = STEP * math.exp(-2 * math.pi**2 * NOISE**2 / STEP**2) / math.pi
PROFILE_ERROR = 5 * PROFILE_STD + QUANTISER_BIAS + 0.0003e-6
#: Residual runout on a gap at 120 rpm, m.
RESIDUAL = SLOPE * (SPEED + SLOW) / 2048.0 + PROFILE_ERROR


def _csv(path: Path, case: RigCase, recording) -> Path:
    frame = pd.DataFrame(recording.signals, columns=list(case.layout.channels))
    frame["keyphasor"] = recording.keyphasor
    frame.insert(0, "time", np.arange(len(frame)) / recording.sample_rate)
    frame.to_csv(path, index=False, float_format="%.10g")
    return path


@pytest.fixture(scope="module")
def runout_rig(tmp_path_factory):
    folder = tmp_path_factory.mktemp("slow_roll")
    case = RigCase(runout=RUNOUT, revolutions=8.0, axial_nodes=31, circumferential_nodes=72)
    recording, slow = simulate(case, SPEED), simulate(case, SLOW)
    return case, recording, _csv(folder / "run.csv", case, recording), _csv(folder / "slow.csv", case, slow)


def _gap_std(case: RigCase, section) -> np.ndarray:
    return np.sqrt(case.noise**2 + np.array([p.resolution for p in section.probes]) ** 2 / 12.0)


def _residual(section, layout) -> np.ndarray:
    """Residual runout on the film at FILM_ANGLES: RESIDUAL on every gap times sqrt(p) times the
    root-sum-square gain of the least squares, m."""
    gain = film_noise_std(section, FILM_ANGLES, layout.rotation, np.ones(len(section.probes)))
    return math.sqrt(len(section.probes)) * gain * RESIDUAL


def test_the_slow_roll_file_gives_the_runout(runout_rig):
    """The profile read from the file, in blocks of any size, is the forward model's runout less its
    mean at every probe within the residual (at the slow roll's own phase: the slow roll's mark error
    only, 0.0008 rad x 4 um/rad, plus the bins and noise); the speed is the slow roll's."""
    import shaftline.monitor.processing as processing

    case, _, _, slow_file = runout_rig
    layout = case.layout
    found = slow_roll_runout(layout, slow_file, "keyphasor")
    assert found.speed == pytest.approx(SLOW, rel=1e-3) and found.revolutions == 7
    phases = np.random.default_rng([case.seed, 0]).uniform(0, 2 * math.pi, (len(layout.channels), 2))
    centres = (np.arange(found.profile.shape[0]) + 0.5) * 2 * math.pi / found.profile.shape[0]
    # the forward model's shaft phase is 0.5 rad at the first sample; the keyphasor's phase is 0 at
    # its first rising edge, where the model's phase is 2 pi (its mark is a pulse over [0, 0.2) rad)
    true = RUNOUT[0] * np.cos(centres[:, None] - phases[None, :, 0]) + RUNOUT[1] * np.cos(
        2 * centres[:, None] - phases[None, :, 1]
    )
    slow_residual = SLOPE * SLOW / 2048.0 + PROFILE_ERROR
    np.testing.assert_allclose(found.profile, true - true.mean(axis=0), atol=slow_residual)
    # blocks far shorter than a revolution (4 s = 8192 samples): the carried samples keep every turn
    small = processing.SLOW_ROLL_BLOCK
    processing.SLOW_ROLL_BLOCK = 1000
    try:
        again = slow_roll_runout(layout, slow_file, "keyphasor")
    finally:
        processing.SLOW_ROLL_BLOCK = small
    assert again.revolutions == found.revolutions
    # the same samples; one on a bin edge (64 a bin exactly here) may fall either side by round-off
    np.testing.assert_allclose(again.profile, true - true.mean(axis=0), atol=slow_residual)


def test_identified_film_is_within_the_bound_with_compensation_and_not_without(runout_rig):
    """Every sample's film every 15 deg round each probe section against the forward model's."""
    case, recording, _, slow_file = runout_rig
    layout = case.layout
    profile = slow_roll_runout(layout, slow_file, "keyphasor").profile
    kept = whole_revolutions(revolution_marks(recording.keyphasor))
    outside = {}
    for label, runout in (("compensated", profile), ("raw", None)):
        result = identify_window(layout, recording.signals, recording.keyphasor, case.sample_rate, runout=runout)
        share = []
        for section, film in zip(layout.sections, result.films, strict=True):
            true = recording.film(layout, FILM_ANGLES, np.array([section.position]))[kept, 0, :]
            noise = film_noise_std(section, FILM_ANGLES, layout.rotation, _gap_std(case, section))
            bound = 5 * noise + _residual(section, layout)
            allowed = np.maximum(0.02 * np.abs(true), bound[None, :])
            share.append(np.mean(np.abs(film - true) > allowed))
        outside[label] = max(share)
    assert outside["compensated"] == 0.0
    assert outside["raw"] > 0.1  # the runout (up to 3 um) is far beyond the bound on the thin side


def test_monitor_identify_with_a_slow_roll(runout_rig, tmp_path):
    """The verb with --slow-roll stores each section's 1X vectors and lowest film of the window as the
    forward model made them (whirl 1 um at 215 rpm, so 0.31 um at 120 rpm, both directions); without
    it the runout passes into both. The JSON names the slow roll and its runout."""
    case, recording, run_file, slow_file = runout_rig
    layout = case.layout
    whirl = case.whirl * (SPEED / case.whirl_speed) ** 2
    stored = {}
    for label, extra in (("compensated", ["--slow-roll", str(slow_file)]), ("raw", [])):
        database = tmp_path / f"{label}.sqlite"
        result = invoke("monitor", "identify", str(case_file(tmp_path)), str(run_file), *extra, "--db", str(database),
                        "--json", "-")  # fmt: skip
        assert result.exit_code == 0, result.stderr
        assert rows(database) == 2
        stored[label] = json.loads(result.stdout)["monitor"]["identify"]
    slow = stored["compensated"]["slow_roll"]
    assert slow["name"] == "slow.csv" and slow["revolutions"] == 7 and stored["raw"]["slow_roll"] is None
    # A1 cos + A2 cos 2x: at most 2 (A1 + A2) = 6 um peak to peak, at least pi A1 / 2 = 3.1 um (|a1| <= 2 ptp / pi)
    assert all(math.pi * RUNOUT[0] / 2 <= v <= 2 * sum(RUNOUT) for v in slow["runout_peak_to_peak"].values())
    size = 4096  # 2 s windows at 2048 Hz
    for section in layout.sections:
        ey, ez = recording.centres(np.array([section.position]))
        true_min = recording.clearance - np.hypot(ey[:, 0], ez[:, 0])
        true_low = []
        for k in range(2):
            block = slice(k * size, (k + 1) * size)
            marks = revolution_marks(recording.keyphasor[block])
            true_low.append(true_min[block][marks[0] : marks[-1]].min())
        sigma = film_noise_std(section, FILM_ANGLES, layout.rotation, _gap_std(case, section)).max()
        residual = _residual(section, layout).max()
        errors = {}
        for label in stored:
            with TrendStore(tmp_path / f"{label}.sqlite") as store:
                low = store.series("min_film_thickness_low", section.name)["value"].to_numpy()
                one_x = np.concatenate(
                    [store.series(name, section.name)["value"].to_numpy() for name in ("vertical_1x", "horizontal_1x")]
                )
            errors[label] = np.abs(low - true_low).max()
            errors[label + " 1x"] = np.abs(one_x - whirl).max()
        assert errors["compensated"] <= 5 * sigma + residual, (section.name, errors)
        assert errors["raw"] > 5 * sigma + residual, (section.name, errors)
        # a vector's amplitude moves by at most the residual's (the noise averages out over 9 turns)
        assert errors["compensated 1x"] <= residual, (section.name, errors)
        assert errors["raw 1x"] > 5 * residual, (section.name, errors)


def test_a_slow_roll_at_running_speed_is_warned(runout_rig, tmp_path):
    """A "slow roll" as fast as the recordings (here the running recording itself, 120 rpm) measures
    the film's and the unbalance's motion as runout: the terminal and report say so (it was taken
    silently); the seed's 15 rpm slow roll, 0.125 of 120 rpm, is not warned (the test above)."""
    case, _, run_file, slow_file = runout_rig
    for file, warned in ((run_file, True), (slow_file, False)):
        database = tmp_path / f"{file.stem}.sqlite"
        result = invoke("monitor", "identify", str(case_file(tmp_path)), str(run_file), "--slow-roll", str(file),
                        "--db", str(database))  # fmt: skip
        assert result.exit_code == 0, result.stderr
        text = " ".join(result.stdout.split())
        assert ("but the slow roll ran at 120 rpm, more than 50% of the lowest speed identified" in text) == warned


# --- Runout from the slow windows of the recording itself, and from a table in the case ---------------
#
# A run-up as a monitoring system records it: 32 s at the 15 rpm slow roll, then 16 s at 120 rpm, in one
# file (the forward model's two recordings back to back; 8 s windows, so the change of speed falls on a
# window boundary and each window's keyphasor marks come from one of them). Each 8 s slow window holds
# two keyphasor marks (the model's first mark is 0.92 of a turn in), one whole revolution: the profile
# averages 4 revolutions, 256 samples a bin. Its bound is the one above with that count.
SLOW_TURNS = 4
SLOW_PROFILE_ERROR = (
    5 * math.sqrt(NOISE**2 + STEP**2 / 12) / math.sqrt(SLOW_TURNS * 8192 / 128) + QUANTISER_BIAS + 0.0003e-6
)
SLOW_WINDOWS_RESIDUAL = SLOPE * (SPEED + SLOW) / 2048.0 + SLOW_PROFILE_ERROR


def _true_profile(case: RigCase, bins: int = 128) -> np.ndarray:
    """The forward model's runout of every probe at the keyphasor's shaft phase (bin centres), mean removed."""
    phases = np.random.default_rng([case.seed, 0]).uniform(0, 2 * math.pi, (len(case.layout.channels), 2))
    centres = (np.arange(bins) + 0.5) * 2 * math.pi / bins
    true = RUNOUT[0] * np.cos(centres[:, None] - phases[None, :, 0]) + RUNOUT[1] * np.cos(
        2 * centres[:, None] - phases[None, :, 1]
    )
    return true - true.mean(axis=0)


@pytest.fixture(scope="module")
def run_up(tmp_path_factory):
    from dataclasses import replace

    folder = tmp_path_factory.mktemp("run_up")
    case = RigCase(runout=RUNOUT, revolutions=8.0, axial_nodes=31, circumferential_nodes=72)
    slow = simulate(case, SLOW)
    fast = simulate(replace(case, revolutions=32.0), SPEED)
    assert slow.signals.shape[0] == 4 * 16384 and fast.signals.shape[0] == 2 * 16384
    both = replace(
        fast,
        signals=np.concatenate([slow.signals, fast.signals]),
        keyphasor=np.concatenate([slow.keyphasor, fast.keyphasor]),
    )
    return case, fast, _csv(folder / "run_up.csv", case, both)


def test_the_slow_windows_of_a_recording_give_the_runout(run_up):
    """The windows below slow_roll_speed (30 rpm): the four at 15 rpm, four whole revolutions; their profile
    is the forward model's runout within the bound (the slow roll's one-sample mark error and the profile's
    noise over 4 turns). Below 10 rpm no window is slow enough: None."""
    from shaftline.monitor.processing import plan_recording, slow_windows_runout

    case, _, path = run_up
    plan = plan_recording(case.layout, path, "keyphasor", window_seconds=8.0)
    found = slow_windows_runout(case.layout, plan, 30 * RPM)
    assert found is not None and (found.windows, found.revolutions, found.source) == (4, SLOW_TURNS, "slow windows")
    assert found.speed == pytest.approx(SLOW, rel=1e-3)
    bound = SLOPE * SLOW / 2048.0 + SLOW_PROFILE_ERROR
    np.testing.assert_allclose(found.profile, _true_profile(case), atol=bound)
    assert slow_windows_runout(case.layout, plan, 10 * RPM) is None


def _identify(tmp_path: Path, name: str, path: Path, extra: str, window: str = "2 s", *more: str):
    rig = case_file(tmp_path).read_text().replace('window = "2 s"', f'window = "{window}"') + extra
    (tmp_path / f"{name}.toml").write_text(rig)
    database = tmp_path / f"{name}.sqlite"
    result = invoke("monitor", "identify", str(tmp_path / f"{name}.toml"), str(path), "--db", str(database),
                    "--json", str(tmp_path / f"{name}.json"), *more)  # fmt: skip
    return result, database


def _document(tmp_path: Path, name: str) -> dict:
    return json.loads((tmp_path / f"{name}.json").read_text())["monitor"]["identify"]


def _fast_errors(case: RigCase, fast, database: Path, first: int, size: int, windows: int) -> dict:
    """Largest error of each section's stored lowest film and 1X amplitudes over the fast windows against the
    forward model's, in units of the bound (5 sigma of the film noise + the residual runout)."""
    whirl = case.whirl * (SPEED / case.whirl_speed) ** 2
    worst = {"low": 0.0, "1x": 0.0}
    for section in case.layout.sections:
        ey, ez = fast.centres(np.array([section.position]))
        true_min = fast.clearance - np.hypot(ey[:, 0], ez[:, 0])
        true_low = []
        for k in range(windows):
            block = slice(k * size, (k + 1) * size)
            marks = revolution_marks(fast.keyphasor[block])
            true_low.append(true_min[block][marks[0] : marks[-1]].min())
        sigma = film_noise_std(section, FILM_ANGLES, case.layout.rotation, _gap_std(case, section)).max()
        gain = film_noise_std(section, FILM_ANGLES, case.layout.rotation, np.ones(len(section.probes))).max()
        residual = math.sqrt(len(section.probes)) * gain * SLOW_WINDOWS_RESIDUAL
        with TrendStore(database) as store:
            low = store.series("min_film_thickness_low", section.name)["value"].to_numpy()[first:]
            one_x = np.concatenate(
                [store.series(q, section.name)["value"].to_numpy()[first:] for q in ("vertical_1x", "horizontal_1x")]
            )
        worst["low"] = max(worst["low"], np.abs(low - true_low).max() / (5 * sigma + residual))
        worst["1x"] = max(worst["1x"], np.abs(one_x - whirl).max() / residual)
    return worst


@pytest.mark.slow  # two runs of the verb over 48 s of recording (about 10 s on the shared machine)
def test_monitor_identify_with_a_slow_roll_speed(run_up, tmp_path):
    """`slow_roll_speed = "30 rpm"`: the runout from the recording's own slow windows is subtracted, and the
    fast windows' lowest film and 1X amplitudes are the forward model's within the bound (as with a slow-roll
    file, the residual for 4 turns); without it they are far off. The JSON names the source per recording."""
    case, fast, path = run_up
    compensated, database = _identify(tmp_path, "speed", path, 'slow_roll_speed = "30 rpm"\n', "8 s")
    assert compensated.exit_code == 0, compensated.stderr
    document = _document(tmp_path, "speed")
    runout = document["recordings"][0]["runout"]
    assert (runout["source"], runout["windows"], runout["revolutions"]) == ("slow windows", 4, SLOW_TURNS)
    assert document["slow_roll"] is None and document["slow_roll_speed"] == pytest.approx(30 * RPM)
    text = " ".join(compensated.stdout.split())
    assert "run_up.csv: runout from its 4 windows below 30 rpm (4 revolutions at 15 rpm)" in text, text
    assert "warning" not in text, text
    raw, raw_database = _identify(tmp_path, "raw", path, "", "8 s")
    assert raw.exit_code == 0, raw.stderr
    errors = _fast_errors(case, fast, database, 4, 16384, 2)
    assert errors["low"] <= 1.0 and errors["1x"] <= 1.0, errors
    raw_errors = _fast_errors(case, fast, raw_database, 4, 16384, 2)
    assert raw_errors["low"] > 1.0 and raw_errors["1x"] > 5.0, raw_errors


def _table(case: RigCase, step_deg: float = 5.0) -> str:
    """The forward model's runout of every probe as [[monitor.identify.runout]] rows, um, every step_deg."""
    phases = np.random.default_rng([case.seed, 0]).uniform(0, 2 * math.pi, (len(case.layout.channels), 2))
    angles = np.radians(np.arange(0.0, 360.0, step_deg))
    rows = []
    for channel, (first, second) in zip(case.layout.channels, phases, strict=True):
        values = RUNOUT[0] * np.cos(angles - first) + RUNOUT[1] * np.cos(2 * angles - second)
        shaft_angle = ", ".join(f'"{a:g} deg"' for a in np.degrees(angles))
        value = ", ".join(f'"{v * 1e6:.6f} um"' for v in values)
        rows.append(f'\n[[monitor.identify.runout]]\nprobe = "{channel}"\n')
        rows.append(f"shaft_angle = [{shaft_angle}]\nvalue = [{value}]\n")
    return "".join(rows)


def test_monitor_identify_with_a_runout_table(runout_rig, tmp_path):
    """A runout table in the case (the forward model's runout every 5 deg, as a commissioning measurement
    would give it, to 1e-6 um): the lowest film and 1X amplitudes of the 120 rpm recording within the bound
    of the slow-roll file's test, whose profile error is replaced by the table's interpolation error (chord
    of a curve of largest curvature A1 + 4 A2 over 5 deg: (5 deg)^2 / 8 x 6 um = 0.0057 um) and the 128 bins'."""
    case, recording, run_file, _ = runout_rig
    result, database = _identify(tmp_path, "table", run_file, _table(case))
    assert result.exit_code == 0, result.stderr
    document = _document(tmp_path, "table")
    assert document["slow_roll"]["source"] == "table" and document["recordings"][0]["runout"]["source"] == "table"
    interpolation = math.radians(5.0) ** 2 / 8 * (RUNOUT[0] + 4 * RUNOUT[1]) + 0.0003e-6
    residual = SLOPE * SPEED / 2048.0 + interpolation
    size = 4096
    whirl = case.whirl * (SPEED / case.whirl_speed) ** 2
    for section in case.layout.sections:
        ey, ez = recording.centres(np.array([section.position]))
        true_min = recording.clearance - np.hypot(ey[:, 0], ez[:, 0])
        true_low = []
        for k in range(2):
            block = slice(k * size, (k + 1) * size)
            marks = revolution_marks(recording.keyphasor[block])
            true_low.append(true_min[block][marks[0] : marks[-1]].min())
        sigma = film_noise_std(section, FILM_ANGLES, case.layout.rotation, _gap_std(case, section)).max()
        gain = film_noise_std(section, FILM_ANGLES, case.layout.rotation, np.ones(len(section.probes))).max()
        bound = math.sqrt(len(section.probes)) * gain * residual
        with TrendStore(database) as store:
            low = store.series("min_film_thickness_low", section.name)["value"].to_numpy()
            one_x = np.concatenate(
                [store.series(q, section.name)["value"].to_numpy() for q in ("vertical_1x", "horizontal_1x")]
            )
        assert np.abs(low - true_low).max() <= 5 * sigma + bound, section.name
        assert np.abs(one_x - whirl).max() <= bound, section.name


@pytest.mark.parametrize(
    ("extra", "message"),
    [
        ('slow_roll_speed = "30 rpm"\nslow_roll = "slow.csv"\n',
         "monitor.identify.slow_roll_speed = 3.14159265359 rad/s: allowed one source of runout only"),
        ('slow_roll_speed = "-3 rpm"\n', "monitor.identify.slow_roll_speed = "),
        ('slow_roll_speed = "3000 rpm"\n', "monitor.identify.slow_roll_speed = "),
        ('\n[[monitor.identify.runout]]\nprobe = "D1_1"\nshaft_angle = ["0 deg", "90 deg", "45 deg"]\n'
         'value = ["1 um", "0 um", "-1 um"]\n',
         "monitor.identify.runout[0].shaft_angle[2] = 0.785398163397 rad: allowed > shaft_angle[1]"),
        ('\n[[monitor.identify.runout]]\nprobe = "D1_1"\nshaft_angle = ["0 deg", "90 deg", "180 deg", "270 deg"]\n'
         'value = ["1 um", "0 um", "-1 um"]\n',
         "monitor.identify.runout[0].value = 3: allowed one value per shaft angle (4)"),
        ('\n[[monitor.identify.runout]]\nprobe = "D1_1"\nshaft_angle = ["10 deg", "90 deg", "370 deg"]\n'
         'value = ["1 um", "0 um", "-1 um"]\n', "monitor.identify.runout[0].shaft_angle[2] = "),
        ('\n[[monitor.identify.runout]]\nprobe = "D1_1"\nshaft_angle = ["0 deg", "90 deg", "180 deg"]\n'
         'value = ["1 mm", "0 um", "-1 um"]\n', "monitor.identify.runout[0].value[0] = 0.001 m"),
        ('\n[[monitor.identify.runout]]\nprobe = "D9_1"\nshaft_angle = ["0 deg", "90 deg", "180 deg"]\n'
         'value = ["1 um", "0 um", "-1 um"]\n', "monitor.identify.runout[0].probe = 'D9_1': allowed one of the probes"),
        ('\n[[monitor.identify.runout]]\nprobe = "D1_1"\nshaft_angle = ["0 deg", "90 deg", "180 deg"]\n'
         'value = ["1 um", "0 um", "-1 um"]\n', "monitor.identify.runout = '1 of 9 probes': allowed a runout table for "
         "every probe (missing: D1_2, D1_3"),
    ],
)  # fmt: skip
def test_bad_runout_settings_are_one_line(runout_rig, tmp_path, extra, message):
    """Each wrong runout setting: one line naming the field, the value with its unit and what is allowed;
    nothing stored."""
    _, _, run_file, _ = runout_rig
    (tmp_path / "slow.csv").write_text("not used")
    result, database = _identify(tmp_path, "bad", run_file, extra)
    assert result.exit_code == 2, result.stdout
    assert result.stderr.count("\n") == 1 and message in result.stderr, result.stderr
    assert not database.exists()


def test_a_stored_recording_with_other_settings_is_refused_or_replaced(runout_rig, tmp_path):
    """A recording stored without runout compensation and run again with a slow roll was skipped as stored
    (its content hash): now it is refused in one line naming the setting that differs, the database
    untouched; --replace identifies it again, its windows then the same as in a new database with the slow
    roll, another recording's windows kept; the same command again stores nothing, and the first
    (without the slow roll) is now the one refused."""
    case, _, run_file, slow_file = runout_rig
    other = tmp_path / "other.csv"
    text = run_file.read_text()
    other.write_text(text + text.rstrip("\n").rsplit("\n", 1)[1] + "\n")  # other bytes: one sample more
    database = tmp_path / "m.sqlite"
    rig = str(case_file(tmp_path))

    def identify(*arguments: str, db: Path = database):
        result = invoke("monitor", "identify", rig, *arguments, "--db", str(db), "--json", "-")
        return result, json.loads(result.stdout)["monitor"]["identify"] if result.exit_code == 0 else None

    first, _ = identify(str(run_file), str(other))
    assert first.exit_code == 0, first.stderr
    with TrendStore(database) as store:
        kept = store.series("min_film_thickness_low")
        kept = kept[kept["recording"] == "other.csv"].reset_index(drop=True)
    before = database.read_bytes()
    refused, _ = identify(str(run_file), "--slow-roll", str(slow_file))
    assert refused.exit_code == 2 and refused.stderr.count("\n") == 1, refused.stderr
    message = " ".join(refused.stderr.split())
    assert message.startswith("error: run.csv: settings = 'runout slow-roll recording sha256 "), message
    assert "were identified with (runout none); --replace identifies it again" in message, message
    assert database.read_bytes() == before
    replaced, document = identify(str(run_file), "--slow-roll", str(slow_file), "--replace")
    assert replaced.exit_code == 0, replaced.stderr
    assert [(r["windows"], r["written"], r["replaced"]) for r in document["recordings"]] == [(2, 2, True)]
    fresh, _ = identify(str(run_file), "--slow-roll", str(slow_file), db=tmp_path / "fresh.sqlite")
    assert fresh.exit_code == 0, fresh.stderr
    with TrendStore(database) as store, TrendStore(tmp_path / "fresh.sqlite") as new:
        now = store.series("min_film_thickness_low")
        np.testing.assert_array_equal(
            now[now["recording"] == "run.csv"]["value"].to_numpy(), new.series("min_film_thickness_low")["value"]
        )
        after = now[now["recording"] == "other.csv"].reset_index(drop=True)
        assert len(store.recordings()) == 2
    assert after.equals(kept)
    again, document = identify(str(run_file), "--slow-roll", str(slow_file))
    assert again.exit_code == 0 and document["recordings"][0]["written"] == 0, again.stderr
    back, _ = identify(str(run_file))
    assert back.exit_code == 2, back.stderr
    assert "were identified with (runout slow-roll recording sha256" in " ".join(back.stderr.split())


def test_a_slow_roll_speed_above_the_running_speed_is_warned(runout_rig, tmp_path):
    """`slow_roll_speed` above the recording's 120 rpm: every window is a "slow" one, so its runout is the
    recording's whole synchronous motion (film, whirl); said in the terminal, as for a slow-roll file run
    at speed (the run-up above, 15 rpm slow windows against 120 rpm, is not warned)."""
    _, _, run_file, _ = runout_rig
    result, _ = _identify(tmp_path, "high", run_file, 'slow_roll_speed = "150 rpm"\n')
    assert result.exit_code == 0, result.stderr
    text = " ".join(result.stdout.split())
    assert "warning: run.csv: runout from its 2 windows below 150 rpm" in text, text
    assert "but every window is below slow_roll_speed" in text, text
