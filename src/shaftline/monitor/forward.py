"""Forward model of seed 001's rig: synthetic probe signals from the bearing solver and the shaft model.

The validation of the identification (issue 13): the journal of the rig's stern bearing
is placed by the project's bearing solver (:meth:`JournalBearing.equilibrium` under the
bearing load, with the misalignment as a journal tilt and the shaft model's bending
inside the bearing as a bent journal), a 1X forward whirl growing with the speed squared
(unbalance) is added, each probe's gap is computed from the exact geometry of two circles
(M1), then runout, noise and quantisation at the probe's resolution, and the probe's
calibration turns gaps into volts. The true centre line is kept, so that the identified
film can be compared with the film that made the signals.

The rig (seed 001 Sect. 2, Tables 1-3): journal 323 mm, bearing 1200 mm (L/D 3.7),
radial clearance 0.55 mm after break-in, water at 25 degC, 7.5 t overhung counterweight,
75 kN on the stern bearing, 15-215 rpm. The seed gives no lengths of the rest of the
shaft line; :func:`rig_shaft_line` assumes them (stated there). With the seed's surfaces
and liner (``RigCase(surface=..., liner=...)``: Ra 0.8 / 1.6 um, a 20 mm polymer liner of
E = 2320 MPa) the solver carries the load at every speed of the seed, 15-215 rpm, in
boundary lubrication at the loaded end at low speed; rigid and smooth (the default) it
loses the film below about 135 rpm.

What the probes see: they sit in the housing and read the distance to the journal, so a
liner pressed in by the film and the asperities does not change their gaps; the film
they identify is the gap between the journal and the undeformed bore, which goes
negative where the journal has pressed the liner in (seed 001 Sect. 5.1 reports such
negative films at D1's bottom). The bearing's own film (liner deformed) is reported
beside it (:class:`RigEquilibrium`).
"""

from __future__ import annotations

import functools
import math
from dataclasses import dataclass, field, replace
from typing import TYPE_CHECKING

import numpy as np

from shaftline import parallel
from shaftline.errors import InputError, SolverFailure, require_finite, require_positive
from shaftline.monitor.identification import film_between_circles
from shaftline.monitor.probes import ProbeLayout, seed001_layout

if TYPE_CHECKING:
    from collections.abc import Callable, Sequence

    from shaftline.film import BearingGeometry, JournalBearing
    from shaftline.film.liner import Liner
    from shaftline.film.roughness import SurfaceRoughness
    from shaftline.shaft import ShaftLine

#: Counterweight (overhung mass) of the rig, kg (seed 001 Sect. 2.1).
RIG_OVERHUNG_MASS = 7500.0
#: Load on the stern bearing, N (seed 001 Table 3).
RIG_LOAD = 75e3
#: Water supply temperature, degC (seed 001 Table 3).
RIG_TEMPERATURE = 25.0
#: Stern-bearing support points and their stiffness in the shaft model, N/m: the seed's FE
#: model simulates bearings by springs of 1e9 N/m (Sect. 5.3).
RIG_SUPPORT_POINTS = 12
RIG_SUPPORT_STIFFNESS = 1e9


def rig_shaft_line(overhung_mass: float = RIG_OVERHUNG_MASS) -> ShaftLine:
    """The rig's shaft line as an alignment model (:class:`shaftline.shaft.ShaftLine`).

    x = 0 at the overhung end. A 6 m shaft of 323 mm (the seed gives the journal diameter
    only; the rest of the line is assumed): the counterweight at x = 0.2 m, the stern
    bearing (1.2 m, aft edge at 0.5 m) as 12 one-sided springs of 1e9 N/m (the seed's FE
    model uses such springs), a front bearing at 3.6 m and the thrust bearing at 5.6 m.
    """
    from shaftline.shaft import Bearing, PointMass, ShaftLine, ShaftSegment

    require_positive("overhung_mass", overhung_mass, "kg")
    return ShaftLine(
        segments=(ShaftSegment(length=6.0, outer_diameter=0.323, name="stern and intermediate shafts"),),
        bearings=(
            Bearing(
                "stern",
                1.1,
                1.2,
                support="multi_point",
                points=RIG_SUPPORT_POINTS,
                stiffness=RIG_SUPPORT_STIFFNESS,
                material="composite",
            ),
            Bearing("front", 3.6, 0.4, material="composite"),
            Bearing("thrust", 5.6, 0.3),
        ),
        masses=(PointMass(0.2, overhung_mass, "counterweight"),),
        element_length=0.05,
    )


