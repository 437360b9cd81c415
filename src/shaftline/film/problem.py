"""The bearing problem as pure data: operating point, solver options and their choices.

Everything here is frozen, picklable and cheap to import (numpy, no scipy or
qdldl), so that a command line starts fast and a case schema can read the
defaults and the allowed choices (``typing.Literal``) straight from these
dataclasses: the domain is the single source of both. The solver state built
from a problem lives in :class:`shaftline.film.bearing.JournalBearing`.

Errors name the field relative to the object that checks it (``"speed"``,
``"grooves[0].angle"``), never a case-file path: see :class:`shaftline.errors.InputError`.
"""

from __future__ import annotations

import math
import os
from dataclasses import dataclass, field
from functools import lru_cache
from typing import TYPE_CHECKING, Any, Literal, get_args

from shaftline.errors import InputError, require_finite, require_positive
from shaftline.film.geometry import (
    BORE_ANCHORS,
    MIN_AXIAL_NODES,
    MIN_CIRCUMFERENTIAL_NODES,
    ROTATIONS,
    BearingGeometry,
    BentJournal,
    BoreAnchor,
    BoreSegment,
    FilmProfile,
    JournalPosition,
    Rotation,
    coarse_shape,
    require_nodes,
)
from shaftline.film.options import (
    ActiveSetOptions,
    ContinuationOptions,
    JfoOptions,
    LinerOptions,
    NewtonOptions,
    SettleOptions,
)
from shaftline.film.turbulence import TURBULENCE_MODELS, TURBULENCE_MODES, TurbulenceMode, TurbulenceModel

if TYPE_CHECKING:
    from shaftline.film.cavitation import CavitationModel

#: The cavitation models a case file names (:data:`shaftline.film.cavitation.CAVITATION_MODELS`
#: holds their classes; a class of one's own serves from Python).
Cavitation = Literal["reynolds", "jfo", "half_sommerfeld"]
#: Where the film starts when no supply groove fixes it.
FilmStart = Literal["periodic", "max_film"]
#: What shears in the cavitated zone.
CavitatedShear = Literal["film_fraction", "full_film"]

FILM_STARTS: tuple[FilmStart, ...] = get_args(FilmStart)
CAVITATED_SHEARS: tuple[CavitatedShear, ...] = get_args(CavitatedShear)

__all__ = [
    "BORE_ANCHORS",
    "CAVITATED_SHEARS",
    "FILM_STARTS",
    "ROTATIONS",
    "ActiveSetOptions",
    "BearingGeometry",
    "BearingProblem",
    "BentJournal",
    "BoreAnchor",
    "BoreSegment",
    "CavitatedShear",
    "Cavitation",
    "ContinuationOptions",
    "FilmProfile",
    "FilmStart",
    "JfoOptions",
    "JournalPosition",
    "LinerOptions",
    "NewtonOptions",
    "OperatingPoint",
    "Rotation",
    "SettleOptions",
    "SolverOptions",
    "SupplyGroove",
    "default_memory_limit",
    "estimated_memory",
]


def _one_of(choices: tuple[str, ...]) -> str:
    return "one of " + ", ".join(choices)


# -- memory of a film solution --------------------------------------------------------------
# Calibrated in docs/validation.md ("Memory of a film solution"): peak resident memory of an
# equilibrium with its stiffness and damping, grids 21 x 60 to 2561 x 120 and 641 x 480.

