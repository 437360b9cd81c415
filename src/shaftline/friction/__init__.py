"""Friction laws usable by any module: static (Coulomb ... Karnopp) and dynamic (Dahl, LuGre)."""

from shaftline.friction.models import (
    Dahl,
    LuGre,
    coulomb,
    finite_slope,
    karnopp,
    simulate_block,
    stribeck,
    viscous,
)

__all__ = ["Dahl", "LuGre", "coulomb", "finite_slope", "karnopp", "simulate_block", "stribeck", "viscous"]
