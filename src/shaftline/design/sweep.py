"""The best bores across misalignments: one search per misalignment ratio psi_x (seed 004
Sect. 5.2, Tables 5-31…5-36: the Pareto-dominant designs for psi_x = 0.1 … 0.6).

The problem at each ratio comes from a function of psi_x, so that the journal may be the linear
shaft (tilt psi_x 2c/L, :func:`linear_shaft`) or a bent one whose shape changes with psi_x (the
local shaft model, :func:`shaftline.design.shaft_models.bent_shaft`).
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import dataclass, replace
from typing import Any

from shaftline.design.problem import SlopeDesignProblem
from shaftline.design.search import SearchProgress, SearchResult, search
from shaftline.errors import InputError, require_finite

__all__ = ["DEFAULT_RATIOS", "SweepResult", "linear_shaft", "misalignment_sweep"]

#: Seed 004 Sect. 5.2 (Tables 5-31…5-36).
DEFAULT_RATIOS = (0.1, 0.2, 0.3, 0.4, 0.5, 0.6)


def linear_shaft(problem: SlopeDesignProblem) -> Callable[[float], SlopeDesignProblem]:
    """``psi_x -> problem`` with a straight journal tilted by ``psi_x 2c/L`` (the seed's linear shaft)."""
    geometry = problem.film.geometry
    scale = 2.0 * geometry.radial_clearance / geometry.length

    def at(ratio: float) -> SlopeDesignProblem:
        return replace(problem, tilt_y=ratio * scale)

    return at


@dataclass(frozen=True, eq=False)
class SweepResult:
    """One search per misalignment ratio.

    Attributes
    ----------
    ratios : tuple of float
    searches : list of SearchResult
    """

    ratios: tuple[float, ...]
    searches: list[SearchResult]

    def dominant(self) -> Any:
        """The Pareto-dominant designs of every ratio as one pandas DataFrame (column ``psi_x``)."""
        import pandas as pd

        frames = []
        for ratio, result in zip(self.ratios, self.searches, strict=True):
            table = result.table()
            front = table[table["pareto"]].copy()
            front.insert(0, "psi_x", ratio)
            frames.append(front)
        return pd.concat(frames, ignore_index=True)


def misalignment_sweep(
    problem_at: Callable[[float], SlopeDesignProblem] | SlopeDesignProblem,
    ratios: Sequence[float] = DEFAULT_RATIOS,
    *,
    progress: Callable[[float, SearchProgress], None] | None = None,
    **options: Any,
) -> SweepResult:
    """A search at each misalignment ratio.

    Parameters
    ----------
    problem_at : callable or SlopeDesignProblem
        ``psi_x -> SlopeDesignProblem``; a problem alone means its linear shaft
        (:func:`linear_shaft`).
    ratios : sequence of float
        psi_x values (default 0.1 … 0.6).
    progress : callable, optional
        ``progress(psi_x, SearchProgress)`` after each generation of each search.
    **options
        Passed to :func:`~shaftline.design.search.search` (algorithm, population, generations,
        seed, backend, workers, scheduler); a ``store`` folder gets one sub-folder per ratio.

    Raises
    ------
    InputError
        ``"ratios"`` empty or not finite.
    """
    if not len(ratios):
        raise InputError("ratios", [], "", "at least one misalignment ratio")
    values = tuple(require_finite(f"ratios[{k}]", r) for k, r in enumerate(ratios))
    at = linear_shaft(problem_at) if isinstance(problem_at, SlopeDesignProblem) else problem_at
    store = options.pop("store", None)
    searches = []
    for ratio in values:
        told = None if progress is None else (lambda state, ratio=ratio: progress(ratio, state))
        where = None if store is None else f"{store}/psi_{ratio:g}"
        searches.append(search(at(ratio), store=where, progress=told, **options))
    return SweepResult(values, searches)
