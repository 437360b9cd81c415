"""Hydrodynamic film of a journal bearing: geometry, Reynolds equation, bearing results.

The names below are imported on first use (PEP 562), so that
``import shaftline.film.problem`` or ``from shaftline.film import BearingGeometry``
loads numpy only: the solver modules (scipy, qdldl) load with the first name that
needs them, e.g. ``JournalBearing``.
"""

from __future__ import annotations

import importlib
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    from shaftline.film.bearing import (
        BearingState,
        Equilibrium,
        FilmLinearisation,
        FilmLoad,
        JournalBearing,
        TiltLinearisation,
    )
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
    from shaftline.film.sweeps import sweep

#: Public name -> module that defines it.
_WHERE = {
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
    "BearingState": "bearing",
    "Equilibrium": "bearing",
    "FilmLinearisation": "bearing",
    "FilmLoad": "bearing",
    "JournalBearing": "bearing",
    "TiltLinearisation": "bearing",
    "DynamicCoefficients": "dynamics",
    "dynamic_coefficients": "dynamics",
    "sweep": "sweeps",
}

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
    "OperatingPoint",
    "SolverOptions",
    "SupplyGroove",
    "TiltLinearisation",
    "dynamic_coefficients",
    "film_thickness",
    "sweep",
]


def __getattr__(name: str) -> Any:
    module = _WHERE.get(name)
    if module is None:
        raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
    value = getattr(importlib.import_module(f"{__name__}.{module}"), name)
    globals()[name] = value  # later look-ups skip this function
    return value


def __dir__() -> list[str]:
    return sorted(set(globals()) | set(__all__))
