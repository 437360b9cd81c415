"""Fretting motion of the blade carrier (seed 000 Sect. 4.6-4.8, Eq. 4.20-4.30).

    (I_blade + I_water) phi'' = M_sp(t) - Q_fr - M_hyd

M_sp(t) and the Coulomb friction torque Q_c(t) follow the blade's position in the wake
(tables over a revolution, periodic, any spacing). Friction is either LuGre (Eq. 4.13-4.15,
parameters of Table 4.2 rescaled to the Coulomb torque) or the finite-slope static law of
Eq. 4.8. The hydraulic reaction is the oil spring behind the yoke acting through the pin:
yoke travel r_pin (sin phi - sin phi_0) less half the backlash on either side (dead zone),
force k_oil times that, moment force * r_pin cos phi (Eq. 4.25-4.27).

The equations of motion (right-hand side and analytic Jacobian) are written once, compiled,
in :mod:`shaftline.cpp._carrier`; every integrator uses them. The system is stiff
(sigma_0 = 5e10 N m/rad against a blade inertia of the order of 10^3 kg m^2): the methods of
:data:`METHODS` are L-stable, the default TR-BDF2 (second order, fixed step), backward Euler
(first order, the method before it) and scipy's Radau (adaptive, the reference). By default
the integration stops once the motion is periodic (:func:`simulate_carrier`). numba and
scipy are imported only when integrating, so that reading a case (which takes defaults from
:class:`CarrierModel`) stays fast.
"""

from __future__ import annotations

import warnings
from collections.abc import Callable
from dataclasses import dataclass, replace
from time import perf_counter
from typing import TYPE_CHECKING, Any, Literal

import numpy as np

from shaftline.errors import InputError, SolverFailure, require_positive

if TYPE_CHECKING:
    from shaftline.cpp._carrier import CarrierParameters

#: Wall time, s, that one compiled chunk of the integration aims at. Python
#: handles Ctrl-C (and reports progress) only between chunks, so this is how long an interrupt
#: waits; 0.1 s leaves room for steps ten times slower than those the chunk size was measured
#: on before Ctrl-C takes more than a second.
CHUNK_SECONDS = 0.1

#: Steps of the first chunk, before a chunk's duration is known (about 2 ms at ~1 us a step).
FIRST_CHUNK_STEPS = 2048

MethodName = Literal["trbdf2", "backward_euler", "radau"]


@dataclass(frozen=True)
class Method:
    """An integration method of the carrier motion.

    Attributes
    ----------
    code : int or None
        Its number in the compiled kernel (:func:`shaftline.cpp._carrier.advance`); None for
        scipy's Radau.
    order : int
        Order of accuracy in the time step.
    steps_per_revolution : int or None
        Default fixed steps per revolution; None for the adaptive Radau.
    description : str
    """

    code: int | None
    order: int
    steps_per_revolution: int | None
    description: str


#: The integration methods by name (as scipy's ``solve_ivp`` names its methods). The step
#: defaults cost about the same a revolution: TR-BDF2 at 2880 steps is 2.8e-4 from the
#: converged amplitude in the benchmark case, backward Euler at 7200 steps 1.5e-2
#: (docs/validation.md).
METHODS: dict[str, Method] = {
    "trbdf2": Method(1, 2, 2880, "TR-BDF2, second order, L-stable, fixed step (compiled)"),
    "backward_euler": Method(0, 1, 7200, "backward Euler, first order, L-stable, fixed step (compiled)"),
    "radau": Method(None, 5, None, "scipy's Radau IIA, adaptive, rtol 1e-6 (reference, slower)"),
}

#: The default method.
DEFAULT_METHOD: MethodName = "trbdf2"

#: Default periodicity tolerance: the motion is taken as periodic when the rotation and the
#: rotation rate over the last revolutions repeat those before within this share of their
#: peak-to-peak (:func:`shaftline.cpp._carrier.periodic_change`). It is far below the time
#: step's error of the amplitude (about 3e-4 at the default step), so stopping there changes
#: the amplitude by less than the integration's own error.
PERIODIC_TOLERANCE = 1e-6

