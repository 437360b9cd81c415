"""A bearing study: a stern-tube bearing under its load, with variants (other bores or
tilts) solved beside it, each at equilibrium with its stiffness and damping.

This is what ``[bearing]`` in a case file becomes; notebooks can build one directly::

    study = BearingStudy((BearingCase("base", geometry, operating, SolverOptions(), load_y=-3e5),))
    result = solve_study(study)
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
from dataclasses import dataclass, field
from typing import TYPE_CHECKING

from shaftline.film.geometry import BearingGeometry
from shaftline.film.problem import OperatingPoint, SolverOptions

if TYPE_CHECKING:
    import numpy as np

    from shaftline.film.bearing import Equilibrium, JournalBearing
    from shaftline.film.dynamics import DynamicCoefficients
    from shaftline.film.geometry import JournalPosition
    from shaftline.film.stribeck import StribeckCurve
    from shaftline.film.thermal import ThermalOptions, ThermalResult
    from shaftline.lubricants import Lubricant


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


@dataclass(frozen=True, eq=False)
class BearingStudyResult:
    """The results of a study, in the order of its cases, and the base case's Stribeck curve
    when asked for (:func:`shaftline.film.stribeck.stribeck_curve`)."""

    cases: tuple[BearingResult, ...]
    stribeck: StribeckCurve | None = None


def solve_case(
    case: BearingCase,
    progress: Callable[[str], None] | None = None,
    bearing: JournalBearing | None = None,
    initial: JournalPosition | None = None,
    coefficients: bool = True,
    initial_cavitated: np.ndarray | None = None,
) -> BearingResult:
    """Equilibrium under the case load, then stiffness and damping there (not at contact).

    ``progress``, when given, is told each Newton iteration of the equilibrium
    (``"base: Newton iteration 3, force residual 2.1e-04 of the load"``) and the start of the
    stiffness and damping: on a fine grid each takes seconds to minutes.

    ``bearing`` is a :class:`~shaftline.film.JournalBearing` of the case's problem to reuse
    (its factorisation pattern and coarse grids; :func:`shaftline.film.sweep` passes one per
    group of cases), ``initial`` the start of the equilibrium's Newton iteration and
    ``initial_cavitated`` the cavitated set of its first film solution (a warm start from a
    solved neighbour). Without them the case is solved from scratch. ``coefficients``
    False leaves out the stiffness and damping.
    """
    from shaftline.errors import located
    from shaftline.film.bearing import JournalBearing
    from shaftline.film.dynamics import dynamic_coefficients

    def newton(iteration: int, residual: float) -> None:
        if progress is not None:
            progress(f"{case.name}: Newton iteration {iteration}, force residual {residual:.1e} of the load")

    balance = None
    if case.thermal is not None:
        case, balance = _at_effective_temperature(case, progress)
        # The viscosity changed: neither the given bearing nor its warm start applies.
        bearing, initial, initial_cavitated = None, None, None
    if bearing is None:
        bearing = JournalBearing(case.geometry, case.operating, case.options)
    # A tilt that does not fit in the clearance is found only here; name it as the case file does.
    with located("", case.error_fields):
        equilibrium = bearing.equilibrium(
            case.load_y,
            case.load_z,
            tilt_y=case.tilt_y,
            tilt_z=case.tilt_z,
            initial=initial,
            progress=newton,
            initial_cavitated=initial_cavitated,
        )
    dynamics = None
    if coefficients and equilibrium.converged and not equilibrium.contact:
        if progress is not None:
            progress(f"{case.name}: stiffness and damping")
        dynamics = dynamic_coefficients(bearing, equilibrium.state)
    return BearingResult(case, equilibrium, dynamics, balance)


def _at_effective_temperature(
    case: BearingCase, progress: Callable[[str], None] | None
) -> tuple[BearingCase, ThermalResult]:
    """The heat balance of ``case`` (docs/theory.md Sect. 8.1) and the case at its effective
    temperature; a balance that does not close below the top of the viscosity model leaves
    the case at that top temperature (``converged`` False)."""
    from dataclasses import replace

    from shaftline.errors import located
    from shaftline.film.problem import BearingProblem
    from shaftline.film.thermal import bearing_film, thermal_balance

    assert case.thermal is not None
    if case.lubricant is None:
        raise ValueError(f"{case.name}: a heat balance needs the case's lubricant")
    if progress is not None:
        progress(f"{case.name}: heat balance")
    problem = BearingProblem(case.geometry, case.operating, case.options)
    with located("", case.error_fields):
        balance = thermal_balance(
            bearing_film(problem, case.load_y, case.load_z, case.tilt_y, case.tilt_z), case.lubricant, case.thermal
        )
    temperature = balance.effective_temperature
    operating = replace(case.operating, viscosity=balance.viscosity, density=float(case.lubricant.density(temperature)))
    return replace(case, operating=operating, temperature=temperature), balance


def solve_study(
    study: BearingStudy,
    progress: Callable[[str], None] | None = None,
    *,
    backend: str | None = None,
    workers: int | None = None,
    scheduler: str | None = None,
    stribeck: bool = False,
) -> BearingStudyResult:
    """Solve the base case and every variant with :func:`shaftline.film.sweep`: variants with
    the same film problem share one bearing and warm-start from each other, and the groups
    run on a process pool (``backend``, ``workers``, ``scheduler`` as in
    :func:`shaftline.parallel.map`).

    ``progress`` is told each case's name, then its Newton iterations (:func:`solve_case`),
    when the cases are solved in this process (serially, or one group only); from a pool it
    is told how many cases are done each time a chunk of them finishes (a chunk is the cases
    of one film problem, up to ``chunk_size`` of :func:`shaftline.film.sweep`).
    """
    from shaftline.film.sweeps import sweep

    results = sweep(study.cases, backend=backend, workers=workers, scheduler=scheduler, progress=progress)
    curve = None
    if stribeck:
        from shaftline.film.stribeck import stribeck_curve

        if progress is not None:
            progress(f"{study.cases[0].name}: Stribeck curve, {len(study.stribeck_speeds)} speeds")

        def chunks_done(done: int, total: int) -> None:
            if progress is not None:
                progress(f"{study.cases[0].name}: Stribeck curve, {done} of {total} groups of speeds done")

        curve = stribeck_curve(
            study.cases[0],
            study.stribeck_speeds,
            backend=backend,
            workers=workers,
            scheduler=scheduler,
            progress=chunks_done,
        )
    return BearingStudyResult(tuple(results), curve)
