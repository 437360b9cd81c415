"""A recording from file to trend database (issue 13): seed 001's rig simulated by the forward
model, written as a file, processed window by window, stored; again without duplicates; and
resumed after a stop."""

from __future__ import annotations

import datetime as dt

import numpy as np
import pandas as pd
import pytest

from shaftline.errors import InputError
from shaftline.monitor.forward import RigCase, simulate
from shaftline.monitor.processing import BEARING, process_recording
from shaftline.monitor.trends import TrendStore

RPM = 2 * np.pi / 60
START = dt.datetime(2026, 11, 2, 6, 0, tzinfo=dt.UTC)


@pytest.fixture(scope="module")
def rig_file(tmp_path_factory):
    """12 revolutions at 120 rpm (6 s) written as a CSV with a time column."""
    case = RigCase(revolutions=12.0, axial_nodes=31, circumferential_nodes=72)
    truth = simulate(case, 120 * RPM)
    frame = pd.DataFrame(truth.signals, columns=list(case.layout.channels))
    frame["keyphasor"] = truth.keyphasor
    frame.insert(0, "time", np.arange(len(frame)) / truth.sample_rate)
    path = tmp_path_factory.mktemp("rig") / "rig_120rpm.csv"
    frame.to_csv(path, index=False, float_format="%.10g")
    return case, truth, path


def test_windows_are_stored_once_with_the_truths_film(rig_file, tmp_path):
    """Three 2 s windows; each section's mean smallest film within 2 % of the forward model's
    (the identification's own tolerance, tests/monitor/test_forward.py); the same file again
    adds nothing."""
    case, truth, path = rig_file
    with TrendStore(tmp_path / "monitor.sqlite") as store:
        done = process_recording(case.layout, path, store, "keyphasor", window_seconds=2.0, started_at=START)
        assert (done.windows, done.written) == (3, 3)
        again = process_recording(case.layout, path, store, "keyphasor", window_seconds=2.0, started_at=START)
        assert again.written == 0 and again.recording.id == done.recording.id
        for section in case.layout.sections:
            series = store.series("min_film_thickness", section.name)
            assert len(series) == 3
            ey, ez = truth.centres(np.array([section.position]))
            true_film = (truth.clearance - np.hypot(ey[:, 0], ez[:, 0])).mean()
            np.testing.assert_allclose(series["value"], true_film, rtol=0.02)
        times = store.series("film_parameter", BEARING)["time"]
        assert [t.to_pydatetime() for t in times] == [START + dt.timedelta(seconds=2 * k) for k in range(3)]
        speeds = store.series("min_film_thickness", BEARING)["speed"]
        np.testing.assert_allclose(speeds, 120 * RPM, rtol=1e-3)


def test_a_stopped_run_resumes_with_the_same_numbers(rig_file, tmp_path):
    case, _, path = rig_file
    with TrendStore(tmp_path / "whole.sqlite") as store:
        process_recording(case.layout, path, store, "keyphasor", window_seconds=2.0, started_at=START)
        whole = store.series("eccentricity_ratio")

    def stop_after_first(done: int, total: int) -> None:
        if done == 1:
            raise KeyboardInterrupt

    database = tmp_path / "stopped.sqlite"
    with TrendStore(database) as store, pytest.raises(KeyboardInterrupt):
        process_recording(
            case.layout, path, store, "keyphasor", window_seconds=2.0, started_at=START, progress=stop_after_first
        )
    with TrendStore(database) as store:
        assert len(store.series("eccentricity_ratio", case.layout.sections[0].name)) == 1
        resumed = process_recording(case.layout, path, store, "keyphasor", window_seconds=2.0, started_at=START)
        assert resumed.written == 2
        # The reference point is the first window's in both runs, so every number agrees.
        pd.testing.assert_frame_equal(store.series("eccentricity_ratio"), whole)


def test_a_window_longer_than_the_recording_is_refused(rig_file, tmp_path):
    case, _, path = rig_file
    with TrendStore(tmp_path / "monitor.sqlite") as store, pytest.raises(InputError) as error:
        process_recording(case.layout, path, store, "keyphasor", window_seconds=60.0)
    assert error.value.field == "window_seconds"
    with TrendStore(tmp_path / "monitor.sqlite") as store, pytest.raises(InputError) as error:
        process_recording(case.layout, path, store, "kp", window_seconds=1.0)
    # a keyphasor the file lacks is the case's field that names it (was the file's "channels")
    assert error.value.field == "monitor.identify.keyphasor" and "kp" in str(error.value)
