"""Readers of probe recordings (CSV, Parquet, HDF5, TDMS): the same samples in any format,
in blocks of any size from any start, and the faults a user meets (issue 13)."""

from __future__ import annotations

import numpy as np
import pytest

from shaftline.errors import InputError
from shaftline.monitor.recordings import content_hash, open_recording

RATE = 2000.0
SAMPLES = 1000
NAMES = ("p315", "p45", "p180", "kp")


def _data() -> np.ndarray:
    rng = np.random.default_rng(7)
    return rng.normal(size=(SAMPLES, len(NAMES)))


def _write(path, data: np.ndarray) -> None:
    suffix = path.suffix
    if suffix == ".csv":
        import pandas as pd

        frame = pd.DataFrame(data, columns=list(NAMES))
        frame.insert(0, "time", np.arange(SAMPLES) / RATE)
        # repr-exact floats so the CSV round trip is exact
        frame.to_csv(path, index=False, float_format="%.17g")
    elif suffix == ".parquet":
        import pyarrow as pa
        import pyarrow.parquet as pq

        table = pa.table({n: data[:, k] for k, n in enumerate(NAMES)})
        table = table.replace_schema_metadata({"sample_rate": str(RATE)})
        pq.write_table(table, path, row_group_size=300)
    elif suffix == ".h5":
        import h5py

        with h5py.File(path, "w") as file:
            file.attrs["sample_rate"] = RATE
            for k, n in enumerate(NAMES):
                file.create_dataset(f"probes/{n}", data=data[:, k])
    elif suffix == ".tdms":
        from nptdms import ChannelObject, TdmsWriter

        with TdmsWriter(path) as writer:
            writer.write_segment(
                [
                    ChannelObject("probes", n, data[:, k], properties={"wf_increment": 1.0 / RATE})
                    for k, n in enumerate(NAMES)
                ]
            )


def _columns(suffix: str) -> list[str]:
    prefix = "probes/" if suffix in (".h5", ".tdms") else ""
    return [prefix + n for n in NAMES[:3]]


@pytest.mark.parametrize("suffix", [".csv", ".parquet", ".h5", ".tdms"])
@pytest.mark.parametrize("size, start", [(1000, 0), (128, 0), (77, 450)])
def test_every_format_gives_the_same_samples_in_blocks(tmp_path, suffix, size, start):
    data = _data()
    path = tmp_path / f"rec{suffix}"
    _write(path, data)
    recording = open_recording(path)
    columns = _columns(suffix)
    assert recording.samples == SAMPLES
    assert recording.sample_rate(columns) == pytest.approx(RATE, rel=1e-9)
    firsts, blocks = zip(*recording.blocks(columns, size=size, start=start), strict=True)
    assert all(b.shape[0] == size for b in blocks[:-1]) and 0 < blocks[-1].shape[0] <= size
    assert list(firsts) == list(range(start, SAMPLES, size))
    np.testing.assert_array_equal(np.concatenate(blocks), data[start:, :3])


def test_the_content_hash_names_the_bytes_not_the_file(tmp_path):
    data = _data()
    _write(tmp_path / "a.parquet", data)
    (tmp_path / "b.parquet").write_bytes((tmp_path / "a.parquet").read_bytes())
    _write(tmp_path / "c.parquet", data[::-1].copy())
    assert content_hash(tmp_path / "a.parquet") == content_hash(tmp_path / "b.parquet")
    assert content_hash(tmp_path / "a.parquet") != content_hash(tmp_path / "c.parquet")


def test_a_missing_channel_is_named_with_the_channels_there(tmp_path):
    _write(tmp_path / "rec.csv", _data())
    with pytest.raises(InputError) as error:
        list(open_recording(tmp_path / "rec.csv").blocks(["p315", "p90"]))
    assert error.value.field == "channels" and "p90" in str(error.value) and "p45" in str(error.value)


