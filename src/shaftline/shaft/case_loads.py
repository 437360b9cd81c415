"""The loads and load conditions of ``[alignment]``: point loads, masses, distributed
loads and ``[[alignment.conditions]]``."""

from __future__ import annotations

from typing import Annotated

from shaftline.cases.types import Force, ForcePerLength, Fraction, Moment, Plausible, PositiveMass, Section, default_of
from shaftline.shaft.case_ranges import LINE_FORCE, LINE_MOMENT, OFFSET, X
from shaftline.shaft.model import DistributedLoad, PointLoad


class PointLoadSection(Section):
    """A point force and moment on the shaft."""

    x: X
    """Station."""
    force_y: Annotated[Force, LINE_FORCE] = default_of(PointLoad, "force_y")
    """Vertical force (+ up)."""
    force_z: Annotated[Force, LINE_FORCE] = default_of(PointLoad, "force_z")
    """Horizontal force (+ starboard)."""
    moment_vertical: Annotated[Moment, LINE_MOMENT] = default_of(PointLoad, "moment_vertical")
    """Moment in the vertical plane (+ turning +x towards +y)."""
    moment_horizontal: Annotated[Moment, LINE_MOMENT] = default_of(PointLoad, "moment_horizontal")
    """Moment in the horizontal plane (+ turning +x towards +z)."""
    name: str = ""
    """Label."""


class MassSection(Section):
    """A point mass (flywheel, coupling): its weight acts at x."""

    x: X
    """Station."""
    mass: Annotated[
        PositiveMass,
        Plausible(
            0.1,
            5e5,
            "couplings, flywheels, gears and rotors from kg to some tens of t (the example's flywheel: 14 t); "
            "500 t is beyond any shaft-line mass (engineering judgement)",
        ),
    ]
    """Mass."""
    name: str = ""
    """Label."""


DISTRIBUTED_LOAD = Plausible(
    -1e6,
    1e6,
    "the weight of a 1.2 m steel shaft is about 87 kN/m; 1 MN/m is ten times any line's (engineering judgement)",
)


class DistributedLoadSection(Section):
    """A load spread uniformly over a length of shaft."""

    x_start: X
    """Aft end of the loaded length."""
    x_end: X
    """Forward end."""
    load_y: Annotated[ForcePerLength, DISTRIBUTED_LOAD] = default_of(DistributedLoad, "load_y")
    """Vertical load per length (+ up)."""
    load_z: Annotated[ForcePerLength, DISTRIBUTED_LOAD] = default_of(DistributedLoad, "load_z")
    """Horizontal load per length (+ starboard)."""
    name: str = ""
    """Label."""


class ConditionSection(Section):
    """A load condition: offsets added to the bearings' and loads added to the line's."""

    name: str
    """Name (cold/hot, ballast/laden, static/running, ...)."""
    offsets_y: dict[str, OFFSET] = {}
    """Vertical offsets added per bearing name, e.g. { "intermediate" = "0.2 mm" }."""
    offsets_z: dict[str, OFFSET] = {}
    """Horizontal offsets added per bearing name."""
    propeller_immersion: Fraction | None = None
    """Immersed share of the propeller in this condition."""
    loads: list[PointLoadSection] = []
    """Point loads of this condition only."""


def point_load(load: PointLoadSection) -> PointLoad:
    return PointLoad(
        x=load.x,
        force_y=load.force_y,
        force_z=load.force_z,
        moment_vertical=load.moment_vertical,
        moment_horizontal=load.moment_horizontal,
        name=load.name,
    )
