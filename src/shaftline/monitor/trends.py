"""Trends of processed windows in a database (SQLite by default, PostgreSQL by URL).

Each window of a recording gives a handful of numbers per measurement section (smallest film,
eccentricity, attitude, regime lengths, orbit descriptors). They are kept in three tables
through SQLAlchemy, so one file-based SQLite database serves a laptop and a PostgreSQL server
a fleet, by changing the URL only:

``recordings``
    One row per recording, identified by the SHA-256 of its bytes (processing the same file
    again, under any name, adds nothing), with its name, samples, sample rate, start time
    and whether every window of it is stored.
``windows``
    One row per processed window: recording, window number, time of its first sample, speed.
``window_values``
    One row per (window, section, quantity): the value in SI units.
``recording_settings``
    One row per recording: the processing settings its windows were identified with (layout,
    window, runout source...), as JSON, and their SHA-256; a recording is skipped as stored only
    when they are the same (added to a database made before it).

Each window is written in its own transaction, with all its values, so a run stopped at any
point leaves whole windows only; a new run on the same recording skips the windows already
there and carries on (:meth:`TrendStore.windows_done`).

Alarms are computed from the stored series: a film parameter below a threshold for longer than
a set time, and a fitted trend of the smallest film crossing a limit, with the projected date.
"""

from __future__ import annotations

import datetime as dt
import math
from collections.abc import Iterable, Mapping
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np

from shaftline.errors import InputError

__all__ = [
    "MIN_TREND_SPAN",
    "DEFAULT_DATABASE",
    "CentreLine",
    "LambdaAlarm",
    "SectionTrend",
    "TrendCrossing",
    "TrendStore",
    "centre_lines",
    "lambda_alarms",
    "section_trends",
    "trend_crossing",
]

#: Shortest span of windows over which a film trend is fitted and projected: over seconds or
#: hours a straight line through the smallest film follows the operating point (speed, load,
#: temperature), not wear, and its projected date means nothing.
MIN_TREND_SPAN = dt.timedelta(days=1)

#: The database a run uses without ``--db``: a SQLite file in the output folder.
DEFAULT_DATABASE = "monitor.sqlite"


def _tables() -> Any:
    import sqlalchemy as sa

    metadata = sa.MetaData()
    sa.Table(
        "recordings",
        metadata,
        sa.Column("id", sa.Integer, primary_key=True),
        sa.Column("content_hash", sa.String(64), nullable=False, unique=True),
        sa.Column("name", sa.String(512), nullable=False),
        sa.Column("samples", sa.BigInteger, nullable=False),
        sa.Column("sample_rate", sa.Float, nullable=False),
        sa.Column("started_at", sa.DateTime(timezone=True), nullable=False),
        sa.Column("complete", sa.Boolean, nullable=False, default=False),
    )
    sa.Table(
        "windows",
        metadata,
        sa.Column("id", sa.Integer, primary_key=True),
        sa.Column("recording_id", sa.Integer, sa.ForeignKey("recordings.id", ondelete="CASCADE"), nullable=False),
        sa.Column("window", sa.Integer, nullable=False),
        sa.Column("time", sa.DateTime(timezone=True), nullable=False),
        sa.Column("speed", sa.Float, nullable=True),
        sa.UniqueConstraint("recording_id", "window"),
    )
    sa.Table(
        "window_values",
        metadata,
        sa.Column("window_id", sa.Integer, sa.ForeignKey("windows.id", ondelete="CASCADE"), primary_key=True),
        sa.Column("section", sa.String(128), primary_key=True),
        sa.Column("quantity", sa.String(128), primary_key=True),
        sa.Column("value", sa.Float, nullable=True),
    )
    sa.Table(
        "recording_settings",
        metadata,
        sa.Column("recording_id", sa.Integer, sa.ForeignKey("recordings.id", ondelete="CASCADE"), primary_key=True),
        sa.Column("fingerprint", sa.String(64), nullable=False),
        sa.Column("settings", sa.Text, nullable=False),
    )
    return metadata


