"""A bearing study as data: a stern-tube bearing under its load, with variants (other bores or
tilts) solved beside it, each at equilibrium with its stiffness and damping, and the results
that export themselves (``to_dict`` for results.json, ``to_pandas`` for a table).

This is what ``[bearing]`` in a case file becomes; notebooks can build one directly and solve
it with :func:`shaftline.film.solve.solve_study`::

    study = BearingStudy((BearingCase("base", geometry, operating, SolverOptions(), load_y=-3e5),))
    result = solve_study(study)
    result.to_pandas()
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any

from shaftline.film.geometry import BearingGeometry
from shaftline.film.problem import OperatingPoint, SolverOptions

if TYPE_CHECKING:
    import pandas as pd

    from shaftline.film.dynamics import DynamicCoefficients
    from shaftline.film.results import Equilibrium
    from shaftline.film.stribeck import StribeckCurve
    from shaftline.film.thermal import ThermalOptions, ThermalResult
    from shaftline.lubricants import Lubricant

#: Units of a case's ``thermal`` entry (with [bearing.thermal]).
THERMAL_UNITS = {
    "thermal.inlet_temperature": "degC",
    "thermal.effective_temperature": "degC",
    "thermal.outlet_temperature": "degC",
    "thermal.viscosity": "Pa s",
    "thermal.heat_to_lubricant": "-",
}


@dataclass(frozen=True, eq=False)
class BearingCase:
    """One bearing problem in SI units: the bearing, its running condition and its load.

    Attributes
    ----------
    name : str
        Label of the case or variant.
    geometry, operating, options :
        Inputs of :class:`shaftline.film.JournalBearing`.
    load_y, load_z : float
        Applied load on the journal, N (``load_y < 0`` downwards).
    tilt_y, tilt_z : float
        Journal tilt relative to the nominal bore axis, rad.
    lubricant : Lubricant or None
        The lubricant (for the report).
    temperature : float or None
        Effective film temperature, degC, where given.
    surface_roughness : float
        Composite roughness of journal and bore, sqrt(Rq_journal^2 + Rq_bore^2), m. The
        smooth-film model holds where the film is at least three times it (Hamrock & Dowson,
        "Ball Bearing Lubrication", 1981: partial lubrication below film parameter 3). The
        default, 2.2 µm, is a ground journal (Rq 1 µm, Ra about 0.8 µm) in a bored white-metal
        liner (Rq 2 µm, Ra about 1.6 µm), engineering judgement of usual stern-tube finishes.
    thermal : ThermalOptions or None
        Solve the film at the effective temperature of its heat balance
        (:func:`shaftline.film.thermal.thermal_balance`) instead of ``operating.viscosity``;
        needs ``lubricant`` with a temperature-dependent viscosity.
    error_fields : mapping
        Where the case file gives the equilibrium's inputs (``{"tilt_y":
        "variants[1].tilt_vertical"}``), for an error found only while solving; empty
        for a case built in code (errors then name ``tilt_y`` etc.).
    """

    name: str
    geometry: BearingGeometry
    operating: OperatingPoint
    options: SolverOptions
    load_y: float
    load_z: float = 0.0
    tilt_y: float = 0.0
    tilt_z: float = 0.0
    lubricant: Lubricant | None = None
    temperature: float | None = None
    surface_roughness: float = 2.2e-6
    error_fields: Mapping[str, str] = field(default_factory=dict)
    thermal: ThermalOptions | None = None


@dataclass(frozen=True, eq=False)
class BearingStudy:
    """The base case (first) and its variants; ``stribeck_speeds`` (rad/s) are the speeds of
    the base case's Stribeck curve (``shaftline bearing stribeck``)."""

    cases: tuple[BearingCase, ...]
    stribeck_speeds: tuple[float, ...] = ()


@dataclass(frozen=True, eq=False)
class BearingResult:
    """Equilibrium of one case, with stiffness and damping where the film carries the load;
    with ``case.thermal`` the heat balance, and ``case`` is then the case at its effective
    temperature (viscosity, density and ``temperature``)."""

    case: BearingCase
    equilibrium: Equilibrium
    coefficients: DynamicCoefficients | None
    thermal: ThermalResult | None = None

    def to_dict(self) -> dict[str, Any]:
        """The case's results for results.json: its name, the equilibrium's scalars, the stiffness
        and damping (null where the film does not carry the load), the heat balance, and the
        liner deformation and local Reynolds number maps where they apply (rows along the bearing
        from the aft edge, columns around the bore from the grid's first angle)."""
        import numpy as np

        from shaftline.film.dynamics import DynamicCoefficients

        coefficients = DynamicCoefficients.absent() if self.coefficients is None else self.coefficients.to_dict()
        out: dict[str, Any] = {"name": self.case.name, **self.equilibrium.to_dict(), **coefficients}
        if self.thermal is not None:
            out["thermal"] = self.thermal_dict()
        state = self.equilibrium.state
        if state.liner is not None:
            out["liner_deformation_map"] = np.round(state.liner.deformation, 12).tolist()  # m
        if state.turbulence is not None:
            out["reynolds_number_map"] = np.round(state.turbulence.reynolds_number, 3).tolist()
        return out

    def thermal_dict(self) -> dict[str, Any]:
        """The heat balance (``thermal``) for results.json, in :data:`THERMAL_UNITS`."""
        balance = self.thermal
        assert balance is not None and self.case.thermal is not None
        return {
            "inlet_temperature": balance.inlet_temperature,
            "effective_temperature": balance.effective_temperature,
            "outlet_temperature": balance.outlet_temperature,
            "viscosity": balance.viscosity,
            "heat_to_lubricant": self.case.thermal.heat_to_lubricant,
            "converged": balance.converged,
            "film_solutions": balance.evaluations,
        }


@dataclass(frozen=True, eq=False)
class BearingStudyResult:
    """The results of a study, in the order of its cases, and the base case's Stribeck curve
    when asked for (:func:`shaftline.film.stribeck.stribeck_curve`)."""

    cases: tuple[BearingResult, ...]
    stribeck: StribeckCurve | None = None

    def units(self) -> dict[str, str]:
        """The unit of every key of a case's :meth:`BearingResult.to_dict` in this study."""
        from shaftline.export import units
        from shaftline.film.dynamics import DynamicCoefficients
        from shaftline.film.results import BearingState, Equilibrium

        runs = self.cases
        rough = any(run.case.geometry.surface is not None for run in runs)
        lined = any(run.case.geometry.liner is not None for run in runs)
        turbulence = any(run.case.options.turbulence != "off" for run in runs)
        out = {**BearingState.units(rough, lined, turbulence), **Equilibrium.units(), **units(DynamicCoefficients)}
        if lined:
            out["liner_deformation_map"] = "m"
        if turbulence:
            out["reynolds_number_map"] = "-"
        if any(run.thermal is not None for run in runs):
            out.update(THERMAL_UNITS)
        return out

    def to_dict(self) -> dict[str, Any]:
        """The study for results.json: the units, each case's results, the Stribeck curve."""
        out: dict[str, Any] = {"units": self.units(), "cases": [run.to_dict() for run in self.cases]}
        if self.stribeck is not None:
            out["stribeck"] = self.stribeck.to_dict()
        return out

    def to_pandas(self) -> pd.DataFrame:
        """One row per case (indexed by its name) with every scalar of :meth:`BearingResult.to_dict`
        (the units are :meth:`units`)."""
        import pandas as pd

        rows = []
        for run in self.cases:
            entry = run.to_dict()
            rows.append({key: value for key, value in entry.items() if not isinstance(value, list | dict)})
        return pd.DataFrame(rows).set_index("name")
