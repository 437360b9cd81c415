"""Elastohydrodynamic shaft alignment: the shaft line solved together with its bearing films.

A bearing marked hydrodynamic is supported by its film, not by a point: the shaft's elastic
line across the bearing is the journal centre line the film solver takes (a bent journal),
and the film's pressure acts back on the shaft as a distributed load, applied as the
consistent nodal forces and moments of the beam elements across the bearing (docs/theory.md,
"Elastohydrodynamic alignment"). Every other bearing keeps its point, spring or multi-point
model with lift-off.

Method. The unknowns are the shaft's degrees of freedom across the film bearings, ``s``
(deflection and rotation of every node of the elements the bearing covers, both planes).
For given ``s`` the film gives its nodal forces ``f(s)`` and stiffness ``df/ds`` (the film
solver's own frozen-set linearisation, one triangular solve per degree of freedom); the rest
of the line is the existing contact problem (:class:`~shaftline.shaft.alignment.AlignmentModel`)
with those forces applied. So that this inner problem keeps its supports when a film bearing
is one of only two (a mechanism otherwise), each film bearing is also held there by auxiliary
two-sided springs ``k0`` at its points whose force the outer iteration adds back exactly:

    s = G( f(s) + K0 (s - s_ref) ),

``G`` the inner alignment (affine while its contact set holds). Newton's method on
``R(s) = s - G(...)`` uses ``dR/ds = I - dG/df (df/ds + K0)``, with ``dG/df`` from
:meth:`AlignmentModel.displacement_response`; steps keep the film above its floor (fraction
to the boundary) and lower ``|R|`` (backtracking). At convergence ``s = G(...)`` and the
springs carry nothing: the film alone supports the shaft there.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass, replace

import numpy as np

from shaftline.errors import InputError, SolverFailure
from shaftline.film.bearing import FilmLoad, JournalBearing, LinerConvergenceError
from shaftline.shaft.alignment import AlignmentModel, ConditionResult
from shaftline.shaft.film_supports import (
    CoupledResult,
    CouplingOptions,
    FilmBearingResult,
    FilmSupport,
    film_coefficients,
    hermite_shape,
    plane_support_point,
)
from shaftline.shaft.film_tangent import tangent_influence
from shaftline.shaft.model import Condition, ShaftLine

__all__ = [
    "CouplingOptions",
    "CoupledAlignment",
    "CoupledResult",
    "FilmBearingResult",
    "FilmSupport",
    "film_coefficients",
    "hermite_shape",
]


#: Force mismatch (share of the film's force, :meth:`CoupledAlignment._force_residual`) above
#: which a stalled film at its floor is out of equilibrium with the shaft and grounds: 1 %, far
#: above the converged solutions' 1e-6 and far below the 1.6-31 (160-3100 %) of the films
#: that ground in the tests and examples (docs/theory.md Sect. 10.1, "Contact fall-back").
GROUNDED_FORCE_MISMATCH = 1e-2


def _liner_trials_note(failed: int) -> str:
    """The message's note on line-search trials rejected because an elastic liner did not settle."""
    if not failed:
        return ""
    trials = f"{failed} line-search trial{'s' * (failed != 1)}"
    were = "were" if failed != 1 else "was"
    return (
        f"; {trials} asked more of the elastic liner than it holds (its film-liner iteration did not "
        f"settle) and {were} rejected as a film cutting the bore"
    )


@dataclass(eq=False)
class _Film:
    """What the solver keeps for one film bearing."""

    support: FilmSupport
    index: int  # in line.bearings
    bearing: JournalBearing
    dofs: np.ndarray  # global dof numbers (per plane) of the nodes the bearing covers
    shape: np.ndarray  # (nz, len(dofs)) Hermite map dofs -> centre line at the film stations
    points: np.ndarray  # support-point indices of its auxiliary springs (inner model)
    point_dofs: np.ndarray  # positions in ``dofs`` of those points' deflections
    spring: float  # auxiliary spring stiffness per point, N/m
    aft_edge: float


@dataclass(eq=False)
class _Iterate:
    """The coupled state at one ``s``: films, inner alignment and residual."""

    s: np.ndarray  # (2, total dofs): vertical and horizontal
    loads: list[FilmLoad]
    inner: ConditionResult
    image: np.ndarray  # G(...) at the same dofs
    residual: np.ndarray
    norm: float


