"""Reading a TOML case file into SI domain objects.

The file is one table per capability (``[bearing]``, ``[alignment]``, ``[wear]``,
``[cpp]``) plus ``[case]`` for its labels. The schema of the whole file is assembled from
the registry; pydantic validates it and names any bad field by its path; each
capability's ``build`` then makes its domain objects, and an error the domain raises is
placed under the table it came from.
"""

from __future__ import annotations

import difflib
import math
import re
from collections.abc import Iterable, Mapping
from functools import lru_cache
from pathlib import Path
from typing import Any

from pydantic import BaseModel, Field, ValidationError, create_model

from shaftline import registry
from shaftline.cases.files import read_case_file
from shaftline.cases.plausibility import check_table
from shaftline.cases.types import CaseInfo, Section, nested_model
from shaftline.errors import InputError, located
from shaftline.pipeline import Case
from shaftline.registry import BuildContext, SectionT


@lru_cache(maxsize=4)
def _case_model(version: int) -> type[BaseModel]:
    fields: dict[str, Any] = {"case": (CaseInfo, Field(CaseInfo(), description="Name and description of the case."))}
    for key, capability in registry.capabilities().items():
        fields[key] = (capability.schema() | None, Field(None, description=capability.title))
    model: type[BaseModel] = create_model("CaseFile", __base__=Section, __doc__="A shaftline case file.", **fields)
    return model


def case_model() -> type[BaseModel]:
    """The pydantic model of a whole case file, for the capabilities registered now."""
    return _case_model(registry.version())


def _find_nan(data: Any, where: str = "") -> None:
    """Reject NaN and infinities anywhere in the parsed file (TOML allows ``nan`` and ``inf``)."""
    if isinstance(data, dict):
        for key, value in data.items():
            _find_nan(value, f"{where}.{key}" if where else str(key))
    elif isinstance(data, list):
        for k, value in enumerate(data):
            _find_nan(value, f"{where}[{k}]")
    elif isinstance(data, float) and not math.isfinite(data):
        raise InputError(where, data, "", "a finite number")


#: Parts of pydantic's error locations that name the member of a union (``float | str``,
#: ``FilmSection | bool``), not a field; the schema's tables are all named ``...Section``.
_UNION_TAGS = {"float", "int", "str", "bool"}
_TABLE_TAG = re.compile(r"[A-Z]\w*Section")


def _path(location: Iterable[Any]) -> str:
    name = ""
    for part in location:
        if isinstance(part, str) and (part in _UNION_TAGS or _TABLE_TAG.fullmatch(part)):
            continue
        if isinstance(part, int):
            name += f"[{part}]"
        elif part:
            name += f".{part}" if name else str(part)
    return name


def _model_at(root: type[BaseModel], location: tuple[Any, ...]) -> type[BaseModel] | None:
    """The model whose fields an error location points into (for spelling suggestions)."""
    model: Any = root
    for part in location:
        if isinstance(part, int) or not (isinstance(model, type) and issubclass(model, BaseModel)):
            continue
        if part == model.__name__:  # the union member's tag of a "table or value" field
            continue
        info = model.model_fields.get(part)
        if info is None:
            return None
        nested = nested_model(info.annotation)
        model = nested[0] if nested is not None else None
    return model if isinstance(model, type) and issubclass(model, BaseModel) else None


#: What pydantic's type errors ask for, in the words of the one-line message.
_EXPECTED = {
    "float_parsing": "a number",
    "float_type": "a number",
    "int_parsing": "a whole number",
    "int_type": "a whole number",
    "int_from_float": "a whole number",
    "bool_parsing": "true or false",
    "bool_type": "true or false",
    "string_type": "text in quotes",
    "list_type": "a list [...] (or an array of tables [[...]])",
    "too_short": "at least {min_length} entries",
    "too_long": "at most {max_length} entries",
}

_ALLOWED = {
    "greater_than": ("> {gt}", "gt"),
    "greater_than_equal": (">= {ge}", "ge"),
    "less_than": ("< {lt}", "lt"),
    "less_than_equal": ("<= {le}", "le"),
}


