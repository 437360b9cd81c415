"""Case files: TOML with units, validated by pydantic and converted once to SI."""

from shaftline.cases.loader import load_case, parse_case
from shaftline.cases.schema import BearingCase, Case

__all__ = ["BearingCase", "Case", "load_case", "parse_case"]