class CoupledAlignment:
    """A shaft line whose hydrodynamic bearings are supported by their films.

    Parameters
    ----------
    line : ShaftLine
        The line as for :class:`~shaftline.shaft.alignment.AlignmentModel`; the bearings named
        in ``films`` are solved with their film instead of their declared support (which
        stays the model of the comparison "point supports").
    films : sequence of FilmSupport
    options : CouplingOptions

    Raises
    ------
    InputError
        ``films[k].bearing`` naming no bearing, or a bearing with ``support = "spring"``;
        ``films[k].problem.geometry.length`` differing from the bearing's length;
        ``films[k].problem.geometry.bent_journal`` set; ``films[k].problem.options.axial_nodes``
        for a film grid coarser than the shaft elements across the bearing.
    """

    def __init__(
        self,
        line: ShaftLine,
        films: tuple[FilmSupport, ...] | list[FilmSupport],
        options: CouplingOptions | None = None,
    ) -> None:
        self.line = line
        self.options = options or CouplingOptions()
        self.point_model = AlignmentModel(line)
        names = [b.name for b in line.bearings]
        seen: set[str] = set()
        for k, support in enumerate(films):
            where = f"films[{k}]"
            if support.bearing not in names:
                raise InputError(f"{where}.bearing", support.bearing, "", "the name of a bearing: " + ", ".join(names))
            if support.bearing in seen:
                raise InputError(f"{where}.bearing", support.bearing, "", "a bearing not given a film twice")
            seen.add(support.bearing)
            bearing = line.bearings[names.index(support.bearing)]
            if bearing.support == "spring":
                raise InputError(
                    f"{where}.bearing",
                    support.bearing,
                    "",
                    'a bearing with support "point" or "multi_point": a film is the support itself, '
                    "not a spring (give the liner's compliance to the film instead)",
                )
            geometry = support.problem.geometry
            if abs(geometry.length - bearing.length) > 1e-6 * bearing.length:
                raise InputError(
                    f"{where}.problem.geometry.length", geometry.length, "m", f"the bearing's length {bearing.length}"
                )
            if geometry.bent_journal is not None:
                raise InputError(
                    f"{where}.problem.geometry.bent_journal",
                    "given",
                    "",
                    "none: the shaft's elastic line is the journal",
                )
            if not 2 <= int(support.elements) <= 50:
                raise InputError(f"{where}.elements", support.elements, "", "an integer in [2, 50]")
        self._supports = tuple(films)
        self._build()

    # -- set-up ----------------------------------------------------------------------------
    def _inner_line(self, springs: dict[str, float]) -> ShaftLine:
        bearings = []
        film_of = {f.bearing: f for f in self._supports}
        for bearing in self.line.bearings:
            support = film_of.get(bearing.name)
            if support is None:
                bearings.append(bearing)
                continue
            c = support.problem.geometry.radial_clearance
            bearings.append(
                replace(
                    bearing,
                    support="multi_point",
                    points=int(support.elements),
                    stiffness=springs[bearing.name],
                    one_sided=False,
                    vertical_clearance=math.inf,
                    offset_y=bearing.offset_y + c,
                )
            )
        return replace(self.line, bearings=tuple(bearings))

    def _build(self) -> None:
        base = self.point_model.solve_condition(self.line.all_conditions()[0])
        springs = {}
        for support in self._supports:
            c = support.problem.geometry.radial_clearance
            result = base.bearing(support.bearing)
            # About the film's own stiffness (load over a share of the clearance): the outer
            # Newton iteration does not depend on it, the conditioning of its matrix does.
            load = max(math.hypot(result.reaction_y, result.reaction_z), 1e3)
            springs[support.bearing] = load / (0.5 * c) / support.elements
        self.model = AlignmentModel(self._inner_line(springs))
        mesh = self.model.mesh
        self._films: list[_Film] = []
        names = [b.name for b in self.line.bearings]
        for support in self._supports:
            index = names.index(support.bearing)
            bearing = self.line.bearings[index]
            film = JournalBearing.from_problem(support.problem)
            aft = bearing.x - 0.5 * bearing.length
            stations = aft + film.axial_stations
            first = int(np.clip(np.searchsorted(mesh.x, stations[0], side="right") - 1, 0, mesh.nodes - 2))
            last = int(np.clip(np.searchsorted(mesh.x, stations[-1], side="left"), first + 1, mesh.nodes - 1))
            nodes = np.arange(first, last + 1)
            element_length = float(np.max(np.diff(mesh.x[nodes])))
            spacing = film.axial_stations[1] - film.axial_stations[0]
            if spacing > element_length * (1 + 1e-9):
                raise InputError(
                    f"films[{self._supports.index(support)}].problem.options.axial_nodes",
                    support.problem.options.axial_nodes,
                    "",
                    f"a film grid at least as fine as the shaft elements across the bearing "
                    f"({element_length:.4g} m): >= {math.ceil(bearing.length / element_length) + 1} nodes",
                )
            dofs = np.stack([2 * nodes, 2 * nodes + 1], axis=1).ravel()
            shape = hermite_shape(mesh.x[nodes], stations)
            points = np.flatnonzero(self.model.supports.bearing == index)
            point_nodes = self.model.supports.node[points]
            point_dofs = np.searchsorted(dofs, 2 * point_nodes)
            if not np.array_equal(dofs[point_dofs], 2 * point_nodes):
                raise RuntimeError("film support points off the bearing's nodes")  # a meshing bug
            self._films.append(
                _Film(support, index, film, dofs, shape, points, point_dofs, springs[support.bearing], aft)
            )
        self._offsets = [np.concatenate([[0], np.cumsum([f.dofs.size for f in self._films])])]

    # -- pieces of the iteration ---------------------------------------------------------
    def _slices(self) -> list[slice]:
        edges = self._offsets[0]
        return [slice(int(a), int(b)) for a, b in zip(edges[:-1], edges[1:], strict=True)]

    def _bore_reference(self, film: _Film, condition: Condition) -> tuple[np.ndarray, np.ndarray]:
        """Nominal bore centre line at the film stations (y, z), m: offset, clearance and slope."""
        bearing = self.line.bearings[film.index]
        x = film.aft_edge + film.bearing.axial_stations
        c = film.support.problem.geometry.radial_clearance
        y = bearing.offset_y + condition.offsets_y.get(bearing.name, 0.0) + c + bearing.slope * (x - bearing.x)
        z = np.full(x.size, bearing.offset_z + condition.offsets_z.get(bearing.name, 0.0))
        return y, z

    def _centre_lines(self, s: np.ndarray, condition: Condition) -> list[tuple[np.ndarray, np.ndarray]]:
        lines = []
        for film, part in zip(self._films, self._slices(), strict=True):
            ref_y, ref_z = self._bore_reference(film, condition)
            lines.append((film.shape @ s[0, part] - ref_y, film.shape @ s[1, part] - ref_z))
        return lines

    def _min_film_share(self, s: np.ndarray, condition: Condition) -> float:
        """Smallest film over all film bearings less its floor, as a share of the clearance."""
        shares = []
        for film, (cy, cz) in zip(self._films, self._centre_lines(s, condition), strict=True):
            c = film.support.problem.geometry.radial_clearance
            # The bearing's own floor: lower with rough surfaces (their asperities carry load).
            floor = film.bearing.film_floor / c
            shares.append(film.bearing.min_film_of_line(cy, cz) / c - floor)
        return min(shares)

    def _evaluate(self, s: np.ndarray, condition: Condition) -> _Iterate:
        mesh = self.model.mesh
        extra = np.zeros((2, 2 * mesh.nodes))
        loads = []
        oy, oz = self.model._offsets(condition)
        offsets = np.stack([oy, oz])
        for film, part, (cy, cz) in zip(self._films, self._slices(), self._centre_lines(s, condition), strict=True):
            k = film.dofs.size
            directions = np.zeros((2 * k, 2, cy.size))
            directions[:k, 0] = film.shape.T
            directions[k:, 1] = film.shape.T
            load = film.bearing.film_load(cy, cz, directions)
            loads.append(load)
            for plane in range(2):
                nodal = film.shape.T @ load.row_force[plane]
                # The auxiliary springs' force, added back (see the module docstring).
                correction = np.zeros(k)
                deflection = s[plane, part][film.point_dofs]
                correction[film.point_dofs] = film.spring * (deflection - offsets[plane, film.points])
                np.add.at(extra[plane], film.dofs, nodal + correction)
        inner = self.model.solve_condition(condition, extra_forces=(extra[0], extra[1]))
        image = np.zeros_like(s)
        for film, part in zip(self._films, self._slices(), strict=True):
            v = np.empty(2 * mesh.nodes)
            w = np.empty(2 * mesh.nodes)
            v[0::2], v[1::2] = inner.deflection_y, inner.rotation_y
            w[0::2], w[1::2] = inner.deflection_z, inner.rotation_z
            image[0, part] = v[film.dofs]
            image[1, part] = w[film.dofs]
        residual = s - image
        return _Iterate(s, loads, inner, image, residual, self._norm(residual))

    def _scale(self) -> np.ndarray:
        """Weights making a dof mismatch a share of the clearance (rotations times the length)."""
        weights = []
        for film in self._films:
            c = film.support.problem.geometry.radial_clearance
            length = film.support.problem.geometry.length
            w = np.empty(film.dofs.size)
            w[0::2] = 1.0 / c
            w[1::2] = length / c
            weights.append(w)
        return np.concatenate(weights)

    def _norm(self, residual: np.ndarray) -> float:
        return float(np.max(np.abs(residual * self._scale()[None, :])))

    def _jacobian(self, iterate: _Iterate) -> tuple[np.ndarray, np.ndarray]:
        """d R / d s, both planes stacked: (2 m, 2 m), m the film dofs per plane; and the film
        (plus spring) stiffness it is made of."""
        mesh = self.model.mesh
        m = iterate.s.shape[1]
        stiffness = np.zeros((2 * m, 2 * m))  # d (nodal film force + spring correction) / d s
        columns = np.zeros((2, 2 * mesh.nodes, m))  # unit nodal forces at the film dofs, per plane
        for film, part, load in zip(self._films, self._slices(), iterate.loads, strict=True):
            k = film.dofs.size
            for plane in range(2):
                rows = slice(plane * m + part.start, plane * m + part.stop)
                for other in range(2):
                    cols = slice(other * m + part.start, other * m + part.stop)
                    derivative = load.derivative[plane][:, other * k : (other + 1) * k]
                    stiffness[rows, cols] = film.shape.T @ derivative
                diagonal = plane * m + part.start + film.point_dofs
                stiffness[diagonal, diagonal] += film.spring
                columns[plane, film.dofs, np.arange(part.start, part.stop)] = 1.0
        response = np.zeros((2 * m, 2 * m))
        for plane in range(2):
            u = self.model.displacement_response(iterate.inner, columns[plane], vertical=plane == 0)
            picked = np.concatenate([u[film.dofs] for film in self._films])
            response[plane * m : (plane + 1) * m, plane * m : (plane + 1) * m] = picked
        return np.eye(2 * m) - response @ stiffness, stiffness

    def _start(self, condition: Condition, points: ConditionResult) -> np.ndarray:
        """Journal lines from each film's own equilibrium under its point-support reaction and
        relative slope (the seed's uncoupled analysis), as nodal dofs."""
        mesh = self.model.mesh
        total = self._offsets[0][-1]
        s = np.zeros((2, total))
        for film, part in zip(self._films, self._slices(), strict=True):
            bearing = self.line.bearings[film.index]
            result = points.bearing(bearing.name)
            load_y, load_z = -result.reaction_y, -result.reaction_z
            if math.hypot(load_y, load_z) < 1.0:
                load_y = -1.0
            c = film.support.problem.geometry.radial_clearance
            tilt = result.relative_slope
            try:
                found = film.bearing.equilibrium(load_y, load_z, tilt_y=tilt)
                position = found.state.position
            except InputError:  # the point model's slope does not fit the clearance
                position = film.bearing.initial_position(load_y, load_z)
            ref_y = bearing.offset_y + condition.offsets_y.get(bearing.name, 0.0) + c
            ref_z = bearing.offset_z + condition.offsets_z.get(bearing.name, 0.0)
            x = mesh.x[film.dofs[0::2] // 2]
            arm = x - bearing.x
            s[0, part][0::2] = ref_y + bearing.slope * arm + position.ey + position.tilt_y * arm
            s[0, part][1::2] = bearing.slope + position.tilt_y
            s[1, part][0::2] = ref_z + position.ez + position.tilt_z * arm
            s[1, part][1::2] = position.tilt_z
        return s

    # -- solution --------------------------------------------------------------------------
    def solve(
        self,
        condition: Condition | None = None,
        progress: Callable[[int, float], None] | None = None,
        initial: CoupledResult | None = None,
    ) -> CoupledResult:
        """Solve one condition (default: the line's first) with the film bearings coupled.

        Parameters
        ----------
        condition : Condition, optional
        progress : callable, optional
            Called after each Newton iteration with its number and the film mismatch (share
            of the clearance).
        initial : CoupledResult, optional
            A solution of this model to start from (a nearby speed, load or condition);
            otherwise each film starts from its own equilibrium under its point-support
            reaction. The solution does not depend on the start, only the iterations do.
        """
        condition = condition or self.line.all_conditions()[0]
        points = self.point_model.solve_condition(condition)
        if initial is not None and initial.dofs.shape == (2, int(self._offsets[0][-1])):
            s = initial.dofs.copy()
        else:
            s = self._start(condition, points)
        if self._min_film_share(s, condition) <= 0.0:
            s = self._pulled_inside(s, condition)
        current, solutions = self._first_iterate(s, condition)
        history = [current.norm]
        iterations = 0
        converged = False
        force_residual = math.inf
        message = ""
        failed_trials = 0
        options = self.options
        while True:
            jacobian, stiffness = self._jacobian(current)
            force_residual = self._force_residual(current, stiffness)
            if current.norm <= options.film_tolerance and force_residual <= options.force_tolerance:
                converged = True
                break
            if iterations >= options.max_iterations:
                message = (
                    f"not converged in {iterations} iterations: film mismatch {current.norm:.3g} of the clearance, "
                    f"force mismatch {force_residual:.3g}; raise max_iterations or the tolerances, "
                    "or refine the film grid"
                )
                break
            iterations += 1
            flat = np.concatenate([current.residual[0], current.residual[1]])
            try:
                step = np.linalg.solve(jacobian, -flat).reshape(2, -1)
            except np.linalg.LinAlgError:
                message = "the coupled Jacobian is singular (a mechanism): check the supports"
                break
            accepted, trials, failed = self._line_search(current, step, condition)
            solutions += trials
            failed_trials += failed
            if accepted is None:
                mismatches = self._film_force_mismatches(current, stiffness)
                grounded = self._grounded(current.s, step, mismatches, condition)
                if grounded:
                    spent = (iterations, solutions * len(self._films))
                    return self._fall_back(
                        grounded, current, points, condition, progress, spent, mismatches, failed_trials
                    )
                message = (
                    f"the coupled iteration stalled at a film mismatch of {current.norm:.3g} of the clearance, "
                    f"force mismatch {force_residual:.3g}" + _liner_trials_note(failed_trials)
                )
                break
            current = accepted
            history.append(current.norm)
            if progress is not None:
                progress(iterations, current.norm)
        result = self._result(
            current,
            points,
            converged,
            iterations,
            solutions * len(self._films),
            history,
            force_residual,
            message,
            condition,
        )
        if not converged:
            return result
        influence = tangent_influence(
            self.model, current.inner, self._films, self._slices(), jacobian, stiffness, condition.name
        )
        return replace(result, influence=influence)

    def _line_search(
        self, current: _Iterate, step: np.ndarray, condition: Condition
    ) -> tuple[_Iterate | None, int, int]:
        """The first iterate along ``step`` from ``current`` that lowers the film mismatch, the
        step halved from where the film keeps a fifth of its room (fraction to the boundary);
        with the trials evaluated and those an elastic liner did not settle on."""
        trials = failed = 0
        alpha = 1.0
        room = self._min_film_share(current.s, condition)
        while alpha > 1e-6 and self._min_film_share(current.s + alpha * step, condition) < 0.2 * room:
            alpha *= 0.5
        while alpha > 1e-6:
            try:
                trial: _Iterate | None = self._evaluate(current.s + alpha * step, condition)
            except LinerConvergenceError:
                # The trial asks more of an elastic liner than it holds (its film-liner
                # iteration does not settle): rejected like a film cutting the bore.
                trial = None
                failed += 1
            trials += 1
            if trial is not None and trial.norm < (1.0 - 1e-4 * alpha) * current.norm:
                return trial, trials, failed
            alpha *= 0.5
        return None, trials, failed

    def _grounded(self, s: np.ndarray, step: np.ndarray, mismatches: list[float], condition: Condition) -> list[int]:
        """Film bearings (indices into the films) that cannot carry their share, after a stall.

        A film is grounded when the stalled iteration leaves it (1) within twice its floor,
        (2) with the Newton step, the linearised equilibrium of shaft and film, taking it
        below its floor (the shaft asks for a thinner film than the film model may give:
        edge loading, or asperities at their Greenwood-Tripp cap), and (3) out of equilibrium
        with the shaft: its force would change by more than :data:`GROUNDED_FORCE_MISMATCH`
        of itself to follow the shaft's line. A film near its floor that carries its share (a
        lined or rough film's end rows sit there) stalls as "not converged" instead.
        docs/theory.md Sect. 10.1, "Contact fall-back"."""
        grounded = []
        lines = zip(self._centre_lines(s, condition), self._centre_lines(s + step, condition), strict=True)
        for k, (film, (now, after)) in enumerate(zip(self._films, lines, strict=True)):
            floor = film.bearing.film_floor
            # Within the floor's own size above it (a rough film's floor is below the mean plane).
            near = film.bearing.min_film_of_line(*now) <= floor + abs(floor)
            below = film.bearing.min_film_of_line(*after) < floor
            if near and below and mismatches[k] > GROUNDED_FORCE_MISMATCH:
                grounded.append(k)
        return grounded

    def _fall_back(
        self,
        grounded: list[int],
        last: _Iterate,
        points: ConditionResult,
        condition: Condition,
        progress: Callable[[int, float], None] | None,
        spent: tuple[int, int] = (0, 0),
        mismatches: list[float] | None = None,
        failed_trials: int = 0,
    ) -> CoupledResult:
        """Solve again with the grounded films as contact at their bore: a multi-point support
        along the bore bottom with the top of the bore as a second contact (edge loading).

        ``spent``: the Newton iterations and film solutions before the films grounded, counted
        in the result's with those of the solution after it; ``mismatches``: each film's force
        mismatch at the stall (:meth:`_film_force_mismatches`), quoted in the message;
        ``failed_trials``: line-search trials whose film-liner iteration did not settle (said in
        the message: the liner could not hold what those trials asked)."""
        line = self.line
        bearings = list(line.bearings)
        for k in grounded:
            film = self._films[k]
            geometry = film.support.problem.geometry
            bore_y, _ = geometry.bore_centre_line(np.array([0.0, geometry.length]))
            bearing = bearings[film.index]
            bearings[film.index] = replace(
                bearing,
                support="multi_point",
                points=int(film.support.elements),
                one_sided=True,
                vertical_clearance=2.0 * geometry.radial_clearance,
                # The chord of a slope-bored bore: its knuckles are not modelled by the fall-back.
                slope=bearing.slope + float(bore_y[1] - bore_y[0]) / geometry.length,
                offset_y=bearing.offset_y + float(np.mean(bore_y)),
            )
        remaining = [f.support for k, f in enumerate(self._films) if k not in grounded]
        contact_line = replace(line, bearings=tuple(bearings))
        if remaining:
            inner = CoupledAlignment(contact_line, remaining, self.options).solve(condition, progress)
            result_condition = inner.condition
            films = list(inner.films)
            converged, iterations, solutions = inner.converged, inner.iterations, inner.film_solutions
            history, force_residual = inner.residual_history, inner.force_residual
        else:
            result_condition = AlignmentModel(contact_line).solve_condition(condition)
            films = []
            converged, iterations, solutions, history, force_residual = True, 0, 0, [], 0.0
        iterations, solutions = iterations + spent[0], solutions + spent[1]
        own = self._result(last, points, False, 0, 0, [], math.inf, "", condition)
        for k in grounded:
            films.append(replace(own.films[k], contact=True))
        order = {b.name: i for i, b in enumerate(line.bearings)}
        films.sort(key=lambda f: order[f.name])
        names = ", ".join(self._films[k].support.bearing for k in grounded)
        shortfall = ""
        if mismatches is not None:
            worst = max(mismatches[k] for k in grounded)
            shortfall = f" (the shaft's line asks for a film below the floor; force mismatch {worst:.3g})"
        message = (
            f"film at its floor in {names}: the film cannot carry its share there{shortfall}, so the bearing was "
            "solved as contact at the bore (edge loading); the film results are those at the last journal line "
            "reached, at the floor (not an equilibrium)"
        ) + _liner_trials_note(failed_trials)
        return CoupledResult(
            condition=result_condition,
            films=films,
            point_supports=self._against_bores(points),
            converged=converged,
            iterations=iterations,
            film_solutions=solutions,
            residual_history=history,
            force_residual=force_residual,
            message=message,
        )

    def _first_iterate(self, s: np.ndarray, condition: Condition) -> tuple[_Iterate, int]:
        """The iterate at the starting lines, and the film solutions it took.

        A start whose elastic liner does not settle (its film-liner iteration fails, as for a
        film cutting the bore) is moved towards the bore centres as :meth:`_pulled_inside`
        does, a fifth of the way at a time, until it settles.

        Raises
        ------
        SolverFailure
            When no start within 20 such moves settles (naming the liners).
        """
        centre = self._bore_centres(condition)
        for attempt in range(1, 21):
            try:
                return self._evaluate(s, condition), attempt
            except LinerConvergenceError:
                s = centre + 0.8 * (s - centre)
        names = ", ".join(f.support.bearing for f in self._films if f.support.problem.geometry.liner is not None)
        raise SolverFailure(
            f"film-supported alignment: the elastic liner of {names} does not settle at any starting line "
            "(its film-liner iteration fails); try a stiffer or thinner liner, or a finer film grid"
        )

    def _bore_centres(self, condition: Condition) -> np.ndarray:
        """Nodal dofs of every film bearing's journal on its bore centre line (the film open
        all round: eccentricity zero)."""
        centre = np.zeros((2, int(self._offsets[0][-1])))
        for film, part in zip(self._films, self._slices(), strict=True):
            bearing = self.line.bearings[film.index]
            c = film.support.problem.geometry.radial_clearance
            x = self.model.mesh.x[film.dofs[0::2] // 2]
            centre[0, part][0::2] = (
                bearing.offset_y + condition.offsets_y.get(bearing.name, 0.0) + c + bearing.slope * (x - bearing.x)
            )
            centre[0, part][1::2] = bearing.slope
            centre[1, part][0::2] = bearing.offset_z + condition.offsets_z.get(bearing.name, 0.0)
        return centre

    def _pulled_inside(self, s: np.ndarray, condition: Condition) -> np.ndarray:
        """Move each journal line towards its bore centre until every film is open."""
        centre = self._bore_centres(condition)
        for _ in range(60):
            if self._min_film_share(s, condition) > 0.05:
                return s
            s = centre + 0.8 * (s - centre)
        return centre

    def _force_residual(self, iterate: _Iterate, stiffness: np.ndarray) -> float:
        """Largest change of a film's resultant that moving it onto the shaft's line would cause,
        as a share of that resultant."""
        return max(self._film_force_mismatches(iterate, stiffness))

    def _film_force_mismatches(self, iterate: _Iterate, stiffness: np.ndarray) -> list[float]:
        """Per film, the change of its resultant that moving it onto the shaft's line would
        cause, as a share of that resultant."""
        m = iterate.s.shape[1]
        flat = np.concatenate([iterate.residual[0], iterate.residual[1]])
        change = stiffness @ flat  # nodal film force change (springs: they cancel at the fixed point)
        shares = []
        for film, part, load in zip(self._films, self._slices(), iterate.loads, strict=True):
            spring = np.zeros(2 * m)
            for plane in range(2):
                spring[plane * m + part.start + film.point_dofs] = (
                    film.spring * flat[plane * m + part.start + film.point_dofs]
                )
            film_change = change - spring
            resultant = np.array(
                [film_change[plane * m + part.start : plane * m + part.stop][0::2].sum() for plane in range(2)]
            )
            magnitude = max(float(np.hypot(*load.row_force.sum(axis=1))), 1e-30)
            shares.append(float(np.hypot(*resultant)) / magnitude)
        return shares

    def _against_bores(self, points: ConditionResult) -> ConditionResult:
        """The point-support alignment with each film bearing's relative slope taken against
        the chord of its machined bore (the bearing's slope plus the slope-boring profile's
        chord), as the film's own: the point-support model knows only the bearing's slope, and
        "point supports vs film supports" must compare the two against the same bore."""
        bearings = list(points.bearings)
        for film in self._films:
            geometry = film.support.problem.geometry
            bore_y, _ = geometry.bore_centre_line(np.array([0.0, geometry.length]))
            chord = float(bore_y[1] - bore_y[0]) / geometry.length
            old = bearings[film.index]
            bearings[film.index] = replace(old, relative_slope=float(old.relative_slope - chord))
        return replace(points, bearings=bearings)

    def _result(
        self,
        current: _Iterate,
        points: ConditionResult,
        converged: bool,
        iterations: int,
        solutions: int,
        history: list[float],
        force_residual: float,
        message: str,
        condition: Condition,
    ) -> CoupledResult:
        inner = current.inner
        films = []
        bearings = list(inner.bearings)
        for film, load, (cy, cz) in zip(
            self._films, current.loads, self._centre_lines(current.s, condition), strict=True
        ):
            state = load.state
            geometry = film.support.problem.geometry
            z = film.bearing.axial_stations
            bore_y, bore_z = geometry.bore_centre_line(z)
            weights = np.full(z.size, z[1] - z[0])
            weights[[0, -1]] *= 0.5
            fy, fz = (float(v) for v in load.row_force.sum(axis=1))
            contact = bool(state.contact)
            coefficients_note = ""
            try:
                stiffness, damping = film_coefficients(film.bearing, cy, cz)
            except LinerConvergenceError as exc:
                # The coefficients' film-liner solve at the converged line (from its own start)
                # does not settle on a soft liner: the alignment stands without them.
                stiffness, damping = np.full((4, 4), np.nan), np.full((4, 4), np.nan)
                coefficients_note = (
                    "stiffness and damping not available: the elastic liner's film-liner iteration "
                    f"does not settle at the converged journal line (liner residual {float(exc.args[0]):.3g} "
                    "of the clearance); try a stiffer or thinner liner, or a finer film grid"
                )
            bore_chord = float(bore_y[-1] - bore_y[0]) / geometry.length
            bore_relative = float((cy[-1] - cy[0]) / geometry.length) - bore_chord
            films.append(
                FilmBearingResult(
                    name=self.line.bearings[film.index].name,
                    state=state,
                    z=z,
                    centre_y=cy,
                    centre_z=cz,
                    bore_y=bore_y,
                    bore_z=bore_z,
                    force_y=fy,
                    force_z=fz,
                    line_load=load.row_force / weights[None, :],
                    moment_y=state.moment_y,
                    moment_z=state.moment_z,
                    support_point_y=plane_support_point(fy, state.moment_y, geometry.length, math.hypot(fy, fz)),
                    support_point_z=plane_support_point(fz, state.moment_z, geometry.length, math.hypot(fy, fz)),
                    relative_slope=bore_relative,
                    contact=contact,
                    stiffness=stiffness,
                    damping=damping,
                    coefficients_note=coefficients_note,
                )
            )
            old = bearings[film.index]
            diameter = geometry.diameter
            bearing = self.line.bearings[film.index]
            bearings[film.index] = replace(
                old,
                reaction_y=fy,
                reaction_z=fz,
                mean_pressure=abs(fy) / (bearing.length * diameter),
                contact="film",
                relative_slope=float(old.shaft_slope - bearing.slope - bore_chord),
                point_reactions=(film.shape.T @ load.row_force[0])[0::2],
                point_contact=np.full(film.dofs.size // 2, "film", dtype=object),
            )
        condition_result = replace(inner, bearings=bearings)
        return CoupledResult(
            condition=condition_result,
            films=films,
            point_supports=self._against_bores(points),
            converged=converged,
            iterations=iterations,
            film_solutions=solutions,
            residual_history=history,
            force_residual=force_residual,
            message=message,
            dofs=current.s.copy(),
        )
