"""The Reynolds (Swift-Stieber) cavitation condition: a linear complementarity problem.

``P >= 0, w = A P - b >= 0, P w = 0`` on the free nodes (docs/theory.md Sect. 4): the film
ruptures where the pressure would fall below the cavitation pressure, and the pressure and its
normal derivative vanish on the free boundary. Solved by the primal-dual active-set method
(Hintermueller, Ito & Kunisch 2002), which terminates in finitely many steps for the film's
M-matrix, with the trial sets' linear systems solved by kept node-set factors
(:mod:`shaftline.film.cavitation.node_set`) or conjugate gradients preconditioned by them, and
the cavitated set of a cold start predicted on the coarser grids, by sweeps alone on the small
ones (:mod:`shaftline.film.relaxation`, a cascadic multigrid; docs/theory.md Sect. 4.1).
"""

from __future__ import annotations

from typing import TYPE_CHECKING, ClassVar

import numpy as np

from shaftline.film.cavitation.base import CavitationConvergenceError, CavitationSolution, NodeGrid, SolverCounts
from shaftline.film.cavitation.coarse import CoarseGrid
from shaftline.film.cavitation.node_set import NodeSetFactor
from shaftline.film.geometry import coarse_shape
from shaftline.film.relaxation import projected_sor
from shaftline.film.stencil import Stencil, apply_operator, build_stencil, stencil_diagonal, symmetric_pattern

if TYPE_CHECKING:
    from shaftline.film.options import ActiveSetOptions
    from shaftline.film.problem import SolverOptions
    from shaftline.film.roughness import FilmFlow

__all__ = ["ReynoldsCondition", "marched_film_fraction"]


class _MarchedSolution(CavitationSolution):
    """A Reynolds-condition solution whose film fraction is marched (:func:`marched_film_fraction`)
    when first read: the Newton trials of an equilibrium never read it, only its final state."""

    def __init__(
        self, pressure: np.ndarray, cavitated: np.ndarray, iterations: int, film: np.ndarray, settled: bool = True
    ) -> None:
        self._film = film
        self._fraction: np.ndarray | None = None
        super().__init__(pressure, None, cavitated, iterations, settled=settled)  # type: ignore[arg-type]

    @property
    def film_fraction(self) -> np.ndarray:
        if self._fraction is None:
            self._fraction = marched_film_fraction(self._film, self.cavitated)
        return self._fraction

    @film_fraction.setter
    def film_fraction(self, value: np.ndarray | None) -> None:
        self._fraction = value