#: Bytes per node of a grid level for the dense arrays (film, stencil, pressures, masks, the
#: slot maps of the sparsity pattern, right-hand sides of the Jacobian, the result's fields).
#: Issue 11 raised it from 500: the 4 x 4 film coefficients with tilt take eight directions'
#: film, residual and pressure changes where the 2 x 2 took four (measured peaks rose from
#: 0.84-1.00 to 1.00-1.16 of the old estimate on 161 x 120 and 81 x 240). The second pass of
#: the solver (kept node-set factors, the red-black set prediction's colour structures and
#: sparse products, the concatenated slot source) raised it to 780, with the factor share below.
_DENSE_BYTES = 780.0
#: Bytes per nonzero of the qdldl LDL^T factor (int64 row index, float64 value, workspace):
#: measured 20.4-22.2.
_FACTOR_BYTES = 22.0
#: Share of the full periodic pattern's factor that the factor of the free sub-matrix holds
#: (issue 10: only the pressurised nodes are factorised, with an ordering of their own graph,
#: which the cavitated zone cuts open). The peak of an equilibrium with stiffness and damping
#: then lies at 0.84-1.00 of the estimate on 41 x 120 to 2561 x 120 (loaded and lightly
#: loaded); a film with no cavitated node at all would need up to about 1.2 times it. Since the
#: factor is that of a kept node set (the free nodes and three cells around them, up to 1.35
#: times the free nodes) the share is 0.85: measured peaks had reached 0.97-1.04 of the
#: estimate with 0.7 and 700 bytes a node (1.12 once, on 81 x 240 in a CI run).
_FREE_FACTOR_SHARE = 0.85
#: Default grid of SolverOptions (the refusal names the node count furthest above it).
_DEFAULT_AXIAL_NODES = 41
_DEFAULT_CIRCUMFERENTIAL_NODES = 120
#: The limit when the machine's memory cannot be read, bytes.
_FALLBACK_MEMORY_LIMIT = 4 * 1024**3
#: Share of the machine's memory a film solution may take by default.
_MEMORY_SHARE = 0.5


def _factor_fill(axial_nodes: int, circumferential_nodes: int) -> float:
    """Nonzeros of the LDL^T factor of the Reynolds operator on one grid, estimated.

    The factor of a 2-D five-point operator under a fill-reducing ordering (qdldl orders with
    AMD) holds about ``n (a log2 w - b)`` nonzeros, ``w`` the width of the grid across its
    longer direction (nested-dissection growth, ``n log n`` for a square grid, ``n log w`` for
    a long strip). Fitted to qdldl's factors on 72 grids from 5 x 16 to 1281 x 960 (the
    circumference counts half, as it is periodic): within -2 % / +25 % of the measured count
    above 2000 nodes, -2 % / +19 % above 100 000 (docs/validation.md).
    """
    width = min(0.68 * axial_nodes, 0.5 * circumferential_nodes)
    return axial_nodes * circumferential_nodes * max(8.5 * math.log2(width + 8.0) - 22.0, 1.0)


def estimated_memory(
    axial_nodes: int, circumferential_nodes: int, cavitation: Cavitation | type[CavitationModel] = "reynolds"
) -> int:
    """Peak memory of one film solution on a grid, bytes, estimated before anything is allocated.

    Counts what :class:`shaftline.film.bearing.JournalBearing` holds while it finds an
    equilibrium and its stiffness and damping: the dense arrays of every node and the sparse
    LDL^T factor, on the grid and on the coarser grids that predict the cavitated set, and for
    the mass-conserving model its sparse LU. The factor grows faster than the node count
    (about ``n log n``), so a grid twice as fine each way takes more than four times the memory.
    Calibrated against the measured peak (docs/validation.md): from 5 000 to 300 000 nodes the
    estimate is 3 % below to 27 % above it, on the high side by design. Since issue 10 only
    the free sub-matrix is factorised (:data:`_FREE_FACTOR_SHARE`), and since issue 11 the
    stiffness and damping include the tilt terms (:data:`_DENSE_BYTES`); since the solver's
    second pass the factor is that of a kept node set: the measured peaks lie at 0.84-0.90 of
    the estimate from 19 000 to 77 000 nodes (docs/validation.md).

    Parameters
    ----------
    axial_nodes, circumferential_nodes : int
        The grid (:class:`SolverOptions`).
    cavitation : Cavitation or CavitationModel class
        The cavitation model, which adds what it keeps (its ``dense_bytes`` a node and
        ``factor_bytes`` a nonzero of the fine LDL^T factor); ``"jfo"`` needs about 1.5 times
        the memory of the others.

    Returns
    -------
    int
        Bytes.

    Examples
    --------
    >>> round(estimated_memory(41, 120) / 2**20, 1)  # the default grid, MiB (measured peak 6.9)
    7.3
    >>> round(estimated_memory(2561, 120) / 2**20)  # measured peak 498 MiB
    504
    """
    total = 0.0
    shape: tuple[int, int] | None = (int(axial_nodes), int(circumferential_nodes))
    while shape is not None:
        total += _DENSE_BYTES * shape[0] * shape[1] + _FREE_FACTOR_SHARE * _FACTOR_BYTES * _factor_fill(*shape)
        shape = coarse_shape(shape)
    from shaftline.film.cavitation import cavitation_model

    model = cavitation_model(cavitation)
    if model.dense_bytes or model.factor_bytes:
        nodes = int(axial_nodes) * int(circumferential_nodes)
        total += model.dense_bytes * nodes + model.factor_bytes * _factor_fill(axial_nodes, circumferential_nodes)
    return int(total)


