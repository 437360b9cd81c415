"""Journal bearing: the film solution at a journal position and the equilibrium under a load.

Forces are those of the film on the journal, in the shaft axes (y up, z
starboard), N. Pressures are gauge pressures above the ambient pressure, Pa.
An applied load ``(load_y, load_z)`` is carried when the film force balances it:
``force + load = 0``.

A :class:`JournalBearing` is a :class:`~shaftline.film.problem.BearingProblem`
(pure data) plus solver state that belongs to one process: the Reynolds solver
with its sparse factorisation, the coarse-grid solver that predicts the
cavitated set, and the last active set (the warm start). Pickling or deep-copying
a bearing carries only the problem; the solver state is rebuilt on first use.
"""

from __future__ import annotations

import copy
import math
from collections.abc import Callable, Iterator
from dataclasses import dataclass, field, replace
from typing import Any

import numpy as np

from shaftline.errors import InputError, SolverFailure, require_finite
from shaftline.film.analytic import eccentricity_guess
from shaftline.film.elastic import CoupledLiner, CoupledOrderings, LayerSystem, LinerSystem
from shaftline.film.extremes import local_extreme
from shaftline.film.geometry import (
    MIN_AXIAL_NODES,
    MIN_CIRCUMFERENTIAL_NODES,
    BearingGeometry,
    BentJournal,
    Grid,
    JournalPosition,
    coarse_shape,
    film_thickness,
    squeeze_velocity,
)
from shaftline.film.jfo import JfoSolution, relaxed_set, void_transport
from shaftline.film.layer import ElasticLayer, layer_operator
from shaftline.film.problem import (
    CAVITATION_MODELS,
    FILM_STARTS,
    BearingProblem,
    Cavitation,
    OperatingPoint,
    SolverOptions,
    SupplyGroove,
)
from shaftline.film.reynolds import (
    ReynoldsConvergenceError,
    ReynoldsSolution,
    ReynoldsSolver,
    Stencil,
    apply_operator,
    build_stencil,
    stencil_derivative,
)
from shaftline.film.roughness import (
    BOUNDARY_LIMIT,
    LAMBDA_SWITCH,
    TABLE_LOWEST,
    FilmFlow,
    RoughFilm,
    asperity_pressure,
    asperity_pressure_derivative,
    contact_area_ratio,
    lubrication_regime,
    mean_gap,
)
from shaftline.film.turbulence import TurbulentFilm, clearance_reynolds, couette_shear_factor, turbulence_active

__all__ = [
    # Problem data, defined in shaftline.film.problem and re-exported here for compatibility.
    "CAVITATION_MODELS",
    "FILM_STARTS",
    "BearingProblem",
    "OperatingPoint",
    "SolverOptions",
    "SupplyGroove",
    # Results and the solver.
    "BearingState",
    "Equilibrium",
    "FilmLinearisation",
    "FilmLoad",
    "JournalBearing",
    "TiltLinearisation",
]

#: Grids with at least this many nodes start the equilibrium from the equilibrium on the grid
#: halved in both directions (grid continuation): the fine Newton steps are then short, so
#: each trial's predicted active set is nearly right, and the first film solution starts its
#: active set from the coarse pressure. Measured on the NTUA case (misaligned; median of 15,
#: benchmarks/bench_bearing.py): 80 x 48 the same with and without (16 ms), 100 x 60 17 ms
#: against 23, 120 x 72 27 against 34, 140 x 84 57 against 111, 200 x 120 91 against 314 (4
#: fine Newton iterations from the closed-form start, 2 from the coarse equilibrium). The
#: mass-conserving model too (NTUA, cavitation pressure -30 kPa, 100 x 60: 89 -> 52 ms, 4 -> 2
#: fine iterations); a bearing with a liner or a rough surface keeps the threshold that its
#: solver paths were tuned with, :data:`CONTINUATION_NODES_OTHER`.
CONTINUATION_NODES = 5_000
CONTINUATION_NODES_OTHER = 20_000
#: Force tolerance (share of the load) of that coarse equilibrium: it only places the start.
#: The fine Newton iteration takes about ``r -> 0.7 r^2`` there, so from a start within 1 % of
#: the load it converges (1e-8) in two steps; the start's residual is the coarse grid's
#: discretisation error plus this tolerance, so a tighter one buys nothing (18 NTUA
#: equilibria, 100 x 60 and 200 x 120, three loads and tilts: the same fine iterations at
#: 1e-5 and 2e-3, one coarse iteration fewer at 2e-3 on the example, 5 % of its time). The
#: mass-conserving model on a smooth rigid bore takes it too (18 NTUA JFO equilibria, the same
#: grids, loads and tilts: the same fine iterations and flags at 1e-5 and 2e-3, positions
#: within 6e-10 of the clearance, the 100 x 60 example 5 % faster; of 108 a review tried, two
#: took one fine iteration more, in the same time). Liners and rough surfaces
#: keep :data:`OTHER_START_TOLERANCE`.
CONTINUATION_TOLERANCE = 2e-3
#: Force tolerance of the equilibria that only place the start of a bearing with a liner or a
#: rough surface (the coarse grid's, and a lined bearing's rigid bore's): the one their solver
#: paths were tuned with (docs/theory.md Sect. 17).
OTHER_START_TOLERANCE = 1e-5
#: Force residual (share of the load) below which a Newton step's trials refine their pressure
#: from the step's linear guess by conjugate gradients preconditioned by the current film's
#: factor instead of factorising their own matrix: there the step changes the film by about
#: that share, so the iteration gains about that factor per step (ReynoldsSolver.solve).
REFINE_RESIDUAL = 1e-3
#: Force residual (share of the load) above which a mass-conserving (JFO) Newton iterate may leave
#: its active set a few nodes short of settling (each set costs an LU factorisation there). Such
#: an iterate's force is off by about 1e-5 of the load, which stalls Newton's quadratic steps
#: below about 1e-3 (NTUA 100 x 60: 1.1e-3 -> 1.5e-5 -> 2.8e-6 with loose trials throughout):
#: below it the trials settle, and so does an unsettled iterate before its step. The Reynolds
#: condition's floor is :data:`REFINE_RESIDUAL`, below which its trials are refined.
JFO_UNSETTLED_RESIDUAL = 1e-2
#: Newton iterations in a row that each leave more than ``STALLED_REDUCTION`` of the force
#: residual, after which a rigid rough bore's equilibrium is given up: as contact when its film
#: is at the boundary limit (the asperities there cannot carry the rest of the load), as not
#: converged above it (seed 001's rig at 15 rpm: the residual stalls at 11 % of the load with
#: the film at lambda 0.1, the fluid spike of a contact zone one or two cells wide) unless the
#: grid resolves the contact zone (:data:`SETTLE_ZONE_NODES`), where the equilibrium is settled
#: (:meth:`JournalBearing._settle`). Smooth films keep their rule (no descent left).
STALLED_ITERATIONS = 4
STALLED_REDUCTION = 0.99
#: The same rule for a crawl: this many Newton iterations in a row whose steps the line search's
#: residual test shortened and that each leave more than ``CRAWL_REDUCTION`` of the residual
#: (docs/theory.md, "The stall rule and crawling Newton steps"). Measured on 244 rigid rough
#: equilibria (the test suite, both Stribeck curves of bench_mixed from warm and cold starts, the
#: NTUA bearing at psi 0 to 0.4): no equilibrium that converged had more than 5 such iterations
#: in a row; the NTUA curve at 12.4 rpm from a cold start had 45.
CRAWL_ITERATIONS = 10
CRAWL_REDUCTION = 0.95
#: A rough film within this many sigma above the boundary limit (``BOUNDARY_LIMIT * sigma``) is
#: at its floor: its asperities at the limit of the model cannot carry the rest of the load.
FLOOR_MARGIN = 0.05
#: Pseudo-transient settling of a stalled rigid rough bore (:meth:`JournalBearing._settle`): its
#: first step moves the journal about this many sigma along the net force, no step moves it more
#: than ``SETTLE_MAX_MOVE`` sigma (the film changes by at most that much), and a step that raises
#: the residual more than ``SETTLE_GROWTH`` times is taken again with a quarter of the pseudo-time.
SETTLE_FIRST_MOVE = 0.1
SETTLE_MAX_MOVE = 0.5
SETTLE_GROWTH = 2.0
#: Circumferential nodes the film must have within one sigma of its minimum (on the row of the
#: minimum) for the settling to run. On fewer the film pressure of the contact zone is a spike on
#: a node or two whose size jumps as the minimum moves between nodes, the discrete force is not a
#: function a root-finder can follow, and the equilibrium is reported not converged at once, as
#: before. Seed 001's rigid rig (docs/validation.md, "Rigid rough bore at low speed"): 3-4 nodes on
#: 120 (Newton stalls at 5 of 5 speeds below 21 rpm), 7 on 240 (the settling ran its 60 steps
#: without converging at 3 of 3 stalled speeds), 14 on 480 (it converged at 3 of 3).
SETTLE_ZONE_NODES = 10
#: A lined equilibrium whose film-liner iteration does not settle at its start is started where
#: it does, on the way to the bore's centre (:meth:`JournalBearing._start_evaluation`): the journal
#: lifted by sigma, 2 sigma, 4 sigma, ... (rough) or by this share of the clearance, doubled
#: likewise (smooth; about sigma / c of seed 001's rig, 0.004).
START_LIFT = 0.005
#: Liner deformation converged when the column model's residual is below this share of the
#: radial clearance everywhere (0.55 pm on seed 001's rig): tight enough that the force it
#: leaves uncertain is below the equilibrium's tolerance (1e-8 of the load); Newton's quadratic
#: convergence makes the last digits cheap.
LINER_TOLERANCE = 1e-9
#: Inside the equilibrium's Newton iteration a trial's liner is solved only until the force
#: error it leaves is about this share of the force residual (an inexact Newton method; Dembo,
#: Eisenstat & Steihaug, SIAM J. Numer. Anal. 19 (1982) 400-408): far from the equilibrium the
#: last digits of the deformation change the force by far less than the residual. A deformation
#: error dD (of c) changes the film at its thinnest, H_min, by dD, and the force by about dD /
#: H_min of itself, so the liner tolerance is the force share times H_min; the converged
#: equilibrium's liner is solved to a tenth of the equilibrium's own tolerance that way.
INEXACT_LINER = 0.01
#: Force residual (share of the load) above which the equilibrium's Jacobian with a liner may use
#: the matrix of the film-liner iteration's last step instead of a new factorisation.
NEARBY_JACOBIAN = 1e-3
#: Newton iterations of the film-liner system allowed per film solution.
LINER_ITERATIONS = 40
#: The film-liner iteration gives up when its residual has not halved over this many steps (a
#: trial the film cannot hold; the seed 001 rig at 15 rpm spent 27 such trials x 40 steps).
LINER_STAGNATION = 10
#: A kept (chord) factor of the film-liner matrix is used while each of its steps leaves at most
#: this share of the liner residual: a slower step costs a film solution for little, and a
#: fresh factor (about three film solutions on 100 x 60) converges quadratically.
CHORD_REDUCTION = 0.1
#: Scalar Newton iterations allowed on the fixed-pressure nodes of a column liner with asperity
#: contact before each film solution (:meth:`JournalBearing._evaluate_liner`), and the share of
#: the liner tolerance they reach there (5 to 10 iterations from a zero start on seed 001's rig).
FIXED_ITERATIONS = 30
FIXED_TOLERANCE = 0.1


class LinerConvergenceError(SolverFailure):
    """The film-liner Newton iteration did not settle (treated like a film that cuts the bore).

    ``residual`` (also ``args[0]``) is the liner residual left, of the clearance; ``evaluation``
    the iteration's last iterate where the solver raised it (None where it was raised elsewhere).
    Its message is a sentence (the command line printed the bare number: "not solved: 0.0079")."""

    def __init__(self, residual: float, evaluation: _Evaluation | None = None) -> None:
        super().__init__(residual)
        self.residual = float(residual)
        self.evaluation = evaluation

    def __str__(self) -> str:
        return f"the film-liner iteration did not settle (liner residual {self.residual:.3g} of the clearance)"


