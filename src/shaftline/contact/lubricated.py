"""A lubricated contact evaluated in one vectorised pass: Hertz, film, Lambda and friction.

:func:`evaluate` takes arrays of load, radii, surface speeds and temperature that broadcast
against each other (a path of contact, a map of load stages x speeds x points) and returns
a :class:`ContactState` of arrays of the broadcast shape. No Python loop runs over points.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Literal

import numpy as np

from shaftline.contact import ehl, hertz
from shaftline.contact.friction import seed_friction
from shaftline.contact.rheology import ContactLubricant
from shaftline.errors import InputError, first_offending

ArrayLike = float | np.ndarray
Geometry = Literal["line", "point"]

#: How an error names the mean Hertz pressure, which the user sets through the load and the radii.
MEAN_PRESSURE = "mean Hertz pressure p_m (from the load and the radii)"


@dataclass(frozen=True)
class Surfaces:
    """Elastic constants and roughness of the two bodies (SI).

    Attributes
    ----------
    youngs_modulus_1, youngs_modulus_2 : float
        Pa.
    poisson_ratio_1, poisson_ratio_2 : float
    roughness_1, roughness_2 : float
        Rq of each surface, m.
    """

    youngs_modulus_1: float = 206e9
    poisson_ratio_1: float = 0.3
    youngs_modulus_2: float = 206e9
    poisson_ratio_2: float = 0.3
    roughness_1: float = 0.5e-6
    roughness_2: float = 0.5e-6

    @property
    def modulus(self) -> float:
        """Reduced modulus E', Pa."""
        return float(
            hertz.reduced_modulus(
                self.youngs_modulus_1, self.poisson_ratio_1, self.youngs_modulus_2, self.poisson_ratio_2
            )
        )


@dataclass(frozen=True)
class ContactModel:
    """The choices of a lubricated-contact evaluation.

    Attributes
    ----------
    lubricant : ContactLubricant
    geometry : str
        ``"line"`` (load per unit length, one radius) or ``"point"`` (load, two radii).
    film_method : str
        A key of :data:`shaftline.contact.ehl.LINE_FILM_METHODS` (line) or
        :data:`~shaftline.contact.ehl.POINT_FILM_METHODS` (point); ``"default"`` is
        Dowson-Toyoda or Hamrock-Dowson.
    thermal_method : str
        A key of :data:`shaftline.contact.ehl.THERMAL_METHODS`.
    pressure_viscosity_model : str
        ``"roelands"`` or ``"barus"``: the viscosity in the contact for the Bair-Winer stress.
    boundary_friction : float
        f_b of seed 002 Eq. 1.
    ellipticity_method : str
        ``"exact"`` or ``"hamrock_brewe"`` (point contacts).
    extrapolate : bool
        Evaluate correlations outside their validity ranges with a warning instead of an error.
    """

    lubricant: ContactLubricant
    geometry: Geometry = "line"
    film_method: str = "default"
    thermal_method: str = "gupta"
    pressure_viscosity_model: str = "roelands"
    boundary_friction: float = 0.1
    ellipticity_method: str = "exact"
    extrapolate: bool = False

    @property
    def film(self) -> str:
        """The film method in use (``"default"`` resolved)."""
        if self.film_method != "default":
            return self.film_method
        return "dowson_toyoda" if self.geometry == "line" else "hamrock_dowson"


