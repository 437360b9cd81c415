"""The bore's surfaces in ``[bearing]``: rough journal and bore (``[bearing.surface]``,
mixed lubrication) and the elastic liner on the bore (``[bearing.liner]``), and the domain
objects built from them; ``[monitor]`` and ``[alignment]`` take the same tables."""

from __future__ import annotations

import math
from typing import Annotated, Literal

from pydantic import model_validator

from shaftline.cases.types import (
    NonNegativeLength,
    Plausible,
    PositiveLength,
    PositivePressure,
    Quantity,
    Section,
    field_error,
)
from shaftline.errors import InputError, located
from shaftline.film.liner import Liner
from shaftline.film.roughness import SurfaceRoughness

_SURFACE_ROUGHNESS = (
    "machined journals and bores: Ra 0.1 um (lapped) to 6.3 um (rough turned); seed 001: polymer liner Ra 1.6 um, "
    "sleeve Ra 0.8 um; 20 um keeps a value in um written as mm out (engineering judgement)"
)
_ASPERITY_RADIUS = (
    "asperity tip radii from profiles of machined surfaces, about 1 um to 1 mm (Greenwood & Williamson 1966: "
    "tens of um; sigma/beta = 0.001 on Ra 1 um is about 1 mm); mm written as m is above (engineering judgement)"
)
_ASPERITY_DENSITY = (
    "asperities per m^2 from profiles of machined surfaces, about 1e8 to 1e12 (Greenwood & Williamson 1966: "
    "1e9-1e11; sigma beta eta 0.04 with sigma 1 um and beta 1 mm is 4e7); per mm^2 written as per m^2 is "
    "below (engineering judgement)"
)
_MODULUS = (
    "nitrile rubber liners about 3-10 MPa, polymer composites 1-10 GPa (seed 001: 2320 MPa), white metal about "
    "50 GPa, steel 206 GPa; 3 MPa to 500 GPa keeps GPa written as MPa and MPa as kPa out (engineering judgement)"
)


class SurfaceSection(Section):
    """Rough journal and bore: Patir-Cheng flow factors in the film and Greenwood-Tripp asperity
    contact (mixed lubrication, docs/theory.md). A preset gives every field; fields given
    beside it replace the preset's."""

    preset: Literal["steel_polymer", "turned_steel_white_metal", "ground_steel_white_metal"] | None = None
    """Named surface pair (docs/theory.md lists the sources): steel_polymer (seed 001's rig),
    turned_steel_white_metal, ground_steel_white_metal."""
    journal_roughness: Annotated[NonNegativeLength, Plausible(0.0, 2e-5, _SURFACE_ROUGHNESS)] | None = None
    """Roughness of the journal (sleeve)."""
    bore_roughness: Annotated[NonNegativeLength, Plausible(0.0, 2e-5, _SURFACE_ROUGHNESS)] | None = None
    """Roughness of the bore (liner)."""
    roughness_parameter: Literal["Rq", "Ra"] = "Ra"
    """Rq (root mean square) or Ra (arithmetic mean; Rq = 1.25 Ra, seed 001 Eq. 10)."""
    journal_modulus: Annotated[PositivePressure, Plausible(3e6, 5e11, _MODULUS)] | None = None
    """Young's modulus of the journal (default steel, 206 GPa)."""
    journal_poisson: Annotated[float, Quantity("dimensionless", gt=0, lt=0.5)] | None = None
    """Poisson's ratio of the journal (default 0.3)."""
    bore_modulus: Annotated[PositivePressure, Plausible(3e6, 5e11, _MODULUS)] | None = None
    """Young's modulus of the bore surface (liner)."""
    bore_poisson: Annotated[float, Quantity("dimensionless", gt=0, lt=0.5)] | None = None
    """Poisson's ratio of the bore surface."""
    sigma_beta_eta: Annotated[float, Quantity("dimensionless", gt=0, lt=1)] | None = None
    """Roughness parameter sigma beta eta (default 0.04)."""
    sigma_over_beta: Annotated[float, Quantity("dimensionless", gt=0, lt=1)] | None = None
    """RMS roughness over asperity tip radius (default 0.001)."""
    asperity_radius: Annotated[PositiveLength, Plausible(1e-7, 0.01, _ASPERITY_RADIUS)] | None = None
    """Mean asperity tip radius beta, measured (in place of sigma_over_beta: sigma / beta with
    sigma the composite Rq)."""
    asperity_density: (
        Annotated[float, Quantity("areal_density", gt=0), Plausible(1e6, 1e14, _ASPERITY_DENSITY)] | None
    ) = None
    """Asperities per unit area eta, measured (with asperity_radius, in place of sigma_beta_eta:
    sigma beta eta with sigma the composite Rq)."""
    boundary_friction: Annotated[float, Quantity("dimensionless", ge=0, lt=1)] | None = None
    """Coefficient of friction on the asperity load (default 0.1)."""

    @model_validator(mode="after")
    def _complete(self) -> SurfaceSection:
        if self.preset is None:
            for name in ("journal_roughness", "bore_roughness", "bore_modulus", "bore_poisson"):
                if getattr(self, name) is None:
                    raise field_error(name, "missing", "a value, or a preset")
        journal, bore = self.journal_roughness, self.bore_roughness
        if journal == 0 and bore == 0:
            raise field_error("bore_roughness", 0.0, "> 0 where journal_roughness is 0 (a rough surface)", "m")
        return self


