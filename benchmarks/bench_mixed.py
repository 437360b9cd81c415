"""Mixed-lubrication timings (issue 15 part A): rough equilibria against the smooth path.

Run ``.venv/bin/python benchmarks/bench_mixed.py [--repeat N]``. Prints medians and ratios,
pair by pair in one process (the machine is shared: ratios, not absolute times, are the
measure).

1. NTUA stern tube (seed 004 Table 5-1, examples/ntua_stern_tube.toml), 100 x 60 nodes: one
   load equilibrium smooth and with the turned-steel / white-metal roughness preset, at the
   seed's 90 rpm and psi = 0.3 (full film: the rough path's overhead), and aligned at 1 rpm,
   where the film is mixed (lambda_min 1.4, the asperities carry 3 %). (Misaligned at low
   speed the rigid bore's edge takes the load on a vanishing area: contact, part B's liner.)
   Issue 15 target (with the elastic liner of part B): <= 0.3 s. Beside each rough equilibrium,
   the same with a white-metal and with seed 001's polymer liner, each by the column model
   (part B) and as a bonded elastic layer (film/layer.py), the ratio to the rigid rough one and
   the layer's to the column's. (The layer's transfer function, built once per grid and liner,
   is in the first of the repeats: the median leaves it out.)
2. The same smooth equilibrium as bench_bearing.py, to show the smooth path's time unchanged
   (its stencil is the smooth one: ``rough`` None takes the old code).
3. 30-speed Stribeck curves, warm-started: seed 001's rig (examples/seed001_water_rig.toml,
   41 x 120, 3.5 to 350 rpm) and the NTUA bearing with the turned-steel / white-metal roughness
   (100 x 60, the case's default 9 to 900 rpm), and the rig on its polymer liner
   (examples/seed001_water_rig_liner.toml, column model, the case's 9.5 to 950 rpm), each by
   default (which runs serially below the work estimate of ``stribeck.estimated_seconds``),
   explicitly serially (workers = 1) and on the process pool (backend "process"), alternated
   run by run; ratio to the default.
   Target <= 5 s.
4. Turbulence: seed 001's rig at 350 rpm (water, Re_h up to 7200), the equilibrium laminar and
   with the Ng-Pan coefficients (``[solver] turbulence = "on"``), smooth and rough; ratio to the
   laminar one.
"""

from __future__ import annotations

import sys
from dataclasses import replace
from pathlib import Path

import numpy as np
from timing import median_time

from shaftline.cases import load_case
from shaftline.film import JournalBearing
from shaftline.film.liner import Liner
from shaftline.film.roughness import SurfaceRoughness, gaussian_integral_table
from shaftline.film.stribeck import stribeck_curve

ROOT = Path(__file__).resolve().parents[1]


