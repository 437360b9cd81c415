"""Speed of the film monitor (issue 13): the per-sample part, and a long recording end to end.

Run ``PYTHONPATH=src .venv/bin/python benchmarks/bench_monitor.py [--minutes 60] [--only per-sample|end-to-end]
[--format hdf5|tdms|both] [--via verb|function] [--model-shape]``.

**Per-sample part.** For seed 001's layout (3 sections
x 3 probes, 9 channels) and a 32-channel one (8 sections x 4 probes, the issue's recording), times
:func:`shaftline.monitor.identification.probe_films` on a block of one million time samples (orbit of
every section and the film at its probe angles, exact circle geometry, two correction passes), prints
the median of five calls as time samples per second and channel samples per second (the issue's
target: >= 5 million samples per second per core; the compiled kernel runs on one core), and, pair by
pair in the same process, the same arithmetic written with numpy arrays (the first implementation) and
the ratio. Three rounds.

**End to end** (the issue's 1-hour, 32-channel, 10 kHz recording, 1.15 G samples). A synthetic
recording of the 32-channel layout (a 1X whirl of 5 um about an offset centre at 120 rpm, 0.05 um
noise, a keyphasor channel) is written in 10 s chunks to a temporary folder as HDF5 (float32,
chunked datasets, sample rate as an attribute; 4.4 GiB for an hour) or, with ``--format tdms``,
as TDMS (npTDMS, one segment of every channel per chunk, ``wf_increment``; ``--format both`` runs
one after the other). A fresh process (so that its peak resident memory is that of the processing
alone) then runs the whole command, ``shaftline monitor identify CASE RECORDING --db ... --json
...`` (``--via verb``, the default: the case file of the layout, the fingerprints of the inputs,
SHA-256 of the file, the checks of the first window, then every 2 s window read, masked,
identified (orbits, film, the least-squares centre line of eight sections, regimes,
descriptors) and stored in a SQLite database one transaction each, and the JSON), or, with
``--via function``, :func:`shaftline.monitor.processing.process_recording` alone (the figures
before issue 13's review). It prints the wall time, the ratio of recorded time to wall time
(> 1: faster than real time), probe samples per second and the peak resident memory
(the child's ``VmHWM``: ``ru_maxrss`` counts the forked copy of this process before the exec).
``--model-shape`` fits the centre line with the shaft model's bending shape
(seed 001's rig, differential evolution per window), as a case with ``shaft_model`` does.
``--minutes`` shortens the recording; the wall time of the hour is then extrapolated linearly
(per window and per byte hashed), and both are printed.
"""

from __future__ import annotations

import argparse
import datetime as dt
import json
import math
import subprocess
import sys
import tempfile
import time
from collections.abc import Iterator
from pathlib import Path

import numpy as np
from timing import median_time

from shaftline.monitor.identification import (
    CIRCLE_PASSES,
    _circle_term,
    _solver,
    directions,
    film_between_circles,
    probe_films,
    reference_points,
)
from shaftline.monitor.probes import Probe, ProbeLayout, Section, seed001_layout

SAMPLES = 1_000_000
ROOT = Path(__file__).resolve().parents[1]


def layout_32(prefix: str = "") -> ProbeLayout:
    """8 sections of 4 probes (45, 135, 225, 315 deg) along a 1.2 m bearing: 32 channels, named
    ``prefix`` + S<section>_<probe>."""
    angles = [math.radians(a) for a in (45.0, 135.0, 225.0, 315.0)]
    sections = tuple(
        Section(f"S{i}", 0.075 + 0.15 * i, tuple(Probe(f"{prefix}S{i}_{j}", a, 1e-3) for j, a in enumerate(angles)))
        for i in range(8)
    )
    return ProbeLayout(sections, 1.2, 0.16205, 0.55e-3)


def block(layout: ProbeLayout) -> np.ndarray:
    t = np.arange(SAMPLES) / 10_000.0
    ey = -0.5e-3 + 5e-6 * np.cos(2 * math.pi * 3.0 * t)
    ez = -0.1e-3 + 5e-6 * np.sin(2 * math.pi * 3.0 * t)
    return np.hstack([film_between_circles(ey, ez, s.angles, layout) + s.mounting_distances for s in layout.sections])