@dataclass(frozen=True, eq=False)
class BearingState:
    """Film solution at one journal position. Fields are SI unless noted.

    Attributes
    ----------
    position : JournalPosition
        Journal centre offsets from the nominal bore axis (m) and tilts (rad) at the
        bearing mid-plane.
    eccentricity_ratio : float
        Eccentricity of the journal from the bore centre at the mid-plane (the
        machined bore of a slope-bored bearing) over the radial clearance.
    position_angle : float
        Bearing angle of that line of centres (towards the thinnest film), rad.
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
    force_y, force_z : float
        Film force on the journal, N.
    load_capacity : float
        Magnitude of the film force, N.
    attitude_angle : float
        Angle from the load line (opposite to the film force) to the line of
        centres, positive in the direction of rotation, rad.
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
    circumferential_flow : ndarray (nt,)
        Flow across the axial line midway between node i and i+1, m^3/s.
    edge_leakage : ndarray (2, nt)
        Outflow through the aft (row 0) and forward (row 1) edge at each angle, m^3/s.
    sommerfeld_number : float
        ``(R/c)^2 eta N / P`` with N in rev/s and P the mean pressure.
    contact : bool
        True when the film reaches ``min_film_floor`` or less (the load is not carried
        by a film this grid can resolve); with rough surfaces when it reaches the boundary
        limit ``-3 sigma`` (the film may be negative above it: the mean planes past each other).
    cavitation : Cavitation
        Cavitation model used.
    cavitated : ndarray of bool (nz, nt)
        Nodes held at the cavitation pressure (the solution's active set); a nearby
        equilibrium can start from it (``equilibrium(..., initial_cavitated=...)``).
    iterations : int
        Active-set iterations (linear solves) of this solution; a warm start
        (``solve_at(..., warm_start=True)``) needs fewer for the same result.
    asperity_pressure : ndarray (nz, nt) or None
        Greenwood-Tripp asperity contact pressure, Pa (rough surfaces, ``geometry.surface``;
        None when smooth). ``force_y``, ``force_z``, the moments and ``load_capacity`` include it;
        ``pressure`` and ``max_pressure`` are the film's alone.
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
        asperity load (``boundary_friction x`` asperity pressure), N; they sum to
        ``friction_force`` (smooth: all fluid).
    film_ratio : ndarray (nz, nt) or None
        ``lambda = h / sigma`` over the bore (rough surfaces).
    min_film_ratio : float
        ``h_min / sigma`` (inf when smooth).
    lubrication_regime : str or None
        ``"boundary"`` (lambda_min < 1), ``"mixed"`` (1-3) or ``"full film"`` (> 3); None when smooth.
    liner_deformation : ndarray (nz, nt) or None
        Deformation of an elastic liner away from the journal, m (``geometry.liner``; None for a
        rigid bore). ``film`` includes it, and so ``min_film_thickness`` and the pressures.
    max_liner_deformation : float
        Its largest value, m.
    liner_iterations : int
        Newton iterations of the film-liner system in this solution.
    reynolds_number : ndarray (nz, nt) or None
        Local Reynolds number ``Re_h = rho omega R h / mu`` over the bore (with
        ``options.turbulence`` on or auto; None when off).
    max_reynolds_number : float
        Its largest value (0 when off).
    turbulent : bool
        Whether the turbulence coefficients were applied (docs/theory.md Sect. 17, "Turbulent
        films"): ``options.turbulence`` on, or auto above the transition.

    Equality is identity: the fields hold arrays, which have no single truth value.
    """

    position: JournalPosition
    eccentricity_ratio: float
    position_angle: float
    theta: np.ndarray = field(repr=False)
    z: np.ndarray = field(repr=False)
    film: np.ndarray = field(repr=False)
    pressure: np.ndarray = field(repr=False)
    film_fraction: np.ndarray = field(repr=False)
    force_y: float
    force_z: float
    load_capacity: float
    attitude_angle: float
    min_film_thickness: float
    min_film_theta: float
    min_film_z: float
    max_pressure: float
    max_pressure_theta: float
    max_pressure_z: float
    mean_pressure: float
    moment_y: float
    moment_z: float
    load_centre_offset: float
    friction_force: float
    friction_torque: float
    friction_coefficient: float
    power_loss: float
    inlet_flow: float
    side_leakage: float
    circumferential_flow: np.ndarray = field(repr=False)
    edge_leakage: np.ndarray = field(repr=False)
    sommerfeld_number: float
    contact: bool
    cavitation: Cavitation
    cavitated: np.ndarray
    iterations: int
    asperity_pressure: np.ndarray | None = field(default=None, repr=False)
    asperity_load: float = 0.0
    asperity_load_share: float = 0.0
    max_asperity_pressure: float = 0.0
    contact_area_ratio: float = 0.0
    fluid_friction_force: float = 0.0
    boundary_friction_force: float = 0.0
    film_ratio: np.ndarray | None = field(default=None, repr=False)
    min_film_ratio: float = math.inf
    lubrication_regime: str | None = None
    liner_deformation: np.ndarray | None = field(default=None, repr=False)
    max_liner_deformation: float = 0.0
    liner_iterations: int = 0
    reynolds_number: np.ndarray | None = field(default=None, repr=False)
    max_reynolds_number: float = 0.0
    turbulent: bool = False


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
    """

    state: BearingState
    load_y: float
    load_z: float
    converged: bool
    contact: bool
    iterations: int
    residual: float

    @property
    def status(self) -> str:
        """``"ok"``, ``"contact"`` (the film reached its floor) or ``"not converged"``."""
        return "contact" if self.contact else ("ok" if self.converged else "not converged")


@dataclass(frozen=True, eq=False)
class FilmLinearisation:
    """Film force at one journal position and its first derivatives.

    The derivatives are those of the discrete film force with the cavitated set
    frozen at that of the solution at ``position``: exact for the Reynolds
    (Swift-Stieber) condition, where ``p = dp/dn = 0`` on the free boundary so that
    moving the boundary changes the force only to second order; for the ``"jfo"``
    model they are those of the JFO system with its void-fraction transport (exact
    for the discrete film, docs/theory.md Eq. C4); an approximation for
    ``"half_sommerfeld"`` (whose
    clipped pressure changes with the full-film linear solution, which this
    holds at zero on the clipped nodes).

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

    Equality is identity: the fields hold arrays, which have no single truth value.
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

    Equality is identity: the fields hold arrays, which have no single truth value.
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
        Where the film was linearised.
    force : ndarray (2,)
        ``(F_y, F_z)``, N.
    moment : ndarray (2,)
        ``(M_y, M_z)``, N*m.
    offset_derivative : ndarray (4, 4)
        ``[i, j] = d(F_y, F_z, M_y, M_z)_i / dq_j``: N/m and N/rad in the force rows
        (offset, tilt columns), N*m/m and N*m/rad in the moment rows.
    velocity_derivative : ndarray (4, 4)
        The same for the rates: N*s/m and N*s/rad, N*m*s/m and N*m*s/rad.

    Equality is identity: the fields hold arrays, which have no single truth value.
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


@dataclass(eq=False)
class _Evaluation:
    position: JournalPosition
    grid: Grid
    film: np.ndarray
    stencil: Stencil
    solution: ReynoldsSolution
    relative_pressure: np.ndarray  # dimensionless, above cavitation pressure, fixed nodes included
    force: np.ndarray  # (2,) N, film and asperities
    rate: np.ndarray | None = None  # (2/omega) dH/dt of a moving journal
    contact: np.ndarray | None = None  # asperity pressure, Pa (rough surfaces only)
    deformation: np.ndarray | None = None  # liner deformation, m (elastic liner only)
    liner_system: CoupledLiner | None = None  # coupled Newton matrix at this film (built on demand)
    liner_iterations: int = 0
    liner_residual: float = 0.0  # max |R| of the liner equation left, of the clearance
    nearby_system: CoupledLiner | None = None  # the last matrix factorised in its liner iteration
    shortened: bool = False  # a line-search trial reached by a step its residual test shortened


@dataclass
class _Found:
    """Where :meth:`JournalBearing._find_equilibrium` ended: its last film solution, whether it
    converged or met the film floor, its Newton iterations and force residual (N), and whether
    its start was solved (False: a lined start whose film-liner iteration did not settle at any
    position tried, reported as it is)."""

    evaluation: _Evaluation
    converged: bool
    contact: bool
    iterations: int
    residual: float
    started: bool = True


class _SolverState:
    """What a bearing builds from its problem to solve it, in one process.

    Never pickled: :class:`JournalBearing` drops it when pickled or copied and
    builds it again on first use, so a problem sent to another process carries no
    factorisation (qdldl objects do not pickle) and no stale warm start.

    Attributes
    ----------
    grid : Grid
        Grid with its first angle at 0; rotated per position by ``JournalBearing.grid``.
    d_theta, d_z : float
        Dimensionless mesh steps: rad, and axial step over the radius.
    area_weights : ndarray (nz, 1)
        Bore area per node, m^2 (trapezoid in z, periodic in theta).
    reynolds : ReynoldsSolver
        Solver for the grid and the fixed-pressure nodes, with its factorisation and coarse grid.
    last_cavitated : ndarray of bool or None
        Cavitated set of the last solution (the warm start of the next one).
    """

    def __init__(self, problem: BearingProblem) -> None:
        geometry, op, options = problem.geometry, problem.operating, problem.options
        grid = Grid(geometry.length, options.axial_nodes, options.circumferential_nodes)
        radius = geometry.radius
        self.grid = grid
        self.d_theta = grid.d_theta
        self.d_z = grid.dz / radius
        wz = np.full(grid.axial_nodes, grid.dz)
        wz[[0, -1]] *= 0.5
        self.area_weights = wz[:, None] * (radius * grid.d_theta)
        self.last_cavitated: np.ndarray | None = None
        #: Liner deformation of the last solution, m (the start of the next film-liner Newton
        #: iteration when none is given: a linearisation at an equilibrium starts from its own).
        #: With a liner, results then depend on earlier calls to within the liner tolerance
        #: (1e-9 of the clearance); the equilibrium clears it first.
        self.last_deformation: np.ndarray | None = None
        #: The layer model's compliance on this grid (built on first use; film/layer.py).
        self.layer: ElasticLayer | None = None
        #: Orderings of the coupled film-liner matrix per free set (film/elastic.py), cleared
        #: with the deformation where a result must not depend on earlier calls.
        self.orderings = CoupledOrderings()
        nz, nt = grid.shape
        fixed = np.zeros(grid.shape, dtype=bool)
        value = np.zeros(grid.shape)
        fixed[0], value[0] = True, op.aft_pressure
        fixed[-1], value[-1] = True, op.fore_pressure
        if op.grooves:
            first = op.grooves[0].angle
            for groove in op.grooves:
                column = int(round(((groove.angle - first) % (2 * math.pi)) / grid.d_theta)) % nt
                half = 0.5 * groove.length_fraction * grid.length
                rows = np.abs(grid.z - 0.5 * grid.length) <= half + 1e-12 * grid.length
                fixed[rows, column] = True
                value[rows & ~np.isin(np.arange(nz), (0, nz - 1)), column] = groove.pressure
        elif options.film_start == "max_film":
            fixed[:, 0] = True
            value[1:-1, 0] = 0.0
        relative = (value - op.cavitation_pressure) / problem.pressure_scale
        self.reynolds = ReynoldsSolver(grid.shape, self.d_theta, self.d_z, fixed, relative)
        self.coarse_bearing: JournalBearing | None = None
        #: The same bearing with a rigid bore: the start of a lined equilibrium.
        self.rigid_bearing: JournalBearing | None = None