def main() -> None:
    repeat = int(sys.argv[sys.argv.index("--repeat") + 1]) if "--repeat" in sys.argv else 7
    gaussian_integral_table(2.5)  # built once per process (about 0.05 s): not an equilibrium's cost
    gaussian_integral_table(2.0)
    case = load_case(ROOT / "examples" / "ntua_stern_tube.toml").studies["bearing"].cases[0]
    surface = SurfaceRoughness.preset("turned_steel_white_metal")
    print(f"NTUA stern tube, {case.options.axial_nodes} x {case.options.circumferential_nodes}")
    print("ratio: to the smooth equilibrium; a liner's to the rigid rough one")
    print(f"{'case':60s} {'median s':>9s} {'ratio':>7s} {'h_min um':>9s} {'lambda':>7s} {'share %':>8s}")
    runs = (
        ("90 rpm, psi 0.3 (seed 004)", case.operating.speed, case.tilt_y),
        ("1 rpm, aligned (mixed)", np.pi / 30, 0.0),
    )
    for label, speed, tilt in runs:
        operating = replace(case.operating, speed=speed)
        smooth = JournalBearing(case.geometry, operating, case.options)
        rough = JournalBearing(replace(case.geometry, surface=surface), operating, case.options)
        lined = {
            (name, model): JournalBearing(
                replace(case.geometry, surface=surface, liner=Liner.preset(name, model=model)), operating, case.options
            )
            for name in ("white_metal", "polymer_composite")
            for model in ("column", "layer")
        }

        def solve(bearing: JournalBearing, tilt: float = tilt):  # noqa: ANN202 - benchmark helper
            return bearing.equilibrium(case.load_y, case.load_z, tilt_y=tilt, tilt_z=case.tilt_z)

        # Alternated pair by pair so that both see the same load of the shared machine.
        t_smooth, eq_smooth = median_time(lambda b=smooth: solve(b), repeat)
        t_rough, eq_rough = median_time(lambda b=rough: solve(b), repeat)
        t_lined = {name: median_time(lambda b=b: solve(b), repeat) for name, b in lined.items()}
        s, r = eq_smooth.state, eq_rough.state
        print(
            f"{label + ', smooth':60s} {t_smooth:9.3f} {1.0:7.2f} {s.min_film_thickness * 1e6:9.2f} {'-':>7s} {'-':>8s}"
        )
        print(
            f"{label + ', rough (white metal)':60s} {t_rough:9.3f} {t_rough / t_smooth:7.2f} "
            f"{r.min_film_thickness * 1e6:9.2f} {r.min_film_ratio:7.2f} {100 * r.asperity_load_share:8.3f}"
            + ("" if eq_rough.converged else "  (not converged)")
        )
        for (name, model), (t, eq) in t_lined.items():
            st = eq.state
            versus = f", layer/column {t / t_lined[name, 'column'][0]:.2f}" if model == "layer" else ""
            print(
                f"{label + ', rough + ' + name + ' liner, ' + model:60s} {t:9.3f} {t / t_rough:7.2f} "
                f"{st.min_film_thickness * 1e6:9.2f} {st.min_film_ratio:7.2f} {100 * st.asperity_load_share:8.3f}"
                f"  (max deformation {st.max_liner_deformation * 1e6:.2f} um{versus})"
                + ("" if eq.converged else "  (not converged)")
            )
    rig = load_case(ROOT / "examples" / "seed001_water_rig.toml").studies["bearing"].cases[0]
    fast = replace(rig.operating, speed=350 * np.pi / 30)
    print("\nseed 001 rig at 350 rpm, 41 x 120: laminar against turbulent (Ng-Pan)")
    for label, geometry in (("smooth", replace(rig.geometry, surface=None)), ("rough", rig.geometry)):
        pair = {mode: JournalBearing(geometry, fast, replace(rig.options, turbulence=mode)) for mode in ("off", "on")}
        times: dict[str, list[float]] = {"off": [], "on": []}
        solved = {}
        for _ in range(repeat):  # alternated: both see the same load of the machine
            for mode, bearing in pair.items():
                t, solved[mode] = median_time(lambda b=bearing: b.equilibrium(rig.load_y, rig.load_z), 1)
                times[mode].append(t)
        t_off, t_on = float(np.median(times["off"])), float(np.median(times["on"]))
        eq_off, eq_on = solved["off"], solved["on"]
        print(
            f"{label}: laminar {t_off:.3f} s (h_min {eq_off.state.min_film_thickness * 1e6:.2f} um), turbulent "
            f"{t_on:.3f} s (h_min {eq_on.state.min_film_thickness * 1e6:.2f} um, Re_h max "
            f"{eq_on.state.turbulence.max_reynolds_number:.0f}); ratio {t_on / t_off:.2f}"
        )
    ntua = load_case(ROOT / "examples" / "ntua_stern_tube.toml").studies["bearing"]
    lined = load_case(ROOT / "examples" / "seed001_water_rig_liner.toml").studies["bearing"]
    curves = (
        ("seed 001 rig, 3.5-350 rpm", rig, np.geomspace(3.5, 350.0, 30) * np.pi / 30.0),
        (
            "NTUA, white metal rough, 9-900 rpm",
            replace(ntua.cases[0], geometry=replace(ntua.cases[0].geometry, surface=surface)),
            np.asarray(ntua.stribeck_speeds),
        ),
        (
            "seed 001 rig on its polymer liner (column), 9.5-950 rpm",
            lined.cases[0],
            np.asarray(lined.stribeck_speeds),
        ),
    )
    ways = (("default", {}), ("serial", {"workers": 1}), ("pool", {"backend": "process"}))
    runs = max(3, repeat // 2)
    for label, base, speeds in curves:
        grid = f"{base.options.axial_nodes} x {base.options.circumferential_nodes}"
        print(f"\nStribeck curve, {label}, {speeds.size} speeds, {grid}")
        times: dict[str, list[float]] = {name: [] for name, _ in ways}
        results = {}
        for _ in range(runs):  # alternated way by way: each sees the same load of the machine
            for name, options in ways:
                t, results[name] = median_time(lambda o=options, c=base, v=speeds: stribeck_curve(c, v, **o), 1)
                times[name].append(t)
        reference = float(np.median(times["default"]))
        for name, _ in ways:
            curve = results[name]
            transition = curve.transition_speed * 30.0 / np.pi if curve.transition_speed else float("nan")
            median = float(np.median(times[name]))
            print(
                f"{name:8s} median {median:6.2f} s (runs {', '.join(f'{t:.2f}' for t in times[name])}), "
                f"ratio to default {median / reference:5.2f}; transition {transition:.1f} rpm; "
                f"{int(curve.contact.sum())} speeds in contact, {int(curve.stalled.sum())} not converged"
            )


if __name__ == "__main__":
    main()