#: The tables a trend database holds from its first version on (``recording_settings`` came later
#: and is added to a database without it).
CORE_TABLES = frozenset({"recordings", "windows", "window_values"})


@dataclass(frozen=True)
class StoredRecording:
    """A recording's row: its id, whether every window of it is stored, and its length (s)."""

    id: int
    content_hash: str
    name: str
    started_at: dt.datetime
    complete: bool
    duration: float = math.nan


def _stored(row: Any) -> StoredRecording:
    duration = row.samples / row.sample_rate if row.sample_rate else math.nan
    return StoredRecording(
        row.id, row.content_hash, row.name, _aware(row.started_at), bool(row.complete), float(duration)
    )


class TrendStore:
    """The trend database of a monitoring installation.

    Parameters
    ----------
    url : str or Path
        A SQLAlchemy URL (``sqlite:///path/monitor.sqlite``,
        ``postgresql+psycopg://user:password@host:5432/name``), or the path of a SQLite file.

    Raises
    ------
    InputError
        ``"db"`` when the database cannot be reached (with the driver's reason, one line).
    """

    def __init__(self, url: str | Path) -> None:
        import sqlalchemy as sa

        text = self.url_of(url)
        self.url = text
        file = self.file_of(text)
        if file is not None and not file.parent.is_dir():
            # SQLite's own message ("unable to open database file") does not say why
            folder = file.parent
            raise InputError("db", _hide_password(text), "", f"a database file in an existing folder (no {folder})")
        try:
            self._engine = sa.create_engine(text, future=True)
            self._metadata = _tables()
            if file is None or file.is_file():  # (inspecting a new file would make it empty first)
                # before create_all: a foreign table of one of our names is refused with nothing written
                tables = self._refuse_other_columns(_hide_password(text))
                if file is not None:
                    self._refuse_foreign(file, tables)
            self._metadata.create_all(self._engine)
        except InputError:
            self._engine.dispose()
            raise
        except (ModuleNotFoundError, sa.exc.NoSuchModuleError, sa.exc.ArgumentError) as error:
            # a dialect or driver this installation does not have (e.g. mysql://): say which it has
            reason = str(error).strip().splitlines()[0]
            raise InputError(
                "db",
                _hide_password(text),
                "",
                f"a SQLite file or sqlite:/// URL, or a postgresql+psycopg:// URL ({reason})",
            ) from None
        except Exception as error:  # the drivers raise their own kinds; the user needs one line
            reason = str(getattr(error, "orig", None) or error).strip().splitlines()[0]
            raise InputError("db", _hide_password(text), "", f"a database that can be reached ({reason})") from None
        self._recordings = self._metadata.tables["recordings"]
        self._windows = self._metadata.tables["windows"]
        self._values = self._metadata.tables["window_values"]

    def _refuse_other_columns(self, shown: str) -> set[str]:
        """The database's tables; an InputError when one of them has the name of one of ours but
        other columns (another application's ``recordings`` on a shared server, say): inserting
        into it would fail half-way with the driver's error, or write into that application's
        table. Checked before anything is created, so nothing is written."""
        import sqlalchemy as sa

        inspector = sa.inspect(self._engine)
        tables = set(inspector.get_table_names())
        for table in self._metadata.sorted_tables:
            if table.name not in tables:
                continue
            have = [column["name"] for column in inspector.get_columns(table.name)]
            need = [column.name for column in table.columns]
            if set(have) != set(need):
                raise InputError(
                    "db",
                    shown,
                    "",
                    f"a database whose table {table.name} is the trend store's, with the columns {', '.join(need)} "
                    f"(this one's has {', '.join(have) or 'none'}: another application's table; use another database)",
                )
        return tables

    def _refuse_foreign(self, file: Path, tables: set[str]) -> None:
        """A SQLite file holding tables but not those of a trend database is another program's:
        adding ours to it would change a file this program did not make (a server's database
        may hold other applications' tables beside ours, and is not checked)."""
        ours = set(self._metadata.tables)
        if tables and not CORE_TABLES <= tables:
            others = sorted(tables - ours) or sorted(tables)
            raise InputError(
                "db",
                str(file),
                "",
                f"a trend database made by monitor identify, or a new file (this one holds the tables "
                f"{', '.join(others[:5])})",
            )

    @staticmethod
    def url_of(url: str | Path) -> str:
        """The SQLAlchemy URL of ``url``: itself, or a SQLite URL for a file path."""
        text = str(url)
        return text if "://" in text else f"sqlite:///{Path(text).resolve()}"

    @staticmethod
    def file_of(url: str | Path) -> Path | None:
        """The file of a SQLite database (a path or a ``sqlite:///`` URL), None for a server
        or an in-memory database: the file no output of a run may replace."""
        text = TrendStore.url_of(url)
        if not text.startswith("sqlite") or "://" not in text:
            return None
        name = text.split("://", 1)[1].removeprefix("/").split("?", 1)[0]
        return None if name in ("", ":memory:") else Path(name).resolve()

    def close(self) -> None:
        """Release the connection pool."""
        self._engine.dispose()

    def __enter__(self) -> TrendStore:
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()

    # -- recordings --------------------------------------------------------------------
    def recording(
        self, content_hash: str, name: str, samples: int, sample_rate: float, started_at: dt.datetime
    ) -> StoredRecording:
        """The row of a recording, added if it is new (an existing one is returned as it is,
        so a recording processed before, under any name, is recognised)."""
        import sqlalchemy as sa

        with self._engine.begin() as connection:
            row = connection.execute(
                sa.select(self._recordings).where(self._recordings.c.content_hash == content_hash)
            ).first()
            if row is None:
                connection.execute(
                    self._recordings.insert().values(
                        content_hash=content_hash,
                        name=name,
                        samples=int(samples),
                        sample_rate=float(sample_rate),
                        started_at=_aware(started_at),
                        complete=False,
                    )
                )
                row = connection.execute(
                    sa.select(self._recordings).where(self._recordings.c.content_hash == content_hash)
                ).first()
        assert row is not None
        return _stored(row)

    def find(self, content_hash: str) -> StoredRecording | None:
        """The row of the recording of these bytes, None when it is not stored."""
        import sqlalchemy as sa

        with self._engine.connect() as connection:
            row = connection.execute(
                sa.select(self._recordings).where(self._recordings.c.content_hash == content_hash)
            ).first()
        if row is None:
            return None
        return _stored(row)

    def settings(self, recording: StoredRecording) -> dict[str, Any] | None:
        """The processing settings ``recording``'s windows were stored with (None: none recorded,
        a recording stored before settings were kept, or one with no window yet)."""
        import json

        import sqlalchemy as sa

        table = self._metadata.tables["recording_settings"]
        with self._engine.connect() as connection:
            row = connection.execute(sa.select(table.c.settings).where(table.c.recording_id == recording.id)).first()
        return None if row is None else dict(json.loads(row.settings))

    def keep_settings(self, recording: StoredRecording, settings: Mapping[str, Any], replace: bool = False) -> None:
        """Record the processing settings of ``recording``'s windows; with ``replace``, first delete
        its windows and their values (its row stays; no other recording is touched), in the same
        transaction, so that it is identified again with these settings."""
        import hashlib
        import json

        import sqlalchemy as sa

        table = self._metadata.tables["recording_settings"]
        text = json.dumps(dict(settings), sort_keys=True)
        fingerprint = hashlib.sha256(text.encode()).hexdigest()
        with self._engine.begin() as connection:
            if replace:
                ids = sa.select(self._windows.c.id).where(self._windows.c.recording_id == recording.id)
                connection.execute(self._values.delete().where(self._values.c.window_id.in_(ids)))
                connection.execute(self._windows.delete().where(self._windows.c.recording_id == recording.id))
                connection.execute(
                    self._recordings.update().where(self._recordings.c.id == recording.id).values(complete=False)
                )
            connection.execute(table.delete().where(table.c.recording_id == recording.id))
            connection.execute(table.insert().values(recording_id=recording.id, fingerprint=fingerprint, settings=text))

    def windows_done(self, recording: StoredRecording) -> set[int]:
        """Numbers of the windows of ``recording`` already stored."""
        import sqlalchemy as sa

        with self._engine.connect() as connection:
            rows = connection.execute(
                sa.select(self._windows.c.window).where(self._windows.c.recording_id == recording.id)
            )
            return {int(r.window) for r in rows}

    def add_window(
        self,
        recording: StoredRecording,
        window: int,
        time: dt.datetime,
        values: Mapping[tuple[str, str], float],
        speed: float | None = None,
    ) -> bool:
        """Store one window and its values in one transaction; False (nothing written) when
        that window of that recording is already stored."""
        import sqlalchemy as sa

        with self._engine.begin() as connection:
            exists = connection.execute(
                sa.select(self._windows.c.id).where(
                    (self._windows.c.recording_id == recording.id) & (self._windows.c.window == int(window))
                )
            ).first()
            if exists is not None:
                return False
            result = connection.execute(
                self._windows.insert().values(
                    recording_id=recording.id,
                    window=int(window),
                    time=_aware(time),
                    speed=None if speed is None else float(speed),
                )
            )
            key = result.inserted_primary_key
            assert key is not None
            window_id = key[0]
            rows = [
                {"window_id": window_id, "section": s, "quantity": q, "value": _finite_or_none(v)}
                for (s, q), v in values.items()
            ]
            if rows:
                connection.execute(self._values.insert(), rows)
        return True

    def mark_complete(self, recording: StoredRecording) -> None:
        """Record that every window of ``recording`` is stored."""
        with self._engine.begin() as connection:
            connection.execute(
                self._recordings.update().where(self._recordings.c.id == recording.id).values(complete=True)
            )

    def recordings(self) -> list[StoredRecording]:
        """Every recording, oldest first."""
        import sqlalchemy as sa

        with self._engine.connect() as connection:
            rows = connection.execute(sa.select(self._recordings).order_by(self._recordings.c.started_at))
            return [_stored(r) for r in rows]

    # -- series ------------------------------------------------------------------------
    def series(self, quantity: str, section: str | None = None, recording: StoredRecording | None = None) -> Any:
        """A quantity over time as a pandas DataFrame (``time``, ``recording``, ``recording_id``,
        ``window``, ``section``, ``speed``, ``value``), oldest first; one section or all, of one
        recording or all. ``recording`` is the recording's file name, for people; ``recording_id``
        its stored identity (one per content hash), which tells apart two recordings of one name
        (files of one name in two folders)."""
        import pandas as pd
        import sqlalchemy as sa

        w, v, r = self._windows, self._values, self._recordings
        query = (
            sa.select(
                w.c.time,
                r.c.name.label("recording"),
                w.c.recording_id,
                w.c.window,
                v.c.section,
                w.c.speed,
                v.c.value,
            )
            .join(v, v.c.window_id == w.c.id)
            .join(r, r.c.id == w.c.recording_id)
            .where(v.c.quantity == quantity)
            .order_by(w.c.time, v.c.section)
        )
        if section is not None:
            query = query.where(v.c.section == section)
        if recording is not None:
            query = query.where(w.c.recording_id == recording.id)
        with self._engine.connect() as connection:
            frame = pd.DataFrame(connection.execute(query).mappings().all())
        if frame.empty:
            return pd.DataFrame(columns=["time", "recording", "recording_id", "window", "section", "speed", "value"])
        frame["time"] = pd.to_datetime(frame["time"], utc=True)
        return frame

    def quantities(self) -> list[tuple[str, str]]:
        """Every (section, quantity) stored."""
        import sqlalchemy as sa

        with self._engine.connect() as connection:
            rows = connection.execute(
                sa.select(self._values.c.section, self._values.c.quantity)
                .distinct()
                .order_by(self._values.c.section, self._values.c.quantity)
            )
            return [(r.section, r.quantity) for r in rows]


