"""numba's ``njit`` with its on-disk cache where one can be written, without it elsewhere.

numba caches compiled code next to the source (``__pycache__``) or in a user cache folder, and
``njit(cache=True)`` raises ``RuntimeError: cannot cache function ...: no locator available``
when it can write neither (a read-only installation with no writable ``NUMBA_CACHE_DIR``, user
cache folder or home). The kernels then compile in every process instead (a few seconds) rather
than leave the package unusable. Imports numba: import it only from modules of compiled code.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

from numba import njit

__all__ = ["njit_cached"]


def njit_cached(signature: str | None = None, **options: Any) -> Callable[[Callable[..., Any]], Any]:
    """``numba.njit(signature, cache=True, **options)``, or without the cache where numba can
    write none. With a ``signature`` the function compiles (or loads from the cache) when the
    decorator runs; without one at its first call, for each argument type."""

    def decorate(function: Callable[..., Any]) -> Any:
        try:
            return njit(signature, cache=True, **options)(function)
        except RuntimeError:  # "cannot cache function ...: no locator available for file ..."
            return njit(signature, cache=False, **options)(function)

    return decorate