#: Longest period looked for, revolutions. With backlash the motion can settle into a cycle of
#: several revolutions (3 and 6 in the tests and the example's study); beyond this it is
#: treated as not periodic and integrated for all the revolutions asked for.
LONGEST_PERIOD = 8


@dataclass(frozen=True, eq=False)
class CarrierModel:
    """Inputs of the blade-carrier motion (SI).

    Attributes
    ----------
    inertia : float
        Blade + carrier inertia about the spindle axis, kg m^2.
    water_inertia : float
        Entrained-water inertia, kg m^2.
    speed : float
        Shaft speed, rad/s.
    angle : ndarray
        Blade angles of the tables, rad (one revolution): strictly increasing, spanning less
        than 2 pi, any spacing.
    spindle_torque, coulomb_torque : ndarray
        M_sp and Q_c at those angles, N m (Q_c > 0).
    oil_stiffness : float
        k_oil, N/m.
    pin_radius : float
        Pin eccentricity r_pin (e of Eq. 3.38), m.
    pitch_angle : float
        phi_0, rad.
    backlash : float
        Total free play in the pin-slot-yoke chain, m (dead zone of the spring).
    bearing_radius : float
        Radius at which fretting amplitudes are reported, m.
    friction : str
        ``"lugre"`` or ``"static"`` (Eq. 4.8).
    stiffness, damping : float
        LuGre sigma_0 (N m/rad) and sigma_1 (N m s/rad), Table 4.2.
    static_ratio : float
        F_s / F_c (1.1).
    stribeck_velocity : float
        v_s, rad/s (0.002).
    threshold_velocity : float
        v_th of the static law, rad/s (1e-4). The seed gives no number. Below Q_c the law
        creeps at w = v_th |M| / Q_c <= v_th; in the design case the seed reports about
        10 um of creep with Eq. 4.8 over the 145 deg from 390 to 535 deg (Sect. 4.6.3), which
        at 95 rpm (Sect. 2.7, Eq. 4.35) and a 0.4 m bearing radius (v_s of Table 4.1 over
        that of Table 4.2) needs v_th >= 10 um / (0.4 m * 0.254 s) = 1e-4 rad/s; 1e-5 rad/s
        would creep at most 1 um. It stays well below v_s (0.002 rad/s) and the gross-sliding
        rates (~1e-3 rad/s), so Eq. 4.8 is Coulomb friction wherever the carrier slides.
    holding_moment : float
        Mean hydraulic moment on the blade from the holding pressure, N m (Eq. 4.24; the
        seed takes it zero, which balances the mean spindle torque).
    """

    inertia: float
    water_inertia: float
    speed: float
    angle: np.ndarray
    spindle_torque: np.ndarray
    coulomb_torque: np.ndarray
    oil_stiffness: float
    pin_radius: float
    pitch_angle: float
    backlash: float = 0.0
    bearing_radius: float = 0.392
    friction: str = "lugre"
    stiffness: float = 5e10
    damping: float = 1e8
    static_ratio: float = 1.1
    stribeck_velocity: float = 0.002
    threshold_velocity: float = 1e-4
    holding_moment: float = 0.0

    def __post_init__(self) -> None:
        for name in (
            "inertia",
            "speed",
            "oil_stiffness",
            "pin_radius",
            "bearing_radius",
            "stiffness",
            "stribeck_velocity",
            "threshold_velocity",
        ):
            require_positive(name, getattr(self, name))
        for name, unit in (("water_inertia", "kg m^2"), ("backlash", "m"), ("damping", "N m s/rad")):
            if not getattr(self, name) >= 0:
                raise InputError(name, getattr(self, name), unit, ">= 0")
        if not self.static_ratio >= 1:
            raise InputError("static_ratio", self.static_ratio, "", ">= 1 (F_s >= F_c)")
        for name in ("pitch_angle", "holding_moment"):
            if not np.isfinite(getattr(self, name)):
                raise InputError(name, getattr(self, name), "", "a finite number")
        if self.friction not in ("lugre", "static"):
            raise InputError("friction", self.friction, "", "lugre or static")
        angle = np.asarray(self.angle, dtype=float)
        if angle.ndim != 1 or angle.size < 2 or not np.all(np.isfinite(angle)):
            raise InputError("angle", str(angle.shape), "rad", "at least two finite blade angles")
        if not (np.all(np.diff(angle) > 0) and angle[-1] - angle[0] < 2 * np.pi):
            raise InputError("angle", "not increasing", "rad", "strictly increasing, spanning less than 2 pi")
        object.__setattr__(self, "angle", angle)
        for name in ("spindle_torque", "coulomb_torque"):
            values = np.asarray(getattr(self, name), dtype=float)
            if values.shape != angle.shape:
                raise InputError(name, str(values.shape), "", f"one value per angle, shape {angle.shape}")
            if not np.all(np.isfinite(values)):
                raise InputError(name, "NaN", "N m", "finite values")
            object.__setattr__(self, name, values)
        if np.any(self.coulomb_torque <= 0):
            raise InputError("coulomb_torque", float(np.min(self.coulomb_torque)), "N m", "> 0")


