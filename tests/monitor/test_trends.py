"""The trend store (SQLite, and a real PostgreSQL server) and the alarms (issue 13)."""

from __future__ import annotations

import datetime as dt

import numpy as np
import pytest

from shaftline.errors import InputError
from shaftline.monitor.trends import TrendStore, lambda_alarms, trend_crossing

START = dt.datetime(2026, 11, 1, 8, 0, tzinfo=dt.UTC)


def _fill(store: TrendStore, content_hash: str = "a" * 64, windows: range = range(6), fail_at: int | None = None):
    recording = store.recording(content_hash, "run1.tdms", 600_000, 10_000.0, START)
    for k in windows:
        if k in store.windows_done(recording):
            continue
        if k == fail_at:
            raise KeyboardInterrupt
        values = {("aft", "min_film_thickness"): 40e-6 - 1e-6 * k, ("aft", "lambda"): 3.0 - 0.5 * k}
        values[("fore", "min_film_thickness")] = 80e-6
        store.add_window(recording, k, START + dt.timedelta(minutes=10 * k), values, speed=9.4)
    return recording


def _round_trip(store: TrendStore) -> None:
    recording = _fill(store)
    # The same bytes again (another file name): recognised, nothing added.
    again = store.recording("a" * 64, "copy-of-run1.tdms", 600_000, 10_000.0, START)
    assert again.id == recording.id and again.name == "run1.tdms"
    assert not store.add_window(again, 2, START, {("aft", "lambda"): 9.0})
    assert store.windows_done(recording) == set(range(6))
    series = store.series("min_film_thickness", "aft")
    assert len(series) == 6
    np.testing.assert_allclose(series["value"], 40e-6 - 1e-6 * np.arange(6))
    assert series["time"].iloc[-1].to_pydatetime() == START + dt.timedelta(minutes=50)
    assert len(store.series("min_film_thickness")) == 12
    assert store.quantities() == [("aft", "lambda"), ("aft", "min_film_thickness"), ("fore", "min_film_thickness")]
    store.mark_complete(recording)
    assert store.recordings()[0].complete


def test_sqlite_round_trip(tmp_path):
    with TrendStore(tmp_path / "monitor.sqlite") as store:
        _round_trip(store)


def test_an_interrupted_run_keeps_whole_windows_and_resumes(tmp_path):
    path = tmp_path / "monitor.sqlite"
    with TrendStore(path) as store, pytest.raises(KeyboardInterrupt):
        _fill(store, fail_at=3)
    with TrendStore(path) as store:  # a new run, as after Ctrl-C
        recording = store.recording("a" * 64, "run1.tdms", 600_000, 10_000.0, START)
        assert store.windows_done(recording) == {0, 1, 2}
        assert len(store.series("lambda", "aft")) == 3
        _fill(store)
        assert store.windows_done(recording) == set(range(6))
        assert len(store.series("lambda", "aft")) == 6


def test_a_database_that_cannot_be_reached_is_one_line(tmp_path):
    with pytest.raises(InputError) as error:
        TrendStore("postgresql+psycopg://someone:secret@127.0.0.1:9/none?connect_timeout=2")
    message = str(error.value)
    assert error.value.field == "db" and "\n" not in message and "secret" not in message
    with pytest.raises(InputError):
        TrendStore(f"sqlite:///{tmp_path}/no/such/folder/monitor.sqlite")


def test_lambda_alarm_needs_the_stretch_to_last():
    times = [START + dt.timedelta(minutes=5 * k) for k in range(10)]
    values = [3, 0.8, 0.7, 0.9, 2, 0.5, 2, 0.9, 0.8, float("nan")]
    alarms = lambda_alarms(times, values, threshold=1.0, min_duration=dt.timedelta(minutes=10), section="aft")
    # 1-3 (10 min) counts; 5 alone (0 min) and 7-8 (5 min) do not.
    assert [(a.start, a.end, a.lowest) for a in alarms] == [(times[1], times[3], 0.7)]
    assert alarms[0].duration == dt.timedelta(minutes=10)


def test_trend_crossing_of_a_falling_line():
    """A straight line falling 1 um a day from 40 um reaches 30 um on day 10 exactly."""
    times = [START + dt.timedelta(days=k) for k in range(5)]
    fit = trend_crossing(times, [40e-6 - 1e-6 * k for k in range(5)], limit=30e-6)
    assert fit.slope == pytest.approx(-1e-6)
    assert abs((fit.crossing - (START + dt.timedelta(days=10))).total_seconds()) < 1.0
    rising = trend_crossing(times, [40e-6 + 1e-6 * k for k in range(5)], limit=30e-6)
    assert rising.crossing is None
    past = trend_crossing(times, [29e-6] * 5, limit=30e-6)
    assert past.crossing == times[-1]


def test_postgresql_round_trip(postgres_url):
    """The same store on a real PostgreSQL server: one URL is the only difference."""
    with TrendStore(postgres_url) as store:
        _round_trip(store)
    with TrendStore(postgres_url) as store:  # a second connection sees the committed rows
        assert len(store.series("lambda")) == 6


