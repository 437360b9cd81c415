"""Friction laws usable by any module: static (Coulomb ... Karnopp) and dynamic (Dahl, LuGre).

The names are re-exported lazily (PEP 562) from :mod:`shaftline.friction.models`, so that
importing this package costs nothing until a law is used; the compiled kernels that the laws
share with the blade-carrier model are in :mod:`shaftline.friction.kernels`.
"""

from __future__ import annotations

import importlib
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
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


def __getattr__(name: str) -> Any:
    if name in __all__:
        return getattr(importlib.import_module("shaftline.friction.models"), name)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


def __dir__() -> list[str]:
    return sorted([*globals(), *__all__])
