"""How the film is solved in ``[bearing]``: grid and models (``[bearing.solver]``) with the
notes on them, and the speeds of the Stribeck curve (``[bearing.stribeck]``)."""

from __future__ import annotations

import math
from typing import Annotated

import numpy as np
from pydantic import Field

from shaftline.cases.types import SHAFT_SPEED, Quantity, Section, default_of
from shaftline.errors import InputError
from shaftline.film.geometry import MIN_AXIAL_NODES, MIN_CIRCUMFERENTIAL_NODES, BearingGeometry
from shaftline.film.problem import CavitatedShear, Cavitation, FilmStart, OperatingPoint, SolverOptions
from shaftline.film.turbulence import TurbulenceMode, TurbulenceModel


class SolverSection(Section):
    """Grid and models of the film solution."""

    axial_nodes: Annotated[int, Field(ge=MIN_AXIAL_NODES)] = default_of(SolverOptions, "axial_nodes")
    """Grid nodes along the bearing, edges included."""
    circumferential_nodes: Annotated[int, Field(ge=MIN_CIRCUMFERENTIAL_NODES)] = default_of(
        SolverOptions, "circumferential_nodes"
    )
    """Grid nodes around the bore."""
    cavitation: Cavitation = default_of(SolverOptions, "cavitation")
    """Reynolds (Swift-Stieber), jfo (mass-conserving; needs an edge or groove pressure above the cavitation
    pressure) or half_sommerfeld (comparison only)."""
    film_start: FilmStart = default_of(SolverOptions, "film_start")
    """periodic (the film is continuous all round) or max_film (ambient pressure at the thickest film, as the
    classical design charts)."""
    cavitated_shear: CavitatedShear = default_of(SolverOptions, "cavitated_shear")
    """Shear in the cavitated zone: film_fraction (liquid streamers only) or full_film (design-chart friction)."""
    min_film_floor: Annotated[float, Quantity("dimensionless", gt=0, lt=0.5)] = default_of(
        SolverOptions, "min_film_floor"
    )
    """Smallest film, share of the radial clearance, the equilibrium may approach before reporting contact."""
    tolerance: Annotated[float, Quantity("dimensionless", gt=0, lt=0.01)] = default_of(SolverOptions, "tolerance")
    """Relative force residual at which the equilibrium is accepted."""
    max_iterations: Annotated[int, Field(ge=1, le=1000)] = default_of(SolverOptions, "max_iterations")
    """Newton iterations allowed for the equilibrium."""
    memory_limit: Annotated[float, Quantity("memory", gt=0)] | None = None
    """Largest memory a film solution may take (e.g. "8 GiB"); a finer grid is refused before
    anything is allocated. Default: half the machine's memory."""
    turbulence: TurbulenceMode = default_of(SolverOptions, "turbulence")
    """Turbulent film (large, fast, low-viscosity films such as water): off (laminar), on (the turbulence
    coefficients at every node), or auto (on above the Taylor-vortex onset, 2 rho omega R c / mu > 41.3 sqrt(R/c));
    the local Reynolds number is reported unless off."""
    turbulence_model: TurbulenceModel = default_of(SolverOptions, "turbulence_model")
    """Coefficients of the turbulent film: ng_pan (Ng & Pan 1965) or constantinescu (Constantinescu 1962)."""


def solver_options(s: SolverSection) -> SolverOptions:
    """The film's :class:`SolverOptions` of a ``solver`` table."""
    return SolverOptions(
        axial_nodes=s.axial_nodes,
        circumferential_nodes=s.circumferential_nodes,
        cavitation=s.cavitation,
        film_start=s.film_start,
        cavitated_shear=s.cavitated_shear,
        min_film_floor=s.min_film_floor,
        tolerance=s.tolerance,
        max_iterations=s.max_iterations,
        memory_limit=s.memory_limit,
        turbulence=s.turbulence,
        turbulence_model=s.turbulence_model,
    )


#: ``turbulence = "on"`` with a largest local Reynolds number below this share of the transition
#: is noted (not refused): the coefficients are fits to turbulent films, and a film this far
#: below transition is laminar.
FAR_BELOW_TRANSITION = 0.1