@dataclass(frozen=True, eq=False)
class CarrierMotion:
    """Motion over the simulated revolutions.

    Attributes
    ----------
    time, blade_angle, rotation, rotation_rate, hydraulic_force : ndarray
        s, rad (blade position), rad (carrier rotation from the set pitch), rad/s, N.
    revolutions : int
    amplitude : ndarray
        Peak-to-peak carrier displacement at the bearing radius per revolution, m.
    sliding_per_revolution : ndarray
        Sliding distance at the bearing radius per revolution, m.
    force_fluctuation : ndarray
        Peak-to-peak oil-spring (yoke) force per revolution, N; divided by the yoke area it is
        the pressure fluctuation a pressure signal would show (Sect. 4.8).
    method : str
        The integration method (a key of :data:`METHODS`).
    requested_revolutions : int
        Revolutions asked for; ``revolutions`` is fewer when the integration stopped at the
        periodic state.
    periodic_tolerance : float
        The periodicity tolerance the motion was judged by.
    period : int
        Revolutions after which the motion repeats: the smallest m <= :data:`LONGEST_PERIOD`
        with ``periodic_change`` within the tolerance, or, when there is none, the m closest
        to it; 0 with fewer than two revolutions.
    periodic_change : float or None
        How far the last ``period`` revolutions are from repeating the ``period`` before them:
        the largest change of the rotation or the rotation rate at the same shaft angle over
        its peak-to-peak (:func:`shaftline.cpp._carrier.periodic_change`); None with fewer
        than two revolutions.
    periodic : bool
        Whether the motion is periodic: ``periodic_change`` <= ``periodic_tolerance``.
    """

    time: np.ndarray
    blade_angle: np.ndarray
    rotation: np.ndarray
    rotation_rate: np.ndarray
    hydraulic_force: np.ndarray
    revolutions: int
    amplitude: np.ndarray
    sliding_per_revolution: np.ndarray
    force_fluctuation: np.ndarray
    method: str = DEFAULT_METHOD
    requested_revolutions: int = 0
    periodic_tolerance: float = PERIODIC_TOLERANCE
    period: int = 0
    periodic_change: float | None = None

    @property
    def periodic(self) -> bool:
        """Whether the motion repeats to the tolerance (see ``periodic_change``)."""
        return self.periodic_change is not None and self.periodic_change <= self.periodic_tolerance