#: Largest ratio of a grid cell's sides (round the bore to along it, or the other way).
MAX_CELL_ASPECT = 100.0


@lru_cache(maxsize=1)
def default_memory_limit() -> int:
    """The memory a film solution may take unless ``SolverOptions.memory_limit`` says, bytes.

    Half the machine's physical memory (``os.sysconf``), or half the container's limit where a
    Linux control group sets a smaller one (``/sys/fs/cgroup/memory.max``), so that the rest of
    the run, the operating system and other programs keep room; 4 GiB where neither can be
    read (Windows). Read once per process.
    """
    total: float | None = None
    try:
        total = float(os.sysconf("SC_PAGE_SIZE") * os.sysconf("SC_PHYS_PAGES"))
    except (AttributeError, ValueError, OSError):
        pass
    try:
        with open("/sys/fs/cgroup/memory.max") as file:
            text = file.read().strip()
        if text.isdigit():
            total = min(total or math.inf, float(text))
    except OSError:
        pass
    if not total or total <= 0:
        return _FALLBACK_MEMORY_LIMIT
    return int(_MEMORY_SHARE * total)


def _bytes(value: float) -> str:
    """``value`` bytes in GiB or MiB, for a message."""
    return f"{value / 2**30:.1f} GiB" if value >= 2**30 else f"{value / 2**20:.0f} MiB"


@dataclass(frozen=True)
class SupplyGroove:
    """An axial supply groove at a fixed bearing angle.

    Attributes
    ----------
    angle : float
        Bearing angle of the groove centre, rad (from the top, in the direction of rotation).
    pressure : float
        Supply pressure above ambient, Pa.
    length_fraction : float
        Axial length of the groove as a share of the bearing length, centred, (0, 1].
    """

    angle: float
    pressure: float = 0.0
    length_fraction: float = 1.0