def turbulence_note(
    geometry: BearingGeometry, operating: OperatingPoint, speed: float, field: str = "bearing.solver"
) -> str | None:
    """A note when turbulence is asked for with a film whose largest local Reynolds number
    (``2 Re_c``, a film of at most 2c) is far below the Taylor-vortex onset; None otherwise.
    ``field``: the case-file path of the solver table, for the note's text."""
    from shaftline.film.turbulence import clearance_reynolds, pressure_flow_coefficients, transition_reynolds

    radius, clearance = geometry.radius, geometry.radial_clearance
    largest = 2.0 * clearance_reynolds(operating.density, speed, radius, clearance, operating.viscosity)
    transition = transition_reynolds(radius, clearance)
    if largest >= FAR_BELOW_TRANSITION * transition:
        return None
    kx, _ = pressure_flow_coefficients(largest)
    return (
        f"{field}.turbulence = on with a film whose largest local Reynolds number is {largest:.3g}, far below the "
        f"transition at {transition:.3g} (41.3 sqrt(R/c)): the film is laminar; the turbulence coefficients change "
        f"its pressure flow by at most {100 * (1 - 12 / float(kx)):.2g} % (set turbulence = off or auto)."
    )


#: The layer model's end rows are resolved only with an axial step of at most this share of the
#: liner thickness (docs/validation.md "Elastic layer": seed 001's rig at 135 rpm, end film
#: 0.58, 0.96, 1.50, 1.94 um at dz = 1.5, 0.75, 0.375, 0.19 t; the interior within 1 %).
LAYER_RESOLUTION = 0.5


def layer_note(geometry: BearingGeometry, axial_nodes: int, table: str = "") -> str | None:
    """A note when the layer model's liner is thin against the axial step (its deformation
    near the bearing ends is not resolved); None otherwise. ``table``: the case-file path of the
    film's table with its dot (``"alignment.bearings[0].film."``; empty for ``[bearing]``), for
    the fields the note names."""
    liner = geometry.liner
    if liner is None or liner.model != "layer":
        return None
    dz = geometry.length / (axial_nodes - 1)
    if dz <= LAYER_RESOLUTION * liner.thickness:
        return None
    needed = math.ceil(geometry.length / (LAYER_RESOLUTION * liner.thickness)) + 1
    return (
        f"{table}liner.model = layer with an axial step of {dz * 1e3:.3g} mm, more than half the liner's "
        f"{liner.thickness * 1e3:.3g} mm: the layer's deformation near the bearing ends is not resolved and the "
        f"film there comes out too thin (set {table}solver.axial_nodes to {needed} or more; docs/validation.md, "
        '"Elastic layer").'
    )


def turbulence_notes(
    solver: SolverSection,
    options: SolverOptions,
    geometry: BearingGeometry,
    operating: OperatingPoint,
    field: str = "bearing.solver",
) -> list[str]:
    """The notes (not errors) on a film's turbulence settings, the same for ``[bearing.solver]``
    and ``[alignment.bearings.film.solver]``: turbulence on for a film far below transition
    (:func:`turbulence_note`), and a ``turbulence_model`` named with turbulence left off.
    ``field``: the case-file path of the solver table, for the notes' text."""
    notes = []
    if options.turbulence == "on":
        note = turbulence_note(geometry, operating, operating.speed, field)
        if note is not None:
            notes.append(note)
    if options.turbulence == "off" and "turbulence_model" in solver.model_fields_set:
        # a model named with turbulence left at its default: the user likely meant it to apply
        notes.append(
            f"{field}.turbulence_model = {options.turbulence_model} has no effect with turbulence = off (the "
            "default): the film is laminar (set turbulence = on or auto)."
        )
    return notes


class StribeckSection(Section):
    """Speeds of ``shaftline bearing stribeck``: geometric steps from lowest to highest."""

    lowest: Annotated[float, Quantity("speed", gt=0), SHAFT_SPEED] | None = None
    """Lowest speed (default a tenth of the case's)."""
    highest: Annotated[float, Quantity("speed", gt=0), SHAFT_SPEED] | None = None
    """Highest speed (default ten times the case's)."""
    points: Annotated[int, Field(ge=2, le=500)] = 30
    """Number of speeds."""


def stribeck_speeds(section: StribeckSection | None, speed: float) -> tuple[float, ...]:
    """The speeds (rad/s) of a ``stribeck`` table for a case running at ``speed``."""
    table = section or StribeckSection()
    lowest = table.lowest if table.lowest is not None else 0.1 * speed
    highest = table.highest if table.highest is not None else 10.0 * speed
    if highest <= lowest:
        raise InputError("stribeck.highest", highest, "rad/s", f"above the lowest speed ({lowest:.4g} rad/s)")
    return tuple(float(v) for v in np.geomspace(lowest, highest, table.points))
