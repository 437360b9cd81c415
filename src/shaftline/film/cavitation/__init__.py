"""Cavitation models of the discrete film: how the pressure field and its ruptured zone are
found on one grid, and how they respond to a change of the film.

=====================  ===========================================================================
module                 job
=====================  ===========================================================================
``base``               the protocol a model meets (:class:`CavitationModel`), the grid it solves on
                       (:class:`NodeGrid`), its solution, the solver's counters
``reynolds``           the Reynolds (Swift-Stieber) condition: a complementarity problem solved by a
                       primal-dual active set, its set predicted on coarser grids
``node_set``           the Reynolds condition's LDL^T factors, kept on a node set for nearby sets
``jfo``                mass-conserving Jakobsson-Floberg-Olsson cavitation by semi-smooth Newton
``half_sommerfeld``    the full-film solution clipped at the cavitation pressure (comparison only)
``coarse``             the grid halved both ways under a model's grid, and the maps between them
=====================  ===========================================================================

:data:`CAVITATION_MODELS` maps each model's name to its class, as SciPy's ``solve_ivp``
maps its ``METHODS``: ``SolverOptions(cavitation=...)`` takes a name or a class that meets
:class:`CavitationModel` (:func:`cavitation_model` resolves either). Only numpy is imported
here; the models import scipy, qdldl and numba where they first solve.
"""

from __future__ import annotations

from collections.abc import Mapping
from types import MappingProxyType
from typing import Any

from shaftline.film.cavitation.base import (
    CavitationConvergenceError,
    CavitationModel,
    CavitationSolution,
    NodeGrid,
    SolverCounts,
)
from shaftline.film.cavitation.half_sommerfeld import HalfSommerfeld
from shaftline.film.cavitation.jfo import MassConserving
from shaftline.film.cavitation.reynolds import ReynoldsCondition

__all__ = [
    "CAVITATION_MODELS",
    "CavitationConvergenceError",
    "CavitationModel",
    "CavitationSolution",
    "HalfSommerfeld",
    "MassConserving",
    "NodeGrid",
    "ReynoldsCondition",
    "SolverCounts",
    "cavitation_model",
]

#: The cavitation models by name (read-only).
CAVITATION_MODELS: Mapping[str, type[CavitationModel]] = MappingProxyType(
    {
        ReynoldsCondition.name: ReynoldsCondition,
        MassConserving.name: MassConserving,
        HalfSommerfeld.name: HalfSommerfeld,
    }
)

#: What a model class must have to serve (the attributes and methods of :class:`CavitationModel`).
_REQUIRED = (
    "name",
    "active_set",
    "refines_trials",
    "starts_from_coarse_contact",
    "rough_surfaces",
    "liners",
    "refusal",
    "needs_feed_pressure",
    "dense_bytes",
    "factor_bytes",
    "solve",
    "start_from_guess",
    "trial_guess",
    "film_residual_change",
    "pressure_response",
    "start_field",
    "unsettled_residual",
    "coarse_grid",
    "drop_factors",
)


def cavitation_model(choice: Any) -> type[CavitationModel]:
    """The model class of ``choice``: a name of :data:`CAVITATION_MODELS` or a class that has
    every attribute and method of :class:`CavitationModel`.

    Raises
    ------
    ValueError
        For an unknown name (the message lists the registry's names) or a class that lacks
        part of the protocol (the message names what is missing).
    """
    if isinstance(choice, str):
        model = CAVITATION_MODELS.get(choice)
        if model is None:
            raise ValueError("one of " + ", ".join(CAVITATION_MODELS))
        return model
    if isinstance(choice, type):
        missing = [name for name in _REQUIRED if not hasattr(choice, name)]
        if not missing:
            return choice
        raise ValueError(f"a cavitation model class (missing {', '.join(missing)})")
    raise ValueError("one of " + ", ".join(CAVITATION_MODELS) + ", or a cavitation model class")
