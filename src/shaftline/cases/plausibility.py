"""Plausibility of a validated case-file table: values a real shaft line has, not only
values the models accept.

A bare number in a case file is SI, so ``length = 1050`` meant in mm is a 1050 m bearing,
and ``"0.5 furlongs"`` is a valid 100 m one. Each quantity field of the schema may carry a
:class:`~shaftline.cases.types.Plausible` range beside its :class:`Quantity`, and a table
may declare cross-field checks (:class:`~shaftline.cases.types.PlausibleRatio`, such as
c/R or W/(L D)). :func:`check_table` walks a table after pydantic has validated it, with
the path of every value in the file, and refuses the first value outside its range with
one line that names the field, gives the value and the plausible range in SI, and suggests
the unit that would bring the number as written into range::

    bearing.length = 1050 m: plausible 0.02 to 4 m; did you mean 1050 mm? (if 1050 m is
    right, add "bearing.length" to [case] unusual)

A case lowers the guard of single fields with ``[case] unusual = ["bearing.length"]``; the
paths are checked to name fields of the case that have a plausible range. Capability
authors only declare the ranges in their schema; nothing here knows a capability.
"""

from __future__ import annotations

import difflib
import re
import types
from collections.abc import Iterable, Iterator, Mapping
from dataclasses import dataclass, field
from typing import Annotated, Any, Union, get_args, get_origin

from pydantic import BaseModel

from shaftline.cases.types import Plausible, PlausibleRatio, Quantity, nested_model
from shaftline.errors import InputError


@dataclass(frozen=True)
class Alternative:
    """A unit a number of some kind is commonly written in: SI value = factor * number + offset.

    ``shown`` is how the suggestion is written, with ``{n}`` the number as written and
    ``{si}`` the value it would have in this unit (SI of the kind)."""

    unit: str
    factor: float
    offset: float = 0.0
    shown: str = "{n} {unit}"

    def text(self, number: str, si: float) -> str:
        return self.shown.format(n=number, unit=self.unit, si=f"{si:.6g}")


def _units(*pairs: tuple[str, float]) -> tuple[Alternative, ...]:
    return tuple(Alternative(unit, factor) for unit, factor in pairs)


#: The usual units of each kind, the most common slip first: the suggestion tries each on the
#: number as written. Every text here is read back by ``units.to_si`` to the same value
#: (tests/test_plausibility.py checks it).
ALTERNATIVES: dict[str, tuple[Alternative, ...]] = {
    "length": _units(("mm", 1e-3), ("cm", 1e-2), ("µm", 1e-6), ("in", 0.0254), ("ft", 0.3048), ("m", 1.0)),
    "angle": _units(("mrad", 1e-3), ("deg", 0.017453292519943295), ("rad", 1.0)),
    "speed": _units(("rpm", 0.10471975511965977), ("Hz", 6.283185307179586), ("rad/s", 1.0)),
    "force": _units(("kN", 1e3), ("MN", 1e6), ("tf", 9806.65), ("N", 1.0)),
    "moment": _units(("kN*m", 1e3), ("MN*m", 1e6), ("tf*m", 9806.65), ("N*m", 1.0)),
    "pressure": _units(("bar", 1e5), ("MPa", 1e6), ("kPa", 1e3), ("psi", 6894.757293168361), ("GPa", 1e9), ("Pa", 1.0)),
    "viscosity": _units(("mPa*s", 1e-3), ("Pa*s", 1.0)),
    "kinematic_viscosity": _units(("cSt", 1e-6), ("m^2/s", 1.0)),
    "temperature": (
        Alternative("degF", 5.0 / 9.0, -32.0 * 5.0 / 9.0),
        Alternative("K", 1.0, -273.15),
        Alternative("degC", 1.0),
    ),
    "density": _units(("g/cm^3", 1e3), ("lb/ft^3", 16.018463373960138), ("kg/m^3", 1.0)),
    "mass": _units(("t", 1e3), ("kg", 1.0), ("lb", 0.45359237)),
    "stiffness": _units(("kN/mm", 1e6), ("N/mm", 1e3), ("N/m", 1.0)),
    "force_per_length": _units(("kN/m", 1e3), ("N/m", 1.0)),
    "acceleration": _units(("cm/s^2", 1e-2), ("m/s^2", 1.0)),
    "wear_rate": _units(("mm^3/(N*m)", 1e-9), ("m^3/(N*m)", 1.0)),
    "time": _units(("min", 60.0), ("h", 3600.0), ("d", 86400.0), ("s", 1.0)),
    "frequency": _units(("mHz", 1e-3), ("1/min", 1.0 / 60.0), ("Hz", 1.0)),
    "volume": _units(("l", 1e-3), ("cm^3", 1e-6), ("m^3", 1.0)),
    "area": _units(("cm^2", 1e-4), ("mm^2", 1e-6), ("m^2", 1.0)),
    "areal_density": _units(("1/mm^2", 1e6), ("1/um^2", 1e12), ("1/m^2", 1.0)),
    "inertia": _units(("t*m^2", 1e3), ("kg*m^2", 1.0)),
    "rotational_stiffness": _units(("kN*m", 1e3), ("MN*m", 1e6), ("N*m", 1.0)),
    "rotational_damping": _units(("kN*m*s", 1e3), ("N*m*s", 1.0)),
    "dimensionless": _units(("%", 1e-2)),
    # a percentage written as a share (0.03 for 3 %)
    "percent": (Alternative("%", 100.0, shown="{si} % ({n} as a share)"),),
}

