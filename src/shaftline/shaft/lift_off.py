"""Minimum speed for hydrodynamic operation: the lift-off curve of a line's film bearings.

Below some shaft speed a film bearing can no longer keep the journal off the bore: its
smallest film falls to the height of the surface roughness and the bearing runs in mixed
lubrication. :func:`minimum_speed` solves the line with its film bearings coupled
(:class:`~shaftline.shaft.coupled.CoupledAlignment`) at falling speeds, brackets the speed
at which the smallest film of any film bearing crosses a limit and narrows the bracket by
bisection (on the logarithm of the speed). The curve of every solution, smallest film
against speed per bearing, is the "lift-off" curve class-society tools draw
(:func:`shaftline.shaft.figures.lift_off_curve`).

The limit (:class:`FilmLimit`) is the larger of a film parameter (3 by default) times the
composite roughness ``sqrt(Rq_journal^2 + Rq_bore^2)`` (the film parameter of Hamrock &
Dowson, "Ball Bearing Lubrication", 1981, and Hamrock, Schmid & Jacobson, "Fundamentals of
Fluid Film Lubrication", 2nd ed. 2004, Ch. 1: full film above 3, partial lubrication
below) and a class value (e.g. the Bureau Veritas 30 um that seed 004 quotes). Ra is
turned into Rq with Rq = sqrt(pi/2) Ra = 1.25 Ra, the ratio of a Gaussian profile (ISO 4287).
"""

from __future__ import annotations

import math
from collections.abc import Callable, Sequence
from dataclasses import dataclass, field, replace
from typing import Literal

import numpy as np

from shaftline.errors import InputError, require_finite, require_positive
from shaftline.shaft.coupled import CoupledAlignment
from shaftline.shaft.film_supports import CoupledResult, CouplingOptions, FilmSupport
from shaftline.shaft.model import Condition, ShaftLine

__all__ = ["FilmLimit", "LiftOffResult", "minimum_speed"]

#: Rq / Ra of a Gaussian surface profile (ISO 4287): sqrt(pi / 2).
RQ_PER_RA = math.sqrt(math.pi / 2.0)


@dataclass(frozen=True)
class FilmLimit:
    """Smallest film for hydrodynamic operation.

    Attributes
    ----------
    journal_roughness, bore_roughness : float
        Surface roughness of the journal and of the bore, m, as ``roughness_parameter``.
        Defaults: a ground journal (Rq 1 um) in a bored white-metal liner (Rq 2 um), as the
        film bearing's own default composite roughness (2.2 um, :mod:`shaftline.film.study`).
    roughness_parameter : "Rq" or "Ra"
        Whether the roughnesses are root-mean-square (Rq) or arithmetic-mean (Ra)
        heights; Ra is converted with Rq = sqrt(pi/2) Ra = 1.25 Ra (Gaussian profile).
    film_parameter : float
        Smallest film over the composite roughness (3: full-film lubrication).
    class_value : float
        Smallest film a class rule or the designer asks for, m (0: none; the Bureau
        Veritas value seed 004 quotes is 30e-6).

    Examples
    --------
    >>> limit = FilmLimit(journal_roughness=0.8e-6, bore_roughness=1.6e-6, roughness_parameter="Ra")
    >>> round(limit.composite_roughness * 1e6, 2), round(limit.value * 1e6, 2)
    (2.24, 6.73)
    >>> FilmLimit(class_value=30e-6).value
    3e-05
    """

    journal_roughness: float = 1.0e-6
    bore_roughness: float = 2.0e-6
    roughness_parameter: Literal["Rq", "Ra"] = "Rq"
    film_parameter: float = 3.0
    class_value: float = 0.0

    def __post_init__(self) -> None:
        for name in ("journal_roughness", "bore_roughness"):
            value = require_finite(name, getattr(self, name), "m")
            if not 0.0 <= value <= 1e-4:
                raise InputError(name, value, "m", "in [0, 1e-4] (a roughness in um written as m is outside)")
        if self.roughness_parameter not in ("Rq", "Ra"):
            raise InputError("roughness_parameter", self.roughness_parameter, "", "Rq or Ra")
        value = require_positive("film_parameter", self.film_parameter)
        if value > 20.0:
            raise InputError("film_parameter", value, "", "in (0, 20] (3: full film)")
        value = require_finite("class_value", self.class_value, "m")
        if not 0.0 <= value <= 1e-3:
            raise InputError("class_value", value, "m", "in [0, 1e-3]")
        if self.value <= 0.0:
            raise InputError("class_value", value, "m", "> 0 when both roughnesses are 0")

    @property
    def composite_roughness(self) -> float:
        """``sqrt(Rq_journal^2 + Rq_bore^2)``, m."""
        scale = RQ_PER_RA if self.roughness_parameter == "Ra" else 1.0
        return scale * math.hypot(self.journal_roughness, self.bore_roughness)

    @property
    def value(self) -> float:
        """The limit, m: the larger of the film parameter times the composite roughness and
        the class value."""
        return max(self.film_parameter * self.composite_roughness, self.class_value)


