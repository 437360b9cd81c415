"""Eddy-current probes in a journal bearing: layout, calibration and checks (seed 001 Sect. 2.2).

Angles follow the film module (docs/architecture.md): a bearing angle ``theta`` is
measured from the top of the bore (+y) in the direction of shaft rotation, and the unit
vector from the bore centre towards the bore surface at ``theta`` is
``(cos theta, s sin theta)`` in the (y up, z starboard) plane, ``s = rotation``. Axial
positions are measured from the loaded (aft, ballast) end of the bearing, as
``z_local`` of the film module. Every length is in metres.

A probe sits in a radial hole with its face a mounting distance ``S`` behind the bore
surface (seed 001 Fig. 3: S1, S2, S3), so that it reads the gap ``g = S + h`` to the
journal along its own axis, ``h`` the film there. Its output follows its calibration:
``signal = sign * sensitivity * (g - zero)``, ``zero`` being the gap at which it reads 0
(the sensor's zero point, seed 001 Table 2).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from shaftline.errors import InputError, located, require_finite, require_positive

#: Plausible radial clearance over bore radius: stern-tube and journal bearings run at
#: 0.5 to 4 per mille of the diameter (seed 001: 0.55 mm on R = 161.5 mm, 3.4e-3); a
#: clearance given in the wrong unit (mm for m, um for mm) is 1000 times outside.
CLEARANCE_RATIO_RANGE = (1e-4, 2e-2)
#: Largest mounting distance in radial clearances: a probe sits within its measuring range
#: of the journal (a few mm; seed 001: 0.5 and 3 mm ranges), never metres away.
MAX_MOUNTING_CLEARANCES = 50.0
#: Largest roughness Ra as a share of the clearance: a rougher surface fills the clearance.
MAX_ROUGHNESS_SHARE = 0.1
#: Allowed Rq / Ra factor (seed 001 Eq. 10: 1.20 to 1.25; a Gaussian surface has 1.2533).
RQ_FACTOR_RANGE = (1.20, 1.26)


@dataclass(frozen=True)
class Probe:
    """One eddy-current displacement probe.

    Attributes
    ----------
    name : str
        Channel name (a recording maps its columns to probes by this name).
    angle : float
        Bearing angle of the probe axis, rad (from the top, in the direction of rotation).
    mounting_distance : float
        S: distance from the probe face back to the bore surface, m (>= 0; 0 is flush).
    sensitivity : float
        Output per unit gap, V/m (8 mV/um = 8000 V/m).
    zero : float
        Gap at which the output is zero, m (the sensor's zero point).
    sign : int
        +1 when the output grows with the gap, -1 when it falls.
    measuring_range : float
        Gap span the probe measures above ``zero``, m (readings beyond it are invalid).
    resolution : float
        Smallest gap step the probe resolves, m (seed 001 Table 2: 0.15 and 0.025 um).
    """

    name: str
    angle: float
    mounting_distance: float
    sensitivity: float = 1.0
    zero: float = 0.0
    sign: int = 1
    measuring_range: float = math.inf
    resolution: float = 0.0

    def validate(self, clearance: float) -> None:
        """Check the probe against the bearing's radial clearance ``clearance`` (m)."""
        require_finite("angle", self.angle, "rad")
        distance = require_finite("mounting_distance", self.mounting_distance, "m")
        if not 0.0 <= distance <= MAX_MOUNTING_CLEARANCES * clearance:
            raise InputError(
                "mounting_distance",
                distance,
                "m",
                f"in [0, {MAX_MOUNTING_CLEARANCES * clearance:.4g}] ({MAX_MOUNTING_CLEARANCES:g} radial clearances;"
                " a value 1000 times off is in the wrong unit)",
            )
        require_positive("sensitivity", self.sensitivity, "V/m")
        require_finite("zero", self.zero, "m")
        if self.sign not in (1, -1):
            raise InputError("sign", self.sign, "", "+1 (output grows with the gap) or -1")
        if not self.measuring_range > 0.0:
            raise InputError("measuring_range", self.measuring_range, "m", "> 0")
        resolution = require_finite("resolution", self.resolution, "m")
        if not 0.0 <= resolution < clearance:
            raise InputError("resolution", resolution, "m", f"in [0, {clearance:.4g}) (below the radial clearance)")

    def gap(self, signal: np.ndarray) -> np.ndarray:
        """Gap to the journal, m, from the probe output ``signal`` (V)."""
        return self.zero + self.sign * np.asarray(signal, dtype=float) / self.sensitivity

    def signal(self, gap: np.ndarray) -> np.ndarray:
        """Probe output, V, for a gap ``gap`` (m): the inverse of :meth:`gap`."""
        return self.sign * self.sensitivity * (np.asarray(gap, dtype=float) - self.zero)


@dataclass(frozen=True)
class Section:
    """A measurement section: two or more probes in one plane across the bearing.

    Attributes
    ----------
    name : str
        Label (seed 001: D1, D2, D3).
    position : float
        Axial position from the loaded (aft) end of the bearing, m.
    probes : tuple of Probe
        At least two probes whose axes are not collinear (they fix the journal centre).
    """

    name: str
    position: float
    probes: tuple[Probe, ...]

    @property
    def angles(self) -> np.ndarray:
        """Probe angles, rad, shape (p,)."""
        return np.array([p.angle for p in self.probes], dtype=float)

    @property
    def mounting_distances(self) -> np.ndarray:
        """Mounting distances S, m, shape (p,)."""
        return np.array([p.mounting_distance for p in self.probes], dtype=float)


@dataclass(frozen=True)
class ProbeLayout:
    """Probes of a bearing with the geometry and surfaces the identification needs.

    Attributes
    ----------
    sections : tuple of Section
        From the loaded end forward (increasing ``position``), inside the bearing.
    length : float
        Bearing length L, m.
    radius : float
        Bore radius R, m.
    radial_clearance : float
        Radial clearance c, m (the clearance after break-in; seed 001: 0.55 mm).
    roughness_bearing, roughness_journal : float
        Arithmetic mean roughness Ra of the bore (liner) and the journal (sleeve), m
        (seed 001: 1.6 and 0.8 um).
    rq_factor : float
        Rq / Ra, in [1.20, 1.26] (seed 001 Eq. 10: 1.20 to 1.25).
    rotation : int
        +1 for a shaft turning clockwise seen from aft, -1 anticlockwise.

    Raises
    ------
    InputError
        Naming the field (``"radial_clearance"``, ``"sections[1].position"``,
        ``"sections[0].probes[2].mounting_distance"``...), its value, unit and allowed range.
    """

    sections: tuple[Section, ...]
    length: float
    radius: float
    radial_clearance: float
    roughness_bearing: float = 1.6e-6
    roughness_journal: float = 0.8e-6
    rq_factor: float = 1.25
    rotation: int = 1

    def __post_init__(self) -> None:
        length = require_positive("length", self.length, "m")
        radius = require_positive("radius", self.radius, "m")
        clearance = require_positive("radial_clearance", self.radial_clearance, "m")
        low, high = CLEARANCE_RATIO_RANGE
        if not low * radius <= clearance <= high * radius:
            raise InputError(
                "radial_clearance",
                clearance,
                "m",
                f"in [{low * radius:.3g}, {high * radius:.3g}] ({low:g} to {high:g} of the radius {radius:g} m;"
                " a value 1000 times off is in the wrong unit)",
            )
        for name in ("roughness_bearing", "roughness_journal"):
            value = require_positive(name, getattr(self, name), "m")
            if value > MAX_ROUGHNESS_SHARE * clearance:
                raise InputError(
                    name, value, "m", f"<= {MAX_ROUGHNESS_SHARE * clearance:.3g} ({MAX_ROUGHNESS_SHARE:g} c; unit?)"
                )
        factor = require_finite("rq_factor", self.rq_factor)
        if not RQ_FACTOR_RANGE[0] <= factor <= RQ_FACTOR_RANGE[1]:
            raise InputError("rq_factor", factor, "", f"in [{RQ_FACTOR_RANGE[0]}, {RQ_FACTOR_RANGE[1]}]")
        if self.rotation not in (1, -1):
            raise InputError("rotation", self.rotation, "", "+1 (clockwise from aft) or -1")
        if not self.sections:
            raise InputError("sections", 0, "", "at least one measurement section")
        names: set[str] = set()
        previous = -math.inf
        for k, section in enumerate(self.sections):
            with located(f"sections[{k}]"):
                position = require_finite("position", section.position, "m")
                if not 0.0 <= position <= length:
                    raise InputError("position", position, "m", f"inside the bearing, [0, {length:g}]")
                if position <= previous:
                    order = f"> {previous:g} (sections from the loaded end forward)"
                    raise InputError("position", position, "m", order)
                previous = position
                self._check_probes(section, clearance, names)

    @staticmethod
    def _check_probes(section: Section, clearance: float, names: set[str]) -> None:
        if len(section.probes) < 2:
            raise InputError("probes", len(section.probes), "", "at least 2 probes per section")
        for j, probe in enumerate(section.probes):
            with located(f"probes[{j}]"):
                probe.validate(clearance)
                if probe.name in names:
                    raise InputError("name", probe.name, "", "a channel name not used by another probe")
                names.add(probe.name)
        angles = section.angles
        # Two probes fix the centre unless their axes are collinear (same or opposite angles).
        sine = np.abs(np.sin(angles[:, None] - angles[None, :]))
        if sine.max() < 1e-3:
            raise InputError(
                "probes", np.degrees(angles).round(3).tolist(), "deg", "axes not all on one line (two apart)"
            )

    @property
    def positions(self) -> np.ndarray:
        """Axial positions of the sections from the loaded end, m, shape (n,)."""
        return np.array([s.position for s in self.sections], dtype=float)

    @property
    def journal_radius(self) -> float:
        """Nominal journal radius R - c, m."""
        return self.radius - self.radial_clearance

    @property
    def composite_roughness(self) -> float:
        """sqrt(Rq1^2 + Rq2^2) with Rq = rq_factor * Ra, m (seed 001 Eq. 10)."""
        return self.rq_factor * math.hypot(self.roughness_bearing, self.roughness_journal)

    @property
    def channels(self) -> tuple[str, ...]:
        """Probe names in section order, the column order of a sample block."""
        return tuple(p.name for s in self.sections for p in s.probes)

    def section_columns(self) -> list[slice]:
        """Column slice of each section in a (samples x channels) block ordered as :attr:`channels`."""
        slices, start = [], 0
        for section in self.sections:
            slices.append(slice(start, start + len(section.probes)))
            start += len(section.probes)
        return slices

    def gaps(self, signals: np.ndarray) -> np.ndarray:
        """Gaps (m) from probe outputs (V), both (samples x channels) in :attr:`channels` order."""
        signals = np.asarray(signals, dtype=float)
        probes = [p for s in self.sections for p in s.probes]
        if signals.ndim != 2 or signals.shape[1] != len(probes):
            raise InputError("signals", signals.shape, "V", f"(samples, {len(probes)}) in channel order")
        zero = np.array([p.zero for p in probes])
        scale = np.array([p.sign / p.sensitivity for p in probes])
        return zero + signals * scale


def within_range(layout: ProbeLayout, gaps: np.ndarray) -> np.ndarray:
    """Which gaps each probe can measure: ``zero <= g <= zero + measuring_range`` (and finite).

    Parameters
    ----------
    layout : ProbeLayout
    gaps : ndarray (N, channels)
        Gaps in the column order of ``layout.channels``, m.

    Returns
    -------
    ndarray of bool (N, channels)
        False where a reading is beyond the probe's range (saturated) or not a number, so that
        a reader can mask and count such samples.
    """
    gaps = np.asarray(gaps, dtype=float)
    probes = [p for s in layout.sections for p in s.probes]
    if gaps.ndim != 2 or gaps.shape[1] != len(probes):
        raise InputError("gaps", gaps.shape, "m", f"(samples, {len(probes)}) in channel order")
    low = np.array([p.zero for p in probes])
    high = low + np.array([p.measuring_range for p in probes])
    return np.isfinite(gaps) & (gaps >= low) & (gaps <= high)


def seed001_layout(
    radial_clearance: float = 0.55e-3,
    mounting_distances: tuple[float, float, float] = (1.2e-3, 1.2e-3, 0.15e-3),
) -> ProbeLayout:
    """The probe layout of seed 001 (Sect. 2.2, Fig. 3, Tables 1-2).

    Three sections D1-D3 at 292, 429.5 and 856 mm from the ballast end of a 1.2 m bearing
    of 323 mm journal diameter; probes #1 and #2 (eddyNCDT 3010-U3: 3 mm range, zero point
    0.3 mm, 0.15 um resolution) at 315 and 45 deg, #3 (0.5 mm range, zero point 0.05 mm,
    0.025 um) at 180 deg. The mounting distances are not given in the seed: the defaults
    put each probe near the middle of its range with the journal centred (seed: "near the
    median of the sensor range"). Sensitivities are 1 V per range (an assumption).
    """
    radius = 0.5 * 0.323 + radial_clearance
    sections = []
    for label, position in (("D1", 0.292), ("D2", 0.4295), ("D3", 0.856)):
        probes = (
            Probe(f"{label}_1", math.radians(315.0), mounting_distances[0], 1.0 / 3e-3, 0.3e-3, 1, 3e-3, 0.15e-6),
            Probe(f"{label}_2", math.radians(45.0), mounting_distances[1], 1.0 / 3e-3, 0.3e-3, 1, 3e-3, 0.15e-6),
            Probe(f"{label}_3", math.radians(180.0), mounting_distances[2], 1.0 / 0.5e-3, 0.05e-3, 1, 0.5e-3, 0.025e-6),
        )
        sections.append(Section(label, position, probes))
    return ProbeLayout(tuple(sections), length=1.2, radius=radius, radial_clearance=radial_clearance)