def _input_error(error: Mapping[str, Any], root: type[BaseModel], table: str) -> InputError:
    """One pydantic error of validating ``root`` (the model of ``table``) as an
    :class:`InputError` naming the field by its path in the file."""
    location = (table, *error["loc"])
    kind = error["type"]
    context = error.get("ctx") or {}
    value = error.get("input")
    if kind == "field":  # a cross-field check of a model validator names its own field
        where = _path(location)
        field = f"{where}.{context['field']}" if where else context["field"]
        return InputError(field, context["value"], context["unit"], context["allowed"])
    field = _path(location) or "case file"
    if kind == "quantity":
        return InputError(field, context["value"], context["unit"], context["allowed"])
    if kind == "missing":
        return InputError(field, "missing", "", "a value (required field)")
    if kind == "extra_forbidden":
        allowed = "no such field (check the spelling)"
        model = _model_at(root, location[1:-1])
        if model is not None:
            close = difflib.get_close_matches(str(location[-1]), list(model.model_fields), n=1)
            if close:
                allowed = f"no such field; did you mean {close[0]!r}?"
        return InputError(field, value if not isinstance(value, (dict, list)) else "{...}", "", allowed)
    if kind in _EXPECTED:
        shown = "{...}" if isinstance(value, dict) else "[...]" if isinstance(value, list) else value
        return InputError(field, shown, "", _EXPECTED[kind].format(**context))
    if kind == "literal_error":
        return InputError(field, value, "", f"one of {context['expected']}")
    if kind in _ALLOWED:
        text, key = _ALLOWED[kind]
        return InputError(field, value, "", text.format(**{key: context[key]}))
    if kind in ("model_type", "model_attributes_type", "dict_type"):
        return InputError(field, "{...}" if isinstance(value, (dict, list)) else value, "", "a table of fields")
    if isinstance(value, (dict, list)):
        value = "{...}" if isinstance(value, dict) else "[...]"
    return InputError(field, value, "", str(error["msg"]).removeprefix("Value error, "))


def _top_level(data: Mapping[str, Any]) -> None:
    """Refuse unknown tables; point a case file of the older layout (shaftline 0.1) at the
    tables' new places."""
    capabilities = registry.capabilities()
    moved = [(old, new) for c in capabilities.values() for old, new in c.moved_tables.items() if old in data]
    if moved:
        places = "; ".join(f"[{old}] under [{new}]" for old, new in moved)
        raise InputError(moved[0][0], "{...}", "", f"the new layout of case files: {places} (see CHANGELOG)")
    known = ["case", *capabilities]
    for key, value in data.items():
        if key not in known:
            close = difflib.get_close_matches(key, known, n=1)
            hint = f"; did you mean [{close[0]}]?" if close else ""
            shown = "{...}" if isinstance(value, dict) else "[...]" if isinstance(value, list) else value
            raise InputError(key, shown, "", f"one of the tables {', '.join(f'[{k}]' for k in known)}{hint}")
        if not isinstance(value, dict):
            raise InputError(key, value if not isinstance(value, list) else "[...]", "", "a table [" + key + "]")


def _validate(model: type[SectionT], data: Any, table: str) -> SectionT:
    try:
        return model.model_validate(data)
    except ValidationError as exc:
        errors = exc.errors()
        # A misspelt key is the cause of the "missing" field it was meant to be: report it first.
        errors.sort(key=lambda error: error["type"] != "extra_forbidden")
        raise _input_error(errors[0], model, table) from None


def _set(data: dict[str, Any], dotted: str, value: Any) -> None:
    *parents, last = dotted.split(".")
    if parents and parents[0] not in data:
        raise InputError("case file", "{...}", "", f"a [{parents[0]}] table (needed for {dotted})")
    node = data
    for part in parents:
        node = node.setdefault(part, {})
        if not isinstance(node, dict):
            raise InputError(dotted, value, "", "a field inside a table")
    node[last] = value


def _unusual(paths: list[str], present: list[str]) -> dict[str, list[tuple[int, str]]]:
    """The entries of ``[case] unusual`` per table (with their index), refusing wildcards and
    paths outside the tables of the case; the tables check the rest (:func:`check_table`)."""
    per_table: dict[str, list[tuple[int, str]]] = {}
    for k, path in enumerate(paths):
        if "*" in path or "?" in path:
            raise InputError(f"case.unusual[{k}]", path, "", "one field per entry (no wildcards)")
        table = re.split(r"[.\[]", path.strip(), maxsplit=1)[0]
        if table not in present:
            tables = ", ".join(f"[{key}]" for key in present)
            raise InputError(f"case.unusual[{k}]", path, "", f"the path of a field of a table of the case ({tables})")
        per_table.setdefault(table, []).append((k, path.strip()))
    return per_table


