"""The bearing problem as pure data: operating point, solver options and their choices.

Everything here is frozen, picklable and cheap to import (numpy, no scipy or
qdldl), so that a command line starts fast and a case schema can read the
defaults and the allowed choices (``typing.Literal``) straight from these
dataclasses: the domain is the single source of both. The solver state built
from a problem lives in :class:`shaftline.film.bearing.JournalBearing`.

Errors name the field relative to the object that checks it (``"speed"``,
``"grooves[0].angle"``), never a case-file path: see :class:`shaftline.errors.InputError`.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Literal, get_args

from shaftline.errors import InputError, require_finite, require_positive
from shaftline.film.geometry import (
    BORE_ANCHORS,
    MIN_AXIAL_NODES,
    MIN_CIRCUMFERENTIAL_NODES,
    ROTATIONS,
    BearingGeometry,
    BentJournal,
    BoreAnchor,
    BoreSegment,
    FilmProfile,
    JournalPosition,
    Rotation,
    require_nodes,
)

#: Cavitation model of the film (see :mod:`shaftline.film.reynolds`).
Cavitation = Literal["reynolds", "jfo", "half_sommerfeld"]
#: Where the film starts when no supply groove fixes it.
FilmStart = Literal["periodic", "max_film"]
#: What shears in the cavitated zone.
CavitatedShear = Literal["film_fraction", "full_film"]

CAVITATION_MODELS: tuple[Cavitation, ...] = get_args(Cavitation)
FILM_STARTS: tuple[FilmStart, ...] = get_args(FilmStart)
CAVITATED_SHEARS: tuple[CavitatedShear, ...] = get_args(CavitatedShear)

__all__ = [
    "BORE_ANCHORS",
    "CAVITATED_SHEARS",
    "CAVITATION_MODELS",
    "FILM_STARTS",
    "ROTATIONS",
    "BearingGeometry",
    "BearingProblem",
    "BentJournal",
    "BoreAnchor",
    "BoreSegment",
    "CavitatedShear",
    "Cavitation",
    "FilmProfile",
    "FilmStart",
    "JournalPosition",
    "OperatingPoint",
    "Rotation",
    "SolverOptions",
    "SupplyGroove",
]


def _one_of(choices: tuple[str, ...]) -> str:
    return "one of " + ", ".join(choices)


@dataclass(frozen=True)
class SupplyGroove:
    """An axial supply groove at a fixed bearing angle.

    Attributes
    ----------
    angle : float
        Bearing angle of the groove centre, rad (from the top, in the direction of rotation).
    pressure : float
        Supply pressure above ambient, Pa.
    length_fraction : float
        Axial length of the groove as a share of the bearing length, centred, (0, 1].
    """

    angle: float
    pressure: float = 0.0
    length_fraction: float = 1.0


@dataclass(frozen=True)
class OperatingPoint:
    """Running condition of a bearing.

    Attributes
    ----------
    speed : float
        Shaft angular speed, rad/s (> 0; the sense of rotation is a geometry input).
    viscosity : float
        Effective dynamic viscosity of the lubricant, Pa*s.
    density : float
        Lubricant density, kg/m^3 (reported flows by mass; no effect on pressures).
    aft_pressure, fore_pressure : float
        Pressures at the aft and forward bearing edges above ambient, Pa.
    cavitation_pressure : float
        Pressure at which the film ruptures, above ambient, Pa (<= edge and groove pressures).
    grooves : tuple of SupplyGroove
        Axial supply grooves.

    Raises
    ------
    InputError
        Naming the attribute, e.g. ``"viscosity"`` or ``"grooves[0].angle"``.
    """

    speed: float
    viscosity: float
    density: float = 880.0
    aft_pressure: float = 0.0
    fore_pressure: float = 0.0
    cavitation_pressure: float = 0.0
    grooves: tuple[SupplyGroove, ...] = ()

    def __post_init__(self) -> None:
        require_positive("speed", self.speed, "rad/s")
        require_positive("viscosity", self.viscosity, "Pa*s")
        require_positive("density", self.density, "kg/m^3")
        for name in ("aft_pressure", "fore_pressure", "cavitation_pressure"):
            require_finite(name, getattr(self, name), "Pa")
        for k, groove in enumerate(self.grooves):
            require_finite(f"grooves[{k}].angle", groove.angle, "rad")
            require_finite(f"grooves[{k}].pressure", groove.pressure, "Pa")
            fraction = require_finite(f"grooves[{k}].length_fraction", groove.length_fraction)
            if not 0.0 < fraction <= 1.0:
                raise InputError(f"grooves[{k}].length_fraction", fraction, "", "in (0, 1]")
        lowest = min(self.aft_pressure, self.fore_pressure, *(g.pressure for g in self.grooves))
        if self.cavitation_pressure > lowest:
            raise InputError(
                "cavitation_pressure",
                self.cavitation_pressure,
                "Pa",
                f"<= the lowest supply pressure {lowest}",
            )

    @property
    def feed_pressure(self) -> float:
        """Highest pressure feeding the film, Pa: the largest edge or groove pressure."""
        return max(self.aft_pressure, self.fore_pressure, *(g.pressure for g in self.grooves))


@dataclass(frozen=True)
class SolverOptions:
    """Numerical options of the film solution.

    Attributes
    ----------
    axial_nodes, circumferential_nodes : int
        Grid nodes along the bearing (edges included, >= 5) and around the bore (>= 16).
    cavitation : Cavitation
        ``"reynolds"`` (Swift-Stieber, default), ``"jfo"`` (mass-conserving) or
        ``"half_sommerfeld"`` (comparison only).
    film_start : FilmStart
        ``"periodic"`` (default: the film is continuous all round) or ``"max_film"``
        (the classical design-chart assumption of Raimondi & Boyd: ambient pressure
        along the line of maximum film thickness, where the oil enters).
    cavitated_shear : CavitatedShear
        Shear in the cavitated zone: ``"film_fraction"`` (default: only the liquid
        streamers shear, share ``h_rupture / h`` or the JFO film fraction) or
        ``"full_film"`` (the whole clearance shears, the convention behind the
        Raimondi & Boyd friction variable).
    min_film_floor : float
        Smallest film, as a share of the radial clearance, that the equilibrium search
        may approach; below it the load is reported as not carried (contact).
    tolerance : float
        Relative force residual at which the equilibrium is accepted.
    max_iterations : int
        Newton iterations allowed for the equilibrium (>= 1).

    Raises
    ------
    InputError
        Naming the attribute, e.g. ``"cavitation"`` or ``"axial_nodes"``.
    """

    axial_nodes: int = 41
    circumferential_nodes: int = 120
    cavitation: Cavitation = "reynolds"
    film_start: FilmStart = "periodic"
    cavitated_shear: CavitatedShear = "film_fraction"
    min_film_floor: float = 1e-3
    tolerance: float = 1e-8
    max_iterations: int = 60

    def __post_init__(self) -> None:
        require_nodes("axial_nodes", self.axial_nodes, MIN_AXIAL_NODES)
        require_nodes("circumferential_nodes", self.circumferential_nodes, MIN_CIRCUMFERENTIAL_NODES)
        if self.cavitation not in CAVITATION_MODELS:
            raise InputError("cavitation", self.cavitation, "", _one_of(CAVITATION_MODELS))
        if self.film_start not in FILM_STARTS:
            raise InputError("film_start", self.film_start, "", _one_of(FILM_STARTS))
        if self.cavitated_shear not in CAVITATED_SHEARS:
            raise InputError("cavitated_shear", self.cavitated_shear, "", _one_of(CAVITATED_SHEARS))
        floor = require_finite("min_film_floor", self.min_film_floor)
        if not 0.0 < floor < 0.5:
            raise InputError("min_film_floor", floor, "", "in (0, 0.5) of the clearance")
        tolerance = require_finite("tolerance", self.tolerance)
        if not 0.0 < tolerance < 1e-2:
            raise InputError("tolerance", tolerance, "", "in (0, 0.01)")
        require_nodes("max_iterations", self.max_iterations, 1, "an integer >= 1")


@dataclass(frozen=True)
class BearingProblem:
    """One film problem: what the bearing is, how it runs and how to solve it.

    Pure data, with no solver state: it pickles, deep-copies and compares cheaply,
    so it is what a process pool or a Dask worker receives.
    :class:`shaftline.film.bearing.JournalBearing` builds (and rebuilds after
    unpickling) the solver state from it.

    Attributes
    ----------
    geometry : BearingGeometry
        Bore, clearance, slope boring, bent journal, film profile, sense of rotation.
    operating : OperatingPoint
        Speed, lubricant viscosity and density, edge, groove and cavitation pressures.
    options : SolverOptions
        Grid and cavitation model.

    Raises
    ------
    InputError
        ``"operating.cavitation_pressure"`` for the mass-conserving (``"jfo"``) model
        when no edge or groove pressure lies above the cavitation pressure.

    Examples
    --------
    >>> from shaftline.film.problem import BearingGeometry, BearingProblem, OperatingPoint
    >>> problem = BearingProblem(
    ...     BearingGeometry(length=0.1, diameter=0.1, radial_clearance=1e-4),
    ...     OperatingPoint(speed=100.0, viscosity=0.02),
    ... )
    >>> problem.options.cavitation
    'reynolds'
    >>> round(problem.pressure_scale / 1e6, 3)  # 6 eta omega (R/c)^2, MPa
    3.0
    """

    geometry: BearingGeometry
    operating: OperatingPoint
    options: SolverOptions = field(default_factory=SolverOptions)

    def __post_init__(self) -> None:
        if self.options.cavitation == "jfo" and self.operating.feed_pressure <= self.operating.cavitation_pressure:
            raise InputError(
                "operating.cavitation_pressure",
                self.operating.cavitation_pressure,
                "Pa",
                f"below the highest edge or groove pressure ({self.operating.feed_pressure} Pa) for the "
                "mass-conserving (jfo) model: without a pressure difference to feed it the film runs dry",
            )

    @property
    def pressure_scale(self) -> float:
        """Pressure scale of the dimensionless Reynolds equation, ``6 eta omega (R/c)^2``, Pa."""
        ratio = self.geometry.radius / self.geometry.radial_clearance
        return 6.0 * self.operating.viscosity * self.operating.speed * ratio**2

    @property
    def flow_scale(self) -> float:
        """Flow scale ``omega R^2 c / 2``, m^3/s."""
        g = self.geometry
        return 0.5 * self.operating.speed * g.radius**2 * g.radial_clearance