def simulate_carrier(
    model: CarrierModel,
    revolutions: int = 10,
    samples_per_revolution: int = 720,
    steps_per_revolution: int | None = None,
    method: str = DEFAULT_METHOD,
    progress: Callable[[float], None] | None = None,
    stop_when_periodic: bool = True,
    periodic_tolerance: float = PERIODIC_TOLERANCE,
) -> CarrierMotion:
    """Integrate the carrier motion from rest over at most ``revolutions`` shaft turns.

    The motion is periodic when the rotation and the rotation rate over the last m
    revolutions repeat those over the m before at the same shaft angles, to within
    ``periodic_tolerance`` of their peak-to-peak (m from 1 to :data:`LONGEST_PERIOD`, the
    smallest; docs/theory.md). With ``stop_when_periodic`` (default) the integration stops at
    the end of the first revolution where it is; the result says whether it is, and the
    period, either way.

    The compiled integration runs in chunks of about :data:`CHUNK_SECONDS` (0.1 s), carrying
    the state from one to the next, so that Ctrl-C (``KeyboardInterrupt``) stops a long run
    within a fraction of a second and ``progress`` hears how far it is; the chunks do not
    change the result, which is that of one uninterrupted integration bit for bit.

    Parameters
    ----------
    model : CarrierModel
    revolutions : int
        Shaft revolutions, >= 1 (at most, when stopping at the periodic state).
    samples_per_revolution : int
        Output samples per revolution (the amplitude, sliding and periodicity are taken from
        them).
    steps_per_revolution : int, optional
        Fixed steps per revolution of the compiled methods, a multiple of
        ``samples_per_revolution``; by default the method's (:data:`METHODS`: 2880 for
        TR-BDF2, 7200 for backward Euler). TR-BDF2 is second order: halving the step quarters
        the error (0.6-4e-4 of the amplitude at 2880 steps in the tests against Radau).
    method : str
        A key of :data:`METHODS`: ``"trbdf2"`` (default), ``"backward_euler"`` or
        ``"radau"``. All integrate the same compiled equations of motion.
    progress : callable, optional
        Called with the share of the requested time done, in (0, 1], after each chunk
        (compiled) or every 1 % of the time (Radau), and with 1.0 at the end.
    stop_when_periodic : bool
        Stop at the end of the first revolution at which the motion is periodic.
    periodic_tolerance : float
        Periodicity tolerance, in (0, 1).
    """
    if method not in METHODS:
        raise InputError("method", method, "", ", ".join(METHODS))
    chosen = METHODS[method]
    steps = chosen.steps_per_revolution if steps_per_revolution is None else steps_per_revolution
    for name, value in (
        ("revolutions", revolutions),
        ("samples_per_revolution", samples_per_revolution),
        ("steps_per_revolution", steps),
    ):
        if value is not None and (isinstance(value, bool) or int(value) != value or value < 1):
            raise InputError(name, value, "", "a positive integer")
    if not 0 < periodic_tolerance < 1:
        raise InputError("periodic_tolerance", periodic_tolerance, "", "> 0 and < 1")
    stop = _Stop(float(periodic_tolerance) if stop_when_periodic else 0.0, float(periodic_tolerance))
    revolutions, samples = int(revolutions), int(samples_per_revolution)
    if chosen.code is None or steps is None:
        return _simulate_radau(model, revolutions, samples, progress, stop)
    if steps % samples:
        raise InputError("steps_per_revolution", steps, "", f"a multiple of {samples} samples")
    return _simulate_compiled(model, method, revolutions, samples, int(steps), progress, stop)


@dataclass(frozen=True)
class _Stop:
    """When to stop: ``at`` the tolerance (0: never), and the tolerance the result is judged by."""

    at: float
    tolerance: float


def _parameters(model: CarrierModel) -> CarrierParameters:
    from shaftline.cpp._carrier import CarrierParameters, close_table

    angle, spindle, coulomb = close_table(model.angle, model.spindle_torque, model.coulomb_torque)
    return CarrierParameters(
        angle,
        spindle,
        coulomb,
        float(model.speed),
        float(model.inertia + model.water_inertia),
        float(model.oil_stiffness),
        float(model.pin_radius),
        float(model.pitch_angle),
        0.5 * float(model.backlash),
        float(model.holding_moment),
        model.friction == "lugre",
        float(model.stiffness),
        float(model.damping),
        float(model.static_ratio),
        float(model.stribeck_velocity),
        float(model.threshold_velocity),
    )


def _simulate_compiled(
    model: CarrierModel,
    method: str,
    revolutions: int,
    samples: int,
    steps: int,
    progress: Callable[[float], None] | None,
    stop: _Stop,
) -> CarrierMotion:
    period = 2 * np.pi / model.speed
    step = period / steps
    every = steps // samples
    code = METHODS[method].code
    assert code is not None
    phi, w, force, unconverged = _integrate_in_chunks(
        _parameters(model), code, step, revolutions * steps, every, steps, stop.at, progress
    )
    if unconverged:
        # none in the tested cases; say so rather than return a silently degraded motion
        warnings.warn(
            f"carrier motion: Newton did not converge in {unconverged} implicit stages of "
            f"{phi.size // samples * steps} steps (accepted as they are); a larger steps_per_revolution "
            "or method='radau' is safer",
            RuntimeWarning,
            stacklevel=3,
        )
    time = np.arange(phi.size) * step * every
    return _motion(model, time, phi, w, force, revolutions, samples, method, stop)


