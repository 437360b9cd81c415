"""Robustness of chosen bores: the film of each design under deviations of speed, load and oil
temperature from the operating point it was designed for (seed 004 Sect. 5.1.5-5.1.19,
Tables 5-4…5-15 and 5-17…5-28).

The seed's set is the default: +20 % and -30 % speed, +50 %, -50 % and +20 % load, +10 °C and
+20 °C. The seed's runs actually used 110 and 60 rpm for its "+20 %" and "-30 %" (their
Sommerfeld numbers; ``../shared/reference/seed004-chapter5.md`` §3.5): the defaults here are the
nominal percentages, and a case may give any factor. A temperature change acts through the
lubricant's viscosity (ASTM D341 for oils, the water models for water) from the temperature of
the operating point. As in the seed, the journal's shape (tilt, bent shaft) is held: a load
change is taken as spread over the shaft without changing its misalignment (seed 004 L1741).
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass, replace
from typing import TYPE_CHECKING, Any

import numpy as np

from shaftline import parallel
from shaftline.design.problem import DesignEvaluation, SlopeDesignProblem, evaluate_design
from shaftline.errors import InputError, located, require_finite, require_positive
from shaftline.lubricants import Lubricant

if TYPE_CHECKING:
    from distributed import Client

__all__ = ["SEED_SCENARIOS", "RobustnessResult", "Scenario", "robustness"]

#: Temperatures over which each viscosity model holds, degC: ASTM D341 is stated for
#: petroleum oils from about -20 degC to their boiling range (the standard's scope; 150 degC
#: is kept here as the hottest stern-tube oil worth computing), the water models for liquid water.
VALID_TEMPERATURES = {"walther": (-20.0, 150.0), "water": (0.0, 100.0), "seawater": (0.0, 100.0)}


@dataclass(frozen=True)
class Scenario:
    """A deviation from the design's operating point.

    Attributes
    ----------
    name : str
    speed_factor, load_factor : float
        Multipliers of the shaft speed and of the load (> 0).
    temperature_change : float
        Change of the oil's effective temperature, K (viscosity from the lubricant model).
    """

    name: str
    speed_factor: float = 1.0
    load_factor: float = 1.0
    temperature_change: float = 0.0

    def __post_init__(self) -> None:
        require_positive("speed_factor", self.speed_factor)
        require_positive("load_factor", self.load_factor)
        require_finite("temperature_change", self.temperature_change, "K")


#: The seed's scenarios (Table 5-2; +20 % load and +10 degC from Sect. 5.1.17 and 5.1.19).
SEED_SCENARIOS = (
    Scenario("+20 % speed", speed_factor=1.2),
    Scenario("-30 % speed", speed_factor=0.7),
    Scenario("+50 % load", load_factor=1.5),
    Scenario("-50 % load", load_factor=0.5),
    Scenario("+20 % load", load_factor=1.2),
    Scenario("+10 degC", temperature_change=10.0),
    Scenario("+20 degC", temperature_change=20.0),
)


@dataclass(frozen=True, eq=False)
class RobustnessResult:
    """The designs under every scenario.

    Attributes
    ----------
    designs : ndarray (d, n_var)
    names : list of str
        Design labels.
    scenarios : tuple of Scenario
    reference : list of DesignEvaluation
        Each design at its operating point.
    evaluations : list of list of DesignEvaluation
        ``[design][scenario]``.
    limit : float
        The h_min limit of the verdict, m.
    """

    designs: np.ndarray
    names: list[str]
    scenarios: tuple[Scenario, ...]
    reference: list[DesignEvaluation]
    evaluations: list[list[DesignEvaluation]]
    limit: float

    def passes(self) -> np.ndarray:
        """(d, s) bool: the design keeps h_min >= limit (and its film) in the scenario."""
        return np.array(
            [[e.ok and e.values["min_film_thickness"] >= self.limit for e in row] for row in self.evaluations]
        )

    def robust(self) -> np.ndarray:
        """(d,) bool: above the limit at the operating point and in every scenario."""
        reference = np.array([e.ok and e.values["min_film_thickness"] >= self.limit for e in self.reference])
        return reference & self.passes().all(axis=1)

    def deviation(self, quantity: str) -> np.ndarray:
        """(d, s) change of ``quantity`` from the operating point, % (as seed 004 Tables 5-14/5-15)."""
        base = np.array([e.values[quantity] for e in self.reference])
        values = np.array([[e.values[quantity] for e in row] for row in self.evaluations])
        with np.errstate(divide="ignore", invalid="ignore"):
            return 100.0 * (values - base[:, None]) / np.abs(base[:, None])

    def table(self) -> Any:
        """One row per design and scenario (the operating point as scenario "reference")."""
        import pandas as pd

        rows = []
        for k, name in enumerate(self.names):
            for scenario, evaluation in (
                ("reference", self.reference[k]),
                *zip([s.name for s in self.scenarios], self.evaluations[k], strict=True),
            ):
                row = {"design": name, "scenario": scenario, **evaluation.values, "status": evaluation.status}
                row["passes"] = evaluation.ok and evaluation.values["min_film_thickness"] >= self.limit
                rows.append(row)
        return pd.DataFrame(rows)


def outside_range(lubricant: Lubricant, temperature: float, change: float) -> str:
    """The "allowed" of a temperature change that takes ``lubricant`` out of its model's range.

    >>> from shaftline.lubricants import Lubricant
    >>> outside_range(Lubricant.preset("SAE 30"), 40.0, -70.0)
    'a film temperature from -20 to 150 degC, where the viscosity of SAE 30 is known (40 - 70 = -30 degC is outside)'
    """
    low, high = VALID_TEMPERATURES[lubricant.model]
    sign = "+" if change >= 0 else "-"
    return (
        f"a film temperature from {low:g} to {high:g} degC, where the viscosity of {lubricant.name} is known "
        f"({temperature:g} {sign} {abs(change):g} = {temperature + change:g} degC is outside)"
    )


def _scenario_problem(
    problem: SlopeDesignProblem, scenario: Scenario, lubricant: Lubricant | None, temperature: float | None
) -> SlopeDesignProblem:
    operating = problem.film.operating
    viscosity, density = operating.viscosity, operating.density
    if scenario.temperature_change:
        if lubricant is None or temperature is None or lubricant.model == "constant":
            raise InputError(
                "lubricant",
                "constant viscosity" if lubricant is not None else "none",
                "",
                f"a lubricant whose viscosity follows temperature, and its temperature, for {scenario.name!r}",
            )
        hot = temperature + scenario.temperature_change
        low, high = VALID_TEMPERATURES[lubricant.model]
        if not low <= hot <= high:
            raise InputError(
                "temperature_change",
                scenario.temperature_change,
                "K",
                outside_range(lubricant, temperature, scenario.temperature_change),
            )
        viscosity = float(lubricant.dynamic_viscosity(hot))
        density = float(lubricant.density(hot))
    film = replace(
        problem.film,
        operating=replace(
            operating, speed=operating.speed * scenario.speed_factor, viscosity=viscosity, density=density
        ),
    )
    return replace(
        problem,
        film=film,
        load_y=problem.load_y * scenario.load_factor,
        load_z=problem.load_z * scenario.load_factor,
    )


def _evaluate_pair(pair: tuple[SlopeDesignProblem, np.ndarray]) -> DesignEvaluation:
    return evaluate_design(*pair)


def robustness(
    problem: SlopeDesignProblem,
    designs: np.ndarray,
    *,
    names: list[str] | None = None,
    scenarios: tuple[Scenario, ...] = SEED_SCENARIOS,
    lubricant: Lubricant | None = None,
    temperature: float | None = None,
    limit: float = 30e-6,
    backend: str | None = None,
    workers: int | None = None,
    scheduler: str | Client | None = None,
    progress: Callable[[int, int], None] | None = None,
) -> RobustnessResult:
    """Evaluate ``designs`` at the operating point of ``problem`` and in every scenario.

    Parameters
    ----------
    problem : SlopeDesignProblem
    designs : ndarray (d, n_var)
        Design variables (e.g. the Pareto set of a search, or named designs).
    names : list of str, optional
        Labels of the designs (default ``design 1`` …).
    scenarios : tuple of Scenario
        Default: the seed's (:data:`SEED_SCENARIOS`).
    lubricant, temperature
        The lubricant model and the film temperature of the operating point (degC), needed
        for temperature scenarios.
    limit : float
        The h_min a design must keep, m (default 30 µm, the Bureau Veritas value seed 004 quotes).
    backend, workers, scheduler
        Where the (design, scenario) pairs are solved (:func:`shaftline.parallel.map`; ``scheduler`` a
        scheduler's address or the caller's ``dask.distributed.Client``).
    progress : callable, optional
        ``progress(done, total)`` as the (design, scenario) pairs are solved, the operating
        points included (:func:`shaftline.parallel.map`).

    Raises
    ------
    InputError
        ``"designs"`` of the wrong width, ``"lubricant"`` missing for a temperature scenario,
        ``"temperature_change"`` leaving the lubricant's range, ``"limit"`` not positive.
    """
    designs = np.atleast_2d(np.asarray(designs, dtype=float))
    n = problem.parametrisation.variables
    if designs.shape[1] != n or designs.shape[0] == 0:
        raise InputError("designs", list(designs.shape), "", f"one or more designs of {n} variables")
    require_positive("limit", limit, "m")
    labels = names or [f"design {k + 1}" for k in range(designs.shape[0])]
    if len(labels) != designs.shape[0]:
        raise InputError("names", len(labels), "", f"{designs.shape[0]} names, one per design")
    variants = [problem]
    for k, scenario in enumerate(scenarios):
        with located(f"scenarios[{k}]", {"lubricant": "lubricant"}):
            variants.append(_scenario_problem(problem, scenario, lubricant, temperature))
    pairs = [(variant, x) for x in designs for variant in variants]
    results = parallel.map(
        _evaluate_pair,
        pairs,
        backend=backend,
        workers=workers,
        scheduler=scheduler,
        chunksize=max(1, math.ceil(len(pairs) / (4 * parallel.available_workers()))),
        progress=progress,
        work_here=True,
    )
    per_design = [results[k * len(variants) : (k + 1) * len(variants)] for k in range(designs.shape[0])]
    return RobustnessResult(
        designs=designs,
        names=list(labels),
        scenarios=tuple(scenarios),
        reference=[row[0] for row in per_design],
        evaluations=[row[1:] for row in per_design],
        limit=limit,
    )
