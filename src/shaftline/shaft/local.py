"""Local shaft model around the aft stern-tube bearing (seed 004 Sect. 4.5.2-4.5.4).

A short beam: an aft overhang carrying the propeller end force and moment, the
bearing length divided into equal parts, and a forward length whose end has the
slope of the whole shaft line imposed. The shaft rests on the two bearing edges,
offset so that the chord across the bearing has the misalignment slope (the
seed's third, preferred "bypass" model). Its elastic line inside the bearing is
the bent journal of the film model.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np

from shaftline.errors import require_finite, require_positive
from shaftline.film.geometry import BentJournal
from shaftline.shaft.fem import PinnedBeam, build_mesh, uniform_load_vector
from shaftline.shaft.model import Bearing, ShaftLine, ShaftSegment


@dataclass(frozen=True)
class LocalShaftModel:
    """Inputs of the local model (seed 004 Table 4-5), SI.

    Attributes
    ----------
    bearing_length : float
        L, m.
    shaft_diameter : float
        m (solid shaft).
    aft_overhang, fore_length : float
        Shaft beyond the aft bearing edge and forward of the forward edge, m.
    aft_force, aft_moment : float
        Force (N, + up) and moment (N m, + nose-up, i.e. hogging for a propeller aft)
        at the aft end.
    fore_force : float
        Force at the forward end, N.
    fore_rotation : float
        Slope imposed at the forward end, rad.
    weight_per_length : float
        Distributed weight, N/m (+ downwards).
    youngs_modulus : float
        Pa.
    aft_edge_offset, fore_edge_offset : float
        Vertical offsets of the support points at the bearing edges, m.
    divisions : int
        Elements across the bearing length (10 in the seed).
    beam_theory : str
        ``"timoshenko"`` (default) or ``"euler_bernoulli"``.
    shear_area_factor : float or None
        Timoshenko shear coefficient; None for Cowper's. The seed's tables are reproduced
        with 1.0 (shear area = section area), see docs/theory.md.
    """

    bearing_length: float
    shaft_diameter: float
    aft_overhang: float
    fore_length: float
    aft_force: float
    aft_moment: float
    fore_force: float
    fore_rotation: float
    weight_per_length: float
    youngs_modulus: float = 206e9
    aft_edge_offset: float = 0.0
    fore_edge_offset: float = 0.0
    divisions: int = 10
    beam_theory: str = "timoshenko"
    shear_area_factor: float | None = None

    def __post_init__(self) -> None:
        for name in ("bearing_length", "shaft_diameter", "aft_overhang", "fore_length", "youngs_modulus"):
            require_positive(name, getattr(self, name), "m" if name != "youngs_modulus" else "Pa")
        for name in (
            "aft_force",
            "aft_moment",
            "fore_force",
            "fore_rotation",
            "weight_per_length",
            "aft_edge_offset",
            "fore_edge_offset",
        ):
            require_finite(name, getattr(self, name))

    @classmethod
    def from_misalignment(
        cls, ratio: float, radial_clearance: float, aft_share: float = 0.25, **kwargs: Any
    ) -> LocalShaftModel:
        """Edge offsets giving a chord slope of ``ratio * 2c/L``: the aft edge ``aft_share`` of
        the rise below the reference, the forward edge the rest above it (seed 004 Table 5-29
        puts a quarter below)."""
        rise = ratio * 2.0 * radial_clearance
        return cls(aft_edge_offset=-aft_share * rise, fore_edge_offset=(1 - aft_share) * rise, **kwargs)


@dataclass(frozen=True, eq=False)
class LocalShaftLine:
    """Elastic line of the local model.

    Attributes
    ----------
    x : ndarray
        Stations from the aft end, m.
    deflection : ndarray
        m (+ up).
    rotation : ndarray
        Section rotation, rad.
    edge_reactions : ndarray (2,)
        Support forces at the aft and forward bearing edges, N.
    """

    x: np.ndarray
    deflection: np.ndarray
    rotation: np.ndarray
    edge_reactions: np.ndarray
    aft_edge: float
    fore_edge: float

    def bent_journal(self) -> tuple[float, BentJournal]:
        """(chord slope, offsets from the chord) of the shaft inside the bearing, for the film model."""
        inside = (self.x >= self.aft_edge - 1e-9) & (self.x <= self.fore_edge + 1e-9)
        z = self.x[inside] - self.aft_edge
        v = self.deflection[inside]
        slope = (v[-1] - v[0]) / (z[-1] - z[0])
        chord = v[0] + slope * z
        mid = 0.5 * (z[0] + z[-1])
        # Offsets from the straight line through the chord, taken relative to mid-plane.
        dy = v - chord
        dy = dy - np.interp(mid, z, dy)
        return float(slope), BentJournal(z=z, dy=dy, dz=np.zeros_like(z))


def seed004_local_model() -> LocalShaftModel:
    """The local shaft model of seed 004 Table 4-5 / 5-1 (its edge offsets set per psi_x by
    :func:`bent_shaft`): L = 1.05 m, D = 0.52 m, overhangs 0.407 and 0.5412 m, M_aft = 409948 N m
    (nose-up in shaftline's sign), F_aft = -202598.2 N, F_fore = -107261.7 N, fore slope
    0.465 mrad, 16343 N/m, E = 206 GPa, shear area = section area (the seed's tables are
    reproduced so, tests/shaft/test_local_seed004.py)."""
    return LocalShaftModel(
        bearing_length=1.05,
        shaft_diameter=0.52,
        aft_overhang=0.407,
        fore_length=0.5412,
        aft_force=-202598.2,
        aft_moment=409948.0,
        fore_force=-107261.7,
        fore_rotation=0.000465,
        weight_per_length=16343.0,
        beam_theory="timoshenko",
        shear_area_factor=1.0,
    )


def solve_local_model(model: LocalShaftModel) -> LocalShaftLine:
    """Elastic line of the local shaft model (nodes at the ends, bearing edges and divisions)."""
    aft_edge = model.aft_overhang
    fore_edge = aft_edge + model.bearing_length
    total = fore_edge + model.fore_length
    line = ShaftLine(
        segments=(
            ShaftSegment(
                total,
                model.shaft_diameter,
                youngs_modulus=model.youngs_modulus,
                shear_area_factor=model.shear_area_factor,
            ),
        ),
        bearings=(Bearing("aft edge", aft_edge, 1e-6), Bearing("fore edge", fore_edge, 1e-6)),
        self_weight=False,
        element_length=model.bearing_length / model.divisions,
        beam_theory=model.beam_theory,
    )
    stations = np.concatenate([[0.0], aft_edge + np.linspace(0.0, model.bearing_length, model.divisions + 1), [total]])
    mesh = build_mesh(line, stations)
    aft, fore = (int(k) for k in mesh.node_at(np.array([aft_edge, fore_edge])))
    end = mesh.nodes - 1
    beam = PinnedBeam(mesh, (2 * aft, 2 * fore, 2 * end + 1))
    forces = uniform_load_vector(mesh, np.full(mesh.nodes - 1, -model.weight_per_length))
    forces[0] += model.aft_force
    forces[1] += model.aft_moment
    forces[2 * end] += model.fore_force
    prescribed = np.array([model.aft_edge_offset, model.fore_edge_offset, model.fore_rotation])
    u = beam.solve(forces, prescribed)
    reactions = beam.reactions(u, forces)[:2]
    return LocalShaftLine(mesh.x, u[0::2], u[1::2], reactions, aft_edge, fore_edge)