@dataclass(frozen=True, eq=False)
class LiftOffResult:
    """Minimum speed of a line's film bearings and their lift-off curve. SI units.

    Attributes
    ----------
    speed : float
        Lowest speed found at which every film bearing keeps its smallest film at or above
        the limit, rad/s (the upper end of the final bracket: on the safe side). ``nan``
        when the films are below the limit at the operating speed.
    bracket : (float, float)
        Speeds between which the smallest film crosses the limit, rad/s; ``(nan, top)``
        when it is below at the operating speed ``top``, ``(0, lowest)`` when it stays
        above down to the lowest speed tried.
    limit : float
        The film limit, m.
    governing : str
        The film bearing that reaches the limit (empty when none did).
    names : list of str
        The film bearings, in line order.
    speeds : ndarray (n,)
        Every speed solved, increasing, rad/s.
    min_film : ndarray (len(names), n)
        Smallest film of each bearing at those speeds, m (at the film floor where the
        bearing fell back to contact).
    contact : ndarray of bool (len(names), n)
        The bearing fell back to contact at the bore (no film could carry its share).
    converged : ndarray of bool (n,)
        The coupled solution converged.
    solutions : int
        Coupled solutions used.
    message : str
        Empty when the limit was bracketed within the tolerance; otherwise what happened.
    """

    speed: float
    bracket: tuple[float, float]
    limit: float
    governing: str
    names: list[str]
    speeds: np.ndarray = field(repr=False)
    min_film: np.ndarray = field(repr=False)
    contact: np.ndarray = field(repr=False)
    converged: np.ndarray = field(repr=False)
    solutions: int = 0
    message: str = ""


def _at_speed(films: Sequence[FilmSupport], speed: float) -> list[FilmSupport]:
    return [replace(f, problem=replace(f.problem, operating=replace(f.problem.operating, speed=speed))) for f in films]


def minimum_speed(
    line: ShaftLine,
    films: Sequence[FilmSupport],
    limit: FilmLimit | float | None = None,
    *,
    condition: Condition | None = None,
    options: CouplingOptions | None = None,
    lowest: float = 0.05,
    points: int = 8,
    tolerance: float = 0.01,
    progress: Callable[[int, float, float], None] | None = None,
) -> LiftOffResult:
    """Lowest shaft speed at which every film bearing of the line keeps the limit film.

    The speeds ``top * lowest**(k / (points - 1))``, ``k = 0 .. points - 1`` (``top`` the
    films' operating speed) are solved from the top down until the smallest film of any
    bearing is below the limit; the bracket then found is halved on the logarithm of the
    speed until its upper end is within ``tolerance`` of its lower end (relative).

    Parameters
    ----------
    line : ShaftLine
    films : sequence of FilmSupport
        The film bearings (:class:`~shaftline.shaft.coupled.CoupledAlignment`); they turn
        with the shaft, so each is solved at the swept speed (the first one's operating
        speed is the top of the sweep).
    limit : FilmLimit, float or None
        The film limit: a :class:`FilmLimit`, a value in m, or None for ``FilmLimit()``.
    condition : Condition, optional
        Default: the line's first.
    options : CouplingOptions, optional
    lowest : float
        Lowest speed of the sweep as a share of the operating speed, (0, 1).
    points : int
        Speeds of the sweep (>= 2), before the bisection.
    tolerance : float
        Relative width of the final bracket, (1e-6, 0.5).
    progress : callable, optional
        Called after each coupled solution with its number, the speed (rad/s) and the
        smallest film of all bearings (m).

    Returns
    -------
    LiftOffResult

    Raises
    ------
    InputError
        ``films`` empty; ``limit``, ``lowest``, ``points`` or ``tolerance`` out of range.
    """
    if not films:
        raise InputError("films", 0, "", "at least one film bearing")
    value, lowest, points, tolerance = _checked_sweep(limit, lowest, points, tolerance)
    top = films[0].problem.operating.speed
    names = [b.name for b in line.bearings if b.name in {f.bearing for f in films}]
    solutions = _SpeedSolutions(line, films, names, condition, options, progress)
    sweep = top * lowest ** (np.arange(points) / (points - 1))
    low, high, message = _bracket_limit(solutions, sweep, value, top)
    if not message:
        low, high = _narrow_bracket(solutions, low, high, value, tolerance)
    return _lift_off_result(solutions, low, high, value, message)


def _checked_sweep(
    limit: FilmLimit | float | None, lowest: float, points: int, tolerance: float
) -> tuple[float, float, int, float]:
    """The arguments of :func:`minimum_speed` that shape the sweep, checked.

    Returns
    -------
    value : float
        The film limit, m.
    lowest : float
        Lowest speed of the sweep, share of the operating speed.
    points : int
        Speeds of the sweep.
    tolerance : float
        Relative width of the final bracket.

    Raises
    ------
    InputError
        Any of them out of range.
    """
    if limit is None:
        limit = FilmLimit()
    if isinstance(limit, FilmLimit):
        value = limit.value
    else:
        value = require_positive("limit", limit, "m")
    lowest = require_finite("lowest", lowest)
    if not 0.0 < lowest < 1.0:
        raise InputError("lowest", lowest, "", "in (0, 1) of the operating speed")
    if not 2 <= int(points) <= 200:
        raise InputError("points", points, "", "an integer in [2, 200]")
    tolerance = require_finite("tolerance", tolerance)
    if not 1e-6 < tolerance < 0.5:
        raise InputError("tolerance", tolerance, "", "in (1e-6, 0.5)")
    return value, lowest, int(points), tolerance


