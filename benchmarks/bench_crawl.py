"""Time saved by the crawl rule of a rigid rough bore (docs/theory.md Sect. 17, "The stall
rule and crawling Newton steps").

Run ``PYTHONPATH=src .venv/bin/python benchmarks/bench_crawl.py [--repeat N]``. The NTUA rough curve's
12.36 rpm (benchmarks/bench_mixed.py: examples/ntua_stern_tube.toml, 100 x 60, psi 0.3, turned steel
on white metal, rigid) from a cold start, with the crawl rule and without it (``NewtonOptions.crawl_iterations``
set out of reach: the iteration as before the rule), alternated run by run in one process; medians,
the ratio, iterations and the final status of each.
"""

from __future__ import annotations

import sys
import time
from dataclasses import replace
from pathlib import Path

import numpy as np

from shaftline.cases import load_case
from shaftline.film import JournalBearing
from shaftline.film.roughness import SurfaceRoughness, gaussian_integral_table

ROOT = Path(__file__).resolve().parents[1]


def main() -> None:
    repeat = int(sys.argv[sys.argv.index("--repeat") + 1]) if "--repeat" in sys.argv else 5
    gaussian_integral_table(2.5)
    gaussian_integral_table(2.0)
    study = load_case(ROOT / "examples" / "ntua_stern_tube.toml").studies["bearing"]
    case = study.cases[0]
    geometry = replace(case.geometry, surface=SurfaceRoughness.preset("turned_steel_white_metal"))
    operating = replace(case.operating, speed=study.stribeck_speeds[2])
    rule = case.options.newton.crawl_iterations
    times: dict[str, list[float]] = {"with the crawl rule": [], "without": []}
    results = {}
    for _ in range(repeat):
        for name, crawl in (("with the crawl rule", rule), ("without", 10**9)):
            options = replace(case.options, newton=replace(case.options.newton, crawl_iterations=crawl))
            bearing = JournalBearing(geometry, operating, options)
            start = time.perf_counter()
            results[name] = bearing.equilibrium(case.load_y, case.load_z, tilt_y=case.tilt_y, tilt_z=case.tilt_z)
            times[name].append(time.perf_counter() - start)
    print(f"NTUA rough, rigid, {operating.speed * 30 / np.pi:.2f} rpm, cold start, {repeat} runs each, alternated")
    reference = float(np.median(times["without"]))
    for name, spent in times.items():
        eq = results[name]
        status = "converged" if eq.converged else ("contact" if eq.contact else "not converged")
        print(
            f"{name:20s} median {np.median(spent):6.3f} s, ratio {np.median(spent) / reference:5.2f}; "
            f"{eq.iterations} iterations, {status}, residual {eq.residual / abs(case.load_y):.3g} of the load"
        )


if __name__ == "__main__":
    main()
