"""The bearings of ``[alignment]``: ``[[alignment.bearings]]``, each a point, spring or
multi-point support or a film."""

from __future__ import annotations

from typing import Annotated, Literal

from pydantic import Field, StrictBool

from shaftline.cases.types import Angle, Plausible, PositiveLength, PositiveStiffness, Section, default_of
from shaftline.shaft.case_film import FilmSection
from shaftline.shaft.case_ranges import EXAMPLE_CASE, OFFSET, X
from shaftline.shaft.model import Bearing

SupportModel = Literal["point", "spring", "multi_point"]
SupportPosition = Literal["centre", "aft_third"]
Material = Literal["white_metal", "synthetic", "rubber", "bronze", "composite", "lignum_vitae", "engine", "roller"]


class SupportSection(Section):
    """A bearing of the line: its position, offsets and support model."""

    name: str
    """Name (conditions, rules and procedures refer to it)."""
    x: X
    """Centre of the bearing."""
    length: Annotated[
        PositiveLength,
        Plausible(
            0.02,
            4.0,
            "aft stern-tube bearings up to about 2-2.5 m (L/D about 2 on the largest shafts), engine and "
            f"intermediate bearings 0.2-0.6 m ({EXAMPLE_CASE}: 0.45-1.5 m); 20 mm covers small craft "
            "(engineering judgement)",
        ),
    ]
    """Bearing length."""
    offset_y: OFFSET = default_of(Bearing, "offset_y")
    """Vertical offset of the bearing from the reference line (+ up)."""
    offset_z: OFFSET = default_of(Bearing, "offset_z")
    """Horizontal offset (+ starboard)."""
    vertical_clearance: (
        Annotated[
            PositiveLength,
            Plausible(
                2e-5,
                0.04,
                f"diametral clearances are about 1e-3 to 2e-3 of the diameter ({EXAMPLE_CASE}: 0.6-1.2 mm; seed 004: "
                "0.9 mm), several mm in worn water-lubricated bearings (engineering judgement); mm written as m is "
                "far above",
            ),
        ]
        | None
    ) = None
    """Diametral clearance: the shaft touches the top of the bore after it (none: no top)."""
    material: Material = default_of(Bearing, "material")
    """Lining material (selects the class rules that apply); engine: limits of the engine maker."""
    support: SupportModel = default_of(Bearing, "support")
    """Rigid point, spring, or several points along a long bearing."""
    stiffness: (
        Annotated[
            PositiveStiffness,
            Plausible(
                1e6,
                1e12,
                f"bearing and foundation stiffnesses of ship lines are about 1e8 to 1e10 N/m ({EXAMPLE_CASE}: 2.5e9) "
                "(engineering judgement); kN/mm written as a bare number (N/m) is far below",
            ),
        ]
        | None
    ) = None
    """Support stiffness of a spring support."""
    points: Annotated[int, Field(ge=1, le=50)] = default_of(Bearing, "points")
    """Support points of a multi-point support."""
    position: SupportPosition = default_of(Bearing, "position")
    """Where a point support acts: the centre or a third of the length from the aft end."""
    one_sided: StrictBool = default_of(Bearing, "one_sided")
    """The shaft can lift off (the bearing only pushes up)."""
    slope: Annotated[
        Angle,
        Plausible(
            -0.01,
            0.01,
            "slope-bored stern-tube bearings are inclined by about 0.1-1 mrad (class limit of the relative slope "
            "about 0.3 mrad, rules.toml); 10 mrad (0.57 deg) is ten times that, mrad or deg written as a bare "
            "number (rad) is far above (engineering judgement)",
        ),
    ] = default_of(Bearing, "slope")
    """The bearing's own slope (slope boring)."""
    film: FilmSection | StrictBool = False
    """true: supported by the film of [alignment.film]; a table: its own film; false: the support above."""
