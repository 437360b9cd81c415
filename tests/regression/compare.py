"""Number-by-number comparison of two results documents (JSON), shared by the regression tests.

Three rules, each with its reason:

* every number to ``rtol`` relative;
* an entry of a list also passes within ``share`` of the list's largest magnitude: a pressure at
  a cavitated node or a reaction of an unloaded support is rounding next to its neighbours;
* a number that is the residual of a converged iteration where the answer is zero (named in
  :data:`RESIDUAL_ATOL`) passes within an absolute bound far below anything physical. Such a
  number is rounding below the solver's tolerance: another machine's floating-point kernels, or
  another path of the same Newton iteration, move it by orders of magnitude (1e-10 to 1e-3 N on
  the film examples) without any result moving.

Strings, booleans and integers that are counts (Newton iterations) compare exactly, so a change
of the solver's path shows there even where its numbers stay inside the tolerance.
"""

from __future__ import annotations

import math
from typing import Any

#: Residual-level numbers and their absolute bounds. A film equilibrium's force tolerance is 1e-8
#: of the load (3.1e-3 N on the NTUA stern tube, 7.5e-4 N on the water rig); a real horizontal load
#: or moment in the examples is 1e3 N or N m or more, a real load-centre offset a millimetre, a
#: probe's resolution 0.1 µm.
RESIDUAL_ATOL = {
    "force_z": 3.1e-3,  # N: a vertical load's horizontal film force
    "force_residual": 3.1e-3,  # N: what the equilibrium leaves unbalanced
    "moment_y": 1e-5,  # N m: the moments of an aligned or symmetric film
    "moment_z": 1e-5,  # N m
    "load_centre_offset": 1e-12,  # m: the load centre of a film with no moment
    "residual": 1e-12,  # m: the monitor's fit residual of a section read by exactly enough probes
}


def is_number(value: Any) -> bool:
    return isinstance(value, (int, float)) and not isinstance(value, bool)


def compare(actual: Any, expected: Any, rtol: float, share: float, path: str = "", scale: float = 0.0) -> list[str]:
    """Where ``actual`` differs from ``expected`` beyond the tolerance, one readable line each.

    Parameters
    ----------
    actual, expected : JSON values (dict, list, str, bool, None, int, float)
    rtol : float
        Relative tolerance of every number.
    share : float
        Absolute tolerance of a list's entry, as a fraction of the list's largest magnitude.
    path : str
        Where ``expected`` sits in its document (for the message).
    scale : float
        The largest magnitude of the list that holds ``expected`` (0 outside a list).
    """
    if isinstance(expected, dict):
        if not isinstance(actual, dict) or set(actual) != set(expected):
            keys = sorted(actual) if isinstance(actual, dict) else actual
            return [f"{path}: keys {keys!r} != {sorted(expected)}"]
        return [
            line
            for key in expected
            for line in compare(actual[key], expected[key], rtol, share, f"{path}.{key}" if path else key)
        ]
    if isinstance(expected, list):
        if not isinstance(actual, list) or len(actual) != len(expected):
            length = len(actual) if isinstance(actual, list) else actual
            return [f"{path}: length {length!r} != {len(expected)}"]
        largest = max((abs(v) for v in expected if is_number(v)), default=0.0)
        return [
            line
            for k, (a, e) in enumerate(zip(actual, expected, strict=True))
            for line in compare(a, e, rtol, share, f"{path}[{k}]", largest)
        ]
    counts = is_number(expected) and isinstance(expected, int) and is_number(actual) and isinstance(actual, int)
    if counts or not (is_number(expected) and is_number(actual)):
        same = type(actual) is type(expected) and actual == expected
        return [] if same else [f"{path}: {actual!r} != {expected!r}"]
    atol = max(share * scale, RESIDUAL_ATOL.get(path.rsplit(".", 1)[-1], 0.0))
    close = math.isclose(actual, expected, rel_tol=rtol, abs_tol=atol)
    return [] if close else [f"{path}: {actual!r} != {expected!r}"]
