"""Bearing solver timings (issue 2 and issue 10 targets) and a side-by-side run with ROSS.

Run ``make bench`` (its own environment, with ROSS) or, without ROSS,
``.venv/bin/python benchmarks/bench_bearing.py [--large] [--quick]``. Prints medians and ratios.
``--large`` adds the 800 x 480 equilibrium; ``--quick`` leaves out the scaling and ROSS.

Issue 10 targets (Reynolds condition, NTUA case):
  one cold pressure solution on 100 x 60 within 4x one factorisation + solve of its own final
  matrix (the unit: qdldl's numeric factorisation of the free sub-matrix of the converged
  active set, its ordering and symbolic analysis done beforehand, and one solve), one load
  equilibrium within 12x of that unit; the equilibrium time growing no faster than N^1.4 from
  100 x 60 to 400 x 240 and an 800 x 480 equilibrium in under 30 s. The ratios are also printed
  against a fresh factorisation (AMD ordering included) and against the numeric factorisation
  of the full periodic pattern with held rows and columns zeroed (the solver before issue 10).

Targets on the 2-core machine:
  NTUA stern tube, 100 axial x 60 circumferential nodes, psi_x = 0.3, Reynolds condition:
  one pressure solution at a fixed position <= 20 ms, one load equilibrium <= 0.1 s.
  ROSS comparison: aligned L/D = 1 bearing at S = 0.121 against the published
  eps = 0.60, attitude 50.54 deg (Butenschoen 1976, Raimondi & Boyd 1958); aim >= 10x faster.
"""

from __future__ import annotations

import statistics
import sys
import time
import warnings
from dataclasses import replace
from pathlib import Path
from typing import Any

import numpy as np
import qdldl
import scipy.sparse as sp
from timing import median_time

from shaftline.cases import load_case
from shaftline.film import BearingGeometry, JournalBearing, OperatingPoint, SolverOptions

ROOT = Path(__file__).resolve().parents[1]


def operator_matrix(stencil, fixed: np.ndarray, cavitated: np.ndarray, free_only: bool) -> sp.csc_matrix:
    """Upper triangle of the Reynolds operator A: its free sub-matrix (``free_only``), or the
    full periodic pattern with the held rows and columns zeroed (held diagonals kept), built
    from the stencil alone so that it does not depend on the solver's own code."""
    nz, nt = fixed.shape
    node = np.arange(nz * nt).reshape(nz, nt)
    east = np.roll(node, -1, axis=1)
    a = np.concatenate([node.ravel(), node[:-1].ravel()])
    b = np.concatenate([east.ravel(), node[1:].ravel()])
    c = np.concatenate([stencil.c_theta.ravel(), stencil.c_z.ravel()])
    diag = np.zeros(nz * nt)
    np.add.at(diag, a, c)
    np.add.at(diag, b, c)
    held = (fixed | cavitated).ravel()
    links = ~held[a] & ~held[b]
    lo, hi = np.minimum(a, b), np.maximum(a, b)
    if free_only:
        index = np.cumsum(~held) - 1
        keep = np.flatnonzero(~held)
        rows = np.concatenate([index[keep], index[lo[links]]])
        cols = np.concatenate([index[keep], index[hi[links]]])
        vals = np.concatenate([diag[keep], -c[links]])
        size = keep.size
    else:
        rows = np.concatenate([np.arange(nz * nt), lo])
        cols = np.concatenate([np.arange(nz * nt), hi])
        vals = np.concatenate([diag, np.where(links, -c, 0.0)])
        size = nz * nt
    matrix = sp.csc_matrix((vals, (rows, cols)), shape=(size, size))
    matrix.sort_indices()
    return matrix


