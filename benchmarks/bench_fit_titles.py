"""Cost of wrapping the report's long panel titles (``report.plotting.fit_titles``), measured on
the figures of ``examples/seed001_water_rig_liner.toml``: the figures drawn and saved as the
report does (``report.html.draw_figure``) with and without it, paired in each repetition, and
``fit_titles`` alone. Prints medians and the ratio.

Run: ``.venv/bin/python benchmarks/bench_fit_titles.py``. Measured (issue 15 follow-up, 2-core machine):
drawing and saving with and without, ratio 0.97-1.0 (noise); ``fit_titles`` alone 4-7 ms a
figure against about 0.4 s to draw and save one.
"""

from __future__ import annotations

import statistics
import tempfile
import time
from pathlib import Path

from matplotlib.figure import Figure as MatplotlibFigure

import shaftline.report.html as html
from shaftline.cases import load_case
from shaftline.pipeline import report_sections, run_case
from shaftline.report.blocks import Figure
from shaftline.report.plotting import fit_titles

EXAMPLE = Path(__file__).resolve().parents[1] / "examples" / "seed001_water_rig_liner.toml"
REPEATS = 5


def figures() -> list[Figure]:
    found: list[Figure] = []

    def collect(blocks: list) -> None:
        for block in blocks:
            if isinstance(block, Figure):
                found.append(block)
            collect(list(getattr(block, "blocks", [])))

    for section in report_sections(run_case(load_case(EXAMPLE))):
        collect(list(section.blocks))
    return found


def main() -> None:
    drawn = figures()
    folder = Path(tempfile.mkdtemp())
    times: dict[str, list[float]] = {"with": [], "without": []}
    for _ in range(REPEATS):
        for mode in ("with", "without"):
            html.fit_titles = fit_titles if mode == "with" else (lambda figure: None)
            start = time.perf_counter()
            for k, figure in enumerate(drawn):
                html.draw_figure(figure, folder / f"{k}.png")
            times[mode].append(time.perf_counter() - start)
    html.fit_titles = fit_titles
    alone = []
    for figure in drawn * REPEATS:
        canvas = MatplotlibFigure(figsize=figure.plot.size, layout="constrained")
        axes = canvas.subplots(*figure.plot.layout, sharex=figure.plot.sharex)
        figure.plot(*figure.args, ax=axes, **figure.kwargs)
        start = time.perf_counter()
        fit_titles(canvas)
        alone.append(time.perf_counter() - start)
    with_, without = statistics.median(times["with"]), statistics.median(times["without"])
    print(f"{len(drawn)} figures drawn and saved, median of {REPEATS}:")
    print(f"  with fit_titles    {with_:.3f} s")
    print(f"  without            {without:.3f} s   ratio with/without {with_ / without:.3f}")
    print(f"  fit_titles alone   {statistics.median(alone) * 1e3:.1f} ms a figure (median of {len(alone)})")


if __name__ == "__main__":
    main()
