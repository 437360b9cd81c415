"""Plausible ranges shared by the tables of ``[alignment]``: stations, diameters, offsets,
forces and materials of a ship's shaft line."""

from __future__ import annotations

from typing import Annotated

from shaftline.cases.types import Length, Plausible

#: The worked example the ranges quote.
EXAMPLE_CASE = "examples/single_screw_alignment.toml"

# Plausible ranges of a ship's shaft line (the README's table of plausible ranges is made
# from them): generous, to catch a unit slip (a bare number is SI: 2200 meant in mm is 2.2 km),
# not an unusual line, which a case lists in [case] unusual.
X = Annotated[
    Length,
    Plausible(
        -30.0,
        300.0,
        "stations from the aft end of the model: the propeller overhangs a few m aft, the longest lines (engine "
        f"room amidships) are about 100 m; {EXAMPLE_CASE}: 0.55-28.8 m (engineering judgement); mm written as m is "
        "beyond 300 m",
    ),
]
SHAFT_DIAMETER = Plausible(
    0.02,
    3.0,
    "propeller shafts from about 25 mm (small craft) to about 1.2 m (the largest ships), flanges up to about "
    f"2 m; {EXAMPLE_CASE}: 0.62-1.25 m (engineering judgement)",
)
BORE = Plausible(0.0, 2.5, "a hollow shaft's bore is smaller than its outer diameter (the larger range above)")
YOUNGS_MODULUS = Plausible(
    1e9,
    1e12,
    "shaft steels about 206 GPa, composite shafts 20-150 GPa (engineering judgement); GPa or MPa written as a "
    "bare number (Pa) is far below",
)
SHAFT_DENSITY = Plausible(
    1000.0,
    30000.0,
    "steel 7850 kg/m^3, composite shafts about 1600; an equivalent crankshaft may take a modified density "
    "(engineering judgement); g/cm^3 as a bare number is far below",
)
OFFSET = Annotated[
    Length,
    Plausible(
        -0.05,
        0.05,
        f"bearing offsets from the reference line are a few mm ({EXAMPLE_CASE}: up to 1.6 mm plus 0.9 mm of hull and "
        "thermal change); 50 mm is ten times the largest (engineering judgement), an offset in mm written as a "
        "bare number (m) is above it",
    ),
]
LINE_FORCE = Plausible(
    -3e7,
    3e7,
    "forces on a shaft line are at most a few MN (the largest propellers weigh 1.3 MN); 30 MN is ten times "
    "that (engineering judgement)",
)
LINE_MOMENT = Plausible(
    -1e8,
    1e8,
    f"eccentric-thrust moments of the largest propellers are a few MN m ({EXAMPLE_CASE}: 0.35 MN m); 100 MN m is "
    "ten times beyond (engineering judgement)",
)
#: Density of shaft steel, kg/m^3: the scale of the propeller-mass check (not the model's density).
STEEL = 7850.0
