"""What a film solution gives: the bearing state at a journal position and its optional parts,
the equilibrium under a load with its counters, and the film's linearisations.

Forces are those of the film on the journal, in the shaft axes (y up, z starboard), N.
Pressures are gauge pressures above the ambient pressure, Pa. An applied load ``(load_y,
load_z)`` is carried when the film force balances it: ``force + load = 0``. The fields a
result writes to results.json carry their unit and meaning in their metadata
(:mod:`shaftline.export`): ``to_dict()`` writes them, ``units()`` gives their units.

Equality of the results holding arrays is identity: arrays have no single truth value.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from shaftline import export
from shaftline.export import part, quantity
from shaftline.film.geometry import JournalPosition

__all__ = [
    "BearingState",
    "Equilibrium",
    "FilmLinearisation",
    "FilmLoad",
    "LinerState",
    "RoughContact",
    "TiltLinearisation",
    "TurbulenceState",
]

_CONTACT = (
    "true when the film reaches the solver's film floor (rough surfaces: the boundary limit 3σ below the mean "
    "plane; h_min, the mean-plane separation, is negative in boundary lubrication: docs/theory.md Sect. 17)"
)


@dataclass(frozen=True, eq=False)
class RoughContact(export.Exported):
    """What rough surfaces add to a film solution (Greenwood-Tripp asperity contact).

    Attributes
    ----------
    min_film_ratio : float
        ``lambda_min = h_min / sigma``.
    lubrication_regime : str
        ``"boundary"`` (lambda_min < 1), ``"mixed"`` (1-3) or ``"full film"`` (> 3).
    asperity_load : float
        Magnitude of the asperity force on the journal, N.
    asperity_load_share : float
        Share of the total force carried by the asperities (the asperity force projected on the
        total force, over the total force's magnitude).
    max_asperity_pressure : float
        Largest nodal asperity pressure, Pa.
    contact_area_ratio : float
        Real (asperity) contact area over the bore's area, Greenwood-Tripp.
    fluid_friction_force, boundary_friction_force : float
        The friction force split into the film's shear and the boundary friction on the
        asperity load (``boundary_friction x`` asperity pressure), N; they sum to the state's
        ``friction_force``.
    asperity_pressure : ndarray (nz, nt)
        Asperity contact pressure, Pa. The state's forces, moments and load capacity include
        it; its ``pressure`` and ``max_pressure`` are the film's alone.
    film_ratio : ndarray (nz, nt)
        ``lambda = h / sigma`` over the bore.
    """

    min_film_ratio: float = quantity("-", "h_min / composite RMS roughness sigma (lambda)")
    lubrication_regime: str = quantity("-", "boundary (lambda < 1), mixed (1-3) or full film (> 3), from h_min")
    asperity_load: float = quantity("N", "magnitude of the asperity contact force (Greenwood-Tripp)")
    asperity_load_share: float = quantity(
        "-", "share of the carried load on the asperities (their force along the total force / total force)"
    )
    max_asperity_pressure: float = quantity("Pa", "largest asperity contact pressure")
    contact_area_ratio: float = quantity("-", "real asperity contact area / bore area")
    fluid_friction_force: float = quantity("N", "friction force of the film's shear")
    boundary_friction_force: float = quantity(
        "N", "friction force of the asperities (boundary coefficient x asperity load)"
    )
    asperity_pressure: np.ndarray = field(default_factory=lambda: np.zeros((0, 0)), repr=False)
    film_ratio: np.ndarray = field(default_factory=lambda: np.zeros((0, 0)), repr=False)


@dataclass(frozen=True, eq=False)
class LinerState(export.Exported):
    """What an elastic liner adds to a film solution.

    Attributes
    ----------
    max_deformation : float
        Largest liner deformation, m.
    deformation : ndarray (nz, nt)
        Deformation of the liner away from the journal, m. The state's ``film`` includes it,
        and so ``min_film_thickness`` and the pressures.
    iterations : int
        Newton iterations of the film-liner system in this solution.
    """

    max_deformation: float = quantity(
        "m",
        "largest liner deformation (column or layer model); film, h_min and p_max include the deformation",
        key="max_liner_deformation",
    )
    deformation: np.ndarray = field(default_factory=lambda: np.zeros((0, 0)), repr=False)
    iterations: int = 0


@dataclass(frozen=True, eq=False)
class TurbulenceState(export.Exported):
    """What a turbulent-film model adds to a film solution (``options.turbulence`` on or auto).

    Attributes
    ----------
    max_reynolds_number : float
        Largest local Reynolds number.
    turbulent : bool
        Whether the turbulence coefficients were applied (docs/theory.md Sect. 17, "Turbulent
        films"): ``options.turbulence`` on, or auto above the transition.
    reynolds_number : ndarray (nz, nt)
        Local Reynolds number ``Re_h = rho omega R h / mu`` over the bore.
    """

    max_reynolds_number: float = quantity("-", "largest local Reynolds number rho omega R h / mu of the film")
    turbulent: bool = quantity(
        "-", "whether the turbulence coefficients were applied (on, or auto above 41.3 sqrt(R/c))"
    )
    reynolds_number: np.ndarray = field(default_factory=lambda: np.zeros((0, 0)), repr=False)


@dataclass(frozen=True, eq=False)
class BearingState:
    """Film solution at one journal position. Fields are SI unless noted.

    Attributes
    ----------
    eccentricity_ratio : float
        Eccentricity of the journal from the bore centre at the mid-plane (the
        machined bore of a slope-bored bearing) over the radial clearance.
    attitude_angle : float
        Angle from the load line (opposite to the film force) to the line of
        centres, positive in the direction of rotation, rad.
    position_angle : float
        Bearing angle of that line of centres (towards the thinnest film), rad.
    position : JournalPosition
        Journal centre offsets from the nominal bore axis (m) and tilts (rad) at the
        bearing mid-plane.
    min_film_thickness : float
        Smallest film h_min, m, and where: ``min_film_theta`` (rad), ``min_film_z`` (m);
        located between nodes by a local quadratic fit around the thinnest node
        (:func:`shaftline.film.extremes.local_extreme`, docs/theory.md).
    max_pressure : float
        Largest pressure p_max, Pa, and where: ``max_pressure_theta`` (rad), ``max_pressure_z``
        (m); located likewise from the free (neither fixed nor cavitated) nodes around the
        largest nodal pressure, never below it.
    mean_pressure : float
        Load capacity over projected area L*D, Pa.
    load_capacity : float
        Magnitude of the film force, N.
    force_y, force_z : float
        Film force on the journal, N.
    moment_y, moment_z : float
        First moments of the vertical and horizontal film force about the mid-plane,
        ``sum((z - L/2) dF)``, N*m.
    load_centre_offset : float
        Axial position of the resultant film force from the mid-plane, m (positive
        forward); seed 004 calls it the distance of the support point from L/2.
    friction_force : float
        Shear force on the journal surface opposing rotation, N.
    friction_torque : float
        Friction torque on the journal, N*m.
    friction_coefficient : float
        Friction force over load capacity.
    power_loss : float
        Friction torque times shaft speed, W.
    inlet_flow : float
        Flow entering the film: the supply through the grooves, or (no groove)
        the circumferential flow across the line of maximum film, m^3/s.
    side_leakage : float
        Net flow leaving through both bearing edges, m^3/s.
    sommerfeld_number : float
        ``(R/c)^2 eta N / P`` with N in rev/s and P the mean pressure.
    contact : bool
        True when the film reaches ``min_film_floor`` or less (the load is not carried
        by a film this grid can resolve); with rough surfaces when it reaches the boundary
        limit ``-3 sigma`` (the film may be negative above it: the mean planes past each other).
    theta : ndarray (nt,)
        Node angles, rad, from the top in the direction of rotation.
    z : ndarray (nz,)
        Node stations from the aft bearing edge, m.
    film : ndarray (nz, nt)
        Film thickness h, m.
    pressure : ndarray (nz, nt)
        Gauge pressure, Pa.
    film_fraction : ndarray (nz, nt)
        Liquid share of the clearance (1 in the full film).
    circumferential_flow : ndarray (nt,)
        Flow across the axial line midway between node i and i+1, m^3/s.
    edge_leakage : ndarray (2, nt)
        Outflow through the aft (row 0) and forward (row 1) edge at each angle, m^3/s.
    cavitation : str
        Name of the cavitation model used.
    cavitated : ndarray of bool (nz, nt)
        Nodes held at the cavitation pressure (the solution's active set); a nearby
        equilibrium can start from it (``equilibrium(..., initial_cavitated=...)``).
    iterations : int
        Active-set iterations (linear solves) of this solution; a warm start
        (``solve_at(..., warm_start=True)``) needs fewer for the same result.
    rough : RoughContact or None
        Asperity contact of rough surfaces (``geometry.surface``; None when smooth).
    liner : LinerState or None
        Deformation of an elastic liner (``geometry.liner``; None for a rigid bore).
    turbulence : TurbulenceState or None
        Local Reynolds numbers and whether the turbulence coefficients applied (with
        ``options.turbulence`` on or auto; None when off).
    """

    # The fields: the written ones (quantity, part) after those kept only in memory.
    theta: np.ndarray = field(repr=False)
    z: np.ndarray = field(repr=False)
    film: np.ndarray = field(repr=False)
    pressure: np.ndarray = field(repr=False)
    film_fraction: np.ndarray = field(repr=False)
    circumferential_flow: np.ndarray = field(repr=False)
    edge_leakage: np.ndarray = field(repr=False)
    cavitation: str
    cavitated: np.ndarray = field(repr=False)
    iterations: int
    eccentricity_ratio: float = quantity(
        "-", "journal eccentricity from the bore centre at mid-plane / radial clearance"
    )
    attitude_angle: float = quantity(
        "rad", "load line to line of centres, positive in the sense of rotation", degrees=True
    )
    position_angle: float = quantity(
        "rad", "bearing angle of the line of centres (from top, in the sense of rotation)", degrees=True
    )
    position: JournalPosition = part(JournalPosition)
    min_film_thickness: float = quantity("m", "smallest film thickness h_min")
    min_film_theta: float = quantity("rad", "bearing angle of h_min", degrees=True)
    min_film_z: float = quantity("m", "axial position of h_min from the aft edge")
    max_pressure: float = quantity("Pa", "largest film pressure p_max (gauge)")
    max_pressure_theta: float = quantity("rad", "bearing angle of p_max", degrees=True)
    max_pressure_z: float = quantity("m", "axial position of p_max from the aft edge")
    mean_pressure: float = quantity("Pa", "load capacity / (L D)")
    load_capacity: float = quantity("N", "magnitude of the film force")
    force_y: float = quantity("N", "vertical film force on the journal (+ up)")
    force_z: float = quantity("N", "horizontal film force on the journal (+ starboard)")
    moment_y: float = quantity("N m", "first moment of the vertical film force about mid-plane")
    moment_z: float = quantity("N m", "first moment of the horizontal film force about mid-plane")
    load_centre_offset: float = quantity("m", "axial position of the film resultant from mid-plane (+ forward)")
    friction_force: float = quantity("N", "shear force on the journal")
    friction_torque: float = quantity("N m", "friction torque on the journal")
    friction_coefficient: float = quantity("-", "friction force / load capacity")
    power_loss: float = quantity("W", "friction power")
    inlet_flow: float = quantity("m^3/s", "flow entering the film (groove supply, or across the line of maximum film)")
    side_leakage: float = quantity("m^3/s", "net flow out through both bearing edges")
    sommerfeld_number: float = quantity("-", "(R/c)^2 eta N / P, N in rev/s")
    contact: bool = quantity("-", _CONTACT)
    rough: RoughContact | None = part(RoughContact, default=None)
    liner: LinerState | None = part(LinerState, default=None)
    turbulence: TurbulenceState | None = part(TurbulenceState, default=None)

    @property
    def min_film_ratio(self) -> float:
        """``h_min / sigma`` (inf for smooth surfaces, whose film is never near their asperities)."""
        return math.inf if self.rough is None else self.rough.min_film_ratio

    @property
    def asperity_load_share(self) -> float:
        """Share of the load carried by the asperities (0 for smooth surfaces)."""
        return 0.0 if self.rough is None else self.rough.asperity_load_share

    @property
    def max_liner_deformation(self) -> float:
        """Largest liner deformation, m (0 for a rigid bore)."""
        return 0.0 if self.liner is None else self.liner.max_deformation

    def to_dict(self) -> dict[str, Any]:
        """Every scalar result, keyed and in the units of :meth:`units` (plain JSON)."""
        return export.to_dict(self)

    @staticmethod
    def units(rough: bool = False, liner: bool = False, turbulence: bool = False) -> dict[str, str]:
        """The unit of every key of :meth:`to_dict` (with ``rough``, ``liner``, ``turbulence`` the
        keys of those parts too)."""
        present = (rough, liner, turbulence)
        parts = [
            kind for kind, there in zip((RoughContact, LinerState, TurbulenceState), present, strict=True) if there
        ]
        return export.units(BearingState, (JournalPosition, *parts))


@dataclass(frozen=True)
class Equilibrium:
    """Journal position that carries a given load.

    Attributes
    ----------
    state : BearingState
        Film solution at the final position.
    load_y, load_z : float
        Applied load on the journal, N.
    converged : bool
        True when the force residual fell below the tolerance.
    contact : bool
        True when the load cannot be carried above the film floor (``state`` is then
        the position reached at the floor).
    iterations : int
        Newton iterations used (on the bearing's grid; on a grid started from the
        equilibrium of a coarser one, those after that start), with the settling steps of
        a rigid rough bore whose Newton stalled (at most ``max_iterations`` more).
    residual : float
        Magnitude of ``force + load`` at the end, N.
    newton_iterations : int
        Newton iterations of every equilibrium this one solved, its start's on a coarser grid or
        a rigid bore included (``iterations`` counts this grid's only).
    film_solutions : int
        Film pressure solutions it took, on every grid (:class:`~shaftline.film.cavitation.SolverCounts`).
    factorisations : int
        Numeric sparse factorisations it took, on every grid.
    """

    state: BearingState = part(BearingState)
    load_y: float = quantity("N", "applied vertical load on the journal (− downward)")
    load_z: float = quantity("N", "applied horizontal load (+ starboard)")
    converged: bool = quantity("-", "equilibrium reached within the tolerance")
    contact: bool = quantity("-", _CONTACT)
    iterations: int = quantity("-", "Newton iterations")
    residual: float = quantity("N", "magnitude of film force + load at the end", key="force_residual")
    newton_iterations: int = 0
    film_solutions: int = 0
    factorisations: int = 0

    @property
    def status(self) -> str:
        """``"ok"``, ``"contact"`` (the film reached its floor) or ``"not converged"``."""
        return "contact" if self.contact else ("ok" if self.converged else "not converged")

    def to_dict(self) -> dict[str, Any]:
        """The state's results and the equilibrium's own (its ``contact`` in place of the state's)."""
        return export.to_dict(self)

    @staticmethod
    def units() -> dict[str, str]:
        """The unit of the equilibrium's own keys."""
        return export.units(Equilibrium)


@dataclass(frozen=True, eq=False)
class FilmLinearisation:
    """Film force at one journal position and its first derivatives.

    The derivatives are those of the discrete film force with the cavitated set
    frozen at that of the solution at ``position``: exact for the Reynolds
    (Swift-Stieber) condition, where ``p = dp/dn = 0`` on the free boundary so that
    moving the boundary changes the force only to second order; for the ``"jfo"``
    model they are those of the JFO system with its void-fraction transport (exact
    for the discrete film, docs/theory.md Eq. C4); an approximation for
    ``"half_sommerfeld"`` (whose clipped pressure changes with the full-film linear
    solution, which this holds at zero on the clipped nodes).

    Axes are the shaft axes (y up, z starboard); ``q = (ey, ez)`` are the
    journal centre offsets at the mid-plane and ``v = (vy, vz)`` their velocities.

    Attributes
    ----------
    position : JournalPosition
        Where the film was linearised.
    force : ndarray (2,)
        Film force on the journal ``(F_y, F_z)``, N (as ``BearingState.force_y``, ``force_z``).
    offset_derivative : ndarray (2, 2)
        ``[i, j] = dF_i / dq_j``, N/m: rows ``(F_y, F_z)``, columns ``(ey, ez)``.
    velocity_derivative : ndarray (2, 2)
        ``[i, j] = dF_i / dv_j``, N*s/m: rows ``(F_y, F_z)``, columns ``(vy, vz)``.
    """

    position: JournalPosition
    force: np.ndarray = field(repr=False)
    offset_derivative: np.ndarray
    velocity_derivative: np.ndarray

    @property
    def stiffness(self) -> np.ndarray:
        """``K = -dF/dq``, N/m, ``[[K_yy, K_yz], [K_zy, K_zz]]`` (positive when the film pushes back)."""
        return -self.offset_derivative

    @property
    def damping(self) -> np.ndarray:
        """``C = -dF/dv``, N*s/m, ``[[C_yy, C_yz], [C_zy, C_zz]]``."""
        return -self.velocity_derivative


@dataclass(frozen=True, eq=False)
class FilmLoad:
    """Film solution for a journal centre line of any shape, with its load along the bearing.

    Attributes
    ----------
    state : BearingState
        The film solution (position: the line's mid-plane offsets and chord tilts).
    row_force : ndarray (2, nz)
        Film force on the journal carried by each axial grid row (trapezoid share of the
        bore), ``(F_y, F_z)``, N; the rows sum to ``state.force_y``, ``state.force_z``.
    derivative : ndarray (2, nz, k)
        ``d row_force / d parameter`` for the requested centre-line directions, N per unit,
        with the cavitated set frozen.
    velocity_derivative : ndarray (2, nz, q)
        ``d row_force / d parameter`` for the requested centre-line velocities, N s per unit.
    """

    state: BearingState
    row_force: np.ndarray = field(repr=False)
    derivative: np.ndarray = field(repr=False)
    velocity_derivative: np.ndarray = field(repr=False, default_factory=lambda: np.zeros((2, 0, 0)))


@dataclass(frozen=True, eq=False)
class TiltLinearisation:
    """Film force and moment at one journal position and their first derivatives by journal
    offset, tilt and their rates: the 4 x 4 stiffness and damping of a film that resists
    rotation as well as translation (a long stern-tube bearing).

    Same frozen cavitated set and the same exactness as :class:`FilmLinearisation`, whose
    2 x 2 matrices are the top-left blocks of these. Axes are the shaft axes (y up, z
    starboard). Rows are ``(F_y, F_z, M_y, M_z)``, the film force on the journal (N) and its
    first moments about the mid-plane ``sum((z - L/2) dF)`` (N*m, as
    ``BearingState.moment_y``, ``moment_z``). Columns are ``q = (ey, ez, tilt_y, tilt_z)``,
    the journal centre offsets at the mid-plane (m) and the journal tilts (rad, dy/dx and
    dz/dx), for :attr:`offset_derivative`, and their rates ``(vy, vz, tilt rate y, tilt
    rate z)`` (m/s, rad/s) for :attr:`velocity_derivative`.

    Attributes
    ----------
    position : JournalPosition
        Where the film was linearised (for a bent journal line: its mid-plane offsets and chord
        tilts; the journal then moves as a rigid body from that line).
    force : ndarray (2,)
        ``(F_y, F_z)``, N.
    moment : ndarray (2,)
        ``(M_y, M_z)``, N*m.
    offset_derivative : ndarray (4, 4)
        ``[i, j] = d(F_y, F_z, M_y, M_z)_i / dq_j``: N/m and N/rad in the force rows
        (offset, tilt columns), N*m/m and N*m/rad in the moment rows.
    velocity_derivative : ndarray (4, 4)
        The same for the rates: N*s/m and N*s/rad, N*m*s/m and N*m*s/rad.
    """

    position: JournalPosition
    force: np.ndarray = field(repr=False)
    moment: np.ndarray = field(repr=False)
    offset_derivative: np.ndarray
    velocity_derivative: np.ndarray

    @property
    def stiffness(self) -> np.ndarray:
        """``K = -offset_derivative`` (4 x 4): rows (F_y, F_z, M_y, M_z), columns (ey, ez, tilt_y, tilt_z)."""
        return -self.offset_derivative

    @property
    def damping(self) -> np.ndarray:
        """``C = -velocity_derivative`` (4 x 4), columns the rates of (ey, ez, tilt_y, tilt_z)."""
        return -self.velocity_derivative