def numpy_films(layout: ProbeLayout, gaps: np.ndarray, references) -> list[np.ndarray]:
    """The same orbit and film with (N, p) numpy temporaries: the first, uncompiled implementation."""
    out = []
    for section, columns, reference in zip(layout.sections, layout.section_columns(), references, strict=True):
        k = reference.correction
        inverse, _, normal = _solver(section, layout.rotation, False)
        rhs = (layout.radial_clearance + k + section.mounting_distances) - gaps[:, columns]
        centre = rhs @ inverse.T
        for _ in range(CIRCLE_PASSES):
            centre = (rhs + _circle_term(centre @ normal.T, layout.journal_radius - k)) @ inverse.T
        along, across = directions(section.angles, layout.rotation)
        film = (
            layout.radial_clearance + k - centre @ along.T + _circle_term(centre @ across.T, layout.journal_radius - k)
        )
        out.append(film)
    return out


RATE = 10_000.0
SPEED = 4 * math.pi  # 120 rpm
CHUNK_SECONDS = 10
WINDOW_SECONDS = 2.0


def _chunks(minutes: float, seed: int = 1) -> tuple[int, Iterator[tuple[int, list[np.ndarray], np.ndarray]]]:
    """Samples of the synthetic 32-channel recording and its 10 s chunks: (first sample, one
    float32 array per probe, keyphasor)."""
    layout = layout_32()
    total = int(round(minutes * 60 * RATE))
    chunk = int(CHUNK_SECONDS * RATE)
    rng = np.random.default_rng(seed)

    def chunks() -> Iterator[tuple[int, list[np.ndarray], np.ndarray]]:
        for first in range(0, total, chunk):
            stop = min(first + chunk, total)
            t = np.arange(first, stop) / RATE
            phase = SPEED * t + 0.5
            ey = -0.5e-3 + 5e-6 * np.cos(phase)
            ez = -0.1e-3 + 5e-6 * np.sin(phase)
            probes = []
            for section in layout.sections:
                gaps = film_between_circles(ey, ez, section.angles, layout) + section.mounting_distances
                gaps += rng.normal(0.0, 0.05e-6, gaps.shape)
                # sensitivity 1 V/m: the output is the gap
                probes += [gaps[:, j].astype(np.float32) for j in range(gaps.shape[1])]
            keyphasor = np.where((phase % (2 * math.pi)) < 0.2, 5.0, 0.0).astype(np.float32)
            yield first, probes, keyphasor

    return total, chunks()


#: Group of the channels in the TDMS file: its channels are named "probes/<name>".
TDMS_GROUP = "probes"


def write_recording(path: Path, minutes: float, seed: int = 1) -> int:
    """The synthetic 32-channel recording, written chunk by chunk as HDF5 (``.h5``: one chunked
    float32 dataset per channel, the sample rate as a file attribute) or TDMS (``.tdms``, npTDMS:
    one segment per chunk holding every channel, float32, the sample rate as each channel's
    ``wf_increment``); returns its samples."""
    names = [*layout_32().channels, "keyphasor"]
    total, chunks = _chunks(minutes, seed)
    if path.suffix == ".tdms":
        from nptdms import ChannelObject, TdmsWriter

        properties = {"wf_increment": 1.0 / RATE, "wf_start_offset": 0.0}
        with TdmsWriter(str(path)) as writer:
            for _, probes, keyphasor in chunks:
                writer.write_segment(
                    [
                        ChannelObject(TDMS_GROUP, name, data, properties=properties)
                        for name, data in zip(names, [*probes, keyphasor], strict=True)
                    ]
                )
        return total
    import h5py

    with h5py.File(path, "w") as file:
        file.attrs["sample_rate"] = RATE
        datasets = [file.create_dataset(name, shape=(total,), dtype="float32", chunks=(65_536,)) for name in names]
        for first, probes, keyphasor in chunks:
            # a loop over channels: the file has one dataset each
            for dataset, data in zip(datasets, [*probes, keyphasor], strict=True):
                dataset[first : first + data.size] = data
    return total


