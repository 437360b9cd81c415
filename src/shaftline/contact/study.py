"""A lubricated-contact study: one operating point with a load sweep and a speed sweep
around it (what ``[contact]`` in a case file becomes; notebooks can build one directly)."""

from __future__ import annotations

import warnings
from collections.abc import Callable
from dataclasses import dataclass, field

import numpy as np

from shaftline.contact.lubricated import ContactModel, ContactState, Surfaces, evaluate
from shaftline.contact.rheology import ExtrapolationWarning

#: Load share of the film g below which the contact is called boundary-dominated: the film
#: carries less than half the load (Lambda < 0.27 with the Zhu-Hu function).
BOUNDARY_SHARE = 0.5


@dataclass(frozen=True, eq=False)
class ContactStudy:
    """A lubricated contact at one operating point (SI).

    Attributes
    ----------
    model : ContactModel
    surfaces : Surfaces
    load : float
        N/m (line) or N (point).
    speed_1, speed_2 : float
        Surface speeds in the rolling direction, m/s.
    temperature : float
        Inlet oil temperature, degC.
    radius_x, radius_y : float
        Reduced radii, m (radius_y inf for a line contact).
    speed_factors, load_factors : ndarray
        Factors on both surface speeds (slide-to-roll ratio kept) and on the load of the sweeps.
    """

    model: ContactModel
    surfaces: Surfaces
    load: float
    speed_1: float
    speed_2: float
    temperature: float
    radius_x: float
    radius_y: float = np.inf
    speed_factors: np.ndarray = field(default_factory=lambda: np.geomspace(0.01, 3.0, 60))
    load_factors: np.ndarray = field(default_factory=lambda: np.linspace(0.1, 2.0, 60))


@dataclass(frozen=True, eq=False)
class ContactResult:
    """The operating point and the two sweeps (each a :class:`ContactState` of arrays)."""

    study: ContactStudy
    operating: ContactState
    speed_sweep: ContactState
    load_sweep: ContactState
    warnings: tuple[str, ...] = ()

    @property
    def lubrication(self) -> str:
        """The regime of the operating point by the film's load share (seed 002 Eq. 2)."""
        return lubrication_regime(float(self.operating.load_sharing), float(self.operating.film_ratio))


def lubrication_regime(load_sharing: float, film_ratio: float) -> str:
    """``"full film"`` (Lambda >= 2, g = 1), ``"mixed"`` or ``"boundary-dominated"`` (g < 0.5)."""
    if film_ratio >= 2.0:
        return "full film"
    return "mixed" if load_sharing >= BOUNDARY_SHARE else "boundary-dominated"


def _at(study: ContactStudy, load: np.ndarray | float, speed_factor: np.ndarray | float) -> ContactState:
    radius_y = study.radius_y if study.model.geometry == "point" else np.inf
    return evaluate(
        study.model,
        study.surfaces,
        load=np.asarray(load, dtype=float),
        speed_1=study.speed_1 * np.asarray(speed_factor),
        speed_2=study.speed_2 * np.asarray(speed_factor),
        temperature=study.temperature,
        radius_x=study.radius_x,
        radius_y=radius_y,
    )


def solve_contact(study: ContactStudy, progress: Callable[[str], None] = lambda _: None) -> ContactResult:
    """Evaluate the operating point and both sweeps (each one vectorised call). Correlations
    evaluated outside their ranges (``extrapolate``) are listed in ``warnings``."""
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always", ExtrapolationWarning)
        progress("operating point")
        operating = _at(study, study.load, 1.0)
        progress("speed and load sweeps")
        speed = _at(study, study.load, study.speed_factors)
        load = _at(study, study.load * study.load_factors, 1.0)
    notes = tuple(dict.fromkeys(str(w.message) for w in caught if issubclass(w.category, ExtrapolationWarning)))
    return ContactResult(study, operating, speed, load, notes)
