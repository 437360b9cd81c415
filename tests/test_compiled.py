"""The compiled kernels (numba) where numba can write no cache.

numba caches compiled code next to the source or in a user cache folder; where it can write
neither (a read-only installation), ``njit(cache=True)`` raised ``RuntimeError: cannot cache
function`` when the module was imported, and the film solver, the friction laws, the
blade-carrier motion and the probe identification were unusable (a review found it for the
film solver; the same test found it for the others).
:func:`shaftline._compiled.njit_cached` then compiles without the cache.
"""

from __future__ import annotations

import os
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

import shaftline

_PROBE = """
import numpy as np
import shaftline
assert shaftline.__file__.startswith({root!r}), shaftline.__file__
import shaftline.cpp._carrier, shaftline.monitor.identification
from shaftline.film.relaxation import projected_sor
from shaftline.friction.kernels import stribeck_level
out = projected_sor(np.array([[1.0], [0.0], [1.0]]), np.zeros((3, 1)), np.ones((2, 1)), np.zeros((3, 1)),
                    np.array([[True], [False], [True]]), sweeps=1, omega=1.0)
print(out.ravel().tolist(), stribeck_level(0.0, 1.0, 2.0, 0.1))
"""


@pytest.mark.skipif(not Path("/proc").is_dir(), reason="needs a folder no process can create files in (Linux /proc)")
def test_the_kernels_compile_where_numba_can_write_no_cache(tmp_path):
    """A copy of the package whose ``__pycache__`` folders are files, with every cache folder
    numba looks at under /proc: the kernel modules import and compute (fails without
    ``njit_cached``: RuntimeError at import)."""
    copy = tmp_path / "shaftline"
    shutil.copytree(Path(shaftline.__file__).resolve().parent, copy, ignore=shutil.ignore_patterns("__pycache__"))
    for folder in (copy, copy / "film", copy / "friction", copy / "cpp", copy / "monitor"):
        (folder / "__pycache__").write_text("")  # numba cannot make its cache folder here
    nowhere = "/proc/no-such-folder"
    env = {**os.environ, "PYTHONPATH": str(tmp_path), "NUMBA_CACHE_DIR": nowhere, "XDG_CACHE_HOME": nowhere}
    env["HOME"] = nowhere
    probe = _PROBE.format(root=str(tmp_path))
    result = subprocess.run([sys.executable, "-c", probe], env=env, capture_output=True, text=True, timeout=300)
    assert result.returncode == 0, result.stderr
    assert result.stdout.split() == ["[1.0,", "1.0,", "1.0]", "2.0"]
