"""Class-rule checks of an alignment, from rules kept as data (``data/rules.toml``)."""

from __future__ import annotations

import math
import operator
import tomllib
from dataclasses import dataclass
from importlib.resources import files
from pathlib import Path
from typing import TYPE_CHECKING

import numpy as np

from shaftline.errors import InputError

if TYPE_CHECKING:  # for annotations only: the case schema imports the rules, not the solver
    from shaftline.shaft.alignment import AlignmentModel, ConditionResult

QUANTITIES = {
    "reaction": "N",
    "reaction_share": "-",
    "mean_pressure": "Pa",
    "relative_slope": "rad",
}
COMPARISONS = {">": operator.gt, ">=": operator.ge, "<": operator.lt, "<=": operator.le}


@dataclass(frozen=True)
class Rule:
    """One rule: what is compared with which limit, and where it comes from.

    Attributes
    ----------
    id, society, clause, edition : str
        Identity and source.
    quantity : str
        One of :data:`QUANTITIES`.
    comparison : str
        ``">"``, ``">="``, ``"<"`` or ``"<="`` (value <comparison> limit passes).
    limit : float
        SI value.
    applies_to : str
        ``"all"``, ``"aft_stern_tube"`` or a bearing material.
    confidence : str
        ``"high"``, ``"medium"`` or ``"low"``: how sure we are of the value.
    note : str
    """

    id: str
    society: str
    clause: str
    edition: str
    quantity: str
    comparison: str
    limit: float
    applies_to: str = "all"
    confidence: str = "medium"
    note: str = ""


@dataclass(frozen=True)
class RuleCheck:
    """The outcome of one rule at one bearing in one condition."""

    rule: Rule
    condition: str
    bearing: str
    value: float
    passed: bool


def load_rules(path: str | Path | None = None) -> list[Rule]:
    """Rules from a TOML file of ``[[rule]]`` tables (default: the bundled set)."""
    if path is None:
        text = files("shaftline.shaft").joinpath("data/rules.toml").read_text(encoding="utf-8")
        where = "bundled rules"
    else:
        try:
            text = Path(path).read_text(encoding="utf-8")
        except OSError:
            raise InputError("path", str(path), "", "an existing TOML file") from None
        where = str(path)
    try:
        data = tomllib.loads(text)
    except tomllib.TOMLDecodeError as exc:
        raise InputError("path", where, "", f"valid TOML ({exc})") from None
    return [rule_from_dict(entry, f"rule[{k}]") for k, entry in enumerate(data.get("rule", []))]


def rule_from_dict(entry: dict, where: str) -> Rule:
    known = set(Rule.__dataclass_fields__)
    unknown = set(entry) - known
    if unknown:
        raise InputError(f"{where}.{sorted(unknown)[0]}", "?", "", "no such field (check the spelling)")
    for name in ("id", "quantity", "comparison", "limit"):
        if name not in entry:
            raise InputError(f"{where}.{name}", "missing", "", "a value (required field)")
    if entry["quantity"] not in QUANTITIES:
        raise InputError(f"{where}.quantity", entry["quantity"], "", "one of " + ", ".join(QUANTITIES))
    if entry["comparison"] not in COMPARISONS:
        raise InputError(f"{where}.comparison", entry["comparison"], "", "one of " + ", ".join(COMPARISONS))
    limit = entry["limit"]
    if not isinstance(limit, (int, float)) or not math.isfinite(limit):
        raise InputError(f"{where}.limit", limit, QUANTITIES[entry["quantity"]], "a finite number (SI)")
    values = {k: entry.get(k, "") for k in ("society", "clause", "edition", "note")}
    return Rule(
        id=str(entry["id"]),
        quantity=entry["quantity"],
        comparison=entry["comparison"],
        limit=float(limit),
        applies_to=str(entry.get("applies_to", "all")),
        confidence=str(entry.get("confidence", "medium")),
        **{k: str(v) for k, v in values.items()},
    )


def weight_shares(model: AlignmentModel) -> np.ndarray:
    """Share of the line's weight each bearing would carry as a simple beam between mid-spans, N.

    The shaft (and point masses, propeller) between the mid-points to the neighbouring
    bearings; the end bearings take everything beyond them.
    """
    line, mesh = model.line, model.mesh
    x = np.array([b.x for b in line.bearings])
    order = np.argsort(x)
    bounds = np.concatenate(([-np.inf], 0.5 * (x[order][1:] + x[order][:-1]), [np.inf]))
    middle = 0.5 * (mesh.x[:-1] + mesh.x[1:])
    weight = mesh.weight_per_length * mesh.length
    shares = np.zeros(x.size)
    for rank, k in enumerate(order):
        inside = (middle >= bounds[rank]) & (middle < bounds[rank + 1])
        shares[k] = weight[inside].sum()
        for mass in line.masses:
            if bounds[rank] <= mass.x < bounds[rank + 1]:
                shares[k] += mass.mass * line.gravity
        if line.propeller is not None and bounds[rank] <= line.propeller.x < bounds[rank + 1]:
            shares[k] += line.propeller.weight()
    return shares


def check_rules(model: AlignmentModel, results: list[ConditionResult], rules: list[Rule]) -> list[RuleCheck]:
    """Evaluate every rule at every bearing it applies to, in every condition."""
    line = model.line
    aft_most = min(line.bearings, key=lambda b: b.x).name
    shares = weight_shares(model)
    checks = []
    for result in results:
        for k, (bearing, outcome) in enumerate(zip(line.bearings, result.bearings, strict=True)):
            for rule in rules:
                if rule.applies_to == "aft_stern_tube":
                    if bearing.name != aft_most:
                        continue
                elif rule.applies_to != "all" and rule.applies_to != bearing.material:
                    continue
                value = {
                    "reaction": outcome.reaction_y,
                    "reaction_share": outcome.reaction_y / shares[k] if shares[k] > 0 else math.inf,
                    "mean_pressure": outcome.mean_pressure,
                    "relative_slope": abs(outcome.relative_slope),
                }[rule.quantity]
                passed = bool(COMPARISONS[rule.comparison](value, rule.limit))
                checks.append(RuleCheck(rule, result.name, bearing.name, float(value), passed))
    return checks
