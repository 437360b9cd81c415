"""``shaftline monitor identify`` and ``shaftline monitor trend`` (issue 13, part B): recordings of
seed 001's rig made by the forward model, identified window by window into the trend database
through the command line, the bad inputs of the issue's list (one line, exit 2, nothing stored),
a real Ctrl-C and the resumed run, and the trends, alarms and projected crossing read back."""

from __future__ import annotations

import datetime as dt
import json
import signal
import subprocess
import sys
import time
from pathlib import Path

import numpy as np
import pandas as pd
import pytest
import sqlalchemy as sa

from shaftline.monitor.forward import RigCase, simulate
from shaftline.monitor.trends import TrendStore, centre_lines, section_trends
from tests.conftest import invoke

ROOT = Path(__file__).resolve().parents[2]
EXAMPLE = ROOT / "examples" / "monitor_rig.toml"
RPM = 2 * np.pi / 60
START = dt.datetime(2026, 11, 2, 6, 0, tzinfo=dt.UTC)


def case_file(folder: Path, identify: str = "") -> Path:
    """The example's probes and [monitor.identify] (no [monitor.simulate]), its shaft model by absolute path."""
    text = EXAMPLE.read_text()
    text = text[: text.index("[monitor.simulate]")] + text[text.index("[monitor.identify]") :]
    text = text.replace(
        'shaft_model = "monitor_rig_shaft.toml"', f'shaft_model = "{ROOT / "examples" / "monitor_rig_shaft.toml"}"'
    )
    # 2 s windows: the tests' recordings are a few seconds at 120 rpm (the example's 8 s hold two turns at 15 rpm)
    text = text.replace('window = "8 s"', 'window = "2 s"')
    path = folder / "rig.toml"
    path.write_text(text + identify)
    return path


@pytest.fixture(scope="module")
def truth():
    """8 revolutions at 120 rpm (4 s at 2048 Hz) of the forward model on a small grid."""
    case = RigCase(revolutions=8.0, axial_nodes=31, circumferential_nodes=72)
    return case, simulate(case, 120 * RPM)


def write_csv(path: Path, truth, signals: np.ndarray | None = None, extra: dict | None = None) -> Path:
    case, recording = truth
    frame = pd.DataFrame(recording.signals if signals is None else signals, columns=list(case.layout.channels))
    frame["keyphasor"] = recording.keyphasor
    for name, values in (extra or {}).items():
        frame[name] = values
    frame.insert(0, "time", np.arange(len(frame)) / recording.sample_rate)
    frame.to_csv(path, index=False, float_format="%.10g")
    return path


def rows(database: Path) -> int:
    if not database.exists():
        return 0
    engine = sa.create_engine(f"sqlite:///{database}")
    try:
        with engine.connect() as connection:
            if not sa.inspect(connection).has_table("windows"):
                return 0  # a run that is making the database
            return int(connection.execute(sa.text("select count(*) from windows")).scalar_one())
    finally:
        engine.dispose()


def test_identify_stores_the_windows_once_and_reports_them(truth, tmp_path):
    """Two 2 s windows; the mean h_min of each section within 2 % of the forward model's (the
    identification's tolerance, tests/monitor/test_forward.py); the same file again stores
    nothing; the trend verb reads the same numbers back."""
    case, recording = truth
    path = write_csv(tmp_path / "rig.csv", truth)
    database, out = tmp_path / "trends.sqlite", tmp_path / "out"
    result = invoke("monitor", "identify", str(case_file(tmp_path)), str(path), "--db", str(database),
                    "--out", str(out), "--json", "-")  # fmt: skip
    assert result.exit_code == 0, result.stderr
    stored = json.loads(result.stdout)["monitor"]["identify"]["recordings"]
    assert [(r["windows"], r["written"], r["masked_samples"]) for r in stored] == [(2, 2, 0)]
    assert stored[0]["started_at"] == START.isoformat()  # the case's start, not the file's time
    for section in case.layout.sections:
        ey, ez = recording.centres(np.array([section.position]))
        true_film = (recording.clearance - np.hypot(ey[:, 0], ez[:, 0])).mean()
        films = stored[0]["sections"][section.name]["min_film_thickness"]
        np.testing.assert_allclose(films, true_film, rtol=0.02)
    assert (out / "figures" / "monitor_identified_0.png").stat().st_size > 10_000
    # the last window's figures, as monitor simulate draws them: film along and round the bearing, orbits
    names = ["min_film", "film_map"] + [f"{kind}_{k}" for kind in ("orbit", "film_polar") for k in range(3)]
    for name in names:
        assert (out / "figures" / f"monitor_identified_{name}.png").stat().st_size > 10_000, name
    assert "Last window identified: rig.csv, window 1" in (out / "report.html").read_text()
    again = invoke("monitor", "identify", str(case_file(tmp_path)), str(path), "--db", str(database), "--json", "-")
    assert again.exit_code == 0, again.stderr
    assert json.loads(again.stdout)["monitor"]["identify"]["recordings"][0]["written"] == 0
    assert rows(database) == 2
    trend = invoke("monitor", "trend", "--db", str(database), "--json", "-")
    assert trend.exit_code == 0, trend.stderr
    sections = json.loads(trend.stdout)["monitor_trend"]["sections"]
    assert list(sections) == ["D1", "D2", "D3", "bearing"]
    assert sections["D1"]["min_film_thickness"] == stored[0]["sections"]["D1"]["min_film_thickness"]


