"""The class rules and alignment procedures of ``[alignment]``: rules, offset
optimisation, sag and gap, jack-up and measured reactions."""

from __future__ import annotations

from typing import Annotated, Any, Literal

from pydantic import Field

from shaftline.cases.types import Force, Number, Plausible, PositiveLength, Section
from shaftline.shaft.case_ranges import LINE_FORCE, OFFSET, SHAFT_DIAMETER, X

RuleQuantity = Literal["reaction", "reaction_share", "mean_pressure", "relative_slope"]
Comparison = Literal[">", ">=", "<", "<="]
Objective = Literal["aft_slope", "load_spread"]


class RuleSection(Section):
    """A class rule (or yard limit) checked at every bearing it applies to, in every condition."""

    id: str
    """Identifier shown with the check."""
    quantity: RuleQuantity
    """The checked quantity (SI: N, -, Pa, rad)."""
    comparison: Comparison
    """value <comparison> limit passes."""
    limit: Number
    """Limit in SI units."""
    applies_to: str = "all"
    """all, aft_stern_tube or a bearing material."""
    society: str = ""
    """Source of the rule."""
    clause: str = ""
    """Clause of the source."""
    edition: str = ""
    """Edition of the source."""
    confidence: Literal["high", "medium", "low"] = "medium"
    """How sure the value is."""
    note: str = ""
    """Remark."""


class OptimiseSection(Section):
    """Offsets of the adjustable bearings that meet the rules in every condition."""

    objective: Objective = "aft_slope"
    """Minimise the aft bearing's relative slope, or the spread of the load ratios."""
    adjustable: list[str] | None = None
    """Bearings whose offsets may change (default: all but the aft- and forward-most)."""
    bound: Annotated[
        PositiveLength,
        Plausible(1e-5, 0.05, "offsets are a few mm (the offsets above); the default bound is 5 mm"),
    ] = 5e-3
    """Largest added offset either way."""


class TemporarySupportSection(Section):
    """A temporary support of the uncoupled shaft."""

    name: str
    """Label."""
    x: X
    """Station."""
    offset_y: OFFSET = 0.0
    """Vertical offset (+ up)."""


class SagGapSection(Section):
    """Sag and gap at an uncoupled flange."""

    flange_x: X
    """Station of the flange."""
    flange_diameter: Annotated[PositiveLength, SHAFT_DIAMETER] | None = None
    """Flange diameter (default: the larger shaft diameter at the flange)."""
    condition: str | None = None
    """Condition (default: the first)."""
    temporary_supports: list[TemporarySupportSection] = []
    """Supports added while the line is uncoupled."""


class JackUpSection(Section):
    """A jack-up test of one bearing, modelled and, with a measured curve, evaluated."""

    bearing: str
    """The bearing jacked."""
    jack_x: X
    """Station of the jack."""
    condition: str | None = None
    """Condition (default: the first)."""
    measured_curve: str | None = None
    """CSV with columns load (N) and lift (m) from the test; path relative to the case file."""


class MeasuredReactionsSection(Section):
    """Offsets that explain measured reactions (reverse engineering of the alignment)."""

    values: dict[str, Annotated[Force, LINE_FORCE]]
    """Measured reaction per bearing name."""
    condition: str | None = None
    """Condition of the measurement (default: the first)."""
    reference: Annotated[list[str], Field(min_length=2, max_length=2)] | None = None
    """Two bearings whose offsets are held (default: the aft- and forward-most)."""


def read_jack_curve(path: Any) -> tuple[Any, Any]:
    """A measured jack-up curve from CSV: columns ``load`` (N) and ``lift`` (m)."""
    from shaftline.csvio import read_columns

    table = read_columns(path, ["load", "lift"], "measured_curve")
    return table["load"], table["lift"]
