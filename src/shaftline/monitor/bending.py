"""Journal centre line along the bearing from the measured sections (seed 001 Eq. 8-9, Sect. 5.3).

The centre offsets of the journal at the probe sections fix a centre line
``e(z, t) = (ey(z, t), ez(z, t))`` along the whole bearing, from which the film at any
section and angle follows (M1 with a k interpolated between the sections). Two methods:

* :func:`least_squares_line` (seed 001 Sect. 5.3, first method): a polynomial in z fitted
  to the section centres at every sample; degree 1 is Eq. 8 (a straight journal tilted by
  ``theta_x``, ``theta_y``), degree 2 (three sections) the seed's least-squares bending curve.
* :func:`model_line` (the seed's improved method): the bending shape comes from the shaft
  model of the machine (:func:`model_shape`, the project's alignment model) and only its
  free coefficients, an offset, a tilt and a scale of the shape in each plane, are fitted
  to the mean section centres by a global optimiser (scipy's differential evolution; the
  seed used PSO) minimising the seed's objective, RMSE less correlation. The motion about
  that mean (orbits) is carried as a rigid-body offset and tilt fitted at every sample.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass, field
from typing import TYPE_CHECKING

import numpy as np

from shaftline.errors import InputError
from shaftline.monitor.identification import SectionOrbit, film_between_circles
from shaftline.monitor.probes import ProbeLayout

if TYPE_CHECKING:
    from shaftline.shaft import ShaftLine


@dataclass(frozen=True, eq=False)
class Basis:
    """Functions of the axial position the centre line is made of.

    The polynomial terms ``(z - origin)^j`` for ``j = 0 .. degree``, then, when ``shape``
    is given, a tabulated bending shape (linear between its stations).

    Attributes
    ----------
    origin : float
        Axial position the polynomial is centred on, m.
    degree : int
        Highest power of the polynomial part.
    shape_z : ndarray (s,) or None
        Stations of the tabulated shape from the loaded end, m (increasing).
    shape : ndarray (s,) or None
        The shape, m (any linear part of it is indistinguishable from the polynomial).
    """

    origin: float
    degree: int
    shape_z: np.ndarray | None = None
    shape: np.ndarray | None = None

    @property
    def size(self) -> int:
        """Number of functions."""
        return self.degree + 1 + (self.shape is not None)

    def values(self, z: np.ndarray) -> np.ndarray:
        """The functions at stations ``z`` (m), shape (size, nz)."""
        z = np.asarray(z, dtype=float)
        rows = [(z - self.origin) ** j for j in range(self.degree + 1)]
        if self.shape is not None and self.shape_z is not None:
            rows.append(np.interp(z, self.shape_z, self.shape))
        return np.array(rows)

    def slopes(self, z: np.ndarray) -> np.ndarray:
        """d/dz of the functions at ``z``, 1/m powers, shape (size, nz)."""
        z = np.asarray(z, dtype=float)
        rows = [j * (z - self.origin) ** (j - 1) if j else np.zeros_like(z) for j in range(self.degree + 1)]
        if self.shape is not None and self.shape_z is not None:
            gradient = np.gradient(self.shape, self.shape_z)
            rows.append(np.interp(z, self.shape_z, gradient))
        return np.array(rows)


@dataclass(frozen=True, eq=False)
class CentreLine:
    """Journal centre line along the bearing at every sample of a block.

    Attributes
    ----------
    basis_y, basis_z : Basis
        Functions of the vertical and horizontal centre line.
    coefficients_y, coefficients_z : ndarray (N, size)
        Their coefficients at each sample, m per unit of the function.
    positions : ndarray (n,)
        Axial positions of the measured sections, m.
    corrections : ndarray (n,)
        Correction factor k of each section, m (interpolated linearly between sections,
        held beyond the end sections).
    objective : float
        Final value of the fit's objective (``nan`` for a least-squares line).
    """

    basis_y: Basis
    basis_z: Basis
    coefficients_y: np.ndarray = field(repr=False)
    coefficients_z: np.ndarray = field(repr=False)
    positions: np.ndarray = field(repr=False)
    corrections: np.ndarray = field(repr=False)
    objective: float = float("nan")

    def at(self, z: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """Centre offsets (ey, ez) at stations ``z`` (m), each shape (N, nz), m."""
        return self.coefficients_y @ self.basis_y.values(z), self.coefficients_z @ self.basis_z.values(z)

    def tilt(self, z: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """Slopes of the journal (vertical dy/dz, horizontal dz/dz) at ``z``, rad, each (N, nz)."""
        return self.coefficients_y @ self.basis_y.slopes(z), self.coefficients_z @ self.basis_z.slopes(z)

    def correction_at(self, z: np.ndarray) -> np.ndarray:
        """Correction factor k at stations ``z``, m, shape (nz,)."""
        return np.interp(np.asarray(z, dtype=float), self.positions, self.corrections)


def _section_centres(
    orbits: Sequence[SectionOrbit], minimum: int = 1
) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    if len(orbits) < minimum:
        raise InputError("orbits", len(orbits), "sections", f"at least {minimum} measured sections")
    sizes = {o.ey.size for o in orbits}
    if len(sizes) != 1:
        raise InputError("orbits", sorted(sizes), "samples", "the same samples at every section")
    positions = np.array([o.position for o in orbits])
    ey = np.stack([o.ey for o in orbits], axis=1)
    ez = np.stack([o.ez for o in orbits], axis=1)
    return positions, ey, ez, np.array([o.correction for o in orbits])


def least_squares_line(orbits: Sequence[SectionOrbit], degree: int = 2, origin: float | None = None) -> CentreLine:
    """Polynomial centre line through the section centres at every sample (seed 001 Eq. 8, Sect. 5.3).

    Parameters
    ----------
    orbits : sequence of SectionOrbit
        Sections over the same samples (one gives a journal parallel to the bore).
    degree : int
        Polynomial degree, reduced to (sections - 1) when larger; 1 is the straight tilted
        journal of Eq. 8, 2 the seed's bending curve through three sections.
    origin : float, optional
        Centre of the polynomial, m (default: the mean section position).
    """
    positions, ey, ez, corrections = _section_centres(orbits)
    if not isinstance(degree, int) or degree < 1:
        raise InputError("degree", degree, "", "an integer >= 1")
    degree = min(degree, positions.size - 1)
    basis = Basis(float(positions.mean()) if origin is None else origin, degree)
    inverse = np.linalg.pinv(basis.values(positions).T)  # (size, n)
    return CentreLine(basis, basis, ey @ inverse.T, ez @ inverse.T, positions, corrections)


def model_shape(line: ShaftLine, bearing: str, stations: np.ndarray) -> np.ndarray:
    """Bending of the journal inside a bearing from the shaft model, less its chord, m.

    Solves the line's first condition with the project's alignment model
    (:class:`shaftline.shaft.AlignmentModel`) and returns the vertical deflection at
    ``stations`` (m from the bearing's aft edge, the loaded end) less the straight line
    through its values at the bearing edges: the shape a scale, an offset and a tilt are
    fitted to (:func:`model_line`).

    Parameters
    ----------
    line : shaftline.shaft.ShaftLine
        The machine: shaft, bearings (the monitored one as a multi-point elastic support),
        masses.
    bearing : str
        Name of the monitored bearing.
    stations : ndarray
        Stations from the bearing's aft edge, m.
    """
    from shaftline.shaft import AlignmentModel, ShaftLine

    if not isinstance(line, ShaftLine):
        raise InputError("line", type(line).__name__, "", "a shaftline.shaft.ShaftLine")
    names = [b.name for b in line.bearings]
    if bearing not in names:
        raise InputError("bearing", bearing, "", "one of " + ", ".join(names))
    monitored = line.bearings[names.index(bearing)]
    result = AlignmentModel(line).solve(line.all_conditions()[:1])[0]
    aft = monitored.x - 0.5 * monitored.length
    stations = np.asarray(stations, dtype=float)
    deflection = np.interp(aft + stations, result.x, result.deflection_y)
    ends = np.interp(aft + np.array([0.0, monitored.length]), result.x, result.deflection_y)
    chord = ends[0] + (ends[1] - ends[0]) * stations / monitored.length
    return deflection - chord


def seed_objective(fitted: np.ndarray, measured: np.ndarray, scale: float) -> np.ndarray:
    """The seed's objective: RMSE (over ``scale``) less the correlation coefficient.

    Seed 001 Sect. 5.3 takes "the difference between the root-mean-square error and the
    correlation coefficient"; the RMSE is divided by ``scale`` (the radial clearance) so
    that the two terms are both dimensionless (our reading). Lower is better; -1 is a
    perfect fit.

    Parameters
    ----------
    fitted : ndarray (n,) or (n, S)
        Fitted values, m; a column per candidate.
    measured : ndarray (n,)
        Measured values, m.
    scale : float
        Length the RMSE is divided by, m.

    Returns
    -------
    ndarray () or (S,)
        The objective of each candidate.
    """
    fitted = np.asarray(fitted, dtype=float)
    measured = np.asarray(measured, dtype=float)
    target = measured.reshape((-1,) + (1,) * (fitted.ndim - 1))
    error = np.sqrt(np.mean((fitted - target) ** 2, axis=0)) / scale
    spread = fitted.std(axis=0) * measured.std()
    covariance = np.mean((fitted - fitted.mean(axis=0)) * (target - measured.mean()), axis=0)
    with np.errstate(divide="ignore", invalid="ignore"):
        correlation = np.where(spread > 0, covariance / np.where(spread > 0, spread, 1.0), 0.0)
    return error - correlation


def model_line(
    orbits: Sequence[SectionOrbit],
    shape_z: np.ndarray,
    shape: np.ndarray,
    clearance: float,
    length: float,
    scale_bounds: tuple[float, float] = (0.0, 3.0),
    seed: int = 0,
) -> CentreLine:
    """Centre line with the shaft model's bending shape fitted to the sections (seed 001 Sect. 5.3).

    The mean centre of each section over the block is matched by
    ``e(z) = b0 + b1 (z - L/2) + a w(z)`` in each plane, ``w`` the model's shape, with
    ``(b0, b1, a)`` per plane found by :func:`scipy.optimize.differential_evolution`
    minimising :func:`seed_objective` over both planes, inside bounds: ``|b0| <= 1.5 c``,
    ``|b1| <= 3 c / L``, ``a`` in ``scale_bounds`` vertically (the shaft bends the way the
    model says, by up to the given factor) and in ``[-max, max]`` horizontally (the model,
    loaded by gravity, gives no horizontal shape: the vertical one stands for it). The
    motion about the mean is a rigid-body offset and tilt fitted to the section
    deviations at every sample by least squares.

    Parameters
    ----------
    orbits : sequence of SectionOrbit
        At least three sections over the same samples.
    shape_z, shape : ndarray
        The bending shape (:func:`model_shape`) at stations from the loaded end, m.
    clearance, length : float
        Radial clearance and bearing length, m (bounds and the objective's scale).
    scale_bounds : (float, float)
        Bounds of the vertical scale of the shape.
    seed : int
        Seed of the optimiser (the result is then repeatable).
    """
    from scipy.optimize import differential_evolution

    # Three coefficients a plane: two sections leave the fit undetermined (use least squares).
    positions, ey, ez, corrections = _section_centres(orbits, minimum=3)
    shape_z = np.asarray(shape_z, dtype=float)
    shape = np.asarray(shape, dtype=float)
    if shape_z.shape != shape.shape or shape.ndim != 1 or shape.size < 2 or np.any(np.diff(shape_z) <= 0):
        raise InputError("shape_z", shape_z.size, "m", "increasing stations with one shape value each")
    low, high = float(scale_bounds[0]), float(scale_bounds[1])
    if not (np.isfinite(low) and np.isfinite(high) and low < high):
        raise InputError("scale_bounds", [low, high], "", "finite (low, high) with low < high")
    basis = Basis(0.5 * length, 1, shape_z, shape)
    values = basis.values(positions)  # (3, n)
    mean = np.concatenate([ey.mean(axis=0), ez.mean(axis=0)])
    reach = max(abs(low), abs(high))
    bounds = [
        (-1.5 * clearance, 1.5 * clearance),
        (-3 * clearance / length, 3 * clearance / length),
        (low, high),
        (-1.5 * clearance, 1.5 * clearance),
        (-3 * clearance / length, 3 * clearance / length),
        (-reach, reach),
    ]

    def objective(x: np.ndarray) -> np.ndarray:
        # x is (6,) or (6, S): a whole population per call (vectorised differential evolution).
        fitted = np.concatenate([values.T @ x[:3], values.T @ x[3:]])
        return seed_objective(fitted, mean, clearance)

    result = differential_evolution(
        objective, bounds, seed=seed, tol=1e-10, maxiter=2000, polish=True, vectorized=True, updating="deferred"
    )
    static_y, static_z = result.x[:3], result.x[3:]
    # Motion about the mean: offset and tilt of a rigid journal at every sample.
    rigid = np.linalg.pinv(values[:2].T)  # (2, n)
    moving_y = (ey - ey.mean(axis=0)) @ rigid.T
    moving_z = (ez - ez.mean(axis=0)) @ rigid.T
    samples = ey.shape[0]
    coefficients_y = np.tile(static_y, (samples, 1))
    coefficients_z = np.tile(static_z, (samples, 1))
    coefficients_y[:, :2] += moving_y
    coefficients_z[:, :2] += moving_z
    return CentreLine(basis, basis, coefficients_y, coefficients_z, positions, corrections, float(result.fun))


def film_map(line: CentreLine, layout: ProbeLayout, theta: np.ndarray, z: np.ndarray) -> np.ndarray:
    """Full-bearing film h(theta, z, t) from a centre line (seed 001 Eq. 9, exact form M1), m.

    Returns
    -------
    ndarray (N, nz, nt)
        Film at every sample, station ``z`` (m from the loaded end) and angle ``theta`` (rad).
    """
    ey, ez = line.at(z)
    return film_between_circles(ey, ez, np.asarray(theta, dtype=float), layout, line.correction_at(z)[None, :])


def min_film_along(line: CentreLine, layout: ProbeLayout, z: np.ndarray) -> np.ndarray:
    """Smallest film round the bore at each station, ``c + k - |e(z)|`` (exact for circles), m, (N, nz)."""
    ey, ez = line.at(z)
    return layout.radial_clearance + line.correction_at(z)[None, :] - np.hypot(ey, ez)
