"""Hydrodynamic film of a journal bearing: geometry, Reynolds equation, bearing results."""

from shaftline.film.bearing import BearingState, Equilibrium, JournalBearing, OperatingPoint, SolverOptions
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

__all__ = [
    "BearingGeometry",
    "BearingState",
    "BentJournal",
    "BoreSegment",
    "DynamicCoefficients",
    "FilmProfile",
    "Equilibrium",
    "Grid",
    "JournalBearing",
    "JournalPosition",
    "OperatingPoint",
    "SolverOptions",
    "dynamic_coefficients",
    "film_thickness",
]
