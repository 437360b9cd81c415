"""Gear scuffing along the mesh (issue 14 target): load sharing + Hertz + film + Lambda + seed 002
friction + frictional-power integrals (SP) and ISO's flash temperature on a load-stage x speed x
path map, 12 x 50 x 200 = 120 000 points, <= 1 s.

Seed 002's test gears (28/28, module 5 mm, 20 deg, MIL-PRF-23699 at 90 degC): 12 torque steps
to 500 N m, 50 pinion speeds to 18 000 rpm, 200 points A..E. One call of
:func:`shaftline.gears.scuffing.evaluate_mesh` and one of :func:`shaftline.gears.flash.iso_scuffing`;
and ISO/TS 6336-21's integral temperature; medians of 5 runs and the ratio to the target.

Run: ``.venv/bin/python benchmarks/bench_gears.py``.
"""

from __future__ import annotations

import math
import warnings
from dataclasses import replace

import numpy as np
from timing import median_time

from shaftline.contact.lubricated import ContactModel, Surfaces
from shaftline.contact.rheology import contact_lubricant
from shaftline.gears.flash import FLASH_METHODS, IsoScuffingData, iso_scuffing
from shaftline.gears.integral import integral_temperature
from shaftline.gears.mesh import GearPair
from shaftline.gears.scuffing import GearMesh, evaluate_mesh, scuffing_parameter

TARGET = 1.0


def main() -> None:
    pair = GearPair(28, 28, 5e-3, math.radians(20.0), 20e-3)
    lubricant = contact_lubricant("MIL-PRF-23699")
    rq = math.sqrt(math.pi / 2)
    mesh = GearMesh(
        pair, ContactModel(lubricant, extrapolate=True), Surfaces(roughness_1=0.4e-6 * rq, roughness_2=0.1e-6 * rq)
    )
    torque = np.linspace(500.0 / 12, 500.0, 12)[:, None, None]
    speed = np.linspace(1000.0, 18000.0, 50)[None, :, None] * math.pi / 30
    n = 12 * 50 * mesh.points
    eta = float(lubricant.dynamic_viscosity(90.0))
    data = IsoScuffingData(8, base_oil="phosphate ester", roughness_ra=0.25e-6)

    def seed() -> np.ndarray:
        state = evaluate_mesh(mesh, torque, speed, 90.0)
        return scuffing_parameter(state.power_integral, 5000.0, 126.0, 90.0)

    def iso() -> np.ndarray:
        rho = mesh.positions()
        integral_temperature(pair, data, torque[..., 0], speed[..., 0], 90.0, eta, 25e-6)  # TS 6336-21
        return iso_scuffing(pair, data, torque, speed, 90.0, eta, mesh.load_sharing(rho), rho).safety

    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # slow, light corners leave the fit range of seed Eq. 6 (extrapolated)
        seconds, sp = median_time(seed)
        print(
            f"seed 002 SP, 12 x 50 x {mesh.points} = {n} points: {seconds:.3f} s median "
            f"(target <= {TARGET:g} s, ratio {seconds / TARGET:.3f}); SP {sp.min():.3f}-{sp.max():.3f} "
            "(C = 5000 W/(m K))"
        )
        iso_seconds, safety = median_time(iso)
        print(
            f"ISO flash (TS 6336-20) and integral (-21) temperature, {n} points: {iso_seconds:.3f} s median; "
            f"S_B {safety.min():.2f}-{safety.max():.2f}; "
            f"both: {seconds + iso_seconds:.3f} s (ratio {(seconds + iso_seconds) / TARGET:.3f})"
        )
        # the flash-temperature forms of gears.flash.FLASH_METHODS, pair by pair in this process
        rho = mesh.positions()
        share = mesh.load_sharing(rho)
        times = {}
        for method in FLASH_METHODS:
            form = replace(data, flash_method=method)
            times[method], _ = median_time(
                lambda form=form: iso_scuffing(pair, form, torque, speed, 90.0, eta, share, rho)
            )
        first = next(iter(times))
        print(
            "ISO flash temperature alone, by form: "
            + ", ".join(f"{m} {t:.3f} s (ratio {t / times[first]:.2f})" for m, t in times.items())
        )


if __name__ == "__main__":
    main()
