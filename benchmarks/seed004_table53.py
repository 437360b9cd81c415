"""Seed 004 Table 5-3 (linear shaft, psi_x = 0.3) against the project: the evidence for the
open discrepancy in docs/validation.md ("Seed 004 Table 5-3: the gap", issue 11).

Run ``PYTHONPATH=src .venv/bin/python benchmarks/seed004_table53.py`` (about 20 s). Prints:

1. the three linear-shaft cases of ``examples/ntua_stern_tube.toml`` with the project's
   defaults (periodic film, film-fraction shear) and in "R&B mode" (``film_start="max_film"``,
   ``cavitated_shear="full_film"``: an ambient-pressure line at the largest film and shear
   over the whole clearance, as Raimondi & Boyd's charts count it) beside the thesis's values;
2. the bore anchor (where the slope-bored bore meets the nominal axis: fore, mid or aft end)
   does not change h_min, p_max, power loss or the support point, i.e. where an eccentricity is
   referred to cannot explain the gap;
3. the psi_x at which the no-slope h_min equals the thesis's 79.1 um, and p_max and power loss
   there (against 1.56 MPa and 2.395 kW), and the defaults at psi_x = 0.365;
4. readings of the double-slope bore, none of which gives the thesis's 145 um, 1.42 MPa and a
   support point forward of mid-length (-0.0417 m in its + aft convention).

The support point is printed in the thesis's sign (+ aft of mid-length), the opposite of the
project's ``load_centre_offset`` (+ forward). Numbers are quoted in docs/validation.md.
"""

from __future__ import annotations

from dataclasses import replace
from pathlib import Path

import numpy as np
from scipy.optimize import brentq

from shaftline.cases import load_case
from shaftline.film.bearing import BearingState, JournalBearing
from shaftline.film.geometry import BearingGeometry, FilmProfile
from shaftline.film.study import BearingCase

EXAMPLE = Path(__file__).resolve().parents[1] / "examples" / "ntua_stern_tube.toml"
#: Seed 004 Table 5-3, linear shaft: h_min [um], p_max [MPa], support from L/2 [m, + aft], P_loss [kW].
THESIS = {
    "no slope": (79.1, 1.56, 0.074414, 2.395),
    "single slope": (175.0, 1.22, -4.62e-5, 2.342),
    "double slope": (145.0, 1.42, -0.041679, 2.352),
}
MODES = {"default": {}, "R&B": {"film_start": "max_film", "cavitated_shear": "full_film"}}


def cases() -> dict[str, BearingCase]:
    study = load_case(EXAMPLE)["bearing"]
    return {case.name.split(",")[-1].strip(): case for case in study.cases}


def solve(
    case: BearingCase, mode: str = "default", psi: float | None = None, geometry: BearingGeometry | None = None
) -> BearingState:
    """Equilibrium state of ``case`` (optionally at another psi_x or bore) in a solver mode."""
    geometry = geometry or case.geometry
    tilt = case.tilt_y if psi is None else psi * 2.0 * geometry.radial_clearance / geometry.length
    bearing = JournalBearing(geometry, case.operating, replace(case.options, **MODES[mode]))
    equilibrium = bearing.equilibrium(case.load_y, case.load_z, tilt_y=tilt)
    assert equilibrium.converged and not equilibrium.contact, case.name
    return equilibrium.state


def row(state: BearingState) -> tuple[float, float, float, float]:
    """h_min [um], p_max [MPa], support from L/2 [m, + aft as the thesis], P_loss [kW]."""
    return (
        state.min_film_thickness * 1e6,
        state.max_pressure / 1e6,
        -state.load_centre_offset,
        state.power_loss / 1e3,
    )


