"""The alignment's contact QP: shaftline's active-set solvers against off-the-shelf QP solvers.

The workload is the alignment example (examples/single_screw_alignment.toml) as the pipeline
layer runs it: its 3 conditions, the influence matrix, rule checks, the offset optimisation
it asks for, sag and gap, and the jack-up. Two measurements:

1. QP level: every contact QP that run poses (recorded once, with the original solver),
   solved cold by each solver; total time over the set (median of repeats), worst
   relative error of x against the original solver, scaled by the largest |x| of the QP,
   and how many QPs end with the same contact set (which bounded x are zero).
2. End to end: ``solve_alignment`` with each solver in place of the alignment's one,
   median time, ratio to the original solver, worst relative change of any number of
   the results (scaled by the largest value of the same array) and whether every contact
   state of every bearing in every solved condition is the same.

Off-the-shelf solvers get the problem scaled to unit size (forces by the target, H by its
largest diagonal entry); daqp, which needs a positive definite H, also gets the augmented
Lagrangian term rho |E x - t|^2 / 2 (zero on the feasible set, so the minimiser is unchanged).
"+ polish" re-solves the equality-constrained problem on the contact set the solver found
(x below 1e-6 of the largest |x| counts as a closed bound) and checks the optimality
conditions; a QP failing the check is handed to shaftline's solver (counted as "fallback").
The equality multipliers (the rigid line) of an unpolished result are the least-squares
solution of the stationarity on its free variables.

Times are CPU time of this process (``time.process_time``): on the shared 2-core machine
wall time moved by a factor of 2 between runs with other work on it; the solvers here are
single-threaded at these sizes, so CPU time is what they cost.

Not installed solvers are skipped. They are measurement-only, not dependencies:
``pip install daqp proxsuite clarabel osqp``.

Run: ``PYTHONPATH=src .venv/bin/python benchmarks/bench_contact_qp.py [repeats]``
"""

from __future__ import annotations

import importlib.util
import statistics
import sys
import time
from collections.abc import Callable
from pathlib import Path
from typing import Any

import numpy as np

import shaftline.shaft.alignment as alignment
from shaftline.cases import load_case
from shaftline.shaft.capability import CAPABILITY
from shaftline.shaft.contact_qp import GAP_TOLERANCE, REGULARISATION, ContactQP, active_set_qp
from shaftline.shaft.study import solve_alignment

EXAMPLE = Path(__file__).resolve().parents[1] / "examples" / "single_screw_alignment.toml"
Solution = tuple[np.ndarray, np.ndarray, int]


class Reference:
    """The original solver (LP start, least-squares steps) behind ContactQP's interface."""

    def __init__(self, hessian: np.ndarray, equality: np.ndarray, bounded: np.ndarray) -> None:
        self.hessian, self.equality, self.bounded = hessian, equality, bounded

    def solve(self, linear: np.ndarray, target: np.ndarray) -> Solution:
        return active_set_qp(self.hessian, linear, self.equality, target, self.bounded)


