"""Slope-boring design: bores with N slope segments searched for the best film (seed 004
Sect. 4.4-4.5.5 and Ch. 5).

Problem, algorithm and result kept apart (as pymoo does): :mod:`~shaftline.design.bore`
turns design variables into a bore, :mod:`~shaftline.design.problem` evaluates one design
(the film at equilibrium with that bore), :mod:`~shaftline.design.search` runs a pymoo
algorithm over batches of designs through :func:`shaftline.parallel.map`.

Every name is imported on first use (PEP 562): the command line imports
``shaftline.design.capability`` to list its verbs, which must not load the film solver
and scipy that :mod:`~shaftline.design.problem` needs.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    from shaftline.design.bore import SlopeParametrisation
    from shaftline.design.problem import OBJECTIVES, DesignEvaluation, SlopeDesignProblem, evaluate_design

#: Public name -> module that defines it.
_LAZY = {
    "SlopeParametrisation": "shaftline.design.bore",
    "OBJECTIVES": "shaftline.design.problem",
    "DesignEvaluation": "shaftline.design.problem",
    "SlopeDesignProblem": "shaftline.design.problem",
    "evaluate_design": "shaftline.design.problem",
}

__all__ = ["OBJECTIVES", "DesignEvaluation", "SlopeDesignProblem", "SlopeParametrisation", "evaluate_design"]


def __getattr__(name: str) -> Any:
    if name in _LAZY:
        import importlib

        value = getattr(importlib.import_module(_LAZY[name]), name)
        globals()[name] = value  # later look-ups skip this function
        return value
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


def __dir__() -> list[str]:
    return sorted(set(globals()) | set(__all__))
