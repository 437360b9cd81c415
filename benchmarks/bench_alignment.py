"""Alignment timing (issue 3 target): a line with 10 bearings and 400 elements, all
conditions plus the influence matrix <= 50 ms median on the 2-core machine.

Run: ``.venv/bin/python benchmarks/bench_alignment.py`` (or ``make bench``).
"""

from __future__ import annotations

import statistics
import time

from shaftline.shaft import AlignmentModel, Bearing, Condition, Propeller, ShaftLine, ShaftSegment


def line() -> ShaftLine:
    bearings = [
        Bearing("aft stern tube", 2.2, 1.5, support="multi_point", points=6, vertical_clearance=1.2e-3),
        Bearing("fwd stern tube", 7.9, 0.7, vertical_clearance=1e-3),
        Bearing("intermediate 1", 13.0, 0.5, support="spring", stiffness=2.5e9),
        Bearing("intermediate 2", 18.5, 0.5),
    ] + [Bearing(f"engine {k}", 23.0 + 1.6 * k, 0.45, offset_y=-1.0e-3, vertical_clearance=0.6e-3) for k in range(6)]
    conditions = (
        Condition("cold ballast", propeller_immersion=0.6),
        Condition("cold laden", offsets_y={f"engine {k}": 0.4e-3 for k in range(6)}),
        Condition("hot laden", offsets_y={f"engine {k}": 0.8e-3 for k in range(6)}),
        Condition("hot ballast", propeller_immersion=0.6, offsets_y={f"engine {k}": 0.6e-3 for k in range(6)}),
    )
    return ShaftLine(
        segments=(ShaftSegment(9.0, 0.76), ShaftSegment(12.0, 0.62), ShaftSegment(11.0, 0.84, inner_diameter=0.3)),
        bearings=tuple(bearings),
        propeller=Propeller(0.55, 62000.0),
        conditions=conditions,
        element_length=32.0 / 400,
    )


def job(shaft: ShaftLine):
    model = AlignmentModel(shaft)
    return model, model.solve(), model.influence_matrix()


def main() -> None:
    shaft = line()
    job(shaft)
    times = []
    for _ in range(30):
        start = time.perf_counter()
        model, results, _ = job(shaft)
        times.append(time.perf_counter() - start)
    median = statistics.median(times)
    print(
        f"Alignment: {len(shaft.bearings)} bearings, {model.mesh.nodes - 1} elements, "
        f"{len(results)} conditions + influence matrix"
    )
    print(
        f"  model + all conditions + influence matrix: {median * 1e3:.1f} ms median "
        f"(target <= 50 ms, ratio {median / 0.050:.2f})"
    )


if __name__ == "__main__":
    main()