@dataclass(frozen=True, eq=False)
class ContactState:
    """A lubricated contact at every point (arrays of one broadcast shape, SI).

    Attributes
    ----------
    peak_pressure, mean_pressure : ndarray
        Hertz p_H and p_m, Pa.
    half_width : ndarray
        Semi-width of the contact in the rolling direction, m.
    max_shear, max_shear_depth : ndarray
        Largest subsurface shear stress (Pa) and its depth (m) on the contact's axis, for
        line, circular and elliptical contacts.
    rolling_speed, sliding_speed, slide_roll : ndarray
        u = (u1 + u2)/2, Delta u = u2 - u1 (m/s) and S = Delta u / u.
    central_film, minimum_film : ndarray
        Film thickness with the thermal reduction, m (minimum NaN for Moes).
    thermal_factor : ndarray
        Inlet shear-heating reduction phi_T.
    film_ratio : ndarray
        Lambda = h_c / sqrt(Rq1^2 + Rq2^2).
    regime : ndarray
        Index into :data:`shaftline.contact.ehl.REGIMES`: the point-contact map, or Moes' asymptotes
        for line contacts.
    friction, mixed_friction, full_film_friction, load_sharing, thermal_correction : ndarray
        f, f_a, f_c, g and c of seed 002.
    power_intensity : ndarray
        Frictional power intensity ``f p_H |Delta u|``, W/m^2.
    """

    peak_pressure: np.ndarray
    mean_pressure: np.ndarray
    half_width: np.ndarray
    max_shear: np.ndarray
    max_shear_depth: np.ndarray
    rolling_speed: np.ndarray
    sliding_speed: np.ndarray
    slide_roll: np.ndarray
    central_film: np.ndarray
    minimum_film: np.ndarray
    thermal_factor: np.ndarray
    film_ratio: np.ndarray
    regime: np.ndarray
    friction: np.ndarray
    mixed_friction: np.ndarray
    full_film_friction: np.ndarray
    load_sharing: np.ndarray
    thermal_correction: np.ndarray
    power_intensity: np.ndarray


def evaluate(
    model: ContactModel,
    surfaces: Surfaces,
    load: ArrayLike,
    speed_1: ArrayLike,
    speed_2: ArrayLike,
    temperature: ArrayLike,
    radius_x: ArrayLike,
    radius_y: ArrayLike = np.inf,
) -> ContactState:
    """Evaluate a lubricated contact at every point of broadcast arrays.

    Parameters
    ----------
    model : ContactModel
    surfaces : Surfaces
    load : array_like
        Load per unit length w' (line, N/m) or load w (point, N).
    speed_1, speed_2 : array_like
        Surface speeds of the two bodies in the rolling direction, m/s; their mean must be > 0.
    temperature : array_like
        Inlet (bulk) oil temperature, degC.
    radius_x, radius_y : array_like
        Reduced radii in the rolling and transverse direction, m (radius_y only for point).
    """
    lubricant = model.lubricant
    modulus = surfaces.modulus
    u1 = np.asarray(speed_1, dtype=float)
    u2 = np.asarray(speed_2, dtype=float)
    rolling = 0.5 * (u1 + u2)
    if np.any(~(rolling > 0.0)):
        raise InputError(
            "rolling_speed", first_offending(rolling, rolling > 0.0), "m/s", "> 0 (mean of the surface speeds)"
        )
    sliding = u2 - u1
    slide_roll = sliding / rolling
    eta0 = lubricant.dynamic_viscosity(temperature, model.extrapolate)
    alpha = lubricant.alpha(temperature)
    u_param = ehl.speed_parameter(eta0, rolling, modulus, radius_x)
    g_param = ehl.material_parameter(alpha, modulus)
    contact = _hertz_and_film(model, load, radius_x, radius_y, modulus, u_param, g_param)
    p_h, p_m = contact.peak_pressure, contact.mean_pressure
    loading = ehl.thermal_loading(
        lubricant.temperature_viscosity_coefficient(temperature), eta0, rolling, lubricant.thermal_conductivity
    )
    thermal = ehl.method(ehl.THERMAL_METHODS, model.thermal_method, "thermal_method")(
        loading, slide_roll, p_h / modulus
    )
    central = contact.central * np.asarray(radius_x) * thermal
    minimum = contact.minimum * np.asarray(radius_x) * thermal
    film_ratio = ehl.film_ratio(central, surfaces.roughness_1, surfaces.roughness_2)
    friction = seed_friction(
        film_ratio=film_ratio,
        boundary=model.boundary_friction,
        limiting_stress=lubricant.limiting_shear_stress(p_m, model.extrapolate, MEAN_PRESSURE),
        viscosity_at_pressure=lubricant.viscosity_at(
            p_m, temperature, model.pressure_viscosity_model, model.extrapolate, MEAN_PRESSURE
        ),
        viscosity=eta0,
        rolling_speed=rolling,
        slide_roll=slide_roll,
        central_film=central,
        peak_pressure=p_h,
        mean_pressure=p_m,
        extrapolate=model.extrapolate,
    )
    shape = np.broadcast_shapes(np.shape(central), np.shape(friction.coefficient), np.shape(p_h))

    def full(a: ArrayLike) -> np.ndarray:
        return np.broadcast_to(np.asarray(a), shape)

    return ContactState(
        peak_pressure=full(p_h),
        mean_pressure=full(p_m),
        half_width=full(contact.half_width),
        max_shear=full(contact.max_shear),
        max_shear_depth=full(contact.depth),
        rolling_speed=full(rolling),
        sliding_speed=full(sliding),
        slide_roll=full(slide_roll),
        central_film=full(central),
        minimum_film=full(minimum),
        thermal_factor=full(thermal),
        film_ratio=full(film_ratio),
        regime=full(contact.regime),
        friction=full(friction.coefficient),
        mixed_friction=full(friction.mixed),
        full_film_friction=full(friction.full_film),
        load_sharing=full(friction.load_sharing),
        thermal_correction=full(friction.thermal),
        power_intensity=full(friction.coefficient * p_h * np.abs(sliding)),
    )