#: At most this many suggestions in a message.
MAX_SUGGESTIONS = 2

#: A number as written, then its unit.
_WRITTEN = re.compile(r"^\s*([+-]?(?:\d+\.?\d*|\.\d+)(?:[eE][+-]?\d+)?)\s*(\S.*)?$")


def _written_number(raw: Any) -> str | None:
    """The number as the file writes it (``"1050"`` of ``1050`` or of ``"1050 mm"``), or None
    when the text is not a number followed by a unit."""
    if isinstance(raw, bool):
        return None
    if isinstance(raw, int):
        return str(raw)
    if isinstance(raw, float):
        return f"{raw:.12g}"
    if isinstance(raw, str):
        match = _WRITTEN.match(raw)
        return match.group(1) if match else None
    return None


def _has_unit(raw: Any) -> bool:
    """Whether the file wrote a unit after the number (``"50 deg"``, not ``50``)."""
    if not isinstance(raw, str):
        return False
    match = _WRITTEN.match(raw)
    return bool(match and match.group(2))


def suggestions(kind: str, raw: Any, value: float, fits: Any) -> list[str]:
    """The number as written in the usual units of ``kind`` that ``fits`` accepts (a callable
    taking the SI value), in the order of :data:`ALTERNATIVES`, one per distinct value, other
    than the value given."""
    number = _written_number(raw)
    if number is None:
        return []
    n = float(number)
    found: list[str] = []
    seen = [value]
    for alternative in ALTERNATIVES.get(kind, ()):
        si = alternative.factor * n + alternative.offset
        if any(abs(si - other) <= 1e-9 * max(abs(si), abs(other)) for other in seen):
            continue  # the unit written (or one equal to it) is no suggestion
        seen.append(si)
        if fits(si):
            found.append(alternative.text(number, si))
    return found[:MAX_SUGGESTIONS]


class ImplausibleInput(InputError):
    """A value outside its plausible range (most likely a unit slip).

    ``str()`` is the one-line message; ``allowed`` holds its part after the value (the
    plausible range and the suggestion) and ``suggestions`` the suggested values as text.
    """

    def __init__(
        self,
        field: str,
        value: Any,
        unit: str,
        plausible: str,
        suggested: Iterable[str] = (),
        detail: str = "",
        limit: bool = False,
    ) -> None:
        super().__init__(field, value, unit)
        head = self.args[0]  # "bearing.length = 1050 m"
        self.plausible = plausible
        self.suggestions = tuple(suggested)
        self.detail = detail
        self.limit = limit
        word = "allowed" if limit else "plausible"
        tail = f"{detail}, {word} {plausible}" if detail else f"{word} {plausible}"
        if self.suggestions:
            tail += f"; did you mean {' or '.join(self.suggestions)}?"
        if not limit:  # a model's limit: [case] unusual could not let the value through
            shown = head.partition(" = ")[2]
            tail += f' (if {shown} is right, add "{field}" to [case] unusual)'
        self.allowed = tail
        self.args = (f"{head}: {tail}",)

    def within(self, prefix: str, renames: Mapping[str, str] | None = None) -> InputError:
        moved = super().within(prefix, renames)
        return ImplausibleInput(
            moved.field, self.value, self.unit, self.plausible, self.suggestions, self.detail, self.limit
        )


