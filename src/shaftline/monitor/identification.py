"""Journal-centre orbit and film thickness at the probe sections (seed 001 Eq. 1-7).

Geometry (docs/theory.md, "Film-thickness monitoring"): the bore is a circle of radius
``R`` about the bore centre, the journal a circle of radius ``R_j = R - c - k`` about
the journal centre ``e = (ey, ez)``. Along the bearing angle ``theta`` (unit vector
``u = (cos theta, s sin theta)``, normal ``n = (-sin theta, s cos theta)``, ``s`` the
sense of rotation) the film between the two circles is exactly

    h(theta) = R - u.e - sqrt(R_j^2 - (n.e)^2),                        (M1)

and a probe at ``theta_i`` mounted ``S_i`` behind the bore reads the gap
``g_i = S_i + h(theta_i)``. To first order in ``e / R`` (M1) is the film module's
``h = c + k - u.e`` (seed 001 Eq. 4 and 9); the second-order term ``(n.e)^2 / (2 R_j)``
reaches 0.9 um at full eccentricity on the seed's bearing, a fifth of the boundary
threshold 2.24 um, so the exact form is kept. The centre follows from the gaps of 2+
probes by least squares on the linear form, corrected twice for the second-order term
(each pass shrinks the error by ``e / R``, below 1e-11 m after two).

The correction factor ``k`` (seed 001 Eq. 5-7) is a gap common to all probes of a
section that no journal displacement explains; three probes fix it with the centre
from the mean gaps of stable running (the "linear midpoint values").
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from shaftline._compiled import njit_cached
from shaftline.errors import InputError
from shaftline.monitor.probes import ProbeLayout, Section

#: Fixed-point passes for the second-order (circle) term: each shrinks the error by e/R.
CIRCLE_PASSES = 2


def directions(angles: np.ndarray, rotation: int = 1) -> tuple[np.ndarray, np.ndarray]:
    """Unit vectors along and normal to the bearing angles, each shape (p, 2) in (y, z)."""
    angles = np.asarray(angles, dtype=float)
    along = np.stack([np.cos(angles), rotation * np.sin(angles)], axis=-1)
    normal = np.stack([-np.sin(angles), rotation * np.cos(angles)], axis=-1)
    return along, normal


def _circle_term(normal_offset: np.ndarray, journal_radius: float | np.ndarray) -> np.ndarray:
    """``R_j - sqrt(R_j^2 - w^2)`` without cancellation, m (w the offset normal to the axis)."""
    w2 = normal_offset * normal_offset
    return w2 / (journal_radius + np.sqrt(np.maximum(journal_radius * journal_radius - w2, 0.0)))


def film_between_circles(
    ey: np.ndarray, ez: np.ndarray, theta: np.ndarray, layout: ProbeLayout, correction: float | np.ndarray = 0.0
) -> np.ndarray:
    """Film thickness (M1) at angles ``theta`` for journal centres ``(ey, ez)``, m.

    Parameters
    ----------
    ey, ez : ndarray (...,)
        Journal centre offsets from the bore centre, m (vertical up, horizontal starboard).
    theta : ndarray (m,)
        Bearing angles, rad.
    layout : ProbeLayout
        Bore radius, clearance and sense of rotation.
    correction : float or ndarray broadcasting with ``ey``
        Correction factor k, m (adds to the clearance).

    Returns
    -------
    ndarray (..., m)
        Film thickness, m; negative where the circles overlap (contact, seed 001 Sect. 5.1).

    Examples
    --------
    The seed's bearing (c = 0.55 mm) with the journal 0.5 mm below the bore centre: the film
    at the top and the bottom, and 90 deg round, where the exact form adds e^2 / (2 R_j):

    >>> import numpy as np
    >>> from shaftline.monitor.probes import seed001_layout
    >>> h = film_between_circles(np.array(-5e-4), np.array(0.0), np.radians([0.0, 90.0, 180.0]), seed001_layout())
    >>> (h * 1e6).round(3).tolist()
    [1050.0, 550.774, 50.0]
    """
    along, normal = directions(theta, layout.rotation)
    ey = np.asarray(ey, dtype=float)[..., None]
    ez = np.asarray(ez, dtype=float)[..., None]
    k = np.asarray(correction, dtype=float)
    k = k[..., None] if k.ndim else k
    journal = layout.journal_radius - k
    projection = ey * along[:, 0] + ez * along[:, 1]
    across = ey * normal[:, 0] + ez * normal[:, 1]
    return layout.radial_clearance + k - projection + _circle_term(across, journal)


@dataclass(frozen=True)
class SectionReference:
    """Journal centre and correction factor of one section in stable running (seed 001 Eq. 1, 5-7).

    Attributes
    ----------
    name : str
        Section name.
    ey, ez : float
        Journal centre offsets at the reference point, m.
    correction : float
        Correction factor k, m (0 for a section of two probes: it cannot be told apart).
    residual : float
        RMS of the probe gaps not explained by the fitted centre and k, m (0 when exact).
    """

    name: str
    ey: float
    ez: float
    correction: float
    residual: float


@dataclass(frozen=True, eq=False)
class SectionOrbit:
    """Journal-centre orbit of one section over a block of samples.

    Attributes
    ----------
    name : str
    position : float
        Axial position from the loaded end, m.
    ey, ez : ndarray (N,)
        Journal centre offsets from the bore centre, m.
    correction : float
        Correction factor k used, m.
    clearance : float
        Radial clearance c of the layout, m.
    rotation : int
        Sense of rotation of the layout.

    Equality is identity (the arrays have no single truth value).
    """

    name: str
    position: float
    ey: np.ndarray = field(repr=False)
    ez: np.ndarray = field(repr=False)
    correction: float
    clearance: float
    rotation: int

    @property
    def eccentricity(self) -> np.ndarray:
        """|e|, m, shape (N,)."""
        return np.hypot(self.ey, self.ez)

    @property
    def eccentricity_ratio(self) -> np.ndarray:
        """|e| / (c + k), shape (N,)."""
        return self.eccentricity / (self.clearance + self.correction)

    @property
    def position_angle(self) -> np.ndarray:
        """Bearing angle of the line of centres (where the film is thinnest), rad in [0, 2 pi)."""
        return np.arctan2(self.rotation * self.ez, self.ey) % (2.0 * math.pi)

    @property
    def attitude_angle(self) -> np.ndarray:
        """Angle from the bottom of the bore (the line of a vertical load) to the line of
        centres, positive in the direction of rotation, rad in [-pi, pi)."""
        return self.position_angle - math.pi

    @property
    def min_film(self) -> np.ndarray:
        """Smallest film of the section, ``c + k - |e|`` (exact for two circles), m, shape (N,)."""
        return self.clearance + self.correction - self.eccentricity


def _solver(section: Section, rotation: int, with_correction: bool) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Pseudo-inverse of the linear probe model of one section and the probe directions."""
    along, normal = directions(section.angles, rotation)
    matrix = along if not with_correction else np.hstack([along, -np.ones((along.shape[0], 1))])
    if np.linalg.matrix_rank(matrix) < matrix.shape[1]:
        raise InputError(
            f"{section.name}.probes", np.degrees(section.angles).round(3).tolist(), "deg", "angles that fix the centre"
        )
    return np.linalg.pinv(matrix), along, normal


