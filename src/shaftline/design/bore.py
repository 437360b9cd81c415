"""Design variables of a slope-bored bore: N segment slopes and N - 1 knuckle positions.

Seed 004 (Sect. 4.5.5, Table 4-8) searches a double slope with three variables: the slopes of
the aft and forward segments as shares of 2c/L and the knuckle position as a share of L. This
generalises it to N segments (N = 1: a single slope; N = 3 …). Variables, in order: the slopes
from aft to forward, then the knuckle positions from aft to forward.

Default bounds: the slopes of Table 4-8 (aft 0-0.6, forward 0-0.3 of 2c/L; further segments
0-0.6). Its knuckle bound, 0-0.5 of L, is not used: the thesis's own optima have aft segments
of 0.58-0.74 L and forward segments up to 0.8 L (``../shared/reference/seed004-chapter5.md``
§2), outside it in either reading, so that bound cannot be the one searched. The default
keeps every segment at least a tenth of L: knuckles in 0.1-0.9 of L.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from shaftline.errors import InputError, require_finite
from shaftline.film.geometry import BoreSegment

#: Slope bounds of seed 004 Table 4-8 (shares of 2c/L): aft (its "secondary") and forward
#: ("primary") segment.
SEED_SLOPE_BOUNDS = ((0.0, 0.6), (0.0, 0.3))
#: Default knuckle bounds (shares of L from the aft edge); see the module docstring.
KNUCKLE_BOUNDS = (0.1, 0.9)


@dataclass(frozen=True)
class SlopeParametrisation:
    """A bore of ``segments`` slope segments and the bounds of its design variables.

    Attributes
    ----------
    segments : int
        Number of slope segments, >= 1.
    slope_bounds : tuple of (float, float)
        (lower, upper) slope of each segment from aft to forward, as shares of 2c/L (positive:
        the bore axis rises going forward, the aft end machined lower). Default: seed 004
        Table 4-8 for two segments, (0, 0.6) for each segment otherwise.
    knuckle_bounds : tuple of (float, float)
        (lower, upper) position of each knuckle from aft to forward, as shares of L from the
        aft edge. Default (0.1, 0.9) each.

    Raises
    ------
    InputError
        ``"segments"`` below 1; ``"slope_bounds[k]"`` or ``"knuckle_bounds[k]"`` with lower >
        upper, a knuckle bound outside (0, 1) or below the previous knuckle's (out of order), or
        the wrong number of bounds.
    """

    segments: int = 2
    slope_bounds: tuple[tuple[float, float], ...] | None = None
    knuckle_bounds: tuple[tuple[float, float], ...] | None = None

    def __post_init__(self) -> None:
        if isinstance(self.segments, bool) or not isinstance(self.segments, int) or self.segments < 1:
            raise InputError("segments", self.segments, "", "an integer >= 1")
        n = self.segments
        if self.slope_bounds is None:
            slopes = SEED_SLOPE_BOUNDS if n == 2 else tuple((0.0, 0.6) for _ in range(n))
            object.__setattr__(self, "slope_bounds", slopes)
        if self.knuckle_bounds is None:
            object.__setattr__(self, "knuckle_bounds", tuple(KNUCKLE_BOUNDS for _ in range(n - 1)))
        for name, bounds, count in (
            ("slope_bounds", self.slope_bounds, n),
            ("knuckle_bounds", self.knuckle_bounds, n - 1),
        ):
            assert bounds is not None
            if len(bounds) != count:
                raise InputError(name, len(bounds), "", f"{count} (lower, upper) pairs for {n} segments")
            for k, pair in enumerate(bounds):
                if len(pair) != 2:
                    raise InputError(f"{name}[{k}]", pair, "", "a (lower, upper) pair")
                lower = require_finite(f"{name}[{k}]", pair[0])
                upper = require_finite(f"{name}[{k}]", pair[1])
                if lower > upper:
                    raise InputError(f"{name}[{k}]", [lower, upper], "", "lower <= upper")
                if name == "knuckle_bounds" and not 0.0 < lower <= upper < 1.0:
                    raise InputError(f"{name}[{k}]", [lower, upper], "", "within (0, 1) of the length")
                if name == "knuckle_bounds" and k and (lower < bounds[k - 1][0] or upper < bounds[k - 1][1]):
                    # bore() sorts the knuckles, so bounds given forward to aft would silently
                    # bound other knuckles than the user meant
                    raise InputError(
                        f"{name}[{k}]",
                        [lower, upper],
                        "",
                        f"knuckles aft to forward: bounds not below those of knuckle_bounds[{k - 1}] "
                        f"{list(bounds[k - 1])}",
                    )

    @property
    def variables(self) -> int:
        """Number of design variables, 2N - 1."""
        return 2 * self.segments - 1

    @property
    def names(self) -> list[str]:
        """Variable names: ``slope_1`` (aft) … ``slope_N``, ``knuckle_1`` … ``knuckle_{N-1}``."""
        n = self.segments
        return [f"slope_{k + 1}" for k in range(n)] + [f"knuckle_{k + 1}" for k in range(n - 1)]

    @property
    def lower(self) -> np.ndarray:
        assert self.slope_bounds is not None and self.knuckle_bounds is not None
        return np.array([b[0] for b in self.slope_bounds] + [b[0] for b in self.knuckle_bounds], dtype=float)

    @property
    def upper(self) -> np.ndarray:
        assert self.slope_bounds is not None and self.knuckle_bounds is not None
        return np.array([b[1] for b in self.slope_bounds] + [b[1] for b in self.knuckle_bounds], dtype=float)

    def bore(self, x: np.ndarray, length: float, radial_clearance: float) -> tuple[BoreSegment, ...]:
        """The bore of design ``x`` (shares of 2c/L and of L) in :class:`BoreSegment` form.

        Knuckles are taken in increasing order (a search may propose them crossed); coincident
        knuckles leave a segment of zero length out.
        """
        x = np.asarray(x, dtype=float)
        if x.shape != (self.variables,):
            raise InputError("x", list(x.shape), "", f"{self.variables} design variables")
        n = self.segments
        scale = 2.0 * radial_clearance / length
        knuckles = np.sort(np.clip(x[n:], 0.0, 1.0))
        edges = np.concatenate(([0.0], knuckles, [1.0]))
        fractions = np.diff(edges)
        segments = [
            BoreSegment(length_fraction=float(f), slope=float(s * scale))
            for f, s in zip(fractions, x[:n], strict=True)
            if f > 1e-12
        ]
        # The fractions must sum to 1 exactly for BearingGeometry; put round-off on the last.
        total = sum(s.length_fraction for s in segments[:-1])
        last = segments[-1]
        segments[-1] = BoreSegment(length_fraction=1.0 - total, slope=last.slope)
        return tuple(segments)