def _integrate_in_chunks(
    params: CarrierParameters,
    method: int,
    step: float,
    steps: int,
    every: int,
    revolution: int,
    tolerance: float,
    progress: Callable[[float], None] | None,
    chunk_steps: int | None = None,
) -> tuple[np.ndarray, np.ndarray, np.ndarray, int]:
    """Integrate from rest over at most ``steps`` steps of ``step`` s with ``method`` (a
    kernel number), in compiled chunks, stopping at the periodic state if ``tolerance`` > 0.

    Returns what :func:`shaftline.cpp._carrier.integrate` returns (samples every ``every``
    steps up to the last step taken, and the count of unconverged stages), with the same bits.
    A chunk holds ``chunk_steps`` steps when given (tests), else as many as take about
    :data:`CHUNK_SECONDS`, judged from the last chunk; the size may at most quadruple from one
    chunk to the next, so that cheap steps at the start (the carrier at rest) do not size a
    chunk for harder ones.
    """
    from shaftline.cpp._carrier import advance, at_rest

    samples = steps // every + 1
    phi, w, force = np.zeros(samples), np.zeros(samples), np.zeros(samples)
    carried = at_rest(params)
    unconverged = 0
    done = 0
    chunk = chunk_steps or FIRST_CHUNK_STEPS
    while done < steps:
        end = min(steps, done + chunk)
        started = perf_counter()
        failed, reached, period = advance(
            params, method, step, carried, done, end, every, revolution, tolerance, LONGEST_PERIOD, phi, w, force
        )
        elapsed = perf_counter() - started
        unconverged += failed
        done = reached
        if progress is not None:
            progress(1.0 if period else done / steps)
        if period:
            break
        if chunk_steps is None:
            chunk = max(1, min(4 * chunk, int(chunk * CHUNK_SECONDS / max(elapsed, 1e-6))))
    used = done // every + 1
    return phi[:used], w[:used], force[:used], unconverged


def _simulate_radau(
    model: CarrierModel,
    revolutions: int,
    samples: int,
    progress: Callable[[float], None] | None,
    stop: _Stop,
) -> CarrierMotion:
    """scipy's Radau, one revolution at a time (so that it can stop at the periodic state)."""
    from scipy.integrate import solve_ivp

    from shaftline.cpp._carrier import jacobian, motion_period, rhs, spring_force

    params = _parameters(model)
    lugre = model.friction == "lugre"
    period = 2 * np.pi / model.speed
    end = revolutions * period
    next_report = 0.01 * end

    def right_hand_side(t: float, y: np.ndarray) -> np.ndarray:
        # solve_ivp has no progress hook; its right-hand side sees the time. Radau's loop is
        # Python, so Ctrl-C needs nothing here.
        nonlocal next_report
        if progress is not None and t >= next_report:
            progress(min(t / end, 1.0))
            next_report = t + 0.01 * end
        return rhs(t, y, params)

    y = np.zeros(3 if lugre else 2)
    times, phis, ws = [np.zeros(1)], [np.zeros(1)], [np.zeros(1)]
    for k in range(revolutions):
        t_eval = np.linspace(k * period, (k + 1) * period, samples + 1)
        solution = solve_ivp(
            right_hand_side,
            (t_eval[0], t_eval[-1]),
            y,
            method="Radau",
            jac=lambda t, y: jacobian(t, y, params),
            t_eval=t_eval,
            rtol=1e-6,
            atol=[1e-10, 1e-8] + ([1e-12] if lugre else []),
            max_step=period / 90,
        )
        if solution.status != 0:  # pragma: no cover - Radau reports failure for pathological input
            raise SolverFailure(f"carrier motion integration failed: {solution.message}")
        y = solution.y[:, -1]
        times.append(solution.t[1:])
        phis.append(solution.y[0, 1:])
        ws.append(solution.y[1, 1:])
        if stop.at and motion_period(
            np.concatenate(phis), np.concatenate(ws), (k + 1) * samples, samples, stop.at, LONGEST_PERIOD
        ):
            break
    phi = np.ascontiguousarray(np.concatenate(phis))
    force = spring_force(phi, params)
    if progress is not None:
        progress(1.0)
    return _motion(model, np.concatenate(times), phi, np.concatenate(ws), force, revolutions, samples, "radau", stop)