class OffTheShelf:
    """Common scaling, multiplier recovery and optional polishing of a third-party solver."""

    polish = False

    def __init__(self, hessian: np.ndarray, equality: np.ndarray, bounded: np.ndarray) -> None:
        n = hessian.shape[0]
        self.scale_h = max(float(np.abs(np.diag(hessian)).max()), 1e-300)
        self.hessian = hessian + REGULARISATION * self.scale_h * np.eye(n)
        self.equality, self.bounded = equality, bounded
        self.row_scale = np.abs(equality).max(axis=1)
        self.own = ContactQP(hessian, equality, bounded)  # for polishing and fallback
        self.fallbacks = 0

    def scaled(self, linear: np.ndarray, target: np.ndarray) -> tuple[np.ndarray, ...]:
        force = max(1.0, float(np.abs(target).max()))
        h = self.hessian / self.scale_h
        g = linear / (force * self.scale_h)
        e = self.equality / self.row_scale[:, None]
        t = target / force / self.row_scale
        return h, g, e, t, np.array(force)

    def raw(self, linear: np.ndarray, target: np.ndarray) -> np.ndarray:
        raise NotImplementedError

    def solve(self, linear: np.ndarray, target: np.ndarray) -> Solution:
        x = self.raw(linear, target)
        if not self.polish:
            free = ~self.bounded | (x > 0.0)
            g = self.hessian @ x + linear
            mu = np.linalg.lstsq(self.equality[:, free].T, -g[free], rcond=None)[0]
            return x, mu, 0
        working = self.bounded & (x <= 1e-6 * max(float(np.abs(x).max()), 1e-300))
        found = self.own._minimiser(working, linear, target)
        if found is not None:
            x, mu = found
            gaps = self.own._gaps(x, mu, linear)
            if np.all(x[self.bounded] >= 0.0) and np.all(gaps[working] >= -GAP_TOLERANCE):
                return x, mu, 0
        self.fallbacks += 1
        return self.own.solve(linear, target)


class Daqp(OffTheShelf):
    def raw(self, linear: np.ndarray, target: np.ndarray) -> np.ndarray:
        import daqp

        h, g, e, t, force = self.scaled(linear, target)
        rho = 1.0
        h = h + rho * e.T @ e
        g = g - rho * e.T @ t
        n = g.size
        upper = np.concatenate([np.full(n, 1e30), t])
        lower = np.concatenate([np.where(self.bounded, 0.0, -1e30), t])
        sense = np.concatenate([np.zeros(n), np.full(t.size, 5)]).astype(np.int32)
        x, _, flag, _ = daqp.solve(h, g, e, upper, lower, sense, primal_tol=1e-10)
        return force * np.asarray(x)


class ProxQP(OffTheShelf):
    def raw(self, linear: np.ndarray, target: np.ndarray) -> np.ndarray:
        import proxsuite

        h, g, e, t, force = self.scaled(linear, target)
        lower = np.where(self.bounded, 0.0, -1e20)
        result = proxsuite.proxqp.dense.solve(
            h, g, A=e, b=t, C=None, l=None, u=None, l_box=lower, u_box=np.full(g.size, 1e20), eps_abs=1e-10
        )
        return force * np.asarray(result.x)


class Clarabel(OffTheShelf):
    def raw(self, linear: np.ndarray, target: np.ndarray) -> np.ndarray:
        import clarabel
        import scipy.sparse as sparse

        h, g, e, t, force = self.scaled(linear, target)
        bound_rows = -np.eye(g.size)[self.bounded]
        settings = clarabel.DefaultSettings()
        settings.verbose = False
        settings.tol_gap_abs = settings.tol_gap_rel = settings.tol_feas = 1e-10
        solver = clarabel.DefaultSolver(
            sparse.csc_matrix(np.triu(h)),
            g,
            sparse.csc_matrix(np.vstack([e, bound_rows])),
            np.concatenate([t, np.zeros(bound_rows.shape[0])]),
            [clarabel.ZeroConeT(t.size), clarabel.NonnegativeConeT(bound_rows.shape[0])],
            settings,
        )
        return force * np.asarray(solver.solve().x)


class Osqp(OffTheShelf):
    def raw(self, linear: np.ndarray, target: np.ndarray) -> np.ndarray:
        import osqp
        import scipy.sparse as sparse

        h, g, e, t, force = self.scaled(linear, target)
        count = int(self.bounded.sum())
        solver = osqp.OSQP()
        solver.setup(
            sparse.csc_matrix(np.triu(h)),
            g,
            sparse.csc_matrix(np.vstack([e, np.eye(g.size)[self.bounded]])),
            np.concatenate([t, np.zeros(count)]),
            np.concatenate([t, np.full(count, np.inf)]),
            verbose=False,
            eps_abs=1e-10,
            eps_rel=1e-10,
            polishing=True,
            max_iter=200_000,
        )
        return force * np.asarray(solver.solve().x)