# --- walking a validated table -------------------------------------------------------------


@dataclass
class _Value:
    """A guarded quantity of the case: its path, SI value, the file's text, kind and range."""

    path: str
    value: float
    raw: Any
    quantity: Quantity
    plausible: Plausible


@dataclass
class _Walk:
    """What a walk of a validated table found."""

    values: list[_Value] = field(default_factory=list)
    tables: list[tuple[str, BaseModel, Any]] = field(default_factory=list)
    #: Paths a case may list in ``unusual``: guarded values, lists and tables of them, and
    #: the fields named by cross-field checks.
    guarded: dict[str, None] = field(default_factory=dict)
    #: SI value, unit and kind of every quantity seen, for the cross-field checks.
    quantities: dict[str, tuple[float, str, str]] = field(default_factory=dict)


def _ratios(model: type[BaseModel]) -> tuple[PlausibleRatio, ...]:
    """The cross-field checks a table declares (none for a model that is no ``Section``)."""
    return tuple(getattr(model, "plausible_ratios", ()))


def _join(path: str, name: str) -> str:
    return f"{path}.{name}" if path else name


def _annotation(info: Any) -> Any:
    """A field's annotation with the metadata pydantic keeps apart from it."""
    return Annotated[(info.annotation, *info.metadata)] if info.metadata else info.annotation


def _strip(annotation: Any) -> Any:
    """The annotation without ``| None``."""
    if get_origin(annotation) in (Union, types.UnionType):
        inner = [arg for arg in get_args(annotation) if arg is not type(None)]
        if len(inner) == 1:
            return inner[0]
    return annotation


def _guard(annotation: Any) -> tuple[Quantity, Plausible] | None:
    """The quantity and plausible range of a field's (or an entry's) annotation, if it has both."""
    annotation = _strip(annotation)
    if get_origin(annotation) is not Annotated:
        return None
    metadata = annotation.__metadata__
    quantity = next((m for m in metadata if isinstance(m, Quantity)), None)
    plausible = next((m for m in metadata if isinstance(m, Plausible)), None)
    return (quantity, plausible) if quantity is not None and plausible is not None else None


def _entry(annotation: Any, container: type) -> Any:
    """The annotation of the entries of a ``list[...]`` (or the values of a ``dict[str, ...]``)."""
    annotation = _strip(annotation)
    if get_origin(annotation) is Annotated:
        annotation = get_args(annotation)[0]
    if get_origin(annotation) is container:
        return get_args(annotation)[-1]
    return None


def _walk(value: Any, raw: Any, path: str, annotation: Any, out: _Walk) -> None:
    """Gather the quantities, tables and guarded paths of ``value`` (a validated table, list,
    table of values or number) at ``path``, with ``raw`` the same part of the file."""
    if value is None:
        return
    if isinstance(value, BaseModel):
        out.tables.append((path, value, raw))
        for name, info in type(value).model_fields.items():
            sub = raw.get(name) if isinstance(raw, dict) else None
            _walk(getattr(value, name), sub, _join(path, name), _annotation(info), out)
        return
    if isinstance(value, (list, dict)):
        entry = _entry(annotation, list if isinstance(value, list) else dict)
        if entry is not None and _guard(entry) is not None:
            out.guarded[path] = None  # the whole list (or table of values) may be listed
        if isinstance(value, list):
            for k, item in enumerate(value):
                sub = raw[k] if isinstance(raw, list) and k < len(raw) else None
                _walk(item, sub, f"{path}[{k}]", entry, out)
        else:
            for key, item in value.items():
                _walk(item, raw.get(key) if isinstance(raw, dict) else None, _join(path, key), entry, out)
        return
    if isinstance(value, (int, float)) and not isinstance(value, bool):
        metadata = getattr(_strip(annotation), "__metadata__", ())
        quantity = next((m for m in metadata if isinstance(m, Quantity)), None)
        if quantity is None:
            return
        out.quantities[path] = (float(value), quantity.unit, quantity.kind)
        plausible = next((m for m in metadata if isinstance(m, Plausible)), None)
        if plausible is not None:
            out.guarded[path] = None
            out.values.append(_Value(path, float(value), raw, quantity, plausible))


