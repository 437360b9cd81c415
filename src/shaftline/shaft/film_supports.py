"""The film supports of an elastohydrodynamic alignment as data: which bearings are films and
how the coupled iteration runs (inputs), each film's result and a condition's (outputs), and the
two maps between shaft and film: the film's 4 x 4 coefficients at a journal centre line and the
beam's Hermite shape functions at the film's stations. The solver is
:class:`~shaftline.shaft.coupled.CoupledAlignment`."""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import TYPE_CHECKING

import numpy as np

from shaftline.errors import InputError, require_positive
from shaftline.film.problem import BearingProblem
from shaftline.film.results import BearingState
from shaftline.shaft.alignment import ConditionResult, InfluenceMatrix

if TYPE_CHECKING:
    from shaftline.film.bearing import JournalBearing

__all__ = [
    "COUPLE_ROUNDING",
    "CouplingOptions",
    "CoupledResult",
    "FilmBearingResult",
    "FilmSupport",
    "carries_couple",
    "film_coefficients",
    "hermite_shape",
    "plane_support_point",
]


@dataclass(frozen=True)
class FilmSupport:
    """A bearing of the line supported by its film.

    Attributes
    ----------
    bearing : str
        Name of the bearing of the :class:`~shaftline.shaft.model.ShaftLine`.
    problem : BearingProblem
        Its film: geometry (length equal to the bearing's; clearance, bore profile),
        operating point (speed, lubricant) and grid. The journal centre line comes from the
        shaft, so the geometry must not carry a bent journal of its own.
    elements : int
        Beam elements across the bearing (at least this many: the line's own mesh may add
        nodes), the stations at which the film load enters the shaft. Seed 004 uses 10.
    """

    bearing: str
    problem: BearingProblem
    elements: int = 10


@dataclass(frozen=True)
class CouplingOptions:
    """Tolerances and limits of the coupled solution.

    Attributes
    ----------
    force_tolerance : float
        Largest change of any film's resultant force, as a share of that force, that the
        remaining mismatch between shaft and film would cause (film stiffness times the
        mismatch of the journal line).
    film_tolerance : float
        Largest mismatch between the journal line the film was solved for and the line the
        shaft takes under that film, as a share of the radial clearance (deflections; the
        rotations are weighted by the bearing length).
    max_iterations : int
        Newton iterations allowed.
    """

    force_tolerance: float = 1e-6
    film_tolerance: float = 1e-5
    max_iterations: int = 40

    def __post_init__(self) -> None:
        for name in ("force_tolerance", "film_tolerance"):
            value = require_positive(name, getattr(self, name))
            if value >= 0.1:
                raise InputError(name, value, "", "in (0, 0.1)")
        if not 1 <= int(self.max_iterations) <= 1000:
            raise InputError("max_iterations", self.max_iterations, "", "an integer in [1, 1000]")