class JournalBearing:
    """A finite journal bearing: geometry, operating point and solver options.

    The inputs form a :class:`~shaftline.film.problem.BearingProblem` (``.problem``),
    checked when the bearing is made. The solver state (Reynolds solver, sparse
    factorisation, coarse grid, last active set) is built on first use in each
    process: pickling, ``copy.copy`` or ``copy.deepcopy`` carry only the problem, so
    a bearing, solved or not, can be sent to a process pool. The first
    ``solve_at(..., warm_start=True)`` after that starts cold; :meth:`equilibrium`,
    :meth:`linearise` and ``solve_at(..., warm_start=False)`` never depend on
    earlier calls.

    Parameters
    ----------
    geometry : BearingGeometry
    operating : OperatingPoint
    options : SolverOptions, optional
        Defaults to ``SolverOptions()``.

    Raises
    ------
    InputError
        ``"operating.cavitation_pressure"`` for a ``"jfo"`` film without feed pressure.

    Examples
    --------
    >>> from shaftline.film import BearingGeometry, JournalBearing, OperatingPoint
    >>> bearing = JournalBearing(
    ...     BearingGeometry(length=0.1, diameter=0.1, radial_clearance=1e-4),
    ...     OperatingPoint(speed=100.0, viscosity=0.02),
    ... )
    >>> eq = bearing.equilibrium(load_y=-5e3, load_z=0.0)
    >>> round(eq.state.sommerfeld_number, 3), round(eq.state.eccentricity_ratio, 2)
    (0.159, 0.53)
    >>> stiffness = bearing.linearise(eq.state.position).stiffness  # N/m
    >>> bool(stiffness[0, 0] > 0)
    True
    """

    def __init__(
        self, geometry: BearingGeometry, operating: OperatingPoint, options: SolverOptions | None = None
    ) -> None:
        self._problem = BearingProblem(geometry, operating, SolverOptions() if options is None else options)
        self._cache: _SolverState | None = None

    @classmethod
    def from_problem(cls, problem: BearingProblem) -> JournalBearing:
        """The bearing of ``problem``, which it keeps as it is (already checked when made)."""
        bearing = cls.__new__(cls)
        bearing.__setstate__({"problem": problem})
        return bearing

    def with_geometry(self, geometry: BearingGeometry) -> JournalBearing:
        """This bearing with another bore or journal shape, sharing the solver it has built.

        For a design search over bores: the grid, the fixed nodes and the Reynolds solver
        with its kept factorisations depend on the length, diameter, clearance, sense of
        rotation, operating point and options, not on the bore profile, the bent journal or a
        film profile, so a bearing that differs only in those reuses them (the coarse bearing
        of the grid continuation is built again: it carries the geometry). The kept factors
        are dropped, so that its results do not depend on what the shared solver solved
        before (their orderings would round differently).

        Raises
        ------
        InputError
            ``"geometry.length"`` (or ``diameter``, ``radial_clearance``, ``rotation``) when it
            differs from this bearing's.
        """
        for name in ("length", "diameter", "radial_clearance", "rotation"):
            if getattr(geometry, name) != getattr(self.geometry, name):
                raise InputError(
                    f"geometry.{name}", getattr(geometry, name), "", f"{getattr(self.geometry, name)}, as the bearing's"
                )
        other = JournalBearing.from_problem(replace(self._problem, geometry=geometry))
        if self._cache is not None:
            shared = copy.copy(self._cache)
            shared.coarse_bearing = None
            shared.last_cavitated = None
            shared.last_deformation = None
            shared.orderings = CoupledOrderings()
            shared.reynolds.drop_factors()
            other._cache = shared
        return other

    # -- the problem: read-only, since the solver state is built from it ------------------
    @property
    def problem(self) -> BearingProblem:
        """Geometry, operating point and solver options (pure data)."""
        return self._problem

    @property
    def geometry(self) -> BearingGeometry:
        """``problem.geometry``."""
        return self._problem.geometry

    @property
    def operating(self) -> OperatingPoint:
        """``problem.operating``."""
        return self._problem.operating

    @property
    def options(self) -> SolverOptions:
        """``problem.options``."""
        return self._problem.options

    @property
    def pressure_scale(self) -> float:
        """Pressure scale p_ref = 6 eta omega (R/c)^2, Pa."""
        return self._problem.pressure_scale

    @property
    def flow_scale(self) -> float:
        """Flow scale omega R^2 c / 2, m^3/s."""
        return self._problem.flow_scale

    def __repr__(self) -> str:
        return f"JournalBearing({self._problem!r})"

    # -- pickling and copying carry the problem only ------------------------------------
    def __getstate__(self) -> dict[str, Any]:
        return {"problem": self._problem}

    def __setstate__(self, state: dict[str, Any]) -> None:
        self._problem = state["problem"]
        self._cache = None

    def _solver_state(self) -> _SolverState:
        if self._cache is None:
            self._cache = _SolverState(self._problem)
        return self._cache

    # -- grid and fixed nodes ----------------------------------------------------------
    def _local_polar(self, position: JournalPosition) -> tuple[float, float]:
        """Eccentricity (m) and line-of-centres angle (rad) relative to the bore centre at mid-plane."""
        bore_y, bore_z = self.geometry.bore_centre_line(np.array([0.5 * self.geometry.length]))
        local = JournalPosition(ey=position.ey - float(bore_y[0]), ez=position.ez - float(bore_z[0]))
        return local.polar(self.geometry.rotation)

    def grid(self, position: JournalPosition) -> Grid:
        """The grid on which the film is solved with the journal at ``position``.

        Its first angle sits on the first supply groove, or with ``film_start="max_film"``
        on the line of maximum film at ``position``; otherwise at 0 (then the grid does
        not depend on the position).
        """
        base = self._solver_state().grid
        if self.operating.grooves:
            start = self.operating.grooves[0].angle
        elif self.options.film_start == "max_film":
            e, angle = self._local_polar(position)
            start = angle + math.pi if e > 0 else 0.0
        else:
            return base
        return replace(base, theta_start=float(start))

    # -- core evaluation -------------------------------------------------------------
    def film(self, position: JournalPosition) -> np.ndarray:
        """Film thickness on :meth:`grid` for ``position``, m, shape (nz, nt) (no clipping)."""
        return film_thickness(self.geometry, self.grid(position), position)

    def _evaluate(
        self,
        position: JournalPosition,
        warm: bool = True,
        start: np.ndarray | None = None,
        geometry: BearingGeometry | None = None,
        tilt_rates: tuple[float, float] = (0.0, 0.0),
        start_pressure: np.ndarray | None = None,
        deformation: np.ndarray | None = None,
        chord: CoupledLiner | None = None,
        liner_tolerance: float = LINER_TOLERANCE,
        refine_from: np.ndarray | None = None,
        settle: bool = True,
    ) -> _Evaluation:
        """The film solution at ``position`` (with ``geometry`` in place of the bearing's, e.g. a
        bent journal of :meth:`film_load`); ``tilt_rates`` (rad/s, dy/dx and dz/dx per second)
        add the squeeze of a tilting journal, ``dh/dt = -(z - L/2)(w_y cos + s w_z sin)``
        (the position carries only the centre's velocities). ``start_pressure`` (relative,
        dimensionless), a guess of the pressure, gives the start set of the Reynolds
        condition's active set instead of ``start``
        (:meth:`~shaftline.film.reynolds.ReynoldsSolver.predicted_set`). With an elastic liner
        the film and the liner are solved together (:meth:`_evaluate_liner`), from the
        ``deformation`` given (m) or none, its first steps with the Newton matrix ``chord`` of a
        nearby film when given, to ``liner_tolerance`` (max |R| of the liner equation over the
        clearance). ``refine_from``, a pressure guess close to the solution (relative,
        dimensionless; rigid bore, Reynolds condition), with ``start`` the set it starts from:
        the solution is iterated from it with the kept factor instead of factorising
        (:meth:`~shaftline.film.reynolds.ReynoldsSolver.solve`). ``settle=False`` (rigid bore,
        Reynolds condition or JFO): its active set may stop a few nodes short of settling, as a
        Newton iterate far from the equilibrium may (:meth:`_settled_set` finishes it). With the
        JFO model ``start_pressure`` is the coarse JFO unknown (P, or -s where cavitated), whose
        negative nodes, after the sweeps of :func:`~shaftline.film.jfo.relaxed_set`, start the set."""
        cache = self._solver_state()
        grid = self.grid(position)
        film = film_thickness(geometry or self.geometry, grid, position)
        liner = (geometry or self.geometry).liner
        rigid = film
        if liner is not None:
            # The journal may pass the rigid bore surface into the liner: the film is the rigid
            # gap plus the deformation, started where none is given from the least deformation
            # that leaves a film of the floor (the Newton iteration then finds the real one); a
            # rough film's from the mean plane's approach, not from below it.
            floor = self._approach_floor()
            if deformation is None and cache.last_deformation is not None:
                deformation = cache.last_deformation
            start_deformation = np.zeros_like(film) if deformation is None else deformation
            film = film + np.maximum(start_deformation, floor - film)
        if film.min() <= self._film_limit():
            raise _NegativeFilm(float(film.min()))
        c = self.geometry.radial_clearance
        film_nd = film / c
        rate = None
        if position.vy or position.vz or tilt_rates[0] or tilt_rates[1]:
            tilting = replace(position, vy=tilt_rates[0], vz=tilt_rates[1])
            arm = (grid.z - 0.5 * self.geometry.length)[:, None]
            dh_dt = squeeze_velocity(self.geometry, grid, position) + arm * squeeze_velocity(
                self.geometry, grid, tilting
            )
            rate = (2.0 / self.operating.speed) * dh_dt / c
        rough = self._rough_film()
        stencil = build_stencil(film_nd, cache.d_theta, cache.d_z, rate, rough)
        solver = cache.reynolds
        # A turbulent film's coarse-grid prediction of the cavitated set uses its own flow (the
        # laminar one put the boundary off by many nodes: 8 active-set solves instead of 1).
        solver.flow = rough if isinstance(rough, TurbulentFilm) else None
        if start_pressure is not None and self.options.cavitation == "reynolds":
            start = solver.trial_set(stencil, film_nd, start_pressure)
        elif start_pressure is not None and self.options.cavitation == "jfo":
            # The coarse JFO unknown (P, or -s where cavitated) changes sign on both cavitation
            # boundaries: sharpened on this grid, its negative nodes start the set (as in the
            # JFO nested start).
            start = relaxed_set(solver, stencil, start_pressure)
        if start is None and warm:
            start = cache.last_cavitated
        if liner is not None:
            return self._evaluate_liner(
                position, grid, rigid, rate, start, film - rigid, geometry or self.geometry, chord, liner_tolerance
            )
        solution = solver.solve(
            stencil, film_nd, self.options.cavitation, start, refine_from=refine_from, settle=settle
        )
        surface = (geometry or self.geometry).surface
        contact = None if surface is None else asperity_pressure(surface, film)
        relative, force = self._solved(solution, grid, contact)
        return _Evaluation(position, grid, film, stencil, solution, relative, force, rate, contact)

    def _solved(
        self, solution: ReynoldsSolution, grid: Grid, contact: np.ndarray | None
    ) -> tuple[np.ndarray, np.ndarray]:
        """Relative pressure (dimensionless, fixed nodes included) and force (N, film and
        asperities) of a rigid film's solution; its set becomes the next warm start."""
        cache = self._solver_state()
        cache.last_cavitated = solution.cavitated
        solver = cache.reynolds
        relative = np.where(solver.fixed, solver.fixed_pressure, solution.pressure)
        return relative, self._integrate_force(grid, relative, contact=contact)

    def _settled_set(self, evaluation: _Evaluation) -> _Evaluation:
        """``evaluation`` with its active set settled (itself when it is): the solve continues
        from its set on its own stencil, so the kept factor of that set and film carries the
        last switch as a bordered update (rigid bore; see :meth:`_evaluate`, ``settle``)."""
        if evaluation.solution.settled:
            return evaluation
        solver = self._solver_state().reynolds
        film_nd = evaluation.film / self.geometry.radial_clearance
        solution = solver.solve(evaluation.stencil, film_nd, self.options.cavitation, evaluation.solution.cavitated)
        relative, force = self._solved(solution, evaluation.grid, evaluation.contact)
        return replace(evaluation, solution=solution, relative_pressure=relative, force=force)

    def _evaluate_liner(
        self,
        position: JournalPosition,
        grid: Grid,
        rigid: np.ndarray,
        rate: np.ndarray | None,
        start: np.ndarray | None,
        deformation: np.ndarray,
        geometry: BearingGeometry,
        chord: CoupledLiner | None = None,
        tolerance: float = LINER_TOLERANCE,
    ) -> _Evaluation:
        """The film and the column-model liner solved together by Newton's method on the coupled
        system (:mod:`shaftline.film.elastic`, docs/theory.md "Elastic liner"), from the
        deformation ``deformation`` (m) on the ``rigid`` film (m, which may be negative where
        the journal has passed the rigid bore); a backtracking step keeps the film positive and
        lowers the liner residual. With ``chord``, the Newton matrix of a nearby film (a line-search
        trial's parent), the steps use it while each cuts the residual tenfold (a chord
        iteration: no factorisation), then the film's own, kept likewise for the next steps.
        The layer model (``liner.model == "layer"``) takes the same steps with its own liner
        residual and Newton system (:class:`~shaftline.film.elastic.LayerSystem`)."""
        cache = self._solver_state()
        solver = cache.reynolds
        liner = geometry.liner
        assert liner is not None
        c = self.geometry.radial_clearance
        compliance = liner.compliance
        layer = self._layer() if liner.model == "layer" else None
        surface = geometry.surface
        rough = self._rough_film()
        rigid_nd = rigid / c

        def solve(d_nd: np.ndarray, start_set: np.ndarray | None) -> tuple[_Evaluation, np.ndarray, float]:
            film_nd = rigid_nd + d_nd
            stencil = build_stencil(film_nd, cache.d_theta, cache.d_z, rate, rough)
            solution = solver.solve(stencil, film_nd, self.options.cavitation, start_set)
            relative = np.where(solver.fixed, solver.fixed_pressure, solution.pressure)
            film = film_nd * c
            contact = None if surface is None else asperity_pressure(surface, film)
            load = self._gauge(relative) if contact is None else self._gauge(relative) + contact
            if layer is None:
                residual = d_nd - (compliance / c) * load
            else:
                residual = d_nd - layer.apply(load) / c
            evaluation = _Evaluation(
                position,
                grid,
                film,
                stencil,
                solution,
                relative,
                self._integrate_force(grid, relative, contact=contact),
            )
            evaluation.rate, evaluation.contact, evaluation.deformation = rate, contact, d_nd * c
            return evaluation, residual, float(np.abs(residual).max())

        fixed = solver.fixed
        fixed_load = self._gauge(solver.fixed_pressure)[fixed]

        def settled(d_nd: np.ndarray) -> np.ndarray:
            """``d_nd`` with the column liner's equation solved node by node on the fixed-pressure
            nodes (the bearing's ends, grooves): there ``R = D - (k/c)(p + p_a(c (H_r + D)))``
            depends on the node's own deformation only, so a scalar Newton iteration settles the
            asperity contact's nonlinearity (seed 001's polymer liner at 1 rpm: ~1 MPa at the
            aft end) without film solutions, and the coupled steps are left with the free nodes'.
            (Not on the cavitated nodes: their set is the film's, and a node settled as
            cavitated that the film then pressurises slowed the iteration from far starts.)"""
            if surface is None or layer is not None or not fixed.any():
                return d_nd  # linear there (the Newton step is exact) / the layer couples all nodes
            d = d_nd[fixed]
            rigid_fixed = rigid_nd[fixed]
            limit_nd = self._film_limit() / c
            if float((rigid_fixed + d).min()) * c < self._approach_floor():
                # Below the mean plane (boundary lubrication) the coupled steps alone converge,
                # settled nodes there made the film-liner iteration stall (seed 001's rig, 15 rpm).
                return d_nd
            for _ in range(FIXED_ITERATIONS):
                film = (rigid_fixed + d) * c
                r = d - (compliance / c) * (fixed_load + asperity_pressure(surface, film))
                if np.abs(r).max() <= FIXED_TOLERANCE * tolerance:
                    break
                slope = 1.0 - compliance * asperity_pressure_derivative(surface, film)
                # R is increasing and concave in D (p_a convex and decreasing in h): Newton's
                # iterates approach the root from below after at most one step; the film may
                # close by at most 80 % of itself in a step (fraction to the boundary).
                # (Counted from the lowest film evaluated: 0 smooth, below the mean plane rough.)
                d = d + np.maximum(-r / slope, -0.8 * (rigid_fixed + d - limit_nd))
            out = d_nd.copy()
            out[fixed] = d
            return out

        d_nd = settled(deformation / c)
        evaluation, residual, norm = solve(d_nd, start)
        iterations = 0
        factorised = None  # the last matrix factorised here (at one of this solution's iterates)
        history = [norm]
        while norm > tolerance:
            if iterations >= LINER_ITERATIONS:
                raise LinerConvergenceError(norm, evaluation)
            if iterations >= LINER_STAGNATION and norm > 0.5 * history[-LINER_STAGNATION]:
                # No halving of the residual in that many steps: a trial the film cannot hold (the
                # line search then shortens the step); it would only spend the remaining steps so.
                raise LinerConvergenceError(norm, evaluation)
            iterations += 1
            if chord is None:
                system = factorised = self._liner_system(evaluation)
            else:
                system = chord
            _, step = system.step(residual)
            step = step.reshape(d_nd.shape)
            film_now = rigid_nd + d_nd
            alpha = 1.0
            # Fraction to the boundary: the film may close by at most 80 % of what is left of it
            # above the lowest film evaluated (0 smooth, below the mean plane rough).
            room = film_now - self._film_limit() / c
            closing = np.min(np.where(step < 0.0, -0.8 * room / np.minimum(step, -1e-300), np.inf))
            alpha = min(alpha, float(closing))
            if chord is not None:
                trial = solve(settled(d_nd + alpha * step), evaluation.solution.cavitated)
                if trial[2] > CHORD_REDUCTION * norm:
                    chord = None  # too slow or diverging: the film's own matrix from the next step
                if trial[2] < 0.5 * norm:
                    # Progress all the same: keep the iterate (its film solution is paid for).
                    evaluation, residual, norm = trial
                    assert evaluation.deformation is not None
                    d_nd = evaluation.deformation / c
                history.append(norm)
                continue
            while True:
                trial = solve(settled(d_nd + alpha * step), evaluation.solution.cavitated)
                if trial[2] < (1.0 - 1e-4 * alpha) * norm or alpha < 1e-6:
                    break
                alpha *= 0.5
            if alpha < 1e-6:
                raise LinerConvergenceError(norm, evaluation)
            evaluation, residual, norm = trial
            assert evaluation.deformation is not None
            d_nd = evaluation.deformation / c
            # The next steps keep this factor while it cuts the residual tenfold.
            chord = system
            history.append(norm)
        cache.last_cavitated = evaluation.solution.cavitated
        cache.last_deformation = evaluation.deformation
        evaluation.liner_iterations = iterations
        evaluation.liner_residual = norm
        evaluation.nearby_system = factorised
        return evaluation

    def _liner_tolerance(self, evaluation: _Evaluation, share: float) -> float:
        """Liner tolerance (max |R| over the clearance) that leaves a force error of about
        ``share`` of the force at ``evaluation``'s film: ``share * H_min`` (:data:`INEXACT_LINER`),
        never below 1e-13, the round-off of the residual."""
        hmin = float(evaluation.film.min())
        surface = self.geometry.surface
        if surface is not None:
            # A film at or below the mean plane (boundary lubrication): the force is then the
            # asperities' and the film's on the mean gap, not a share of a vanishing film.
            hmin = max(hmin, LAMBDA_SWITCH * surface.sigma)
        return max(1e-13, share * hmin / self.geometry.radial_clearance)

    def _layer(self) -> ElasticLayer:
        """The layer model's compliance on this bearing's grid (docs/theory.md, "Elastic layer"),
        built once per solver state: the end rows carry half cells."""
        cache = self._solver_state()
        if cache.layer is None:
            liner = self.geometry.liner
            assert liner is not None
            grid = cache.grid
            cache.layer = layer_operator(
                grid.shape,
                self.geometry.radius,
                grid.dz,
                liner.thickness,
                liner.modulus,
                liner.poisson,
                half_end_cells=True,
            )
        return cache.layer

    def _liner_system(self, evaluation: _Evaluation) -> CoupledLiner:
        """The coupled film-liner Newton matrix at ``evaluation``'s film (kept on it)."""
        if evaluation.liner_system is None:
            cache = self._solver_state()
            liner = self.geometry.liner
            assert liner is not None
            c = self.geometry.radial_clearance
            surface = self.geometry.surface
            if liner.model == "layer":
                slope = (
                    np.zeros_like(evaluation.film)
                    if surface is None
                    else asperity_pressure_derivative(surface, evaluation.film)
                )
                evaluation.liner_system = LayerSystem.build(
                    evaluation.stencil,
                    evaluation.film / c,
                    evaluation.relative_pressure,
                    cache.reynolds.fixed | evaluation.solution.cavitated,
                    cache.d_theta,
                    cache.d_z,
                    self._rough_film(),
                    evaluation.rate,
                    self._layer(),
                    slope,
                    self.pressure_scale,
                    c,
                    cache.orderings,
                )
                return evaluation.liner_system
            diagonal = (
                np.ones_like(evaluation.film)
                if surface is None
                else 1.0 - liner.compliance * asperity_pressure_derivative(surface, evaluation.film)
            )
            held = cache.reynolds.fixed | evaluation.solution.cavitated
            evaluation.liner_system = LinerSystem.build(
                evaluation.stencil,
                evaluation.film / c,
                evaluation.relative_pressure,
                held,
                cache.d_theta,
                cache.d_z,
                self._rough_film(),
                evaluation.rate,
                liner.compliance * self.pressure_scale / c,
                diagonal,
                cache.orderings,
            )
        return evaluation.liner_system

    def _rough_film(self) -> FilmFlow | None:
        """The flow factors of the film equation: the roughness's, combined with the turbulence
        coefficients when they apply (:attr:`turbulent`); None for a smooth laminar film."""
        surface = self.geometry.surface
        rough = None
        if surface is not None:
            rough = RoughFilm(surface.sigma / self.geometry.radial_clearance, surface.shear_weight)
        if self.turbulent:
            return TurbulentFilm(self.reynolds_number, self.options.turbulence_model, rough)
        return rough

    @property
    def reynolds_number(self) -> float:
        """Clearance Reynolds number ``Re_c = rho omega R c / mu``; the local one is ``Re_c h / c``."""
        g, op = self.geometry, self.operating
        return clearance_reynolds(op.density, op.speed, g.radius, g.radial_clearance, op.viscosity)

    @property
    def turbulent(self) -> bool:
        """Whether the turbulence coefficients apply (``options.turbulence``: on, or auto with the
        largest local Reynolds number above the Taylor-vortex onset)."""
        g = self.geometry
        return turbulence_active(self.options.turbulence, self.reynolds_number, g.radius, g.radial_clearance)

    def _film_floor(self) -> float:
        """Smallest film the equilibrium may approach, m: ``min_film_floor`` of the clearance
        (smooth), or with rough surfaces the boundary limit ``BOUNDARY_LIMIT * sigma`` (-3 sigma):
        the nominal gap between the mean planes may go negative, the asperities carrying the load
        by Greenwood-Tripp (docs/theory.md, "Boundary lubrication")."""
        surface = self.geometry.surface
        if surface is None:
            return self.options.min_film_floor * self.geometry.radial_clearance
        return BOUNDARY_LIMIT * surface.sigma

    def _approach_floor(self) -> float:
        """The floor a rough film had before it could pass the mean plane, m: ``min_film_floor``
        of the clearance, at most 2 % of sigma (``LAMBDA_SWITCH``). The equilibrium's line search
        approaches it first and passes it only from within twice its film; a liner's deformation
        starts from a film of it. Smooth: the floor itself."""
        floor = self.options.min_film_floor * self.geometry.radial_clearance
        surface = self.geometry.surface
        return floor if surface is None else min(floor, LAMBDA_SWITCH * surface.sigma)

    def _film_limit(self) -> float:
        """Film below which no film is evaluated, m: 0 smooth (the journal cuts the bore), the end
        of the tables of F_n (``TABLE_LOWEST * sigma``, -4 sigma) rough."""
        surface = self.geometry.surface
        return 0.0 if surface is None else TABLE_LOWEST * surface.sigma

    def _at_floor(self, hmin: float) -> bool:
        """Whether a film of ``hmin`` (m) is at the floor: within half the floor above it smooth,
        within :data:`FLOOR_MARGIN` sigma above the boundary limit rough."""
        floor = self._film_floor()
        surface = self.geometry.surface
        if surface is None:
            return hmin <= 1.5 * floor
        return hmin <= floor + FLOOR_MARGIN * surface.sigma

    def _contact_changes(
        self, evaluation: _Evaluation, films: list[np.ndarray], d_pressure: np.ndarray | None = None
    ) -> list[np.ndarray | None]:
        """Asperity pressure changes (Pa) for film changes ``dH`` (of H = h/c); None when smooth.
        With an elastic liner the film also changes by the liner's deformation under the
        pressure changes ``d_pressure`` (k, nz, nt), which must then be given."""
        surface = self.geometry.surface
        if surface is None or evaluation.contact is None:
            return [None] * len(films)
        slope = asperity_pressure_derivative(surface, evaluation.film) * self.geometry.radial_clearance
        system = evaluation.liner_system
        if system is not None:
            # The film with the liner following: dH_r + dD of the linearised liner equation.
            assert d_pressure is not None
            films = [system.film_change(d_film, dp) for d_film, dp in zip(films, d_pressure, strict=True)]
        return [slope * d_film for d_film in films]

    def _evaluate_inside(self, position: JournalPosition, warm: bool, start: np.ndarray | None = None) -> _Evaluation:
        """:meth:`_evaluate`, with a journal cutting the bore reported as bad input."""
        try:
            return self._evaluate(position, warm=warm, start=start)
        except _NegativeFilm as exc:
            raise InputError(
                "position",
                f"e=({position.ey:.4g}, {position.ez:.4g}) m",
                "",
                f"a journal position inside the clearance (film would be {exc.value:.3g} m)",
            ) from None

    def _gauge(self, relative: np.ndarray) -> np.ndarray:
        return relative * self.pressure_scale + self.operating.cavitation_pressure

    def _integrate_force(
        self, grid: Grid, relative: np.ndarray, gauge: bool = True, contact: np.ndarray | None = None
    ) -> np.ndarray:
        """Film force on the journal, N, from dimensionless pressures (a change of them when
        ``gauge`` is False, which leaves out the constant cavitation-pressure offset), with the
        asperity pressure ``contact`` (Pa, or its change) added."""
        pressure = self._gauge(relative) if gauge else relative * self.pressure_scale
        if contact is not None:
            pressure = pressure + contact
        # Per-column sums first (one product with the area weights): the film force is
        # computed at every trial and derivative, and this is its cheapest form.
        per_column = self._solver_state().area_weights[:, 0] @ pressure
        theta = grid.theta
        return np.array([-(per_column @ np.cos(theta)), -self.geometry.rotation * (per_column @ np.sin(theta))])

    def _integrate_moment(
        self, grid: Grid, relative: np.ndarray, gauge: bool = True, contact: np.ndarray | None = None
    ) -> np.ndarray:
        """First moments ``(M_y, M_z) = sum((z - L/2) dF)`` of the film force about the
        mid-plane, N*m, from dimensionless pressures (as :meth:`_integrate_force`)."""
        pressure = self._gauge(relative) if gauge else relative * self.pressure_scale
        if contact is not None:
            pressure = pressure + contact
        arm = grid.z - 0.5 * self.geometry.length
        weighted = pressure * self._solver_state().area_weights * arm[:, None]
        theta = grid.theta
        my = -np.sum(weighted * np.cos(theta)[None, :])
        mz = -self.geometry.rotation * np.sum(weighted * np.sin(theta)[None, :])
        return np.array([my, mz])

    def _force_derivatives(
        self, evaluation: _Evaluation, directions: list[tuple[np.ndarray, np.ndarray | None]]
    ) -> list[np.ndarray]:
        """Film force changes for film changes ``dH`` and film-rate changes, frozen active set.

        Each direction is ``(dH, dRate)`` with ``dH`` the change of H = h/c and
        ``dRate`` the change of ``(2/omega) dH/dt`` per unit of the parameter.
        """
        _, d_pressure = self._pressure_derivatives(evaluation, directions)
        d_contact = self._contact_changes(evaluation, [d_film for d_film, _ in directions], d_pressure)
        return [
            self._integrate_force(evaluation.grid, dp, gauge=False, contact=dc)
            for dp, dc in zip(d_pressure, d_contact, strict=True)
        ]

    def _pressure_derivatives(
        self, evaluation: _Evaluation, directions: list[tuple[np.ndarray, np.ndarray | None]]
    ) -> tuple[np.ndarray, np.ndarray]:
        """Residual and pressure changes, each (k, nz, nt), for the ``directions`` of
        :meth:`_force_derivatives`."""
        cache = self._solver_state()
        solution = evaluation.solution
        c = self.geometry.radial_clearance
        changes = []
        lined = evaluation.deformation is not None
        system = self._liner_system(evaluation) if lined else None
        for d_film, d_rate in directions:
            if system is not None:
                # The asperity load of the rigid film change deforms the liner too: the column
                # model's film changes by dH_r / M before the pressure change's share; the layer
                # model takes that share in its own solve (film/elastic.py, CoupledLiner).
                d_film = system.film_direction(d_film)
            dc_theta, dc_z, d_couette = stencil_derivative(
                evaluation.film / self.geometry.radial_clearance,
                d_film,
                cache.d_theta,
                cache.d_z,
                self._rough_film(),
                evaluation.rate,
            )
            d_residual = apply_operator(dc_theta, dc_z, evaluation.relative_pressure) - d_couette
            if d_rate is not None:
                rough = self._rough_film()
                squeeze = d_rate if rough is None else d_rate * rough.squeeze_factor(evaluation.film / c)
                d_residual = d_residual + cache.d_theta * cache.d_z * squeeze
            if isinstance(solution, JfoSolution):
                # JFO: the voids ride on the Couette flux, whose change moves them too (exact linearisation).
                d_face = cache.d_z * 0.5 * (d_film + np.roll(d_film, -1, axis=1))
                d_residual = d_residual + void_transport(d_face, solution.void)
            changes.append(d_residual)
        d_residual = np.array(changes)
        if system is not None:
            # Elastic liner: the film follows the pressure change (docs/theory.md, "Elastic liner"
            # and "Elastic layer").
            rigid = np.array([np.broadcast_to(d_film, evaluation.film.shape) for d_film, _ in directions])
            d_pressure, _ = system.response(d_residual, rigid)
        elif isinstance(solution, JfoSolution):
            d_pressure = solution.pressure_response(d_residual)
        else:
            d_pressure = cache.reynolds.linear_response(evaluation.stencil, solution, d_residual)
        return d_residual, d_pressure

    def _offset_directions(self, evaluation: _Evaluation) -> tuple[np.ndarray, np.ndarray]:
        """Changes of H = h/c per metre of journal offset ey and ez, shape (nz, nt)."""
        theta = evaluation.grid.theta
        c = self.geometry.radial_clearance
        shape = evaluation.film.shape
        d_ey = np.broadcast_to(-np.cos(theta) / c, shape)
        d_ez = np.broadcast_to(-self.geometry.rotation * np.sin(theta) / c, shape)
        return d_ey, d_ez

    def _position_jacobian(self, evaluation: _Evaluation) -> np.ndarray:
        """d(force)/d(ey, ez), N/m, with the active set frozen (exact for the Reynolds condition)."""
        return self._position_response(evaluation)[0]

    def _position_response(self, evaluation: _Evaluation) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """The Jacobian of :meth:`_position_jacobian` with the residual and pressure changes
        per metre of ey and ez it comes from, each (2, nz, nt): a Newton step's trials predict
        their cavitated sets from these (:meth:`_predicted_cavitation`)."""
        d_ey, d_ez = self._offset_directions(evaluation)
        d_residual, d_pressure = self._pressure_derivatives(evaluation, [(d_ey, None), (d_ez, None)])
        d_contact = self._contact_changes(evaluation, [d_ey, d_ez], d_pressure)
        dfy, dfz = (
            self._integrate_force(evaluation.grid, dp, gauge=False, contact=dc)
            for dp, dc in zip(d_pressure, d_contact, strict=True)
        )
        return np.column_stack([dfy, dfz]), d_residual, d_pressure

    # -- public API ----------------------------------------------------------------------
    def solve_at(self, position: JournalPosition, warm_start: bool = True) -> BearingState:
        """Film solution with the journal held at ``position``.

        ``warm_start`` starts the cavitation active set from the previous solution of this
        bearing in this process (a sweep over nearby positions); otherwise from the nested
        coarse-grid guess. Both settle on the same active set; only ``iterations`` differs.

        Raises
        ------
        InputError
            ``"position"`` when the journal at that position would cut into the bore (h <= 0).
        """
        return self._state(self._evaluate_inside(position, warm=warm_start))

    def linearise(self, position: JournalPosition, initial_cavitated: np.ndarray | None = None) -> FilmLinearisation:
        """Film force at ``position`` and its derivatives by journal offset and velocity.

        Solved from the coarse-grid guess, or from ``initial_cavitated`` (e.g. the
        ``cavitated`` set of the equilibrium state at ``position``, which spares the cold
        start), never from an earlier call, so the result depends only on the problem and
        ``position`` (the solution of the cavitation problem is unique); the four
        derivatives reuse the factorisation of the converged active set (one triangular
        solve each). ``position`` may carry
        velocities ``vy, vz``; the derivatives are taken about them. The stiffness and
        damping of :func:`shaftline.film.dynamics.dynamic_coefficients` are
        ``-offset_derivative`` and ``-velocity_derivative``.

        Parameters
        ----------
        position : JournalPosition
            Journal offsets (m), tilts (rad) and velocities (m/s).
        initial_cavitated : ndarray of bool (nz, nt), optional
            Cavitated set to start the film solution from.

        Returns
        -------
        FilmLinearisation
            Force (N), ``dF/dq`` (N/m) and ``dF/dv`` (N*s/m) with the cavitated set frozen.

        Raises
        ------
        InputError
            ``"position"`` when the journal at that position would cut into the bore (h <= 0).
        """
        evaluation = self._evaluate_inside(position, warm=False, start=self._start_set(initial_cavitated))
        d_ey, d_ez = self._offset_directions(evaluation)
        # A velocity changes the squeeze term (2/omega) dH/dt, not the film itself.
        rate = 2.0 / self.operating.speed
        zero = np.zeros(evaluation.film.shape)
        directions = [(d_ey, None), (d_ez, None), (zero, rate * d_ey), (zero, rate * d_ez)]
        dfy, dfz, dfvy, dfvz = self._force_derivatives(evaluation, directions)
        return FilmLinearisation(
            position=evaluation.position,
            force=evaluation.force,
            offset_derivative=np.column_stack([dfy, dfz]),
            velocity_derivative=np.column_stack([dfvy, dfvz]),
        )

    def linearise_with_tilt(
        self, position: JournalPosition, initial_cavitated: np.ndarray | None = None
    ) -> TiltLinearisation:
        """Film force and moment at ``position`` and their derivatives by journal offset,
        tilt and their rates: the 4 x 4 stiffness and damping (docs/theory.md §7.1).

        Solved as :meth:`linearise` (from the coarse-grid guess or ``initial_cavitated``,
        never from an earlier call); the eight derivatives reuse the factorisation of the
        converged active set, one triangular solve each. A tilt changes the film by
        ``dh = -(z - L/2)(d tilt_y cos(theta) + s d tilt_z sin(theta))``, a tilt rate gives
        that as a squeeze ``dh/dt`` varying along the bearing. The top-left 2 x 2 blocks are
        :meth:`linearise`'s.

        Parameters
        ----------
        position : JournalPosition
            Journal offsets (m), tilts (rad) and velocities (m/s); the tilt rates are zero.
        initial_cavitated : ndarray of bool (nz, nt), optional
            Cavitated set to start the film solution from.

        Returns
        -------
        TiltLinearisation
            Force (N), moment (N*m) and their derivatives with the cavitated set frozen.

        Raises
        ------
        InputError
            ``"position"`` when the journal at that position would cut into the bore (h <= 0).
        """
        evaluation = self._evaluate_inside(position, warm=False, start=self._start_set(initial_cavitated))
        d_ey, d_ez = self._offset_directions(evaluation)
        arm = (evaluation.grid.z - 0.5 * self.geometry.length)[:, None]
        # dH per radian of tilt: the offset direction times the lever arm from the mid-plane.
        shapes = [d_ey, d_ez, arm * d_ey, arm * d_ez]
        rate = 2.0 / self.operating.speed
        zero = np.zeros(evaluation.film.shape)
        directions: list[tuple[np.ndarray, np.ndarray | None]] = [(d, None) for d in shapes]
        directions += [(zero, rate * d) for d in shapes]
        _, d_pressure = self._pressure_derivatives(evaluation, directions)
        d_contact = self._contact_changes(evaluation, [d_film for d_film, _ in directions], d_pressure)
        grid = evaluation.grid
        columns = [
            np.concatenate(
                [
                    self._integrate_force(grid, dp, gauge=False, contact=dc),
                    self._integrate_moment(grid, dp, gauge=False, contact=dc),
                ]
            )
            for dp, dc in zip(d_pressure, d_contact, strict=True)
        ]
        return TiltLinearisation(
            position=evaluation.position,
            force=evaluation.force,
            moment=self._integrate_moment(grid, evaluation.relative_pressure, contact=evaluation.contact),
            offset_derivative=np.column_stack(columns[:4]),
            velocity_derivative=np.column_stack(columns[4:]),
        )

    @property
    def axial_stations(self) -> np.ndarray:
        """Axial grid stations from the aft edge, m (where :meth:`film_load` takes the journal)."""
        return self._solver_state().grid.z.copy()

    def film_load(
        self,
        centre_y: np.ndarray,
        centre_z: np.ndarray,
        directions: np.ndarray | None = None,
        warm_start: bool = True,
        initial_cavitated: np.ndarray | None = None,
        velocity_directions: np.ndarray | None = None,
    ) -> FilmLoad:
        """Film solution and its load along the bearing for a journal centre line of any shape.

        The journal of an elastohydrodynamic alignment (:mod:`shaftline.shaft.coupled`) is the
        shaft's elastic line: its centre is given at every axial grid station, and the film
        returns its force per grid row and, optionally, how those forces change with chosen
        changes of the centre line (the film stiffness of the shaft's degrees of freedom).

        Parameters
        ----------
        centre_y, centre_z : ndarray (nz,)
            Journal centre offsets from the nominal bore axis (the bore of a straight bearing;
            a slope-bored bore is the geometry's) at :attr:`axial_stations`, m. Any bent
            journal of the geometry is replaced by this line.
        directions : ndarray (k, 2, nz), optional
            Changes of ``(centre_y, centre_z)`` per unit of k parameters.
        warm_start : bool
            Start the cavitation set from this bearing's previous solution (nearby shapes).
        initial_cavitated : ndarray of bool (nz, nt), optional
            Start set instead (it wins over ``warm_start``); the result does not depend on it.
        velocity_directions : ndarray (q, 2, nz), optional
            Velocities of the centre line (m/s per unit of q parameters), for damping: the
            journal at this line moving so.

        Returns
        -------
        FilmLoad
            The state at the mid-plane offsets and chord tilt of the line, the force per row
            and its derivatives (cavitated set frozen, exact for the Reynolds condition).

        Raises
        ------
        InputError
            ``"centre_y"`` for a line of the wrong length or one that cuts into the bore.
        """
        z = self.axial_stations
        position, geometry = self._centre_line(centre_y, centre_z)
        start = self._start_set(initial_cavitated)
        try:
            evaluation = self._evaluate(position, warm=warm_start, start=start, geometry=geometry)
        except _NegativeFilm as exc:
            raise InputError(
                "centre_y", f"hmin {exc.value:.3g}", "m", "a journal centre line inside the clearance"
            ) from None
        state = self._state(evaluation)
        row_force = self._row_forces(
            evaluation.grid, evaluation.relative_pressure, gauge=True, contact=evaluation.contact
        )
        theta = evaluation.grid.theta
        c = self.geometry.radial_clearance

        def film_change(lines: np.ndarray) -> np.ndarray:
            """dH (k, nz, nt) of centre-line changes (k, 2, nz), m per unit."""
            steps = np.asarray(lines, dtype=float)
            cos, sin = np.cos(theta)[None, None, :], np.sin(theta)[None, None, :]
            return -(steps[:, 0, :, None] * cos + self.geometry.rotation * steps[:, 1, :, None] * sin) / c

        requests: list[tuple[np.ndarray, np.ndarray | None]] = []
        if directions is not None:
            requests += [(d, None) for d in film_change(directions)]
        moving = 0
        if velocity_directions is not None:
            # A velocity changes the squeeze term (2/omega) dH/dt, not the film (as linearise).
            rate = 2.0 / self.operating.speed
            zero = np.zeros(evaluation.film.shape)
            changes = film_change(velocity_directions)
            requests += [(zero, rate * d) for d in changes]
            moving = len(changes)
        if requests:
            _, d_pressure = self._pressure_derivatives(evaluation, requests)
            d_contact = self._contact_changes(evaluation, [d_film for d_film, _ in requests], d_pressure)
            rows = np.stack(
                [
                    self._row_forces(evaluation.grid, dp, gauge=False, contact=dc)
                    for dp, dc in zip(d_pressure, d_contact, strict=True)
                ],
                axis=-1,
            )
        else:
            rows = np.zeros((2, z.size, 0))
        split = rows.shape[-1] - moving
        return FilmLoad(
            state=state, row_force=row_force, derivative=rows[..., :split], velocity_derivative=rows[..., split:]
        )

    def _centre_line(self, centre_y: np.ndarray, centre_z: np.ndarray) -> tuple[JournalPosition, BearingGeometry]:
        """The mid-plane position and chord tilt of a centre line, and the geometry whose bent
        journal is the rest of it (see :meth:`film_load`)."""
        z = self.axial_stations
        line_y = np.asarray(centre_y, dtype=float)
        line_z = np.asarray(centre_z, dtype=float)
        for name, line in (("centre_y", line_y), ("centre_z", line_z)):
            if line.shape != z.shape or not np.all(np.isfinite(line)):
                raise InputError(name, f"shape {line.shape}", "m", f"{z.size} finite offsets, one per axial station")
        length = self.geometry.length
        mid_y, mid_z = float(np.interp(0.5 * length, z, line_y)), float(np.interp(0.5 * length, z, line_z))
        tilt_y, tilt_z = (line_y[-1] - line_y[0]) / length, (line_z[-1] - line_z[0]) / length
        arm = z - 0.5 * length
        bent = BentJournal(z=z, dy=line_y - mid_y - tilt_y * arm, dz=line_z - mid_z - tilt_z * arm)
        position = JournalPosition(ey=mid_y, ez=mid_z, tilt_y=float(tilt_y), tilt_z=float(tilt_z))
        return position, replace(self.geometry, bent_journal=bent)

    def min_film_of_line(self, centre_y: np.ndarray, centre_z: np.ndarray) -> float:
        """Smallest film for a journal centre line given as in :meth:`film_load`, m (no solve).

        With an elastic liner the film is the rigid gap plus the liner deformation of the last
        solution (the journal may pass the rigid bore into the liner): a prediction for nearby
        lines, as the equilibrium's own line search uses."""
        position, geometry = self._centre_line(centre_y, centre_z)
        film = film_thickness(geometry, self.grid(position), position)
        deformation = self._solver_state().last_deformation
        if geometry.liner is not None and deformation is not None and deformation.shape == film.shape:
            film = film + deformation
        return float(film.min())

    @property
    def film_floor(self) -> float:
        """Smallest film the solver lets a journal approach, m: ``min_film_floor`` of the
        clearance, with rough surfaces the boundary limit ``-3 sigma`` below the mean plane (see
        :meth:`_film_floor`; negative)."""
        return self._film_floor()

    def _row_forces(
        self, grid: Grid, relative: np.ndarray, gauge: bool, contact: np.ndarray | None = None
    ) -> np.ndarray:
        """Film force on the journal per axial grid row, (2, nz), N (sums to :meth:`_integrate_force`)."""
        pressure = self._gauge(relative) if gauge else relative * self.pressure_scale
        if contact is not None:
            pressure = pressure + contact
        weighted = pressure * self._solver_state().area_weights
        theta = grid.theta
        return np.stack([-weighted @ np.cos(theta), -self.geometry.rotation * (weighted @ np.sin(theta))])

    def min_film(self, position: JournalPosition) -> float:
        """Smallest film thickness at ``position``, m (negative when the journal cuts the bore)."""
        return float(self.film(position).min())

    def equilibrium(
        self,
        load_y: float,
        load_z: float = 0.0,
        tilt_y: float = 0.0,
        tilt_z: float = 0.0,
        initial: JournalPosition | None = None,
        progress: Callable[[int, float], None] | None = None,
        initial_cavitated: np.ndarray | None = None,
        initial_deformation: np.ndarray | None = None,
    ) -> Equilibrium:
        """Find the mid-plane journal offsets at which the film carries the applied load.

        Newton's method on ``force(ey, ez) + load = 0`` with the Jacobian from the
        reused factorisation (frozen active set), a fraction-to-boundary rule that keeps
        the film above the floor, and a backtracking line search on the residual.
        The tilts are held fixed (misalignment is an input). Each trial starts its
        cavitated set from the one the step predicts; without ``initial``, a grid of
        :data:`CONTINUATION_NODES` or more starts from the equilibrium on the grid halved
        both ways (docs/theory.md, Sect. 4.1), and a bearing with an elastic liner from the
        rigid bore's equilibrium (its iterations not counted in ``iterations``), solving its
        trials' liners only as far as the force residual needs (docs/theory.md Sect. 17).

        Parameters
        ----------
        load_y, load_z : float
            Load applied to the journal, N (e.g. ``load_y = -W`` for a weight).
        tilt_y, tilt_z : float
            Journal tilt relative to the bore in the vertical and horizontal planes, rad.
        initial : JournalPosition, optional
            Starting position (warm start from a previous equilibrium).
        progress : callable, optional
            Called after each Newton iteration with its number and the force residual
            ``|force + load|`` as a share of the load; on a fine grid an iteration takes
            seconds to minutes. It does not change the result.
        initial_cavitated : ndarray of bool (nz, nt), optional
            Cavitated set to start the first film solution from, e.g. ``state.cavitated`` of
            a neighbouring equilibrium (a sweep); without it the set comes from the coarse
            grids. The solution of the cavitation problem is unique, so this changes the
            active-set iterations, not the result.
        initial_deformation : ndarray (nz, nt), optional
            Liner deformation (m) to start the first film-liner iteration from, e.g.
            ``state.liner_deformation`` of a neighbouring equilibrium (a sweep); without it the
            iteration starts from the undeformed liner. It changes the iterations and the result
            only within the liner's tolerance (a grid that turns with the journal,
            ``film_start = "max_film"``, takes it node by node: a start, not a map). Ignored
            without a liner.

        Raises
        ------
        InputError
            Naming the parameter: ``"load_y"``, ``"load_z"``, ``"tilt_y"`` or ``"tilt_z"``
            for a value that is not finite, ``"load_y"`` for no load at all, the
            larger tilt for a misalignment that does not fit in the clearance, and
            ``"initial_deformation"`` for one that is not finite or not on the grid.
        """
        load_y = require_finite("load_y", load_y, "N")
        load_z = require_finite("load_z", load_z, "N")
        require_finite("tilt_y", tilt_y, "rad")
        require_finite("tilt_z", tilt_z, "rad")
        load = np.array([load_y, load_z])
        magnitude = float(np.hypot(*load))
        if magnitude == 0.0:
            raise InputError("load_y", 0.0, "N", "a non-zero load (load_y, load_z): a loaded bearing")
        deformation = None
        if self.geometry.liner is not None and initial_deformation is not None:
            deformation = np.array(initial_deformation, dtype=float)
            shape = (self.options.axial_nodes, self.options.circumferential_nodes)
            if deformation.shape != shape or not np.all(np.isfinite(deformation)):
                raise InputError(
                    "initial_deformation",
                    f"an array of shape {deformation.shape}",
                    "m",
                    f"finite values on the bearing's grid, shape {shape}",
                )
        found = self._find_equilibrium(load, tilt_y, tilt_z, initial, progress, initial_cavitated, deformation)
        state = self._state(found.evaluation, load=load)
        contact = found.contact
        if found.started and not found.converged and self._at_floor(state.min_film_thickness):
            contact = True
        if contact:
            state = replace(state, contact=True)
        return Equilibrium(state, load_y, load_z, found.converged, contact, found.iterations, found.residual)

    def _find_equilibrium(
        self,
        load: np.ndarray,
        tilt_y: float,
        tilt_z: float,
        initial: JournalPosition | None = None,
        progress: Callable[[int, float], None] | None = None,
        initial_cavitated: np.ndarray | None = None,
        initial_deformation: np.ndarray | None = None,
    ) -> _Found:
        """The iteration of :meth:`equilibrium` (its arguments checked, ``load`` (2,) N) up to its
        last film solution, without the state: the coarse grid's and the rigid bore's equilibria,
        which only start another, need no more (the state's extremes, flows and friction cost a
        film solution's worth on a small grid)."""
        load_y, load_z = float(load[0]), float(load[1])
        magnitude = float(np.hypot(*load))
        c = self.geometry.radial_clearance
        floor = self._film_floor()
        start_pressure = None
        if initial is None:
            coarse = self._coarse_equilibrium(load_y, load_z, tilt_y, tilt_z)
            if coarse is not None:
                initial, start_pressure = coarse
        if initial is None and self.geometry.liner is not None:
            initial = self._rigid_equilibrium(load_y, load_z, tilt_y, tilt_z)
            if initial is not None and self.min_film(initial) < self._approach_floor():
                # A rigid rough bore in boundary lubrication (its film below the mean plane) is no
                # start for the liner (seed 001's rig at 15 rpm: the lined Newton stalls from it at
                # 12 % of the load): the default start instead.
                initial = None
        position = initial or self._initial_position(load, tilt_y, tilt_z)
        position = replace(position, tilt_y=tilt_y, tilt_z=tilt_z, vy=0.0, vz=0.0)
        if self.min_film(position) <= floor:
            position = self._pull_inside(position, floor)
        tolerance = self.options.tolerance * magnitude
        final_share = 0.1 * self.options.tolerance  # force share the converged liner may leave
        # Start the active set from the coarse grid, never from an earlier call: the
        # equilibrium then depends only on the problem and its arguments.
        self._solver_state().last_cavitated = None
        self._solver_state().last_deformation = None
        self._solver_state().orderings.clear()
        start_set = self._start_set(initial_cavitated)
        if start_set is not None:
            start_pressure = None  # the caller's set comes first
        # A smooth rigid bore's Newton iterates far from the equilibrium leave their active sets a
        # few nodes short of settling (docs/theory.md Sect. 4.1): the converged one is settled.
        loose = self._smooth_rigid_active_set()
        # Below this residual an unsettled iterate is settled before its step: its force error
        # (1e-6 to 1e-5 of the load) would steer a step meant to reach the tolerance, and a line
        # search measuring progress against it can reject every step (a start at the root).
        settle_below = (
            REFINE_RESIDUAL if self.options.cavitation == "reynolds" else JFO_UNSETTLED_RESIDUAL
        ) * magnitude
        evaluation, started = self._start_evaluation(
            position, start_set, start_pressure, settle=not loose, deformation=initial_deformation
        )
        residual = evaluation.force + load
        if not started:
            # No position of the retreat settles the film-liner iteration: the start itself,
            # its liner as the iteration left it, reported as not converged.
            return _Found(evaluation, False, False, 0, float(np.hypot(*residual)), started=False)
        contact = False
        iterations = 0
        # A liner carries any load by deforming (the journal may pass the rigid bore surface):
        # the stall rule of a rigid rough bore does not apply to it.
        rough = self.geometry.surface is not None and self.geometry.liner is None
        refinable = self.geometry.liner is None and self.options.cavitation == "reynolds"
        stalled = crawled = 0
        unsettled = False
        while iterations < self.options.max_iterations:
            norm = float(np.hypot(*residual))
            share = final_share if norm <= tolerance else max(final_share, INEXACT_LINER * norm / magnitude)
            required = self._liner_tolerance(evaluation, share)
            if evaluation.liner_residual > required:
                # A liner solved more loosely than this residual needs (a trial's tolerance came
                # from its parent's larger residual): finish it, then look again.
                try:
                    evaluation = self._evaluate(
                        evaluation.position,
                        start=evaluation.solution.cavitated,
                        deformation=evaluation.deformation,
                        chord=evaluation.liner_system or evaluation.nearby_system,
                        liner_tolerance=required,
                    )
                except LinerConvergenceError:
                    # Its liner does not settle that far (seed 001's rig at 15 rpm, aligned, on
                    # 41 x 120 with min_film_floor 1e-4): reported as not converged, the position
                    # and liner as they are, rather than as an exception.
                    unsettled = True
                    break
                residual = evaluation.force + load
                continue
            if not evaluation.solution.settled and norm <= settle_below:
                evaluation = self._settled_set(evaluation)
                residual = evaluation.force + load
                continue
            if norm <= tolerance:
                break
            iterations += 1
            borrowed = evaluation.liner_system is None and norm > NEARBY_JACOBIAN * magnitude
            if borrowed:
                # Far from the equilibrium the Jacobian from the last matrix factorised in this
                # film's liner iteration (at an iterate within its residual) steers as well as the
                # exact one; none factorised there (chord steps only): the exact one.
                evaluation.liner_system = evaluation.nearby_system
            jacobian, d_residual, d_pressure = self._position_response(evaluation)
            accepted = None
            inexact = required
            # Near the equilibrium the step barely changes the film: its trials are iterated from
            # the linear pressure guess with this film's factor (no factorisation, no set sweeps).
            refine = refinable and norm <= REFINE_RESIDUAL * magnitude
            for step, sufficient in self._candidate_steps(jacobian, residual, load, c):
                accepted = self._line_search(
                    evaluation,
                    (d_residual, d_pressure),
                    step,
                    load,
                    norm,
                    floor,
                    sufficient,
                    inexact,
                    refine,
                    loose and norm > settle_below,
                )
                if accepted is not None:
                    break
            if accepted is None:
                hmin = float(evaluation.film.min()) if evaluation.deformation is not None else self.min_film(position)
                contact = self._at_floor(hmin)
                if rough and not contact and self.contact_zone_nodes(evaluation.film) >= SETTLE_ZONE_NODES:
                    evaluation, iterations, contact = self._settle(evaluation, load, tolerance, iterations, progress)
                    residual = evaluation.force + load
                break
            evaluation = accepted
            position = evaluation.position
            residual = evaluation.force + load
            if progress is not None:
                progress(iterations, float(np.hypot(*residual)) / magnitude)
            if rough:
                # A rigid rough bore whose steps only crawl: stop after a few such steps instead of
                # spending max_iterations. It is contact only at the boundary limit, where the
                # asperities at the model's end cannot carry the rest of the load; above it the
                # journal is settled along its net force where the grid resolves the contact zone
                # (:meth:`_settle`), else reported as not converged (docs/theory.md, "Boundary
                # lubrication", "Rigid rough bore at low speed").
                left = float(np.hypot(*residual)) / norm
                stalled = stalled + 1 if left > STALLED_REDUCTION else 0
                # A crawl: steps the line search's residual test cuts short, each leaving most of
                # the residual (the NTUA rigid rough bore at 12.4 rpm: Newton steps cut to 1/16,
                # 1-3 % each, for 45 iterations). Steps cut only by the fraction to the boundary
                # (a film approaching its floor) do not count.
                crawled = crawled + 1 if left > CRAWL_REDUCTION and evaluation.shortened else 0
                if stalled >= STALLED_ITERATIONS or crawled >= CRAWL_ITERATIONS:
                    contact = self._at_floor(self.min_film(position))
                    if not contact and self.contact_zone_nodes(evaluation.film) >= SETTLE_ZONE_NODES:
                        evaluation, iterations, contact = self._settle(
                            evaluation, load, tolerance, iterations, progress
                        )
                        residual = evaluation.force + load
                    break
        if evaluation.liner_system is evaluation.nearby_system:
            evaluation.liner_system = None  # the state's derivatives are the exact ones
        if not evaluation.solution.settled:  # stopped before converging (contact, a stall)
            evaluation = self._settled_set(evaluation)
            residual = evaluation.force + load
        residual_norm = float(np.hypot(*residual))
        converged = residual_norm <= tolerance and not unsettled
        return _Found(evaluation, converged, contact, iterations, residual_norm)

    def _start_evaluation(
        self,
        position: JournalPosition,
        start: np.ndarray | None,
        start_pressure: np.ndarray | None = None,
        settle: bool = True,
        deformation: np.ndarray | None = None,
    ) -> tuple[_Evaluation, bool]:
        """The equilibrium's first film solution, at ``position`` or, where an elastic liner's
        film-liner iteration does not settle there, at the first position of :meth:`_retreat`
        where it does; and whether one settled. None settling: the evaluation the iteration left
        at ``position`` (its liner unsettled) and False.

        A journal started far into a soft liner (a misaligned or bent journal whose closed-form
        start puts its edge below the mean plane: seed 001's rig at 15 and 35 rpm, psi 5e-5 rad)
        can leave the film-liner Newton iteration without a descent; a journal lifted off the
        liner by a few roughness heights settles, and the equilibrium's Newton iteration then
        takes it down to the equilibrium, with its line search rejecting trials that do not
        settle (docs/theory.md, "Starting a lined equilibrium")."""
        try:
            return (
                self._evaluate(
                    position, start=start, start_pressure=start_pressure, settle=settle, deformation=deformation
                ),
                True,
            )
        except LinerConvergenceError as failure:
            first = failure
        for lifted in self._retreat(position):
            try:
                return self._evaluate(lifted, start=start), True
            except LinerConvergenceError:
                continue
        evaluation = first.evaluation
        assert evaluation is not None  # raised by _evaluate_liner, which attaches its iterate
        evaluation.liner_residual = first.residual
        return evaluation, False

    def _retreat(self, position: JournalPosition) -> Iterator[JournalPosition]:
        """Positions on the way from ``position`` to the bore's centre at the mid-plane (tilts
        kept): the offset shortened by ``START_LIFT`` times 1, 2, 4, ... (the rigid film's
        minimum rises by about that much), the centre last."""
        g = self.geometry
        bore_y, bore_z = (float(v[0]) for v in g.bore_centre_line(np.array([0.5 * g.length])))
        dy, dz = position.ey - bore_y, position.ez - bore_z
        offset = float(np.hypot(dy, dz))
        lift = self._start_lift()
        while lift < offset:
            share = 1.0 - lift / offset
            yield replace(position, ey=bore_y + share * dy, ez=bore_z + share * dz)
            lift *= 2.0
        yield replace(position, ey=bore_y, ez=bore_z)

    def _start_lift(self) -> float:
        """The first lift of :meth:`_retreat`, m: the composite roughness sigma (rough), else
        :data:`START_LIFT` of the radial clearance."""
        surface = self.geometry.surface
        return surface.sigma if surface is not None else START_LIFT * self.geometry.radial_clearance

    def _settle(
        self,
        evaluation: _Evaluation,
        load: np.ndarray,
        tolerance: float,
        iterations: int,
        progress: Callable[[int, float], None] | None,
    ) -> tuple[_Evaluation, int, bool]:
        """Pseudo-transient continuation of a rigid rough bore's equilibrium where Newton stalls:
        the journal moves with the net force, ``dx/dt = force + load``, by implicit Euler steps
        ``(I/delta - J) dx = force + load`` whose pseudo-time step ``delta`` grows as the residual
        falls (switched evolution relaxation), so the iteration becomes Newton's near the
        equilibrium (Kelley & Keyes, SIAM J. Numer. Anal. 35 (1998) 508-523). Newton's line search
        asks the residual to fall; the film force of a contact zone one or two cells wide is not
        monotone in the journal's position (it peaks near the mean plane and dips below it), so
        Newton stops at a local minimum of the residual on the wrong side of the peak, where the
        force rises as the journal lifts. The net force there still pushes the journal down, and
        following it passes the peak, as the journal itself would (docs/theory.md, "Boundary
        lubrication", "Settling").

        Returns the last evaluation, the iterations counted on, and whether it ended in contact
        (the film at the boundary limit with the force still pressing it down)."""
        surface = self.geometry.surface
        assert surface is not None
        sigma = surface.sigma
        floor = self._film_floor()
        residual = evaluation.force + load
        norm = float(np.hypot(*residual))
        magnitude = float(np.hypot(*load))
        delta = SETTLE_FIRST_MOVE * sigma / norm
        used = 0
        while used < self.options.max_iterations:
            if norm <= tolerance:
                return evaluation, iterations, False
            jacobian, d_residual, d_pressure = self._position_response(evaluation)
            newton = self._newton_trial(evaluation, jacobian, (d_residual, d_pressure), load, norm)
            if newton is not None:
                # Near the equilibrium a full Newton step that halves the residual is taken: the
                # settling's own steps converge only linearly along the soft (attitude) direction.
                used += 1
                evaluation = newton
                residual = evaluation.force + load
                norm = float(np.hypot(*residual))
                iterations += 1
                if progress is not None:
                    progress(iterations, norm / magnitude)
                continue
            try:
                step = np.linalg.solve(np.eye(2) / delta - jacobian, residual)
            except np.linalg.LinAlgError:
                used += 1
                delta *= 0.25
                continue
            length = float(np.hypot(*step))
            if length > SETTLE_MAX_MOVE * sigma:
                step *= SETTLE_MAX_MOVE * sigma / length
            position = evaluation.position
            hmin_now = self.min_film(position)
            moved = self._moved(position, step)
            hmin_next = self.min_film(moved)
            if hmin_next < floor + FLOOR_MARGIN * sigma:
                if hmin_now <= floor + FLOOR_MARGIN * sigma:
                    return evaluation, iterations, True  # at the limit and pressed further down
                # Stop at the limit: the share of the step that leaves the margin above it.
                share = (hmin_now - floor - FLOOR_MARGIN * sigma) / max(hmin_now - hmin_next, 1e-300)
                step = step * max(min(share, 1.0), 0.0)
                moved = self._moved(position, step)
            used += 1
            try:
                start, guess = self._predicted_cavitation(evaluation, (d_residual, d_pressure), step)
                trial = self._evaluate(moved, start=start, start_pressure=guess)
            except (_NegativeFilm, ReynoldsConvergenceError):
                delta *= 0.25
                continue
            new_residual = trial.force + load
            new_norm = float(np.hypot(*new_residual))
            if new_norm > SETTLE_GROWTH * norm:
                delta *= 0.25  # a step too long for the local force: shorter pseudo-time
                continue
            # Switched evolution relaxation: the pseudo-time step grows as the residual falls.
            # At least doubled after a step that lowers it: a journal sliding slowly along a valley
            # of the residual (its force nearly carrying the load) must not crawl.
            ratio = norm / new_norm if new_norm > 0.0 else 10.0
            delta *= min(max(ratio, 2.0), 10.0) if ratio > 1.0 else max(ratio, 0.1)
            evaluation, residual, norm = trial, new_residual, new_norm
            iterations += 1
            if progress is not None:
                progress(iterations, norm / magnitude)
        return evaluation, iterations, self._at_floor(self.min_film(evaluation.position))

    def contact_zone_nodes(self, film: np.ndarray) -> int:
        """:func:`contact_zone_nodes` of ``film`` (m, on :meth:`grid`) with this bearing's
        composite roughness (0 for smooth surfaces)."""
        surface = self.geometry.surface
        return 0 if surface is None else contact_zone_nodes(film, surface.sigma)

    def _newton_trial(
        self,
        evaluation: _Evaluation,
        jacobian: np.ndarray,
        response: tuple[np.ndarray, np.ndarray],
        load: np.ndarray,
        norm: float,
    ) -> _Evaluation | None:
        """The full Newton step from ``evaluation`` if it stays above the film limit and halves the
        force residual (:meth:`_settle`), else None."""
        residual = evaluation.force + load
        try:
            step = np.linalg.solve(jacobian, -residual)
        except np.linalg.LinAlgError:
            return None
        surface = self.geometry.surface
        assert surface is not None
        if float(np.hypot(*step)) > SETTLE_MAX_MOVE * surface.sigma:
            return None
        moved = self._moved(evaluation.position, step)
        if self.min_film(moved) < self._film_floor():
            return None
        try:
            start, guess = self._predicted_cavitation(evaluation, response, step)
            trial = self._evaluate(moved, start=start, start_pressure=guess)
        except (_NegativeFilm, ReynoldsConvergenceError):
            return None
        return trial if np.hypot(*(trial.force + load)) < 0.5 * norm else None

    # -- helpers -------------------------------------------------------------------------
    def _start_set(self, initial_cavitated: np.ndarray | None) -> np.ndarray | None:
        """A caller's start set for the active set, checked against the grid."""
        if initial_cavitated is None:
            return None
        start = np.asarray(initial_cavitated, dtype=bool)
        shape = self._solver_state().grid.shape
        if start.shape != shape:
            raise InputError(
                "initial_cavitated",
                f"shape {start.shape}",
                "",
                f"the grid's shape {shape} (axial, circumferential nodes)",
            )
        return start

    def _smooth_rigid_active_set(self) -> bool:
        """A smooth rigid bore with an active-set cavitation model (Reynolds condition or JFO): the
        film whose equilibrium continues from 5 000 nodes and leaves its far iterates unsettled."""
        return (
            self.geometry.liner is None
            and self.geometry.surface is None
            and self.options.cavitation in ("reynolds", "jfo")
        )

    def _coarse_equilibrium(
        self, load_y: float, load_z: float, tilt_y: float, tilt_z: float
    ) -> tuple[JournalPosition, np.ndarray] | None:
        """Equilibrium position on the grid halved in both directions (grid continuation) and
        its pressure brought onto this grid (relative, dimensionless: the start of the first
        film solution's active set), or None on a grid below :data:`CONTINUATION_NODES`
        (:data:`CONTINUATION_NODES_OTHER` with a liner or a rough surface) or where it does not
        converge. A smooth rigid bore with the Reynolds condition
        whose coarse equilibrium's line search ends at the film floor (contact) starts from where
        it ended: the fine film is then at or near its floor too, and its own iteration decides
        (NTUA at twice the load and the tilt, 100 x 60: 24 fine iterations crawling from the
        closed-form start to contact, 2 from the coarse end, 121 -> 37 ms).

        Depends only on the problem and the arguments, as the equilibrium does."""
        options = self.options
        shape = coarse_shape((options.axial_nodes, options.circumferential_nodes))
        # The mass-conserving film on a smooth rigid bore continues from the same grids and to the
        # same force tolerance (its fine start then comes from the coarse JFO unknown).
        smooth = self._smooth_rigid_active_set()
        plain = smooth and options.cavitation == "reynolds"
        threshold = CONTINUATION_NODES if smooth else CONTINUATION_NODES_OTHER
        coarse_tolerance = CONTINUATION_TOLERANCE if smooth else OTHER_START_TOLERANCE
        if options.axial_nodes * options.circumferential_nodes < threshold or shape is None:
            return None
        if shape[0] < MIN_AXIAL_NODES or shape[1] < MIN_CIRCUMFERENTIAL_NODES:
            return None  # a grid too coarse to resolve the film is no start (e.g. 200 x 30)
        cache = self._solver_state()
        if cache.coarse_bearing is None:
            coarse_options = replace(
                options,
                axial_nodes=shape[0],
                circumferential_nodes=shape[1],
                tolerance=max(options.tolerance, coarse_tolerance),
            )
            cache.coarse_bearing = JournalBearing(self.geometry, self.operating, coarse_options)
        coarse = cache.coarse_bearing._find_equilibrium(np.array([load_y, load_z]), tilt_y, tilt_z)
        if not ((coarse.converged and not coarse.contact) or (plain and coarse.contact)):
            return None
        relative = coarse.evaluation.relative_pressure
        solution = coarse.evaluation.solution
        if isinstance(solution, JfoSolution):
            relative = np.where(solution.cavitated, -solution.void, relative)  # the JFO unknown
        # Both grids start at the same angle at the same position, so the coarse rows and
        # columns are the fine solver's coarse grid's (CoarseGrid: every other column, rows
        # evenly from edge to edge).
        grid = cache.reynolds.coarse_grid()
        assert grid is not None and grid.solver.shape == relative.shape  # both coarse_shape's
        return coarse.evaluation.position, grid.prolong(relative)

    def _rigid_equilibrium(self, load_y: float, load_z: float, tilt_y: float, tilt_z: float) -> JournalPosition | None:
        """Equilibrium position of the same bearing with a rigid bore (the liner left out), or
        None where it does not converge or ends in contact: the start of a lined equilibrium.

        A rigid film solution costs one factorisation of the film operator, a film-liner one
        several of the coupled matrix; far from the equilibrium, where the journal's steps are
        cut by the fraction-to-the-boundary rule, the rigid bearing takes them at that price
        (NTUA 100 x 60 polymer liner at 1 rpm: 9 lined Newton iterations from the default start,
        6 from the rigid equilibrium). Depends only on the problem and the arguments."""
        cache = self._solver_state()
        if cache.rigid_bearing is None:
            # Its force tolerance is the coarse start's: it only places the start.
            options = replace(self.options, tolerance=max(self.options.tolerance, OTHER_START_TOLERANCE))
            cache.rigid_bearing = JournalBearing(replace(self.geometry, liner=None), self.operating, options)
        try:
            rigid = cache.rigid_bearing._find_equilibrium(np.array([load_y, load_z]), tilt_y, tilt_z)
        except SolverFailure:
            return None
        if not rigid.converged or rigid.contact:
            return None
        return rigid.evaluation.position

    def _moved(self, position: JournalPosition, step: np.ndarray) -> JournalPosition:
        return replace(position, ey=position.ey + float(step[0]), ez=position.ez + float(step[1]))

    def _candidate_steps(
        self, jacobian: np.ndarray, residual: np.ndarray, load: np.ndarray, c: float
    ) -> Iterator[tuple[np.ndarray, float]]:
        """Newton step first; then the damped fallbacks: steepest descent of |r|^2/2 and a push
        along the load (which walks a load that is too large down to the film floor)."""
        try:
            yield self._limit_step(np.linalg.solve(jacobian, -residual), c), 1e-4
        except np.linalg.LinAlgError:
            pass
        gradient = -jacobian.T @ residual
        if np.any(gradient):
            yield 0.1 * c * gradient / float(np.hypot(*gradient)), 0.0
        yield 0.1 * c * load / float(np.hypot(*load)), 0.0

    def _line_search(
        self,
        evaluation: _Evaluation,
        response: tuple[np.ndarray, np.ndarray],
        step: np.ndarray,
        load: np.ndarray,
        norm: float,
        floor: float,
        sufficient: float,
        liner_tolerance: float = LINER_TOLERANCE,
        refine: bool = False,
        loose: bool = False,
    ) -> _Evaluation | None:
        """Backtracking that keeps the film above the floor and lowers the force residual
        (by the Armijo share ``sufficient * alpha`` for a Newton step, at all for a fallback).

        Each trial starts its active set from the one predicted by the step from the
        evaluation's ``response`` (the residual and pressure changes per metre of ey and ez of
        :meth:`_position_response`; see :meth:`_predicted_cavitation`); with ``refine`` each
        trial starts from the evaluation's set and iterates its pressure from that guess
        (:meth:`_evaluate`), otherwise with ``loose`` its set may stop short of settling."""
        position = evaluation.position
        lined = evaluation.deformation is not None
        hmin_now = float(evaluation.film.min())  # rigid: the film at ``position``; lined: with its liner
        alpha = 1.0
        approach = self._approach_floor()
        if approach > floor and hmin_now > 2.0 * approach:
            # A rough film approaches the mean plane as it did when that was its floor, and passes
            # it only from there: a long step through it from a thick film lands in the contact
            # zone's one-node pressure spikes and ends in a spurious equilibrium (docs/theory.md,
            # "Boundary lubrication").
            floor = approach
        # Fraction to the boundary: never close more than 80 % of the film left above the floor
        # (with a liner the film predicted with its deformation).
        while alpha > 1e-8:
            moved = self._moved(position, alpha * step)
            if lined:
                predicted = self._predicted_deformation(evaluation, response, alpha * step)
                hmin_next = float((self.film(moved) + predicted).min())
            else:
                hmin_next = self.min_film(moved)
            if hmin_next - floor >= 0.2 * (hmin_now - floor):
                break
            alpha *= 0.5
        boundary = alpha  # the step the fraction to the boundary allows
        while alpha > 1e-8:
            try:
                start, guess = self._predicted_cavitation(evaluation, response, alpha * step)
                if refine and guess is not None:
                    trial = self._evaluate(
                        self._moved(position, alpha * step), start=evaluation.solution.cavitated, refine_from=guess
                    )
                else:
                    trial = self._evaluate(
                        self._moved(position, alpha * step),
                        start=start,
                        start_pressure=guess,
                        deformation=self._predicted_deformation(evaluation, response, alpha * step),
                        chord=evaluation.liner_system,
                        liner_tolerance=liner_tolerance,
                        settle=not loose,
                    )
            except (_NegativeFilm, LinerConvergenceError):
                alpha *= 0.5
                continue
            except ReynoldsConvergenceError:
                if self.geometry.surface is None:
                    raise
                # A rough trial far past the mean plane: the closing mean gap's pressure spike
                # can keep the active set from settling; a shorter step (docs/theory.md,
                # "Boundary lubrication").
                alpha *= 0.5
                continue
            if np.hypot(*(trial.force + load)) < (1.0 - sufficient * alpha) * norm:
                trial.shortened = alpha < boundary
                return trial
            alpha *= 0.5
        return None

    def _predicted_cavitation(
        self, evaluation: _Evaluation, response: tuple[np.ndarray, np.ndarray], step: np.ndarray
    ) -> tuple[np.ndarray | None, np.ndarray | None]:
        """Start of the active set after the journal moves by ``step`` (m): a set, or a
        pressure guess from which the solver predicts it.

        The film is linear in the offsets, so the pressure change ``dP`` with the set frozen
        is that per metre of ey and ez (``response``, from the Jacobian's own solves) combined
        by the step: ``P + dP`` is the guess for the Reynolds condition, whose solver sharpens
        the set it implies with a few projected over-relaxation sweeps on the new film
        (:meth:`~shaftline.film.reynolds.ReynoldsSolver.predicted_set`). (None, None) for the
        half-Sommerfeld model, which has no active set, and for the mass-conserving model,
        whose own solver predicts the set of a warm start (a chord step of its last factor,
        :func:`shaftline.film.jfo.solve_jfo`).
        """
        if self.options.cavitation in ("half_sommerfeld", "jfo"):
            return None, None
        d_pressure = np.tensordot(step, response[1], axes=1)
        return None, evaluation.relative_pressure + d_pressure

    def _predicted_deformation(
        self, evaluation: _Evaluation, response: tuple[np.ndarray, np.ndarray], step: np.ndarray
    ) -> np.ndarray | None:
        """Liner deformation (m) after the journal moves by ``step`` (m), to first order: the
        start of the trial's film-liner Newton iteration (None without a liner)."""
        system = evaluation.liner_system
        if evaluation.deformation is None or system is None:
            return evaluation.deformation
        d_pressure = np.tensordot(step, response[1], axes=1)
        d_ey, d_ez = self._offset_directions(evaluation)
        rigid = step[0] * d_ey + step[1] * d_ez
        # The linearised liner equation's dD (film/elastic.py, CoupledLiner.deformation_change).
        change = system.deformation_change(np.broadcast_to(rigid, d_pressure.shape), d_pressure)
        return evaluation.deformation + self.geometry.radial_clearance * change

    def _limit_step(self, step: np.ndarray, c: float) -> np.ndarray:
        length = float(np.hypot(*step))
        limit = 0.5 * c
        return step if length <= limit else step * (limit / length)

    def _pull_inside(self, position: JournalPosition, floor: float) -> JournalPosition:
        for _ in range(200):
            if self.min_film(position) > 2.0 * max(floor, 0.0) + 0.05 * self.geometry.radial_clearance:
                return position
            position = replace(position, ey=0.8 * position.ey, ez=0.8 * position.ez)
        # Both tilts together do not fit; name the larger, which is the one to reduce first.
        name = "tilt_y" if abs(position.tilt_y) >= abs(position.tilt_z) else "tilt_z"
        raise InputError(
            name,
            getattr(position, name),
            "rad",
            "a misalignment that fits in the clearance with the journal centred "
            f"(tilt_y, tilt_z = {position.tilt_y:.4g}, {position.tilt_z:.4g} rad)",
        )

    def _initial_position(self, load: np.ndarray, tilt_y: float, tilt_z: float) -> JournalPosition:
        g = self.geometry
        ey, ez = closed_form_offsets(g, self.operating, float(load[0]), float(load[1]), max_eccentricity=0.95)
        bore_y, bore_z = g.bore_centre_line(np.array([0.5 * g.length]))
        return JournalPosition(ey=ey + float(bore_y[0]), ez=ez + float(bore_z[0]), tilt_y=tilt_y, tilt_z=tilt_z)

    def _state(self, evaluation: _Evaluation, load: np.ndarray | None = None) -> BearingState:
        g = self.geometry
        op = self.operating
        grid = evaluation.grid
        theta, z = grid.theta.copy(), grid.z.copy()  # the state's own (the grid's are shared, read-only)
        film = evaluation.film
        pressure = self._gauge(evaluation.relative_pressure)
        fraction = evaluation.solution.film_fraction
        weights = self._solver_state().area_weights
        fy, fz = (float(v) for v in evaluation.force)
        capacity = float(np.hypot(fy, fz))
        e, angle = self._local_polar(evaluation.position)
        # Load line = opposite to the film force (what the film carries).
        if load is None:
            load_angle = float(np.arctan2(-g.rotation * fz, -fy))
        else:
            load_angle = float(np.arctan2(g.rotation * load[1], load[0]))
        attitude = float((angle - load_angle + np.pi) % (2 * np.pi) - np.pi) if e > 0 else 0.0
        # Extremes between nodes (docs/theory.md): the film is smooth everywhere; the pressure
        # only on free nodes (fixed-pressure and cavitated values are not samples of it).
        thinnest = local_extreme(film)
        free = ~(self._solver_state().reynolds.fixed | evaluation.solution.cavitated)
        peak = local_extreme(pressure, usable=free, maximum=True)
        arm = z - 0.5 * g.length
        contact = evaluation.contact
        carried = pressure if contact is None else pressure + contact
        dfy = -carried * weights * np.cos(theta)[None, :]
        dfz = -g.rotation * carried * weights * np.sin(theta)[None, :]
        moment_y = float(np.sum(dfy * arm[:, None]))
        moment_z = float(np.sum(dfz * arm[:, None]))
        offset = (moment_y * fy + moment_z * fz) / capacity**2 if capacity > 0 else 0.0
        # Friction on the journal: Couette shear on the liquid share plus the Poiseuille part.
        speed = op.speed * g.radius
        dp_dx = (np.roll(pressure, -1, axis=1) - np.roll(pressure, 1, axis=1)) / (2.0 * grid.d_theta * g.radius)
        shearing = fraction if self.options.cavitated_shear == "film_fraction" else np.ones_like(fraction)
        surface = g.surface
        turbulent = self.turbulent
        # Re_h on the nominal film, 0 where a rough film is past the mean plane (h <= 0): the
        # coefficients of the film equation take Re_h = Re_c max(H, 0) there (turbulence.py), and
        # a film a fraction of sigma thin is laminar on any gap (on the mean gap h_T <= 0.4 sigma,
        # Re_h <= 6 on seed 001's rig at 350 rpm, against the Taylor onset 708).
        local_reynolds = self.reynolds_number * np.maximum(film, 0.0) / g.radial_clearance
        # Turbulent films: the Couette shear times C_f(Re_h); the Poiseuille part as laminar
        # (the linearised theory, docs/theory.md Sect. 17 "Turbulent films").
        couette = couette_shear_factor(local_reynolds) if turbulent else 1.0
        if surface is None:
            shear = op.viscosity * speed * shearing * couette / film + 0.5 * film * dp_dx
            friction = float(np.sum(shear * weights))
            fluid_friction, boundary_friction = friction, 0.0
        else:
            # Couette shear over the mean gap h_T (finite as h -> 0), the Poiseuille part over h_T
            # too (the nominal h is negative past the mean plane and would turn its sign);
            # boundary friction on the asperity pressure (docs/theory.md, "Mixed lubrication").
            lam = film / surface.sigma
            gap = surface.sigma * mean_gap(lam)
            shear = op.viscosity * speed * shearing * couette / gap + 0.5 * gap * dp_dx
            fluid_friction = float(np.sum(shear * weights))
            assert contact is not None
            boundary_friction = float(np.sum(surface.boundary_friction * contact * weights))
            friction = fluid_friction + boundary_friction
        torque = friction * g.radius
        # Flows from the discrete face fluxes (consistent with the solver's mass balance).
        stencil = evaluation.stencil
        rel = evaluation.relative_pressure
        # Couette transport carries the liquid share of the upwind node. The half cells between
        # the edge rows and the first interior faces carry half the transport of their interior
        # row; what they gain in the full film leaves through the edge. Fixed-pressure nodes
        # (supply lines) are sources, not leakage, so their half cells are left out.
        transport = stencil.couette_face * fraction
        theta_flux = transport - stencil.c_theta * (np.roll(rel, -1, axis=1) - rel)
        edge_transport = 0.5 * np.vstack([transport[1], transport[-2]])
        circumferential = self.flow_scale * (theta_flux[1:-1].sum(axis=0) + edge_transport.sum(axis=0))
        solver_fixed = self._solver_state().reynolds.fixed
        half_cells = np.roll(edge_transport, 1, axis=1) - edge_transport
        half_cells[:, solver_fixed[1] | solver_fixed[-2]] = 0.0
        aft = stencil.c_z[0] * (rel[1] - rel[0])
        fore = stencil.c_z[-1] * (rel[-2] - rel[-1])
        edge = self.flow_scale * (np.vstack([aft, fore]) + half_cells)
        side_leakage = float(edge.sum())
        inlet = self._inlet_flow(evaluation, theta_flux, circumferential)
        mean_pressure = capacity / (g.length * g.diameter)
        sommerfeld = (
            (g.radius / g.radial_clearance) ** 2 * op.viscosity * (op.speed / (2 * np.pi)) / mean_pressure
            if mean_pressure > 0
            else math.inf
        )
        hmin = float(thinnest.value)
        rough: dict[str, Any] = {}
        if surface is not None and contact is not None:
            ay = -float(np.sum(contact * weights * np.cos(theta)[None, :]))
            az = -g.rotation * float(np.sum(contact * weights * np.sin(theta)[None, :]))
            lam_min = hmin / surface.sigma
            rough = {
                "asperity_pressure": contact,
                "asperity_load": float(np.hypot(ay, az)),
                "asperity_load_share": (ay * fy + az * fz) / capacity**2 if capacity > 0 else 0.0,
                "max_asperity_pressure": float(contact.max()),
                "contact_area_ratio": float(
                    np.sum(contact_area_ratio(surface, film) * weights) / (2.0 * math.pi * g.radius * g.length)
                ),
                "film_ratio": film / surface.sigma,
                "min_film_ratio": lam_min,
                "lubrication_regime": lubrication_regime(lam_min),
            }
        if evaluation.deformation is not None:
            rough["liner_deformation"] = evaluation.deformation
            rough["max_liner_deformation"] = float(evaluation.deformation.max())
            rough["liner_iterations"] = evaluation.liner_iterations
        if self.options.turbulence != "off":
            rough["reynolds_number"] = local_reynolds
            rough["max_reynolds_number"] = float(local_reynolds.max())
            rough["turbulent"] = turbulent
        return BearingState(
            position=evaluation.position,
            eccentricity_ratio=e / g.radial_clearance,
            position_angle=angle,
            theta=theta,
            z=z,
            film=film,
            pressure=pressure,
            film_fraction=fraction,
            force_y=fy,
            force_z=fz,
            load_capacity=capacity,
            attitude_angle=attitude,
            min_film_thickness=hmin,
            min_film_theta=float((theta[0] + thinnest.column * grid.d_theta) % (2 * np.pi)),
            min_film_z=float(thinnest.row * grid.dz),
            max_pressure=float(peak.value),
            max_pressure_theta=float((theta[0] + peak.column * grid.d_theta) % (2 * np.pi)),
            max_pressure_z=float(peak.row * grid.dz),
            mean_pressure=mean_pressure,
            moment_y=moment_y,
            moment_z=moment_z,
            load_centre_offset=float(offset),
            friction_force=friction,
            friction_torque=torque,
            friction_coefficient=friction / capacity if capacity > 0 else math.inf,
            power_loss=torque * op.speed,
            inlet_flow=inlet,
            side_leakage=side_leakage,
            circumferential_flow=circumferential,
            edge_leakage=edge,
            sommerfeld_number=sommerfeld,
            contact=bool(hmin <= self._film_floor()),
            cavitation=self.options.cavitation,
            cavitated=evaluation.solution.cavitated,
            iterations=evaluation.solution.iterations,
            fluid_friction_force=fluid_friction,
            boundary_friction_force=boundary_friction,
            **rough,
        )

    def _inlet_flow(self, evaluation: _Evaluation, theta_flux: np.ndarray, circumferential: np.ndarray) -> float:
        if self.operating.grooves:
            # Net outflow of the groove nodes into the film, with the Couette inflow from a
            # cavitated upstream zone carrying only its liquid share.
            groove = self._solver_state().reynolds.fixed.copy()
            groove[[0, -1]] = False
            rel = evaluation.relative_pressure
            stencil = evaluation.stencil
            net = theta_flux - np.roll(theta_flux, 1, axis=1)
            flow_north = stencil.c_z * (rel[:-1] - rel[1:])
            net[:-1] += flow_north
            net[1:] -= flow_north
            return float(self.flow_scale * net[groove].sum())
        # Without a groove: the flow entering the converging film across the line of
        # maximum film thickness at mid-plane (Raimondi & Boyd's Q).
        mid = evaluation.film.shape[0] // 2
        column = int(np.argmax(evaluation.film[mid]))
        return float(circumferential[column])


