"""Thin elastic liner bonded to a rigid bearing shell: the column (Winkler) model.

A thin layer of thickness ``t``, Young's modulus ``E`` and Poisson's ratio ``nu``, bonded to a
rigid backing and loaded by a normal pressure ``p`` on its free face, is compressed in
uniaxial strain when the pressure varies slowly over distances of order ``t`` (the lateral
strains are held by the bond and the neighbouring material). Its surface then moves away from
the journal by (docs/theory.md, "Elastic liner"; Johnson, *Contact Mechanics*, 1985, Sect. 5.9)

    u = p t / M,   M = E (1 - nu) / ((1 + nu)(1 - 2 nu)),

``M`` the constrained (oedometric, P-wave) modulus. Each point of the bore moves with its own
pressure only: the compliance is a diagonal ``t / M`` (m/Pa). For ``nu -> 0.5`` the
constrained modulus grows without bound and the column model predicts no deflection: a
nearly incompressible layer (rubber) deforms by lateral bulging instead, which the column
model does not hold, so for rubber it gives a lower bound of the deformation.

Only numpy-free Python is imported here: :mod:`shaftline.film.geometry` and the case schema
import :class:`Liner`.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Literal, get_args

from shaftline.errors import InputError, require_finite, require_positive

__all__ = [
    "LINER_MODELS",
    "LINER_PRESETS",
    "MAX_THICKNESS_RATIO",
    "Liner",
    "LinerModel",
    "LinerPreset",
    "constrained_modulus",
]

#: Largest liner thickness over the bore radius the column model is used for: a liner thicker
#: than a quarter of the radius is a bush, whose curvature and bending the plane-layer column
#: model does not hold (docs/theory.md, "Elastic liner"; seed 001's 20 mm liner on a 162 mm
#: radius is 0.12).
MAX_THICKNESS_RATIO = 0.25

LinerPreset = Literal["polymer_composite", "rubber", "white_metal"]
#: How the liner deforms: "column" (each point under its own pressure, this module) or "layer"
#: (the surface compliance of an elastic layer bonded to the shell, :mod:`shaftline.film.layer`).
LinerModel = Literal["column", "layer"]
LINER_MODELS: tuple[str, ...] = get_args(LinerModel)

#: Preset liners: (thickness m, Young's modulus Pa, Poisson's ratio); sources in docs/theory.md.
#: polymer_composite: seed 001 (Li et al., Sensors 2022, 22, 3670, Sect. 2.1 and Table 1):
#: E 2320 MPa, nu 0.327, lining 20 mm. rubber: nitrile rubber stave of a water-lubricated stern
#: tube, E 7 MPa, nu 0.49, 10 mm (Litwin's rubber bearings; typical NBR data, ranges in
#: docs/theory.md). white_metal: tin-based white metal (ASTM B23 grade 2, UNS L13890) E 53 GPa,
#: nu 0.35 (the same data as the white-metal roughness presets), 2 mm lining on a steel shell.
LINER_PRESETS: dict[str, tuple[float, float, float]] = {
    "polymer_composite": (0.020, 2.32e9, 0.327),
    "rubber": (0.010, 7.0e6, 0.49),
    "white_metal": (0.002, 53.0e9, 0.35),
}


def constrained_modulus(modulus: float, poisson: float) -> float:
    """Constrained (uniaxial-strain) modulus ``E (1 - nu) / ((1 + nu)(1 - 2 nu))``, Pa.

    >>> round(constrained_modulus(2.32e9, 0.327) / 1e9, 3)  # seed 001's polymer liner, GPa
    3.401
    """
    return modulus * (1.0 - poisson) / ((1.0 + poisson) * (1.0 - 2.0 * poisson))


@dataclass(frozen=True)
class Liner:
    """A thin liner bonded to a rigid shell, deforming as columns (Winkler foundation).

    Attributes
    ----------
    thickness : float
        Liner thickness t, m (> 0; checked against the bore radius by the geometry:
        at most :data:`MAX_THICKNESS_RATIO` of it).
    modulus : float
        Young's modulus E, Pa (> 0).
    poisson : float
        Poisson's ratio nu, in (0, 0.5); the layer model also takes 0.5 (incompressible).
    model : {"column", "layer"}
        The column (Winkler) model (default) or the bonded elastic layer's compliance
        (:mod:`shaftline.film.layer`, docs/theory.md "Elastic layer").

    Raises
    ------
    InputError
        Naming the attribute, its value, unit and allowed range.

    Examples
    --------
    >>> liner = Liner.preset("polymer_composite")
    >>> round(liner.compliance * 1e12, 3)  # m/Pa x 1e12: 5.9 um at 1 MPa
    5.881
    """

    thickness: float
    modulus: float
    poisson: float
    model: LinerModel = "column"

    def __post_init__(self) -> None:
        require_positive("thickness", self.thickness, "m")
        require_positive("modulus", self.modulus, "Pa")
        if self.model not in LINER_MODELS:
            raise InputError("model", self.model, "", "one of " + ", ".join(LINER_MODELS))
        nu = require_finite("poisson", self.poisson)
        if self.model == "layer":
            # The bonded layer holds an incompressible liner (rubber): it deflects by bulging.
            if not 0.0 < nu <= 0.5:
                raise InputError("poisson", nu, "", "in (0, 0.5] for the layer model")
        elif not 0.0 < nu < 0.5:
            raise InputError("poisson", nu, "", "in (0, 0.5)")

    @classmethod
    def preset(cls, name: str, model: LinerModel = "column") -> Liner:
        """A preset liner (:data:`LINER_PRESETS`) deforming by ``model``."""
        if name not in LINER_PRESETS:
            raise InputError("preset", name, "", "one of " + ", ".join(get_args(LinerPreset)))
        return cls(*LINER_PRESETS[name], model=model)

    @property
    def constrained_modulus(self) -> float:
        """``M = E (1 - nu) / ((1 + nu)(1 - 2 nu))``, Pa (infinite for nu = 0.5)."""
        if self.poisson == 0.5:
            return float("inf")
        return constrained_modulus(self.modulus, self.poisson)

    @property
    def compliance(self) -> float:
        """Column compliance ``t / M = t (1 + nu)(1 - 2 nu) / (E (1 - nu))``, m/Pa: the liner's
        surface moves by this times the local pressure (the column model; the layer model's
        long-wave limit). Zero for nu = 0.5."""
        return self.thickness / self.constrained_modulus

    def deflection(self, pressure: float) -> float:
        """Deflection of the liner surface away from the journal under ``pressure`` (Pa), m."""
        return self.compliance * pressure