@dataclass(frozen=True, eq=False)
class FilmBearingResult:
    """A film bearing at the coupled equilibrium. SI units.

    Attributes
    ----------
    name : str
    state : BearingState
        The film solution (pressure and film maps, hmin and pmax with their places,
        friction, flows; eccentricity and attitude at the mid-plane).
    z : ndarray (nz,)
        Axial stations of the film grid from the aft bearing edge, m.
    centre_y, centre_z : ndarray (nz,)
        Journal centre line relative to the nominal (unbored) bore centre line, m.
    bore_y, bore_z : ndarray (nz,)
        Machined bore centre line (slope boring) relative to the same line, m.
    force_y, force_z : float
        Film force on the shaft, N.
    line_load : ndarray (2, nz)
        Film force per unit length along the bearing (vertical, horizontal), N/m.
    moment_y, moment_z : float
        First moments of the vertical and horizontal film force about the bearing's mid-length,
        ``sum((z - L/2) dF)``, N m: with ``force_y, force_z`` the film's resultant in each plane.
    support_point_y, support_point_z : float
        Axial position of the film's resultant in the vertical and horizontal plane from the
        mid-length, ``M / F``, m, positive forward (towards the bow); seed 004's "contact
        point" is ``L/2 + support_point_y`` from the aft edge. NaN where that position lies
        outside the bearing (the film carries a couple in that plane: :attr:`couple_planes`)
        or the plane carries no force.
    relative_slope : float
        Chord slope of the journal across the bearing relative to the chord of its machined
        bore (the bearing's axis plus any slope boring), rad: zero when a single slope follows
        the journal exactly.
    contact : bool
        True when the film could not carry its share above the film floor: the bearing was
        then solved as contact at the bore (multi-point, edge loading) and ``state`` is the
        film at the last journal line reached.
    stiffness, damping : ndarray (4, 4)
        Film stiffness ``-dF/dq`` and damping ``-dF/dv`` at the coupled journal line
        (:func:`film_coefficients`): rows ``(F_y, F_z, M_y, M_z)``, columns
        ``(y, z, tilt_y, tilt_z)``; N/m, N/rad, N m/m, N m/rad (and N s/m ... for damping).
        NaN when they are not available (:attr:`coefficients_note`).
    coefficients_note : str
        Empty when the stiffness and damping were computed; otherwise why they are not
        available (an elastic liner whose film-liner iteration does not settle at the coupled
        journal line when the coefficients are taken there).
    """

    name: str
    state: BearingState
    z: np.ndarray = field(repr=False)
    centre_y: np.ndarray = field(repr=False)
    centre_z: np.ndarray = field(repr=False)
    bore_y: np.ndarray = field(repr=False)
    bore_z: np.ndarray = field(repr=False)
    force_y: float
    force_z: float
    line_load: np.ndarray = field(repr=False)
    moment_y: float
    moment_z: float
    support_point_y: float
    support_point_z: float
    relative_slope: float
    contact: bool
    stiffness: np.ndarray = field(repr=False, default_factory=lambda: np.full((4, 4), np.nan))
    damping: np.ndarray = field(repr=False, default_factory=lambda: np.full((4, 4), np.nan))
    coefficients_note: str = ""

    @property
    def couple_planes(self) -> tuple[str, ...]:
        """The planes (``"vertical"``, ``"horizontal"``) in which the film carries a couple: its
        resultant there lies outside the bearing (:func:`carries_couple`)."""
        length = float(self.z[-1] - self.z[0])
        total = math.hypot(self.force_y, self.force_z)
        planes = (("vertical", self.force_y, self.moment_y), ("horizontal", self.force_z, self.moment_z))
        return tuple(name for name, force, moment in planes if carries_couple(force, moment, length, total))


#: Moment below which a plane's film moment is rounding, as a share of the film's whole force
#: times the bearing length: an aligned film's moments are 1e-10 of that (the regression
#: snapshots), a couple worth a word 1e-3 or more.
COUPLE_ROUNDING = 1e-6


def carries_couple(force: float, moment: float, length: float, total: float) -> bool:
    """Whether a film's load in one plane, ``force`` (N) and ``moment`` about the mid-length
    (N m), needs a couple: its resultant ``moment / force`` lies outside the bearing of
    ``length`` (m), ``|moment| > |force| length / 2``, and the moment is more than rounding of
    the film's whole force ``total`` (N, :data:`COUPLE_ROUNDING`)."""
    return abs(moment) > abs(force) * 0.5 * length and abs(moment) > COUPLE_ROUNDING * total * length


def plane_support_point(force: float, moment: float, length: float, total: float) -> float:
    """The axial position of a plane's film resultant from the mid-length, ``moment / force``, m;
    NaN when it lies outside the bearing of ``length`` (m) or the plane carries no force (below
    :data:`COUPLE_ROUNDING` of the film's whole force ``total``, N)."""
    if abs(force) <= COUPLE_ROUNDING * total or carries_couple(force, moment, length, total):
        return math.nan
    return moment / force


