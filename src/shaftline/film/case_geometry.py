"""The bearing's shape in ``[bearing]``: the slope-bored bore (``[[bearing.bore]]``), the
journal's bend (``[bearing.bent_journal]``), an additive film change
(``[bearing.film_profile]``) and the sense of rotation, with the slope ranges the tilts of
``[bearing.operation]`` and ``[[bearing.variants]]`` share."""

from __future__ import annotations

from typing import Annotated, Any

import numpy as np
from pydantic import model_validator

from shaftline.cases.types import (
    Angle,
    Length,
    Number,
    Plausible,
    PositiveFraction,
    Section,
    default_of,
    field_error,
)
from shaftline.errors import InputError
from shaftline.film.geometry import BoreSegment, FilmProfile

ROTATION_ALIASES = {
    "clockwise_from_aft": "clockwise",
    "cw": "clockwise",
    "counterclockwise": "anticlockwise",
    "anticlockwise_from_aft": "anticlockwise",
    "ccw": "anticlockwise",
}


# Plausible ranges of a marine stern-tube bearing (the README's table of plausible ranges is
# made from them). They are generous: they catch a unit slip (a factor of 25.4 or 1000, a
# bare number read as SI), not an unusual bearing, which a case lists in [case] unusual.
SLOPE = Plausible(
    -0.01,
    0.01,
    "relative slopes in stern-tube bearings are about 0.1-0.5 mrad (class limit about 0.3 mrad, rules.toml; "
    "seed 004 tilts 0.3-0.6 x 2c/L, 0.26-0.51 mrad); 10 mrad (0.57 deg) is 20 times that, a slope in mrad or "
    "deg written as a bare number (rad) is far above it",
)
CLEARANCE_SHARE = Plausible(
    -3.0,
    3.0,
    "seed 004 optimises slopes and tilts of 0.1-0.6 x 2c/L; 1 brings the journal edge onto the bore, 3 is "
    "three times that (engineering judgement); a share written in % (30 for 0.3) is far outside",
)


def _rotation_alias(value: Any) -> Any:
    if isinstance(value, str):
        key = value.strip().lower()
        return ROTATION_ALIASES.get(key, key)
    return value


class BoreSegmentSection(Section):
    """A slope-bored segment of the bore (aft to forward)."""

    length_fraction: PositiveFraction
    """Share of the bearing length; the shares of all segments sum to 1."""
    slope: Annotated[Angle, SLOPE] | None = None
    """Slope of the bore axis in the vertical plane (+ rising forward); or give slope_ratio."""
    slope_ratio: Annotated[Number, CLEARANCE_SHARE] | None = None
    """Slope as a share of 2c/L (the dimensionless slope of seed 004)."""
    slope_horizontal: Annotated[Angle, SLOPE] = default_of(BoreSegment, "slope_horizontal")
    """Slope in the horizontal plane (+ towards starboard going forward)."""

    @model_validator(mode="after")
    def _one_slope(self) -> BoreSegmentSection:
        if (self.slope is None) == (self.slope_ratio is None):
            raise field_error("slope", "missing" if self.slope is None else self.slope, "either slope or slope_ratio")
        return self


JOURNAL_OFFSET = Plausible(
    -0.01,
    0.01,
    "the journal's bend within a bearing is of the order of its clearance (seed 004 Table 5-29: up to 0.7 mm); "
    "10 mm is ten times the largest clearances (engineering judgement); mm written as m is above it",
)


class BentJournalSection(Section):
    """Journal centre line along the bearing (from a shaft model), linearly interpolated."""

    z: list[Annotated[Length, Plausible(0.0, 4.0, "stations within the bearing: as its length")]]
    """Stations from the aft edge."""
    dy: list[Annotated[Length, JOURNAL_OFFSET]]
    """Vertical offsets of the journal centre at the stations."""
    dz: list[Annotated[Length, JOURNAL_OFFSET]] | None = None
    """Horizontal offsets (default zero)."""


class FilmProfileSection(Section):
    """Additive film change delta(theta, z) from a CSV (wear, bore errors)."""

    file: str
    """CSV with columns theta_deg, z, delta on a full grid; path relative to the case file."""
    length_unit: str = "m"
    """Unit of z and delta in the file."""


def read_film_profile(path: Any, length_unit: str = "m") -> FilmProfile:
    """Read an additive film profile from CSV: columns ``theta_deg, z, delta``, one row per
    point of a full regular grid (any order); z and delta in ``length_unit``."""
    from shaftline.csvio import read_columns
    from shaftline.units import to_si

    scale = to_si(f"1 {length_unit}", "length", "length_unit")
    table = read_columns(path, ["theta_deg", "z", "delta"], "file")
    theta = np.unique(table["theta_deg"])
    z = np.unique(table["z"])
    if theta.size * z.size != table["z"].size:
        raise InputError("file", str(path), "", f"a full grid of {theta.size} angles x {z.size} stations")
    delta = np.full((z.size, theta.size), np.nan)
    delta[np.searchsorted(z, table["z"]), np.searchsorted(theta, table["theta_deg"])] = table["delta"]
    if np.isnan(delta).any():
        raise InputError("file", str(path), "", "each (theta_deg, z) pair exactly once")
    return FilmProfile(theta=np.radians(theta), z=z * scale, delta=delta * scale)


def _bore(segments: list[BoreSegmentSection], length: float, clearance: float) -> tuple[BoreSegment, ...]:
    return tuple(
        BoreSegment(
            length_fraction=segment.length_fraction,
            slope=segment.slope_ratio * 2.0 * clearance / length
            if segment.slope_ratio is not None
            else segment.slope or 0.0,
            slope_horizontal=segment.slope_horizontal,
        )
        for segment in segments
    )


def _tilt(angle: float | None, ratio: float | None, length: float, clearance: float) -> float:
    if ratio is not None:
        return ratio * 2.0 * clearance / length
    return 0.0 if angle is None else angle
