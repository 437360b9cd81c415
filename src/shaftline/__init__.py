"""shaftline: tribology of a ship's propulsion shaft line.

``load_case``, ``run_case`` and ``write_outputs`` run a case file as the command line
does (see the README's "From Python").
"""

from functools import lru_cache
from typing import Any


@lru_cache(maxsize=1)
def _version() -> str:
    # importlib.metadata costs about 0.05 s: paid by the commands that show the version.
    from importlib.metadata import PackageNotFoundError, version

    try:
        return version("shaftline")
    except PackageNotFoundError:  # running from a source tree without installation
        return "0.0.0+unknown"


def example(name: str) -> Any:
    """The path of an example case or data file of the source repository's ``examples``
    folder (found relative to this package, so it works from any working folder).

    >>> example("ntua_stern_tube.toml").name
    'ntua_stern_tube.toml'
    """
    from pathlib import Path

    folder = Path(__file__).resolve().parents[2] / "examples"
    path = folder / name
    if not path.is_file():
        known = ", ".join(sorted(p.name for p in folder.glob("*.*"))) if folder.is_dir() else "none here"
        raise FileNotFoundError(f"no example {name!r} in {folder} (examples: {known})")
    return path


#: Names imported on first use, so that ``import shaftline`` stays cheap.
_LAZY = {
    "load_case": "shaftline.cases",
    "parse_case": "shaftline.cases",
    "run_case": "shaftline.pipeline",
    "results_document": "shaftline.pipeline",
    "write_outputs": "shaftline.pipeline",
}

__all__ = ["__version__", "example", *_LAZY]


def __getattr__(name: str) -> Any:
    if name == "__version__":
        return _version()
    if name in _LAZY:
        import importlib

        return getattr(importlib.import_module(_LAZY[name]), name)
    raise AttributeError(f"module 'shaftline' has no attribute {name!r}")