def surface_roughness(section: SurfaceSection) -> SurfaceRoughness:
    """The :class:`SurfaceRoughness` of a ``surface`` table (fields beside a preset replace it)."""
    from shaftline.film.roughness import PRESETS, RA_TO_RQ, contact_modulus

    base = PRESETS[section.preset] if section.preset is not None else None
    factor = RA_TO_RQ if section.roughness_parameter == "Ra" else 1.0
    journal = section.journal_roughness
    bore = section.bore_roughness
    if base is not None:
        # Preset roughnesses are Ra; a value given beside them is in the table's parameter.
        journal_rq = RA_TO_RQ * base[0] if journal is None else factor * journal
        bore_rq = RA_TO_RQ * base[1] if bore is None else factor * bore
        bore_e = base[2] if section.bore_modulus is None else section.bore_modulus
        bore_nu = base[3] if section.bore_poisson is None else section.bore_poisson
    else:
        assert journal is not None and bore is not None and section.bore_modulus is not None
        assert section.bore_poisson is not None
        journal_rq, bore_rq = factor * journal, factor * bore
        bore_e, bore_nu = section.bore_modulus, section.bore_poisson
    journal_e = 206e9 if section.journal_modulus is None else section.journal_modulus
    journal_nu = 0.3 if section.journal_poisson is None else section.journal_poisson
    sigma_beta_eta, sigma_over_beta = _asperity_parameters(section, math.hypot(journal_rq, bore_rq))
    names = {"journal_rq": "journal_roughness", "bore_rq": "bore_roughness", "contact_modulus": "bore_modulus"}
    with located("", names):
        defaults = SurfaceRoughness(journal_rq=1.0, bore_rq=1.0)
        return SurfaceRoughness(
            journal_rq=journal_rq,
            bore_rq=bore_rq,
            sigma_beta_eta=sigma_beta_eta or defaults.sigma_beta_eta,
            sigma_over_beta=sigma_over_beta or defaults.sigma_over_beta,
            contact_modulus=contact_modulus(journal_e, journal_nu, bore_e, bore_nu),
            boundary_friction=defaults.boundary_friction
            if section.boundary_friction is None
            else section.boundary_friction,
        )


