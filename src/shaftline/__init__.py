"""shaftline: tribology of a ship's propulsion shaft line.

``load_case``, ``run_case`` and ``write_outputs`` run a case file as the command line
does (see the README's "From Python").
"""

from importlib.metadata import PackageNotFoundError, version
from typing import Any

try:
    __version__ = version("shaftline")
except PackageNotFoundError:  # running from a source tree without installation
    __version__ = "0.0.0+unknown"

#: Names imported on first use, so that ``import shaftline`` stays cheap.
_LAZY = {
    "load_case": "shaftline.cases",
    "parse_case": "shaftline.cases",
    "run_case": "shaftline.pipeline",
    "results_document": "shaftline.pipeline",
    "write_outputs": "shaftline.pipeline",
}

__all__ = ["__version__", *_LAZY]


def __getattr__(name: str) -> Any:
    if name in _LAZY:
        import importlib

        return getattr(importlib.import_module(_LAZY[name]), name)
    raise AttributeError(f"module 'shaftline' has no attribute {name!r}")