def polished(kind: type[OffTheShelf]) -> type[OffTheShelf]:
    return type(f"{kind.__name__}Polished", (kind,), {"polish": True})


CANDIDATES: dict[str, tuple[str, type[OffTheShelf]]] = {
    "daqp": ("daqp", Daqp),
    "proxqp": ("proxsuite", ProxQP),
    "clarabel": ("clarabel", Clarabel),
    "osqp": ("osqp", Osqp),
}


def solvers() -> dict[str, Callable[..., Any]]:
    out: dict[str, Callable[..., Any]] = {"original (LP start)": Reference, "ContactQP (shaftline)": ContactQP}
    for name, (module, kind) in CANDIDATES.items():
        if importlib.util.find_spec(module) is None:
            print(f"  {name}: not installed, skipped")
            continue
        out[name] = kind
        out[f"{name} + polish"] = polished(kind)
    return out


def run_with(kind: Callable[..., Any], case: Any) -> Any:
    """solve_alignment with ``kind`` as the alignment's contact solver."""
    saved = alignment.ContactQP
    setattr(alignment, "ContactQP", kind)  # noqa: B010 (a stand-in of another type, on purpose)
    try:
        return solve_alignment(case)
    finally:
        setattr(alignment, "ContactQP", saved)  # noqa: B010


def record(case: Any) -> list[tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray, np.ndarray]]:
    """Every contact QP of the workload: (H, E, bounded, c, t)."""
    found = []

    class Recorder(Reference):
        def solve(self, linear: np.ndarray, target: np.ndarray) -> Solution:
            found.append((self.hessian, self.equality, self.bounded, linear.copy(), target.copy()))
            return super().solve(linear, target)

    run_with(Recorder, case)
    return found


def _numeric(value: Any) -> bool:
    if isinstance(value, list):
        return all(isinstance(v, (int, float)) and not isinstance(v, bool) for v in value)
    return isinstance(value, (int, float)) and not isinstance(value, bool)


def numbers(tree: Any, path: str = "") -> dict[str, np.ndarray]:
    """Numeric leaves of a summary, arrays keyed by their path."""
    out: dict[str, np.ndarray] = {}
    if isinstance(tree, dict):
        for key, value in tree.items():
            out.update(numbers(value, f"{path}.{key}"))
    elif isinstance(tree, list) and tree and all(_numeric(v) for v in tree):
        out[path] = np.asarray(tree, dtype=float)
    elif isinstance(tree, list):
        for k, value in enumerate(tree):
            out.update(numbers(value, f"{path}[{k}]"))
    elif isinstance(tree, (int, float)) and not isinstance(tree, bool):
        out[path] = np.asarray([tree], dtype=float)
    return out


def deviation(a: dict[str, np.ndarray], b: dict[str, np.ndarray]) -> float:
    """Largest |a - b| over all numbers, relative to the largest |value| of the same array
    (absolute for an array of zeros, e.g. the horizontal reactions of a vertical-only case)."""
    worst = 0.0
    for key, x in a.items():
        scale = float(np.abs(x).max()) or 1.0
        worst = max(worst, float(np.abs(x - b[key]).max()) / scale)
    return worst


def contacts(run: Any) -> list[str]:
    results = list(run.conditions) + (list(run.plan.results) if run.plan is not None else [])
    return [b.contact for r in results for b in r.bearings]


