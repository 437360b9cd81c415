"""Tuning of the film solver's steps: the numerical options beside :class:`SolverOptions`.

Each dataclass holds the settings of one step of the solution, with the defaults they were
tuned to and the measurements behind them (docs/theory.md Sect. 4.1 and 17 derive the
steps). They are part of :class:`~shaftline.film.problem.SolverOptions` (``options.newton``,
``options.active_set``, ...), so a problem carries them to every worker and results depend
on nothing else; a study changes one by ``dataclasses.replace``. None of them changes the
solution a converged equilibrium reaches beyond its tolerances: they set how it gets there.

Errors name the field relative to the dataclass (``"crawl_iterations"``), as every domain
object's do.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, fields

from shaftline.errors import InputError

__all__ = [
    "ActiveSetOptions",
    "ContinuationOptions",
    "JfoOptions",
    "LinerOptions",
    "NewtonOptions",
    "SettleOptions",
]


def _check(
    options: object, shares: tuple[str, ...] = (), counts: tuple[str, ...] = (), whole: tuple[str, ...] = ()
) -> None:
    """Refuse a value that is not a finite number > 0 (``shares``: in (0, 1)); ``counts`` must be
    integers >= 1 and ``whole`` integers >= 0 (a count that may be none)."""
    for item in fields(options):  # type: ignore[arg-type]
        value = getattr(options, item.name)
        if item.name in counts or item.name in whole:
            least = 1 if item.name in counts else 0
            if isinstance(value, bool) or not isinstance(value, int) or value < least:
                raise InputError(item.name, value, "", f"an integer >= {least}")
            continue
        if isinstance(value, bool) or not isinstance(value, int | float) or not math.isfinite(value) or value <= 0:
            raise InputError(item.name, value, "", "a finite number > 0")
        if item.name in shares and not value < 1.0:
            raise InputError(item.name, value, "", "in (0, 1)")


@dataclass(frozen=True)
class ActiveSetOptions:
    """The Reynolds condition's primal-dual active set and the prediction of its set
    (docs/theory.md Sect. 4.1).

    Attributes
    ----------
    max_iterations : int
        Active-set iterations allowed before the solver gives up (never reached on the
        M-matrices of the film; a guard). The mass-conserving model takes it too.
    node_set_margin : int
        Cells added around the free nodes, in each direction, when a kept factor's node set is
        chosen: the cavitation boundary of the next trial sets, Newton steps and nearby films
        moves by a few cells, and every set inside the node set reuses its ordering and
        symbolic analysis.
    node_set_slack : float
        A kept node set is chosen again when it holds more than this many times the free
        nodes: its factor then costs noticeably more than a factor of the free nodes alone.
    switch_max_nodes : int
        Active sets that differ from the kept factor's, on the same film, in at most this many
        nodes are solved with the factor and a bordered correction: its k triangular solves
        (0.12 ms each on 100 x 60, against 1.0-1.3 ms for the numeric factorisation; 0.6
        against 8 ms on 200 x 120) cost less than a factorisation up to about ten nodes. Nine
        NTUA equilibria (three loads, three tilts) on 200 x 120: 27 fine factorisations with 3,
        20 with 8; unchanged on 100 x 60 and 400 x 240. 0 factorises every set.
    unsettled_max_nodes : int
        A solution asked for without settling (a Newton iterate far from its root) stops at
        the first trial set that leaves at most this many nodes on the wrong side of the
        complementarity conditions: the pressure of that set, clipped at zero (the switch that
        settles it later costs one triangular solve a node). 0 settles every iterate. The
        mass-conserving model takes it too.
    pcg_min_nodes : int
        Grids below this many nodes factorise every trial set: there a conjugate-gradient
        iteration, its array work in numpy included, costs a tenth of a factorisation or more
        (0.25 ms against 1-3 ms on 100 x 60), and a trial set needs 10-25 of them. Coarse
        grids below it factorise the full pattern with the held rows zeroed (one symbolic
        analysis for every set).
    pcg_max_iterations : int
        Conjugate-gradient solves of the trial active sets, preconditioned by the factor of a
        nearby set, are given up for a factorisation after this many iterations (a few dozen
        triangular solves cost about one factorisation).
    pcg_tolerance : float
        ... and converged when the energy-norm error is below this share of the solution's
        (the trial sets need only the signs; the settled set is solved again with its own
        factor).
    refine_tolerance : float
        Energy-norm share to which a refined solution (a Newton trial iterated from its linear
        guess) is iterated: near the rounding of a direct solve (its pressures agree with the
        factor's to about 1e-12 of the peak), so that it stands for that set's solution.
    nested_swing : float
        Share of the nodes that a Newton trial's linear pressure guess may take below zero and
        still start from its own swept set; beyond it the coarse grids predict the set. Over
        27 test equilibria (grids 60 x 36 to 200 x 120, three tilts and loads) 2 % took the
        fine active-set iterations from 308 to 279.
    prediction_sweeps, prediction_omega : int, float
        Red-black projected SOR sweeps and their over-relaxation factor that sharpen a set
        interpolated from a coarser grid (or extrapolated by a Newton step) on the grid being
        solved. On the NTUA case (100 x 60) the set interpolated from 50 x 30 is 50 nodes off
        the final one; ten sweeps leave 0-2 at 1.5-1.8 (9, 3 and 8 after six). Over 27
        equilibria (grids 60 x 36, 100 x 60, 200 x 120; three tilts, three loads) the fine-grid
        active-set iterations fell from 467 without sweeps to about 300 with ten.
    cascade_sweeps, cascade_omega : int, float
        Projected SOR sweeps and over-relaxation factor of each small coarse grid that predicts
        the cavitated set by sweeps alone, from the coarsest up. The sweeps run to the count
        (no early stop: the pressure, not only its set, starts the next grid). NTUA 100 x 60
        cold solution, 25 x 15 and 50 x 30 below it: 30 sweeps at 1.85 start the fine set 2
        nodes off, as the coarse active sets did; at 1.7 it starts 4 off.
    cascade_coarsest_span : int
        The coarsest grid starts the sweeps from zero only up to this many nodes in either
        direction; a longer one (the halving stops at an odd column count or below 9 axial
        nodes: 200 x 122 stops at 100 x 61, 16 x 250 at 8 x 125) solves its own active set
        instead, as the sweeps carry the boundary only some tens of cells. Sweeps from zero
        there left the 200 x 122 fine set up to 2201 nodes off (14-17 fine active-set
        iterations instead of 3-4), 16 x 250 took 65 fine iterations instead of 10 (four
        positions), and on 31 x 1202 the active set did not settle.
    """

    max_iterations: int = 200
    node_set_margin: int = 3
    node_set_slack: float = 1.35
    switch_max_nodes: int = 8
    unsettled_max_nodes: int = 3
    pcg_min_nodes: int = 10_000
    pcg_max_iterations: int = 30
    pcg_tolerance: float = 1e-9
    refine_tolerance: float = 1e-13
    nested_swing: float = 0.02
    prediction_sweeps: int = 10
    prediction_omega: float = 1.7
    cascade_sweeps: int = 30
    cascade_omega: float = 1.85
    cascade_coarsest_span: int = 40

    def __post_init__(self) -> None:
        _check(
            self,
            shares=("pcg_tolerance", "refine_tolerance", "nested_swing"),
            counts=("max_iterations", "pcg_max_iterations", "cascade_coarsest_span"),
            whole=(
                "node_set_margin",
                "switch_max_nodes",
                "unsettled_max_nodes",
                "pcg_min_nodes",
                "prediction_sweeps",
                "cascade_sweeps",
            ),
        )
        for name in ("prediction_omega", "cascade_omega"):
            if not 0.0 < getattr(self, name) < 2.0:
                raise InputError(name, getattr(self, name), "", "in (0, 2), an over-relaxation factor")


@dataclass(frozen=True)
class JfoOptions:
    """The mass-conserving (JFO) model's semi-smooth Newton iteration (docs/theory.md Sect. 4).

    Attributes
    ----------
    switch_tolerance : float
        Relative tolerance of the set switches: a node enters the cavitated set when its
        pressure is below ``-switch_tolerance * max|P|`` and leaves it when its void fraction
        is below ``-switch_tolerance`` (round-off of the linear solve, not a modelling
        tolerance).
    prediction_sweeps : int
        Red-black nonlinear Gauss-Seidel sweeps that sharpen a set interpolated from a coarser
        grid. On the NTUA case (100 x 60) the set prolonged from the 50 x 30 equilibrium is 126
        nodes off the final one, mostly along the reformation boundary where it runs obliquely
        near the edges; one sweep leaves 33, two 20, five 12.
    ordering_set_change : float
        A kept elimination order serves a later set of its grid that differs from the set it
        was found for in at most this share of that set's boundary nodes; a set further off is
        ordered afresh (and its order kept). The sets of one equilibrium differ along their
        boundaries, by 13 and 26 nodes on the NTUA case (100 x 60 and 200 x 120, boundaries of
        226 and 456 nodes), and an order kept across its six sets factorises each in 2.2-3.1 ms
        against 3.1-3.3 ms ordered afresh (the minimum-degree ordering costs a third of a
        factorisation). A zone moved round the bore (another load direction) is another graph:
        kept there, the order gave 10-23 times a fresh order's fill and 20-40 times its time
        (81 x 240, 161 x 240), and sets 1.7-2 % of the nodes off still 1.5-2.3 times. With this
        share, 20 equilibria over load directions and magnitudes (81 x 120, 161 x 240) keep
        every fine factor within 1.06 times a fresh order's fill, warm starts across 90 degrees
        (81 x 240) within 1.18 times.
    ordering_fill_growth : float
        ... and while its factors hold at most this many times the entries of that set's
        factor: the factor past it is used, and the next set ordered afresh.
    unsettled_residual : float
        Force residual (share of the load) above which a Newton iterate of the equilibrium may
        leave its active set a few nodes short of settling (each set costs an LU factorisation
        here). Such an iterate's force is off by about 1e-5 of the load, which stalls Newton's
        quadratic steps below about 1e-3 (NTUA 100 x 60: 1.1e-3 -> 1.5e-5 -> 2.8e-6 with loose
        trials throughout): below it the trials settle, and so does an unsettled iterate before
        its step. The Reynolds condition's is :attr:`NewtonOptions.refine_residual`.
    """

    switch_tolerance: float = 1e-12
    prediction_sweeps: int = 5
    ordering_set_change: float = 0.25
    ordering_fill_growth: float = 1.2
    unsettled_residual: float = 1e-2

    def __post_init__(self) -> None:
        _check(self, shares=("switch_tolerance", "unsettled_residual"), whole=("prediction_sweeps",))
        if not self.ordering_fill_growth >= 1.0:
            raise InputError("ordering_fill_growth", self.ordering_fill_growth, "", ">= 1")


@dataclass(frozen=True)
class ContinuationOptions:
    """The equilibrium's start from the equilibrium on the grid halved both ways (grid
    continuation, docs/theory.md Sect. 4.1).

    Attributes
    ----------
    nodes : int
        Grids with at least this many nodes start from the coarse equilibrium: the fine Newton
        steps are then short, so each trial's predicted active set is nearly right, and the
        first film solution starts its active set from the coarse pressure. Measured on the
        NTUA case (misaligned; median of 15, benchmarks/bench_bearing.py): 80 x 48 the same with
        and without (16 ms), 100 x 60 17 ms against 23, 120 x 72 27 against 34, 140 x 84 57
        against 111, 200 x 120 91 against 314 (4 fine Newton iterations from the closed-form
        start, 2 from the coarse equilibrium). The mass-conserving model too (NTUA, cavitation
        pressure -30 kPa, 100 x 60: 89 -> 52 ms, 4 -> 2 fine iterations).
    other_nodes : int
        The threshold of a bearing with a liner or a rough surface, that its solver paths were
        tuned with.
    tolerance : float
        Force tolerance (share of the load) of that coarse equilibrium: it only places the
        start. The fine Newton iteration takes about ``r -> 0.7 r^2`` there, so from a start
        within 1 % of the load it converges (1e-8) in two steps; the start's residual is the
        coarse grid's discretisation error plus this tolerance, so a tighter one buys nothing
        (18 NTUA equilibria, 100 x 60 and 200 x 120, three loads and tilts: the same fine
        iterations at 1e-5 and 2e-3, one coarse iteration fewer at 2e-3 on the example, 5 % of
        its time). The mass-conserving model on a smooth rigid bore takes it too (18 NTUA JFO
        equilibria: the same fine iterations and flags at 1e-5 and 2e-3, positions within
        6e-10 of the clearance, the 100 x 60 example 5 % faster).
    other_tolerance : float
        Force tolerance of the equilibria that only place the start of a bearing with a liner
        or a rough surface (the coarse grid's, and a lined bearing's rigid bore's): the one
        their solver paths were tuned with (docs/theory.md Sect. 17).
    """

    nodes: int = 5_000
    other_nodes: int = 20_000
    tolerance: float = 2e-3
    other_tolerance: float = 1e-5

    def __post_init__(self) -> None:
        _check(self, shares=("tolerance", "other_tolerance"), counts=("nodes", "other_nodes"))


@dataclass(frozen=True)
class NewtonOptions:
    """The equilibrium's Newton iteration: its refined trials, and when it stops short.

    Attributes
    ----------
    refine_residual : float
        Force residual (share of the load) below which a Newton step's trials refine their
        pressure from the step's linear guess by conjugate gradients preconditioned by the
        current film's factor instead of factorising their own matrix (Reynolds condition,
        rigid bore): there the step changes the film by about that share, so the iteration
        gains about that factor per step. Below it, too, an unsettled iterate is settled before
        its step.
    stalled_iterations, stalled_reduction : int, float
        Newton iterations in a row that each leave more than ``stalled_reduction`` of the force
        residual, after which a rigid rough bore's equilibrium is given up: as contact when its
        film is at the boundary limit (the asperities there cannot carry the rest of the load),
        as not converged above it (seed 001's rig at 15 rpm: the residual stalls at 11 % of the
        load with the film at lambda 0.1, the fluid spike of a contact zone one or two cells
        wide) unless the grid resolves the contact zone (:attr:`SettleOptions.zone_nodes`),
        where the equilibrium is settled. Smooth films keep their rule (no descent left).
    crawl_iterations, crawl_reduction : int, float
        The same rule for a crawl: this many Newton iterations in a row whose steps the line
        search's residual test shortened and that each leave more than ``crawl_reduction`` of
        the residual (docs/theory.md, "The stall rule and crawling Newton steps"). Measured on
        244 rigid rough equilibria (the test suite, both Stribeck curves of bench_mixed from
        warm and cold starts, the NTUA bearing at psi 0 to 0.4): no equilibrium that converged
        had more than 5 such iterations in a row; the NTUA curve at 12.4 rpm from a cold start
        had 45.
    floor_margin : float
        A rough film within this many sigma above the boundary limit is at its floor: its
        asperities at the limit of the model cannot carry the rest of the load.
    start_lift : float
        A lined equilibrium whose film-liner iteration does not settle at its start is started
        where it does, on the way to the bore's centre: the journal lifted by sigma, 2 sigma,
        4 sigma, ... (rough) or by this share of the clearance, doubled likewise (smooth; about
        sigma / c of seed 001's rig, 0.004).
    nearby_jacobian : float
        Force residual (share of the load) above which the equilibrium's Jacobian with a liner
        may use the matrix of the film-liner iteration's last step instead of a new
        factorisation.
    """

    refine_residual: float = 1e-3
    stalled_iterations: int = 4
    stalled_reduction: float = 0.99
    crawl_iterations: int = 10
    crawl_reduction: float = 0.95
    floor_margin: float = 0.05
    start_lift: float = 0.005
    nearby_jacobian: float = 1e-3

    def __post_init__(self) -> None:
        _check(
            self,
            shares=("refine_residual", "stalled_reduction", "crawl_reduction", "start_lift", "nearby_jacobian"),
            counts=("stalled_iterations", "crawl_iterations"),
        )


@dataclass(frozen=True)
class SettleOptions:
    """Pseudo-transient settling of a stalled rigid rough bore (docs/theory.md, "Settling").

    Attributes
    ----------
    zone_nodes : int
        Circumferential nodes the film must have within one sigma of its minimum (on the row of
        the minimum) for the settling to run. On fewer the film pressure of the contact zone is
        a spike on a node or two whose size jumps as the minimum moves between nodes, the
        discrete force is not a function a root-finder can follow, and the equilibrium is
        reported not converged at once. Seed 001's rigid rig (docs/validation.md, "Rigid rough
        bore at low speed"): 3-4 nodes on 120 (Newton stalls at 5 of 5 speeds below 21 rpm), 7
        on 240 (the settling ran its 60 steps without converging at 3 of 3 stalled speeds), 14
        on 480 (it converged at 3 of 3).
    first_move : float
        The first step moves the journal about this many sigma along the net force,
    max_move : float
        no step moves it more than this many sigma (the film changes by at most that much),
    growth : float
        and a step that raises the residual more than this many times is taken again with a
        quarter of the pseudo-time.
    """

    zone_nodes: int = 10
    first_move: float = 0.1
    max_move: float = 0.5
    growth: float = 2.0

    def __post_init__(self) -> None:
        _check(self, whole=("zone_nodes",))
        if not self.growth > 1.0:
            raise InputError("growth", self.growth, "", "> 1")


@dataclass(frozen=True)
class LinerOptions:
    """The film and an elastic liner solved together (docs/theory.md Sect. 17, "Elastic liner"
    and "Elastic layer").

    Attributes
    ----------
    tolerance : float
        Liner deformation converged when the column model's residual is below this share of
        the radial clearance everywhere (0.55 pm on seed 001's rig): tight enough that the force
        it leaves uncertain is below the equilibrium's tolerance (1e-8 of the load); Newton's
        quadratic convergence makes the last digits cheap.
    inexact : float
        Inside the equilibrium's Newton iteration a trial's liner is solved only until the
        force error it leaves is about this share of the force residual (an inexact Newton
        method; Dembo, Eisenstat & Steihaug, SIAM J. Numer. Anal. 19 (1982) 400-408): far from
        the equilibrium the last digits of the deformation change the force by far less than
        the residual. A deformation error dD (of c) changes the film at its thinnest, H_min, by
        dD, and the force by about dD / H_min of itself, so the liner tolerance is the force
        share times H_min; the converged equilibrium's liner is solved to a tenth of the
        equilibrium's own tolerance that way.
    iterations : int
        Newton iterations of the film-liner system allowed per film solution (0: a film-liner
        iteration that does not start settled is given up).
    stagnation : int
        The film-liner iteration gives up when its residual has not halved over this many
        steps (a trial the film cannot hold; the seed 001 rig at 15 rpm spent 27 such trials x
        40 steps).
    chord_reduction : float
        A kept (chord) factor of the film-liner matrix is used while each of its steps leaves
        at most this share of the liner residual: a slower step costs a film solution for
        little, and a fresh factor (about three film solutions on 100 x 60) converges
        quadratically.
    fixed_iterations : int
        Scalar Newton iterations allowed on the fixed-pressure nodes of a column liner with
        asperity contact before each film solution (0: none, the coupled steps carry those
        nodes too),
    fixed_tolerance : float
        and the share of the liner tolerance they reach there (5 to 10 iterations from a zero
        start on seed 001's rig).
    kept_orderings : int
        Orderings of the coupled film-liner matrix kept per solver (free sets): an equilibrium
        meets 2 to 8.
    layer_step_rtol : float
        Relative residual of the Krylov solve of a layer-model Newton step: an inexact Newton
        step (Dembo, Eisenstat & Steihaug 1982): the film-liner iteration converges linearly at
        about this rate once its quadratic phase is over, and tests its own residual.
    layer_response_rtol : float
        Relative residual of the layer model's film response (the equilibrium's Jacobian and
        the stiffness): close enough to the exact linearisation for Newton's quadratic
        convergence and for the stiffness against central differences
        (tests/film/test_liner.py).
    layer_restart, layer_cycles : int
        Krylov iterations allowed per solve of the layer model: restarted GMRES,
        ``layer_restart`` per cycle.
    """

    tolerance: float = 1e-9
    inexact: float = 0.01
    iterations: int = 40
    stagnation: int = 10
    chord_reduction: float = 0.1
    fixed_iterations: int = 30
    fixed_tolerance: float = 0.1
    kept_orderings: int = 16
    layer_step_rtol: float = 1e-6
    layer_response_rtol: float = 1e-10
    layer_restart: int = 40
    layer_cycles: int = 5

    def __post_init__(self) -> None:
        _check(
            self,
            shares=(
                "tolerance",
                "inexact",
                "chord_reduction",
                "fixed_tolerance",
                "layer_step_rtol",
                "layer_response_rtol",
            ),
            counts=("stagnation", "kept_orderings", "layer_restart", "layer_cycles"),
            whole=("iterations", "fixed_iterations"),
        )
