"""Reading a case file's text: cheap, so that a missing file or bad TOML is reported
before pydantic, numpy or pint are imported."""

from __future__ import annotations

import tomllib
from pathlib import Path
from typing import Any

from shaftline.errors import InputError


def read_case_file(path: str | Path) -> dict[str, Any]:
    """The tables of a TOML case file (raises :class:`InputError` for a missing file or bad TOML)."""
    path = Path(path)
    try:
        text = path.read_text(encoding="utf-8")
    except FileNotFoundError:
        raise InputError("case file", str(path), "", "an existing file") from None
    except IsADirectoryError:
        raise InputError("case file", str(path), "", "a file, not a folder") from None
    except UnicodeDecodeError:
        raise InputError("case file", str(path), "", "a UTF-8 text file") from None
    except OSError as exc:
        raise InputError("case file", str(path), "", f"a readable file ({exc.strerror})") from None
    try:
        return tomllib.loads(text)
    except tomllib.TOMLDecodeError as exc:
        raise InputError("case file", str(path), "", f"valid TOML ({exc})") from None