def main() -> None:
    repeats = int(sys.argv[1]) if len(sys.argv) > 1 else 7
    case = load_case(EXAMPLE)["alignment"]
    print("Contact QP of the alignment example (3 conditions, influence matrix, rules, offset")
    print("optimisation, sag/gap, jack-up)")
    kinds = solvers()
    problems = record(case)
    sizes = sorted({p[0].shape[0] for p in problems})
    print(f"\n1. QP level: {len(problems)} QPs of {sizes} variables, solved cold; total time median of {repeats}")
    reference = [active_set_qp(h, c, e, t, b) for h, e, b, c, t in problems]
    # Round-robin over the solvers so that a change of machine load hits all of them alike.
    times: dict[str, list[float]] = {name: [] for name in kinds}
    answers: dict[str, list[Solution]] = {}
    fallbacks: dict[str, int] = {}
    for _ in range(repeats):
        for name, kind in kinds.items():
            start = time.process_time()
            objects = [kind(h, e, b) for h, e, b, _, _ in problems]
            answers[name] = [o.solve(c, t) for o, (_, _, _, c, t) in zip(objects, problems, strict=True)]
            times[name].append(time.process_time() - start)
            fallbacks[name] = sum(getattr(o, "fallbacks", 0) for o in objects)
    base_time = statistics.median(times[next(iter(kinds))])
    for name, kind in kinds.items():
        median = statistics.median(times[name])
        error, same = 0.0, 0
        for (_, _, b, _, t), (x, _, _), (x_ref, _, _) in zip(problems, answers[name], reference, strict=True):
            scale = max(float(np.abs(x_ref).max()), 1e-9 * max(1.0, float(np.abs(t).max())))
            error = max(error, float(np.abs(x - x_ref).max()) / scale)
            same += bool(np.array_equal(b & (x <= 0.0), b & (x_ref <= 0.0)))
        polish = isinstance(kind, type) and issubclass(kind, OffTheShelf) and kind.polish
        print(
            f"  {name:24s} {median * 1e3:8.1f} ms  ratio {median / base_time:6.3f}  "
            f"max rel. error {error:8.1e}  same contact set {same}/{len(problems)}"
            + (f"  fallback {fallbacks[name]}" if polish else "")
        )

    print(f"\n2. End to end: solve_alignment, median of {repeats}")
    base = run_with(Reference, case)
    base_numbers, base_contacts = numbers(CAPABILITY.to_json(base)), contacts(base)
    usable, runs, failed = {}, {}, {}
    for name, kind in kinds.items():
        try:
            runs[name] = run_with(kind, case)  # warm-up, and the results compared
            usable[name] = kind
        except Exception as error:  # an inexact solver can break the jack-up's root bracket
            failed[name] = f"{type(error).__name__}: {str(error)[:60]}"
    wall: dict[str, list[float]] = {name: [] for name in usable}
    for _ in range(repeats):
        for name, kind in usable.items():
            start = time.process_time()
            run_with(kind, case)
            wall[name].append(time.process_time() - start)
    base_time = statistics.median(wall[next(iter(usable))])
    for name in kinds:
        if name in failed:
            print(f"  {name:24s} failed: {failed[name]}")
            continue
        median = statistics.median(wall[name])
        print(
            f"  {name:24s} {median * 1e3:8.1f} ms  ratio {median / base_time:6.3f}  "
            f"QP share {qp_share(kinds[name], case, repeats):4.0%}  "
            f"max rel. change {deviation(base_numbers, numbers(CAPABILITY.to_json(runs[name]))):8.1e}  "
            f"contact states same: {contacts(runs[name]) == base_contacts}"
        )


def qp_share(kind: Callable[..., Any], case: Any, repeats: int) -> float:
    """Median share of solve_alignment's time spent in the contact solver (a separate pass:
    the stopwatch around each solve is not in the medians above)."""
    spent = [0.0]

    class Timed:
        def __init__(self, *args: Any) -> None:
            self.inner = kind(*args)

        def solve(self, linear: np.ndarray, target: np.ndarray) -> Solution:
            start = time.process_time()
            try:
                return self.inner.solve(linear, target)
            finally:
                spent[0] += time.process_time() - start

    shares = []
    for _ in range(max(3, repeats // 2)):
        spent[0] = 0.0
        start = time.process_time()
        run_with(Timed, case)
        shares.append(spent[0] / (time.process_time() - start))
    return statistics.median(shares)


if __name__ == "__main__":
    main()