def _relative(table: BaseModel, raw: Any, path: str) -> tuple[Any, Any]:
    """The value and the raw value of a field ``path`` relative to ``table`` (dotted names)."""
    value: Any = table
    for name in path.split("."):
        value = getattr(value, name, None) if isinstance(value, BaseModel) else None
        raw = raw.get(name) if isinstance(raw, dict) else None
    return value, raw


def _walk_table(section: BaseModel, raw: Any, table: str) -> _Walk:
    """Everything :func:`check_table` needs of a validated table, by case-file path."""
    out = _Walk()
    _walk(section, raw, table, type(section), out)
    for path, model, _ in out.tables:
        for check in _ratios(type(model)):
            value, _raw = _relative(model, None, check.field)
            if value is not None:
                out.guarded[_join(path, check.field)] = None
    return out


def _lowered(path: str, unusual: set[str]) -> bool:
    """Whether the guard of ``path`` is lowered: it, or the list or table of values it is in,
    is listed."""
    parent = re.sub(r"(\[\d+\]|\.[^.\[\]]+)$", "", path)
    return path in unusual or parent in unusual


def _check_unusual(unusual: Iterable[tuple[int, str]], walk: _Walk) -> None:
    limits = {item.path for item in walk.values if item.plausible.limit}
    for k, path in unusual:
        where = f"case.unusual[{k}]"
        if path in limits:
            # its range is the model's own limit: lowering the guard could not let a value through
            raise InputError(where, path, "", "a field whose range is not the model's limit (this one's is)")
        if path in walk.guarded:
            continue
        if "*" in path or "?" in path:
            raise InputError(where, path, "", "one field per entry (no wildcards)")
        inside = sorted(p for p in walk.guarded if p.startswith(path + ".") or p.startswith(path + "["))
        if inside:
            raise InputError(where, path, "", f"a field, not a table: list the fields themselves, e.g. {inside[0]!r}")
        close = difflib.get_close_matches(path, list(walk.guarded), n=1, cutoff=0.75)
        hint = f"; did you mean {close[0]!r}?" if close else ""
        raise InputError(where, path, "", f"a field of the case with a plausible range{hint}")


def check_table(section: BaseModel, raw: Any, table: str, unusual: Iterable[tuple[int, str]] = ()) -> None:
    """Refuse the first implausible value of a validated case-file table.

    Parameters
    ----------
    section : BaseModel
        The table as validated by its capability's schema.
    raw : Any
        The same table as read from the file (the numbers as written, for the suggestion).
    table : str
        Its key in the case file (``"bearing"``): the start of every path.
    unusual : iterable of (int, str)
        The entries of ``[case] unusual`` that belong to this table, with their index in the
        list: their guards are lowered.

    Raises
    ------
    InputError
        For an entry of ``unusual`` that names no field of the table with a plausible range.
    ImplausibleInput
        For the first value outside its plausible range, then the first cross-field check
        that fails (each field's own range is checked before any ratio that uses it).
    """
    entries = list(unusual)
    walk = _walk_table(section, raw, table)
    _check_unusual(entries, walk)
    lowered = {path for _, path in entries}
    ratios = [
        _Ratio(check, path, model, model_raw)
        for path, model, model_raw in walk.tables
        for check in _ratios(type(model))
    ]
    for item in walk.values:
        if item.plausible.contains(item.value) or _lowered(item.path, lowered):
            continue
        # a suggestion must also pass the cross-field checks that name this field
        named = [r for r in ratios if r.where == item.path]

        def fits(si: float, item: _Value = item, named: list[_Ratio] = named) -> bool:
            inside = item.plausible.contains(si) and item.quantity.inside(si) and item.plausible.sizeable(si)
            return inside and all(r.holds(si) for r in named)

        unit = item.quantity.unit
        suggested = suggestions(item.quantity.kind, item.raw, item.value, fits)
        if item.plausible.limit and _has_unit(item.raw):
            suggested = []  # beyond a model's limit in a unit the user chose: no slip to suggest
        value, shown_unit = item.plausible.shown(item.value, unit)
        raise ImplausibleInput(
            item.path, value, shown_unit, item.plausible.text(unit), suggested, limit=item.plausible.limit
        )
    for ratio in ratios:
        if not _lowered(ratio.where, lowered):
            ratio.check_with(walk)


