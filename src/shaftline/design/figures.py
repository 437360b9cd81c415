"""Figures of a slope-boring design study: the Pareto front coloured by power loss with the
knee, the design maps (each variable against h_min, seed 004 Fig. 5-41 ff.) and the robustness
table as a heat map.

Each function draws into the axes it is given (``ax=``) and returns them; without axes it
makes a pyplot figure of its own (see :mod:`shaftline.report.plotting`).
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING, Any

import numpy as np

from shaftline.report.plotting import FigureFunction, figure_function, plain

if TYPE_CHECKING:
    from shaftline.design.robustness import RobustnessResult
    from shaftline.design.search import SearchResult
    from shaftline.film.bearing import BearingState


def _values(result: SearchResult, name: str) -> np.ndarray:
    return np.array([e.values[name] for e in result.evaluations])


@figure_function(size=(8.5, 5.5))
def pareto_front(result: SearchResult, references: Mapping[str, BearingState] | None = None, *, ax: Any) -> Any:
    """Every acceptable design (grey) and the non-dominated ones coloured by power loss, in the
    seed's plane: h_min against p_max; the knee starred, and the ``references`` (e.g. no slope,
    the single slope) marked."""
    ok = np.array([e.ok for e in result.evaluations])
    hmin = _values(result, "min_film_thickness") * 1e6
    pmax = _values(result, "max_pressure") / 1e6
    power = _values(result, "power_loss") / 1e3
    ax.scatter(hmin[ok], pmax[ok], s=8, color="0.75", label=f"designs evaluated ({ok.sum()})")
    front = result.pareto
    if front.size:
        points = ax.scatter(hmin[front], pmax[front], c=power[front], s=30, cmap="viridis", label="non-dominated")
        ax.figure.colorbar(points, ax=ax, label="power loss [kW]")
    if result.knee is not None:
        ax.plot(hmin[result.knee], pmax[result.knee], "r*", ms=16, label="knee")
    for k, (label, state) in enumerate((references or {}).items()):
        if label != "knee":
            marker = "sD^vP"[k % 5]
            ax.plot(state.min_film_thickness * 1e6, state.max_pressure / 1e6, marker, color="k", mfc="none", ms=9,
                    label=plain(label))  # fmt: skip
    ax.set_xlabel("smallest film h_min [µm]")
    ax.set_ylabel("largest pressure p_max [MPa]")
    ax.set_title(f"Pareto front ({result.algorithm}, {len(result.evaluations)} evaluations, seed {result.seed})")
    ax.legend(fontsize=8)
    return ax


def design_maps(variables: int) -> FigureFunction:
    """The figure function of the design maps of a search with ``variables`` design variables:
    each variable against h_min (top row) and against p_max (bottom row), as seed 004
    Figs. 5-41 ff., the non-dominated designs dark and the knee starred, with a key."""
    return FigureFunction(_design_maps, (2, variables), (4.0 * variables, 7.0), False)


def _design_maps(result: SearchResult, *, ax: Any) -> Any:
    names = result.problem.parametrisation.names
    ok = np.array([e.ok for e in result.evaluations])
    x = np.array([e.x for e in result.evaluations])
    quantities = (
        (_values(result, "min_film_thickness") * 1e6, "h_min [µm]"),
        (_values(result, "max_pressure") / 1e6, "p_max [MPa]"),
    )
    grid = np.asarray(ax).reshape(2, -1)
    for row, (value, label) in enumerate(quantities):
        for k, name in enumerate(names):
            axis = grid[row, k]
            axis.scatter(x[ok, k], value[ok], s=6, color="0.7", label=f"designs evaluated ({int(ok.sum())})")
            axis.scatter(x[result.pareto, k], value[result.pareto], s=10, color="C0", label="non-dominated")
            if result.knee is not None:
                axis.scatter(x[result.knee, k], value[result.knee], s=90, marker="*", color="C3", label="knee")
            axis.set_xlabel(name + (" [× 2c/L]" if name.startswith("slope") else " [× L]"))
            axis.set_ylabel(label)
    grid[0, 0].legend(fontsize="small")  # one key for all the maps: the same marks in each
    return ax


@figure_function(size=(10, 4.5))
def robustness_heatmap(result: RobustnessResult, *, ax: Any) -> Any:
    """h_min of each design in each scenario (µm), the cells below the limit framed and marked, the
    designs that keep it everywhere labelled robust."""
    names = ["operating point", *(s.name for s in result.scenarios)]
    values = np.array(
        [
            [result.reference[d].values["min_film_thickness"]] + [e.values["min_film_thickness"] for e in row]
            for d, row in enumerate(result.evaluations)
        ]
    )
    image = ax.imshow(values * 1e6, cmap="RdYlGn", aspect="auto")
    ax.figure.colorbar(image, ax=ax, label="h_min [µm]")
    for i in range(values.shape[0]):
        for j in range(values.shape[1]):
            ax.text(j, i, f"{values[i, j] * 1e6:.0f}", ha="center", va="center", fontsize=8)
            if not values[i, j] >= result.limit:
                ax.add_patch(_frame(ax, j, i))
                ax.text(j, i + 0.3, "below", ha="center", va="center", fontsize=7, color="white")
    ax.set_xticks(np.arange(len(names)), [plain(n) for n in names], rotation=30, ha="right", fontsize=8)
    robust = result.robust()
    labels = [plain(n) + (" (robust)" if r else "") for n, r in zip(result.names, robust, strict=True)]
    ax.set_yticks(np.arange(len(result.names)), labels, fontsize=8)
    ax.set_title(f"Robustness: h_min in each scenario (limit {result.limit * 1e6:.0f} µm)")
    return ax


def _frame(ax: Any, column: int, row: int) -> Any:
    from matplotlib.patches import Rectangle

    return Rectangle((column - 0.45, row - 0.45), 0.9, 0.9, fill=False, edgecolor="black", linewidth=2.5)


@figure_function(layout=(2, 1), size=(9, 6.5), sharex=True)
def profiles_along_bearing(profiles: Mapping[str, BearingState], *, ax: Any) -> Any:
    """Smallest film (top) and largest pressure (bottom) round the bore at each axial station,
    for each bore (the chosen design beside no slope and the single slope); ``ax`` is two axes."""
    top, bottom = ax
    for k, (label, state) in enumerate(profiles.items()):
        top.plot(state.z, state.film.min(axis=1) * 1e6, color=f"C{k}", label=plain(label))
        bottom.plot(state.z, state.pressure.max(axis=1) / 1e6, color=f"C{k}")
    top.set_ylabel("smallest film round the bore [µm]")
    bottom.set_ylabel("largest pressure [MPa]")
    bottom.set_xlabel("z from the aft edge [m]")
    top.set_title("Along the bearing: the chosen design beside no slope and the single slope")
    top.legend(fontsize=8)
    return ax
