"""Bearing solver timings (issue 2 targets) and a side-by-side run with ROSS.

Run ``make bench`` (its own environment, with ROSS) or, without ROSS,
``.venv/bin/python benchmarks/bench_bearing.py``. Prints medians and ratios.

Targets on the 2-core machine:
  NTUA stern tube, 100 axial x 60 circumferential nodes, psi_x = 0.3, Reynolds condition:
  one pressure solution at a fixed position <= 20 ms, one load equilibrium <= 0.1 s.
  ROSS comparison: aligned L/D = 1 bearing at S = 0.121 against the published
  eps = 0.60, attitude 50.54 deg (Butenschoen 1976, Raimondi & Boyd 1958); aim >= 10x faster.
"""

from __future__ import annotations

import statistics
import time
import warnings
from pathlib import Path

import numpy as np

from shaftline.cases import load_case
from shaftline.film import BearingGeometry, JournalBearing, OperatingPoint, SolverOptions

ROOT = Path(__file__).resolve().parents[1]


def median_time(function, repeat: int) -> tuple[float, object]:
    times, result = [], None
    for _ in range(repeat):
        start = time.perf_counter()
        result = function()
        times.append(time.perf_counter() - start)
    return statistics.median(times), result


def ntua() -> None:
    case = load_case(ROOT / "examples" / "ntua_stern_tube.toml")["bearing"].cases[0]
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
    ross_comparison()