@dataclass(frozen=True)
class LambdaAlarm:
    """A stretch of time with the film parameter below its threshold.

    Attributes
    ----------
    section : str
    start, end : datetime
        First and last window below the threshold.
    lowest : float
        Smallest film parameter in the stretch.
    """

    section: str
    start: dt.datetime
    end: dt.datetime
    lowest: float

    @property
    def duration(self) -> dt.timedelta:
        return self.end - self.start


def lambda_alarms(
    times: Iterable[dt.datetime],
    values: Iterable[float],
    threshold: float = 1.0,
    min_duration: dt.timedelta = dt.timedelta(minutes=10),
    section: str = "",
) -> list[LambdaAlarm]:
    """Stretches of consecutive windows with ``values`` (a film parameter, lambda) below
    ``threshold`` lasting at least ``min_duration`` (from the first to the last window
    below). A missing value (NaN) ends a stretch."""
    stamps = list(times)
    series = np.asarray(list(values), dtype=float)
    if series.size != len(stamps):
        raise ValueError("times and values differ in length")
    below = series < threshold
    alarms: list[LambdaAlarm] = []
    start = None
    for k in range(series.size + 1):
        if k < series.size and below[k]:
            if start is None:
                start = k
            continue
        if start is not None:
            stop = k - 1
            if stamps[stop] - stamps[start] >= min_duration:
                alarms.append(LambdaAlarm(section, stamps[start], stamps[stop], float(series[start : stop + 1].min())))
            start = None
    return alarms