def _asperity_parameters(section: SurfaceSection, sigma: float) -> tuple[float | None, float | None]:
    """Greenwood-Tripp's sigma beta eta and sigma / beta of a ``surface`` table: as given, or
    from a measured asperity radius beta and density eta with sigma the composite Rq (m; the
    spread of the asperity heights taken as the surfaces', docs/theory.md Sect. 17)."""
    sigma_beta_eta, sigma_over_beta = section.sigma_beta_eta, section.sigma_over_beta
    radius, density = section.asperity_radius, section.asperity_density
    if radius is not None:
        if sigma_over_beta is not None:
            raise InputError("asperity_radius", radius, "m", "sigma_over_beta or asperity_radius, not both")
        sigma_over_beta = sigma / radius
        if not sigma_over_beta < 1.0:
            raise InputError(
                "asperity_radius", radius, "m", f"above the composite roughness {sigma:.3g} m (sigma / beta < 1)"
            )
    if density is not None:
        if radius is None:
            raise InputError("asperity_density", density, "1/m^2", "with asperity_radius (sigma beta eta needs both)")
        if sigma_beta_eta is not None:
            raise InputError("asperity_density", density, "1/m^2", "sigma_beta_eta or asperity_density, not both")
        sigma_beta_eta = sigma * radius * density
        if not sigma_beta_eta < 1.0:
            raise InputError(
                "asperity_density",
                density,
                "1/m^2",
                f"below {1.0 / (sigma * radius):.3g} 1/m^2 (sigma beta eta < 1 with sigma {sigma:.3g} m and beta "
                f"{radius:.3g} m)",
            )
    return sigma_beta_eta, sigma_over_beta


def checked_surface(section: SurfaceSection, clearance: float) -> SurfaceRoughness:
    """:func:`surface_roughness` of a ``surface`` table, its composite roughness checked against
    the radial clearance ``clearance`` (m): below half of it (errors placed under ``surface``)."""
    with located("surface"):
        surface = surface_roughness(section)
    if surface.sigma >= 0.5 * clearance:
        name = "bore_roughness" if surface.bore_rq >= surface.journal_rq else "journal_roughness"
        raise InputError(
            f"surface.{name}",
            getattr(section, name),
            "m",
            f"a composite roughness (now {surface.sigma:.3g} m Rq) below half the radial clearance "
            f"({0.5 * clearance:.3g} m)",
        )
    return surface


class LinerSection(Section):
    """Thin elastic liner bonded to the bore: deforms under the film and asperity pressure by
    the column (Winkler) model or as a bonded elastic layer, solved together with the film
    (docs/theory.md, "Elastic liner", "Elastic layer"). A preset gives every field; fields given
    beside it replace the preset's."""

    model: Literal["column", "layer"] = "column"
    """column: each point of the liner moves under its own pressure (Winkler); layer: the
    surface compliance of an elastic layer bonded to the shell (spreads a load over a few
    thicknesses; takes a rubber liner up to poisson 0.5; slower, docs/theory.md "Elastic layer")."""

    preset: Literal["polymer_composite", "rubber", "white_metal"] | None = None
    """Named liner (docs/theory.md lists the sources): polymer_composite (seed 001's rig, 20 mm,
    2320 MPa, 0.327), rubber (10 mm nitrile, 7 MPa, 0.49: the column model's lower bound of its
    deformation), white_metal (2 mm tin-based, ASTM B23 grade 2, 53 GPa, 0.35)."""
    thickness: PositiveLength | None = None
    """Liner thickness (at most a quarter of the bore radius)."""
    modulus: Annotated[PositivePressure, Plausible(3e6, 5e11, _MODULUS)] | None = None
    """Young's modulus of the liner."""
    poisson: Annotated[float, Quantity("dimensionless", gt=0, le=0.5)] | None = None
    """Poisson's ratio of the liner, in (0, 0.5); the layer model also takes 0.5."""

    @model_validator(mode="after")
    def _complete(self) -> LinerSection:
        if self.preset is None:
            for name in ("thickness", "modulus", "poisson"):
                if getattr(self, name) is None:
                    raise field_error(name, "missing", "a value, or a preset")
        if self.model == "column" and self.poisson == 0.5:
            raise field_error("poisson", self.poisson, "in (0, 0.5) for the column model (model = 'layer' takes 0.5)")
        return self


def liner_of(section: LinerSection) -> Liner:
    """The :class:`Liner` of a ``liner`` table (fields beside a preset replace it)."""
    from shaftline.film.liner import LINER_PRESETS

    base = LINER_PRESETS[section.preset] if section.preset is not None else (None, None, None)
    values = [
        given if given is not None else preset
        for given, preset in zip((section.thickness, section.modulus, section.poisson), base, strict=True)
    ]
    return Liner(thickness=values[0], modulus=values[1], poisson=values[2], model=section.model)  # type: ignore[arg-type]