@dataclass(frozen=True, eq=False)
class CoupledResult:
    """One condition of a line with film bearings.

    Attributes
    ----------
    condition : ConditionResult
        Elastic line, moments, stresses and every bearing's result; a film bearing's
        reaction is its film force and its ``contact`` is ``"film"`` (or ``"bottom"`` /
        ``"partial"`` after the fall-back to contact).
    films : list of FilmBearingResult
    point_supports : ConditionResult
        The same condition with every bearing as declared in the line (point, spring or
        multi-point): the comparison "point supports vs film supports". A film bearing's
        relative slope there is taken against its machined bore (bearing slope plus the chord
        of its slope-boring profile), as in the film results.
    converged : bool
    iterations : int
        Newton iterations.
    film_solutions : int
        Film solutions used (all film bearings, line-search trials included).
    residual_history : list of float
        Film mismatch (share of the clearance) after each iteration, starting value first.
    force_residual : float
        Final force mismatch, share of the film force.
    message : str
        Empty when converged with every film open; otherwise what happened and what to try.
    dofs : ndarray (2, m)
        The shaft's deflections and rotations across the film bearings (vertical, horizontal):
        the start of a nearby solve (``solve(..., initial=result)``); empty after a fall-back.
    influence : InfluenceMatrix or None
        The line's influence coefficients at this equilibrium, the films' stiffness included
        (:func:`~shaftline.shaft.film_tangent.tangent_influence`); None when it did not
        converge or a film grounded (there the point-support matrix applies).

    ``converged`` is about the solution found: after the fall-back to contact it is that of
    the line with the grounded bearings in contact; :attr:`contact` says whether any film
    reached its floor.
    """

    condition: ConditionResult
    films: list[FilmBearingResult]
    point_supports: ConditionResult
    converged: bool
    iterations: int
    film_solutions: int
    residual_history: list[float]
    force_residual: float
    message: str = ""
    dofs: np.ndarray = field(repr=False, default_factory=lambda: np.zeros((2, 0)))
    influence: InfluenceMatrix | None = field(repr=False, default=None)

    @property
    def contact(self) -> bool:
        """True when a film bearing could not carry its share (solved as contact at its bore)."""
        return any(f.contact for f in self.films)

    def film(self, name: str) -> FilmBearingResult:
        for result in self.films:
            if result.name == name:
                return result
        raise KeyError(name)


def film_coefficients(
    bearing: JournalBearing, centre_y: np.ndarray, centre_z: np.ndarray
) -> tuple[np.ndarray, np.ndarray]:
    """Film stiffness and damping of a journal at a given centre line, with tilt.

    The journal moves as a rigid body from the given (possibly bent) line: offsets ``y, z`` of
    the mid-plane centre and tilts about it. Forces ``F_y, F_z`` and their moments about the
    mid-plane ``M_y = sum((z - L/2) dF_y)``, ``M_z`` likewise (as ``BearingState.moment_y``),
    with the cavitated set frozen: :meth:`JournalBearing.linearise_line`, the same computation
    as the 4 x 4 coefficients of a journal at a position.

    Returns
    -------
    stiffness, damping : ndarray (4, 4)
        ``-dF/dq`` and ``-dF/dv``; rows ``(F_y, F_z, M_y, M_z)``, columns ``(y, z, tilt_y, tilt_z)``
        (their rates for the damping).
    """
    linearisation = bearing.linearise_line(centre_y, centre_z)
    return linearisation.stiffness, linearisation.damping


def hermite_shape(nodes: np.ndarray, stations: np.ndarray) -> np.ndarray:
    """Cubic Hermite interpolation of a beam's (deflection, rotation) nodal values.

    Parameters
    ----------
    nodes : ndarray (n,)
        Node stations, m, increasing.
    stations : ndarray (q,)
        Where to interpolate, m, within ``[nodes[0], nodes[-1]]``.

    Returns
    -------
    ndarray (q, 2n)
        Row ``i`` gives the deflection at ``stations[i]`` from the nodal vector
        ``(v0, theta0, v1, theta1, ...)``; its transpose turns point forces at the stations
        into consistent nodal forces and moments.

    Examples
    --------
    >>> import numpy as np
    >>> shape = hermite_shape(np.array([0.0, 2.0]), np.array([1.0]))
    >>> shape.round(3).tolist()  # mid-element: half of each deflection, +-L/8 of each rotation
    [[0.5, 0.25, 0.5, -0.25]]
    """
    element = np.clip(np.searchsorted(nodes, stations, side="right") - 1, 0, nodes.size - 2)
    length = nodes[element + 1] - nodes[element]
    xi = (stations - nodes[element]) / length
    shape = np.zeros((stations.size, 2 * nodes.size))
    rows = np.arange(stations.size)
    shape[rows, 2 * element] = 1 - 3 * xi**2 + 2 * xi**3
    shape[rows, 2 * element + 1] = length * (xi - 2 * xi**2 + xi**3)
    shape[rows, 2 * element + 2] = 3 * xi**2 - 2 * xi**3
    shape[rows, 2 * element + 3] = length * (-(xi**2) + xi**3)
    return shape
