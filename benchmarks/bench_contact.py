"""Lubricated-contact evaluation timing (issue 14 target): Hertz + film + Lambda + seed 002
friction on a load-stage x speed x path map, 12 x 50 x 200 = 120 000 points, <= 1 s.

The map stands in for part B's gear mesh: along a path of 200 points the radius of curvature,
surface speeds and load vary as on a spur gear (radii 8-40 mm, sliding through zero at the
pitch point); 12 load stages scale the load, 50 pinion speeds the surface speeds. One call of
:func:`shaftline.contact.lubricated.evaluate` on broadcast arrays; no loop over points.
Prints medians of 5 runs (line contacts; point contacts with the exact ellipticity and with
the Hamrock-Brewe fits) and the ratio to the target.

Run: ``.venv/bin/python benchmarks/bench_contact.py``.
"""

from __future__ import annotations

import numpy as np
from timing import median_time

from shaftline.contact.lubricated import ContactModel, Surfaces, evaluate
from shaftline.contact.rheology import contact_lubricant

TARGET = 1.0


def gear_like_map(stages: int = 12, speeds: int = 50, points: int = 200) -> dict[str, np.ndarray]:
    """Arrays of shape (stages, speeds, points) by broadcasting, as a gear path would give."""
    t = np.linspace(0.0, 1.0, points)[None, None, :]  # position along the path A..E
    rho_1 = 0.010 + 0.030 * t  # pinion radius of curvature grows along the path, m
    rho_2 = 0.040 - 0.030 * t
    radius = rho_1 * rho_2 / (rho_1 + rho_2)
    omega = np.linspace(100.0, 1900.0, speeds)[None, :, None]  # pinion speed, rad/s
    u1 = omega * rho_1
    u2 = omega * rho_2  # equal teeth: the wheel turns at the pinion's speed
    # load sharing: double-tooth contact near the ends of the path carries less per tooth
    share = np.where((t < 0.3) | (t > 0.7), 0.6, 1.0)
    load = np.linspace(1e5, 6e5, stages)[:, None, None] * share  # N/m
    shape = (stages, speeds, points)
    # every input at full size, as a mesh gives them (nothing left to broadcasting)
    return {
        "load": np.broadcast_to(load, shape).copy(),
        "speed_1": np.broadcast_to(u1, shape).copy(),
        "speed_2": np.broadcast_to(u2, shape).copy(),
        "radius_x": np.broadcast_to(radius, shape).copy(),
        "radius_y": np.broadcast_to(radius * (4.0 + 8.0 * t), shape).copy(),
    }


def main() -> None:
    arrays = gear_like_map()
    surfaces = Surfaces(roughness_1=0.5e-6, roughness_2=0.125e-6)
    lubricant = contact_lubricant("MIL-PRF-23699")
    size = np.broadcast_shapes(*(a.shape for a in arrays.values()))
    n = int(np.prod(size))
    line = ContactModel(lubricant, "line", extrapolate=True)
    import warnings

    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        line_arrays = {k: v for k, v in arrays.items() if k != "radius_y"}
        seconds, state = median_time(lambda: evaluate(line, surfaces, temperature=90.0, **line_arrays))
        print(
            f"line contacts, {size[0]} x {size[1]} x {size[2]} = {n} points: {seconds:.3f} s median "
            f"(target <= {TARGET:g} s, ratio {seconds / TARGET:.2f}); {n / seconds / 1e6:.2f} M points/s; "
            f"f from {float(state.friction.min()):.3f} to {float(state.friction.max()):.3f}"
        )
        for method in ("exact", "hamrock_brewe"):
            point = ContactModel(lubricant, "point", ellipticity_method=method, extrapolate=True)
            load = arrays["load"] * 0.02  # N on a crowned tooth
            seconds, _ = median_time(
                lambda point=point, load=load: evaluate(
                    point,
                    surfaces,
                    load=load,
                    speed_1=arrays["speed_1"],
                    speed_2=arrays["speed_2"],
                    temperature=90.0,
                    radius_x=arrays["radius_x"],
                    radius_y=arrays["radius_y"],
                )
            )
            print(
                f"point contacts ({method}), {n} points: {seconds:.3f} s median "
                f"(target <= {TARGET:g} s, ratio {seconds / TARGET:.2f})"
            )


if __name__ == "__main__":
    main()