def show(label: str, values: tuple[float, ...], reference: tuple[float, ...] | None = None) -> None:
    text = f"{values[0]:7.1f} um {values[1]:6.3f} MPa {values[2]:+8.4f} m {values[3]:6.3f} kW"
    if reference is not None:
        h, p, _, w = (100.0 * (a / b - 1.0) for a, b in zip(values, reference, strict=True))
        text += f"   (h_min {h:+5.1f} %, p_max {p:+5.1f} %, P_loss {w:+5.1f} %)"
    print(f"  {label:<44s}{text}")


def literal_bore(geometry: BearingGeometry, origin: float) -> BearingGeometry:
    """Seed 004 Eq. (55) read literally: bore offset y * slope[j] with y from ``origin`` (m from
    the aft edge) and slope[j] the slope of the segment at station j (a step at the knuckle),
    as an additive film change delta = offset * cos(theta)."""
    length = geometry.length
    fractions = np.cumsum([s.length_fraction for s in geometry.bore])
    knuckle = fractions[0] * length
    z = np.array([0.0, knuckle - 1e-9 * length, knuckle + 1e-9 * length, length])
    slope = np.where(z < knuckle, geometry.bore[0].slope, geometry.bore[1].slope)
    theta = np.linspace(0.0, 2 * np.pi, 721)[:-1]
    delta = ((z - origin) * slope)[:, None] * np.cos(theta)[None, :]
    return replace(geometry, bore=(), film_profile=FilmProfile(theta, z, delta))


def main() -> None:
    all_cases = cases()
    print("1. Table 5-3, linear shaft, psi_x = 0.3")
    for name, case in all_cases.items():
        print(f" {name}")
        show("thesis", THESIS[name])
        for mode in MODES:
            state = solve(case, mode)
            show(
                f"{mode} (eps {state.eccentricity_ratio:.3f}, att {np.degrees(state.attitude_angle):.1f} deg)",
                row(state),
                THESIS[name],
            )

    print("2. Bore anchor of the double slope (default mode): the film does not depend on it")
    double = all_cases["double slope"]
    for anchor in ("fore", "mid", "aft"):
        state = solve(double, geometry=replace(double.geometry, bore_anchor=anchor))
        show(f"anchor {anchor}, ey {state.position.ey * 1e6:+.1f} um", row(state))

    print("3. psi_x giving the thesis's no-slope h_min of 79.1 um")
    base = all_cases["no slope"]
    for mode in MODES:
        psi = brentq(lambda p, m=mode: solve(base, m, psi=p).min_film_thickness * 1e6 - 79.1, 0.3, 0.45, xtol=1e-5)
        show(f"{mode}: psi_x = {psi:.4f}", row(solve(base, mode, psi=psi)), THESIS["no slope"])
    show("default: psi_x = 0.365", row(solve(base, psi=0.365)), THESIS["no slope"])

    print("4. Readings of the double-slope bore (thesis 145 um, 1.42 MPa, support -0.0417 m, + aft)")
    g = double.geometry
    first, second = g.bore
    readings = {
        "as printed: aft 0.61 L at 0.31, fore 0.39 L at 0.11": g,
        "segments reversed: aft 0.39 L at 0.11, fore 0.61 L at 0.31": replace(
            g, bore=(replace(second, length_fraction=0.39), replace(first, length_fraction=0.61))
        ),
        "slopes swapped: aft 0.61 L at 0.11, fore 0.39 L at 0.31": replace(
            g, bore=(replace(first, slope=second.slope), replace(second, slope=first.slope))
        ),
        "cumulative: aft 0.61 L at 0.42, fore 0.39 L at 0.11": replace(
            g, bore=(replace(first, slope=first.slope + second.slope), second)
        ),
        "Eq. 55 literal, y from the aft edge": literal_bore(g, 0.0),
        "Eq. 55 literal, y from mid-length": literal_bore(g, 0.5 * g.length),
        "Eq. 55 literal, y from the fore edge": literal_bore(g, g.length),
    }
    for label, geometry in readings.items():
        print(f" {label}")
        for mode in MODES:
            show(mode, row(solve(double, mode, geometry=geometry)), THESIS["double slope"])


if __name__ == "__main__":
    main()