def _motion(
    model: CarrierModel,
    time: np.ndarray,
    phi: np.ndarray,
    w: np.ndarray,
    force: np.ndarray,
    requested: int,
    per: int,
    method: str,
    stop: _Stop,
) -> CarrierMotion:
    from shaftline.cpp._carrier import periodic_change

    revolutions = (phi.size - 1) // per
    amplitude, sliding, fluctuation = [], [], []
    for k in range(revolutions):
        part = slice(k * per, (k + 1) * per + 1)
        amplitude.append(model.bearing_radius * np.ptp(phi[part]))
        sliding.append(model.bearing_radius * np.abs(np.diff(phi[part])).sum())
        fluctuation.append(np.ptp(force[part]))
    # the period: the smallest one within the tolerance, else the one closest to it
    period, change = 0, None
    end = revolutions * per
    for m in range(1, min(LONGEST_PERIOD, revolutions // 2) + 1):
        c = max(periodic_change(phi, end, per, m, np.inf), periodic_change(w, end, per, m, np.inf))
        if change is None or c < change:
            period, change = m, float(c)
        if c <= stop.tolerance:
            break
    return CarrierMotion(
        time,
        (model.speed * time) % (2 * np.pi),
        phi,
        w,
        force,
        revolutions,
        np.array(amplitude),
        np.array(sliding),
        np.array(fluctuation),
        method,
        requested,
        stop.tolerance,
        period,
        change,
    )


#: Parameters a study may vary: model fields, or "spindle_scale" (multiplies the spindle torque,
#: as seed Sect. 4.7.2 does with 0.8 and 1.2).
STUDY_PARAMETERS = ("holding_moment", "spindle_scale", "backlash", "friction", "oil_stiffness", "water_inertia")


def parameter_study(
    model: CarrierModel,
    parameter: str,
    values: list[Any],
    revolutions: int = 10,
    progress: Callable[[float], None] | None = None,
    method: str = DEFAULT_METHOD,
    stop_when_periodic: bool = True,
    periodic_tolerance: float = PERIODIC_TOLERANCE,
) -> list[CarrierMotion]:
    """Fretting motion for each value of one parameter (seed Sect. 4.7).

    Parameters
    ----------
    model : CarrierModel
        The base case.
    parameter : str
        One of :data:`STUDY_PARAMETERS`.
    values : list
        Values of the parameter, in the unit of the model field (SI; a factor for
        ``"spindle_scale"``, ``"lugre"``/``"static"`` for ``"friction"``).
    revolutions : int
        Revolutions simulated for each value (at most, when stopping at the periodic state).
    progress : callable, optional
        Called with the share of the whole study done, in (0, 1], as each motion advances
        (see :func:`simulate_carrier`).
    method, stop_when_periodic, periodic_tolerance
        As for :func:`simulate_carrier`.
    """
    if parameter not in STUDY_PARAMETERS:
        raise InputError("parameter", parameter, "", "one of " + ", ".join(STUDY_PARAMETERS))
    if not values:
        raise InputError("values", "[]", "", "at least one value")
    results = []
    for index, value in enumerate(values):
        if parameter == "spindle_scale":
            changed = replace(model, spindle_torque=float(value) * model.spindle_torque)
        else:
            changed = replace(model, **{parameter: value})
        results.append(
            simulate_carrier(
                changed,
                revolutions,
                method=method,
                progress=_share(progress, index, len(values)),
                stop_when_periodic=stop_when_periodic,
                periodic_tolerance=periodic_tolerance,
            )
        )
    return results


def _share(progress: Callable[[float], None] | None, index: int, count: int) -> Callable[[float], None] | None:
    """The progress of run ``index`` of ``count`` equal runs as a share of all of them."""
    if progress is None:
        return None
    report = progress
    return lambda fraction: report((index + fraction) / count)
