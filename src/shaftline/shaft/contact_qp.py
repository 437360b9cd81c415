"""Convex QP of the bearing contact: min 1/2 x'Hx + c'x s.t. E x = t, x_i >= 0 for bounded i.

Two solvers of the same primal active-set method (Nocedal & Wright 2006, Alg. 16.3):

- :func:`active_set_qp`, the original one, kept as the test oracle: a start from an
  LP (HiGHS) vertex, a dense KKT system rebuilt and solved by least squares at every step.
- :class:`ContactQP`, the one the alignment uses: the problem's fixed parts (H, E, the
  bounds) are kept for the life of the model, the factorisation of the KKT matrix of each
  working set met is kept for reuse, and the working set of the previous solution is tried
  first (conditions, jack loads and offset steps of one line mostly share a contact set).
  A working set whose equality-constrained minimiser is feasible and has no negative bound
  multiplier is optimal, so a repeated contact set costs one triangular solve.

Both end on a working set whose equality-constrained minimiser satisfies the optimality
(KKT) conditions; :class:`ContactQP` returns that minimiser solved afresh from the final
working set, so its result depends on the contact set only, not on the path to it.
benchmarks/bench_contact_qp.py measures both against off-the-shelf QP solvers.
"""

from __future__ import annotations

from collections import OrderedDict

import numpy as np
from scipy.linalg import lu_factor, lu_solve
from scipy.optimize import linprog

from shaftline.errors import InputError, SolverFailure

#: Multipliers of the bounds are gaps (m): a penetration below this is round-off.
GAP_TOLERANCE = 1e-12
#: Relative regularisation of H: the pinned supports have zero flexibility and a bottom
#: and a top contact of one point have opposite columns, so H alone is only semi-definite.
REGULARISATION = 1e-12
#: Working sets whose KKT factorisation is kept per problem.
CACHE_SIZE = 64


def _top_columns(equality: np.ndarray) -> np.ndarray:
    """Columns that push the shaft down (top-of-bore contacts): negative in the force row."""
    return equality[0] < 0


def _infeasible() -> InputError:
    return InputError("bearings", "supports", "", "supports that can carry the loads (the line tips over)")


