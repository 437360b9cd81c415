"""Recordings of proximity probes: CSV, Parquet, HDF5 and TDMS, read in chunks.

A recording holds one column (channel) per probe, and optionally a once-per-revolution
(keyphasor) channel, sampled at one rate. A monitoring run reads it in blocks of samples x
chosen channels, so that an hour of 32 channels at 10 kHz (1.15 G samples, 9 GB as float64)
goes through in bounded memory; each file is named by the SHA-256 of its bytes, so that
processing the same recording twice is recognised whatever the file is called.

Layouts read:

``.csv``
    A header row of channel names, one row per sample; an optional ``time`` (or ``time_s``)
    column (s) gives the sample rate.
``.parquet``
    One column per channel; the sample rate from a ``time`` column or the file's key-value
    metadata ``sample_rate`` (Hz).
``.h5``, ``.hdf5``
    One 1-D dataset per channel, named by its path in the file (``"probes/p315"``); the
    sample rate from a ``sample_rate`` (Hz) or ``dt`` (s) attribute of the dataset or of the
    file's root.
``.tdms``
    National Instruments TDMS (npTDMS, streamed): channels named ``"group/channel"``; the
    sample rate from each channel's ``wf_increment`` (s).

Every reader gives the channel names, the sample rate (or None when the file does not say),
the number of samples, and blocks of float64 samples.
"""

from __future__ import annotations

import hashlib
import math
from collections.abc import Iterator, Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Protocol

import numpy as np

from shaftline.errors import InputError

__all__ = [
    "READERS",
    "Recording",
    "content_hash",
    "open_recording",
]

#: Names of a CSV's column of sample times, s (``time_s``: the recordings ``monitor simulate`` writes).
TIME_COLUMNS = ("time", "time_s")
#: Bytes read at a time to hash a file.
_HASH_BLOCK = 8 << 20


class _Reader(Protocol):
    def channels(self) -> tuple[str, ...]: ...

    def sample_rate(self, columns: Sequence[str]) -> float | None: ...

    def length(self) -> int: ...

    def blocks(self, columns: Sequence[str], size: int, start: int) -> Iterator[np.ndarray]: ...


def content_hash(path: str | Path) -> str:
    """SHA-256 of a file's bytes, hexadecimal (read in 8 MiB blocks)."""
    digest = hashlib.sha256()
    with open(path, "rb") as file:
        while block := file.read(_HASH_BLOCK):
            digest.update(block)
    return digest.hexdigest()


def _rate_from_times(times: np.ndarray, where: str) -> float | None:
    """Sample rate from a column of sample times, s; checked for a uniform step."""
    if times.size < 2:
        return None
    steps = np.diff(times)
    step = float(np.median(steps))
    if not step > 0.0 or np.abs(steps - step).max() > 1e-3 * step:
        raise InputError(
            f"{where}.time", f"steps {steps.min():.6g}-{steps.max():.6g}", "s", "a uniform sample time step"
        )
    # the mean step over the whole span: times printed with a few digits make single steps
    # (and their median) off by the rounding, 2e-7 relative at 9 digits, which moves a window
    # of the hour's end by a second
    return float((times.size - 1) / (times[-1] - times[0]))


class _Csv:
    def __init__(self, path: Path) -> None:
        import pandas as pd

        self._path = path
        try:
            self._header = tuple(str(c) for c in pd.read_csv(path, nrows=0).columns)
        except pd.errors.EmptyDataError:
            raise InputError(
                "recording", "an empty file", "", "a CSV with a header row of channel names and one row per sample"
            ) from None
        self._length: int | None = None

    def channels(self) -> tuple[str, ...]:
        return tuple(c for c in self._header if c not in TIME_COLUMNS)

    def sample_rate(self, columns: Sequence[str]) -> float | None:
        import pandas as pd

        time = next((c for c in TIME_COLUMNS if c in self._header), None)
        if time is None:
            return None
        column = pd.read_csv(self._path, usecols=[time], nrows=1000)[time]
        head = pd.to_numeric(column, errors="coerce").to_numpy(float)
        if np.isnan(head).any():
            row = int(np.flatnonzero(np.isnan(head))[0]) + 2  # the file's line: header, then 1-based
            raise InputError(f"{self._path.name}: line {row}, {time}", str(column.iloc[row - 2]), "s", "a number")
        return _rate_from_times(head, self._path.name)

    def length(self) -> int:
        if self._length is None:
            with open(self._path, "rb") as file:
                lines = sum(block.count(b"\n") for block in iter(lambda: file.read(_HASH_BLOCK), b""))
            with open(self._path, "rb") as file:
                file.seek(-1, 2)
                ends_with_newline = file.read(1) == b"\n"
            self._length = lines - 1 + (0 if ends_with_newline else 1)
        return self._length

    def blocks(self, columns: Sequence[str], size: int, start: int) -> Iterator[np.ndarray]:
        import pandas as pd

        skip = range(1, start + 1) if start else None
        with pd.read_csv(self._path, usecols=list(columns), chunksize=size, skiprows=skip) as reader:
            for frame in reader:
                chosen = frame[list(columns)]
                if not all(kind.kind in "fiu" for kind in chosen.dtypes):
                    # a cell that is not a number (a logger's error text, a cut line) is an
                    # invalid sample like NaN, masked and counted against max_invalid_share
                    chosen = chosen.apply(pd.to_numeric, errors="coerce")
                yield chosen.to_numpy(dtype=float)