@pytest.mark.slow
def test_simulate_then_identify_the_example(simulated_example, tmp_path):
    """The README's commands in a row on examples/monitor_rig.toml: the simulated recordings (16 s each) are
    read back in two windows of 8 s, the runout from the slow roll subtracted, and their mean h_min rises with
    speed at each section (seed 001 Fig. 10)."""
    simulated, sim = simulated_example  # the example's run, shared with test_monitor_cli's
    assert simulated.exit_code == 0, simulated.stderr
    speeds = [35, 65, 95, 135, 175, 215]
    files = sorted((sim / "data").glob("recording_*rpm.csv"))  # zero-padded: in speed order
    assert [f.name for f in files] == [f"recording_{rpm:03d}rpm.csv" for rpm in speeds]
    result = invoke("monitor", "identify", str(EXAMPLE), *map(str, files), "--db", str(tmp_path / "m.sqlite"),
                    "--slow-roll", str(sim / "data" / "slow_roll_15rpm.csv"),
                    "--json", str(tmp_path / "r.json"))  # fmt: skip
    assert result.exit_code == 0, result.stderr
    # D1 and the loaded end are negative (the journal pressed into the liner): the terminal says what that means
    assert "A negative film (and lambda) is the journal nearer the probes" in " ".join(result.stdout.split())
    recordings = json.loads((tmp_path / "r.json").read_text())["monitor"]["identify"]["recordings"]
    assert [r["windows"] for r in recordings] == [2] * len(speeds)
    # back to back from the case's start
    starts = [(START + dt.timedelta(seconds=16 * k)).strftime("%Y-%m-%dT%H:%M:%S") for k in range(len(speeds))]
    assert [r["started_at"][:19] for r in recordings] == starts
    for name in ("D1", "D2", "D3"):
        means = [np.mean(r["sections"][name]["min_film_thickness"]) for r in recordings]
        assert np.all(np.diff(means) > 0), name


def test_ctrl_c_inside_the_compiled_kernel_is_an_interrupt_not_a_traceback(truth, tmp_path, monkeypatch):
    """Ctrl-C while the compiled orbit kernel runs (or loads from numba's cache) reaches Python as a SystemError
    caused by the KeyboardInterrupt ("returned a result with an exception set"): the real-SIGINT test below met
    it once on a fresh clone (exit 1 with a traceback). It is the same interrupt: exit 130, the resume line. Any
    other SystemError keeps its traceback."""
    from shaftline.errors import interrupted_by_user
    from shaftline.monitor import processing

    def interrupted_in_numba(*args, **kwargs):
        try:
            raise KeyboardInterrupt
        except KeyboardInterrupt as stop:
            raise SystemError("CPUDispatcher(_orbit_kernel) returned a result with an exception set") from stop

    path = write_csv(tmp_path / "r.csv", truth)
    monkeypatch.setattr(processing, "process_recording", interrupted_in_numba)
    result = invoke("monitor", "identify", str(case_file(tmp_path)), str(path), "--db", str(tmp_path / "m.sqlite"))
    assert result.exit_code == 130, result.stderr
    assert "run the same command again to resume" in result.stderr and "Traceback" not in result.stderr
    assert not interrupted_by_user(SystemError("a defect")) and interrupted_by_user(KeyboardInterrupt())


def test_nan_and_saturated_samples_are_masked_and_counted(truth, tmp_path):
    """0.5 % of the samples NaN or beyond the probe's range: filled, counted, warned of; the films
    agree with the clean recording's within 0.5 % or 5 nm, a tenth of the probe noise (the
    bearing's smallest film is near zero at 120 rpm; a few samples are filled by interpolation)."""
    case, recording = truth
    clean = write_csv(tmp_path / "clean.csv", truth)
    signals = recording.signals.copy()
    rng = np.random.default_rng(3)
    bad = rng.random(signals.shape) < 0.005
    signals[bad & (rng.random(signals.shape) < 0.5)] = np.nan
    signals[bad & ~np.isnan(signals)] = 50.0  # volts: far beyond every probe's range
    dirty = write_csv(tmp_path / "dirty.csv", truth, signals)
    results = []
    for path in (clean, dirty):
        result = invoke("monitor", "identify", str(case_file(tmp_path)), str(path), "--db",
                        str(tmp_path / f"{path.stem}.sqlite"))  # fmt: skip
        assert result.exit_code == 0, result.stderr
        results.append(result)
    assert f"{int(bad.sum())} probe samples of {signals.size}" in results[1].stdout
    with TrendStore(tmp_path / "clean.sqlite") as a, TrendStore(tmp_path / "dirty.sqlite") as b:
        np.testing.assert_allclose(
            b.series("min_film_thickness")["value"], a.series("min_film_thickness")["value"], rtol=5e-3, atol=5e-9
        )


def hdf5_with_two_rates(path: Path, truth) -> Path:
    import h5py

    case, recording = truth
    with h5py.File(path, "w") as file:
        for k, name in enumerate([*case.layout.channels, "keyphasor"]):
            data = recording.keyphasor if name == "keyphasor" else recording.signals[:, k]
            file.create_dataset(name, data=data).attrs["sample_rate"] = 2048.0 if k else 1024.0
    return path


