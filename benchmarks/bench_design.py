"""Speed of the slope-boring search (issue 12): the seed's search, NSGA-II with 40 generations of 40
on the NTUA bearing (100 x 60 film, psi_x = 0.3), linear and bent shaft, serially, on the process
pool and on a Dask LocalCluster.

Targets (issue 12): linear shaft <= 60 s wall on this 2-core machine; bent shaft (fast path)
<= 3 min. Prints evaluations per second and the ratios of the backends.

    python benchmarks/bench_design.py [GENERATIONS] [--population N] [--backends serial,process,dask]
                                      [--shaft linear|bent|both]

With fewer generations it extrapolates the wall time of 40 (the cost per generation is flat:
every generation is a batch of the same size).
"""

from __future__ import annotations

import argparse
import time

from shaftline.design import SlopeDesignProblem
from shaftline.design.search import search
from shaftline.design.shaft_models import bent_shaft, linear_shaft
from shaftline.film import BearingProblem, OperatingPoint, SolverOptions
from shaftline.film.geometry import BearingGeometry
from shaftline.shaft.local import seed004_local_model

C, L, LOAD, PSI = 0.45e-3, 1.05, 309859.9, 0.3


def problem(shaft: str) -> SlopeDesignProblem:
    film = BearingProblem(
        BearingGeometry(L, 0.52, C),
        OperatingPoint(speed=9.42477796076938, viscosity=0.07, density=890.0),
        SolverOptions(axial_nodes=100, circumferential_nodes=60),
    )
    base = SlopeDesignProblem(film, -LOAD)
    at = linear_shaft(base) if shaft == "linear" else bent_shaft(base, seed004_local_model())
    return at(PSI)


def run(shaft: str, backend: str, generations: int, population: int) -> tuple[float, int, float]:
    start = time.perf_counter()
    if backend == "dask":
        from dask.distributed import LocalCluster

        with LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=":0") as cluster:
            inner = time.perf_counter()
            result = search(
                problem(shaft), population=population, generations=generations, scheduler=cluster.scheduler_address
            )
            searching = time.perf_counter() - inner
        wall = time.perf_counter() - start
        print(f"    (dask: cluster start and stop {wall - searching:.1f} s of {wall:.1f} s)")
    else:
        result = search(problem(shaft), population=population, generations=generations, backend=backend)
        wall = time.perf_counter() - start
    best = max(e.values["min_film_thickness"] for e in result.evaluations if e.ok)
    return wall, len(result.evaluations), best


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("generations", nargs="?", type=int, default=40)
    parser.add_argument("--population", type=int, default=40)
    parser.add_argument("--backends", default="serial,process,dask")
    parser.add_argument("--shaft", default="both", choices=["linear", "bent", "both"])
    args = parser.parse_args()
    shafts = ["linear", "bent"] if args.shaft == "both" else [args.shaft]
    for shaft in shafts:
        print(f"{shaft} shaft: NSGA-II {args.population} x {args.generations}, NTUA bearing 100 x 60, psi_x = {PSI}")
        walls = {}
        for backend in args.backends.split(","):
            wall, evaluations, best = run(shaft, backend, args.generations, args.population)
            walls[backend] = wall
            per_40 = wall * 40 / args.generations
            print(
                f"  {backend:8s} {wall:7.1f} s  {evaluations / wall:6.1f} evaluations/s  "
                f"(40 generations: {per_40:6.1f} s)  best h_min {best * 1e6:.1f} um"
            )
        if "serial" in walls:
            for backend, wall in walls.items():
                if backend != "serial":
                    print(f"  {backend} / serial speed-up {walls['serial'] / wall:.2f}")
        if "process" in walls and "dask" in walls:
            print(f"  dask / process wall time {walls['dask'] / walls['process']:.2f}")


if __name__ == "__main__":
    main()