class _Parquet:
    def __init__(self, path: Path) -> None:
        import pyarrow.parquet as pq

        self._file = pq.ParquetFile(path)
        self._path = path

    def channels(self) -> tuple[str, ...]:
        return tuple(n for n in self._file.schema_arrow.names if n != "time")

    def sample_rate(self, columns: Sequence[str]) -> float | None:
        metadata = self._file.schema_arrow.metadata or {}
        if b"sample_rate" in metadata:
            return float(metadata[b"sample_rate"])
        if "time" in self._file.schema_arrow.names:
            batch = next(self._file.iter_batches(batch_size=1000, columns=["time"]))
            return _rate_from_times(batch.column(0).to_numpy(), self._path.name)
        return None

    def length(self) -> int:
        return int(self._file.metadata.num_rows)

    def blocks(self, columns: Sequence[str], size: int, start: int) -> Iterator[np.ndarray]:
        # Row groups are skipped whole; the rest of the first one is cut off here.
        row = 0
        pending: list[np.ndarray] = []
        held = 0
        for group in range(self._file.num_row_groups):
            rows = self._file.metadata.row_group(group).num_rows
            if row + rows <= start:
                row += rows
                continue
            for batch in self._file.iter_batches(batch_size=size, row_groups=[group], columns=list(columns)):
                block = np.column_stack([batch.column(i).to_numpy(zero_copy_only=False) for i in range(len(columns))])
                if row < start:
                    block = block[start - row :]
                row += batch.num_rows
                pending.append(block.astype(float, copy=False))
                held += block.shape[0]
                while held >= size:
                    joined = np.concatenate(pending)
                    yield joined[:size]
                    pending, held = [joined[size:]], joined.shape[0] - size
        if held:
            yield np.concatenate(pending)


class _Hdf5:
    def __init__(self, path: Path) -> None:
        import h5py

        self._file = h5py.File(path, "r")
        self._path = path
        names: list[str] = []
        self._file.visititems(lambda name, item: names.append(name) if isinstance(item, h5py.Dataset) else None)
        self._datasets = tuple(n for n in names if self._file[n].ndim == 1)

    def channels(self) -> tuple[str, ...]:
        return tuple(n for n in self._datasets if n.rsplit("/", 1)[-1] != "time")

    def _rate_of(self, name: str) -> float | None:
        for holder in (self._file[name], self._file):
            if "sample_rate" in holder.attrs:
                return float(holder.attrs["sample_rate"])
            if "dt" in holder.attrs:
                return 1.0 / float(holder.attrs["dt"])
        return None

    def sample_rate(self, columns: Sequence[str]) -> float | None:
        return _one_rate({c: self._rate_of(c) for c in columns}, self._path.name)

    def length(self) -> int:
        lengths = {int(self._file[c].shape[0]) for c in self.channels()}
        return min(lengths) if lengths else 0

    def blocks(self, columns: Sequence[str], size: int, start: int) -> Iterator[np.ndarray]:
        sizes = {c: int(self._file[c].shape[0]) for c in columns}
        if len(set(sizes.values())) > 1:
            raise InputError(
                "channels", ", ".join(f"{c}: {n}" for c, n in sizes.items()), "samples", "channels of one length"
            )
        total = min(sizes.values())
        for first in range(start, total, size):
            stop = min(first + size, total)
            yield np.column_stack([self._file[c][first:stop] for c in columns]).astype(float, copy=False)