@dataclass(frozen=True)
class OperatingPoint:
    """Running condition of a bearing.

    Attributes
    ----------
    speed : float
        Shaft angular speed, rad/s (> 0; the sense of rotation is a geometry input).
    viscosity : float
        Effective dynamic viscosity of the lubricant, Pa*s.
    density : float
        Lubricant density, kg/m^3 (reported flows by mass; with turbulence
        (:attr:`SolverOptions.turbulence`) it sets the local Reynolds number, otherwise no effect
        on pressures).
    aft_pressure, fore_pressure : float
        Pressures at the aft and forward bearing edges above ambient, Pa.
    cavitation_pressure : float
        Pressure at which the film ruptures, above ambient, Pa (<= edge and groove pressures).
    grooves : tuple of SupplyGroove
        Axial supply grooves.

    Raises
    ------
    InputError
        Naming the attribute, e.g. ``"viscosity"`` or ``"grooves[0].angle"``.
    """

    speed: float
    viscosity: float
    density: float = 880.0
    aft_pressure: float = 0.0
    fore_pressure: float = 0.0
    cavitation_pressure: float = 0.0
    grooves: tuple[SupplyGroove, ...] = ()

    def __post_init__(self) -> None:
        require_positive("speed", self.speed, "rad/s")
        require_positive("viscosity", self.viscosity, "Pa*s")
        require_positive("density", self.density, "kg/m^3")
        for name in ("aft_pressure", "fore_pressure", "cavitation_pressure"):
            require_finite(name, getattr(self, name), "Pa")
        for k, groove in enumerate(self.grooves):
            require_finite(f"grooves[{k}].angle", groove.angle, "rad")
            require_finite(f"grooves[{k}].pressure", groove.pressure, "Pa")
            fraction = require_finite(f"grooves[{k}].length_fraction", groove.length_fraction)
            if not 0.0 < fraction <= 1.0:
                raise InputError(f"grooves[{k}].length_fraction", fraction, "", "in (0, 1]")
        lowest = min(self.aft_pressure, self.fore_pressure, *(g.pressure for g in self.grooves))
        if self.cavitation_pressure > lowest:
            raise InputError(
                "cavitation_pressure",
                self.cavitation_pressure,
                "Pa",
                f"<= the lowest supply pressure {lowest}",
            )

    @property
    def feed_pressure(self) -> float:
        """Highest pressure feeding the film, Pa: the largest edge or groove pressure."""
        return max(self.aft_pressure, self.fore_pressure, *(g.pressure for g in self.grooves))