@dataclass(frozen=True)
class TrendCrossing:
    """A linear trend of a quantity and where it crosses a limit.

    Attributes
    ----------
    slope : float
        Change per day (the quantity's unit per day).
    value_now : float
        The trend's value at the last sample.
    crossing : datetime or None
        When the trend reaches the limit: None when it moves away from it (or is flat), the
        last sample's time when it is already past it.
    """

    slope: float
    value_now: float
    crossing: dt.datetime | None


def trend_crossing(times: Iterable[dt.datetime], values: Iterable[float], limit: float) -> TrendCrossing:
    """Least-squares straight line through ``values`` against time and the date it reaches
    ``limit`` coming down (a smallest film falling towards its limit).

    Raises
    ------
    ValueError
        Fewer than two finite samples, or all at one time.
    """
    stamps = list(times)
    series = np.asarray(list(values), dtype=float)
    keep = np.isfinite(series)
    if keep.sum() < 2:
        raise ValueError("a trend needs two finite samples or more")
    origin = stamps[0]
    days = np.array([(t - origin).total_seconds() / 86400.0 for t in stamps])[keep]
    if np.ptp(days) == 0.0:
        raise ValueError("a trend needs samples at two times or more")
    slope, intercept = np.polyfit(days, series[keep], 1)
    last = float(days.max())
    now = float(slope * last + intercept)
    if now <= limit:
        crossing: dt.datetime | None = origin + dt.timedelta(days=last)
    elif slope < 0.0:
        crossing = origin + dt.timedelta(days=(limit - intercept) / slope)
    else:
        crossing = None
    return TrendCrossing(float(slope), now, crossing)