@njit_cached(inline="always")
def _circle_series(w: float, journal: float) -> float:
    """``R_j - sqrt(R_j^2 - w^2)`` by its series ``R_j (x/2 + x^2/8 + x^3/16)``, ``x = (w/R_j)^2``.

    The first omitted term is ``5 x^4 R_j / 128``: below 1e-21 m for ``w <= c`` on the seed's
    bearing (x <= 1.2e-5), and no square root in the per-sample loop.
    """
    x = (w / journal) ** 2
    return journal * x * (0.5 + x * (0.125 + 0.0625 * x))


@njit_cached()
def _orbit_kernel(
    gaps: np.ndarray,
    section_of_channel: np.ndarray,
    offset: np.ndarray,
    inverse: np.ndarray,
    normal: np.ndarray,
    section_of_film: np.ndarray,
    film_along: np.ndarray,
    film_normal: np.ndarray,
    journal: np.ndarray,
    clearance: np.ndarray,
    passes: int,
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Centres and films of every section, one time sample at a time in compiled code.

    Per channel ``i`` (section ``section_of_channel[i]``): ``offset[i] - g_i`` is the right-hand
    side of the linear probe model ``u.e = c + k + S - g`` (seed 001 Eq. 1 and 3 in vector
    form), ``inverse[:, i]`` its column of the section's pseudo-inverse and ``normal[i]`` the
    probe's normal direction. One pass over the rows reads each sample once; numpy's (N, p)
    temporaries cost several times more.
    """
    n, channels = gaps.shape
    sections = journal.size
    films = film_along.shape[0]
    ey = np.empty((n, sections))
    ez = np.empty((n, sections))
    film = np.empty((n, films))
    rhs = np.empty(channels)
    y = np.empty(sections)
    z = np.empty(sections)
    y_new = np.empty(sections)
    z_new = np.empty(sections)
    for t in range(n):
        y[:] = 0.0
        z[:] = 0.0
        for i in range(channels):
            j = section_of_channel[i]
            rhs[i] = offset[i] - gaps[t, i]
            y[j] += inverse[0, i] * rhs[i]
            z[j] += inverse[1, i] * rhs[i]
        for _ in range(passes):
            y_new[:] = 0.0
            z_new[:] = 0.0
            for i in range(channels):
                j = section_of_channel[i]
                q = _circle_series(normal[i, 0] * y[j] + normal[i, 1] * z[j], journal[j])
                y_new[j] += inverse[0, i] * (rhs[i] + q)
                z_new[j] += inverse[1, i] * (rhs[i] + q)
            y[:] = y_new
            z[:] = z_new
        for j in range(sections):
            ey[t, j] = y[j]
            ez[t, j] = z[j]
        for f in range(films):
            j = section_of_film[f]
            q = _circle_series(film_normal[f, 0] * y[j] + film_normal[f, 1] * z[j], journal[j])
            film[t, f] = clearance[j] - (film_along[f, 0] * y[j] + film_along[f, 1] * z[j]) + q
    return ey, ez, film


def reference_points(layout: ProbeLayout, gaps: np.ndarray, correction: bool = True) -> tuple[SectionReference, ...]:
    """Reference point and correction factor k of each section from a stable-running block.

    The mean gap of each probe over the block stands for the seed's "linear midpoint
    value" of the periodic signal (pass whole revolutions). Sections of three or more
    probes solve for (ey, ez, k) by least squares (seed 001 Eq. 5-7); sections of two
    probes, or ``correction=False``, for (ey, ez) with k = 0 (Eq. 1-2).

    Parameters
    ----------
    layout : ProbeLayout
    gaps : ndarray (N, channels)
        Gaps in the column order of ``layout.channels``, m.
    correction : bool
        Identify k where three or more probes allow it.
    """
    gaps = _check_block(layout, gaps)
    mean = gaps.mean(axis=0)
    references = []
    for section, columns in zip(layout.sections, layout.section_columns(), strict=True):
        g = mean[columns]
        with_k = correction and len(section.probes) >= 3
        inverse, along, normal = _solver(section, layout.rotation, with_k)
        rhs = layout.radial_clearance + section.mounting_distances - g
        k = 0.0
        solution = inverse @ rhs
        for _ in range(CIRCLE_PASSES + 1):
            k = float(solution[2]) if with_k else 0.0
            across = normal @ solution[:2]
            solution = inverse @ (rhs + _circle_term(across, layout.journal_radius - k))
        k = float(solution[2]) if with_k else 0.0
        ey, ez = float(solution[0]), float(solution[1])
        model = film_between_circles(np.array(ey), np.array(ez), section.angles, layout, k)
        residual = float(np.sqrt(np.mean((model + section.mounting_distances - g) ** 2)))
        references.append(SectionReference(section.name, ey, ez, k, residual))
    return tuple(references)


def identify_orbits(
    layout: ProbeLayout, gaps: np.ndarray, references: tuple[SectionReference, ...] | None = None
) -> tuple[SectionOrbit, ...]:
    """Journal-centre orbit of every section from a block of probe gaps (seed 001 Eq. 3).

    One compiled pass over the samples (:func:`probe_films`). With a reference point the
    seed writes the orbit as the reference centre plus the probe increments (Eq. 3); for a
    model linear in the centre that equals solving Eq. 1 at each sample, which is what is
    done here, with the k of the reference.

    Parameters
    ----------
    layout : ProbeLayout
    gaps : ndarray (N, channels)
        Gaps in the column order of ``layout.channels``, m.
    references : tuple of SectionReference, optional
        Correction factors k per section (None: k = 0).
    """
    return tuple(orbit for orbit, _ in probe_films(layout, gaps, references))


def probe_films(
    layout: ProbeLayout,
    gaps: np.ndarray,
    references: tuple[SectionReference, ...] | None = None,
    theta: np.ndarray | None = None,
) -> list[tuple[SectionOrbit, np.ndarray]]:
    """Orbit and film of every section in one pass: the per-sample part of the monitor.

    Parameters
    ----------
    layout : ProbeLayout
    gaps : ndarray (N, channels)
        Gaps in the column order of ``layout.channels``, m.
    references : tuple of SectionReference, optional
        Correction factors k per section (None: k = 0).
    theta : ndarray (m,), optional
        Angles of the film, rad (None: each section's probe angles).

    Returns
    -------
    list of (SectionOrbit, ndarray (N, m))
        Per section, the orbit and the film h(theta, t) (exact form M1), m.
    """
    gaps = _check_block(layout, gaps)
    if references is not None and len(references) != len(layout.sections):
        raise InputError("references", len(references), "", f"one per section ({len(layout.sections)})")
    corrections = (
        np.array([r.correction for r in references]) if references is not None else np.zeros(len(layout.sections))
    )
    section_of_channel, offsets, inverses, normals = [], [], [], []
    section_of_film, film_along, film_normal = [], [], []
    for index, section in enumerate(layout.sections):
        inverse, _, normal = _solver(section, layout.rotation, False)
        section_of_channel += [index] * len(section.probes)
        offsets.append(layout.radial_clearance + corrections[index] + section.mounting_distances)
        inverses.append(inverse)
        normals.append(normal)
        angles = section.angles if theta is None else np.asarray(theta, dtype=float)
        along, across = directions(angles, layout.rotation)
        section_of_film += [index] * angles.size
        film_along.append(along)
        film_normal.append(across)
    ey, ez, film = _orbit_kernel(
        gaps,
        np.array(section_of_channel, dtype=np.int64),
        np.concatenate(offsets),
        np.ascontiguousarray(np.hstack(inverses)),
        np.vstack(normals),
        np.array(section_of_film, dtype=np.int64),
        np.vstack(film_along),
        np.vstack(film_normal),
        layout.journal_radius - corrections,
        layout.radial_clearance + corrections,
        CIRCLE_PASSES,
    )
    results = []
    start = 0
    for index, section in enumerate(layout.sections):
        count = section_of_film.count(index)
        orbit = SectionOrbit(
            section.name,
            section.position,
            ey[:, index],
            ez[:, index],
            float(corrections[index]),
            layout.radial_clearance,
            layout.rotation,
        )
        results.append((orbit, film[:, start : start + count]))
        start += count
    return results


def section_film(orbit: SectionOrbit, theta: np.ndarray, layout: ProbeLayout) -> np.ndarray:
    """Film h(theta, t) around a section (seed 001 Eq. 4, exact form M1), m, shape (N, m)."""
    return film_between_circles(orbit.ey, orbit.ez, np.asarray(theta, dtype=float), layout, orbit.correction)


def film_noise_std(section: Section, theta: np.ndarray, rotation: int, gap_std: np.ndarray) -> np.ndarray:
    """Standard deviation of the identified film at ``theta`` from independent gap errors, m.

    Linear error propagation through the least-squares centre: the film error is
    ``-u(theta).P dg`` with P the pseudo-inverse of the probe directions, so its variance is
    ``sum_i (u.P)_i^2 sigma_i^2``. For two probes 90 deg apart and the film at a probe
    angle it equals that probe's own error.
    """
    inverse, _, _ = _solver(section, rotation, False)
    along, _ = directions(np.asarray(theta, dtype=float), rotation)
    gain = along @ inverse  # (m, p)
    return np.sqrt((gain * gain) @ (np.asarray(gap_std, dtype=float) ** 2))


def _check_block(layout: ProbeLayout, gaps: np.ndarray) -> np.ndarray:
    gaps = np.asarray(gaps, dtype=float)
    channels = len(layout.channels)
    if gaps.ndim != 2 or gaps.shape[1] != channels or gaps.shape[0] < 1:
        raise InputError("gaps", gaps.shape, "m", f"a (samples, {channels}) block in channel order")
    return gaps
