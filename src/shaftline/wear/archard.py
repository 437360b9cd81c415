"""Archard wear: depth from specific wear rate, contact pressure and sliding distance.

    h = w * sigma * S            (seed 000 Eq. 2.5, 5.2, 6.2)

with w the specific wear rate. SI inside: w in m^3/(N m) (= m^2/N), sigma in Pa, S in m,
h in m. Data sets and users quote w in mm^3/(N m): 1 mm^3/(N m) = 1e-9 m^3/(N m).
"""

from __future__ import annotations

import math
import tomllib
from dataclasses import dataclass
from importlib.resources import files

import numpy as np

from shaftline.errors import InputError, require_finite, require_positive

MM3_PER_NM = 1e-9  # m^3/(N m) in one mm^3/(N m)


def wear_depth(rate: float, pressure: float, distance: float | np.ndarray) -> float | np.ndarray:
    """Archard wear depth h = w sigma S, m (rate in m^3/(N m), pressure Pa, distance m)."""
    require_positive("rate", rate, "m^3/(N m)")
    require_positive("pressure", pressure, "Pa")
    return rate * pressure * np.asarray(distance, dtype=float)


def allowable_rate(depth_limit: float, pressure: float, distance: float) -> float:
    """Largest specific wear rate that keeps the depth within ``depth_limit`` (seed Eq. 6.5), m^3/(N m)."""
    require_positive("depth_limit", depth_limit, "m")
    require_positive("pressure", pressure, "Pa")
    require_positive("distance", distance, "m")
    return depth_limit / (pressure * distance)


def wear_class(rate: float) -> int:
    """Wear class of a specific wear rate (van Beek 2004, seed 000 Table 5.5): class k for
    1e-(10-k) <= w < 1e-(9-k) mm^3/(N m); classes 0-7."""
    value = require_finite("rate", rate, "m^3/(N m)") / MM3_PER_NM
    if not 1e-10 <= value < 1e-2:
        raise InputError("rate", rate, "m^3/(N m)", "within the classified range 1e-19 to 1e-11 (0 to 7)")
    return int(math.floor(math.log10(value))) + 10


@dataclass(frozen=True)
class MaterialPair:
    """A measured specific wear rate of a material pair.

    Attributes
    ----------
    name : str
    test : str
        Where it comes from.
    rate : float
        m^3/(N m).
    kind : str
        ``stable``, ``overall`` or ``fretting``.
    """

    name: str
    test: str
    rate: float
    kind: str


def material_pairs(extra: list[dict] | None = None) -> list[MaterialPair]:
    """The bundled wear-rate data set (seed 000 Tables 5.4, 5.6, 5.12) plus ``extra`` entries
    given as dicts with ``name``, ``test``, ``rate`` (mm^3/(N m)) and ``kind``."""
    text = files("shaftline.wear").joinpath("data/wear_rates.toml").read_text(encoding="utf-8")
    entries = tomllib.loads(text)["pair"] + list(extra or [])
    pairs = []
    for k, entry in enumerate(entries):
        rate = require_positive(f"pairs[{k}].rate", entry.get("rate", float("nan")), "mm^3/(N m)")
        pairs.append(
            MaterialPair(
                str(entry.get("name", "")),
                str(entry.get("test", "")),
                rate * MM3_PER_NM,
                str(entry.get("kind", "overall")),
            )
        )
    return pairs