@dataclass(frozen=True)
class SolverOptions:
    """Numerical options of the film solution.

    Attributes
    ----------
    axial_nodes, circumferential_nodes : int
        Grid nodes along the bearing (edges included, >= 5) and around the bore (>= 16).
    cavitation : Cavitation or CavitationModel class
        ``"reynolds"`` (Swift-Stieber, default), ``"jfo"`` (mass-conserving) or
        ``"half_sommerfeld"`` (comparison only): a name of
        :data:`shaftline.film.cavitation.CAVITATION_MODELS`, or a class that meets
        :class:`shaftline.film.cavitation.CavitationModel`.
    film_start : FilmStart
        ``"periodic"`` (default: the film is continuous all round) or ``"max_film"``
        (the classical design-chart assumption of Raimondi & Boyd: ambient pressure
        along the line of maximum film thickness, where the oil enters).
    cavitated_shear : CavitatedShear
        Shear in the cavitated zone: ``"film_fraction"`` (default: only the liquid
        streamers shear, share ``h_rupture / h`` or the JFO film fraction) or
        ``"full_film"`` (the whole clearance shears, the convention behind the
        Raimondi & Boyd friction variable).
    min_film_floor : float
        Smallest film, as a share of the radial clearance, that the equilibrium search
        may approach; below it the load is reported as not carried (contact). With rough
        surfaces (``geometry.surface``) the film may instead pass the mean plane down to
        ``-3 sigma``, the asperities carrying the load (docs/theory.md Sect. 17, "Boundary
        lubrication"); this share then only sets how the mean plane is first approached.
    tolerance : float
        Relative force residual at which the equilibrium is accepted.
    max_iterations : int
        Newton iterations allowed for the equilibrium (>= 1).
    turbulence : TurbulenceMode
        ``"off"`` (default: laminar), ``"on"`` (the turbulence coefficients of ``turbulence_model``
        at every node; they tend to the laminar values as the local Reynolds number falls) or
        ``"auto"`` (on when the largest local Reynolds number ``2 rho omega R c / mu`` exceeds the
        Taylor-vortex onset ``41.3 sqrt(R/c)``; docs/theory.md Sect. 17, "Turbulent films").
    turbulence_model : TurbulenceModel
        ``"ng_pan"`` (Ng & Pan 1965, default) or ``"constantinescu"`` (Constantinescu 1962).
    memory_limit : float or None
        Largest estimated memory of a film solution on this grid, bytes
        (:func:`estimated_memory`); a finer grid is refused when the options are made, before
        anything is allocated. ``None`` (default): :func:`default_memory_limit`, half the
        machine's memory.
    active_set, jfo, continuation, newton, settling, liner : option dataclasses
        How the solver's steps go: :class:`~shaftline.film.options.ActiveSetOptions` (the
        Reynolds condition's active set and set prediction), :class:`~shaftline.film.options.JfoOptions`
        (the mass-conserving model), :class:`~shaftline.film.options.ContinuationOptions` (the
        start from the coarse grid's equilibrium), :class:`~shaftline.film.options.NewtonOptions`
        (the equilibrium's iteration), :class:`~shaftline.film.options.SettleOptions` (a stalled
        rough bore settled) and :class:`~shaftline.film.options.LinerOptions` (the film-liner
        iteration), each with the defaults they were tuned to.

    The time of a solution grows faster than the node count, as the memory does: on a 2-core
    machine an equilibrium with stiffness and damping took 0.05 s on the default 41 x 120
    grid, 1.6 s on 321 x 240, 9 s on 1281 x 120 and 33 s on 2561 x 120 (1.3 to 2.4 times as
    long with ``cavitation = "jfo"``; measured after issue 10).

    Raises
    ------
    InputError
        Naming the attribute, e.g. ``"cavitation"`` or ``"axial_nodes"``; a grid whose
        estimated memory exceeds the limit names the node count to reduce (the axial or the
        circumferential one, whichever is further above its default) and gives the estimate
        and the limit.
    """

    axial_nodes: int = _DEFAULT_AXIAL_NODES
    circumferential_nodes: int = _DEFAULT_CIRCUMFERENTIAL_NODES
    cavitation: Cavitation = "reynolds"
    film_start: FilmStart = "periodic"
    cavitated_shear: CavitatedShear = "film_fraction"
    min_film_floor: float = 1e-3
    tolerance: float = 1e-8
    max_iterations: int = 60
    memory_limit: float | None = None
    turbulence: TurbulenceMode = "off"
    turbulence_model: TurbulenceModel = "ng_pan"
    active_set: ActiveSetOptions = ActiveSetOptions()
    jfo: JfoOptions = JfoOptions()
    continuation: ContinuationOptions = ContinuationOptions()
    newton: NewtonOptions = NewtonOptions()
    settling: SettleOptions = SettleOptions()
    liner: LinerOptions = LinerOptions()

    def __post_init__(self) -> None:
        require_nodes("axial_nodes", self.axial_nodes, MIN_AXIAL_NODES)
        require_nodes("circumferential_nodes", self.circumferential_nodes, MIN_CIRCUMFERENTIAL_NODES)
        # A model named in a case file is known without importing the models (the start-up of an
        # input error); another name or a class is checked against the registry.
        if not (isinstance(self.cavitation, str) and self.cavitation in get_args(Cavitation)):
            from shaftline.film.cavitation import cavitation_model

            try:
                cavitation_model(self.cavitation)
            except ValueError as exc:
                raise InputError("cavitation", self.cavitation, "", str(exc)) from None
        groups = {
            "active_set": ActiveSetOptions,
            "jfo": JfoOptions,
            "continuation": ContinuationOptions,
            "newton": NewtonOptions,
            "settling": SettleOptions,
            "liner": LinerOptions,
        }
        for name, kind in groups.items():
            if not isinstance(getattr(self, name), kind):
                raise InputError(name, getattr(self, name), "", f"a {kind.__name__}")
        if self.film_start not in FILM_STARTS:
            raise InputError("film_start", self.film_start, "", _one_of(FILM_STARTS))
        if self.cavitated_shear not in CAVITATED_SHEARS:
            raise InputError("cavitated_shear", self.cavitated_shear, "", _one_of(CAVITATED_SHEARS))
        if self.turbulence not in TURBULENCE_MODES:
            raise InputError("turbulence", self.turbulence, "", _one_of(TURBULENCE_MODES))
        if self.turbulence_model not in TURBULENCE_MODELS:
            raise InputError("turbulence_model", self.turbulence_model, "", _one_of(TURBULENCE_MODELS))
        floor = require_finite("min_film_floor", self.min_film_floor)
        if not 0.0 < floor < 0.5:
            raise InputError("min_film_floor", floor, "", "in (0, 0.5) of the clearance")
        tolerance = require_finite("tolerance", self.tolerance)
        if not 0.0 < tolerance < 1e-2:
            raise InputError("tolerance", tolerance, "", "in (0, 0.01)")
        require_nodes("max_iterations", self.max_iterations, 1, "an integer >= 1")
        if self.memory_limit is not None:
            require_positive("memory_limit", self.memory_limit, "B")
        self._check_memory()

    @property
    def estimated_memory(self) -> int:
        """Estimated peak memory of a film solution with these options, bytes
        (:func:`estimated_memory` of the grid and the cavitation model)."""
        return estimated_memory(self.axial_nodes, self.circumferential_nodes, self.cavitation)

    @property
    def cavitation_model(self) -> type[CavitationModel]:
        """The class of :attr:`cavitation` (:func:`shaftline.film.cavitation.cavitation_model`)."""
        from shaftline.film.cavitation import cavitation_model

        return cavitation_model(self.cavitation)

    def _check_memory(self) -> None:
        """Refuse a grid whose film solution would not fit in the memory limit."""
        needed = self.estimated_memory
        if self.memory_limit is None:
            limit, source = default_memory_limit(), "half the machine's memory; memory_limit sets another"
        else:
            limit, source = int(self.memory_limit), "memory_limit"
        if needed <= limit:
            return
        # Name the count that is further above its default: the one to reduce first.
        axial_share = self.axial_nodes / _DEFAULT_AXIAL_NODES
        round_share = self.circumferential_nodes / _DEFAULT_CIRCUMFERENTIAL_NODES
        name = "axial_nodes" if axial_share >= round_share else "circumferential_nodes"
        raise InputError(
            name,
            getattr(self, name),
            "",
            f"a grid that fits in memory: {self.axial_nodes} x {self.circumferential_nodes} nodes "
            f"({self.cavitation_model.name}) need about {_bytes(needed)} for a film solution, above the limit of "
            f"{_bytes(limit)} ({source})",
        )