def active_set_qp(
    hessian: np.ndarray, linear: np.ndarray, equality: np.ndarray, target: np.ndarray, bounded: np.ndarray
) -> tuple[np.ndarray, np.ndarray, int]:
    """Solve min 1/2 x'Hx + c'x s.t. E x = t, x_i >= 0 for bounded i (H positive semi-definite).

    Primal active-set method (Nocedal & Wright 2006, Alg. 16.3) from a feasible point found
    by linear programming. Each step either adds the blocking bound or drops the bound with
    the most negative multiplier; with the objective strictly decreasing between working
    sets no working set repeats, so the iteration ends in finitely many steps.

    This is the original solver, kept unchanged as the reference for :class:`ContactQP`.

    Returns
    -------
    x, equality multipliers (E'mu enters the stationarity as + E'mu), iterations.
    """
    n = linear.size
    scale = max(float(np.abs(np.diag(hessian)).max()), 1e-300)
    hessian = hessian + REGULARISATION * scale * np.eye(n)
    rows = equality.shape[0]
    # Usual case first: every bottom contact closed, every top contact open. If that
    # equality-constrained solution has no negative reaction and no penetration it is optimal.
    guess = ~bounded | (np.arange(n) < n - np.count_nonzero(_top_columns(equality)))
    kkt = np.block(
        [[hessian[np.ix_(guess, guess)], equality[:, guess].T], [equality[:, guess], np.zeros((rows, rows))]]
    )
    try:
        solved = np.linalg.solve(kkt, np.concatenate([-linear[guess], target]))
    except np.linalg.LinAlgError:
        solved = None
    if solved is not None:
        x = np.zeros(n)
        x[guess] = solved[: guess.sum()]
        mu = solved[guess.sum() :]
        gaps = hessian @ x + linear + equality.T @ mu
        if np.all(x[bounded] >= 0.0) and np.all(gaps[~guess] >= -1e-12):
            return x, mu, 1
    bounds = [(0.0, None) if b else (None, None) for b in bounded]
    start = linprog(np.zeros(n), A_eq=equality, b_eq=target, bounds=bounds, method="highs")
    if start.status != 0:
        raise _infeasible()
    x = np.where(bounded, np.maximum(start.x, 0.0), start.x)
    working = bounded & (x <= 1e-12 * max(1.0, float(np.abs(x).max())))
    x[working] = 0.0
    force_scale = max(1.0, float(np.abs(target).max()))
    gap_tolerance = GAP_TOLERANCE
    for iteration in range(1, 20 * n + 50):
        free = ~working
        g = hessian @ x + linear
        kkt = np.block(
            [
                [hessian[np.ix_(free, free)], equality[:, free].T],
                [equality[:, free], np.zeros((equality.shape[0],) * 2)],
            ]
        )
        rhs = np.concatenate([-g[free], np.zeros(equality.shape[0])])
        step_and_mu = np.linalg.lstsq(kkt, rhs, rcond=None)[0]
        step = np.zeros(n)
        step[free] = step_and_mu[: free.sum()]
        mu = step_and_mu[free.sum() :]
        if np.abs(step).max() <= 1e-11 * force_scale:
            multipliers_bound = g + equality.T @ mu
            candidates = np.flatnonzero(working & (multipliers_bound < -gap_tolerance))
            if candidates.size == 0:
                return x, mu, iteration
            drop = candidates[np.argmin(multipliers_bound[candidates])]
            working[drop] = False
            continue
        x = _step_to_bound(x, step, free & bounded & (step < 0), working)
    raise SolverFailure("alignment contact iteration did not terminate")  # pragma: no cover