@dataclass(frozen=True, eq=False)
class SectionTrend:
    """The smallest film of one section (or ``"bearing"``: the smallest along it) over time.

    Attributes
    ----------
    section : str
    times : list of datetime
        Window times, oldest first.
    min_film : ndarray
        Time-mean smallest film of each window, m (NaN where not stored).
    film_parameter : ndarray
        Film parameter lambda of each window.
    speed : ndarray
        Shaft speed of each window, rad/s.
    alarms : tuple of LambdaAlarm
        Stretches with lambda below the threshold for at least the set time.
    limit : float
        Film the trend is projected to, m.
    crossing : TrendCrossing or None
        Fitted straight line and the date it reaches ``limit`` (None: fewer than two finite
        samples, or windows spanning less than :data:`MIN_TREND_SPAN`).
    """

    section: str
    times: list[dt.datetime]
    min_film: np.ndarray
    film_parameter: np.ndarray
    speed: np.ndarray
    alarms: tuple[LambdaAlarm, ...]
    limit: float
    crossing: TrendCrossing | None


def section_trends(
    store: TrendStore,
    threshold: float = 1.0,
    min_duration: dt.timedelta = dt.timedelta(minutes=10),
    limit: float | None = None,
    recording: StoredRecording | None = None,
) -> tuple[SectionTrend, ...]:
    """Trend of the smallest film of every stored section, with its lambda alarms and the
    projected date its fitted straight line reaches ``limit``.

    Parameters
    ----------
    store : TrendStore
    threshold : float
        Film parameter of an alarm (lambda < threshold).
    min_duration : timedelta
        Shortest alarm stretch.
    limit : float, optional
        Film limit, m; without it, the film at which lambda equals ``threshold``:
        ``threshold * sigma``, the composite roughness ``sigma = h_min / lambda`` read from the
        stored pairs (the same for every window of one installation).
    recording : StoredRecording, optional
        One recording only (default: all, oldest first).
    """
    import pandas as pd

    films = store.series("min_film_thickness", recording=recording)
    ratios = store.series("film_parameter", recording=recording)
    if films.empty:
        return ()
    # windows stored as rejected (processing.REJECTED): no film, and each ends a lambda stretch
    flags = store.series("rejected", "bearing", recording=recording)
    flags = flags[flags["value"].fillna(0.0) != 0.0]
    gaps = [t.to_pydatetime() for t in flags["time"]]
    # recordings by their stored identity, not their names: two files of one name (two folders)
    # are two recordings, each with its own window length
    gap_ids = [int(i) for i in flags["recording_id"]]
    windows = pd.concat([films, flags]) if not flags.empty else films
    lengths = _window_lengths(windows, {r.id: r.duration for r in store.recordings()})
    key = ["time", "window", "recording_id", "section"]
    joined = films.merge(ratios[[*key, "value"]], on=key, how="left", suffixes=("", "_lambda"))
    if limit is None:
        sigma = (joined["value"] / joined["value_lambda"]).replace([np.inf, -np.inf], np.nan).median()
        limit = float(threshold * sigma) if math.isfinite(sigma) else math.nan
    trends = []
    sections = list(dict.fromkeys(joined["section"]))
    for section in sorted(sections, key=lambda name: (name == "bearing", sections.index(name))):
        rows = joined[joined["section"] == section]
        times = [t.to_pydatetime() for t in rows["time"]]
        film = rows["value"].to_numpy(float)
        parameter = rows["value_lambda"].to_numpy(float)
        # a rejected window, or time not recorded, ends a stretch: lambda is not known to stay below
        # the threshold over it, so the alarm's duration is not carried across it
        stamps, values = _with_breaks(
            times + gaps,
            np.concatenate([parameter, np.full(len(gaps), math.nan)]),
            [int(i) for i in rows["recording_id"]] + gap_ids,
            lengths,
        )
        alarms = lambda_alarms(stamps, values, threshold, min_duration, section)
        crossing = None
        long_enough = bool(times) and max(times) - min(times) >= MIN_TREND_SPAN
        if math.isfinite(limit) and np.isfinite(film).sum() >= 2 and long_enough:
            crossing = trend_crossing(times, film, limit)
        trends.append(
            SectionTrend(section, times, film, parameter, rows["speed"].to_numpy(float), tuple(alarms), limit, crossing)
        )
    return tuple(trends)


