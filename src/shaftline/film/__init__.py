"""Hydrodynamic film of a journal bearing: geometry, Reynolds equation, bearing results.

====================  ==============================================================================
module                job
====================  ==============================================================================
``problem``           the problem as data: operating point, solver options and their choices
``options``           the tuning of the solver's steps (active set, JFO, continuation, Newton,
                      settling, liner iteration) with the defaults they were tuned to
``geometry``          bore, journal, slope boring, bent journal, film thickness on the grid
``stencil``           the discrete Reynolds operator and its sparsity patterns
``cavitation``        cavitation models from a registry: Reynolds condition, JFO, half-Sommerfeld
``relaxation``        red-black projected SOR that predicts the cavitated set (compiled loop in
                      ``_relaxation_kernel``)
``surfaces``          smooth or rough surfaces: asperity contact, flow factors, the film's floor
``roughness``         Patir-Cheng flow factors and Greenwood-Tripp asperity contact
``turbulence``        Ng-Pan and Constantinescu turbulence coefficients of water films
``liner``, ``layer``  the column (Winkler) and bonded-layer models of an elastic liner
``elastic``           the coupled film-liner Newton systems of the two liner models
``solver``            ``FilmSolver``: one problem's per-process state, the film at a position, its
                      forces and its frozen-set response
``lined``             the film and an elastic liner solved together
``equilibrium``       the Newton iteration that finds the journal position carrying a load
``linearise``         stiffness and damping (2 x 2, 4 x 4 with tilt), the film load along a line
``state``             the bearing state of a solution: extremes, friction, flows
``results``           ``BearingState`` and its parts, ``Equilibrium`` with counters, linearisations
``extremes``          h_min and p_max located between nodes
``bearing``           ``JournalBearing``: the face of all the above
``dynamics``          ``DynamicCoefficients`` at an equilibrium
``analytic``          closed-form estimates (the cold start)
``thermal``           the effective film temperature from the heat balance
``study``, ``solve``  a bearing study as data, and its solution (one case, many cases at once)
``stribeck``          the speed sweep and the transition speed
``case``, ``capability``, ``figures``, ``summary``  the capability: schema, pipeline, figures, JSON fields
====================  ==============================================================================

The names below are imported on first use (PEP 562), so that
``import shaftline.film.problem`` or ``from shaftline.film import BearingGeometry``
loads numpy only: the solver modules (scipy, qdldl) load with the first name that
needs them, e.g. ``JournalBearing``.
"""

from __future__ import annotations

import importlib
from types import MappingProxyType
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    from shaftline.film.bearing import JournalBearing
    from shaftline.film.dynamics import DynamicCoefficients, dynamic_coefficients
    from shaftline.film.geometry import (
        BearingGeometry,
        BentJournal,
        BoreSegment,
        FilmProfile,
        Grid,
        JournalPosition,
        film_thickness,
    )
    from shaftline.film.problem import (
        BearingProblem,
        CavitatedShear,
        Cavitation,
        FilmStart,
        OperatingPoint,
        SolverOptions,
        SupplyGroove,
    )
    from shaftline.film.results import (
        BearingState,
        Equilibrium,
        FilmLinearisation,
        FilmLoad,
        LinerState,
        RoughContact,
        TiltLinearisation,
        TurbulenceState,
    )
    from shaftline.film.solve import sweep

#: Public name -> module that defines it (read-only).
_WHERE = MappingProxyType(
    {
        "BearingGeometry": "geometry",
        "BentJournal": "geometry",
        "BoreSegment": "geometry",
        "FilmProfile": "geometry",
        "Grid": "geometry",
        "JournalPosition": "geometry",
        "film_thickness": "geometry",
        "BearingProblem": "problem",
        "CavitatedShear": "problem",
        "Cavitation": "problem",
        "FilmStart": "problem",
        "OperatingPoint": "problem",
        "SolverOptions": "problem",
        "SupplyGroove": "problem",
        "BearingState": "results",
        "Equilibrium": "results",
        "FilmLinearisation": "results",
        "FilmLoad": "results",
        "LinerState": "results",
        "RoughContact": "results",
        "TiltLinearisation": "results",
        "TurbulenceState": "results",
        "JournalBearing": "bearing",
        "DynamicCoefficients": "dynamics",
        "dynamic_coefficients": "dynamics",
        "sweep": "solve",
    }
)

__all__ = [
    "BearingGeometry",
    "BearingProblem",
    "BearingState",
    "BentJournal",
    "BoreSegment",
    "CavitatedShear",
    "Cavitation",
    "DynamicCoefficients",
    "Equilibrium",
    "FilmLinearisation",
    "FilmLoad",
    "FilmProfile",
    "FilmStart",
    "Grid",
    "JournalBearing",
    "JournalPosition",
    "LinerState",
    "OperatingPoint",
    "RoughContact",
    "SolverOptions",
    "SupplyGroove",
    "TiltLinearisation",
    "TurbulenceState",
    "dynamic_coefficients",
    "film_thickness",
    "sweep",
]


def __getattr__(name: str) -> Any:
    module = _WHERE.get(name)
    if module is None:
        raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
    return getattr(importlib.import_module(f"{__name__}.{module}"), name)


def __dir__() -> list[str]:
    return sorted(set(globals()) | set(__all__))
