"""Per-sample speed of the film monitor (issue 13): journal-centre orbit and film at the probe sections.

Run ``PYTHONPATH=src .venv/bin/python benchmarks/bench_monitor.py``. For seed 001's layout (3 sections
x 3 probes, 9 channels) and a 32-channel one (8 sections x 4 probes, the issue's recording), times
:func:`shaftline.monitor.identification.probe_films` on a block of one million time samples (orbit of
every section and the film at its probe angles, exact circle geometry, two correction passes), prints
the median of five calls as time samples per second and channel samples per second (the issue's
target: >= 5 million samples per second per core; the compiled kernel runs on one core), and, pair by
pair in the same process, the same arithmetic written with numpy arrays (the first implementation) and
the ratio. Three rounds.
"""

from __future__ import annotations

import math

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


def layout_32() -> ProbeLayout:
    """8 sections of 4 probes (45, 135, 225, 315 deg) along a 1.2 m bearing: 32 channels."""
    angles = [math.radians(a) for a in (45.0, 135.0, 225.0, 315.0)]
    sections = tuple(
        Section(f"S{i}", 0.075 + 0.15 * i, tuple(Probe(f"S{i}_{j}", a, 1e-3) for j, a in enumerate(angles)))
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


def main() -> None:
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


if __name__ == "__main__":
    main()