@functools.lru_cache(maxsize=8)
def rig_bending_shape(overhung_mass: float = RIG_OVERHUNG_MASS, stations: int = 49) -> tuple[np.ndarray, np.ndarray]:
    """Stations (m from the loaded end) and the shaft model's bending in the stern bearing, m."""
    from shaftline.monitor.bending import model_shape

    z = np.linspace(0.0, 1.2, stations)
    shape = model_shape(rig_shaft_line(overhung_mass), "stern", z)
    z.setflags(write=False)
    shape.setflags(write=False)
    return z, shape


@dataclass(frozen=True)
class RigCase:
    """Inputs of the forward model (SI units; speeds in rad/s).

    Attributes
    ----------
    layout : ProbeLayout
        Probes and bearing (default: seed 001's, :func:`seed001_layout`).
    load : float
        Load on the bearing, N (downwards).
    viscosity : float
        Water viscosity at the test temperature, Pa*s (default: 25 degC).
    misalignment : float
        Journal tilt relative to the bore in the vertical plane, rad, positive when the
        journal rises going away from the loaded end.
    bend_scale : float
        Share of the shaft model's bending inside the bearing that the journal carries.
    overhung_mass : float
        Counterweight of the rig's shaft model (:func:`rig_shaft_line`), kg.
    shape : (stations, shape) or None
        Bending shape of the journal in the bearing (m from the loaded end, m) from another
        shaft model (:func:`shaftline.monitor.bending.model_shape`); None: the rig's.
    whirl : float
        1X forward whirl, zero-to-peak, at ``whirl_speed``, m (grows with the speed squared).
    whirl_speed : float
        Speed of that whirl amplitude, rad/s.
    runout : tuple of float
        1X and 2X runout amplitudes seen by every probe (random phases), m.
    noise : float
        Standard deviation of white noise on each gap, m.
    quantise : bool
        Round each gap to its probe's resolution.
    sleeve_wear : float
        Uniform wear of the journal sleeve, m: the clearance is ``c + sleeve_wear`` and
        every probe sees it (the correction factor k should find it).
    sample_rate : float
        Samples per second, Hz.
    revolutions : float
        Length of a recording in shaft revolutions (unless ``duration``).
    duration : float or None
        Length of a recording, s, the same at every speed as a data acquisition records
        (None: ``revolutions``).
    seed : int
        Seed of the random phases and noise.
    axial_nodes, circumferential_nodes : int
        Grid of the bearing solver.
    surface : SurfaceRoughness or None
        Rough journal and bore (asperity contact, flow factors; seed 001's:
        ``SurfaceRoughness.preset("steel_polymer")``); None: smooth.
    liner : Liner or None
        Elastic liner of the bore (seed 001's: ``Liner.preset("polymer_composite")``);
        None: rigid.
    """

    layout: ProbeLayout = field(default_factory=seed001_layout)
    load: float = RIG_LOAD
    viscosity: float = 8.904e-4
    misalignment: float = 2e-6
    bend_scale: float = 0.1
    overhung_mass: float = RIG_OVERHUNG_MASS
    whirl: float = 1e-6
    whirl_speed: float = 215 * 2 * math.pi / 60
    runout: tuple[float, float] = (0.3e-6, 0.15e-6)
    noise: float = 0.05e-6
    quantise: bool = True
    sleeve_wear: float = 0.0
    sample_rate: float = 2048.0
    revolutions: float = 8.0
    duration: float | None = None
    seed: int = 1
    axial_nodes: int = 41
    circumferential_nodes: int = 120
    shape: tuple[np.ndarray, np.ndarray] | None = field(default=None, repr=False, compare=False)
    surface: SurfaceRoughness | None = None
    liner: Liner | None = None

    def __post_init__(self) -> None:
        require_positive("load", self.load, "N")
        require_positive("viscosity", self.viscosity, "Pa*s")
        require_finite("misalignment", self.misalignment, "rad")
        require_finite("bend_scale", self.bend_scale)
        require_positive("overhung_mass", self.overhung_mass, "kg")
        for name in ("whirl", "noise", "sleeve_wear"):
            if not require_finite(name, getattr(self, name), "m") >= 0.0:
                raise InputError(name, getattr(self, name), "m", ">= 0")
        require_positive("whirl_speed", self.whirl_speed, "rad/s")
        require_positive("sample_rate", self.sample_rate, "Hz")
        require_positive("revolutions", self.revolutions, "rev")
        if self.duration is not None:
            require_positive("duration", self.duration, "s")
        if len(self.runout) != 2 or not all(math.isfinite(r) and r >= 0 for r in self.runout):
            raise InputError("runout", list(self.runout), "m", "two amplitudes >= 0 (1X, 2X)")


