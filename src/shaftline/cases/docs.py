"""The case-file reference, generated from the schema: Markdown tables (the README's
case-file section) and the JSON Schema (``shaftline schema``).

The README holds generated parts between markers (``<!-- case-file tables -->`` ...
``<!-- end of case-file tables -->`` and the like, see :data:`GENERATED`); a test checks
that they match, and ``python -m shaftline.cases.docs README.md`` rewrites them.
"""

from __future__ import annotations

import datetime
import json
import sys
import types
from collections.abc import Callable
from pathlib import Path
from typing import Annotated, Any, Literal, Union, get_args, get_origin

from pydantic import BaseModel
from pydantic_core import PydanticUndefined

from shaftline.cases.loader import case_model
from shaftline.cases.types import Quantity, nested_model


def _metadata(annotation: Any) -> list[Any]:
    return list(getattr(annotation, "__metadata__", ()))


def _type_text(annotation: Any) -> str:
    """A short description of a field's type: ``length [m]``, ``one of a, b``, ``list of ...``."""
    for item in _metadata(annotation):
        if isinstance(item, Quantity):
            bounds = item.allowed()
            kind = {"dimensionless": "number", "percent": "percentage"}.get(item.kind, item.kind.replace("_", " "))
            unit = f" [{item.unit}]" if item.unit else ""
            return f"{kind}{unit}{', ' + bounds if bounds else ''}"
    origin = get_origin(annotation)
    args = get_args(annotation)
    bounds = _bounds(_metadata(annotation))
    if bounds and args:  # Annotated[int, Field(ge=5)], Annotated[list[...], Field(min_length=2)]
        return f"{_type_text(args[0])}, {bounds}"
    if origin is Literal:
        return "one of " + ", ".join(f"`{a}`" for a in args)
    if origin in (Union, types.UnionType):
        inner = [a for a in args if a is not type(None)]
        return " or ".join(_type_text(a) for a in inner)
    if origin is list:
        return f"list of {_type_text(args[0])}"
    if origin is dict:
        return f"table of {_type_text(args[1])}"
    if origin is not None and args:  # Annotated[int, Field(...)] and the like
        return _type_text(args[0])
    if isinstance(annotation, type) and issubclass(annotation, BaseModel):
        return "table"
    names = {int: "integer", float: "number", str: "text", bool: "true/false", datetime.datetime: "date-time"}
    return names.get(annotation, str(annotation))


def _bounds(metadata: list[Any]) -> str:
    """Range and length limits of annotated_types metadata, in words (``>= 5``, ``2 to 8 entries``)."""
    import annotated_types as at
    from pydantic.fields import FieldInfo

    words = []
    flat = [entry for item in metadata for entry in (item.metadata if isinstance(item, FieldInfo) else [item])]
    for item in flat:
        for cls, symbol, name in ((at.Gt, ">", "gt"), (at.Ge, ">=", "ge"), (at.Lt, "<", "lt"), (at.Le, "<=", "le")):
            if isinstance(item, cls):
                words.append(f"{symbol} {getattr(item, name)}")
        if isinstance(item, at.MinLen):
            words.append(f"at least {item.min_length} entries")
        if isinstance(item, at.MaxLen):
            words.append(f"at most {item.max_length} entries")
    for n in range(1, 100):
        if f"at least {n} entries" in words and f"at most {n} entries" in words:
            words = [w for w in words if not w.endswith(f" {n} entries")] + [f"exactly {n} entries"]
    return ", ".join(words)


def _also_a_value(annotation: Any) -> bool:
    """Whether a field that may be a table may also be a plain value (``FilmSection |
    StrictBool``): it keeps its row beside its table's section."""
    arms = (
        [a for a in get_args(annotation) if a is not type(None)]
        if get_origin(annotation) in (Union, types.UnionType)
        else []
    )
    return any(nested_model(a) is None for a in arms)


