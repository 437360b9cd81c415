"""Jack-up test: the jack load-lift curve near a bearing, its lift-off point, the
correction factor from jack load to bearing reaction, and the inverse from a measured curve.

While the bearing is in contact, the jack load P relieves it: R(P) = R0 - C P. At lift-off
R = 0, so the bearing reaction before jacking is R0 = C P_lift-off; C is the correction
factor (close to 1 when the jack sits at the bearing, less when it stands off). After
lift-off the shaft hangs on the jack and the lift grows faster with load; a measured curve
shows this knee, whose load gives the reaction.
"""

from __future__ import annotations

from dataclasses import dataclass, replace

import numpy as np
from scipy.optimize import brentq, minimize_scalar

from shaftline.errors import InputError
from shaftline.shaft.alignment import AlignmentModel
from shaftline.shaft.model import Condition, PointLoad, ShaftLine


@dataclass(frozen=True, eq=False)
class JackUpCurve:
    """Modelled jack-up test.

    Attributes
    ----------
    bearing : str
    jack_x : float
        m.
    loads : ndarray
        Jack loads, N (upwards).
    lifts : ndarray
        Shaft lift at the jack, m.
    reactions : ndarray
        Bearing reaction at each load, N.
    reaction_before : float
        Bearing reaction without the jack, N.
    liftoff_load : float
        Jack load at which the bearing unloads, N.
    correction_factor : float
        reaction_before / liftoff_load.
    """

    bearing: str
    jack_x: float
    loads: np.ndarray
    lifts: np.ndarray
    reactions: np.ndarray
    reaction_before: float
    liftoff_load: float
    correction_factor: float


def jack_up(
    line: ShaftLine,
    bearing: str,
    jack_x: float,
    condition: Condition | None = None,
    points: int = 41,
    max_load_factor: float = 1.3,
) -> JackUpCurve:
    """Model the jack-up of ``bearing`` with a jack at ``jack_x``, up to ``max_load_factor``
    times the lift-off load (further on, other bearings unload and the curve has more knees;
    a test stops soon after lift-off, and the two-line fit assumes it did)."""
    names = [b.name for b in line.bearings]
    if bearing not in names:
        raise InputError("bearing", bearing, "", "the name of a bearing: " + ", ".join(names))
    if not 0.0 <= jack_x <= line.length:
        raise InputError("jack_x", jack_x, "m", f"on the shaft, [0, {line.length:.4g}]")
    condition = condition or Condition("jack-up")
    # A zero load at the jack puts a node there.
    with_jack = replace(line, point_loads=line.point_loads + (PointLoad(jack_x, name="jack"),))
    model = AlignmentModel(with_jack)
    node = int(model.mesh.node_at(jack_x))

    def state(load: float) -> tuple[float, float]:
        loaded = replace(condition, loads=condition.loads + (PointLoad(jack_x, force_y=load, name="jack"),))
        result = model.solve_condition(loaded)
        return result.bearing(bearing).reaction_y, float(result.deflection_y[node])

    before, rest = state(0.0)
    if before <= 0.0:
        raise InputError("bearing", bearing, "", "a bearing that carries load before jacking")
    # Relief per unit jack load while the contact state holds, then a bracket checked with the
    # full one-sided model (other supports may unload first).
    small = 1e-6 * before
    relief = (before - state(small)[0]) / small
    if relief <= 0.0:
        raise InputError("jack_x", jack_x, "m", f"a jack position that relieves {bearing}")
    guess = before / relief
    low, high = 0.0, guess * (1 + 1e-6)
    try:
        while state(high)[0] > 0.0:
            low, high = high, high * 1.2
            if high > 1e3 * guess:
                raise InputError("jack_x", jack_x, "m", f"a jack position that can unload {bearing}")
    except InputError as error:
        if "tips over" not in str(error):
            raise
        raise InputError("jack_x", jack_x, "m", f"a jack that lifts {bearing} before the line tips") from None
    # The reaction stays at zero once lifted: aim at a tiny positive one for a unique crossing.
    liftoff = brentq(lambda p: state(p)[0] - 1e-9 * before, low, high, xtol=1e-12 * guess, rtol=1e-12)
    rows = []
    for load in np.linspace(0.0, max_load_factor * liftoff, points):
        try:
            rows.append((load, *state(load)))
        except InputError:  # beyond this load the line would tip over the jack: stop the curve
            break
    values = np.array(rows)
    return JackUpCurve(
        bearing=bearing,
        jack_x=jack_x,
        loads=values[:, 0],
        lifts=values[:, 2] - rest,
        reactions=values[:, 1],
        reaction_before=before,
        liftoff_load=float(liftoff),
        correction_factor=float(before / liftoff),
    )


@dataclass(frozen=True)
class JackUpFit:
    """Bilinear fit of a measured jack-up curve.

    Attributes
    ----------
    knee_load : float
        Jack load at the change of slope (lift-off), N.
    slopes : tuple of float
        Lift per load before and after the knee, m/N.
    reaction : float
        Bearing reaction: correction factor times knee load, N.
    residual : float
        Root-mean-square misfit of the lifts, m.
    """

    knee_load: float
    slopes: tuple[float, float]
    reaction: float
    residual: float


def reaction_from_jack_curve(loads: np.ndarray, lifts: np.ndarray, correction_factor: float = 1.0) -> JackUpFit:
    """Bearing reaction from a measured (load, lift) curve by a continuous two-line fit.

    The knee is found by a bounded one-dimensional search; for each trial knee the two
    lines are a linear least-squares fit (continuous at the knee).
    """
    loads = np.asarray(loads, dtype=float)
    lifts = np.asarray(lifts, dtype=float)
    if loads.size < 6:
        raise InputError("loads", loads.size, "points", "at least 6 (load, lift) pairs")
    if lifts.size != loads.size:
        raise InputError("lifts", lifts.size, "points", f"one lift per load ({loads.size})")
    for name, values in (("loads", loads), ("lifts", lifts)):
        if not np.all(np.isfinite(values)):
            raise InputError(name, "NaN", "", "finite values")
    if np.any(np.diff(loads) <= 0):
        raise InputError("loads", "not increasing", "N", "loads rising from row to row")
    if not 0.0 < correction_factor < 10.0:
        raise InputError("correction_factor", correction_factor, "", "in (0, 10)")

    def fit(knee: float) -> tuple[float, np.ndarray]:
        design = np.column_stack([np.ones_like(loads), loads, np.maximum(loads - knee, 0.0)])
        coefficients, *_ = np.linalg.lstsq(design, lifts, rcond=None)
        misfit = lifts - design @ coefficients
        return float(np.sqrt(np.mean(misfit**2))), coefficients

    span = loads[-1] - loads[0]
    best = minimize_scalar(
        lambda k: fit(k)[0], bounds=(loads[1], loads[-2]), method="bounded", options={"xatol": 1e-9 * span}
    )
    # Refine against a grid in case the bounded search stopped in a local dip.
    grid = np.linspace(loads[1], loads[-2], 200)
    knee = min([best.x, *grid], key=lambda k: fit(k)[0])
    residual, coefficients = fit(knee)
    return JackUpFit(
        knee_load=float(knee),
        slopes=(float(coefficients[1]), float(coefficients[1] + coefficients[2])),
        reaction=float(correction_factor * knee),
        residual=residual,
    )
