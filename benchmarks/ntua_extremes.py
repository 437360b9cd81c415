"""h_min and p_max between nodes (issue 11) on the seed 004 NTUA stern tube: node values and the
local quadratic fit of :func:`shaftline.film.extremes.local_extreme` on 100 x 60 against the
fitted values on 400 x 240 and 800 x 480.

Run ``PYTHONPATH=src .venv/bin/python benchmarks/ntua_extremes.py`` (about 30 s). Two
comparisons per case: at one journal position (the 400 x 240 equilibrium), where only the
location of the extreme between nodes differs between the grids besides the Reynolds
solution's own discretisation; and at each grid's own equilibrium, where the equilibrium
position also moves with the grid. Numbers are quoted in docs/validation.md.
"""

from __future__ import annotations

from dataclasses import replace
from pathlib import Path

from shaftline.cases import load_case
from shaftline.film.bearing import JournalBearing
from shaftline.film.study import BearingCase

EXAMPLE = Path(__file__).resolve().parents[1] / "examples" / "ntua_stern_tube.toml"
GRIDS = ((100, 60), (200, 120), (400, 240), (800, 480))


def bearing(case: BearingCase, nodes: tuple[int, int]) -> JournalBearing:
    options = replace(case.options, axial_nodes=nodes[0], circumferential_nodes=nodes[1])
    return JournalBearing(case.geometry, case.operating, options)


def main() -> None:
    cases = load_case(EXAMPLE)["bearing"].cases
    c, length = cases[0].geometry.radial_clearance, cases[0].geometry.length
    runs = [("no slope", cases[0], 0.3), ("no slope", cases[0], 0.6), ("no slope", cases[0], 0.7)]
    runs += [("double slope", cases[2], 0.3)]
    print("case, psi_x | grid | fixed position: p_max fit / node [MPa] | equilibrium: p_max fit / node [MPa],")
    print("            |      |                                        | h_min fit / node [um]")
    for name, case, psi in runs:
        tilt = psi * 2 * c / length
        reference = bearing(case, (400, 240)).equilibrium(case.load_y, case.load_z, tilt_y=tilt).state.position
        rows = {}
        for nodes in GRIDS:
            b = bearing(case, nodes)
            fixed = b.solve_at(reference, warm_start=False)
            eq = b.equilibrium(case.load_y, case.load_z, tilt_y=tilt).state
            rows[nodes] = (fixed.max_pressure, float(fixed.pressure.max()), eq.max_pressure, float(eq.pressure.max()))
            print(
                f"{name}, {psi:.1f} | {nodes[0]}x{nodes[1]} | {fixed.max_pressure / 1e6:.4f} / "
                f"{fixed.pressure.max() / 1e6:.4f} | {eq.max_pressure / 1e6:.4f} / {eq.pressure.max() / 1e6:.4f}, "
                f"{eq.min_film_thickness * 1e6:.3f} / {eq.film.min() * 1e6:.3f}"
            )
        fine_fixed, fine_eq = rows[(400, 240)][0], rows[(400, 240)][2]
        fit_fixed, node_fixed, fit_eq, node_eq = rows[(100, 60)]
        print(
            f"  100x60 against 400x240 (fitted): fixed position fit {100 * (fit_fixed / fine_fixed - 1):+.2f} %, "
            f"node {100 * (node_fixed / fine_fixed - 1):+.2f} %; "
            f"equilibrium fit {100 * (fit_eq / fine_eq - 1):+.2f} %, "
            f"node {100 * (node_eq / fine_eq - 1):+.2f} %"
        )


if __name__ == "__main__":
    main()