class ReynoldsCondition:
    """The Reynolds (Swift-Stieber) condition on one grid: ``P >= 0, w = A P - b >= 0, P w = 0``,
    a linear complementarity problem solved by the primal-dual active-set method (Hintermueller,
    Ito & Kunisch 2002), which terminates in finitely many steps for an M-matrix.

    It keeps state between calls: the sparse LDL^T factor of a node set (qdldl,
    :class:`~shaftline.film.cavitation.node_set.NodeSetFactor`), the active set it was
    factorised for, and the same model on the coarser grid that predicts the cavitated set.
    That state belongs to one process and does not pickle; the film solver
    (:class:`shaftline.film.solver.FilmSolver`) builds it lazily. A :class:`CavitationModel`.

    Parameters
    ----------
    nodes : NodeGrid
        The grid: shape, mesh steps, fixed nodes and their pressures.
    options : SolverOptions
        Its ``active_set`` options (the others are read where they apply).
    counts : SolverCounts, optional
        Counters shared with the solver (factorisations); its own when not given.
    flow : FilmFlow, optional
        Flow model of the coarse grids that predict the cavitated set: None (the smooth film),
        or a turbulent film's, whose damped pressure flow moves the cavitation boundary (a
        function of H = h/c only, so the same object serves every grid).
    masked : bool
        Factorise the full periodic pattern with the held rows and columns zeroed (one symbolic
        analysis for every set) instead of the free sub-matrix: the small coarse grids that only
        predict the cavitated set do.
    """

    name: ClassVar[str] = "reynolds"
    active_set: ClassVar[bool] = True
    refines_trials: ClassVar[bool] = True
    starts_from_coarse_contact: ClassVar[bool] = True
    rough_surfaces: ClassVar[bool] = True
    liners: ClassVar[bool] = True
    refusal: ClassVar[str] = ""
    needs_feed_pressure: ClassVar[bool] = False
    dense_bytes: ClassVar[float] = 0.0
    factor_bytes: ClassVar[float] = 0.0

    def __init__(
        self,
        nodes: NodeGrid,
        options: SolverOptions,
        counts: SolverCounts | None = None,
        flow: FilmFlow | None = None,
        masked: bool = False,
    ) -> None:
        self.nodes = nodes
        self.solver_options = options
        self.options: ActiveSetOptions = options.active_set
        self.counts = SolverCounts() if counts is None else counts
        self.flow = flow
        self.masked = masked
        self.pattern = symmetric_pattern(*nodes.shape)
        self._factor: NodeSetFactor | None = None
        self._masked_factor: NodeSetFactor | None = None
        self._slot_cache: tuple[Stencil, np.ndarray] | None = None
        self._coarse_grid: CoarseGrid[ReynoldsCondition] | None = None
        #: Conjugate-gradient iterations of the trial sets so far.
        self.pcg_iterations = 0

    @property
    def shape(self) -> tuple[int, int]:
        return self.nodes.shape

    @property
    def d_theta(self) -> float:
        return self.nodes.d_theta

    @property
    def d_z(self) -> float:
        return self.nodes.d_z

    @property
    def fixed(self) -> np.ndarray:
        return self.nodes.fixed

    @property
    def fixed_pressure(self) -> np.ndarray:
        return self.nodes.fixed_pressure

    def drop_factors(self) -> None:
        """Forget the kept node-set factors (and those of the coarser grids), keeping the
        sparsity patterns and coarse grids: the next solutions then round the same whatever
        this model solved before (a design search shares one solver across bores, and its
        results must not depend on which worker evaluated which design before). The masked
        factor stays: its pattern is fixed, so its results depend on the matrix only."""
        self._factor = None
        if self._coarse_grid is not None:
            self._coarse_grid.model.drop_factors()

    # -- symmetric masked system -------------------------------------------------
    def _slot_values(self, stencil: Stencil) -> np.ndarray:
        """Values of A on every slot of the full pattern (upper triangle), kept per stencil:
        an active-set iteration builds several sub-matrices of one film."""
        cached = self._slot_cache
        if cached is not None and cached[0] is stencil:
            return cached[1]
        source = np.concatenate([stencil_diagonal(stencil).ravel(), -stencil.c_theta.ravel(), -stencil.c_z.ravel()])
        values = source[self.pattern.slot_source]
        self._slot_cache = (stencil, values)
        return values

    def _factorise(self, stencil: Stencil, held: np.ndarray) -> NodeSetFactor | None:
        """LDL^T factor of the free sub-matrix ``A[free, free]`` (qdldl), kept between calls.

        The factor is that of a kept node set holding the free nodes and a few cells around
        them (``options.node_set_margin``), with the held nodes inside it decoupled (their rows
        and columns zeroed, their diagonals kept): so ``x = 0`` there, and on the free nodes
        the solution is that of ``A[free, free]`` itself. Every active set inside the kept
        node set reuses its AMD ordering and symbolic analysis and costs only qdldl's numeric
        factorisation; the same set and film again (the frozen-set derivatives after a
        solution) cost nothing. A set with a free node outside it, or one much smaller than
        it (``options.node_set_slack``), gets a new node set. Returns None when no node is free.
        """
        free = ~held.ravel()
        if not free.any():
            self._factor = None
            return None
        factor = self._factor
        if factor is not None and factor.is_for(stencil, free):
            return factor
        if factor is None or not factor.holds(free, self.options.node_set_slack):
            self._factor = None  # a fine grid's factors need not fit in memory twice
            margin = self.options.node_set_margin
            factor = NodeSetFactor.around(self.pattern, free, self.shape, margin, self.fixed.ravel())
        elif factor.switch(self._slot_values(stencil), stencil, free, self.options.switch_max_nodes):
            return factor
        factor.factorise(self._slot_values(stencil), stencil, free, self.counts)
        self._factor = factor
        return factor

    def _solve_free(
        self,
        stencil: Stencil,
        held: np.ndarray,
        rhs: np.ndarray,
        guess: np.ndarray | None,
        direct: bool,
        refine: bool = False,
    ) -> np.ndarray:
        """``x`` with ``A[free, free] x[free] = rhs[free]`` and ``x = 0`` on the held nodes (flat).

        Unless ``direct``, conjugate gradients preconditioned by the kept factor (of a nearby
        active set, possibly of a nearby film) come first: they end in a few iterations, as
        the two matrices differ in the rows and columns of the switched nodes and by the
        small change of the film. Otherwise, or when they do not converge, the factor of
        this set. ``guess`` (flat, or None) starts the iteration. ``refine``: conjugate
        gradients on any grid, to ``options.refine_tolerance``.
        """
        free = ~held.ravel()
        out = np.zeros(free.size)
        if not free.any():
            return out
        if self.masked:
            return self._masked_factorisation(stencil, held).solve(np.where(free, rhs.ravel(), 0.0))
        iterative = (refine or free.size >= self.options.pcg_min_nodes) and self._factor is not None
        if iterative and not direct:
            tolerance = self.options.refine_tolerance if refine else self.options.pcg_tolerance
            solution = self._pcg(stencil, free, rhs.ravel()[free], None if guess is None else guess[free], tolerance)
            if solution is not None:
                out[free] = solution
                return out
        factor = self._factorise(stencil, held)
        assert factor is not None
        return factor.solve(np.where(free, rhs.ravel(), 0.0))

    def _masked_factorisation(self, stencil: Stencil, held: np.ndarray) -> NodeSetFactor:
        """Factor of the full pattern with the held rows and columns zeroed, their diagonals
        kept (so ``x = 0`` there for a zero right-hand side): a :class:`NodeSetFactor` whose
        node set is every node, so its one symbolic analysis serves every set."""
        free = ~held.ravel()
        factor = self._masked_factor
        if factor is None:
            everything = np.ones(free.size, dtype=bool)
            factor = self._masked_factor = NodeSetFactor.around(self.pattern, everything, self.shape, 0)
        if not factor.is_for(stencil, free):
            factor.factorise(self._slot_values(stencil), stencil, free, self.counts)
        return factor

    def _is_factored(self, stencil: Stencil, held: np.ndarray) -> bool:
        """Whether the kept factor is that of ``stencil`` and ``held`` (or no node is free)."""
        if held.all() or self.masked:
            return True  # a masked solve is always a direct solve of that set's own matrix
        return self._factor is not None and self._factor.is_for(stencil, ~held.ravel())

    def _pcg(
        self,
        stencil: Stencil,
        free: np.ndarray,
        rhs: np.ndarray,
        guess: np.ndarray | None,
        tolerance: float,
    ) -> np.ndarray | None:
        """Conjugate gradients on ``A[free, free]`` preconditioned by the kept factor.

        The preconditioner applies the kept factor's inverse on the nodes free in both sets
        and the inverse diagonal on the nodes freed since. For the same film it differs from
        the inverse of the new matrix by a term of rank at most about twice the switched
        nodes, so the iteration ends in about that many steps (Golub & Van Loan, Matrix
        Computations, 4th ed., Sect. 11.5); a factor of a nearby film adds a perturbation
        small in norm, which costs a few more.
        Stops when the preconditioned residual (the error in the energy norm) falls below
        ``tolerance`` of the solution's energy norm; None when it does not within
        ``options.pcg_max_iterations``.
        """
        factor = self._factor
        assert factor is not None and factor.free is not None
        kept_free = factor.free
        size = free.size
        in_kept = kept_free[free]  # free now and in the kept factor
        diag = stencil_diagonal(stencil).ravel()[free]
        extra = ~in_kept
        shape = self.shape
        both = free & kept_free

        def operator(x: np.ndarray) -> np.ndarray:
            full = np.zeros(size)
            full[free] = x
            return apply_operator(stencil.c_theta, stencil.c_z, full.reshape(shape)).ravel()[free]

        def precondition(r: np.ndarray) -> np.ndarray:
            z = np.empty_like(r)
            kept_rhs = np.zeros(size)
            kept_rhs[both] = r[in_kept]
            z[in_kept] = factor.solve(kept_rhs)[both]
            z[extra] = r[extra] / diag[extra]
            return z

        x = np.zeros(rhs.size) if guess is None else guess.copy()
        r = rhs - operator(x)
        z = precondition(r)
        p = z.copy()
        rz = _dot(r, z)
        for step in range(self.options.pcg_max_iterations):
            energy = abs(_dot(x, rhs)) + abs(_dot(x, r))
            if rz <= tolerance**2 * energy or rz == 0.0:
                self.pcg_iterations += step
                return x
            q = operator(p)
            alpha = rz / _dot(p, q)
            x += alpha * p
            r -= alpha * q
            z = precondition(r)
            rz_new = _dot(r, z)
            p = z + (rz_new / rz) * p
            rz = rz_new
        return None

    def _solve_masked(
        self,
        stencil: Stencil,
        held: np.ndarray,
        held_values: np.ndarray,
        guess: np.ndarray | None = None,
        direct: bool = True,
        refine: bool = False,
    ) -> np.ndarray:
        """Solve ``A P = b`` on the free nodes with ``P = held_values`` on held nodes."""
        # Moving the held values to the right-hand side: b - A_{free,held} P_held.
        boundary = np.where(held, held_values, 0.0)
        rhs = stencil.rhs - apply_operator(stencil.c_theta, stencil.c_z, boundary)
        pressure = self._solve_free(stencil, held, rhs, None if guess is None else guess.ravel(), direct, refine)
        return (pressure + boundary.ravel()).reshape(self.shape)

    def solve_linear(self, stencil: Stencil) -> np.ndarray:
        """Full-Sommerfeld solution (no cavitation), dimensionless pressure."""
        return self._solve_masked(stencil, self.fixed, self.fixed_pressure)

    def solve(
        self,
        stencil: Stencil,
        film: np.ndarray,
        start: np.ndarray | None = None,
        *,
        refine_from: np.ndarray | None = None,
        settle: bool = True,
    ) -> CavitationSolution:
        """The Reynolds-condition solution of the film ``H`` with ``stencil``; ``start`` warm-starts
        the active set (without it the coarser grids predict it).

        ``refine_from``, a pressure guess (nz, nt) close to the solution (a short Newton step's
        ``P + dP``): the active set's solves then iterate from it by conjugate gradients
        preconditioned by the kept factor (that of the nearby film), to
        ``options.refine_tolerance``, instead of factorising this film's matrix.

        ``settle=False``: stop at the first trial set within ``options.unsettled_max_nodes``
        nodes of settling, the solution marked ``settled=False``: an iterate of a Newton
        iteration far from its root, whose step moves the force by far more than those nodes
        do, need not pay for the last set switch (a bordered update of the factor, about half a
        factorisation). Solving again from its set with the same ``stencil`` finishes it with
        that update (docs/theory.md Sect. 4.1).
        """
        reynolds = self._solve_reynolds_lcp(stencil, start, film, refine_from=refine_from, settle=settle)
        return _MarchedSolution(reynolds.pressure, reynolds.cavitated, reynolds.iterations, film, reynolds.settled)

    def coarse_grid(self) -> CoarseGrid[ReynoldsCondition] | None:
        """The grid halved in both directions under this one (kept), or None when too small.
        Its model is of this class; a small one (below ``options.pcg_min_nodes``) is masked."""
        halved = coarse_shape(self.shape)
        if halved is None:
            return None
        if self._coarse_grid is None:

            def make(nodes: NodeGrid) -> ReynoldsCondition:
                masked = nodes.shape[0] * nodes.shape[1] < self.options.pcg_min_nodes
                return type(self)(nodes, self.solver_options, self.counts, self.flow, masked=masked)

            self._coarse_grid = CoarseGrid.under(self.nodes, halved, make)
        return self._coarse_grid

    def start_from_guess(self, stencil: Stencil, film: np.ndarray, guess: np.ndarray) -> np.ndarray | None:
        """:meth:`trial_set`: the start set of a pressure guess (a coarse solution prolonged, a
        Newton trial's linear guess)."""
        return self.trial_set(stencil, film, guess)

    def trial_guess(self, relative: np.ndarray, step: np.ndarray, response: np.ndarray) -> np.ndarray | None:
        """``P + dP``: the film is linear in the offsets, so the pressure change with the set
        frozen is that per metre of ey and ez (``response``) combined by the ``step``; the set it
        implies is sharpened on the new film (:meth:`trial_set`)."""
        return relative + np.tensordot(step, response, axes=1)

    def film_residual_change(self, solution: CavitationSolution, film_change: np.ndarray) -> np.ndarray | None:
        """None: with the set frozen the stencil's change is all (``p = dp/dn = 0`` on the free
        boundary, so moving it changes the force only to second order)."""
        return None

    def start_field(self, solution: CavitationSolution, relative: np.ndarray) -> np.ndarray:
        """The relative pressure itself: its sign places the cavitated set."""
        return relative

    def unsettled_residual(self, options: SolverOptions) -> float:
        """``options.newton.refine_residual``: below it the trials are refined, and settled."""
        return options.newton.refine_residual

    def _nested_start(self, film: np.ndarray, stencil: Stencil, guess: np.ndarray | None = None) -> np.ndarray | None:
        """Cavitated set predicted from the same problem on the coarser grids.

        The coarse indicator ``P - w / diag(A)`` (pressure where the film is full, minus the
        scaled complementarity multiplier where it is cavitated; :func:`_set_indicator`)
        changes sign on the cavitation boundary; interpolated bilinearly onto this grid it
        places that boundary to within a cell or two. A few projected over-relaxation sweeps
        on this grid (:func:`~shaftline.film.relaxation.projected_sor`), from the
        interpolated pressure, remove that short-wavelength error: the set they leave is one
        or two nodes off the final one where the interpolated one is tens.

        On the small coarse grids (``masked``, below ``options.pcg_min_nodes``) the indicator
        comes from sweeps alone, carried up from the coarsest grid (:meth:`_swept_indicator`);
        a larger coarse grid solves its own active set, itself started this way. ``guess``, a
        Newton trial's pressure guess, starts the coarsest sweeps (restricted to it) or that
        active set (its swept set).
        """
        coarse = self.coarse_grid()
        if coarse is None:
            return None
        solver = coarse.model
        film_c = coarse.restrict(film)
        solver.flow = self.flow  # the film being solved may share this model (FilmSolver.sharing)
        guess_c = None if guess is None else coarse.restrict(guess)
        if solver.masked:
            return self.predicted_set(stencil, coarse.prolong(solver._swept_indicator(film_c, guess_c)))
        stencil_c = build_stencil(film_c, solver.d_theta, solver.d_z, rough=self.flow)
        return self.predicted_set(stencil, coarse.prolong(solver._solved_indicator(stencil_c, film_c, guess_c)))

    def _solved_indicator(self, stencil: Stencil, film: np.ndarray, guess: np.ndarray | None) -> np.ndarray:
        """The set indicator (:func:`_set_indicator`) of this grid's own active-set solution,
        started from the swept set of ``guess`` (a pressure guess on this grid) if given. Only a
        prediction: a set a few nodes short of settling predicts the finer one as well (its
        sweeps correct a node or two), without this grid's last switch."""
        start = None if guess is None else self.predicted_set(stencil, guess)
        solution = self._solve_reynolds_lcp(stencil, start, film, exact=False, settle=False)
        return _set_indicator(stencil, solution.pressure, solution.cavitated, self.fixed)

    def _swept_indicator(self, film: np.ndarray, guess: np.ndarray | None) -> np.ndarray:
        """The set indicator (:func:`_set_indicator`) of this grid's problem from
        ``options.cascade_sweeps`` projected SOR sweeps at ``options.cascade_omega``, started from the
        indicator of the grid below interpolated onto this one, or on the coarsest grid from
        ``guess`` (a pressure guess on this grid) or zero: the prediction climbs the grids by
        sweeps alone (a cascadic multigrid, docs/theory.md Sect. 4.1), with no factorisation.
        A coarsest grid longer than ``options.cascade_coarsest_span`` either way solves its own
        active set instead (a prediction, a few nodes short of settling). On the NTUA case
        (25 x 15 and 50 x 30 under 100 x 60) the fine set starts 2 nodes off the final one, as
        from the coarse active sets this replaced, and a cold solution factorises once instead
        of seven times.
        """
        stencil = build_stencil(film, self.d_theta, self.d_z, rough=self.flow)
        coarse = self.coarse_grid()
        if coarse is None and max(self.shape) > self.options.cascade_coarsest_span:
            # Too long (the halving stopped at an odd column count or a short bore) for sweeps
            # from nothing to carry the boundary across: its own active set.
            return self._solved_indicator(stencil, film, guess)
        if coarse is None:
            start = np.zeros(self.shape) if guess is None else guess
        else:
            coarse.model.flow = self.flow
            guess_below = None if guess is None else coarse.restrict(guess)
            start = coarse.prolong(coarse.model._swept_indicator(coarse.restrict(film), guess_below))
        start = np.where(self.fixed, self.fixed_pressure, np.maximum(start, 0.0))
        sweeps, omega = self.options.cascade_sweeps, self.options.cascade_omega
        pressure = projected_sor(start, stencil.c_theta, stencil.c_z, stencil.rhs, self.fixed, sweeps, omega, False)
        return _set_indicator(stencil, pressure, (pressure <= 0.0) & ~self.fixed, self.fixed)

    def trial_set(self, stencil: Stencil, film: np.ndarray, pressure: np.ndarray) -> np.ndarray | None:
        """Start set of a Newton trial from its linear pressure guess ``P + dP`` (nz, nt):
        :meth:`predicted_set`, or the coarse grids' prediction (:meth:`_nested_start`) when the
        guess takes more than ``options.nested_swing`` of the nodes below zero. Such a long step
        moves the cavitation boundary by many cells, an error the sweeps cannot remove (on
        the NTUA case the first Newton trial's guess is 5 % negative and its swept set 31
        nodes off, four factorisations; from the coarse grids 4 nodes off, two)."""
        if np.count_nonzero((pressure < 0.0) & ~self.fixed) > self.options.nested_swing * pressure.size:
            nested = self._nested_start(film, stencil, pressure)
            if nested is not None:
                return nested
        return self.predicted_set(stencil, pressure)

    def predicted_set(self, stencil: Stencil, pressure: np.ndarray) -> np.ndarray:
        """Cavitated set predicted from a pressure guess (nz, nt), e.g. interpolated from a
        coarser grid or extrapolated by a Newton step: the nodes that a few projected
        over-relaxation sweeps from it (:func:`~shaftline.film.relaxation.projected_sor`)
        leave at zero. The sweeps remove the guess's short-wavelength error around the
        cavitation boundary, so the set is a node or two off the final one."""
        start = np.where(self.fixed, self.fixed_pressure, np.maximum(pressure, 0.0))
        sweeps, omega = self.options.prediction_sweeps, self.options.prediction_omega
        relaxed = projected_sor(start, stencil.c_theta, stencil.c_z, stencil.rhs, self.fixed, sweeps, omega)
        return (relaxed <= 0.0) & ~self.fixed

    def _solve_reynolds_lcp(
        self,
        stencil: Stencil,
        initial_cavitated: np.ndarray | None,
        film: np.ndarray | None = None,
        exact: bool = True,
        refine_from: np.ndarray | None = None,
        settle: bool = True,
    ) -> CavitationSolution:
        """Primal-dual active set (Hintermueller, Ito & Kunisch 2002) for the Reynolds LCP.

        The trial sets are solved by :meth:`_solve_free` (conjugate gradients preconditioned
        by the kept factor where they converge); once the set has settled, its pressures are
        solved again with the factor of that set (``exact``), so that the result depends only
        on the film and the set, which is unique, not on the start or the path. The coarse
        grids that only predict the set skip that last solve. With ``refine_from`` (a pressure guess,
        see :meth:`solve`) every set is solved iteratively to ``options.refine_tolerance``; with
        ``settle=False`` it may stop a few nodes short of settling (see :meth:`solve`).
        """
        iterations = 0
        if initial_cavitated is None and film is not None and stencil.rhs.shape == film.shape:
            initial_cavitated = self._nested_start(film, stencil)
        if initial_cavitated is None:
            pressure = self.solve_linear(stencil)
            iterations += 1
            cavitated = (pressure < 0.0) & ~self.fixed
        else:
            cavitated = initial_cavitated & ~self.fixed
        scale = 1.0
        guess = refine_from
        values = np.where(self.fixed, self.fixed_pressure, 0.0)
        direct = False
        for _ in range(self.options.max_iterations):
            held = self.fixed | cavitated
            pressure = self._solve_masked(stencil, held, values, guess, direct=direct, refine=refine_from is not None)
            guess = pressure
            iterations += 1
            scale = max(float(np.abs(pressure).max()), 1e-300)
            multiplier = apply_operator(stencil.c_theta, stencil.c_z, pressure) - stencil.rhs
            rhs_scale = max(float(np.abs(stencil.rhs).max()), 1e-300)
            leave = cavitated & (multiplier < -1e-12 * rhs_scale)
            enter = ~held & (pressure < -1e-12 * scale)
            if not leave.any() and not enter.any():
                if exact and refine_from is None and not self._is_factored(stencil, held):
                    # Settled on an iterative solution: solve once more with this set's factor
                    # (and check it again) so that the result does not depend on the path.
                    direct = True
                    continue
                pressure = np.where(cavitated, 0.0, pressure)
                return CavitationSolution(pressure, np.ones_like(pressure), cavitated, iterations)
            if not settle and int(np.count_nonzero(leave | enter)) <= self.options.unsettled_max_nodes:
                pressure = np.maximum(np.where(cavitated, 0.0, pressure), 0.0)
                return CavitationSolution(pressure, np.ones_like(pressure), cavitated, iterations, settled=False)
            cavitated = (cavitated & ~leave) | enter
        raise CavitationConvergenceError("Reynolds-condition active set did not settle")

    def pressure_response(self, stencil: Stencil, solution: CavitationSolution, rhs_change: np.ndarray) -> np.ndarray:
        """Pressure change ``dP`` for a residual change ``dR`` with the active set frozen.

        Solves ``A_free dP = -dR`` on the pressurised free nodes, reusing the
        factorisation of the converged active set when it is still held.
        """
        held = self.fixed | solution.cavitated
        columns = np.atleast_2d(rhs_change.reshape(-1, self.shape[0] * self.shape[1]))
        out = np.array([self._solve_free(stencil, held, -column, None, direct=True) for column in columns])
        return out.reshape((-1,) + self.shape)