@dataclass
class _Ratio:
    """A cross-field check of one table of the case."""

    check: PlausibleRatio
    path: str
    model: BaseModel
    raw: Any

    @property
    def where(self) -> str:
        return _join(self.path, self.check.field)

    def holds(self, si: float) -> bool:
        """Whether the ratio is plausible with ``si`` in place of the named field."""
        return self.check.low <= self.check.ratio(self.model, si) <= self.check.high

    def check_with(self, walk: _Walk) -> None:
        """Raise :class:`ImplausibleInput` if the ratio is implausible, suggesting the units of
        the named field that give a plausible ratio and value; the other fields of the ratio
        are shown with their values (each passed its own range already)."""
        value, written = _relative(self.model, self.raw, self.check.field)
        if value is None or self.holds(value):
            return
        check = self.check
        _, unit, kind = walk.quantities[self.where]
        own = next((v.plausible for v in walk.values if v.path == self.where), None)

        def fits(si: float) -> bool:
            return self.holds(si) and (own is None or own.contains(si))

        others = []
        for name in check.uses:
            where = _join(self.path, name)
            if where in walk.quantities:
                other, other_unit, _ = walk.quantities[where]
                others.append(f"{where} = {other:.12g}{' ' + other_unit if other_unit else ''}")
        detail = f"{check.name} = {check.ratio(self.model, value):.3g}{' ' + check.unit if check.unit else ''}"
        if others:
            detail += " with " + ", ".join(others)
        raise ImplausibleInput(self.where, value, unit, check.text(), suggestions(kind, written, value, fits), detail)


# --- the ranges as a table (README, generated) ----------------------------------------------


def _rows(model: type[BaseModel], path: str) -> Iterator[tuple[str, str, str]]:
    for name, info in model.model_fields.items():
        annotation = _annotation(info)
        where = _join(path, name)
        guard = _guard(annotation)
        if guard is None:
            for container, suffix in ((list, "[k]"), (dict, ".<name>")):
                entry = _entry(annotation, container)
                if entry is not None and _guard(entry) is not None:
                    guard, where = _guard(entry), where + suffix
        if guard is not None:
            quantity, plausible = guard
            yield f"`{where}`", plausible.text(quantity.unit), plausible.source
            continue
        nested = nested_model(annotation)
        if nested is not None:
            yield from _rows(nested[0], where + ("[k]" if nested[1] else ""))
    for check in _ratios(model):
        yield (
            f"`{_join(path, check.field)}`: {check.name} ({check.meaning})",
            check.text(),
            check.source,
        )


def ranges_table(root: type[BaseModel]) -> str:
    """Every plausible range of the case file (fields and cross-field checks) as a Markdown
    table: field, range in SI, source; fields that share a range and source share a row."""
    rows: dict[tuple[str, str], list[str]] = {}
    for where, text, source in _rows(root, ""):
        rows.setdefault((text, source), []).append(where)
    lines = ["| field | plausible range | source |", "|---|---|---|"]
    lines += [f"| {', '.join(fields)} | {text} | {source} |" for (text, source), fields in rows.items()]
    return "\n".join(lines) + "\n"


__all__ = ["ALTERNATIVES", "Alternative", "ImplausibleInput", "check_table", "ranges_table", "suggestions"]