def unit_timers(bearing: JournalBearing, position) -> tuple[dict[str, Any], int]:
    """Timers of one factorisation + solve of the converged active set's matrix (the unit and
    its two variants), and the free nodes."""
    evaluation = bearing.solver.evaluate(position, warm=False)
    fixed = bearing.solver.nodes.fixed
    cavitated = evaluation.cavitation.cavitated
    free = operator_matrix(evaluation.stencil, fixed, cavitated, free_only=True)
    full = operator_matrix(evaluation.stencil, fixed, cavitated, free_only=False)
    rhs_free, rhs_full = np.ones(free.shape[0]), np.ones(full.shape[0])
    numeric_free = qdldl.Solver(free, upper=True)
    masked = qdldl.Solver(full, upper=True)
    timers = {
        "numeric": lambda: (numeric_free.update(free, upper=True), numeric_free.solve(rhs_free)),
        "fresh": lambda: qdldl.Solver(free, upper=True).solve(rhs_free),
        "masked": lambda: (masked.update(full, upper=True), masked.solve(rhs_full)),
    }
    return timers, free.shape[0]


def paired_ratios(timers: dict[str, Any], subjects: dict[str, Any], rounds: int) -> dict[str, list[float]]:
    """Per round: the median of each timer and subject (15 calls each, one after the other), and
    each subject over each timer: ratios taken pair by pair, so that a machine whose speed drifts
    between the two measurements (a shared or throttled CPU: the unit alone varied 1.0-1.8 ms
    between runs) does not move them. Returns the rounds' ratios ``"subject/timer"`` and times."""
    out: dict[str, list[float]] = {}
    for _ in range(rounds):
        times = {name: median_time(function, 15)[0] for name, function in {**timers, **subjects}.items()}
        for name, value in times.items():
            out.setdefault(name, []).append(value)
        for subject in subjects:
            for timer in timers:
                out.setdefault(f"{subject}/{timer}", []).append(times[subject] / times[timer])
    return out


class FactorCounter:
    """Counts qdldl factorisations (new solvers and numeric updates) with their sizes, by
    wrapping ``qdldl.Solver`` (the solver's own counter has no sizes: this one tells the fine
    grid's factorisations from the coarse ones')."""

    def __init__(self) -> None:
        self.count = 0
        self.sizes: list[int] = []
        self._original = qdldl.Solver
        counter, original = self, self._original

        class Solver:
            def __init__(self, matrix, *args, **kwargs):
                counter.count += 1
                counter.sizes.append(matrix.shape[0])
                self._inner = original(matrix, *args, **kwargs)

            def update(self, matrix, *args, **kwargs):
                counter.count += 1
                counter.sizes.append(matrix.shape[0])
                return self._inner.update(matrix, *args, **kwargs)

            def solve(self, *args, **kwargs):
                return self._inner.solve(*args, **kwargs)

        self.solver = Solver

    def __enter__(self) -> FactorCounter:
        qdldl.Solver = self.solver  # the film imports qdldl where it first factorises
        return self

    def __exit__(self, *exc) -> None:
        qdldl.Solver = self._original


def ntua_case():
    return load_case(ROOT / "examples" / "ntua_stern_tube.toml")["bearing"].cases[0]


