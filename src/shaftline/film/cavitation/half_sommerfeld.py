"""The half-Sommerfeld condition: the full-film (linear) solution with the pressures below the
cavitation pressure set to it. It conserves no mass and its pressure is not a solution of the
film equation where it was clipped; offered only for comparison with the classical charts."""

from __future__ import annotations

from typing import ClassVar

import numpy as np

from shaftline.film.cavitation.base import CavitationSolution
from shaftline.film.cavitation.reynolds import ReynoldsCondition, marched_film_fraction
from shaftline.film.stencil import Stencil

__all__ = ["HalfSommerfeld"]


class HalfSommerfeld(ReynoldsCondition):
    """The full-Sommerfeld solution clipped at the cavitation pressure, the film fraction in the
    clipped zone marched from its rupture line (:func:`marched_film_fraction`).

    It solves the linear problem with the Reynolds condition's kept factors; its linearisation
    (the frozen-set pressure change, which this model holds at zero on the clipped nodes) is an
    approximation: its clipped pressure changes with the full-film solution. A
    :class:`~shaftline.film.cavitation.base.CavitationModel` without an active set.
    """

    name: ClassVar[str] = "half_sommerfeld"
    active_set: ClassVar[bool] = False
    refines_trials: ClassVar[bool] = False
    starts_from_coarse_contact: ClassVar[bool] = False
    liners: ClassVar[bool] = False

    def solve(
        self,
        stencil: Stencil,
        film: np.ndarray,
        start: np.ndarray | None = None,
        *,
        refine_from: np.ndarray | None = None,
        settle: bool = True,
    ) -> CavitationSolution:
        """The clipped full-film solution (``start``, ``refine_from`` and ``settle`` have no use)."""
        pressure = np.maximum(self.solve_linear(stencil), 0.0)
        cavitated = (pressure <= 0.0) & ~self.fixed
        return CavitationSolution(pressure, marched_film_fraction(film, cavitated), cavitated, 1)

    def start_from_guess(self, stencil: Stencil, film: np.ndarray, guess: np.ndarray) -> np.ndarray | None:
        """None: there is no set to start."""
        return None

    def trial_guess(self, relative: np.ndarray, step: np.ndarray, response: np.ndarray) -> np.ndarray | None:
        """None: there is no set to start."""
        return None