def case_text(prefix: str, model_shape: bool) -> str:
    """A case file of the 32-channel layout for ``monitor identify``; channel names with ``prefix``
    (a TDMS file's group)."""
    layout = layout_32()
    lines = [
        "[case]",
        'name = "bench_monitor: 32 channels"',
        "[monitor]",
        f'length = "{layout.length} m"',
        f'diameter = "{2 * layout.radius} m"',
        f'radial_clearance = "{layout.radial_clearance} m"',
    ]
    if model_shape:  # the seed rig's shaft model (its bearing is as long): differential evolution per window
        lines += [f'shaft_model = "{ROOT / "examples" / "monitor_rig_shaft.toml"}"', 'shaft_bearing = "stern"']
    for section in layout.sections:
        lines += ["[[monitor.sections]]", f'name = "{section.name}"', f'position = "{section.position} m"']
        for probe in section.probes:
            lines += [
                "[[monitor.sections.probes]]",
                f'name = "{prefix}{probe.name}"',
                f'angle = "{math.degrees(probe.angle):g} deg"',
                f'mounting_distance = "{probe.mounting_distance} m"',
                'sensitivity = "1 V/m"',
            ]
    lines += [
        "[monitor.identify]",
        f'keyphasor = "{prefix}keyphasor"',
        f'window = "{WINDOW_SECONDS} s"',
        "start = 2026-11-02T00:00:00Z",
    ]
    return "\n".join(lines) + "\n"


def process(path: Path, model_shape: bool = False) -> None:
    """What ``monitor identify`` does to one recording, through its functions (``--via function``);
    prints wall time, windows and peak RSS."""
    from shaftline.monitor.forward import RigCase, rig_shape_for
    from shaftline.monitor.processing import process_recording
    from shaftline.monitor.trends import TrendStore

    layout = layout_32(f"{TDMS_GROUP}/" if path.suffix == ".tdms" else "")
    # the seed rig's shaft-model shape (its bearing is as long): a differential-evolution fit per window
    shape = rig_shape_for(RigCase()) if model_shape else None
    keyphasor = f"{TDMS_GROUP}/keyphasor" if path.suffix == ".tdms" else "keyphasor"
    start = time.perf_counter()
    with TrendStore(path.with_suffix(".sqlite")) as store:
        done = process_recording(
            layout,
            path,
            store,
            keyphasor,
            WINDOW_SECONDS,
            started_at=dt.datetime(2026, 11, 2, tzinfo=dt.UTC),
            shape=shape,
        )
    wall = time.perf_counter() - start
    print(f"RESULT {wall:.3f} {done.windows} {done.written} {high_water_mark()}")


def high_water_mark() -> int:
    """This process's peak resident memory since its exec, bytes (``VmHWM``; ``ru_maxrss`` may count the
    forked copy of the parent before the exec)."""
    for line in Path("/proc/self/status").read_text().splitlines():
        if line.startswith("VmHWM"):
            return int(line.split()[1]) * 1024
    raise RuntimeError("no VmHWM in /proc/self/status")


def run_verb(path: Path, model_shape: bool) -> tuple[float, int, int, int]:
    """``shaftline monitor identify CASE RECORDING --db ... --json ...`` in a fresh process (the
    whole command: case, input fingerprints, hash, checks, windows, store, JSON): wall time, windows,
    windows stored and the child's peak resident memory in bytes."""
    prefix = f"{TDMS_GROUP}/" if path.suffix == ".tdms" else ""
    case = path.with_name("case.toml")
    case.write_text(case_text(prefix, model_shape))
    result = path.with_name("result.json")
    arguments = ["shaftline", "monitor", "identify", str(case), str(path), "--db", str(path.with_suffix(".sqlite")),
                 "--json", str(result)]  # fmt: skip
    # The child reports its own high-water mark (VmHWM) at exit: RUSAGE_CHILDREN's ru_maxrss counts the
    # forked copy of this process before its exec, so after the per-sample part (1.4 GiB here) it printed
    # that instead of the command's 447 MiB.
    high_water = path.with_name("vmhwm.txt")
    wrapper = (
        "import atexit, runpy, sys\n"
        "def report():\n"
        "    for line in open('/proc/self/status'):\n"
        "        if line.startswith('VmHWM'):\n"
        f"            open({str(high_water)!r}, 'w').write(line.split()[1])\n"
        "atexit.register(report)\n"
        f"sys.argv = {arguments!r}\n"
        "runpy.run_module('shaftline.cli', run_name='__main__')\n"
    )
    start = time.perf_counter()
    subprocess.run([sys.executable, "-c", wrapper], capture_output=True, text=True, check=True)
    wall = time.perf_counter() - start
    peak = int(high_water.read_text()) * 1024  # kB
    stored = json.loads(result.read_text())["monitor"]["identify"]["recordings"][0]
    return wall, int(stored["windows"]), int(stored["written"]), int(peak)