def ntua() -> None:
    case = ntua_case()
    bearing = JournalBearing(case.geometry, case.operating, case.options)
    equilibrium = bearing.equilibrium(case.load_y, case.load_z, tilt_y=case.tilt_y)
    position = equilibrium.state.position
    bearing.solve_at(position)  # first call builds the sparsity pattern and coarse levels
    cold, state = median_time(lambda: bearing.solve_at(position, warm_start=False), 30)
    warm, _ = median_time(lambda: bearing.solve_at(position), 30)
    eq_time, eq = median_time(lambda: bearing.equilibrium(case.load_y, case.load_z, tilt_y=case.tilt_y), 15)
    print("NTUA stern tube, 100 x 60 nodes, psi_x = 0.3, Reynolds condition")
    print(f"  pressure solution, cold start : {cold * 1e3:7.2f} ms median  (target <= 20 ms, ratio {cold / 0.020:.2f})")
    print(f"  pressure solution, warm start : {warm * 1e3:7.2f} ms median")
    print(
        f"  load equilibrium              : {eq_time * 1e3:7.2f} ms median  (target <= 100 ms, "
        f"ratio {eq_time / 0.100:.2f}; {eq.iterations} Newton iterations)"
    )
    print(
        f"  eps = {eq.state.eccentricity_ratio:.4f}, h_min = {eq.state.min_film_thickness * 1e6:.1f} um, "
        f"S = {eq.state.sommerfeld_number:.5f}"
    )
    timers, free_nodes = unit_timers(bearing, position)
    subjects = {
        "cold": lambda: bearing.solve_at(position, warm_start=False),
        "equilibrium": lambda: bearing.equilibrium(case.load_y, case.load_z, tilt_y=case.tilt_y),
    }
    pairs = paired_ratios(timers, subjects, rounds=7)

    def median(name: str) -> float:
        return statistics.median(pairs[name])

    print(f"\nIssue 10: cost against one factorisation + solve of the final matrix ({free_nodes} free nodes)")
    print("  medians of 7 rounds, each timing everything once (median of 15 calls); ratios per round")
    print(f"  unit: qdldl numeric factorisation + solve, free sub-matrix    : {median('numeric') * 1e3:7.3f} ms")
    print(f"        the same with a fresh AMD ordering and symbolic analysis : {median('fresh') * 1e3:7.3f} ms")
    print(f"        numeric factorisation + solve, full periodic pattern     : {median('masked') * 1e3:7.3f} ms")
    for subject, label, target in (("cold", "cold solution", 4), ("equilibrium", "equilibrium  ", 12)):
        ratios = pairs[f"{subject}/numeric"]
        print(
            f"  {label} / unit : {median(f'{subject}/numeric'):6.1f}x  (target <= {target}x; rounds "
            f"{min(ratios):.1f}-{max(ratios):.1f}; {median(f'{subject}/fresh'):.1f}x the fresh ordering, "
            f"{median(f'{subject}/masked'):.1f}x the full pattern)"
        )
    # Fine-grid factorisations: larger than the coarse grid (a quarter of the nodes) can be.
    position_nodes = case.options.axial_nodes * case.options.circumferential_nodes
    # A fresh bearing each: a solver built before the counter started would not be counted.
    with FactorCounter() as counter:
        JournalBearing(case.geometry, case.operating, case.options).solve_at(position, warm_start=False)
    cold_count = counter.count
    with FactorCounter() as counter:
        JournalBearing(case.geometry, case.operating, case.options).equilibrium(
            case.load_y, case.load_z, tilt_y=case.tilt_y
        )
    fine = sum(size > 0.27 * position_nodes for size in counter.sizes)
    print(f"  factorisations: cold solution {cold_count}, equilibrium {counter.count} ({fine} on the fine grid)")


def scaled_equilibrium(shape: tuple[int, int], repeat: int) -> tuple[float, float, int, int, float]:
    """Median equilibrium time of the NTUA case on ``shape`` over ``repeat`` runs after the first,
    the first run's time (which also builds the bearing's solvers: sparsity patterns, orderings,
    coarse grids), and the Newton iterations, fine factorisations and eccentricity ratio."""
    case = ntua_case()
    options = replace(case.options, axial_nodes=shape[0], circumferential_nodes=shape[1])
    bearing = JournalBearing(case.geometry, case.operating, options)
    # The first run counts the factorisations (a bearing's first solver is built inside it).
    with FactorCounter() as counter:
        start = time.perf_counter()
        eq = bearing.equilibrium(case.load_y, case.load_z, tilt_y=case.tilt_y)
        first = time.perf_counter() - start
    # Counted now: the solvers made inside keep counting their updates in the runs below.
    fine = sum(size > 0.27 * shape[0] * shape[1] for size in counter.sizes)
    times = []
    for _ in range(repeat):
        start = time.perf_counter()
        eq = bearing.equilibrium(case.load_y, case.load_z, tilt_y=case.tilt_y)
        times.append(time.perf_counter() - start)
    return statistics.median(times), first, eq.iterations, fine, eq.state.eccentricity_ratio