def parse_case(
    data: Mapping[str, Any],
    base_dir: Path | None = None,
    only: Iterable[str] | None = None,
    overrides: Mapping[str, Any] | None = None,
    source: Path | None = None,
) -> Case:
    """Validate a case given as a dict (as read from TOML) and build its SI domain objects.

    Parameters
    ----------
    data : mapping
        The case file's tables.
    base_dir : Path, optional
        Folder that relative file names in the case are read from (default: the working folder).
    only : iterable of str, optional
        Capability keys to validate and build (default: every table of the case); the
        other tables are left alone.
    overrides : mapping, optional
        Dotted field names and values that replace those of the file (``{"wear.pitch_log":
        "log.csv"}``), applied before validation.

    Raises
    ------
    InputError
        Naming the first bad field by its path in the file; a value outside its plausible
        range (and not listed in ``[case] unusual``) is one too
        (:class:`~shaftline.cases.plausibility.ImplausibleInput`).
    """
    document: dict[str, Any] = {key: value for key, value in data.items()}
    for dotted, value in (overrides or {}).items():
        _set(document, dotted, value)
    _find_nan(document)
    _top_level(document)
    capabilities = registry.capabilities()
    # Each table is validated by its own capability's model, so a file (or a verb) that
    # uses one capability does not build, or import, the schemas of the others.
    info = _validate(CaseInfo, document.get("case", {}), "case")
    present = [key for key in capabilities if key in document]
    if not present:
        raise InputError(
            "case file",
            str(source) if source else "{...}",
            "",
            "one of the tables " + ", ".join(f"[{k}]" for k in capabilities),
        )
    wanted = present if only is None else [key for key in present if key in set(only)]
    needed = {need for key in wanted for need in capabilities[key].needs}
    for key in wanted:
        needs = capabilities[key].needs
        if needs and not any(need in document for need in needs):
            either = " or ".join(f"[{need}]" for need in needs)
            raise InputError(
                "case file", str(source) if source else "{...}", "", f"a {either} table for [{key}] to build on"
            )
    unusual = _unusual(info.unusual, present)
    context = BuildContext(case=info, base_dir=base_dir or Path.cwd())
    studies = {}
    tables: dict[str, Any] = {"case": info.model_dump(mode="json")}
    for key in [k for k in present if k in wanted or k in needed]:
        capability = capabilities[key]
        section = _validate(capability.schema(), document[key], key)
        tables[key] = section.model_dump(mode="json")
        # after validation (paths are the file's) and before building: values a real shaft
        # line has; the entries of [case] unusual of tables not wanted are not checked here
        check_table(section, document[key], key, unusual.get(key, ()))
        with located(key):
            context.studies[key] = capability.build(section, context)
        if key in wanted:
            studies[key] = context.studies[key]
    inputs = tuple(dict.fromkeys([*([source] if source is not None else []), *context.inputs]))
    lowered = tuple(dict.fromkeys(path for entries in unusual.values() for _, path in entries))
    return Case(
        name=info.name,
        description=info.description,
        studies=studies,
        source=source,
        inputs=inputs,
        kept=tuple(dict.fromkeys(context.kept)),
        tables=tables,
        fingerprints=_fingerprints(inputs),
        unusual=lowered,
        warnings=tuple(dict.fromkeys(context.warnings)),
    )


#: Bytes read at a time to fingerprint an input file.
FINGERPRINT_BLOCK = 8 << 20


def _fingerprints(paths: Iterable[Path]) -> tuple[tuple[str, str, int], ...]:
    """(path, SHA-256, size in bytes) of each input file, for the report's record.

    Read in blocks: an input may be a recording of several GB (``monitor identify``), which
    read whole would hold its size in memory."""
    import hashlib

    out = []
    for path in paths:
        digest, size = hashlib.sha256(), 0
        try:
            with open(path, "rb") as file:
                while block := file.read(FINGERPRINT_BLOCK):
                    digest.update(block)
                    size += len(block)
        except OSError:
            continue
        out.append((str(path), digest.hexdigest(), size))
    return tuple(out)


def load_case(path: str | Path, only: Iterable[str] | None = None, overrides: Mapping[str, Any] | None = None) -> Case:
    """Read, validate and build a TOML case file (see :func:`parse_case`).

    Raises
    ------
    InputError
        For a missing or unreadable file, invalid TOML, or any invalid field.
    """
    path = Path(path)
    return parse_case(read_case_file(path), path.parent, only, overrides, source=path)