class _Tdms:
    def __init__(self, path: Path) -> None:
        from nptdms import TdmsFile

        self._file = TdmsFile.open(path)
        self._path = path
        self._channels = {
            f"{group.name}/{channel.name}": channel for group in self._file.groups() for channel in group.channels()
        }

    def channels(self) -> tuple[str, ...]:
        return tuple(self._channels)

    def sample_rate(self, columns: Sequence[str]) -> float | None:
        rates: dict[str, float | None] = {}
        for c in columns:
            increment = self._channels[c].properties.get("wf_increment")
            rates[c] = 1.0 / float(increment) if increment else None
        return _one_rate(rates, self._path.name)

    def length(self) -> int:
        return min((len(c) for c in self._channels.values()), default=0)

    def blocks(self, columns: Sequence[str], size: int, start: int) -> Iterator[np.ndarray]:
        total = min(len(self._channels[c]) for c in columns)
        for first in range(start, total, size):
            stop = min(first + size, total)
            yield np.column_stack([self._channels[c][first:stop] for c in columns]).astype(float, copy=False)


def _one_rate(rates: dict[str, float | None], where: str) -> float | None:
    """The one sample rate of the chosen channels, or None when none states it."""
    known = {c: r for c, r in rates.items() if r is not None}
    if not known:
        return None
    values = list(known.values())
    if max(values) - min(values) > 1e-9 * max(values) or len(known) < len(rates):
        listed = ", ".join(f"{c}: {'?' if r is None else f'{r:g} Hz'}" for c, r in rates.items())
        raise InputError(f"{where} sample rates", listed, "Hz", "one sample rate for every chosen channel")
    return values[0]


#: Readers by file suffix.
READERS: dict[str, type] = {".csv": _Csv, ".parquet": _Parquet, ".h5": _Hdf5, ".hdf5": _Hdf5, ".tdms": _Tdms}


@dataclass
class Recording:
    """An open recording: its channels, sample rate, length and content hash.

    Attributes
    ----------
    path : Path
    channels : tuple of str
        Channel names in the file.
    samples : int
        Samples per channel.
    """

    path: Path
    channels: tuple[str, ...]
    samples: int
    _reader: Any
    _hash: str | None = field(default=None, repr=False, compare=False)

    def sample_rate(self, columns: Sequence[str], given: float | None = None) -> float:
        """The sample rate of ``columns``, Hz: the file's, or ``given`` where the file states
        none; both must agree where both exist."""
        self._check(columns)
        stated = self._reader.sample_rate(columns)
        if stated is None and given is None:
            raise InputError(
                "sample_rate", "none", "Hz", f"a sample rate: {self.path.name} does not state one; give it in the case"
            )
        if stated is not None and given is not None and abs(stated - given) > 1e-6 * given:
            raise InputError("sample_rate", f"{given:g}", "Hz", f"the file's own, {stated:g} Hz")
        return float(stated if stated is not None else given)  # type: ignore[arg-type]

    def content_hash(self) -> str:
        """SHA-256 of the file's bytes (read once per open recording: an hour of 32 channels is 9 GB)."""
        if self._hash is None:
            self._hash = content_hash(self.path)
        return self._hash

    def _check(self, columns: Sequence[str]) -> None:
        missing = [c for c in columns if c not in self.channels]
        if missing:
            shown = ", ".join(self.channels[:12]) + (" ..." if len(self.channels) > 12 else "")
            raise InputError("channels", ", ".join(missing), "", f"channels of {self.path.name}: {shown}")

    def blocks(self, columns: Sequence[str], size: int = 65_536, start: int = 0) -> Iterator[tuple[int, np.ndarray]]:
        """Blocks of ``size`` samples (the last one shorter) of ``columns``, from sample
        ``start``: pairs (index of the block's first sample, float64 array samples x columns)."""
        self._check(columns)
        if not isinstance(size, int) or size < 1:
            raise InputError("chunk_samples", size, "", "an integer >= 1")
        first = start
        for block in self._reader.blocks(columns, size, start):
            yield first, block
            first += block.shape[0]


def open_recording(path: str | Path) -> Recording:
    """Open a recording for reading in blocks (the format from the suffix, see module doc).

    Raises
    ------
    InputError
        ``"recording"`` for a missing file or an unknown suffix.
    """
    path = Path(path)
    if not path.is_file():
        raise InputError("recording", str(path), "", "an existing file")
    reader_type = READERS.get(path.suffix.lower())
    if reader_type is None:
        raise InputError("recording", path.name, "", f"a file ending in {', '.join(sorted(READERS))}")
    reader = reader_type(path)
    return Recording(path=path, channels=reader.channels(), samples=int(reader.length()), _reader=reader)


def block_count(samples: int, size: int) -> int:
    """Blocks of ``size`` samples in ``samples``."""
    return math.ceil(samples / size)