class ContactQP:
    """The contact QP of one model and bending plane, with H, E and the bounds fixed.

    Parameters
    ----------
    hessian : ndarray (n, n)
        H, positive semi-definite (m/N); regularised by :data:`REGULARISATION` times its
        largest diagonal entry as in :func:`active_set_qp`.
    equality : ndarray (2, n)
        E: force row (+1 for a bottom, -1 for a top contact column) and moment row (that
        sign times the station, m) of the reaction columns.
    bounded : ndarray of bool (n,)
        Variables with x_i >= 0 (one-sided contacts).

    Notes
    -----
    The object remembers the working set of its last solution as the first guess of the
    next one (a warm start): it is not safe to share one instance between threads.
    """

    def __init__(self, hessian: np.ndarray, equality: np.ndarray, bounded: np.ndarray) -> None:
        n = hessian.shape[0]
        scale = max(float(np.abs(np.diag(hessian)).max()), 1e-300)
        self.hessian = hessian + REGULARISATION * scale * np.eye(n)
        self.equality = np.ascontiguousarray(equality, dtype=float)
        self.bounded = np.asarray(bounded, dtype=bool)
        self.size = n
        # Station of each column (moment row / force row): E[:, free] has full row rank
        # exactly when the free columns stand at two stations at least.
        self._station = self.equality[1] / self.equality[0]
        top = _top_columns(self.equality)
        # Every bottom contact closed, every top contact open (as the reference's first guess).
        self._default = self.bounded & top
        self._last: np.ndarray | None = None
        self._factors: OrderedDict[bytes, tuple[np.ndarray, np.ndarray] | None] = OrderedDict()
        self._pairs = np.triu_indices(n, 1)

    # -- equality-constrained minimiser on a working set ----------------------------------
    def _factor(self, free: np.ndarray) -> tuple[np.ndarray, np.ndarray] | None:
        key = free.tobytes()
        if key in self._factors:
            self._factors.move_to_end(key)
            return self._factors[key]
        stations = self._station[free]
        factor = None
        if stations.size and np.ptp(stations) > 0.0:
            rows = self.equality.shape[0]
            e_free = self.equality[:, free]
            kkt = np.zeros((stations.size + rows, stations.size + rows))
            kkt[: stations.size, : stations.size] = self.hessian[np.ix_(free, free)]
            kkt[: stations.size, stations.size :] = e_free.T
            kkt[stations.size :, : stations.size] = e_free
            factor = lu_factor(kkt, check_finite=False)
        # None marks a rank-deficient E[:, free] (all free columns at one station).
        self._factors[key] = factor
        if len(self._factors) > CACHE_SIZE:
            self._factors.popitem(last=False)
        return factor

    def _minimiser(
        self, working: np.ndarray, linear: np.ndarray, target: np.ndarray
    ) -> tuple[np.ndarray, np.ndarray] | None:
        """x (zero on ``working``) and mu minimising on E x = t, or None if E[:, free] is rank-deficient."""
        free = ~working
        factor = self._factor(free)
        if factor is None:
            return None
        solved = lu_solve(factor, np.concatenate([-linear[free], target]), check_finite=False)
        x = np.zeros(self.size)
        count = int(free.sum())
        x[free] = solved[:count]
        return x, solved[count:]

    def _gaps(self, x: np.ndarray, mu: np.ndarray, linear: np.ndarray) -> np.ndarray:
        """Bound multipliers H x + c + E'mu: gaps of the open contacts, m."""
        return self.hessian @ x + linear + self.equality.T @ mu

    # -- a feasible start ---------------------------------------------------------------
    def _vertex(self, linear: np.ndarray, target: np.ndarray) -> np.ndarray | None:
        """A feasible point with two nonzero entries (a vertex), the one of least objective.

        With two equality rows a feasible set that is not empty has such a vertex unless the
        target is parallel to a single column (Caratheodory); then None.
        """
        i, j = self._pairs
        e = self.equality
        det = e[0, i] * e[1, j] - e[0, j] * e[1, i]
        ok = np.abs(det) > 1e-12 * np.abs(e[1]).max()
        safe = np.where(ok, det, 1.0)
        xi = (target[0] * e[1, j] - target[1] * e[0, j]) / safe
        xj = (e[0, i] * target[1] - e[1, i] * target[0]) / safe
        ok &= ((xi >= 0.0) | ~self.bounded[i]) & ((xj >= 0.0) | ~self.bounded[j])
        if not ok.any():
            return None
        h = self.hessian
        objective = (
            0.5 * (h[i, i] * xi**2 + 2.0 * h[i, j] * xi * xj + h[j, j] * xj**2) + linear[i] * xi + linear[j] * xj
        )
        best = int(np.flatnonzero(ok)[np.argmin(objective[ok])])
        x = np.zeros(self.size)
        x[i[best]], x[j[best]] = xi[best], xj[best]
        return x

    def _start(self, linear: np.ndarray, target: np.ndarray) -> np.ndarray:
        x = self._vertex(linear, target)
        if x is None:
            bounds = [(0.0, None) if b else (None, None) for b in self.bounded]
            start = linprog(np.zeros(self.size), A_eq=self.equality, b_eq=target, bounds=bounds, method="highs")
            if start.status != 0:
                raise _infeasible()
            x = np.where(self.bounded, np.maximum(start.x, 0.0), start.x)
        return x

    # -- the solution -------------------------------------------------------------------
    def solve(self, linear: np.ndarray, target: np.ndarray) -> tuple[np.ndarray, np.ndarray, int]:
        """Minimiser x, equality multipliers mu (E'mu enters the stationarity as + E'mu), iterations.

        Parameters
        ----------
        linear : ndarray (n,)
            c: gap of each contact column under the loads alone, m.
        target : ndarray (2,)
            t: the reactions' total force (N) and moment (N m).

        Returns
        -------
        x : ndarray (n,)
            Contact forces, N (zero for an open contact).
        mu : ndarray (2,)
            The rigid line (a in m, b in rad) that the multipliers of E x = t are.
        iterations : int
            Equality-constrained solves of the active-set phase (1 when a guessed working
            set is optimal at once).
        """
        bounded = self.bounded
        force_scale = max(1.0, float(np.abs(target).max()))
        start: tuple[np.ndarray, np.ndarray] | None = None
        guesses = [self._default] if self._last is None else [self._last, self._default]
        if len(guesses) == 2 and np.array_equal(guesses[0], guesses[1]):
            guesses.pop()
        for guess in guesses:
            found = self._minimiser(guess, linear, target)
            if found is None:
                continue
            x, mu = found
            if np.all(x[bounded] >= 0.0):
                gaps = self._gaps(x, mu, linear)
                if np.all(gaps[guess] >= -GAP_TOLERANCE):
                    self._last = guess.copy()
                    return x, mu, 1
                if start is None:  # feasible, not optimal: a good start for the iteration
                    start = (x, guess.copy())
        if start is not None:
            x, working = start
        else:
            x = self._start(linear, target)
            working = bounded & (x <= 1e-12 * max(1.0, float(np.abs(x).max())))
            x[working] = 0.0
        n = self.size
        for iteration in range(1, 20 * n + 50):
            found = self._minimiser(working, linear, target)
            if found is None:  # E[:, free] rank-deficient (all free columns at one station)
                mu, step = self._least_squares_step(x, working, linear)
                minimiser = x
            else:
                minimiser, mu = found
                step = minimiser - x
            if np.abs(step).max() <= 1e-11 * force_scale:
                gaps = self._gaps(x, mu, linear)
                candidates = np.flatnonzero(working & (gaps < -GAP_TOLERANCE))
                if candidates.size == 0:
                    # Return the minimiser of the final working set, not the iterate it was
                    # reached by: the result then depends on the contact set alone.
                    x = minimiser
                    x[bounded] = np.maximum(x[bounded], 0.0)
                    self._last = working.copy()
                    return x, mu, iteration
                working[candidates[np.argmin(gaps[candidates])]] = False
                continue
            x = _step_to_bound(x, step, ~working & bounded & (step < 0), working)
        raise SolverFailure("alignment contact iteration did not terminate")  # pragma: no cover

    def _least_squares_step(
        self, x: np.ndarray, working: np.ndarray, linear: np.ndarray
    ) -> tuple[np.ndarray, np.ndarray]:
        """The reference's least-squares step for a rank-deficient KKT matrix."""
        free = ~working
        rows = self.equality.shape[0]
        g = self.hessian @ x + linear
        kkt = np.block(
            [
                [self.hessian[np.ix_(free, free)], self.equality[:, free].T],
                [self.equality[:, free], np.zeros((rows, rows))],
            ]
        )
        solved = np.linalg.lstsq(kkt, np.concatenate([-g[free], np.zeros(rows)]), rcond=None)[0]
        step = np.zeros(self.size)
        count = int(free.sum())
        step[free] = solved[:count]
        return solved[count:], step


def _step_to_bound(x: np.ndarray, step: np.ndarray, blocking: np.ndarray, working: np.ndarray) -> np.ndarray:
    """``x + alpha * step`` with the largest ``alpha <= 1`` that keeps the ``blocking``
    variables (those the step drives down) at or above zero; the first one to reach zero
    is set to exactly zero and joins the ``working`` set (changed in place)."""
    alpha, block = 1.0, -1
    if blocking.any():
        ratios = -x[blocking] / step[blocking]
        k = int(np.argmin(ratios))
        if ratios[k] < 1.0:
            alpha, block = float(ratios[k]), int(np.flatnonzero(blocking)[k])
    x = x + alpha * step
    if block >= 0:
        x[block] = 0.0
        working[block] = True
    return x