def test_channels_at_different_rates_are_refused(tmp_path):
    from nptdms import ChannelObject, TdmsWriter

    path = tmp_path / "rec.tdms"
    with TdmsWriter(path) as writer:
        writer.write_segment(
            [
                ChannelObject("probes", "a", np.zeros(10), properties={"wf_increment": 1e-3}),
                ChannelObject("probes", "b", np.zeros(10), properties={"wf_increment": 5e-4}),
            ]
        )
    with pytest.raises(InputError, match="one sample rate"):
        open_recording(path).sample_rate(["probes/a", "probes/b"])


def test_a_rate_given_must_agree_with_the_file_and_is_needed_without_one(tmp_path):
    data = _data()
    _write(tmp_path / "rec.parquet", data)
    recording = open_recording(tmp_path / "rec.parquet")
    with pytest.raises(InputError) as error:
        recording.sample_rate(["p315"], given=1000.0)
    assert error.value.field == "sample_rate" and "2000" in str(error.value)
    import pandas as pd

    pd.DataFrame(data, columns=list(NAMES)).to_csv(tmp_path / "bare.csv", index=False)
    bare = open_recording(tmp_path / "bare.csv")
    with pytest.raises(InputError, match="does not state one"):
        bare.sample_rate(["p315"])
    assert bare.sample_rate(["p315"], given=500.0) == 500.0


def test_unknown_or_missing_files_are_one_line_errors(tmp_path):
    (tmp_path / "rec.wav").write_bytes(b"RIFF")
    with pytest.raises(InputError, match=r"\.tdms"):
        open_recording(tmp_path / "rec.wav")
    with pytest.raises(InputError, match="existing file"):
        open_recording(tmp_path / "none.csv")


def test_csv_sample_rate_from_times_printed_with_nine_digits(tmp_path):
    """`monitor simulate` writes times with 9 significant digits. From 10 s on a time is rounded to
    1e-7 s, so single steps at 2048 Hz (0.488 ms) are 0.4882 or 0.4883 ms and their median is off by up
    to 1e-4 relative (the example's files, from 0 s, were off by 2e-7: a window at 2 s a microsecond
    early, shown as the second before). The mean step over the span read (1000 samples, 0.49 s) is off
    by 1e-7 s / 0.49 s = 2e-7 relative at most."""
    path = tmp_path / "r.csv"
    times = 10.0 + np.arange(2000) / 2048.0  # a file that starts late makes the rounding coarse
    np.savetxt(path, np.column_stack([times, np.ones_like(times)]), delimiter=",", header="time,p315",
               comments="", fmt="%.9g")  # fmt: skip
    rate = open_recording(path).sample_rate(["p315"])
    assert rate == pytest.approx(2048.0, rel=3e-7)


def test_empty_csv_and_text_cells(tmp_path):
    """The faults of a logger's CSV: an empty file and a text time are one-line errors (they were
    pandas tracebacks, exit 1); a text cell in a probe column is an invalid sample (NaN), which
    the window's max_invalid_share check counts like a dropout."""
    empty = tmp_path / "empty.csv"
    empty.write_text("")
    with pytest.raises(InputError, match="empty file"):
        open_recording(empty)
    data = _data()
    path = tmp_path / "r.csv"
    _write(path, data)
    lines = path.read_text().splitlines()
    cells = lines[11].split(",")
    cells[1] = "ERR"  # p315 of sample 10 (column 0 is the time)
    lines[11] = ",".join(cells)
    path.write_text("\n".join(lines) + "\n")
    recording = open_recording(path)
    (block,) = [b for _, b in recording.blocks(list(NAMES), size=SAMPLES)]
    assert np.isnan(block[10, 0]) and np.isnan(block).sum() == 1
    np.testing.assert_array_equal(np.delete(block, 10, axis=0), np.delete(data, 10, axis=0))
    cells = lines[21].split(",")
    cells[0] = "t?"
    lines[21] = ",".join(cells)
    path.write_text("\n".join(lines) + "\n")
    with pytest.raises(InputError, match=r"r\.csv: line 22, time = 't\?'"):
        open_recording(path).sample_rate(list(NAMES))