@pytest.mark.parametrize(
    ("make", "message"),
    [
        (lambda p, t: _drop(write_csv(p / "r.csv", t), "D2_3"),
         "error: r.csv: channels = 'D2_3': allowed channels of r.csv"),
        (lambda p, t: write_csv(p / "r.csv", t, extra={"D4_1": 0.0}), "error: r.csv channels = 'D4_1'"),
        (lambda p, t: write_csv(p / "r.csv", t, t[1].signals * 1000.0), "error: r.csv window 0, channel D1_1"),
        (lambda p, t: write_csv(p / "r.csv", t, np.where(np.arange(t[1].signals.shape[0])[:, None] % 10 == 0,
                                                         np.nan, t[1].signals)),
         'error: r.csv window 0 = "10.01% of the probe samples NaN'),
        (hdf5_with_two_rates, "error: r.h5 sample rates"),
        (lambda p, t: _rename(write_csv(p / "r.csv", t), "keyphasor", "kp"),
         "error: r.csv: monitor.identify.keyphasor = 'keyphasor': allowed the once-per-revolution channel of r.csv "
         "(channels there besides the probes: kp)"),
    ],
    ids=["missing channel", "extra channel", "units off by 1000", "too many NaN", "two sample rates",
         "keyphasor named otherwise"],
)  # fmt: skip
def test_bad_recordings_are_one_line_and_store_nothing(truth, tmp_path, make, message):
    path = make(tmp_path, truth) if make is not hdf5_with_two_rates else make(tmp_path / "r.h5", truth)
    good = write_csv(tmp_path / "good.csv", truth)
    database = tmp_path / "m.sqlite"
    # the good recording first: nothing of it is stored either, all are checked before
    result = invoke("monitor", "identify", str(case_file(tmp_path)), str(good), str(path), "--db", str(database),
                    "--out", str(tmp_path / "out"))  # fmt: skip
    assert result.exit_code == 2, result.stdout
    assert result.stderr.startswith(message) and result.stderr.count("\n") == 1, result.stderr
    assert rows(database) == 0 and not (tmp_path / "out").exists()


def _rename(path: Path, column: str, name: str) -> Path:
    pd.read_csv(path).rename(columns={column: name}).to_csv(path, index=False)
    return path


def _drop(path: Path, column: str) -> Path:
    pd.read_csv(path).drop(columns=[column]).to_csv(path, index=False)
    return path


def test_an_unreachable_database_and_no_recording_are_one_line(truth, tmp_path):
    path = write_csv(tmp_path / "r.csv", truth)
    url = "postgresql+psycopg://someone:secret@127.0.0.1:9/none?connect_timeout=2"
    result = invoke("monitor", "identify", str(case_file(tmp_path)), str(path), "--db", url)
    assert result.exit_code == 2 and result.stderr.startswith("error: database = ") and "secret" not in result.stderr
    assert result.stderr.count("\n") == 1
    folder = tmp_path / "o"
    inside = invoke("monitor", "identify", str(case_file(tmp_path)), str(path), "--db", str(folder / "m.sqlite"),
                    "--out", str(folder))  # fmt: skip
    assert inside.exit_code == 2 and "allowed a database outside the --out folder" in inside.stderr
    assert not folder.exists()
    none = invoke("monitor", "identify", str(case_file(tmp_path)))
    assert none.exit_code == 2 and none.stderr.startswith("error: RECORDING = 'none'")
    trend = invoke("monitor", "trend", "--db", str(tmp_path / "none.sqlite"))
    assert trend.exit_code == 2 and "an existing trend database" in trend.stderr
    assert not (tmp_path / "none.sqlite").exists()
    # a database kind this installation has no driver for: the line says which it has
    other = invoke("monitor", "identify", str(case_file(tmp_path)), str(path), "--db", "mysql://u:secret@host/db")
    assert other.exit_code == 2 and other.stderr.count("\n") == 1 and "secret" not in other.stderr
    assert "a SQLite file or sqlite:/// URL, or a postgresql+psycopg:// URL" in other.stderr


def test_the_default_database_is_beside_the_case(truth, tmp_path):
    path = write_csv(tmp_path / "r.csv", truth)
    folder = tmp_path / "installation"
    folder.mkdir()
    result = invoke("monitor", "identify", str(case_file(folder)), str(path))
    assert result.exit_code == 0, result.stderr
    assert rows(folder / "monitor.sqlite") == 2
    trend = invoke("monitor", "trend", str(case_file(folder)), "--json", "-")
    assert trend.exit_code == 0, trend.stderr
    assert len(json.loads(trend.stdout)["monitor_trend"]["sections"]["bearing"]["times"]) == 2


