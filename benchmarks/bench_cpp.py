"""Blade-carrier motion: speed before and after issue 10, and the time-step convergence.

Run: ``PYTHONPATH=src .venv/bin/python benchmarks/bench_cpp.py`` from the repository (the
"before" kernel is read from git at :data:`BEFORE`; without git that row is left out).

Speed (issue 10 target: 100 revolutions of LuGre at 150 rpm in <= 0.3 s; 0.84-0.90 s
before): medians of 5 runs, each integrator's ratio to the backward-Euler kernel before,
taken in this process one after the other.

Convergence: the amplitude of the settled (periodic) revolution of the same case against
the steps per revolution, each method's error against TR-BDF2 at 92 160 steps a revolution,
and the observed order log2(e(h) / e(h/2)), which should be about 2 for TR-BDF2 and 1 for
backward Euler. scipy's Radau (rtol 1e-6) is printed as an independent check.
"""

from __future__ import annotations

import importlib.util
import subprocess
import sys
import tempfile
from functools import partial
from pathlib import Path
from types import ModuleType

import numpy as np
from timing import median_time

from shaftline.cpp.motion import CarrierModel, _parameters, simulate_carrier

ROOT = Path(__file__).resolve().parents[1]

#: The commit whose compiled backward Euler is "before" (main when issue 10 was taken up).
BEFORE = "9f6e95a"

#: Revolutions of the convergence table: the case is periodic to 1e-7 after 20.
CONVERGENCE_REVOLUTIONS = 20


def benchmark_model() -> CarrierModel:
    angle = np.linspace(0, 2 * np.pi, 361)[:-1]
    return CarrierModel(
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


def kernel_before(folder: Path) -> ModuleType | None:
    """The compiled carrier kernel of commit :data:`BEFORE`, loaded as its own module (its
    numba cache goes to ``folder``), or None without git."""
    try:
        source = subprocess.run(
            ["git", "show", f"{BEFORE}:src/shaftline/cpp/_carrier.py"],
            cwd=ROOT,
            capture_output=True,
            text=True,
            check=True,
        ).stdout
    except (OSError, subprocess.CalledProcessError):
        return None
    path = folder / "carrier_before.py"
    path.write_text(source)
    spec = importlib.util.spec_from_file_location("carrier_before", path)
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    sys.modules["carrier_before"] = module
    spec.loader.exec_module(module)
    return module


def speed(model: CarrierModel) -> None:
    print("Speed: LuGre, 100 revolutions at 150 rpm (issue 10 target <= 0.3 s), medians of 5")
    rows: list[tuple[str, float, str]] = []
    with tempfile.TemporaryDirectory() as folder:
        before = kernel_before(Path(folder))
        if before is not None:
            p = before.CarrierParameters(*_parameters(model))
            step = 2 * np.pi / model.speed / 7200

            def run_before() -> object:
                return before.backward_euler(p, step, 100 * 7200, 10)

            run_before()  # compile
            seconds, _ = median_time(run_before)
            rows.append((f"before ({BEFORE}): backward Euler, 7200 steps/rev, 100 rev", seconds, ""))
    simulate_carrier(model, 2, method="backward_euler")  # compile
    cases = [
        ("backward Euler, 7200 steps/rev, 100 rev (new kernel)", "backward_euler", False),
        ("TR-BDF2, 2880 steps/rev, all 100 rev", "trbdf2", False),
        ("TR-BDF2, 2880 steps/rev, stop at periodic state (default)", "trbdf2", True),
    ]
    for label, method, stop in cases:
        motion = simulate_carrier(model, 100, method=method, stop_when_periodic=stop)
        seconds, _ = median_time(partial(simulate_carrier, model, 100, method=method, stop_when_periodic=stop))
        rows.append((label, seconds, f"{motion.revolutions} rev integrated, periodic: {motion.periodic}"))
    reference = rows[0][1]
    for label, seconds, note in rows:
        print(f"  {label:62s} {seconds:6.3f} s  ratio {seconds / reference:5.3f}  ", end="")
        print(f"target ratio {seconds / 0.3:5.2f}  {note}")


def convergence(model: CarrierModel) -> None:
    n = CONVERGENCE_REVOLUTIONS
    print(f"\nTime-step convergence: amplitude of revolution {n} (periodic to 1e-7), um at the bearing radius")

    def amplitude(method: str, steps: int | None) -> float:
        motion = simulate_carrier(model, n, method=method, steps_per_revolution=steps, stop_when_periodic=False)
        return float(motion.amplitude[-1]) * 1e6

    reference = amplitude("trbdf2", 92160)
    print(f"  reference TR-BDF2, 92160 steps/rev: {reference:.6f} um; scipy Radau: {amplitude('radau', None):.6f} um")
    for method, steps in (
        ("trbdf2", (720, 1440, 2880, 5760, 11520)),
        ("backward_euler", (1440, 2880, 5760, 11520, 23040)),
    ):
        print(f"  {method}")
        previous = None
        for count in steps:
            value = amplitude(method, count)
            error = abs(value - reference) / reference
            order = f"   observed order {np.log2(previous / error):.2f}" if previous else ""
            print(f"    {count:6d} steps/rev  {value:.6f} um  relative error {error:.2e}{order}")
            previous = error


def main() -> None:
    model = benchmark_model()
    speed(model)
    convergence(model)


if __name__ == "__main__":
    main()