@dataclass(frozen=True, eq=False)
class Recording:
    """Synthetic probe signals with the truth that made them.

    Attributes
    ----------
    signals : ndarray (N, channels)
        Probe outputs, V, in ``layout.channels`` order.
    keyphasor : ndarray (N,)
        Once-per-revolution channel, V.
    sample_rate : float
        Hz.
    speed : float
        Shaft speed, rad/s.
    static_z : ndarray (s,)
        Stations of the true static centre line, m.
    static_ey, static_ez : ndarray (s,)
        True static centre line, m.
    whirl_ey, whirl_ez : ndarray (N,)
        True rigid-body motion about it, m.
    clearance : float
        True radial clearance (layout's plus sleeve wear), m.
    solver_status : str
        How the bearing solver placed the journal (:attr:`RigEquilibrium.status`): ``"ok"``,
        ``"contact"`` or ``"not converged"`` (in the last two the journal stands where the
        search stopped); :attr:`contact` and :attr:`converged` read it.
    solver_min_film : float
        Smallest film of the solver's solution, m (with a liner: deformed; rough: the
        separation of the mean planes, negative in boundary lubrication).
    max_liner_deformation : float
        Largest compression of the liner, m (0 without a liner): what the probes' film
        lacks of the bearing's there.
    asperity_load_share : float
        Share of the load the asperities carry (0 smooth).
    """

    signals: np.ndarray = field(repr=False)
    keyphasor: np.ndarray = field(repr=False)
    sample_rate: float
    speed: float
    static_z: np.ndarray = field(repr=False)
    static_ey: np.ndarray = field(repr=False)
    static_ez: np.ndarray = field(repr=False)
    whirl_ey: np.ndarray = field(repr=False)
    whirl_ez: np.ndarray = field(repr=False)
    clearance: float
    solver_status: str
    solver_min_film: float
    max_liner_deformation: float = 0.0
    asperity_load_share: float = 0.0

    @property
    def contact(self) -> bool:
        """The bearing solver found no film that carries the load above its floor."""
        return self.solver_status == "contact"

    @property
    def converged(self) -> bool:
        """The solver's equilibrium carries the load."""
        return self.solver_status == "ok"

    def centres(self, z: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """True journal centre at stations ``z`` (m) and every sample, each (N, nz), m."""
        z = np.asarray(z, dtype=float)
        ey = np.interp(z, self.static_z, self.static_ey)[None, :] + self.whirl_ey[:, None]
        ez = np.interp(z, self.static_z, self.static_ez)[None, :] + self.whirl_ez[:, None]
        return ey, ez

    def film(self, layout: ProbeLayout, theta: np.ndarray, z: np.ndarray) -> np.ndarray:
        """True film h(theta, z, t), m, shape (N, nz, nt)."""
        ey, ez = self.centres(z)
        wear = self.clearance - layout.radial_clearance
        return film_between_circles(ey, ez, np.asarray(theta, dtype=float), layout, wear)


def rig_shape_for(case: RigCase) -> tuple[np.ndarray, np.ndarray]:
    """The case's bending shape (``case.shape``), or the rig's stretched to the layout's bearing
    length: stations (m from the loaded end) and shape (m, at the model's scale)."""
    if case.shape is not None:
        return np.asarray(case.shape[0], dtype=float), np.asarray(case.shape[1], dtype=float)
    z, shape = rig_bending_shape(case.overhung_mass)
    stretch = case.layout.length / 1.2
    return np.asarray(z) * stretch, np.asarray(shape) * stretch


def rig_geometry(case: RigCase, surface: SurfaceRoughness | None = None, liner: Liner | None = None) -> BearingGeometry:
    """The rig's stern bearing geometry: the layout's bore and clearance (plus sleeve wear), the
    journal bent to the case's shape, the case's surface and liner (``surface`` / ``liner``
    replace them where given).

    Raises
    ------
    InputError
        A surface or liner the bearing cannot take (roughness against the clearance, liner
        thickness against the radius), named by its field.
    """
    from shaftline.film import BearingGeometry
    from shaftline.film.geometry import BentJournal

    layout = case.layout
    stations, shape = rig_shape_for(case)
    bend = case.bend_scale * shape
    return BearingGeometry(
        length=layout.length,
        diameter=2.0 * layout.radius,
        radial_clearance=layout.radial_clearance + case.sleeve_wear,
        bent_journal=BentJournal(stations, bend, np.zeros_like(bend)),
        rotation=1 if layout.rotation == 1 else -1,
        surface=case.surface if surface is None else surface,
        liner=case.liner if liner is None else liner,
    )


def rig_bearing(
    case: RigCase, speed: float, surface: SurfaceRoughness | None = None, liner: Liner | None = None
) -> JournalBearing:
    """The rig's stern bearing as the forward model solves it (:func:`rig_geometry`): the
    case's water film at ``speed`` (rad/s), 41 x 120 nodes unless the case says; ``surface``
    and ``liner`` (:class:`~shaftline.film.roughness.SurfaceRoughness`,
    :class:`~shaftline.film.liner.Liner`) replace the case's where given."""
    from shaftline.film import JournalBearing, OperatingPoint, SolverOptions

    return JournalBearing(
        rig_geometry(case, surface, liner),
        OperatingPoint(speed=speed, viscosity=case.viscosity, density=997.0),
        SolverOptions(
            axial_nodes=case.axial_nodes, circumferential_nodes=case.circumferential_nodes, min_film_floor=1e-4
        ),
    )


@dataclass(frozen=True, eq=False)
class RigEquilibrium:
    """The journal's static centre line from the bearing solver at one speed.

    Attributes
    ----------
    speed : float
        Shaft speed, rad/s.
    stations : ndarray (s,)
        Axial stations from the loaded end, m.
    ey, ez : ndarray (s,)
        Journal centre at the stations (vertical, horizontal), m.
    status : str
        ``"ok"``, ``"contact"`` (no film carries the load above the solver's floor) or
        ``"not converged"`` (the search stopped short of the load); in the last two the
        journal stands where the search stopped.
    residual : float
        Share of the load the film and asperities do not carry at the end.
    min_film : float
        Smallest film of the solution, m (liner deformed; rough: mean-plane separation).
    max_liner_deformation : float
        Largest compression of the liner, m.
    asperity_load_share : float
        Share of the load on the asperities.
    """

    speed: float
    stations: np.ndarray = field(repr=False)
    ey: np.ndarray = field(repr=False)
    ez: np.ndarray = field(repr=False)
    status: str
    residual: float
    min_film: float
    max_liner_deformation: float
    asperity_load_share: float


def equilibrium_line(case: RigCase, speed: float) -> RigEquilibrium:
    """Static journal centre line from the bearing solver at ``speed`` (rad/s): the
    equilibrium under the case's load with the misalignment as a journal tilt and the
    bending as a bent journal.

    Raises
    ------
    SolverFailure
        The solver stopped without a position (a failure it raises rather than reports, e.g.
        a Reynolds iteration that does not converge): one line naming the speed and what to
        change. A lined equilibrium whose liner does not settle at its first position starts
        nearer the bore centre instead (film/bearing.py) and is reported, not raised.
    """
    bearing = rig_bearing(case, speed)
    bent = bearing.geometry.bent_journal
    assert bent is not None  # the rig's journal is always bent (rig_geometry)
    stations, bend = bent.z, bent.dy
    try:
        result = bearing.equilibrium(load_y=-case.load, tilt_y=case.misalignment)
    except SolverFailure as failure:
        raise SolverFailure(
            f"monitor simulate: no journal position at {speed * 30 / math.pi:.0f} rpm: the bearing solver stopped "
            f"({failure}); a smaller misalignment or bend_scale, or a stiffer liner, lets it start"
        ) from failure
    state = result.state
    position = state.position
    arm = stations - 0.5 * case.layout.length
    return RigEquilibrium(
        speed,
        stations,
        position.ey + case.misalignment * arm + bend,
        position.ez + position.tilt_z * arm,
        result.status,
        float(result.residual) / case.load,
        float(state.min_film_thickness),
        float(state.max_liner_deformation),
        float(state.asperity_load_share),
    )


def equilibrium_lines(
    case: RigCase,
    speeds: Sequence[float],
    *,
    backend: str | None = None,
    workers: int | None = None,
    progress: Callable[[int, int], None] | None = None,
) -> list[RigEquilibrium]:
    """:func:`equilibrium_line` at each speed (rad/s), spread over cores with
    :func:`shaftline.parallel.map` (``backend``, ``workers`` as there)."""
    return parallel.map(
        functools.partial(equilibrium_line, case),
        list(speeds),
        backend=backend,
        workers=workers,
        progress=progress,
        work_here=True,
    )


def simulate(case: RigCase, speed: float, equilibrium: RigEquilibrium | None = None) -> Recording:
    """Probe signals of the rig at shaft speed ``speed`` (rad/s); ``equilibrium``: the
    journal's static centre line there if already solved (:func:`equilibrium_lines`).

    Raises
    ------
    InputError
        ``"speed"`` not positive.
    """
    require_positive("speed", speed, "rad/s")
    layout = case.layout
    # The runout belongs to the machine (the same at every speed, so a slow-roll recording
    # measures it); the whirl phase and the noise to the recording.
    runout_phases = np.random.default_rng([case.seed, 0]).uniform(0, 2 * math.pi, (len(layout.channels), 2))
    rng = np.random.default_rng([case.seed, 1, int(round(speed * 1e6))])
    length = case.revolutions * 2 * math.pi / speed if case.duration is None else case.duration
    samples = int(round(length * case.sample_rate))
    time = np.arange(samples) / case.sample_rate
    phase = speed * time + 0.5  # the first keyphasor mark a little after the start
    if equilibrium is None:
        equilibrium = equilibrium_line(case, speed)
    elif equilibrium.speed != speed:
        raise InputError("equilibrium.speed", equilibrium.speed, "rad/s", f"the recording's speed {speed:.6g}")
    amplitude = case.whirl * (speed / case.whirl_speed) ** 2
    lag = rng.uniform(0, 2 * math.pi)
    whirl_ey = amplitude * np.cos(phase - lag)
    whirl_ez = layout.rotation * amplitude * np.sin(phase - lag)
    truth = Recording(
        np.empty((0, 0)),
        np.empty(0),
        case.sample_rate,
        speed,
        equilibrium.stations,
        equilibrium.ey,
        equilibrium.ez,
        whirl_ey,
        whirl_ez,
        layout.radial_clearance + case.sleeve_wear,
        equilibrium.status,
        equilibrium.min_film,
        equilibrium.max_liner_deformation,
        equilibrium.asperity_load_share,
    )
    columns = []
    r1, r2 = case.runout
    channel = 0
    for section in layout.sections:
        centre_y, centre_z = truth.centres(np.array([section.position]))
        film = film_between_circles(centre_y[:, 0], centre_z[:, 0], section.angles, layout, case.sleeve_wear)  # (N, p)
        for j, probe in enumerate(section.probes):
            first, second = runout_phases[channel]
            runout = r1 * np.cos(phase - first) + r2 * np.cos(2 * phase - second)
            channel += 1
            gap = probe.mounting_distance + film[:, j] + runout + case.noise * rng.standard_normal(samples)
            if case.quantise and probe.resolution > 0:
                gap = np.round(gap / probe.resolution) * probe.resolution
            columns.append(probe.signal(gap))
    keyphasor = np.where((phase % (2 * math.pi)) < 0.2, 5.0, 0.0)
    return replace(truth, signals=np.stack(columns, axis=1), keyphasor=keyphasor)