def test_a_rejected_window_ends_a_lambda_stretch(tmp_path):
    """Six windows 5 min apart, lambda 0.8 in every identified one, window 3 stored as rejected (no
    film, as processing stores a window with too many invalid samples): the stretch 0-2 lasts 10 min,
    an alarm; 4-5 lasts 5 min, none. Carried across the rejected window it was one alarm of 25 min,
    a duration no data supports. The trend itself holds the five identified windows."""
    from shaftline.monitor.trends import section_trends

    with TrendStore(tmp_path / "m.sqlite") as store:
        recording = store.recording("b" * 64, "run.csv", 1000, 2048.0, START)
        for k in range(6):
            time = START + dt.timedelta(minutes=5 * k)
            if k == 3:
                values = {("bearing", "rejected"): 1.0, ("bearing", "invalid_share"): 0.2}
            else:
                values = {(s, q): v for s in ("D1", "bearing") for q, v in
                          (("min_film_thickness", 1.6e-6), ("film_parameter", 0.8))}  # fmt: skip
            store.add_window(recording, k, time, values, speed=12.0)
        trends = section_trends(store, 1.0, dt.timedelta(minutes=10))
    for trend in trends:
        assert len(trend.times) == 5
        assert [(a.start, a.end) for a in trend.alarms] == [(START, START + dt.timedelta(minutes=10))], trend.section


@pytest.mark.parametrize(("gap", "spans"), [(dt.timedelta(days=1), [10, 10]), (dt.timedelta(0), [25])])
def test_time_not_recorded_ends_a_lambda_stretch(tmp_path, gap, spans):
    """Two recordings of three 5-min windows each, lambda 0.8 throughout. A day apart: two alarms of
    10 min (the stretch ran on over the day between them, an alarm of a day and 10 min that no data
    supports). Back to back (the second starts where the first ends): one alarm of 25 min."""
    from shaftline.monitor.trends import section_trends

    with TrendStore(tmp_path / "m.sqlite") as store:
        for n, name in enumerate(("a.csv", "b.csv")):
            begin = START + n * (dt.timedelta(minutes=15) + gap)
            recording = store.recording(name[0] * 64, name, 15 * 60 * 100, 100.0, begin)  # 15 min at 100 Hz
            for k in range(3):
                values = {("bearing", "min_film_thickness"): 1.6e-6, ("bearing", "film_parameter"): 0.8}
                store.add_window(recording, k, begin + dt.timedelta(minutes=5 * k), values, speed=12.0)
        (trend,) = section_trends(store, 1.0, dt.timedelta(minutes=10))
    assert [a.duration / dt.timedelta(minutes=1) for a in trend.alarms] == spans


def _same_named_in_two_folders(store: TrendStore) -> tuple:
    """Two recordings both named run.csv (two folders: the name is the file's, its folder is not
    kept), told apart by their bytes' hash: the first of six 1-min windows, the second a day later
    of three 10-min windows (another window setting), lambda 0.8 throughout."""
    from shaftline.monitor.trends import section_trends

    later = START + dt.timedelta(days=1)
    for content, begin, windows, minutes in (("c", START, 6, 1), ("d", later, 3, 10)):
        recording = store.recording(content * 64, "run.csv", windows * minutes * 60 * 100, 100.0, begin)
        for k in range(windows):
            values = {("bearing", "min_film_thickness"): 1.6e-6, ("bearing", "film_parameter"): 0.8}
            store.add_window(recording, k, begin + dt.timedelta(minutes=minutes * k), values, speed=12.0)
    (trend,) = section_trends(store, 1.0, dt.timedelta(minutes=4))
    return trend, later


def _check_same_named(trend, later) -> None:
    # Each recording's windows give its own window length (1 and 10 min): the day between them
    # ends the stretch, and the second's windows are back to back, so two alarms, 5 min and 20 min.
    # Grouped by name, the two recordings' windows were taken as one recording's, whose window
    # length came out as the first's 1 min: the second's windows, 10 min apart, were each followed
    # by 9 min "not recorded", which broke its stretch at every window (no alarm).
    assert [(a.start, a.end) for a in trend.alarms] == [
        (START, START + dt.timedelta(minutes=5)),
        (later, later + dt.timedelta(minutes=20)),
    ]
    assert len(trend.times) == 9


def test_same_named_recordings_in_two_folders_keep_their_own_gaps(tmp_path):
    with TrendStore(tmp_path / "m.sqlite") as store:
        _check_same_named(*_same_named_in_two_folders(store))
        series = store.series("film_parameter", "bearing")
        assert set(series["recording"]) == {"run.csv"} and series["recording_id"].nunique() == 2


def test_same_named_recordings_keep_their_own_gaps_in_postgresql(postgres_url):
    import sqlalchemy as sa

    def drop() -> None:
        engine = sa.create_engine(postgres_url)
        with engine.begin() as connection:
            for table in ("window_values", "windows", "recording_settings", "recordings"):
                connection.execute(sa.text(f"DROP TABLE IF EXISTS {table} CASCADE"))
        engine.dispose()

    drop()  # a fresh store on the module's server (the round trip's rows are there), dropped after
    try:
        with TrendStore(postgres_url) as store:
            _check_same_named(*_same_named_in_two_folders(store))
    finally:
        drop()