def _set_indicator(stencil: Stencil, pressure: np.ndarray, cavitated: np.ndarray, fixed: np.ndarray) -> np.ndarray:
    """``P - w / diag(A)``: the pressure on the full-film nodes, minus the complementarity
    multiplier ``w = A P - b`` (>= 0 there, clipped) over the diagonal on the cavitated ones,
    zero on the fixed nodes. It changes sign on the cavitation boundary, and interpolated onto
    a finer grid it places that boundary between the nodes (docs/theory.md Sect. 4)."""
    multiplier = apply_operator(stencil.c_theta, stencil.c_z, pressure) - stencil.rhs
    indicator = np.where(cavitated, -np.maximum(multiplier, 0.0) / stencil_diagonal(stencil), pressure)
    return np.where(fixed, 0.0, indicator)


def _dot(a: np.ndarray, b: np.ndarray) -> float:
    """Inner product without BLAS: a BLAS ``ddot`` on a vector this short spends more time
    waking its threads than computing, and far more on a machine shared with other work."""
    return float(np.einsum("i,i->", a, b))


def marched_film_fraction(film: np.ndarray, cavitated: np.ndarray) -> np.ndarray:
    """Film fraction in a cavitated zone from Couette transport of the film at rupture.

    Along each circumferential line the liquid leaving the last full-film node is
    carried unchanged through the cavitated zone (pure Couette flow), so the film
    fraction is ``h_rupture / h``. Used with the Reynolds and half-Sommerfeld
    conditions, which do not compute it themselves.
    """
    nz, nt = film.shape
    full = ~cavitated
    if full.all():
        return np.ones_like(film)
    index = np.where(full, np.arange(nt)[None, :], -1)
    # Two periods so that a zone wrapping past theta = 2 pi finds its upstream full node.
    doubled = np.concatenate([index - nt, index], axis=1)
    doubled = np.where(np.concatenate([full, full], axis=1), doubled, -(10 * nt))
    last_full = np.maximum.accumulate(doubled, axis=1)[:, nt:]
    rows = np.arange(nz)[:, None]
    has_source = last_full > -(5 * nt)
    source = np.where(has_source, last_full % nt, 0)
    # A rough film may close past the mean plane (h <= 0, boundary lubrication): the gap there is
    # the asperities' valleys, full (fraction 1), never a negative share.
    has_source = has_source & (film > 0.0)
    fraction = np.where(has_source, film[rows, source] / np.where(has_source, film, 1.0), 1.0)
    return np.where(full, 1.0, np.clip(fraction, 0.0, 1.0))
