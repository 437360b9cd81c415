"""Case files: one TOML table per capability, validated by pydantic with units (pint),
converted once to SI domain objects.

>>> from shaftline.cases import parse_case
>>> case = parse_case({
...     "bearing": {
...         "length": "0.1 m", "diameter": "0.1 m", "radial_clearance": "0.1 mm",
...         "operation": {"speed": "600 rpm", "load": "5 kN"},
...         "lubricant": {"viscosity": "20 cP"},
...     }
... })
>>> case["bearing"].cases[0].operating.viscosity
0.02
"""

from typing import TYPE_CHECKING, Any

from shaftline.cases.files import read_case_file

if TYPE_CHECKING:
    from shaftline.cases.loader import case_model, load_case, parse_case

__all__ = ["case_model", "load_case", "parse_case", "read_case_file"]


def __getattr__(name: str) -> Any:
    # The loader brings pydantic and the schemas: imported on first use, so that reading
    # a case file's text (and failing on a missing one) stays cheap.
    if name in ("case_model", "load_case", "parse_case"):
        from shaftline.cases import loader

        return getattr(loader, name)
    raise AttributeError(f"module 'shaftline.cases' has no attribute {name!r}")
