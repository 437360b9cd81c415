"""Shaft line model: segments, bearings, loads and load conditions (SI units).

Axes as everywhere in shaftline: x along the shaft from the aft end of the
model, positive forward; y up; z starboard. Offsets of bearings are positions
of the bearing (its lowest contact line, the bottom of the bore) relative to the
straight reference line through x-axis, m, + up.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from shaftline.errors import InputError, require_finite, require_positive

GRAVITY = 9.80665
SUPPORT_MODELS = ("point", "spring", "multi_point")
SUPPORT_POSITIONS = ("centre", "aft_third")
#: Bearing materials the rules know; "engine" marks engine main bearings (the engine
#: maker's limits apply), "roller" a roller bearing.
MATERIALS = ("white_metal", "synthetic", "rubber", "bronze", "composite", "lignum_vitae", "engine", "roller")


@dataclass(frozen=True)
class ShaftSegment:
    """A length of shaft with a straight or conical, solid or hollow section.

    Attributes
    ----------
    length : float
        Segment length, m.
    outer_diameter, inner_diameter : float
        Diameters at the aft end of the segment, m (inner 0 for a solid shaft).
    outer_diameter_end, inner_diameter_end : float or None
        Diameters at the forward end for a conical segment, m (None: as at the aft end).
    youngs_modulus : float
        E, Pa.
    shear_modulus : float or None
        G, Pa; None derives it from ``poisson_ratio``.
    poisson_ratio : float
        nu, used for G and the shear coefficient.
    density : float
        kg/m^3 (self-weight).
    shear_area_factor : float or None
        Shear coefficient kappa of the Timoshenko element (shear area / area); None
        (default) uses Cowper's value for a hollow circle (0.886 solid, nu = 0.3).
    name : str
        Label (e.g. "tail shaft", "flange").
    """

    length: float
    outer_diameter: float
    inner_diameter: float = 0.0
    outer_diameter_end: float | None = None
    inner_diameter_end: float | None = None
    youngs_modulus: float = 206e9
    shear_modulus: float | None = None
    poisson_ratio: float = 0.3
    density: float = 7850.0
    shear_area_factor: float | None = None
    name: str = ""

    def validate(self, where: str) -> None:
        require_positive(f"{where}.length", self.length, "m")
        outer_end = self.outer_diameter if self.outer_diameter_end is None else self.outer_diameter_end
        inner_end = self.inner_diameter if self.inner_diameter_end is None else self.inner_diameter_end
        for name, outer, inner in (("", self.outer_diameter, self.inner_diameter), ("_end", outer_end, inner_end)):
            require_positive(f"{where}.outer_diameter{name}", outer, "m")
            inner = require_finite(f"{where}.inner_diameter{name}", inner, "m")
            if inner < 0 or inner >= outer:
                raise InputError(f"{where}.inner_diameter{name}", inner, "m", f"in [0, outer diameter {outer})")
        require_positive(f"{where}.youngs_modulus", self.youngs_modulus, "Pa")
        if self.shear_modulus is not None:
            require_positive(f"{where}.shear_modulus", self.shear_modulus, "Pa")
        if not -1.0 < self.poisson_ratio < 0.5:
            raise InputError(f"{where}.poisson_ratio", self.poisson_ratio, "", "in (-1, 0.5)")
        require_positive(f"{where}.density", self.density, "kg/m^3")
        if self.shear_area_factor is not None and not 0.0 < self.shear_area_factor <= 1.0:
            raise InputError(f"{where}.shear_area_factor", self.shear_area_factor, "", "in (0, 1]")

    @property
    def shear(self) -> float:
        """Shear modulus G, Pa."""
        if self.shear_modulus is not None:
            return self.shear_modulus
        return self.youngs_modulus / (2.0 * (1.0 + self.poisson_ratio))

    def diameters_at(self, fraction: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """Outer and inner diameters at fractions (0 aft, 1 forward) of the segment length, m."""
        outer_end = self.outer_diameter if self.outer_diameter_end is None else self.outer_diameter_end
        inner_end = self.inner_diameter if self.inner_diameter_end is None else self.inner_diameter_end
        outer = self.outer_diameter + (outer_end - self.outer_diameter) * fraction
        inner = self.inner_diameter + (inner_end - self.inner_diameter) * fraction
        return outer, inner


@dataclass(frozen=True)
class PointLoad:
    """A force and/or moment applied at a point of the shaft.

    Attributes
    ----------
    x : float
        Position, m.
    force_y, force_z : float
        Force components, N (+ up, + starboard).
    moment_vertical : float
        Moment in the vertical (x-y) plane, N*m, positive when it turns the shaft
        nose-up (counter-clockwise seen from starboard: +x towards +y).
    moment_horizontal : float
        Moment in the horizontal (x-z) plane, N*m, positive turning +x towards +z.
    name : str
        Label.
    """

    x: float
    force_y: float = 0.0
    force_z: float = 0.0
    moment_vertical: float = 0.0
    moment_horizontal: float = 0.0
    name: str = ""


@dataclass(frozen=True)
class PointMass:
    """A lumped mass on the shaft (gear wheel, flywheel, coupling), weight downwards.

    Attributes
    ----------
    x : float
        Position, m.
    mass : float
        kg.
    name : str
        Label.
    """

    x: float
    mass: float
    name: str = ""


@dataclass(frozen=True)
class DistributedLoad:
    """A uniform line load between two stations, N/m (+ up, + starboard)."""

    x_start: float
    x_end: float
    load_y: float = 0.0
    load_z: float = 0.0
    name: str = ""


@dataclass(frozen=True)
class Propeller:
    """The propeller as a lumped mass with buoyancy when immersed.

    Attributes
    ----------
    x : float
        Position of its centre of gravity, m (usually aft of the shaft end: overhang).
    mass : float
        Propeller mass in air, kg.
    material_density : float
        kg/m^3 (nickel-aluminium bronze about 7600), for the displaced volume.
    water_density : float
        kg/m^3.
    immersed_fraction : float
        Share of the propeller volume under water in the base case, [0, 1].
    """

    x: float
    mass: float
    material_density: float = 7600.0
    water_density: float = 1025.0
    immersed_fraction: float = 1.0

    def weight(self, immersed_fraction: float | None = None, gravity: float = GRAVITY) -> float:
        """Net downward force, N: weight less buoyancy of the immersed share."""
        fraction = self.immersed_fraction if immersed_fraction is None else immersed_fraction
        buoyancy = self.water_density * self.mass / self.material_density * fraction
        return (self.mass - buoyancy) * gravity


@dataclass(frozen=True)
class Bearing:
    """A shaft bearing and how it supports the shaft.

    Attributes
    ----------
    name : str
        Unique label, used by conditions and rules.
    x : float
        Axial position of the bearing centre, m.
    length : float
        Bearing length, m.
    offset_y, offset_z : float
        Position of the bearing relative to the reference line, m (+ up, + starboard).
    vertical_clearance : float
        Diametral clearance: how far the shaft may rise before touching the top of the
        bore, m (``inf`` to ignore the top).
    material : str
        Bearing material, for pressure limits: one of :data:`MATERIALS`.
    support : str
        ``"point"`` (rigid point), ``"spring"`` (one point on a linear spring of the
        bearing and foundation stiffness) or ``"multi_point"`` (``points`` supports
        spread along the bearing, each one-sided).
    stiffness : float
        Support stiffness for ``"spring"`` (and per point for ``"multi_point"`` when
        given), N/m; ``inf`` for rigid.
    points : int
        Number of support points for ``"multi_point"``.
    position : str
        Single-point location: ``"centre"`` or ``"aft_third"`` (at D/3 from the aft edge,
        D the shaft diameter, a usual choice for the aft stern-tube bearing).
    one_sided : bool
        True (default): the shaft may lift off (reaction only upwards until the top of
        the bore is reached).
    slope : float
        Slope of the bearing axis (slope boring) relative to the reference line, rad.
    """

    name: str
    x: float
    length: float
    offset_y: float = 0.0
    offset_z: float = 0.0
    vertical_clearance: float = math.inf
    material: str = "white_metal"
    support: str = "point"
    stiffness: float = math.inf
    points: int = 1
    position: str = "centre"
    one_sided: bool = True
    slope: float = 0.0

    def validate(self, where: str) -> None:
        require_finite(f"{where}.x", self.x, "m")
        require_positive(f"{where}.length", self.length, "m")
        require_finite(f"{where}.offset_y", self.offset_y, "m")
        require_finite(f"{where}.offset_z", self.offset_z, "m")
        require_finite(f"{where}.slope", self.slope, "rad")
        if not (self.vertical_clearance > 0):
            raise InputError(f"{where}.vertical_clearance", self.vertical_clearance, "m", "> 0 (inf to ignore)")
        if self.material not in MATERIALS:
            raise InputError(f"{where}.material", self.material, "", "one of " + ", ".join(MATERIALS))
        if self.support not in SUPPORT_MODELS:
            raise InputError(f"{where}.support", self.support, "", "one of " + ", ".join(SUPPORT_MODELS))
        if self.position not in SUPPORT_POSITIONS:
            raise InputError(f"{where}.position", self.position, "", "one of " + ", ".join(SUPPORT_POSITIONS))
        if not (self.stiffness > 0):
            raise InputError(f"{where}.stiffness", self.stiffness, "N/m", "> 0 (inf for rigid)")
        if self.support == "spring" and math.isinf(self.stiffness):
            raise InputError(f"{where}.stiffness", self.stiffness, "N/m", "a finite stiffness for a spring support")
        if self.support == "multi_point" and not 2 <= int(self.points) <= 50:
            raise InputError(f"{where}.points", self.points, "", "an integer in [2, 50] for a multi-point support")

    def support_points(self, shaft_diameter: float) -> np.ndarray:
        """Axial positions of the support points, m."""
        aft_edge = self.x - 0.5 * self.length
        if self.support == "multi_point":
            n = int(self.points)
            return aft_edge + (np.arange(n) + 0.5) * self.length / n
        if self.position == "aft_third":
            return np.array([aft_edge + min(shaft_diameter / 3.0, 0.5 * self.length)])
        return np.array([self.x])


@dataclass(frozen=True)
class Condition:
    """A named load case: offsets added to the bearings, propeller immersion, extra loads.

    Attributes
    ----------
    name : str
        Label (cold static, hot running, ballast, laden...).
    offsets_y, offsets_z : dict
        Extra offsets per bearing name, m (thermal rise, hull deflection).
    propeller_immersion : float or None
        Immersed share of the propeller in this condition (None: the propeller's own).
    loads : tuple of PointLoad
        Extra point loads (e.g. the eccentric thrust moment when running).
    """

    name: str
    offsets_y: dict[str, float] = field(default_factory=dict)
    offsets_z: dict[str, float] = field(default_factory=dict)
    propeller_immersion: float | None = None
    loads: tuple[PointLoad, ...] = ()


@dataclass(frozen=True)
class ShaftLine:
    """The whole line: segments from aft to forward, bearings, loads and conditions.

    Attributes
    ----------
    segments : tuple of ShaftSegment
        From the aft end (x = 0) forward.
    bearings : tuple of Bearing
    point_loads, masses, distributed_loads : tuples
    propeller : Propeller or None
    conditions : tuple of Condition
        Load cases; an empty tuple means one base condition.
    self_weight : bool
        Include the shaft's own weight.
    gravity : float
        m/s^2.
    element_length : float
        Largest finite-element length, m.
    beam_theory : str
        ``"timoshenko"`` (default) or ``"euler_bernoulli"``.
    """

    segments: tuple[ShaftSegment, ...]
    bearings: tuple[Bearing, ...]
    point_loads: tuple[PointLoad, ...] = ()
    masses: tuple[PointMass, ...] = ()
    distributed_loads: tuple[DistributedLoad, ...] = ()
    propeller: Propeller | None = None
    conditions: tuple[Condition, ...] = ()
    self_weight: bool = True
    gravity: float = GRAVITY
    element_length: float = 0.25
    beam_theory: str = "timoshenko"

    def __post_init__(self) -> None:
        if not self.segments:
            raise InputError("segments", 0, "", "at least one segment")
        for k, segment in enumerate(self.segments):
            segment.validate(f"segments[{k}]")
        length = self.length
        if self.beam_theory not in ("timoshenko", "euler_bernoulli"):
            raise InputError("beam_theory", self.beam_theory, "", "timoshenko or euler_bernoulli")
        require_positive("element_length", self.element_length, "m")
        names: set[str] = set()
        for k, bearing in enumerate(self.bearings):
            where = f"bearings[{k}]"
            bearing.validate(where)
            if bearing.name in names:
                raise InputError(f"{where}.name", bearing.name, "", "a name not used by another bearing")
            names.add(bearing.name)
            if bearing.x - 0.5 * bearing.length < -1e-9 or bearing.x + 0.5 * bearing.length > length + 1e-9:
                raise InputError(f"{where}.x", bearing.x, "m", f"a bearing within the shaft, [0, {length:.4g}] m")
        order = sorted(range(len(self.bearings)), key=lambda k: self.bearings[k].x)
        for i, j in zip(order, order[1:], strict=False):
            a, b = self.bearings[i], self.bearings[j]
            if b.x - 0.5 * b.length < a.x + 0.5 * a.length - 1e-9:
                raise InputError(f"bearings[{j}].x", b.x, "m", f"a bearing not overlapping {a.name}")
        if sum(b.points if b.support == "multi_point" else 1 for b in self.bearings) < 2:
            raise InputError("bearings", len(self.bearings), "", "at least two supports (one leaves a mechanism)")
        located = [(f"point_loads[{k}].x", p.x) for k, p in enumerate(self.point_loads)]
        located += [(f"masses[{k}].x", m.x) for k, m in enumerate(self.masses)]
        located += [
            (f"conditions[{k}].loads[{j}].x", p.x) for k, c in enumerate(self.conditions) for j, p in enumerate(c.loads)
        ]
        for where, value in located:
            x = require_finite(where, value, "m")
            if not 0.0 <= x <= length:
                raise InputError(where, x, "m", f"on the shaft, [0, {length:.4g}]")
        for k, item in enumerate(self.distributed_loads):
            if not 0.0 <= item.x_start < item.x_end <= length:
                raise InputError(
                    f"distributed_loads[{k}].x_end", item.x_end, "m", f"x_start < x_end within [0, {length:.4g}]"
                )
        if self.propeller is not None:
            require_positive("propeller.mass", self.propeller.mass, "kg")
            if not 0.0 <= self.propeller.immersed_fraction <= 1.0:
                raise InputError("propeller.immersed_fraction", self.propeller.immersed_fraction, "", "in [0, 1]")
            if not -0.5 * length <= self.propeller.x <= length:
                raise InputError("propeller.x", self.propeller.x, "m", "near the aft end of the shaft")
        for k, condition in enumerate(self.conditions):
            for plane, offsets in (("offsets_y", condition.offsets_y), ("offsets_z", condition.offsets_z)):
                for key in offsets:
                    if key not in names:
                        raise InputError(
                            f"conditions[{k}].{plane}", key, "", "the name of a bearing: " + ", ".join(sorted(names))
                        )
            if condition.propeller_immersion is not None and not 0.0 <= condition.propeller_immersion <= 1.0:
                raise InputError(f"conditions[{k}].propeller_immersion", condition.propeller_immersion, "", "in [0, 1]")

    @property
    def length(self) -> float:
        """Total shaft length, m."""
        return float(sum(s.length for s in self.segments))

    def segment_edges(self) -> np.ndarray:
        """x of the segment boundaries, m (aft end first)."""
        return np.concatenate(([0.0], np.cumsum([s.length for s in self.segments])))

    def outer_diameter_at(self, x: float) -> float:
        """Outer shaft diameter at station x, m."""
        edges = self.segment_edges()
        k = int(np.clip(np.searchsorted(edges, x, side="right") - 1, 0, len(self.segments) - 1))
        fraction = (x - edges[k]) / self.segments[k].length
        outer, _ = self.segments[k].diameters_at(np.array(fraction))
        return float(outer)

    def all_conditions(self) -> tuple[Condition, ...]:
        return self.conditions or (Condition(name="base"),)