@dataclass(frozen=True, eq=False)
class _HertzFilm:
    """The dry Hertz contact of a line or point contact and its isothermal film.

    Attributes
    ----------
    peak_pressure, mean_pressure : ndarray
        Hertz p_H and p_m, Pa.
    half_width : ndarray
        Semi-width of the contact in the rolling direction, m.
    max_shear, depth : ndarray
        Largest subsurface shear stress, Pa, and its depth, m.
    central, minimum : ndarray
        Dimensionless central and minimum films H = h / R_x of the film method (no thermal
        reduction).
    regime : ndarray
        Index into :data:`shaftline.contact.ehl.REGIMES`.
    """

    peak_pressure: np.ndarray
    mean_pressure: np.ndarray
    half_width: np.ndarray
    max_shear: np.ndarray
    depth: np.ndarray
    central: np.ndarray
    minimum: np.ndarray
    regime: np.ndarray


def _hertz_and_film(
    model: ContactModel,
    load: ArrayLike,
    radius_x: ArrayLike,
    radius_y: ArrayLike,
    modulus: ArrayLike,
    u_param: np.ndarray,
    g_param: np.ndarray,
) -> _HertzFilm:
    """The Hertz contact and the film of ``model``'s geometry: ``load`` per length (line,
    N/m) or load (point, N) on the reduced radii ``radius_x``, ``radius_y`` (m) and modulus
    (Pa), at the speed and material parameters ``u_param``, ``g_param``.

    Raises
    ------
    InputError
        A geometry other than line or point; a film method unknown for the geometry.
    """
    if model.geometry == "line":
        contact = hertz.line_contact(load, radius_x, modulus)
        formula = ehl.method(ehl.LINE_FILM_METHODS, model.film, "film_method")
        central, minimum = formula(u_param, g_param, ehl.line_load_parameter(load, modulus, radius_x))
        regime = ehl.line_regime(u_param, g_param, ehl.line_load_parameter(load, modulus, radius_x))
        return _HertzFilm(
            contact.peak_pressure,
            contact.mean_pressure,
            contact.half_width,
            contact.max_shear,
            contact.max_shear_depth,
            central,
            minimum,
            regime,
        )
    if model.geometry == "point":
        point = hertz.point_contact(load, radius_x, radius_y, modulus, model.ellipticity_method)
        formula = ehl.method(ehl.POINT_FILM_METHODS, model.film, "film_method")
        w_param = ehl.point_load_parameter(load, modulus, radius_x)
        central, minimum = formula(u_param, g_param, w_param, point.ellipticity)
        regime, _ = ehl.point_regime(u_param, g_param, w_param, point.ellipticity)
        return _HertzFilm(
            point.peak_pressure,
            point.mean_pressure,
            point.semi_axis_x,
            point.max_shear,
            point.max_shear_depth,
            central,
            minimum,
            regime,
        )
    raise InputError("geometry", model.geometry, "", "line or point")
