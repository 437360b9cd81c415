"""Reading a TOML case file into SI domain objects."""

from __future__ import annotations

import math
import tomllib
from pathlib import Path
from typing import Any

from pydantic import ValidationError

from shaftline.cases.schema import Case, CaseIn, build_case
from shaftline.errors import InputError


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


def _field_name(location: tuple[Any, ...]) -> str:
    name = ""
    for part in location:
        if isinstance(part, int):
            name += f"[{part}]"
        elif part in ("float", "int", "str", "function-after[_one_slope(), BoreSegmentIn]"):
            continue
        else:
            name += f".{part}" if name else str(part)
    return name


def parse_case(data: dict[str, Any], base_dir: Path | None = None) -> Case:
    """Validate a case given as a dict (as read from TOML) and convert it to SI.

    Relative file names in the case are read from ``base_dir`` (default: the working folder).
    """
    _find_nan(data)
    try:
        model = CaseIn.model_validate(data)
    except ValidationError as exc:
        error = exc.errors()[0]
        location = tuple(p for p in error["loc"] if not (isinstance(p, str) and ("[" in p or "function" in p)))
        field = _field_name(location) or "case"
        value = error.get("input")
        message = error["msg"]
        if error["type"] == "missing":
            raise InputError(field, "missing", "", "a value (required field)") from None
        if error["type"] == "extra_forbidden":
            raise InputError(field, value, "", "no such field (check the spelling)") from None
        if isinstance(value, dict):
            value = "{...}"
        raise InputError(field, value, "", message.removeprefix("Value error, ")) from None
    return build_case(model, base_dir)


def load_case(path: str | Path) -> Case:
    """Read and validate a TOML case file.

    Raises
    ------
    InputError
        For a missing or unreadable file, invalid TOML, or any invalid field.
    """
    path = Path(path)
    try:
        text = path.read_text(encoding="utf-8")
    except FileNotFoundError:
        raise InputError("case file", str(path), "", "an existing file") from None
    except OSError as exc:
        raise InputError("case file", str(path), "", f"a readable file ({exc.strerror})") from None
    try:
        data = tomllib.loads(text)
    except tomllib.TOMLDecodeError as exc:
        raise InputError("case file", str(path), "", f"valid TOML ({exc})") from None
    return parse_case(data, path.parent)