@pytest.mark.slow
def test_ctrl_c_keeps_the_windows_and_the_same_command_resumes(tmp_path):
    """SIGINT to a long identification (a real process, as a user's Ctrl-C): exit 130, a line
    saying where the windows are and how to resume, nothing in --out; the next run stores the
    rest only, and the database then holds every window once."""
    case = RigCase(revolutions=240.0, axial_nodes=31, circumferential_nodes=72, sample_rate=1024.0)
    long = simulate(case, 120 * RPM)  # 120 s: 120 windows of 1 s
    path = write_csv(tmp_path / "long.csv", (case, long))
    # the least-squares centre line (no shaft model): about 10 ms a window
    rig = case_file(tmp_path, "").read_text().replace('window = "2 s"', 'window = "1 s"')
    rig = "\n".join(line for line in rig.splitlines() if not line.startswith("shaft_"))
    (tmp_path / "rig.toml").write_text(rig)
    database, out = tmp_path / "m.sqlite", tmp_path / "out"
    command = [sys.executable, "-m", "shaftline.cli", "monitor", "identify", str(tmp_path / "rig.toml"), str(path),
               "--db", str(database), "--out", str(out)]  # fmt: skip
    process = subprocess.Popen(command, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    deadline = time.monotonic() + 120.0
    while rows(database) < 3 and time.monotonic() < deadline and process.poll() is None:
        time.sleep(0.1)
    process.send_signal(signal.SIGINT)
    _, stderr = process.communicate(timeout=60)
    assert process.returncode == 130, stderr
    assert f"kept in sqlite:///{database}: run the same command again to resume" in stderr and not out.exists()
    kept = rows(database)
    assert 0 < kept < 120
    again = invoke("monitor", "identify", str(tmp_path / "rig.toml"), str(path), "--db", str(database), "--json", "-")
    assert again.exit_code == 0, again.stderr
    assert json.loads(again.stdout)["monitor"]["identify"]["recordings"][0]["written"] == 120 - kept
    assert rows(database) == 120


def _store_falling(path: Path, days: int = 10) -> None:
    """One window a day: h_min falling 0.5 um a day from 8 um at every section, lambda = h / 2 um."""
    with TrendStore(path) as store:
        recording = store.recording("f" * 64, "log.tdms", 100, 10.0, START)
        for k in range(days):
            film = 8e-6 - 0.5e-6 * k
            values = {}
            for section in ("D1", "bearing"):
                values[(section, "min_film_thickness")] = film
                values[(section, "film_parameter")] = film / 2e-6
                values[(section, "eccentricity_ratio")] = 0.9
                values[(section, "attitude_angle")] = 0.3
            store.add_window(recording, k, START + dt.timedelta(days=k), values, speed=(100 + 10 * (k % 2)) * RPM)


def test_trends_alarms_and_projected_crossing(tmp_path):
    """Analytic: h_min = 8 - 0.5 k um on day k, lambda = h / 2 um = 4 - 0.25 k. With a threshold of
    2.5 the default limit is 2.5 sigma = 5 um (sigma read from the stored h / lambda) and lambda is
    below it on days 7-9 (one alarm, lowest 1.75); the straight line reaches a 2 um limit on day
    12 exactly; the centre line has two 5-window speed bins at the stored e/c and attitude."""
    database = tmp_path / "m.sqlite"
    _store_falling(database)
    with TrendStore(database) as store:
        trends = section_trends(store, threshold=2.5, min_duration=dt.timedelta(days=1))
        assert [t.section for t in trends] == ["D1", "bearing"]
        whole = trends[-1]
        assert whole.limit == pytest.approx(5e-6)  # 2.5 x sigma
        # lambda = 4 - 0.25 k < 2.5 from k = 7 to 9: one stretch of two days, lowest 1.75
        assert [(a.start, a.end, a.lowest) for a in whole.alarms] == [
            (START + dt.timedelta(days=7), START + dt.timedelta(days=9), pytest.approx(1.75))
        ]
        own = section_trends(store, threshold=1.0, min_duration=dt.timedelta(days=1), limit=2e-6)[-1]
        assert own.alarms == () and own.crossing is not None
        assert abs((own.crossing.crossing - (START + dt.timedelta(days=12))).total_seconds()) < 1.0
        lines = centre_lines(store)
        assert [line.windows.tolist() for line in lines] == [[5, 5], [5, 5]]
        np.testing.assert_allclose(lines[0].speed, [100 * RPM, 110 * RPM])
        np.testing.assert_allclose(lines[0].eccentricity_ratio, 0.9)
        np.testing.assert_allclose(lines[0].attitude_angle, 0.3)


def test_no_trend_is_projected_over_less_than_a_day(tmp_path):
    """Windows a minute apart with the film falling fast (an operating-point change, not wear):
    no straight line and no crossing date; the verb says why in its summary."""
    database = tmp_path / "m.sqlite"
    with TrendStore(database) as store:
        recording = store.recording("e" * 64, "log.csv", 100, 10.0, START)
        for k in range(5):
            values = {("bearing", "min_film_thickness"): 8e-6 - 1e-6 * k, ("bearing", "film_parameter"): 4.0 - 0.5 * k}
            store.add_window(recording, k, START + dt.timedelta(minutes=k), values, speed=100 * RPM)
    with TrendStore(database) as store:
        (trend,) = section_trends(store, threshold=1.0, min_duration=dt.timedelta(days=1), limit=2e-6)
        assert trend.crossing is None
    result = invoke("monitor", "trend", "--db", str(database), "--out", str(tmp_path / "out"))
    assert result.exit_code == 0, result.stderr
    text = (tmp_path / "out" / "report.html").read_text()
    assert "1 recording in" in text and "5 windows from" in text
    assert "not fitted: the windows span 240 s, and a trend needs 1 day or more" in text


def test_trend_verb_options_and_figures(tmp_path):
    database, out = tmp_path / "m.sqlite", tmp_path / "out"
    _store_falling(database)
    result = invoke("monitor", "trend", "--db", str(database), "--limit", "2 um", "--lambda-threshold", "2.5",
                    "--min-duration", "1 day", "--out", str(out), "--json", "-")  # fmt: skip
    assert result.exit_code == 0, result.stderr
    document = json.loads(result.stdout)["monitor_trend"]
    bearing = document["sections"]["bearing"]
    assert bearing["limit"] == pytest.approx(2e-6) and len(bearing["alarms"]) == 1
    assert bearing["trend"]["crossing"].startswith("2026-11-14T06:00")
    assert document["alarm_duration"] == 86400.0
    for name in ("monitor_trend", "monitor_trend_centre_line"):
        assert (out / "figures" / f"{name}.png").stat().st_size > 10_000
    bad = invoke("monitor", "trend", "--db", str(database), "--limit", "2 kg")
    assert bad.exit_code == 2 and bad.stderr.startswith("error: --limit")


def test_progress_counts_the_windows_of_each_recording(truth, tmp_path):
    """The command line's bar: a Tally per recording counting its windows up to all of them."""
    from shaftline.monitor.processing import identify_recordings
    from shaftline.monitor.study import IdentifyPlan
    from shaftline.registry import Tally

    case, _ = truth
    files = [write_csv(tmp_path / "a.csv", truth), write_csv(tmp_path / "b.csv", truth, truth[1].signals + 1e-7)]
    told: list[Tally] = []
    plan = IdentifyPlan(tuple(map(str, files)), str(tmp_path / "m.sqlite"), start=START)
    done = identify_recordings(case.layout, plan, progress=lambda step: told.append(step))
    assert [(t.label, t.done, t.total, t.unit) for t in told] == [
        ("a.csv (1/2)", 0, 2, "windows"), ("a.csv (1/2)", 1, 2, "windows"), ("a.csv (1/2)", 2, 2, "windows"),
        ("b.csv (2/2)", 0, 2, "windows"), ("b.csv (2/2)", 1, 2, "windows"),
        ("b.csv (2/2)", 2, 2, "windows"),
    ]  # fmt: skip
    # the second file follows the first back to back
    assert done.recordings[1].processed.recording.started_at == START + dt.timedelta(seconds=4)


def _foreign_sqlite(path: Path) -> Path:
    engine = sa.create_engine(f"sqlite:///{path}")
    with engine.begin() as connection:
        connection.execute(sa.text("create table notes (line text)"))
        connection.execute(sa.text("insert into notes values ('kept')"))
    engine.dispose()
    return path


@pytest.mark.parametrize(
    ("verb", "message"),
    [
        ("case database in --out", "allowed a folder that does not hold the input"),
        ("--json is the database", "allowed a file other than the run's inputs"),
        ("trend --json is the database", "allowed a file other than the run's inputs"),
        ("trend database in a result --out", "allowed a folder that does not hold the input"),
        ("database in a missing folder", "allowed a database file in an existing folder"),
        ("another program's SQLite file", "allowed a trend database made by monitor identify, or a new file"),
    ],
)
def test_outputs_never_replace_the_database_or_another_file(truth, tmp_path, verb, message):
    """Never lose user data: the trend database (the case's, --db's, a URL's file) is kept like an
    input, so no --json or --out may replace it or hold it, checked before anything is written;
    a database in a folder that does not exist, or a SQLite file of another program, is refused
    instead of SQLite's "unable to open" or our tables added to it. Every file stays as it was."""
    path = write_csv(tmp_path / "r.csv", truth)
    database = tmp_path / "m.sqlite"
    setup = invoke("monitor", "identify", str(case_file(tmp_path)), str(path), "--db", str(database))
    assert setup.exit_code == 0, setup.stderr
    out = tmp_path / "out"
    if verb == "case database in --out":
        out.mkdir()
        rig = (
            case_file(tmp_path, "")
            .read_text()
            .replace("[monitor.identify]", '[monitor.identify]\ndatabase = "out/m.sqlite"')
        )
        (tmp_path / "rig.toml").write_text(rig)
        arguments = ["monitor", "identify", str(tmp_path / "rig.toml"), str(path), "--out", str(out)]
        watched = [out]
    elif verb == "--json is the database":
        arguments = ["monitor", "identify", str(case_file(tmp_path)), str(path), "--db", f"sqlite:///{database}",
                     "--json", str(database)]  # fmt: skip
        watched = [database]
    elif verb == "trend --json is the database":
        arguments = ["monitor", "trend", "--db", str(database), "--json", str(database)]
        watched = [database]
    elif verb == "trend database in a result --out":
        first = invoke("monitor", "trend", "--db", str(database), "--out", str(out))
        assert first.exit_code == 0, first.stderr
        moved = out / "m.sqlite"
        moved.write_bytes(database.read_bytes())
        arguments = ["monitor", "trend", "--db", str(moved), "--out", str(out)]
        watched = [moved, out / "report.html"]
    elif verb == "database in a missing folder":
        arguments = [
            "monitor",
            "identify",
            str(case_file(tmp_path)),
            str(path),
            "--db",
            str(tmp_path / "no" / "m.sqlite"),
        ]
        watched = [tmp_path / "no"]
    else:
        foreign = _foreign_sqlite(tmp_path / "notes.sqlite")
        arguments = ["monitor", "identify", str(case_file(tmp_path)), str(path), "--db", str(foreign)]
        watched = [foreign]
    before = {p: p.read_bytes() if p.is_file() else sorted(p.iterdir()) if p.is_dir() else None for p in watched}
    result = invoke(*arguments)
    assert result.exit_code == 2, result.stdout
    assert message in result.stderr and result.stderr.count("\n") == 1, result.stderr
    after = {p: p.read_bytes() if p.is_file() else sorted(p.iterdir()) if p.is_dir() else None for p in watched}
    assert after == before
    assert rows(database) == 2


@pytest.mark.parametrize("fault", ["invalid samples", "keyphasor lost"])
def test_a_bad_window_mid_recording_is_flagged_and_the_run_goes_on(truth, tmp_path, fault):
    """A monitoring run does not stop at a bad stretch: window 1 of 2 with 10 % of its probe samples NaN
    (over max_invalid_share, 1 %), or with its keyphasor gone, is stored as rejected with its reason and
    share, left out of the trends, and the run ends; the result is not acceptable (exit 3, the line at
    the top of the output and the report), and so it stays when the same command runs again (the flag
    is in the database). Window 0 is identified as from the clean recording. monitor trend warns too."""
    case, recording = truth
    signals, keyphasor = recording.signals.copy(), recording.keyphasor.copy()
    second = slice(4096, 8192)  # window 1 of 2 s at 2048 Hz
    if fault == "invalid samples":
        rows_of = np.arange(second.start, second.stop)
        signals[rows_of[rows_of % 10 == 0]] = np.nan  # 10 % of the window's samples, every channel
        reason, share = "more than max_invalid_share of its probe samples NaN or beyond range", 0.1
    else:
        keyphasor[second] = 0.0
        reason, share = "no whole shaft revolution", 0.0
    frame = pd.DataFrame(signals, columns=list(case.layout.channels))
    frame["keyphasor"] = keyphasor
    frame.insert(0, "time", np.arange(len(frame)) / recording.sample_rate)
    path = tmp_path / "r.csv"
    frame.to_csv(path, index=False, float_format="%.10g")
    clean = write_csv(tmp_path / "clean.csv", truth)
    database, out = tmp_path / "m.sqlite", tmp_path / "out"
    arguments = ["monitor", "identify", str(case_file(tmp_path)), str(path), "--db", str(database)]
    result = invoke(*arguments, "--out", str(out), "--json", str(tmp_path / "r.json"))
    assert result.exit_code == 3, result.stderr
    text = " ".join(result.stdout.split())  # the terminal wraps lines
    assert text.startswith("NOT ACCEPTABLE: Film-thickness monitoring (eddy-current probes): r.csv: 1 window not")
    assert reason in text
    assert "NOT ACCEPTABLE" in (out / "report.html").read_text()
    stored = json.loads((tmp_path / "r.json").read_text())["monitor"]["identify"]["recordings"][0]
    assert (stored["windows"], stored["written"]) == (2, 2)
    (flag,) = stored["rejected_windows"]
    assert flag["window"] == 1 and flag["reason"] == reason
    assert flag["invalid_share"] == pytest.approx(share, abs=1e-3)
    assert len(stored["sections"]["D1"]["times"]) == 1  # the rejected window is not in the trend
    with TrendStore(database) as store, TrendStore(tmp_path / "clean.sqlite") as reference:
        process = invoke("monitor", "identify", str(case_file(tmp_path)), str(clean), "--db", str(reference.url))
        assert process.exit_code == 0, process.stderr
        film = store.series("min_film_thickness", "D1")
        np.testing.assert_allclose(film["value"], reference.series("min_film_thickness", "D1")["value"][:1], rtol=1e-9)
    again = invoke(*arguments)
    assert again.exit_code == 3 and "r.csv: 1 window not identified" in " ".join(again.stdout.split())
    assert rows(database) == 2
    trend = invoke("monitor", "trend", "--db", str(database), "--json", "-")
    assert trend.exit_code == 0, trend.stderr
    assert "r.csv: 1 window not identified" in " ".join(trend.stderr.split())
    assert json.loads(trend.stdout)["monitor_trend"]["recordings"][0]["rejected_windows"] == 1


def test_identify_and_trend_verbs_on_a_real_postgresql_server(truth, tmp_path, postgres_url):
    """The verbs, not only the store, on the PostgreSQL server the fixture starts from Debian's package
    (tests/monitor/conftest.py): `monitor identify --db URL` stores the same numbers as into SQLite,
    the same file again stores nothing (the content hash on the server), `monitor trend --db URL`
    reads them back with its report, and the server holds the two windows."""
    path = write_csv(tmp_path / "r.csv", truth)
    documents = {}
    for label, database in (("postgresql", postgres_url), ("sqlite", str(tmp_path / "m.sqlite"))):
        result = invoke("monitor", "identify", str(case_file(tmp_path)), str(path), "--db", database,
                        "--out", str(tmp_path / f"out-{label}"), "--json", "-")  # fmt: skip
        assert result.exit_code == 0, result.stderr
        documents[label] = json.loads(result.stdout)["monitor"]["identify"]
    server = documents["postgresql"]
    assert server["database"].startswith("postgresql+psycopg://shaftline@/postgres")
    assert [(r["windows"], r["written"]) for r in server["recordings"]] == [(2, 2)]
    assert server["recordings"][0]["sections"] == documents["sqlite"]["recordings"][0]["sections"]
    again = invoke("monitor", "identify", str(case_file(tmp_path)), str(path), "--db", postgres_url, "--json", "-")
    assert again.exit_code == 0, again.stderr
    assert json.loads(again.stdout)["monitor"]["identify"]["recordings"][0]["written"] == 0
    trend = invoke("monitor", "trend", "--db", postgres_url, "--out", str(tmp_path / "trend"), "--json", "-")
    assert trend.exit_code == 0, trend.stderr
    sections = json.loads(trend.stdout)["monitor_trend"]["sections"]
    assert sections["D1"]["min_film_thickness"] == server["recordings"][0]["sections"]["D1"]["min_film_thickness"]
    assert (tmp_path / "trend" / "figures" / "monitor_trend.png").stat().st_size > 10_000
    engine = sa.create_engine(postgres_url)
    try:
        with engine.connect() as connection:
            assert connection.execute(sa.text("select count(*) from windows")).scalar_one() == 2
    finally:
        engine.dispose()


def test_a_recording_without_a_keyphasor_at_a_given_speed(truth, tmp_path):
    """The issue's optional keyphasor: a file without one, `keyphasor = ""` and the shaft speed given,
    is cut into revolutions at that speed from its first sample; the mean h_min per section is the
    forward model's within 2 % (as with the keyphasor), the stored speed is the given one. Without
    the speed, and with a slow roll (runout needs the shaft's phase), one-line errors."""
    case, recording = truth
    path = write_csv(tmp_path / "r.csv", truth)
    pd.read_csv(path).drop(columns=["keyphasor"]).to_csv(path, index=False, float_format="%.10g")
    identify = '[monitor.identify]\nkeyphasor = ""\nspeed = "120 rpm"'
    rig = case_file(tmp_path).read_text().replace('[monitor.identify]\nkeyphasor = "keyphasor"', identify)
    (tmp_path / "rig.toml").write_text(rig)
    result = invoke("monitor", "identify", str(tmp_path / "rig.toml"), str(path), "--db", str(tmp_path / "m.sqlite"),
                    "--json", "-")  # fmt: skip
    assert result.exit_code == 0, result.stderr
    stored = json.loads(result.stdout)["monitor"]["identify"]["recordings"][0]
    assert (stored["windows"], stored["written"]) == (2, 2)
    for section in case.layout.sections:
        ey, ez = recording.centres(np.array([section.position]))
        true_film = (recording.clearance - np.hypot(ey[:, 0], ez[:, 0])).mean()
        trend = stored["sections"][section.name]
        np.testing.assert_allclose(trend["min_film_thickness"], true_film, rtol=0.02)
        np.testing.assert_allclose(trend["speed"], 120 * RPM, rtol=1e-3)  # whole revolutions of 1024 samples
    (tmp_path / "nospeed.toml").write_text(rig.replace('speed = "120 rpm"\n', ""))
    none = invoke("monitor", "identify", str(tmp_path / "nospeed.toml"), str(path), "--db", str(tmp_path / "n.sqlite"))
    assert none.exit_code == 2 and none.stderr.startswith("error: monitor.identify.speed = 'none'"), none.stderr
    assert not (tmp_path / "n.sqlite").exists()  # refused before any database or file is touched
    slow = invoke("monitor", "identify", str(tmp_path / "rig.toml"), str(path), "--slow-roll", str(path),
                  "--db", str(tmp_path / "s.sqlite"))  # fmt: skip
    assert slow.exit_code == 2 and slow.stderr.startswith("error: monitor.identify.slow_roll = "), slow.stderr
    assert "allowed recordings with a keyphasor" in slow.stderr, slow.stderr
    assert not (tmp_path / "n.sqlite").exists() and not (tmp_path / "s.sqlite").exists()


#: The columns of the trend store's table `recordings`, as the refusal names them.
RECORDINGS_COLUMNS = "id, content_hash, name, samples, sample_rate, started_at, complete"


def _foreign_recordings(url: str) -> None:
    """Another application's table named `recordings`, with a row, in the database at ``url``."""
    engine = sa.create_engine(url)
    try:
        with engine.begin() as connection:
            connection.execute(sa.text("create table recordings (id integer primary key, title text, artist text)"))
            connection.execute(sa.text("insert into recordings values (1, 'Kind of Blue', 'Miles Davis')"))
    finally:
        engine.dispose()


def _tables_and_rows(url: str) -> tuple[list[str], list[tuple]]:
    engine = sa.create_engine(url)
    try:
        with engine.connect() as connection:
            tables = sorted(sa.inspect(connection).get_table_names())
            rows = [tuple(r) for r in connection.execute(sa.text("select * from recordings"))]
        return tables, rows
    finally:
        engine.dispose()


def _refused_foreign_recordings(truth, tmp_path, url: str) -> None:
    path = write_csv(tmp_path / "r.csv", truth)
    result = invoke("monitor", "identify", str(case_file(tmp_path)), str(path), "--db", url)
    assert result.exit_code == 2, result.stdout
    assert result.stderr.count("\n") == 1, result.stderr
    text = result.stderr
    assert text.startswith(f"error: database = '{url.split('?')[0]}"), text
    assert f"table recordings is the trend store's, with the columns {RECORDINGS_COLUMNS}" in text, text
    assert "this one's has id, title, artist" in text, text
    # nothing written: no table of ours made beside it, its row as it was
    assert _tables_and_rows(url) == (["recordings"], [(1, "Kind of Blue", "Miles Davis")])


def test_a_foreign_recordings_table_in_sqlite_is_one_line(truth, tmp_path):
    """Another program's SQLite file with a table named `recordings` of other columns: one line
    naming the table, the columns the trend store needs and the ones it has; the file unchanged."""
    database = tmp_path / "music.sqlite"
    _foreign_recordings(f"sqlite:///{database}")
    before = database.read_bytes()
    _refused_foreign_recordings(truth, tmp_path, f"sqlite:///{database}")
    assert database.read_bytes() == before


def test_a_foreign_recordings_table_on_postgresql_is_one_line(truth, tmp_path, postgres_url):
    """The same on the real PostgreSQL server (a database of its own on it, so that the other tests'
    tables are not touched): the driver's error on the first insert was what the user saw, after our
    other two tables had been created beside the foreign one."""
    engine = sa.create_engine(postgres_url, isolation_level="AUTOCOMMIT")
    try:
        with engine.connect() as connection:
            connection.execute(sa.text("create database music"))
        url = postgres_url.replace("@/postgres?", "@/music?")
        _foreign_recordings(url)
        _refused_foreign_recordings(truth, tmp_path, url)
    finally:
        with engine.connect() as connection:
            connection.execute(sa.text("drop database if exists music"))
        engine.dispose()


def _fits_80_columns(blocks) -> list:
    """Print each table of ``blocks`` on an 80-column console (as COLUMNS=80): every line at most
    80 wide, the header on one line and a line a row (as tests/gears/test_gears_cli.py). The
    tables, for the caller's own checks."""
    from rich.console import Console

    from shaftline.report.blocks import Table
    from shaftline.report.terminal import print_blocks

    tables = [b for b in blocks if isinstance(b, Table)]
    for table in tables:
        console = Console(record=True, width=80)
        print_blocks(console, [table])
        lines = console.export_text().splitlines()
        assert max(len(line) for line in lines) <= 80
        assert sum(line.startswith("┃") for line in lines) == 1, lines  # the header: no "window s"
        assert sum(line.startswith("│") for line in lines) == len(table.rows), lines
    return tables


def test_the_identify_tables_fit_80_columns_a_line_a_row(truth, tmp_path):
    # `monitor identify`'s summary folded every row of its one nine-column table over five lines
    # at COLUMNS=80 and split the header "windows" into "window s": now two tables (what was done
    # with each recording; what was found in it), each row on one line, headers unbroken.
    from shaftline.cases import load_case
    from shaftline.pipeline import run_case

    path = write_csv(tmp_path / "recording_120rpm.csv", truth)
    overrides = {"monitor.identify.recordings": [str(path)], "monitor.identify.database": str(tmp_path / "m.sqlite")}
    case = load_case(case_file(tmp_path), overrides=overrides)
    result = run_case(case, options={"monitor": {"task": "identify"}})
    capability, value = next(result.capabilities())
    work, found = _fits_80_columns(capability.summary(value))
    assert work.headers == ["recording", "start (UTC)", "windows", "stored", "rejected"]
    assert work.rows == [["recording_120rpm.csv", "2026-11-02 06:00:00", "2", "2", "0"]]
    assert found.headers[:3] == ["recording", "rpm", "h_min [µm]"] and found.rows[0][1] == "120"
    assert "mean h_min at D1/D2/D3" in found.title


def test_long_recording_names_are_cut_in_the_middle_in_the_terminal_only(truth, tmp_path):
    # A recording name of 49 characters was folded by rich over three lines of each of the two
    # tables at COLUMNS=80: now cut in the middle to 24 characters (its start and its end, the
    # speed and the suffix, kept), each row on one line, with a note; the report's tables and
    # results.json keep the full name.
    from shaftline.cases import load_case
    from shaftline.monitor.presentation import NAME_WIDTH
    from shaftline.pipeline import dumps, results_document, run_case
    from shaftline.report.blocks import Paragraph, Table

    name = "aft_stern_tube_probes_2026-11-02T06-00-00_120rpm.csv"
    path = write_csv(tmp_path / name, truth)
    overrides = {"monitor.identify.recordings": [str(path)], "monitor.identify.database": str(tmp_path / "m.sqlite")}
    case = load_case(case_file(tmp_path), overrides=overrides)
    result = run_case(case, options={"monitor": {"task": "identify"}})
    capability, value = next(result.capabilities())
    summary = capability.summary(value)
    work, found = _fits_80_columns(summary)
    short = work.rows[0][0]
    assert short == found.rows[0][0] and len(short) == NAME_WIDTH == 24
    assert short == name[:11] + "…" + name[-12:] and short.endswith("_120rpm.csv")
    assert any(isinstance(b, Paragraph) and "cut in the middle" in b.text for b in summary)
    report = [b for b in capability.report(value) if isinstance(b, Table) and b.headers[0] == "recording"]
    assert [t.rows[0][0] for t in report] == [name, name]
    document = json.loads(dumps(results_document(result)))
    assert name in json.dumps(document) and short not in json.dumps(document)


@pytest.mark.slow
def test_the_simulate_table_fits_80_columns_a_line_a_row():
    # `monitor simulate`'s table of the example (then 3 speeds) wrapped each row over two lines at
    # COLUMNS=80 ("3.82 / 4.64 / 4.74" broken at its spaces).
    from shaftline.cases import load_case
    from shaftline.pipeline import run_case

    result = run_case(load_case(EXAMPLE), options={"monitor": {"task": "simulate"}})
    capability, value = next(result.capabilities())
    (table,) = _fits_80_columns(capability.summary(value))
    assert [row[0] for row in table.rows] == ["35", "65", "95", "135", "175", "215"]
    assert all(len(row[1].split("/")) == 3 for row in table.rows)  # h_min at D1, D2, D3
