"""Shaft alignment: beam model of the shaft line on its bearings.

Every name is imported on first use (PEP 562): the command line imports
``shaftline.shaft.capability`` to list its verbs without numpy, and the case schema
imports ``shaftline.shaft.model`` (numpy only) without the solver (scipy).
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    from shaftline.shaft.alignment import AlignmentModel, BearingResult, ConditionResult, InfluenceMatrix
    from shaftline.shaft.model import (
        Bearing,
        Condition,
        DistributedLoad,
        PointLoad,
        PointMass,
        Propeller,
        ShaftLine,
        ShaftSegment,
    )

_LAZY = {
    **{
        name: "shaftline.shaft.model"
        for name in (
            "Bearing",
            "Condition",
            "DistributedLoad",
            "PointLoad",
            "PointMass",
            "Propeller",
            "ShaftLine",
            "ShaftSegment",
        )
    },
    "AlignmentModel": "shaftline.shaft.alignment",
    "BearingResult": "shaftline.shaft.alignment",
    "ConditionResult": "shaftline.shaft.alignment",
    "InfluenceMatrix": "shaftline.shaft.alignment",
}

__all__ = [
    "AlignmentModel",
    "Bearing",
    "BearingResult",
    "Condition",
    "ConditionResult",
    "DistributedLoad",
    "InfluenceMatrix",
    "PointLoad",
    "PointMass",
    "Propeller",
    "ShaftLine",
    "ShaftSegment",
]


def __getattr__(name: str) -> Any:
    if name in _LAZY:
        import importlib

        value = getattr(importlib.import_module(_LAZY[name]), name)
        globals()[name] = value  # later look-ups skip this function
        return value
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


def __dir__() -> list[str]:
    return sorted(set(globals()) | set(__all__))
