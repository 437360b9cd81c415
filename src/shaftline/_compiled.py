"""Importing this module loads the compiled (numba) kernels of the film solver.

The process pool's fork server imports it before it forks its workers
(:func:`shaftline.parallel`'s start-up), so that every worker starts with the kernels loaded
instead of paying numba's import and cache load (0.3-0.7 s) at its first film solution.
Commands that solve nothing never import it.
"""

from __future__ import annotations

from shaftline.film import relaxation

relaxation.load()