def _window_lengths(frame: Any, durations: Mapping[int, float]) -> dict[int, float]:
    """Length of a window of each recording (by its stored id), s: the time from one window to the
    next of the stored ones (a recording's windows are back to back), or the recording's length
    when it has one window only."""
    import pandas as pd

    lengths: dict[int, float] = {}
    for identity, rows in frame.drop_duplicates(["recording_id", "window"]).groupby("recording_id"):
        number = rows["window"].to_numpy(float)
        stamps = pd.to_datetime(rows["time"], utc=True)
        seconds = (stamps - stamps.min()).dt.total_seconds().to_numpy(float)
        order = np.argsort(number)
        steps, spans = np.diff(number[order]), np.diff(seconds[order])
        each = spans[steps > 0] / steps[steps > 0]
        number_id = int(identity)
        lengths[number_id] = float(np.median(each)) if each.size else float(durations.get(number_id, math.nan))
    return lengths


#: Unrecorded time between two windows, in windows, beyond which a lambda stretch ends (back-to-back
#: files lose less than half a window at each file's end: the windows cut from them).
MAX_GAP_WINDOWS = 0.5


def _with_breaks(
    times: list[dt.datetime], values: np.ndarray, recordings: list[int], lengths: Mapping[int, float]
) -> tuple[list[dt.datetime], np.ndarray]:
    """The series in time order with a missing value (NaN, which ends a lambda stretch) wherever
    the next window starts more than :data:`MAX_GAP_WINDOWS` of a window after the end of the
    one before: time between two recordings, or windows of one not stored."""
    order = sorted(range(len(times)), key=lambda k: times[k])
    stamps: list[dt.datetime] = []
    out: list[float] = []
    for position, k in enumerate(order):
        if position:
            before = order[position - 1]
            window = lengths.get(recordings[before], math.nan)
            unrecorded = (times[k] - times[before]).total_seconds() - window
            if math.isfinite(window) and unrecorded > MAX_GAP_WINDOWS * window:
                stamps.append(times[before])
                out.append(math.nan)
        stamps.append(times[k])
        out.append(float(values[k]))
    return stamps, np.asarray(out)


