"""Lubrication regimes from the film-thickness ratio (seed 001 Eq. 10, Table 4).

    lambda = h_min / sqrt(Rq1^2 + Rq2^2),   Rq = f * Ra,  f = 1.20 .. 1.25,

boundary lubrication for lambda < 1, mixed for 1 <= lambda <= 3, hydrodynamic above 3.
With the seed's liner and sleeve (Ra 1.6 and 0.8 um, f = 1.25) the thresholds are
h_min = 2.24 um and 6.71 um.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from shaftline.errors import InputError
from shaftline.monitor.probes import ProbeLayout

#: Film-thickness ratios that bound the mixed regime (seed 001 Sect. 5.3).
MIXED_RANGE = (1.0, 3.0)
#: Regime codes of :func:`classify`, in order of thickening film.
REGIMES = ("boundary", "mixed", "hydrodynamic")


def film_ratio(min_film: np.ndarray, layout: ProbeLayout) -> np.ndarray:
    """lambda = h_min / sqrt(Rq1^2 + Rq2^2) for films ``min_film`` (m); dimensionless."""
    return np.asarray(min_film, dtype=float) / layout.composite_roughness


def thresholds(layout: ProbeLayout) -> tuple[float, float]:
    """Films at lambda = 1 and 3, m: below the first boundary, above the second hydrodynamic."""
    sigma = layout.composite_roughness
    return MIXED_RANGE[0] * sigma, MIXED_RANGE[1] * sigma


def classify(min_film: np.ndarray, layout: ProbeLayout) -> np.ndarray:
    """Regime code of each film: 0 boundary, 1 mixed, 2 hydrodynamic (:data:`REGIMES`)."""
    low, high = thresholds(layout)
    h = np.asarray(min_film, dtype=float)
    return (h >= low).astype(np.int8) + (h > high).astype(np.int8)


@dataclass(frozen=True, eq=False)
class RegimeLengths:
    """Axial extent of each regime along the bearing (seed 001 Table 4), m.

    Attributes
    ----------
    boundary, mixed, hydrodynamic : ndarray (N,)
        Lengths of the bearing in each regime at every sample (or operating point), m;
        they sum to the length covered by the stations.
    """

    boundary: np.ndarray
    mixed: np.ndarray
    hydrodynamic: np.ndarray


def _length_below(z: np.ndarray, h: np.ndarray, level: float) -> np.ndarray:
    """Length of the stations' span where the piecewise-linear film is below ``level``, (N,)."""
    h0, h1 = h[:, :-1], h[:, 1:]
    dz = np.diff(z)[None, :]
    with np.errstate(divide="ignore", invalid="ignore"):
        crossing = np.clip((level - h0) / (h1 - h0), 0.0, 1.0)
    # Rising film: below from the start to the crossing; falling: from the crossing on.
    share = np.where(h1 > h0, crossing, 1.0 - crossing)
    share = np.where(h0 == h1, (h0 < level).astype(float), share)
    return (share * dz).sum(axis=1)


def regime_lengths(z: np.ndarray, min_film: np.ndarray, layout: ProbeLayout) -> RegimeLengths:
    """Lengths of the boundary, mixed and hydrodynamic regions along the bearing.

    The smallest film round the bore at each station is taken as linear between stations,
    so each threshold crossing is placed between nodes and the lengths converge with the
    station spacing squared.

    Parameters
    ----------
    z : ndarray (nz,)
        Stations along the bearing, m, increasing.
    min_film : ndarray (N, nz) or (nz,)
        Smallest film round the bore at each station, m.
    layout : ProbeLayout
        Roughness of the surfaces.
    """
    z = np.asarray(z, dtype=float)
    h = np.atleast_2d(np.asarray(min_film, dtype=float))
    if z.ndim != 1 or z.size < 2 or np.any(np.diff(z) <= 0):
        raise InputError("z", z.size, "m", "at least 2 increasing stations")
    if h.shape[-1] != z.size:
        raise InputError("min_film", h.shape, "m", f"(samples, {z.size})")
    low, high = thresholds(layout)
    below_low = _length_below(z, h, low)
    below_high = _length_below(z, h, high)
    return RegimeLengths(below_low, below_high - below_low, (z[-1] - z[0]) - below_high)
