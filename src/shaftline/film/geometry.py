"""Film thickness on the unwrapped bore of a journal bearing.

Coordinates (see docs/architecture.md): the bearing axis is the shaft x axis,
positive forward; ``z_local`` runs from the aft edge of the bearing (0) to the
forward edge (L). The bearing angle ``theta`` is measured from the top of the
bore (+y) in the direction of shaft rotation. The unit vector from the bore
centre to the bore surface at ``theta`` is ``(cos theta, s sin theta)`` in the
(y, z) plane, where ``s = +1`` for a shaft turning clockwise seen from aft
(right-handed about +x) and ``s = -1`` otherwise.

The film thickness is the radial clearance less the projection, on that unit
vector, of the offset between the journal centre line and the bore centre line:

    h(theta, z) = c - [ey_j(z) - ey_b(z)] cos(theta) - s [ez_j(z) - ez_b(z)] sin(theta) + delta(theta, z)

with the journal centre line ``ey_j(z) = ey + tilt_y (z - L/2) + bend_y(z)``
(likewise in z) and the bore centre line ``ey_b(z)`` given by the slope-bored
segments. This is seed 004 Eq. (53)-(55) written in fixed bearing axes; see
docs/theory.md for why the slope term is not tied to the attitude angle.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from functools import cached_property
from typing import Any, Literal, get_args

import numpy as np

from shaftline.errors import InputError, require_finite, require_positive
from shaftline.export import quantity
from shaftline.film.liner import MAX_THICKNESS_RATIO, Liner
from shaftline.film.roughness import SurfaceRoughness

#: Below this many nodes the Reynolds solution is too coarse to be worth returning.
MIN_CIRCUMFERENTIAL_NODES = 16
MIN_AXIAL_NODES = 5

#: Where a slope-bored bore centre line meets the nominal axis.
BoreAnchor = Literal["fore", "aft", "mid"]
#: Sense of rotation: +1 clockwise seen from aft (right-handed about +x), -1 anticlockwise.
Rotation = Literal[1, -1]

BORE_ANCHORS: tuple[BoreAnchor, ...] = get_args(BoreAnchor)
ROTATIONS: tuple[Rotation, ...] = get_args(Rotation)


def require_nodes(field: str, value: Any, minimum: int, allowed: str = "") -> int:
    """Return ``value`` as int if it is a whole number >= ``minimum``, else raise :class:`InputError`."""
    try:
        whole = not isinstance(value, bool) and int(value) == value
    except (TypeError, ValueError, OverflowError):
        whole = False
    if not whole or value < minimum:
        raise InputError(field, value, "", allowed or f"an integer >= {minimum} to resolve the film")
    return int(value)


@dataclass(frozen=True)
class BoreSegment:
    """One axial segment of a slope-bored bore, listed from aft to forward.

    Attributes
    ----------
    length_fraction : float
        Share of the bearing length, (0, 1]; the fractions of a bore sum to 1.
    slope : float
        Slope of the bore axis in the vertical plane, rad; positive when the bore
        axis rises going forward (the aft end machined lower, as a bore that
        follows a shaft sagging towards the propeller).
    slope_horizontal : float
        Slope of the bore axis in the horizontal plane, rad (towards +z going forward).
    """

    length_fraction: float
    slope: float = 0.0
    slope_horizontal: float = 0.0


@dataclass(frozen=True, eq=False)
class BentJournal:
    """Offsets of the journal centre line from a straight line, along the bearing.

    Attributes
    ----------
    z : ndarray
        Axial stations from the aft edge of the bearing, m, increasing.
    dy, dz : ndarray
        Vertical and horizontal offsets of the journal centre at those stations, m.
        They are interpolated linearly onto the grid (seed 004 Sect. 4.5.1) and
        held constant beyond the first and last station.

    Equality is identity (the arrays have no single truth value).

    Raises
    ------
    InputError
        Naming the attribute: ``"z"``, ``"dy"`` or ``"dz"``.
    """

    z: np.ndarray
    dy: np.ndarray
    dz: np.ndarray

    def __post_init__(self) -> None:
        z = np.asarray(self.z, dtype=float)
        dy = np.asarray(self.dy, dtype=float)
        dz = np.asarray(self.dz, dtype=float) if self.dz is not None else np.zeros_like(z)
        for name, values in (("z", z), ("dy", dy), ("dz", dz)):
            if values.ndim != 1 or values.size != z.size:
                raise InputError(name, values.size, "", f"{z.size} values")
            if not np.all(np.isfinite(values)):
                raise InputError(name, "NaN", "m", "finite numbers")
        if z.size < 2 or np.any(np.diff(z) <= 0.0):
            raise InputError("z", z.tolist(), "m", "at least 2 increasing stations")
        object.__setattr__(self, "z", z)
        object.__setattr__(self, "dy", dy)
        object.__setattr__(self, "dz", dz)


@dataclass(frozen=True, eq=False)
class FilmProfile:
    """An additive film change delta(theta, z) given on its own table (wear, bore errors).

    Attributes
    ----------
    theta : ndarray (m,)
        Bearing angles of the table, rad, increasing within one turn.
    z : ndarray (n,)
        Axial stations from the aft edge, m, increasing.
    delta : ndarray (n, m)
        Film change at those points, m (positive opens the clearance, e.g. wear).

    It is interpolated linearly, periodically in theta and held constant beyond the
    end stations in z, so it follows the grid wherever the grid's angles start.
    Equality is identity (the arrays have no single truth value).

    Raises
    ------
    InputError
        Naming the attribute: ``"theta"``, ``"z"`` or ``"delta"``.
    """

    theta: np.ndarray
    z: np.ndarray
    delta: np.ndarray

    def __post_init__(self) -> None:
        theta = np.asarray(self.theta, dtype=float)
        z = np.asarray(self.z, dtype=float)
        delta = np.asarray(self.delta, dtype=float)
        if theta.ndim != 1 or theta.size < 2 or np.any(np.diff(theta) <= 0) or theta[-1] - theta[0] >= 2 * np.pi:
            raise InputError("theta", theta.size, "rad", "increasing angles within one turn")
        if z.ndim != 1 or z.size < 1 or np.any(np.diff(z) <= 0):
            raise InputError("z", z.size, "m", "increasing stations")
        if delta.shape != (z.size, theta.size):
            raise InputError("delta", str(delta.shape), "m", f"shape {(z.size, theta.size)}")
        if not np.all(np.isfinite(delta)):
            raise InputError("delta", "NaN", "m", "finite values")
        object.__setattr__(self, "theta", theta)
        object.__setattr__(self, "z", z)
        object.__setattr__(self, "delta", delta)

    def on(self, theta: np.ndarray, z: np.ndarray) -> np.ndarray:
        """The profile at grid angles ``theta`` (rad) and stations ``z`` (m), shape (z, theta)."""
        # Linear in z (clamped), then periodic linear in theta.
        if self.z.size == 1:
            rows = np.repeat(self.delta, z.size, axis=0)
        else:
            position = np.clip(np.interp(z, self.z, np.arange(self.z.size)), 0, self.z.size - 1)
            lower = np.minimum(np.floor(position).astype(int), self.z.size - 2)
            weight = position - lower
            rows = self.delta[lower] * (1 - weight)[:, None] + self.delta[lower + 1] * weight[:, None]
        period = 2 * np.pi
        table_theta = np.concatenate([self.theta, [self.theta[0] + period]])
        table = np.concatenate([rows, rows[:, :1]], axis=1)
        wrapped = (theta - self.theta[0]) % period + self.theta[0]
        return np.stack([np.interp(wrapped, table_theta, row) for row in table])


@dataclass(frozen=True)
class BearingGeometry:
    """Geometry of a plain (optionally slope-bored) journal bearing.

    Attributes
    ----------
    length : float
        Bearing length L, m.
    diameter : float
        Bore diameter D, m.
    radial_clearance : float
        Radial clearance c, m (half the diametral clearance).
    bore : tuple of BoreSegment
        Slope-bored segments from aft to forward; empty for a straight bore.
    bore_anchor : BoreAnchor
        Where the bore centre line coincides with the nominal axis: ``"fore"``
        (default: the forward part stays on the nominal line and the aft end is
        machined lower), ``"aft"`` or ``"mid"``.
    bent_journal : BentJournal or None
        Offsets of a bent journal centre line.
    film_profile : FilmProfile or None
        Additive film change delta(theta, z), e.g. wear or bore errors.
    rotation : Rotation
        +1 for a shaft turning clockwise seen from aft, -1 for anticlockwise.
    surface : SurfaceRoughness or None
        Roughness and elasticity of the journal and bore surfaces: with it the film carries
        Patir-Cheng flow factors and the asperities a Greenwood-Tripp contact pressure (mixed
        lubrication, :mod:`shaftline.film.roughness`); None (default) is a smooth film.
    liner : Liner or None
        A thin elastic liner bonded to the bore (column model, :mod:`shaftline.film.liner`, or
        bonded layer, :mod:`shaftline.film.layer`):
        it deforms under the film and asperity pressure and the deformation enters the film,
        solved together with it; None (default) is a rigid bore. Its thickness must not
        exceed :data:`~shaftline.film.liner.MAX_THICKNESS_RATIO` of the radius.

    Raises
    ------
    InputError
        Naming the attribute path, e.g. ``"radial_clearance"``, ``"bore[1].slope"``
        or ``"bent_journal.z"``.
    """

    length: float
    diameter: float
    radial_clearance: float
    bore: tuple[BoreSegment, ...] = ()
    bore_anchor: BoreAnchor = "fore"
    bent_journal: BentJournal | None = None
    film_profile: FilmProfile | None = field(default=None, repr=False)
    rotation: Rotation = 1
    surface: SurfaceRoughness | None = None
    liner: Liner | None = None

    def __post_init__(self) -> None:
        require_positive("length", self.length, "m")
        require_positive("diameter", self.diameter, "m")
        require_positive("radial_clearance", self.radial_clearance, "m")
        if self.radial_clearance >= 0.5 * self.diameter:
            raise InputError("radial_clearance", self.radial_clearance, "m", f"< diameter/2 = {0.5 * self.diameter}")
        if self.surface is not None and self.surface.sigma >= 0.5 * self.radial_clearance:
            raise InputError(
                "surface.bore_rq",
                round(self.surface.sigma, 12),
                "m",
                f"a composite roughness below half the radial clearance ({0.5 * self.radial_clearance:g} m)",
            )
        if self.liner is not None and self.liner.thickness > MAX_THICKNESS_RATIO * 0.5 * self.diameter:
            raise InputError(
                "liner.thickness",
                self.liner.thickness,
                "m",
                f"(0, {MAX_THICKNESS_RATIO * 0.5 * self.diameter:g}]: a thin liner, at most "
                f"{MAX_THICKNESS_RATIO:g} of the bore radius (a plane liner)",
            )
        if self.rotation not in ROTATIONS:
            raise InputError("rotation", self.rotation, "", "+1 (clockwise from aft) or -1")
        if self.bore_anchor not in BORE_ANCHORS:
            raise InputError("bore_anchor", self.bore_anchor, "", "one of " + ", ".join(BORE_ANCHORS))
        if self.bore:
            total = 0.0
            for k, segment in enumerate(self.bore):
                frac = require_finite(f"bore[{k}].length_fraction", segment.length_fraction)
                if not 0.0 < frac <= 1.0:
                    raise InputError(f"bore[{k}].length_fraction", frac, "", "in (0, 1]")
                require_finite(f"bore[{k}].slope", segment.slope, "rad")
                require_finite(f"bore[{k}].slope_horizontal", segment.slope_horizontal, "rad")
                total += frac
            if abs(total - 1.0) > 1e-6:
                # The sum of all segments, not one of them: no index.
                raise InputError("bore.length_fraction", round(total, 9), "", "segments summing to 1")
        if self.bent_journal is not None and (
            self.bent_journal.z[0] < -1e-9 * self.length or self.bent_journal.z[-1] > self.length * (1 + 1e-9)
        ):
            raise InputError(
                "bent_journal.z",
                [float(self.bent_journal.z[0]), float(self.bent_journal.z[-1])],
                "m",
                f"stations within the bearing, [0, {self.length}]",
            )

    @property
    def radius(self) -> float:
        """Bore radius R, m."""
        return 0.5 * self.diameter

    def bore_centre_line(self, z: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """Vertical and horizontal offsets of the bore axis at stations ``z`` (m from aft edge), m."""
        z = np.asarray(z, dtype=float)
        if not self.bore:
            return np.zeros_like(z), np.zeros_like(z)
        fractions = np.array([s.length_fraction for s in self.bore])
        edges = np.concatenate(([0.0], np.cumsum(fractions))) * self.length
        edges[-1] = self.length
        offsets = []
        for attribute in ("slope", "slope_horizontal"):
            slopes = np.array([getattr(s, attribute) for s in self.bore])
            at_edges = np.concatenate(([0.0], np.cumsum(slopes * np.diff(edges))))
            line = np.interp(z, edges, at_edges)
            if self.bore_anchor == "fore":
                line = line - at_edges[-1]
            elif self.bore_anchor == "mid":
                line = line - np.interp(0.5 * self.length, edges, at_edges)
            offsets.append(line)
        return offsets[0], offsets[1]


@dataclass(frozen=True)
class Grid:
    """Nodes of the unwrapped bore.

    ``axial_nodes`` stations from the aft edge (0) to the forward edge (L), the
    two edge rows carrying the end pressures; ``circumferential_nodes`` angles
    ``theta_i = theta_start + i * 2 pi / n`` (periodic). ``theta_start`` lets a
    node sit exactly on a supply groove or on the line of maximum film.

    Raises
    ------
    InputError
        ``"axial_nodes"`` below 5 or ``"circumferential_nodes"`` below 16.
    """

    length: float
    axial_nodes: int
    circumferential_nodes: int
    theta_start: float = 0.0

    def __post_init__(self) -> None:
        require_nodes("axial_nodes", self.axial_nodes, MIN_AXIAL_NODES)
        require_nodes("circumferential_nodes", self.circumferential_nodes, MIN_CIRCUMFERENTIAL_NODES)

    # Kept on the instance, read-only: a bearing's grid is asked for its nodes at every film
    # solution (about twenty per equilibrium), and building them cost more than using them.
    @cached_property
    def theta(self) -> np.ndarray:
        """Node angles, rad, shape (circumferential_nodes,); read-only."""
        return _read_only(self.theta_start + np.arange(self.circumferential_nodes) * self.d_theta)

    @cached_property
    def z(self) -> np.ndarray:
        """Axial node stations from the aft edge, m, shape (axial_nodes,); read-only."""
        return _read_only(np.linspace(0.0, self.length, self.axial_nodes))

    @property
    def d_theta(self) -> float:
        """Angular step between nodes, rad."""
        return 2.0 * np.pi / self.circumferential_nodes

    @property
    def dz(self) -> float:
        """Axial step between nodes, m."""
        return self.length / (self.axial_nodes - 1)

    @property
    def shape(self) -> tuple[int, int]:
        """(axial_nodes, circumferential_nodes): fields are indexed [z, theta]."""
        return (self.axial_nodes, self.circumferential_nodes)


def _read_only(values: np.ndarray) -> np.ndarray:
    values.flags.writeable = False
    return values


def coarse_shape(shape: tuple[int, int]) -> tuple[int, int] | None:
    """Shape of the grid halved in both directions below a grid of ``shape`` (nz, nt), or None.

    The Reynolds solver predicts the cavitated set on this coarser grid (and that one on a
    coarser one, down to about 9 x 16 nodes); the memory estimate of a problem counts the same
    grids. Halving needs at least 9 axial nodes and an even number, >= 16, round the bore.
    """
    nz, nt = shape
    if nz < 9 or nt < 16 or nt % 2:
        return None
    return (nz + 1) // 2, nt // 2


@dataclass(frozen=True)
class JournalPosition:
    """Journal centre and tilt relative to the bore.

    Attributes
    ----------
    ey, ez : float
        Offsets of the journal centre from the bore centre at the bearing mid-plane,
        vertical (+y up) and horizontal (+z starboard), m.
    tilt_y, tilt_z : float
        Slopes of the journal axis relative to the nominal bore axis in the vertical
        plane (dy/dx) and the horizontal plane (dz/dx), rad (misalignment).
    vy, vz : float
        Velocities of the journal centre, m/s (squeeze film; zero at steady state).
    """

    ey: float = quantity(
        "m", "vertical offset of the journal centre at mid-plane from the nominal bore axis", default=0.0
    )
    ez: float = quantity("m", "horizontal (starboard) offset of the journal centre at mid-plane", default=0.0)
    tilt_y: float = quantity("rad", "journal tilt in the vertical plane (dy/dx)", default=0.0)
    tilt_z: float = quantity("rad", "journal tilt in the horizontal plane (dz/dx)", default=0.0)
    vy: float = 0.0
    vz: float = 0.0

    @classmethod
    def from_polar(
        cls, eccentricity: float, position_angle: float, rotation: int = 1, tilt_y: float = 0.0, tilt_z: float = 0.0
    ) -> JournalPosition:
        """Position from eccentricity ``e`` (m) and the bearing angle of the line of centres (rad).

        ``position_angle`` is measured like ``theta`` (from the top, in the direction of
        rotation): the journal centre moves towards the point where the film is thinnest.
        """
        return cls(
            ey=eccentricity * np.cos(position_angle),
            ez=rotation * eccentricity * np.sin(position_angle),
            tilt_y=tilt_y,
            tilt_z=tilt_z,
        )

    def polar(self, rotation: int = 1) -> tuple[float, float]:
        """(eccentricity e in m, bearing angle of the line of centres in rad, in [0, 2 pi))."""
        e = float(np.hypot(self.ey, self.ez))
        angle = float(np.arctan2(rotation * self.ez, self.ey)) % (2.0 * np.pi)
        return e, angle


def journal_centre_line(
    geometry: BearingGeometry, position: JournalPosition, z: np.ndarray
) -> tuple[np.ndarray, np.ndarray]:
    """Offsets (y, z) of the journal centre from the bore centre line at stations ``z``, m."""
    arm = z - 0.5 * geometry.length
    ey = position.ey + position.tilt_y * arm
    ez = position.ez + position.tilt_z * arm
    if geometry.bent_journal is not None:
        bent = geometry.bent_journal
        ey = ey + np.interp(z, bent.z, bent.dy)
        ez = ez + np.interp(z, bent.z, bent.dz)
    bore_y, bore_z = geometry.bore_centre_line(z)
    return ey - bore_y, ez - bore_z


def film_thickness(geometry: BearingGeometry, grid: Grid, position: JournalPosition) -> np.ndarray:
    """Film thickness h on the grid, m, shape ``grid.shape`` ([z, theta]).

    Values <= 0 mean the journal would cut into the bore (contact); they are
    returned as they are so that the caller can report contact, never clipped.
    """
    theta = grid.theta
    oy, oz = journal_centre_line(geometry, position, grid.z)
    h = geometry.radial_clearance - (
        oy[:, None] * np.cos(theta)[None, :] + geometry.rotation * oz[:, None] * np.sin(theta)[None, :]
    )
    if geometry.film_profile is not None:
        h = h + geometry.film_profile.on(theta, grid.z)
    return h


def squeeze_velocity(geometry: BearingGeometry, grid: Grid, position: JournalPosition) -> np.ndarray:
    """Rate of change of film thickness dh/dt from the journal centre velocity, m/s."""
    theta = grid.theta
    row = -(position.vy * np.cos(theta) + geometry.rotation * position.vz * np.sin(theta))
    return np.broadcast_to(row, grid.shape)