def scaling(large: bool) -> None:
    shapes = [(100, 60), (200, 120), (400, 240)]
    print("\nIssue 10: equilibrium time against the node count N (NTUA case, Reynolds condition)")
    rows = []
    print("  median of the runs after the first (the first also builds the solvers, shown apart)")
    for shape in shapes:
        median, first, iterations, fine, eps = scaled_equilibrium(shape, 5 if shape[0] <= 200 else 3)
        rows.append((shape[0] * shape[1], median, first))
        print(
            f"  {shape[0]:4d} x {shape[1]:3d}: {median:8.3f} s  (first {first:.3f} s; {iterations} Newton "
            f"iterations, {fine} fine factorisations, eps = {eps:.5f})"
        )
    nodes = np.log([r[0] for r in rows])
    exponent = float(np.polyfit(nodes, np.log([r[1] for r in rows]), 1)[0])
    exponent_first = float(np.polyfit(nodes, np.log([r[2] for r in rows]), 1)[0])
    print(
        f"  fitted exponent 100 x 60 .. 400 x 240: N^{exponent:.2f}  (target <= 1.4; first runs N^{exponent_first:.2f})"
    )
    if large:
        median, first, iterations, fine, eps = scaled_equilibrium((800, 480), 1)
        print(
            f"   800 x 480: {median:8.3f} s  (target < 30 s; first {first:.3f} s; {iterations} Newton "
            f"iterations, {fine} fine factorisations, eps = {eps:.5f})"
        )


def ross_comparison() -> None:
    radius, clearance, length, rev_s, viscosity, sommerfeld = 0.05, 1e-4, 0.1, 10.0, 0.04, 0.121
    load = (radius / clearance) ** 2 * viscosity * rev_s * length * 2 * radius / sommerfeld
    published = (0.6, 50.54)
    bearing = JournalBearing(
        BearingGeometry(length=length, diameter=2 * radius, radial_clearance=clearance),
        OperatingPoint(speed=2 * np.pi * rev_s, viscosity=viscosity),
        SolverOptions(axial_nodes=31, circumferential_nodes=120, film_start="max_film"),
    )
    ours_time, ours = median_time(lambda: bearing.equilibrium(load_y=-load), 15)
    ours_eps, ours_att = ours.state.eccentricity_ratio, np.degrees(ours.state.attitude_angle)
    print("\nAligned L/D = 1 bearing at S = 0.121 (published eps = 0.600, attitude = 50.54 deg)")
    print(
        f"  shaftline 31 x 120 nodes : eps = {ours_eps:.4f} ({(ours_eps / published[0] - 1) * 100:+.2f} %), "
        f"attitude = {ours_att:.2f} deg ({ours_att - published[1]:+.2f}), {ours_time * 1e3:.1f} ms median"
    )
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            from ross.bearings.plain_journal import PlainJournal
            from ross.units import Q_
    except ImportError:
        print("  ROSS not installed in this environment: run `make bench` for the comparison")
        return

    def run_ross():
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            # One 360-degree land: the groove (ambient pressure) lies outside the loaded zone,
            # the nearest ROSS configuration to the published full bearing. Isoviscous.
            return PlainJournal(
                n=0,
                pad_axial_length=length,
                journal_diameter=2 * radius,
                radial_clearance=clearance,
                n_pads=1,
                pad_arc=Q_(360, "deg"),
                oil_supply_temperature=Q_(40, "degC"),
                speed=[2 * np.pi * rev_s],
                fxs_load=0,
                fys_load=-load,
                lubricant="TEST",  # 0.04 Pa s at 40 degC
                oil_flow_v=1e-2,
                thermal_type=None,
                total_ex_film=80,
                total_ez_film=30,
            )

    run_ross()  # compile ROSS's numba kernels outside the timing
    ross_time, ross = median_time(run_ross, 5)
    ross_eps, ross_att = ross.equilibrium_pos[0], np.degrees(ross.equilibrium_pos[1])
    print(
        f"  ROSS PlainJournal 80 x 30: eps = {ross_eps:.4f} ({(ross_eps / published[0] - 1) * 100:+.2f} %), "
        f"attitude = {ross_att:.2f} deg ({ross_att - published[1]:+.2f}), {ross_time * 1e3:.1f} ms median"
    )
    print(f"  time ratio ROSS / shaftline: {ross_time / ours_time:.1f}x")


if __name__ == "__main__":
    ntua()
    if "--quick" not in sys.argv:
        scaling(large="--large" in sys.argv)
        ross_comparison()
