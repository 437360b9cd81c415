"""Seed 004's robustness comparison (Tables 5-14/5-15, psi_x = 0.3): the single slope 0.3 against
the seed's double slope (0.31 over 0.61 L, 0.11 over 0.39 L) in its seven scenarios, on the linear
and the bent shaft (local model of Table 4-5), 100 x 60 film. Prints h_min per scenario and the
smallest; docs/validation.md ("Slope-boring design") quotes it.

    python benchmarks/seed004_robustness.py [AXIAL CIRCUMFERENTIAL]
"""

from __future__ import annotations

import sys

import numpy as np

from shaftline.design import SlopeDesignProblem
from shaftline.design.robustness import SEED_SCENARIOS, robustness
from shaftline.design.shaft_models import bent_shaft, linear_shaft
from shaftline.film import BearingProblem, OperatingPoint, SolverOptions
from shaftline.film.geometry import BearingGeometry
from shaftline.lubricants import OIL_EXPANSION, Lubricant
from shaftline.shaft.local import seed004_local_model


def main() -> None:
    nz, nt = (int(sys.argv[1]), int(sys.argv[2])) if len(sys.argv) > 2 else (100, 60)
    c, length = 0.45e-3, 1.05
    film = BearingProblem(
        BearingGeometry(length, 0.52, c),
        OperatingPoint(speed=9.42477796076938, viscosity=0.07, density=890.0),
        SolverOptions(axial_nodes=nz, circumferential_nodes=nt),
    )
    base = SlopeDesignProblem(film, -309859.9)
    # SAE 30 through the seed's own viscosities: 0.07 Pa s at 40 degC, 0.026 Pa s at 60 degC
    rho40, rho60 = 890.0 * (1 - OIL_EXPANSION * 25), 890.0 * (1 - OIL_EXPANSION * 45)
    oil = Lubricant.from_two_points("SAE 30 (seed)", 40.0, 0.07 / rho40, 60.0, 0.026 / rho60, 890.0)
    designs = np.array([[0.3, 0.3, 0.5], [0.31, 0.11, 0.61]])
    print(f"film {nz} x {nt}; h_min [um] at the operating point, then " + ", ".join(s.name for s in SEED_SCENARIOS))
    for shaft, at in (("linear", linear_shaft(base)), ("bent", bent_shaft(base, seed004_local_model()))):
        result = robustness(
            at(0.3), designs, names=["single 0.3", "double (seed)"], lubricant=oil, temperature=40.0, backend="serial"
        )
        for k, name in enumerate(result.names):
            values = [result.reference[k].values["min_film_thickness"]]
            values += [e.values["min_film_thickness"] for e in result.evaluations[k]]
            row = " ".join(f"{v * 1e6:6.1f}" for v in values)
            print(f"  {shaft:6s} {name:14s} {row}   smallest {min(values) * 1e6:.1f}")


if __name__ == "__main__":
    main()