@dataclass(frozen=True)
class BearingProblem:
    """One film problem: what the bearing is, how it runs and how to solve it.

    Pure data, with no solver state: it pickles, deep-copies and compares cheaply,
    so it is what a process pool or a Dask worker receives.
    :class:`shaftline.film.bearing.JournalBearing` builds (and rebuilds after
    unpickling) the solver state from it.

    Attributes
    ----------
    geometry : BearingGeometry
        Bore, clearance, slope boring, bent journal, film profile, sense of rotation.
    operating : OperatingPoint
        Speed, lubricant viscosity and density, edge, groove and cavitation pressures.
    options : SolverOptions
        Grid and cavitation model.

    Raises
    ------
    InputError
        ``"operating.cavitation_pressure"`` for the mass-conserving (``"jfo"``) model
        when no edge or groove pressure lies above the cavitation pressure.

    Examples
    --------
    >>> from shaftline.film.problem import BearingGeometry, BearingProblem, OperatingPoint
    >>> problem = BearingProblem(
    ...     BearingGeometry(length=0.1, diameter=0.1, radial_clearance=1e-4),
    ...     OperatingPoint(speed=100.0, viscosity=0.02),
    ... )
    >>> problem.options.cavitation
    'reynolds'
    >>> round(problem.pressure_scale / 1e6, 3)  # 6 eta omega (R/c)^2, MPa
    3.0
    """

    geometry: BearingGeometry
    operating: OperatingPoint
    options: SolverOptions = field(default_factory=SolverOptions)

    def __post_init__(self) -> None:
        from shaftline.film.cavitation import CAVITATION_MODELS

        self._check_cell_shape()
        model = self.options.cavitation_model
        if self.geometry.surface is not None and not model.rough_surfaces:
            able = " or ".join(name for name, kind in CAVITATION_MODELS.items() if kind.rough_surfaces)
            raise InputError(
                "options.cavitation",
                self.options.cavitation,
                "",
                f"{able} with rough surfaces ([bearing.surface] in a case, BearingGeometry.surface in Python)"
                + (f": {model.refusal}" if model.refusal else ""),
            )
        if self.geometry.liner is not None and not model.liners:
            # The film-liner Newton matrix is built on the Reynolds condition's frozen set
            # (film/elastic.py); the other models' linearisations are not coupled to a liner.
            able = " or ".join(name for name, kind in CAVITATION_MODELS.items() if kind.liners)
            raise InputError(
                "options.cavitation", self.options.cavitation, "", f"{able} with an elastic liner (geometry.liner)"
            )
        if model.needs_feed_pressure and self.operating.feed_pressure <= self.operating.cavitation_pressure:
            raise InputError(
                "operating.cavitation_pressure",
                self.operating.cavitation_pressure,
                "Pa",
                f"below the highest edge or groove pressure ({self.operating.feed_pressure} Pa) for the "
                "mass-conserving (jfo) model: without a pressure difference to feed it the film runs dry",
            )

    def _check_cell_shape(self) -> None:
        """Refuse grid cells more than :data:`MAX_CELL_ASPECT` times longer one way than the
        other: the cavitation active set of the nested coarse grids stops settling (seen at
        127 on an L = D bearing of 11 x 4000 nodes and at 2700 on the seed 004 bearing with
        100 000 x 60), and such a grid resolves nothing a squarer one of the same size does not."""
        g, o = self.geometry, self.options
        along = g.length / (o.axial_nodes - 1)
        around = g.radius * 2.0 * math.pi / o.circumferential_nodes
        if around > MAX_CELL_ASPECT * along:
            most = int(MAX_CELL_ASPECT * g.length / around) + 1
            raise InputError(
                "options.axial_nodes",
                o.axial_nodes,
                "",
                f"at most {most} with {o.circumferential_nodes} circumferential nodes (cells "
                f"{around / along:.0f} times longer round the bore than along it; limit {MAX_CELL_ASPECT:g})",
            )
        if along > MAX_CELL_ASPECT * around:
            most = int(MAX_CELL_ASPECT * 2.0 * math.pi * g.radius / along)
            raise InputError(
                "options.circumferential_nodes",
                o.circumferential_nodes,
                "",
                f"at most {most} with {o.axial_nodes} axial nodes (cells {along / around:.0f} times longer along "
                f"the bearing than round it; limit {MAX_CELL_ASPECT:g})",
            )

    @property
    def pressure_scale(self) -> float:
        """Pressure scale of the dimensionless Reynolds equation, ``6 eta omega (R/c)^2``, Pa."""
        ratio = self.geometry.radius / self.geometry.radial_clearance
        return 6.0 * self.operating.viscosity * self.operating.speed * ratio**2

    @property
    def flow_scale(self) -> float:
        """Flow scale ``omega R^2 c / 2``, m^3/s."""
        g = self.geometry
        return 0.5 * self.operating.speed * g.radius**2 * g.radial_clearance


def __getattr__(name: str) -> Any:
    # The registry is the cavitation package's; importing it here would import every model
    # with the problem (which the case schema imports), so it is looked up when asked for.
    if name == "CAVITATION_MODELS":
        from shaftline.film.cavitation import CAVITATION_MODELS

        return CAVITATION_MODELS
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
