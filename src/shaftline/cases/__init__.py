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

from shaftline.cases.loader import case_model, load_case, parse_case, read_case_file

__all__ = ["case_model", "load_case", "parse_case", "read_case_file"]
