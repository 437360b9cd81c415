"""The equilibrium of a film under a load: where the journal sits so that the film carries it.

==============  ============================================================================
module          job
==============  ============================================================================
``newton``      the Newton iteration on the force residual, its liner tolerances, the finish
``steps``       candidate steps, the line search with its fraction to the boundary, the trials'
                cavitated-set starts
``starts``      the closed-form start, the grid continuation from the coarse grid, a lined
                bearing's rigid start and retreat, the first film solution
``settling``    the stall and crawl rules and the pseudo-transient settling of a rigid rough bore
``result``      an equilibrium from its inputs, checked, to its state and counters
==============  ============================================================================
"""

from __future__ import annotations

from shaftline.film.equilibrium.newton import Found, find_equilibrium
from shaftline.film.equilibrium.starts import closed_form_offsets, initial_position

__all__ = ["Found", "closed_form_offsets", "find_equilibrium", "initial_position"]
