"""Slope-boring design: bores with N slope segments searched for the best film (seed 004
Sect. 4.4-4.5.5 and Ch. 5).

Problem, algorithm and result kept apart (as pymoo does): :mod:`~shaftline.design.bore`
turns design variables into a bore, :mod:`~shaftline.design.problem` evaluates one design
(the film at equilibrium with that bore), :mod:`~shaftline.design.search` runs a pymoo
algorithm over batches of designs through :func:`shaftline.parallel.map`.
"""

from __future__ import annotations

from shaftline.design.bore import SlopeParametrisation
from shaftline.design.problem import OBJECTIVES, DesignEvaluation, SlopeDesignProblem, evaluate_design

__all__ = ["OBJECTIVES", "DesignEvaluation", "SlopeDesignProblem", "SlopeParametrisation", "evaluate_design"]
