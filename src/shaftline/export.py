"""Results that export themselves: a dataclass field's unit and meaning in its metadata.

A result dataclass marks the fields it writes to results.json with :func:`quantity` (a
scalar with its unit and a one-line meaning, optionally shown in degrees or under another
key) or :func:`part` (a nested result whose own fields are written in line, when present).
:func:`to_dict` then gives the plain-JSON mapping, :func:`units` the unit of every key and
:func:`rows` the (key, unit, meaning) lines of a reference table, all from the one
declaration. Values are JSON-clean: numpy scalars become Python numbers, a non-finite float
becomes None (JSON has no NaN).

>>> from dataclasses import dataclass
>>> @dataclass
... class Film:
...     thickness: float = quantity("m", "smallest film")
...     angle: float = quantity("rad", "where it is", degrees=True)
>>> to_dict(Film(1e-5, 3.141592653589793))
{'thickness': 1e-05, 'angle_deg': 180.0}
>>> units(Film)
{'thickness': 'm', 'angle_deg': 'deg'}
"""

from __future__ import annotations

import dataclasses
import math
from collections.abc import Callable, Collection, Iterator
from dataclasses import dataclass
from typing import Any

__all__ = ["Export", "Exported", "clean", "part", "quantity", "rows", "to_dict", "units"]

_KEY = "export"


@dataclass(frozen=True)
class Export:
    """How a field is written: under ``key`` (None: the field's name) in ``unit``, meaning
    ``doc``, its value passed through ``convert``; or, with ``inline`` (the nested result's
    class), a nested result whose exported fields are written in its place (nothing when it is
    None); an ``optional`` field is left out when it is None."""

    unit: str = ""
    doc: str = ""
    key: str | None = None
    convert: Callable[[Any], Any] | None = None
    inline: type | None = None
    optional: bool = False


def quantity(
    unit: str,
    doc: str,
    *,
    key: str | None = None,
    degrees: bool = False,
    convert: Callable[[Any], Any] | None = None,
    optional: bool = False,
    **field_options: Any,
) -> Any:
    """A dataclass field written to results.json: ``unit`` (SI, or ``"-"``), ``doc`` its one-line
    meaning. ``degrees``: the value is in radians and written in degrees under ``<name>_deg``
    (or ``key``); ``convert`` turns the value into what is written (a list of an array, a speed
    in rpm; ``unit`` is then the written value's); ``optional``: left out when None. Other
    keywords (``default``, ``repr``, ...) go to :func:`dataclasses.field`."""
    if degrees:
        export = Export("deg", doc, key, math.degrees, optional=optional)
    else:
        export = Export(unit, doc, key, convert, optional=optional)
    return dataclasses.field(metadata={_KEY: export}, **field_options)


def part(kind: type, **field_options: Any) -> Any:
    """A dataclass field holding a nested result of class ``kind`` (or None) whose exported fields
    are written in line; other keywords go to :func:`dataclasses.field`."""
    return dataclasses.field(metadata={_KEY: Export(inline=kind)}, **field_options)


def _exports(kind: Any) -> Iterator[tuple[dataclasses.Field[Any], Export]]:
    for item in dataclasses.fields(kind):
        export = item.metadata.get(_KEY)
        if export is not None:
            yield item, export


def _key(item: dataclasses.Field[Any], export: Export) -> str:
    if export.key is not None:
        return export.key
    return f"{item.name}_deg" if export.convert is math.degrees else item.name


def clean(value: Any) -> Any:
    """A value as plain JSON: numpy scalars as Python numbers, a non-finite float as None (a list
    is cleaned item by item)."""
    if isinstance(value, list):
        return [clean(item) for item in value]
    if isinstance(value, bool) or value is None or isinstance(value, str):
        return value
    if hasattr(value, "dtype") and getattr(value, "shape", None) == ():
        value = value.item()
    if isinstance(value, bool):
        return value
    if isinstance(value, float):
        return value if math.isfinite(value) else None
    return value


def to_dict(result: Any) -> dict[str, Any]:
    """The exported fields of a dataclass instance as plain JSON, in field order, nested
    results (:func:`part`) in line."""
    out: dict[str, Any] = {}
    for item, export in _exports(result):
        value = getattr(result, item.name)
        if export.inline is not None:
            if value is not None:
                out.update(to_dict(value))
            continue
        if value is None and export.optional:
            continue
        out[_key(item, export)] = clean(
            export.convert(value) if export.convert is not None and value is not None else value
        )
    return out


def rows(kind: Any, parts: Collection[type] = ()) -> list[tuple[str, str, str]]:
    """(key, unit, meaning) of every field a dataclass writes, in order, with those of its nested
    results whose classes are in ``parts`` in their place (the others left out: a part that may
    be absent has its own)."""
    out: list[tuple[str, str, str]] = []
    for item, export in _exports(kind):
        if export.inline is None:
            out.append((_key(item, export), export.unit, export.doc))
        elif export.inline in parts:
            out += rows(export.inline, parts)
    return out


def units(kind: Any, parts: Collection[type] = ()) -> dict[str, str]:
    """The unit of every key of :func:`rows`."""
    return {key: unit for key, unit, _ in rows(kind, parts)}


class Exported:
    """A result dataclass that writes itself: :meth:`to_dict` gives its exported fields."""

    def to_dict(self) -> dict[str, Any]:
        """Every written field, keyed and in the units its metadata holds (plain JSON)."""
        return to_dict(self)
