"""Fretting-motion timing (issue 4 target): 100 revolutions with LuGre <= 2 s median.

Run: ``.venv/bin/python benchmarks/bench_cpp.py``.
"""

from __future__ import annotations

import statistics
import time

import numpy as np

from shaftline.cpp.motion import CarrierModel, simulate_carrier


def main() -> None:
    angle = np.linspace(0, 2 * np.pi, 361)[:-1]
    model = CarrierModel(
        inertia=1500.0,
        water_inertia=500.0,
        speed=150 * 2 * np.pi / 60,
        angle=angle,
        spindle_torque=3.0e4 + 3.6e5 * np.cos(angle + 2.4) + 1.0e5 * np.cos(2 * angle + 0.5),
        coulomb_torque=3.4e5 * (1 + 0.2 * np.cos(angle)),
        oil_stiffness=5.7e9,
        pin_radius=0.3,
        pitch_angle=np.radians(28.0),
        friction="lugre",
    )
    simulate_carrier(model, 1)  # compile (cached on disk afterwards)
    times = []
    for _ in range(5):
        start = time.perf_counter()
        motion = simulate_carrier(model, 100)
        times.append(time.perf_counter() - start)
    median = statistics.median(times)
    print(
        f"Fretting motion, LuGre, 100 revolutions at 150 rpm: {median:.2f} s median "
        f"(target <= 2 s, ratio {median / 2:.2f}); amplitude {motion.amplitude[-1] * 1e6:.1f} um"
    )


if __name__ == "__main__":
    main()
