"""What the bore's surfaces add to the film: nothing (smooth), or asperity contact, flow
factors and a film that may pass the mean plane (rough; docs/theory.md Sect. 17, "Mixed
lubrication" and "Boundary lubrication").

The film solver and the equilibrium ask the surfaces, not the geometry, where the film may go
and what it carries besides the fluid: :class:`SmoothSurfaces` and :class:`RoughSurfaces`
answer the same questions (:func:`film_surfaces` picks one).
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING, Protocol

import numpy as np

from shaftline.film.roughness import (
    BOUNDARY_LIMIT,
    LAMBDA_SWITCH,
    TABLE_LOWEST,
    RoughFilm,
    SurfaceRoughness,
    asperity_pressure,
    asperity_pressure_derivative,
    contact_area_ratio,
    lubrication_regime,
    mean_gap,
)

if TYPE_CHECKING:
    from shaftline.film.results import RoughContact

__all__ = ["FilmSurfaces", "RoughSurfaces", "SmoothSurfaces", "contact_zone_nodes", "film_surfaces"]


class FilmSurfaces(Protocol):
    """The questions a film solver asks of the surfaces of journal and bore (lengths in m).

    Attributes
    ----------
    rough : bool
        Whether the surfaces carry asperity contact.
    sigma : float
        Composite RMS roughness, m (0 smooth).
    film_limit : float
        Film below which no film is evaluated: 0 smooth (the journal cuts the bore), the end of
        the tables of F_n (``TABLE_LOWEST * sigma``, -4 sigma) rough.
    floor : float
        Smallest film the equilibrium may approach: ``min_film_floor`` of the clearance
        (smooth), or the boundary limit ``BOUNDARY_LIMIT * sigma`` (-3 sigma; rough): the nominal
        gap between the mean planes may go negative, the asperities carrying the load.
    approach_floor : float
        The floor a rough film had before it could pass the mean plane: ``min_film_floor`` of
        the clearance, at most 2 % of sigma (``LAMBDA_SWITCH``); the equilibrium's line search
        approaches it first and passes it only from within twice its film, and a liner's
        deformation starts from a film of it. Smooth: the floor itself.
    flow : RoughFilm or None
        The film equation's flow factors (None smooth).
    """

    rough: bool
    sigma: float
    film_limit: float
    floor: float
    approach_floor: float
    flow: RoughFilm | None

    def at_floor(self, hmin: float, margin: float) -> bool:
        """Whether a film of ``hmin`` is at the floor: within half the floor above it smooth, within
        ``margin`` sigma (``NewtonOptions.floor_margin``) above the boundary limit rough."""
        ...

    def start_lift(self, share: float) -> float:
        """The first lift of a lined start's retreat: sigma (rough), else ``share`` of the
        clearance (``NewtonOptions.start_lift``)."""
        ...

    def contact(self, film: np.ndarray) -> np.ndarray | None:
        """Asperity contact pressure at the film (Pa; None smooth)."""
        ...

    def contact_slope(self, film: np.ndarray) -> np.ndarray | None:
        """``d p_a / d h`` at the film (Pa/m; None smooth)."""
        ...

    def liner_film(self, hmin: float) -> float:
        """The film that sets a liner's inexact tolerance: ``hmin``, or on a rough film at or below
        the mean plane 2 % of sigma (the force is then the asperities' and the film's on the mean
        gap, not a share of a vanishing film)."""
        ...

    def zone_nodes(self, film: np.ndarray) -> int:
        """:func:`contact_zone_nodes` of the film (0 smooth)."""
        ...

    def shear_gap(self, film: np.ndarray) -> np.ndarray:
        """The gap the fluid shears over: the film (smooth), or the mean gap ``h_T`` (rough:
        finite as the nominal film passes the mean plane)."""
        ...

    def boundary_friction(self, contact: np.ndarray | None, weights: np.ndarray) -> float:
        """Friction force of the asperities, N (0 smooth)."""
        ...

    def contact_part(
        self,
        film: np.ndarray,
        contact: np.ndarray | None,
        weights: np.ndarray,
        theta: np.ndarray,
        rotation: int,
        area: float,
        force: tuple[float, float],
        hmin: float,
        friction: tuple[float, float],
    ) -> RoughContact | None:
        """The rough contact's part of a bearing state (None smooth)."""
        ...


class SmoothSurfaces:
    """Smooth surfaces: the film is the fluid's alone and may not close below its floor."""

    rough = False
    sigma = 0.0
    film_limit = 0.0
    flow: RoughFilm | None = None

    def __init__(self, clearance: float, min_film_floor: float) -> None:
        self.clearance = clearance
        self.floor = min_film_floor * clearance
        self.approach_floor = self.floor

    def at_floor(self, hmin: float, margin: float) -> bool:
        return hmin <= 1.5 * self.floor

    def start_lift(self, share: float) -> float:
        return share * self.clearance

    def contact(self, film: np.ndarray) -> None:
        return None

    def contact_slope(self, film: np.ndarray) -> None:
        return None

    def liner_film(self, hmin: float) -> float:
        return hmin

    def zone_nodes(self, film: np.ndarray) -> int:
        return 0

    def shear_gap(self, film: np.ndarray) -> np.ndarray:
        return film

    def boundary_friction(self, contact: np.ndarray | None, weights: np.ndarray) -> float:
        return 0.0

    def contact_part(self, *args: object, **kwargs: object) -> None:
        return None


