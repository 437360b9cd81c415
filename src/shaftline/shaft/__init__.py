"""Shaft alignment: beam model of the shaft line on its bearings."""

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
