"""Work and time of one lined equilibrium: sparse factorisations (film and coupled matrices), film
solutions, GMRES iterations (layer model) and Newton iterations per equilibrium, with the median
time; the column and the layer model of each liner alternated run by run, with their ratio.

Run ``PYTHONPATH=src .venv/bin/python benchmarks/bench_liner_work.py [--repeat N] [--cpu] [--target]``
in a tree (``--cpu``: CPU-time medians, less disturbed by other processes on a shared machine;
``--target``: only the issue's 1 rpm polymer case);
the counts do not depend on the machine, so running it on two trees (e.g. main before a change,
a branch after) compares the work exactly where the shared machine makes the times noisy.

NTUA stern tube (seed 004 Table 5-1, examples/ntua_stern_tube.toml), 100 x 60, rough
turned-steel / white-metal surfaces, with seed 001's polymer liner and a white-metal liner: aligned
at 1 rpm (mixed lubrication, the issue's <= 0.3 s case) and at the seed's 90 rpm with psi 0.3.
The film solutions include those of a rigid start where the equilibrium makes one. The coupled
matrix's kept orderings (film/elastic.py CoupledOrderings) are cleared at the start of every
equilibrium, so a repeated call does not time a warm cache.
Issue 15 target: the 1 rpm column-liner cases <= 0.3 s (figures in docs/validation.md, "Elastic
liner": polymer 0.36 s -> about 0.25 s on a quiet machine after the fixed-node settling, the
pattern assembly and the kept orderings).
"""

from __future__ import annotations

import statistics
import sys
import time
from dataclasses import replace
from pathlib import Path

import numpy as np
from timing import median_time

import shaftline.film.elastic as elastic
from shaftline.cases import load_case
from shaftline.film import JournalBearing
from shaftline.film.liner import Liner
from shaftline.film.roughness import SurfaceRoughness, gaussian_integral_table

ROOT = Path(__file__).resolve().parents[1]
COUNT = {"krylov": 0}


def _counted() -> None:
    """Count the GMRES iterations of the layer liner (a wrapper, same results); the coupled
    factorisations and the film solutions are the equilibrium's own counters."""
    layer_solve = elastic.LayerSystem.solve

    def counted_layer_solve(self, *args, **kwargs):  # noqa: ANN001, ANN002, ANN003, ANN202
        before = self.krylov_iterations
        result = layer_solve(self, *args, **kwargs)
        COUNT["krylov"] += self.krylov_iterations - before
        return result

    elastic.LayerSystem.solve = counted_layer_solve  # type: ignore[method-assign]


def cpu_time(function) -> float:  # noqa: ANN001 - benchmark helper
    """CPU time of one call of ``function``, s."""
    start = time.process_time()
    function()
    return time.process_time() - start


def main() -> None:
    repeat = int(sys.argv[sys.argv.index("--repeat") + 1]) if "--repeat" in sys.argv else 7
    timer = cpu_time if "--cpu" in sys.argv else (lambda function: median_time(function, 1)[0])
    target = "--target" in sys.argv
    gaussian_integral_table(2.5)  # built once per process: not an equilibrium's cost
    gaussian_integral_table(2.0)
    _counted()
    case = load_case(ROOT / "examples" / "ntua_stern_tube.toml").studies["bearing"].cases[0]
    surface = SurfaceRoughness.preset("turned_steel_white_metal")
    print(
        f"{'case':58s} {'median s':>9s} {'its':>4s} {'fact':>4s} {'film':>5s} {'GMRES':>6s} "
        f"{'h_min um':>9s} {'p_max MPa':>10s} {'layer/column':>12s}"
    )
    for rpm, tilt in ((1.0, 0.0),) if target else ((1.0, 0.0), (90.0, case.tilt_y)):
        operating = replace(case.operating, speed=rpm * np.pi / 30)
        for name in ("polymer_composite",) if target else ("polymer_composite", "white_metal"):
            bearings = {
                model: JournalBearing(
                    replace(case.geometry, surface=surface, liner=Liner.preset(name, model=model)),
                    operating,
                    case.options,
                )
                for model in ("column", "layer")
            }
            work = {}
            for model, bearing in bearings.items():

                def solve(b: JournalBearing = bearing, t: float = tilt):  # noqa: ANN202 - benchmark helper
                    return b.equilibrium(case.load_y, case.load_z, tilt_y=t, tilt_z=case.tilt_z)

                COUNT["krylov"] = 0
                eq = solve()  # the first call builds the layer's transfer function (not timed below)
                work[model] = (solve, eq, eq.factorisations, eq.film_solutions, COUNT["krylov"])
            times: dict[str, list[float]] = {"column": [], "layer": []}
            for _ in range(repeat):  # alternated: both models see the same load of the machine
                for model in ("column", "layer"):
                    times[model].append(timer(work[model][0]))
            medians = {model: statistics.median(t) for model, t in times.items()}
            for model in ("column", "layer"):
                _, eq, lu, film, krylov = work[model]
                st = eq.state
                label = f"{rpm:g} rpm, tilt {tilt * 1e3:.3f} mrad, {name} liner, {model}"
                ratio = f"{medians['layer'] / medians['column']:12.2f}" if model == "layer" else f"{'':12s}"
                print(
                    f"{label:58s} {medians[model]:9.3f} {eq.iterations:4d} {lu:4d} {film:5d} {krylov:6d} "
                    f"{st.min_film_thickness * 1e6:9.4f} {st.max_pressure / 1e6:10.5f} {ratio}"
                    + ("" if eq.converged else "  (not converged)")
                )


if __name__ == "__main__":
    main()