@dataclass(frozen=True)
class CentreLine:
    """Averaged shaft centre line of one section from the stored windows: mean eccentricity
    ratio and attitude angle in speed bins.

    Attributes
    ----------
    section : str
    speed : ndarray
        Bin speeds (mean of the windows in each bin), rad/s, rising.
    eccentricity_ratio, attitude_angle : ndarray
        Mean e/(c + k) and circular-mean attitude angle (rad, from the bottom in the direction
        of rotation) of the windows in each bin.
    windows : ndarray of int
        Windows in each bin.
    """

    section: str
    speed: np.ndarray
    eccentricity_ratio: np.ndarray
    attitude_angle: np.ndarray
    windows: np.ndarray


def centre_lines(
    store: TrendStore, bin_width: float = 5 * math.pi / 30, recording: StoredRecording | None = None
) -> tuple[CentreLine, ...]:
    """The averaged shaft centre line of every section: windows grouped in speed bins of
    ``bin_width`` (rad/s; default 5 rpm), the eccentricity vector averaged in each."""
    ratio = store.series("eccentricity_ratio", recording=recording)
    attitude = store.series("attitude_angle", recording=recording)
    if ratio.empty or attitude.empty:
        return ()
    key = ["time", "window", "recording_id", "section"]
    joined = ratio.merge(attitude[[*key, "value"]], on=key, suffixes=("", "_attitude")).dropna(
        subset=["speed", "value", "value_attitude"]
    )
    lines = []
    for section in dict.fromkeys(joined["section"]):
        rows = joined[joined["section"] == section]
        bins = np.round(rows["speed"].to_numpy(float) / bin_width).astype(int)
        vector = rows["value"].to_numpy(float) * np.exp(1j * rows["value_attitude"].to_numpy(float))
        keys, inverse, counts = np.unique(bins, return_inverse=True, return_counts=True)
        speed = np.bincount(inverse, rows["speed"].to_numpy(float)) / counts
        mean = (np.bincount(inverse, vector.real) + 1j * np.bincount(inverse, vector.imag)) / counts
        lines.append(CentreLine(section, speed, np.abs(mean), np.angle(mean), counts))
    return tuple(lines)


def _aware(moment: dt.datetime) -> dt.datetime:
    """A time with a time zone (UTC where it had none: SQLite keeps none)."""
    return moment if moment.tzinfo is not None else moment.replace(tzinfo=dt.UTC)


def _finite_or_none(value: float) -> float | None:
    value = float(value)
    return value if math.isfinite(value) else None


def _hide_password(url: str) -> str:
    """A URL as it may be shown: the password replaced by ***."""
    try:
        from sqlalchemy.engine import make_url

        return make_url(url).render_as_string(hide_password=True)
    except Exception:
        return url