class RoughSurfaces:
    """Rough surfaces (:class:`~shaftline.film.roughness.SurfaceRoughness`): Greenwood-Tripp
    asperity contact and Patir-Cheng flow factors, the film free to pass the mean plane down to
    the boundary limit."""

    rough = True

    def __init__(self, surface: SurfaceRoughness, clearance: float, min_film_floor: float) -> None:
        self.surface = surface
        self.sigma = surface.sigma
        self.clearance = clearance
        self.film_limit = TABLE_LOWEST * self.sigma
        self.floor = BOUNDARY_LIMIT * self.sigma
        self.approach_floor = min(min_film_floor * clearance, LAMBDA_SWITCH * self.sigma)
        self.flow: RoughFilm | None = RoughFilm(self.sigma / clearance, surface.shear_weight)

    def at_floor(self, hmin: float, margin: float) -> bool:
        return hmin <= self.floor + margin * self.sigma

    def start_lift(self, share: float) -> float:
        return self.sigma

    def contact(self, film: np.ndarray) -> np.ndarray:
        return asperity_pressure(self.surface, film)

    def contact_slope(self, film: np.ndarray) -> np.ndarray:
        return asperity_pressure_derivative(self.surface, film)

    def liner_film(self, hmin: float) -> float:
        return max(hmin, LAMBDA_SWITCH * self.sigma)

    def zone_nodes(self, film: np.ndarray) -> int:
        return contact_zone_nodes(film, self.sigma)

    def shear_gap(self, film: np.ndarray) -> np.ndarray:
        return self.sigma * mean_gap(film / self.sigma)

    def boundary_friction(self, contact: np.ndarray | None, weights: np.ndarray) -> float:
        assert contact is not None
        return float(np.sum(self.surface.boundary_friction * contact * weights))

    def contact_part(
        self,
        film: np.ndarray,
        contact: np.ndarray | None,
        weights: np.ndarray,
        theta: np.ndarray,
        rotation: int,
        area: float,
        force: tuple[float, float],
        hmin: float,
        friction: tuple[float, float],
    ) -> RoughContact:
        from shaftline.film.results import RoughContact

        assert contact is not None
        fy, fz = force
        capacity = float(np.hypot(fy, fz))
        ay = -float(np.sum(contact * weights * np.cos(theta)[None, :]))
        az = -rotation * float(np.sum(contact * weights * np.sin(theta)[None, :]))
        lam_min = hmin / self.sigma
        return RoughContact(
            asperity_pressure=contact,
            asperity_load=float(np.hypot(ay, az)),
            asperity_load_share=(ay * fy + az * fz) / capacity**2 if capacity > 0 else 0.0,
            max_asperity_pressure=float(contact.max()),
            contact_area_ratio=float(np.sum(contact_area_ratio(self.surface, film) * weights) / area),
            fluid_friction_force=friction[0],
            boundary_friction_force=friction[1],
            film_ratio=film / self.sigma,
            min_film_ratio=lam_min,
            lubrication_regime=lubrication_regime(lam_min),
        )


def film_surfaces(surface: SurfaceRoughness | None, clearance: float, min_film_floor: float) -> FilmSurfaces:
    """The surfaces of a bearing: rough where it has a ``surface``, else smooth."""
    if surface is None:
        return SmoothSurfaces(clearance, min_film_floor)
    return RoughSurfaces(surface, clearance, min_film_floor)


def contact_zone_nodes(film: np.ndarray, sigma: float) -> int:
    """Circumferential nodes of the row of the thinnest film whose film is within one composite
    roughness ``sigma`` (m) of that row's minimum: how many nodes resolve a rough contact zone.
    ``film`` in m, shape (nz, nt).

    Near its minimum a journal's film is ``h_min + c eps theta^2 / 2``, so the zone is
    ``2 sqrt(2 sigma / (c eps))`` wide: 10 degrees on seed 001's rig (3.4 nodes on its 3 degree
    grid, 14 on a 0.75 degree one). Below ``SettleOptions.zone_nodes`` the discrete film force of
    a rigid rough bore jumps as the minimum moves between nodes (docs/theory.md, "Rigid rough bore
    at low speed")."""
    row = film[int(np.argmin(film.min(axis=1)))]
    return int(np.count_nonzero(row <= row.min() + sigma))


def nodes_to_resolve_contact_zone(film: np.ndarray, sigma: float, zone_nodes: int) -> int:
    """Circumferential nodes (even) that would put ``zone_nodes`` (``SettleOptions.zone_nodes``)
    nodes across the contact zone of ``film`` (m, shape (nz, nt), on a grid of nt nodes round the
    bore): the zone keeps its width in angle as the grid is refined. The count of nodes inside a
    zone is up to one more than its width in cells, so the width is taken as one node less (seed
    001's rig: 4 nodes on 120, 400 asked; 3.4 cells wide, so 11 nodes there)."""
    nt = film.shape[1]
    zone = max(contact_zone_nodes(film, sigma) - 1, 1)
    needed = math.ceil(nt * zone_nodes / zone)
    return needed + needed % 2