def end_to_end(minutes: float, model_shape: bool = False, kind: str = "hdf5", via: str = "verb") -> None:
    with tempfile.TemporaryDirectory(prefix="bench-monitor-") as folder:
        path = Path(folder) / ("recording.tdms" if kind == "tdms" else "recording.h5")
        start = time.perf_counter()
        samples = write_recording(path, minutes)
        written = time.perf_counter() - start
        size = path.stat().st_size
        channels = len(layout_32().channels)
        print(
            f"recording: {minutes:g} min, {channels} channels + keyphasor at {RATE:g} Hz = "
            f"{samples * channels / 1e9:.3f} G probe samples, {size / 2**30:.2f} GiB {kind.upper()} float32 "
            f"(written in {written:.0f} s)"
        )
        if via == "verb":
            wall_s, windows, stored, peak = run_verb(path, model_shape)
        else:
            output = subprocess.run(
                [sys.executable, __file__, "--process", str(path), *(["--model-shape"] if model_shape else [])],
                capture_output=True,
                text=True,
                check=True,
            ).stdout
            line = next(row for row in output.splitlines() if row.startswith("RESULT"))
            wall, window_count, stored_count, peak_text = line.split()[1:]
            wall_s, windows, stored, peak = float(wall), int(window_count), int(stored_count), int(peak_text)
        recorded = samples / RATE
        line_kind = "shaft-model shape by differential evolution" if model_shape else "least-squares"
        how = "`shaftline monitor identify`" if via == "verb" else "process_recording"
        print(
            f"end to end, {kind.upper()}, {how} ({line_kind} centre line; hash, read, identify, store "
            f"{stored}/{windows} windows of {WINDOW_SECONDS:g} s): "
            f"{wall_s:.1f} s for {recorded:.0f} s recorded, {recorded / wall_s:.1f} x real time, "
            f"{samples * channels / wall_s / 1e6:.2f} M probe samples/s; peak resident memory {peak / 2**20:.0f} MiB"
        )
        if minutes < 60:
            hour = wall_s * 60 / minutes
            print(
                f"extrapolated to 1 hour (linear in windows and bytes): {hour:.0f} s for 3600 s, "
                f"{3600 / hour:.1f} x real time; memory does not grow with the length (windows of "
                f"{WINDOW_SECONDS:g} s)"
            )


def per_sample() -> None:
    for name, layout in (("seed 001, 9 channels", seed001_layout()), ("32 channels", layout_32())):
        gaps = block(layout)
        references = reference_points(layout, gaps[:10_000])
        probe_films(layout, gaps[:1000], references)  # compile (cached on disk after the first run)
        channels = gaps.shape[1]
        for _ in range(3):
            compiled, _ = median_time(lambda: probe_films(layout, gaps, references), 5)  # noqa: B023
            plain, _ = median_time(lambda: numpy_films(layout, gaps, references), 5)  # noqa: B023
            print(
                f"{name}: compiled {SAMPLES / compiled / 1e6:.2f} M time samples/s "
                f"({SAMPLES * channels / compiled / 1e6:.1f} M channel samples/s); "
                f"numpy {SAMPLES / plain / 1e6:.2f} M time samples/s; ratio {plain / compiled:.1f}"
            )


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--minutes", type=float, default=60.0, help="length of the end-to-end recording")
    parser.add_argument("--only", choices=("per-sample", "end-to-end"), default=None)
    parser.add_argument(
        "--model-shape", action="store_true", help="centre line from the shaft model's shape (as the example case)"
    )
    parser.add_argument(
        "--format", choices=("hdf5", "tdms", "both"), default="hdf5", help="file format of the end-to-end recording"
    )
    parser.add_argument(
        "--via",
        choices=("verb", "function"),
        default="verb",
        help="the whole `monitor identify` command (default) or process_recording alone (as before)",
    )
    parser.add_argument("--process", type=Path, default=None, help=argparse.SUPPRESS)
    arguments = parser.parse_args()
    if arguments.process is not None:
        process(arguments.process, arguments.model_shape)
        return
    if arguments.only in (None, "per-sample"):
        per_sample()
    if arguments.only in (None, "end-to-end"):
        for kind in ("hdf5", "tdms") if arguments.format == "both" else (arguments.format,):
            end_to_end(arguments.minutes, arguments.model_shape, kind, arguments.via)


if __name__ == "__main__":
    main()
