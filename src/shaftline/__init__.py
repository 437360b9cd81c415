"""shaftline: tribology of a ship's propulsion shaft line."""

from importlib.metadata import PackageNotFoundError, version

try:
    __version__ = version("shaftline")
except PackageNotFoundError:  # running from a source tree without installation
    __version__ = "0.0.0+unknown"

__all__ = ["__version__"]