@dataclass(eq=False)
class _SpeedSolutions:
    """The line's coupled solutions at the speeds tried, kept by speed (rad/s): each film
    bearing's smallest film (m) and contact flag, and the solutions later speeds start from."""

    line: ShaftLine
    films: Sequence[FilmSupport]
    names: list[str]
    condition: Condition | None
    options: CouplingOptions | None
    progress: Callable[[int, float, float], None] | None
    solved: dict[float, tuple[np.ndarray, np.ndarray, bool]] = field(default_factory=dict)
    starts: dict[float, CoupledResult] = field(default_factory=dict)

    def smallest(self, speed: float) -> float:
        """Smallest film of all bearings at ``speed`` (rad/s), m (minus infinity where one is
        in contact), started from the solved speed nearest to it."""
        start = self.starts[min(self.starts, key=lambda s: abs(math.log(s / speed)))] if self.starts else None
        result = CoupledAlignment(self.line, _at_speed(self.films, speed), self.options).solve(
            self.condition, initial=start
        )
        if not result.contact:
            self.starts[speed] = result
        hmin = np.array([result.film(n).state.min_film_thickness for n in self.names])
        contact = np.array([result.film(n).contact for n in self.names])
        self.solved[speed] = (hmin, contact, result.converged)
        if self.progress is not None:
            self.progress(len(self.solved), speed, float(hmin.min()))
        return -math.inf if contact.any() else float(hmin.min())


def _bracket_limit(solutions: _SpeedSolutions, sweep: np.ndarray, value: float, top: float) -> tuple[float, float, str]:
    """The sweep's speeds from the top down until a film is below ``value`` (m).

    Returns
    -------
    low, high : float
        The speeds (rad/s) between which the smallest film crosses the limit; ``(0,
        lowest)`` when it stays above down to the sweep's lowest speed, ``(nan, top)`` when
        it is below at the operating speed ``top``.
    message : str
        Empty when the limit was bracketed; otherwise which of the two ends it is past.
    """
    low, high = math.nan, math.nan
    previous = math.nan
    for speed in sweep:
        if solutions.smallest(float(speed)) < value:
            low, high = float(speed), previous
            break
        previous = float(speed)
    message = ""
    if math.isnan(low):
        low, high = 0.0, float(sweep[-1])
        message = (
            f"the films stay above the limit down to the lowest speed tried ({high * 30 / math.pi:.4g} rpm): "
            "lower `lowest`"
        )
    elif math.isnan(high):
        low, high = math.nan, top  # as documented: (nan, top)
        message = (
            f"a film is below the limit ({value * 1e6:.3g} µm) at the operating speed ({top * 30 / math.pi:.4g} rpm)"
        )
    return low, high, message


def _narrow_bracket(
    solutions: _SpeedSolutions, low: float, high: float, value: float, tolerance: float
) -> tuple[float, float]:
    """The bracket ``(low, high)`` (rad/s) halved on the logarithm of the speed until
    ``high`` is within ``tolerance`` (relative) of ``low``; the film is below ``value`` (m)
    at ``low`` and at or above it at ``high``."""
    while high > low * (1.0 + tolerance):
        middle = math.sqrt(low * high)
        if solutions.smallest(middle) < value:
            low = middle
        else:
            high = middle
    return low, high


def _lift_off_result(solutions: _SpeedSolutions, low: float, high: float, value: float, message: str) -> LiftOffResult:
    """The sweep's solutions as a :class:`LiftOffResult`: the bracket ``(low, high)``
    (rad/s), the limit ``value`` (m) and, when ``message`` is empty, the bearing whose film
    is below the limit at ``low``."""
    names, solved = solutions.names, solutions.solved
    speeds = np.array(sorted(solved))
    min_film = np.array([solved[s][0] for s in speeds]).T.reshape(len(names), speeds.size)
    contact = np.array([solved[s][1] for s in speeds]).T.reshape(len(names), speeds.size)
    converged = np.array([solved[s][2] for s in speeds])
    governing = ""
    if not message:
        hmin, touching, _ = solved[low]
        below = np.where(touching, -math.inf, hmin)
        governing = names[int(np.argmin(below))]
    return LiftOffResult(
        speed=math.nan if math.isnan(low) else high,
        bracket=(low, high),
        limit=value,
        governing=governing,
        names=names,
        speeds=speeds,
        min_film=min_film,
        contact=contact,
        converged=converged,
        solutions=len(solved),
        message=message,
    )