def _default(info: Any) -> str:
    if info.is_required():
        return "required"
    value = info.default
    if value is PydanticUndefined or value is None:
        return "-"
    if value == "":
        return '""'
    if isinstance(value, BaseModel) or value == []:
        return "-"
    if isinstance(value, float):
        return f"{value:g}"
    return str(value).lower() if isinstance(value, bool) else str(value)


def _tables(model: type[BaseModel], path: str, array: bool, out: list[str]) -> None:
    rows = []
    children = []
    for name, info in model.model_fields.items():
        nested = nested_model(info.annotation)
        if nested is not None:
            child, child_array = nested
            children.append((child, f"{path}.{name}" if path else name, child_array))
            if not _also_a_value(info.annotation):
                continue
        description = " ".join((info.description or "").split())
        annotation: Any = info.annotation
        if info.metadata:  # pydantic keeps Annotated metadata of a plain field apart from its type
            annotation = Annotated[(annotation, *info.metadata)]
        rows.append(f"| `{name}` | {_type_text(annotation)} | {_default(info)} | {description} |")
    if path and rows:
        heading = f"[[{path}]]" if array else f"[{path}]"
        doc = " ".join((model.__doc__ or "").split())
        out.append(f"#### `{heading}`\n\n{doc}\n\n| field | type | default | meaning |\n|---|---|---|---|")
        out.append("\n".join(rows) + "\n")
    elif path:
        doc = " ".join((model.__doc__ or "").split())
        out.append(f"#### `{'[[' + path + ']]' if array else '[' + path + ']'}`\n\n{doc}\n")
    for child, child_path, child_array in children:
        _tables(child, child_path, child_array, out)


def markdown_tables() -> str:
    """Every case-file table with its fields: type and unit, default and meaning."""
    out: list[str] = []
    _tables(case_model(), "", False, out)
    return "\n".join(out).rstrip() + "\n"


def json_schema() -> dict[str, Any]:
    """The JSON Schema of a case file (quantities: a number in SI or a string with a unit;
    ``x-unit`` gives the SI unit, ``x-plausible`` the plausible range in it and
    ``x-plausible-source`` where that comes from)."""
    return case_model().model_json_schema()


def json_schema_text() -> str:
    return json.dumps(json_schema(), indent=2)


def _bearing_json_fields() -> str:
    from shaftline.film.summary import field_table

    return field_table()


def plausibility_table() -> str:
    """The plausible range of every field that has one, and the cross-field checks, with
    their sources (:mod:`shaftline.cases.plausibility`)."""
    from shaftline.cases.plausibility import ranges_table

    return ranges_table(case_model())


#: Generated parts of the README: the name in their markers and what makes them.
GENERATED: dict[str, Callable[[], str]] = {
    "case-file tables": markdown_tables,
    "plausibility ranges": plausibility_table,
    "bearing JSON fields": _bearing_json_fields,
}


def _markers(name: str) -> tuple[str, str]:
    return f"<!-- {name} -->", f"<!-- end of {name} -->"


def readme_part(readme: str, name: str) -> str:
    """A generated part of the README (between its markers)."""
    start, end = _markers(name)
    return readme[readme.index(start) + len(start) : readme.index(end)].strip() + "\n"


def update_readme(path: Path) -> bool:
    """Rewrite the generated parts of the README at ``path``; True if any changed."""
    text = original = path.read_text(encoding="utf-8")
    for name, make in GENERATED.items():
        start, end = _markers(name)
        head, tail = text.index(start) + len(start), text.index(end)
        text = text[:head] + "\n\n" + make() + "\n" + text[tail:]
    if text != original:
        path.write_text(text, encoding="utf-8")
    return text != original


if __name__ == "__main__":  # python -m shaftline.cases.docs README.md
    changed = update_readme(Path(sys.argv[1] if len(sys.argv) > 1 else "README.md"))
    print("README updated" if changed else "README up to date")
