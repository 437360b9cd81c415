"""Shaft alignment: elastic line, bearing reactions, slopes and influence coefficients.

Formulation (docs/theory.md, "Shaft alignment"): the shaft is pinned at two
reference support points, which makes its stiffness non-singular; ``F`` is the
flexibility at all support points for self-equilibrated loads. The reactions
``lambda >= 0`` (bottom contact, upwards; top contact, downwards, after the
vertical clearance) solve the convex quadratic programme

    min 1/2 lambda' (D' F D + C) lambda + (D' (u0 - o) + g)' lambda
    s.t. lambda >= 0 (one-sided),  sum of forces = 0,  sum of moments = 0,

whose optimality conditions are the contact conditions (gap >= 0, reaction >= 0,
gap * reaction = 0); the multipliers of the two equilibrium equations are the
rigid-body line (a + b x) added to the pinned deflection. ``C`` holds the
support compliances (bearing and foundation). The primal active-set method
(Nocedal & Wright 2006, Alg. 16.3, :mod:`shaftline.shaft.contact_qp`) solves it exactly
in a finite number of steps.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from shaftline.errors import InputError
from shaftline.shaft.contact_qp import ContactQP, active_set_qp
from shaftline.shaft.fem import Mesh, PinnedBeam, build_mesh, uniform_load_vector
from shaftline.shaft.model import Condition, ShaftLine


@dataclass(frozen=True, eq=False)
class SupportPoints:
    """All support points of the line, in the order of the bearings.

    Attributes
    ----------
    x : ndarray (m,)
        Stations, m.
    bearing : ndarray of int (m,)
        Index of the bearing each point belongs to.
    compliance : ndarray (m,)
        1 / stiffness, m/N (0 for rigid).
    clearance : ndarray (m,)
        Vertical travel to the top of the bore, m (inf: no top contact).
    one_sided : ndarray of bool (m,)
    node : ndarray of int (m,)
        Mesh node of each point.
    """

    x: np.ndarray
    bearing: np.ndarray
    compliance: np.ndarray
    clearance: np.ndarray
    one_sided: np.ndarray
    node: np.ndarray


@dataclass(frozen=True, eq=False)
class _ContactSetup:
    """The fixed parts of one plane's contact QP (see the module docstring).

    ``columns`` maps the QP variables (bottom contacts, then top contacts ``top``) to
    support-point reactions; ``gap_offset`` is the clearance of each column (0 at the bottom).
    """

    top: np.ndarray
    columns: np.ndarray
    gap_offset: np.ndarray
    hessian: np.ndarray
    equality: np.ndarray
    bounded: np.ndarray
    qp: ContactQP


@dataclass(frozen=True, eq=False)
class BearingResult:
    """Result at one bearing in one condition (SI; slopes in rad).

    Attributes
    ----------
    name : str
    reaction_y, reaction_z : float
        Support force on the shaft, N (+ up / + starboard).
    mean_pressure : float
        |reaction_y| / (L D), Pa.
    contact : str
        ``"bottom"``, ``"top"``, ``"partial"`` (multi-point) or ``"lifted"``.
    shaft_slope : float
        Slope of the shaft across the bearing, (v_fore - v_aft) / L.
    shaft_slope_at_support : float
        Tangent slope of the shaft at the (first) support point.
    relative_slope : float
        Shaft slope across the bearing less the bearing's own slope (slope boring).
    point_reactions : ndarray
        Reactions of the individual support points, N.
    point_contact : ndarray of str
        Contact state of the individual support points: ``"bottom"``, ``"top"`` or
        ``"lifted"`` (``"bottom"`` for every point of a two-sided solution).
    """

    name: str
    reaction_y: float
    reaction_z: float
    mean_pressure: float
    contact: str
    shaft_slope: float
    shaft_slope_at_support: float
    relative_slope: float
    point_reactions: np.ndarray
    point_contact: np.ndarray


@dataclass(frozen=True, eq=False)
class ConditionResult:
    """Elastic line and bearing results of one condition.

    Attributes
    ----------
    name : str
    x : ndarray (n,)
        Node stations, m.
    deflection_y, deflection_z : ndarray (n,)
        Elastic line, m.
    rotation_y, rotation_z : ndarray (n,)
        Section rotations in the vertical and horizontal planes, rad.
    moment_y, moment_z : ndarray (n,)
        Bending moments in the vertical and horizontal planes, N m (+ sagging:
        tension at the bottom / at port). Averaged at nodes where a point load
        makes them jump (use ``element_moment_y`` for the two sides).
    shear_y : ndarray (n,)
        Shear force in the vertical plane, N.
    stress : ndarray (n,)
        Largest bending stress of the combined moment, Pa.
    element_moment_y : ndarray (n-1, 2)
        Vertical-plane moment at both ends of each element, N m.
    bearings : list of BearingResult
    iterations : int
        Active-set iterations of the contact solution.
    """

    name: str
    x: np.ndarray
    deflection_y: np.ndarray
    deflection_z: np.ndarray
    rotation_y: np.ndarray
    rotation_z: np.ndarray
    moment_y: np.ndarray
    moment_z: np.ndarray
    shear_y: np.ndarray
    stress: np.ndarray
    element_moment_y: np.ndarray
    bearings: list[BearingResult]
    iterations: int

    def bearing(self, name: str) -> BearingResult:
        for result in self.bearings:
            if result.name == name:
                return result
        raise KeyError(name)


@dataclass(frozen=True, eq=False)
class InfluenceMatrix:
    """Reaction change at each bearing per unit vertical offset of each bearing.

    Attributes
    ----------
    names : list of str
    matrix : ndarray (b, b)
        ``matrix[i, j]`` = d reaction_i / d offset_j, N/m, for the contact set it was made
        for (by default all supports in contact).
    deflection : ndarray (n, b)
        ``deflection[k, j]`` = d deflection_y at node k / d offset_j, m/m, same contact set.
    kind : str
        ``"point"``: the line on its declared supports (points, springs, multi-point), symmetric
        (Maxwell-Betti); ``"film_tangent"``: the line on its bearing films, the tangent at the
        coupled equilibrium of :attr:`condition` with the films' stiffness
        (:func:`~shaftline.shaft.film_tangent.tangent_influence`), not symmetric in general.
    condition : str
        The condition the film tangent was taken in (empty for ``"point"``).
    """

    names: list[str]
    matrix: np.ndarray
    deflection: np.ndarray
    kind: str = "point"
    condition: str = ""

    @property
    def label(self) -> str:
        """Which matrix this is, in words (for tables, figures and the JSON)."""
        if self.kind == "film_tangent":
            return f"film supports: tangent at the coupled equilibrium ({self.condition}), film stiffness included"
        if self.condition:
            return f"point supports (the contact set of {self.condition})"
        return "point supports (every support in contact)"


class AlignmentModel:
    """The finite-element model of a shaft line, built once for all conditions.

    Parameters
    ----------
    line : ShaftLine
    reference_qp : bool
        Solve the contact with the original active-set solver
        (:func:`~shaftline.shaft.contact_qp.active_set_qp`: an LP start and no reuse)
        instead of :class:`~shaftline.shaft.contact_qp.ContactQP`; the same results to
        round-off, several times slower. For checking only.

    Notes
    -----
    The contact solver remembers the contact set of the last solution as its first guess
    for the next one, so a model should not be shared between threads.

    Examples
    --------
    >>> from shaftline.shaft import AlignmentModel, Bearing, ShaftLine, ShaftSegment
    >>> line = ShaftLine(
    ...     segments=(ShaftSegment(length=12.0, outer_diameter=0.5),),
    ...     bearings=(Bearing("aft", 1.0, 0.5), Bearing("mid", 6.0, 0.4), Bearing("fwd", 11.0, 0.4)),
    ... )
    >>> result = AlignmentModel(line).solve()[0]
    >>> round(sum(b.reaction_y for b in result.bearings) / 1e3, 1)  # carries its own weight, kN
    181.4
    """

    def __init__(self, line: ShaftLine, reference_qp: bool = False) -> None:
        self.line = line
        self.reference_qp = reference_qp
        self._setups: dict[bool, _ContactSetup] = {}
        diameters = [line.outer_diameter_at(b.x) for b in line.bearings]
        self._bearing_diameter = diameters  # for the mean pressures of every solution
        per_bearing = [b.support_points(d) for b, d in zip(line.bearings, diameters, strict=True)]
        stations = [np.concatenate(per_bearing)]
        for bearing in line.bearings:
            stations.append(np.array([bearing.x - 0.5 * bearing.length, bearing.x + 0.5 * bearing.length, bearing.x]))
        stations.append(np.array([p.x for p in line.point_loads] + [m.x for m in line.masses]))
        stations.append(
            np.array([d.x_start for d in line.distributed_loads] + [d.x_end for d in line.distributed_loads])
        )
        for condition in line.all_conditions():
            stations.append(np.array([p.x for p in condition.loads]))
        if line.propeller is not None:
            stations.append(np.array([max(line.propeller.x, 0.0)]))
        self.mesh: Mesh = build_mesh(line, np.concatenate(stations))
        x_points = np.concatenate(per_bearing)
        owner = np.concatenate([np.full(p.size, k) for k, p in enumerate(per_bearing)])
        compliance = []
        for bearing, points in zip(line.bearings, per_bearing, strict=True):
            stiffness = bearing.stiffness if bearing.support != "point" else math.inf
            compliance.append(np.full(points.size, 0.0 if math.isinf(stiffness) else 1.0 / stiffness))
        self.supports = SupportPoints(
            x=x_points,
            bearing=owner,
            compliance=np.concatenate(compliance),
            clearance=np.array([line.bearings[k].vertical_clearance for k in owner]),
            one_sided=np.array([line.bearings[k].one_sided for k in owner]),
            node=self.mesh.node_at(x_points),
        )
        order = np.argsort(x_points)
        self._pins = (int(self.supports.node[order[0]]), int(self.supports.node[order[-1]]))
        if self._pins[0] == self._pins[1]:
            raise InputError("bearings", len(line.bearings), "", "supports at two different stations at least")
        self.beam = PinnedBeam(self.mesh, (2 * self._pins[0], 2 * self._pins[1]))
        unit = np.zeros((2 * self.mesh.nodes, x_points.size))
        unit[2 * self.supports.node, np.arange(x_points.size)] = 1.0
        response = self.beam.solve(unit)
        self.flexibility = response[2 * self.supports.node]
        self._unit_response = response
        self._uniform = -self.mesh.weight_per_length
        # I / (D/2) at the nodes, the smaller of the two neighbouring elements (conservative).
        modulus = self.mesh.inertia / (0.5 * self.mesh.outer_diameter)
        self._section_modulus = np.concatenate(([modulus[0]], np.minimum(modulus[:-1], modulus[1:]), [modulus[-1]]))

    # -- loads ---------------------------------------------------------------------------
    def _loads(self, condition: Condition) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
        """Nodal force vectors (vertical, horizontal) and uniform loads per element (vertical, horizontal)."""
        line, mesh = self.line, self.mesh
        vertical = self._uniform.copy()
        horizontal = np.zeros(mesh.nodes - 1)
        middle = 0.5 * (mesh.x[:-1] + mesh.x[1:])
        for distributed in line.distributed_loads:
            inside = (middle > distributed.x_start) & (middle < distributed.x_end)
            vertical[inside] += distributed.load_y
            horizontal[inside] += distributed.load_z
        fy = uniform_load_vector(mesh, vertical)
        fz = uniform_load_vector(mesh, horizontal)
        for load in (*line.point_loads, *condition.loads):
            node = int(mesh.node_at(load.x))
            fy[2 * node] += load.force_y
            fy[2 * node + 1] += load.moment_vertical
            fz[2 * node] += load.force_z
            fz[2 * node + 1] += load.moment_horizontal
        for mass in line.masses:
            fy[2 * int(mesh.node_at(mass.x))] -= mass.mass * line.gravity
        propeller = line.propeller
        if propeller is not None:
            weight = propeller.weight(condition.propeller_immersion, line.gravity)
            node = int(mesh.node_at(max(propeller.x, 0.0)))
            fy[2 * node] -= weight
            # A centre of gravity beyond the aft end acts on the end node with its lever arm.
            fy[2 * node + 1] += (propeller.x - mesh.x[node]) * -weight
        return fy, fz, vertical, horizontal

    def _offsets(self, condition: Condition) -> tuple[np.ndarray, np.ndarray]:
        line, supports = self.line, self.supports
        oy = np.empty(supports.x.size)
        oz = np.empty(supports.x.size)
        for k, bearing in enumerate(line.bearings):
            pick = supports.bearing == k
            arm = supports.x[pick] - bearing.x
            oy[pick] = bearing.offset_y + condition.offsets_y.get(bearing.name, 0.0) + bearing.slope * arm
            oz[pick] = bearing.offset_z + condition.offsets_z.get(bearing.name, 0.0)
        return oy, oz

    # -- solution ----------------------------------------------------------------------
    def solve(self, conditions: tuple[Condition, ...] | None = None) -> list[ConditionResult]:
        """Solve every condition of the line (or the given ones)."""
        return [self.solve_condition(c) for c in (conditions or self.line.all_conditions())]

    def solve_condition(
        self,
        condition: Condition,
        two_sided: bool = False,
        extra_forces: tuple[np.ndarray, np.ndarray] | None = None,
    ) -> ConditionResult:
        """Elastic line and bearing results of ``condition``.

        ``two_sided`` holds every support point in contact (no lift-off, no top contact): the
        linear model behind the influence matrix. ``extra_forces`` are nodal force vectors
        (vertical, horizontal; each (2n,): force and moment per node, N and N m) added to the
        condition's loads, e.g. the consistent nodal forces of a bearing film
        (:mod:`shaftline.shaft.coupled`).
        """
        mesh, supports = self.mesh, self.supports
        fy, fz, uniform_y, uniform_z = self._loads(condition)
        if extra_forces is not None:
            fy = fy + extra_forces[0]
            fz = fz + extra_forces[1]
        oy, oz = self._offsets(condition)
        reactions_y, rigid_y, iterations, state = self._contact(fy, oy, vertical=not two_sided)
        reactions_z, rigid_z, _, _ = self._contact(fz, oz, vertical=False)
        line_y = self._elastic_line(fy, reactions_y, rigid_y)
        line_z = self._elastic_line(fz, reactions_z, rigid_z)
        forces_y = self.beam.end_forces(line_y, uniform_y)
        forces_z = self.beam.end_forces(line_z, uniform_z)
        element_moment_y = np.stack([-forces_y[:, 1], forces_y[:, 3]], axis=1)
        moment_y = _node_average(element_moment_y, mesh.nodes)
        moment_z = _node_average(np.stack([-forces_z[:, 1], forces_z[:, 3]], axis=1), mesh.nodes)
        shear_y = _node_average(np.stack([forces_y[:, 0], -forces_y[:, 2]], axis=1), mesh.nodes)
        stress = np.hypot(moment_y, moment_z) / self._section_modulus
        v, rot_y = line_y[0::2], line_y[1::2]
        w, rot_z = line_z[0::2], line_z[1::2]
        bearings = []
        for k, bearing in enumerate(self.line.bearings):
            pick = supports.bearing == k
            ry = float(reactions_y[pick].sum())
            rz = float(reactions_z[pick].sum())
            states = state[pick]
            if np.all(states == "bottom"):
                contact = "bottom"
            elif np.all(states == "top"):
                contact = "top"
            elif np.all(states == "lifted"):
                contact = "lifted"
            else:
                contact = "partial"
            aft = np.interp(bearing.x - 0.5 * bearing.length, mesh.x, v)
            fore = np.interp(bearing.x + 0.5 * bearing.length, mesh.x, v)
            slope = (fore - aft) / bearing.length
            node = int(supports.node[np.flatnonzero(pick)[0]])
            diameter = self._bearing_diameter[k]
            bearings.append(
                BearingResult(
                    name=bearing.name,
                    reaction_y=ry,
                    reaction_z=rz,
                    mean_pressure=abs(ry) / (bearing.length * diameter),
                    contact=contact,
                    shaft_slope=float(slope),
                    shaft_slope_at_support=float(rot_y[node]),
                    relative_slope=float(slope - bearing.slope),
                    point_reactions=reactions_y[pick],
                    point_contact=state[pick],
                )
            )
        return ConditionResult(
            name=condition.name,
            x=mesh.x,
            deflection_y=v,
            deflection_z=w,
            rotation_y=rot_y,
            rotation_z=rot_z,
            moment_y=moment_y,
            moment_z=moment_z,
            shear_y=shear_y,
            stress=stress,
            element_moment_y=element_moment_y,
            bearings=bearings,
            iterations=iterations,
        )

    def _elastic_line(self, forces: np.ndarray, reactions: np.ndarray, rigid: np.ndarray) -> np.ndarray:
        total = forces.copy()
        np.add.at(total, 2 * self.supports.node, reactions)
        u = self.beam.solve(total)
        u[0::2] += rigid[0] + rigid[1] * self.mesh.x
        u[1::2] += rigid[1]
        return u

    def _contact_setup(self, vertical: bool) -> _ContactSetup:
        """The parts of the contact QP that depend on the line only, built once per plane."""
        if vertical in self._setups:
            return self._setups[vertical]
        supports = self.supports
        m = supports.x.size
        if vertical:
            top = np.flatnonzero(supports.one_sided & np.isfinite(supports.clearance))
            columns = np.concatenate([np.eye(m), -np.eye(m)[:, top]], axis=1)
            gap_offset = np.concatenate([np.zeros(m), supports.clearance[top]])
            compliance = np.concatenate([supports.compliance, supports.compliance[top]])
            bounded = np.concatenate([supports.one_sided, np.ones(top.size, bool)])
        else:  # horizontal: two-sided supports, the clearance is not modelled
            top = np.zeros(0, dtype=int)
            columns = np.eye(m)
            gap_offset = np.zeros(m)
            compliance = supports.compliance.copy()
            bounded = np.zeros(m, bool)
        hessian = columns.T @ self.flexibility @ columns + np.diag(compliance)
        equality = np.vstack([columns.sum(axis=0), supports.x @ columns])
        setup = _ContactSetup(
            top, columns, gap_offset, hessian, equality, bounded, ContactQP(hessian, equality, bounded)
        )
        self._setups[vertical] = setup
        return setup

    def _contact(
        self, forces: np.ndarray, offsets: np.ndarray, vertical: bool
    ) -> tuple[np.ndarray, np.ndarray, int, np.ndarray]:
        """Support reactions (per point), rigid line (a, b), iterations and contact states."""
        supports = self.supports
        m = supports.x.size
        u0 = self.beam.solve(forces)[2 * supports.node]
        total_force = float(forces[0::2].sum())
        total_moment = float((forces[0::2] * self.mesh.x).sum() + forces[1::2].sum())
        setup = self._contact_setup(vertical)
        linear = setup.columns.T @ (u0 - offsets) + setup.gap_offset
        target = np.array([-total_force, -total_moment])
        if self.reference_qp:
            solution, multipliers, iterations = active_set_qp(
                setup.hessian, linear, setup.equality, target, setup.bounded
            )
        else:
            solution, multipliers, iterations = setup.qp.solve(linear, target)
        reactions = setup.columns @ solution
        state = np.full(m, "bottom", dtype=object)
        if vertical:
            lifted = supports.one_sided & (solution[:m] <= 0.0)
            state[lifted] = "lifted"
            if setup.top.size:
                state[setup.top[solution[m:] > 0.0]] = "top"
        return reactions, multipliers, iterations, state

    def displacement_response(self, contact: ConditionResult, forces: np.ndarray, vertical: bool) -> np.ndarray:
        """Change of the displacements per unit nodal force, contact set held.

        Parameters
        ----------
        contact : ConditionResult
            A solution of this model; its closed contacts stay closed and its lifted points
            lifted (the horizontal plane's supports are always closed).
        forces : ndarray (2n, k)
            Nodal force columns (force and moment per node, N and N m).
        vertical : bool
            The plane: vertical (with lift-off and top contact) or horizontal.

        Returns
        -------
        ndarray (2n, k)
            Displacements (deflection and rotation per node) per unit of each column: exact
            while the contact set holds, since the solution is then affine in the loads.
        """
        return self.linear_response(contact, vertical, forces=forces)[0]

    def linear_response(
        self,
        contact: ConditionResult,
        vertical: bool,
        forces: np.ndarray | None = None,
        offsets: np.ndarray | None = None,
    ) -> tuple[np.ndarray, np.ndarray]:
        """Change of the displacements and of the support-point reactions per unit nodal force
        and per unit offset of the support points, contact set held.

        Parameters
        ----------
        contact : ConditionResult
            A solution of this model; its closed contacts stay closed and its lifted points
            lifted (the horizontal plane's supports are always closed).
        vertical : bool
            The plane: vertical (with lift-off and top contact) or horizontal.
        forces : ndarray (2n, k), optional
            Nodal force columns (force and moment per node, N and N m); zero if not given.
        offsets : ndarray (m, k), optional
            Offset columns of the support points (:attr:`supports`, m), changed together with
            ``forces`` column by column; zero if not given.

        Returns
        -------
        displacements : ndarray (2n, k)
            Deflection and rotation per node per unit of each column (m, rad).
        reactions : ndarray (m, k)
            Reaction of each support point per unit of each column, N.

        Notes
        -----
        Exact while the contact set holds, since the solution is then affine in the loads and
        the offsets (the offsets enter the contact problem's stationarity rows, the loads also
        its equilibrium rows).
        """
        supports = self.supports
        m = supports.x.size
        nodes = 2 * self.mesh.nodes
        if forces is not None:
            forces = np.asarray(forces, dtype=float).reshape(nodes, -1)
        elif offsets is not None:
            forces = np.zeros((nodes, np.asarray(offsets).reshape(m, -1).shape[1]))
        else:
            raise ValueError("linear_response: give forces, offsets or both")
        setup = self._contact_setup(vertical=vertical)
        if vertical:
            state = np.concatenate([b.point_contact for b in contact.bearings])
            if state.size != m:
                raise ValueError("contact: a result of another model (its support points differ)")
            free = np.concatenate([state == "bottom", state[setup.top] == "top"])
        else:
            free = np.ones(setup.columns.shape[1], dtype=bool)
        columns = setup.columns[:, free]
        k = columns.shape[1]
        equality = setup.equality[:, free]
        kkt = np.block([[setup.hessian[np.ix_(free, free)], equality.T], [equality, np.zeros((2, 2))]])
        x = self.mesh.x
        pinned = self.beam.solve(forces)
        d_linear = columns.T @ pinned[2 * supports.node]
        if offsets is not None:
            d_linear = d_linear - columns.T @ np.asarray(offsets, dtype=float).reshape(m, -1)
        d_target = -np.vstack([forces[0::2].sum(axis=0), x @ forces[0::2] + forces[1::2].sum(axis=0)])
        # The KKT system of the contact QP: H lambda + E' mu = -linear, E lambda = target.
        solved = np.linalg.solve(kkt, np.vstack([-d_linear, d_target]))
        reactions = columns @ solved[:k]
        total = forces.copy()
        np.add.at(total, 2 * supports.node, reactions)
        u = self.beam.solve(total)
        u[0::2] += solved[k] + x[:, None] * solved[k + 1]
        u[1::2] += solved[k + 1]
        return u, reactions

    # -- influence coefficients ---------------------------------------------------------
    def influence_matrix(self, contact: ConditionResult | None = None) -> InfluenceMatrix:
        """d reaction_i / d offset_j and d deflection / d offset_j of the bearings (vertical plane).

        Parameters
        ----------
        contact : ConditionResult or None
            Linearise at the contact set of this solution (of this model): lifted support
            points stay lifted, points at the top of their bore stay there. None (default):
            every support point in bottom contact, the two-sided linear model.

        Notes
        -----
        For a fixed contact set the reactions and the rigid line solve the KKT system of the
        contact QP restricted to the closed contacts, and the offsets enter only its
        right-hand side, linearly; reactions and elastic line are then affine in the offsets
        and these derivatives are exact, not a finite-difference estimate. Across a change of
        contact set (a bearing lifting off, or reaching the top of its bore) the response is
        only piecewise affine: the derivatives here are those of the given set, i.e. one-sided
        at a point where the set is about to change.
        """
        supports = self.supports
        m = supports.x.size
        if contact is None:
            setup = self._contact_setup(vertical=False)
            free = np.ones(m, dtype=bool)
        else:
            setup = self._contact_setup(vertical=True)
            state = np.concatenate([b.point_contact for b in contact.bearings])
            if state.size != m:
                raise ValueError("contact: a result of another model (its support points differ)")
            free = np.concatenate([state == "bottom", state[setup.top] == "top"])
        columns = setup.columns[:, free]
        k = columns.shape[1]
        equality = setup.equality[:, free]
        kkt = np.block([[setup.hessian[np.ix_(free, free)], equality.T], [equality, np.zeros((2, 2))]])
        # d lambda / d offsets: the offsets enter the stationarity rows as + columns' offsets.
        rhs = np.vstack([columns.T, np.zeros((2, m))])
        solved = np.linalg.solve(kkt, rhs)
        per_point = columns @ solved[:k]
        grouping = np.zeros((m, len(self.line.bearings)))
        grouping[np.arange(m), supports.bearing] = 1.0
        matrix = grouping.T @ per_point @ grouping
        rigid = solved[k:] @ grouping
        deflection = self._unit_response[0::2] @ per_point @ grouping + rigid[0] + self.mesh.x[:, None] * rigid[1]
        return InfluenceMatrix(
            names=[b.name for b in self.line.bearings],
            matrix=0.5 * (matrix + matrix.T),
            deflection=deflection,
            condition="" if contact is None else contact.name,
        )


def _node_average(ends: np.ndarray, nodes: int) -> np.ndarray:
    out = np.zeros(nodes)
    count = np.zeros(nodes)
    np.add.at(out, np.arange(nodes - 1), ends[:, 0])
    np.add.at(count, np.arange(nodes - 1), 1)
    np.add.at(out, np.arange(1, nodes), ends[:, 1])
    np.add.at(count, np.arange(1, nodes), 1)
    return out / count