def closed_form_offsets(
    geometry: BearingGeometry, operating: OperatingPoint, load_y: float, load_z: float, max_eccentricity: float = 1.0
) -> tuple[float, float]:
    """Journal offsets (ey, ez) from the bore centre that carry the load by the closed-form
    finite-bearing estimate (:func:`shaftline.film.analytic.eccentricity_guess`), m.

    The cold start of :meth:`JournalBearing.equilibrium` (with the eccentricity ratio capped
    at ``max_eccentricity``) and, uncapped and so smooth in the load, the part of a swept
    position that :func:`shaftline.film.sweep` does not extrapolate. The load must not be zero.
    """
    g = geometry
    mean_pressure = math.hypot(load_y, load_z) / (g.length * g.diameter)
    sommerfeld = (g.radius / g.radial_clearance) ** 2 * operating.viscosity * (operating.speed / (2 * math.pi))
    epsilon, attitude = eccentricity_guess(sommerfeld / mean_pressure, g.length / g.diameter)
    epsilon = min(epsilon, max_eccentricity)
    load_angle = math.atan2(g.rotation * load_z, load_y)
    local = JournalPosition.from_polar(epsilon * g.radial_clearance, load_angle + attitude, g.rotation)
    return local.ey, local.ez


def contact_zone_nodes(film: np.ndarray, sigma: float) -> int:
    """Circumferential nodes of the row of the thinnest film whose film is within one composite
    roughness ``sigma`` (m) of that row's minimum: how many nodes resolve a rough contact zone.
    ``film`` in m, shape (nz, nt).

    Near its minimum a journal's film is ``h_min + c eps theta^2 / 2``, so the zone is
    ``2 sqrt(2 sigma / (c eps))`` wide: 10 degrees on seed 001's rig (3.4 nodes on its 3 degree
    grid, 14 on a 0.75 degree one). Below :data:`SETTLE_ZONE_NODES` the discrete film force of a
    rigid rough bore jumps as the minimum moves between nodes (docs/theory.md, "Rigid rough bore
    at low speed")."""
    row = film[int(np.argmin(film.min(axis=1)))]
    return int(np.count_nonzero(row <= row.min() + sigma))


def nodes_to_resolve_contact_zone(film: np.ndarray, sigma: float) -> int:
    """Circumferential nodes (even) that would put :data:`SETTLE_ZONE_NODES` nodes across the
    contact zone of ``film`` (m, shape (nz, nt), on a grid of nt nodes round the bore): the zone
    keeps its width in angle as the grid is refined. The count of nodes inside a zone is up to
    one more than its width in cells, so the width is taken as one node less (seed 001's rig:
    4 nodes on 120, 400 asked; 3.4 cells wide, so 11 nodes there)."""
    nt = film.shape[1]
    zone = max(contact_zone_nodes(film, sigma) - 1, 1)
    needed = math.ceil(nt * SETTLE_ZONE_NODES / zone)
    return needed + needed % 2


class _NegativeFilm(Exception):
    def __init__(self, value: float) -> None:
        super().__init__(value)
        self.value = value
