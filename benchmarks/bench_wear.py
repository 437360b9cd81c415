"""Pitch-log processing timing (issue 4 target): a 24-hour 10 Hz log <= 1 s, reading the
CSV, removing noise with the dead band and summing the travel. Prints the median.

Run: ``.venv/bin/python benchmarks/bench_wear.py``.
"""

from __future__ import annotations

import statistics
import tempfile
import time
from pathlib import Path

import numpy as np

from shaftline.wear.service import pitch_travel, read_pitch_log, stepwise_constant


def main() -> None:
    rng = np.random.default_rng(0)
    samples = 24 * 3600 * 10
    t = np.arange(samples) / 10.0
    pitch = 80 + 10 * np.sin(2 * np.pi * t / 3600) + rng.normal(0, 0.1, samples)
    with tempfile.TemporaryDirectory() as folder:
        path = Path(folder) / "day.csv"
        np.savetxt(path, np.column_stack([t, pitch]), delimiter=",", header="time,pitch", comments="", fmt="%.1f,%.3f")
        times = []
        for _ in range(5):
            start = time.perf_counter()
            log = read_pitch_log(path)
            travel = pitch_travel(stepwise_constant(log.pitch, 0.5))
            times.append(time.perf_counter() - start)
    median = statistics.median(times)
    print(
        f"24-hour 10 Hz pitch log ({samples} samples): read + dead band + travel {median:.3f} s median "
        f"(target <= 1 s, ratio {median:.2f}); travel {travel:.2f} design pitches"
    )


if __name__ == "__main__":
    main()
