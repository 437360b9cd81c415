"""The blade-carrier equations of motion, written once, and the fixed-step integrators.

State y = (phi, w) with the static law, (phi, w, z) with LuGre; phi the carrier rotation from
the set pitch (rad), w = phi' (rad/s), z the mean bristle deflection (rad). Seed 000
Eq. 4.20, 4.24-4.27, 4.29-4.30:

    phi' = w
    (I_blade + I_water) w' = M_sp(t) - M_hyd,mean - Q_fr - M_hyd,reaction(phi)
    z' = w - sigma_0 |w| z / g(w)                               (LuGre only, Eq. 4.13-4.14)

Q_fr = sigma_0 z + sigma_1 z' with g(w) = Q_c + (F_s/F_c - 1) Q_c exp(-(w/v_s)^2) (LuGre,
Table 4.2 scaled to the Coulomb torque), or Q_c clip(w / v_th, -1, 1) (Eq. 4.8). The friction
terms and their derivatives are the kernels of :mod:`shaftline.friction.kernels`, the same
code the public friction laws run. M_sp(t) and Q_c(t) are the load tables at the blade angle
psi = speed t, interpolated linearly with periodic wrap (any spacing). The oil spring acts
through the pin: yoke travel r_pin (sin(phi_0 + phi) - sin phi_0) less half the backlash on
either side (dead zone), force k_oil times that, moment force * r_pin cos(phi_0 + phi).

:func:`evaluate` is the model: the right-hand side and its analytic, exact Jacobian, together
(a Newton iteration needs both at one state). :func:`rhs` and :func:`jacobian` serve scipy's
Radau through thin Python wrappers; :func:`advance` (TR-BDF2 or backward Euler over a range
of steps) calls :func:`evaluate` inside the Newton loop of each implicit stage, and solves the
3 x 3 Newton system in closed form (:func:`_newton_correction`). :mod:`shaftline.cpp.motion`
calls :func:`advance` in chunks of about 0.1 s, carrying the state between them, because
Python handles Ctrl-C only when compiled code returns to it; :func:`integrate` is the same
integration in one call. Both methods are L-stable: steps far longer than the bristle period
(2 pi / sqrt(sigma_0 / I), about 1 ms) stay stable, and the pre-sliding state relaxes without
the ringing an explicit method shows. At the end of each revolution :func:`motion_period`
tells whether the motion has become periodic, and the integration can stop there. numba
compiles all of it because the per-step work is a 3 x 3 Newton solve, which in Python costs
more in overhead than in arithmetic.

This module imports numba; :mod:`shaftline.cpp.motion` imports it only when integrating.
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np

from shaftline._compiled import njit_cached
from shaftline.friction.kernels import (
    finite_slope_force,
    finite_slope_force_slope,
    lugre_state_rate,
    lugre_state_rate_partials,
    stribeck_level_and_slope,
)

TWO_PI = 2.0 * np.pi

#: Newton iterations per implicit stage before the stage is accepted unconverged.
NEWTON_ITERATIONS = 20

#: Halvings of a Newton correction that raises the residual, at most (2^-30 of the step).
HALVINGS = 30

#: Integration methods of :func:`advance` (numba takes them as numbers).
BACKWARD_EULER = 0
TR_BDF2 = 1

#: TR-BDF2's gamma = 2 - sqrt 2: the trapezoidal stage ends at t_n + gamma h, and both stages
#: then have the same implicit coefficient gamma h / 2 (Hosea & Shampine 1996).
GAMMA = 2.0 - np.sqrt(2.0)
#: Weights of the BDF2 stage: y_n+1 - (gamma h / 2) y' = _BDF2_NEW y_gamma - _BDF2_OLD y_n.
_BDF2_NEW = 1.0 / (GAMMA * (2.0 - GAMMA))
_BDF2_OLD = (1.0 - GAMMA) ** 2 / (GAMMA * (2.0 - GAMMA))

#: Absolute convergence scales of (phi, w, z): rad (unused), rad/s, rad.
_SCALE = (0.0, 1e-12, 1e-16)


class CarrierParameters(NamedTuple):
    """Everything the equations need, as plain floats and arrays numba can take (SI).

    The tables are closed: ``angle`` rises strictly from angle[0] to angle[0] + 2 pi, and the
    last value of each table repeats the first, so np.interp covers a whole revolution.
    """

    angle: np.ndarray  # rad, n + 1 values
    spindle_torque: np.ndarray  # M_sp, N m
    coulomb_torque: np.ndarray  # Q_c, N m
    speed: float  # rad/s
    inertia: float  # I_blade + I_water, kg m^2
    oil_stiffness: float  # N/m
    pin_radius: float  # m
    pitch_angle: float  # rad
    half_play: float  # half the backlash, m
    holding_moment: float  # M_hyd,mean, N m
    lugre: bool
    stiffness: float  # sigma_0, N m/rad
    damping: float  # sigma_1, N m s/rad
    static_ratio: float  # F_s / F_c
    stribeck_velocity: float  # rad/s
    threshold_velocity: float  # rad/s


def close_table(angle: np.ndarray, *values: np.ndarray) -> tuple[np.ndarray, ...]:
    """Append angle[0] + 2 pi and the first value of each table (periodic wrap for np.interp)."""
    angle = np.asarray(angle, dtype=float)
    closed = [np.append(angle, angle[0] + TWO_PI)]
    closed += [np.append(np.asarray(v, dtype=float), float(v[0])) for v in values]
    return tuple(closed)


@njit_cached()
def forcing(t, p):
    """(M_sp - M_hyd,mean, Q_c) at time t, s: the tables at psi = speed t, N m.

    Linear interpolation in the closed tables (np.interp's formula, one search for both), so
    unequally spaced angles are exact nodes of the interpolant and the last interval wraps to
    the first node.
    """
    angle = p.angle
    psi = (p.speed * t - angle[0]) % TWO_PI + angle[0]
    # the interval [angle[k], angle[k + 1]) holding psi; psi can round up to the table's end
    k = min(max(np.searchsorted(angle, psi, side="right") - 1, 0), angle.size - 2)
    offset = psi - angle[k]
    width = angle[k + 1] - angle[k]
    spindle = (p.spindle_torque[k + 1] - p.spindle_torque[k]) / width * offset + p.spindle_torque[k]
    coulomb = (p.coulomb_torque[k + 1] - p.coulomb_torque[k]) / width * offset + p.coulomb_torque[k]
    return spindle - p.holding_moment, coulomb


@njit_cached()
def spring(phi, p):
    """Oil spring through the pin (Eq. 4.25-4.27 with the backlash dead zone).

    Returns (force N, moment N m, d moment / d phi N m/rad); all zero inside the dead zone.
    """
    angle = p.pitch_angle + phi
    travel = p.pin_radius * (np.sin(angle) - np.sin(p.pitch_angle))
    if abs(travel) <= p.half_play:
        return 0.0, 0.0, 0.0
    force = p.oil_stiffness * np.sign(travel) * (abs(travel) - p.half_play)
    arm = p.pin_radius * np.cos(angle)
    # d(force * arm)/d phi: the spring stiffness through the arm, less the arm's own change
    return force, force * arm, p.oil_stiffness * arm * arm - force * p.pin_radius * np.sin(angle)


@njit_cached()
def evaluate(y, spindle, coulomb, p, f, jac, with_jacobian):
    """The equations of motion: y' for the loads ``spindle``, ``coulomb`` (N m) into ``f`` and,
    ``with_jacobian``, d y'/d y into ``jac`` (n x n), exact.

    One function for both, so that a Newton iteration, which needs both at the same state,
    computes the shared terms (the pin's sine and cosine, the Stribeck exponential) once. The
    Jacobian includes the Stribeck slope of g(w) in d z'/d w and the change of the pin's arm in
    the spring moment; both only speed up Newton's convergence, the solution is that of the
    rates.
    """
    w = y[1]
    _, moment, stiffness = spring(y[0], p)
    f[0] = w
    if with_jacobian:
        jac[0, 0] = 0.0
        jac[0, 1] = 1.0
        jac[1, 0] = -stiffness / p.inertia
    if p.lugre:
        z = y[2]
        level, slope = stribeck_level_and_slope(w, coulomb, p.static_ratio * coulomb, p.stribeck_velocity)
        z_rate = lugre_state_rate(z, w, p.stiffness, level)
        f[1] = (spindle - p.stiffness * z - p.damping * z_rate - moment) / p.inertia
        f[2] = z_rate
        if with_jacobian:
            d_dz, d_dw = lugre_state_rate_partials(z, w, p.stiffness, level, slope)
            jac[0, 2] = 0.0
            jac[1, 1] = -p.damping * d_dw / p.inertia
            jac[1, 2] = -(p.stiffness + p.damping * d_dz) / p.inertia
            jac[2, 0] = 0.0
            jac[2, 1] = d_dw
            jac[2, 2] = d_dz
    else:
        f[1] = (spindle - finite_slope_force(w, coulomb, p.threshold_velocity) - moment) / p.inertia
        if with_jacobian:
            jac[1, 1] = -finite_slope_force_slope(w, coulomb, 0.0, p.threshold_velocity) / p.inertia


@njit_cached()
def rates(y, spindle, coulomb, p, out):
    """Right-hand side y' for the loads ``spindle``, ``coulomb`` (N m), written into ``out``."""
    evaluate(y, spindle, coulomb, p, out, np.empty((0, 0)), False)


@njit_cached()
def rates_jacobian(y, spindle, coulomb, p, out):
    """d y' / d y of :func:`rates`, written into ``out`` (n x n), exact (:func:`evaluate`)."""
    evaluate(y, spindle, coulomb, p, np.empty(y.size), out, True)


@njit_cached()
def states(p):
    """Number of states: 3 with LuGre (phi, w, z), 2 with the static law (phi, w)."""
    return 3 if p.lugre else 2


@njit_cached()
def at_rest(p):
    """What :func:`advance` carries from one chunk to the next, at rest: the state y = 0,
    followed by its rate y', not yet known (NaN)."""
    n = states(p)
    carried = np.zeros(2 * n)
    carried[n:] = np.nan
    return carried


@njit_cached()
def rhs(t, y, p):
    """y'(t, y), the right-hand side for scipy's solve_ivp (allocates its result)."""
    spindle, coulomb = forcing(t, p)
    out = np.empty(y.size)
    rates(y, spindle, coulomb, p, out)
    return out


@njit_cached()
def jacobian(t, y, p):
    """d y'/d y (t, y), the Jacobian for scipy's solve_ivp (allocates its result)."""
    spindle, coulomb = forcing(t, p)
    out = np.empty((y.size, y.size))
    rates_jacobian(y, spindle, coulomb, p, out)
    return out


@njit_cached()
def spring_force(phi, p):
    """Oil-spring (yoke) force for each rotation in ``phi``, N."""
    force = np.empty(phi.size)
    for k in range(phi.size):
        force[k] = spring(phi[k], p)[0]
    return force


@njit_cached()
def _newton_correction(jac, hc, b, n):
    """Solve (I - hc J) x = b for the Jacobian J of :func:`evaluate`; x replaces b.

    In closed form, because J's first row is (0, 1, 0) (phi' = w) and z' does not depend on
    phi: the first equation gives x_0 = b_0 + hc x_1, which leaves two equations in (x_1, x_2)
    (one with the static law), solved by Cramer's rule. Their determinant is that of
    I - hc J, which the implicit stages need non-zero anyway. A general LAPACK solve costs a
    call and an allocation per Newton iteration, several times the rest of the iteration.
    """
    m10 = -hc * jac[1, 0]
    m11 = 1.0 - hc * jac[1, 1] + hc * m10  # after substituting x_0 = b_0 + hc x_1
    b1 = b[1] - m10 * b[0]
    if n == 3:
        m12 = -hc * jac[1, 2]
        m21 = -hc * jac[2, 1]
        m22 = 1.0 - hc * jac[2, 2]
        det = m11 * m22 - m12 * m21
        x1 = (b1 * m22 - m12 * b[2]) / det
        b[2] = (m11 * b[2] - m21 * b1) / det
    else:
        x1 = b1 / m11
    b[0] = b[0] + hc * x1
    b[1] = x1


@njit_cached()
def _residual(y_new, r, y_ref, spindle, coulomb, hc, p, f, jac, out):
    """Residual y_new - r - hc y'(y_new) of an implicit stage into ``out``, and the Jacobian at
    y_new into ``jac`` (for the next Newton iteration); returns the residual's size for
    the step control: the largest |residual| of w (and z) over its convergence scale at the
    step's start ``y_ref`` (a scale fixed within the step, so a Newton correction is a descent
    direction).

    phi's residual is linear and vanishes after the first full Newton step, so it is left out.
    """
    evaluate(y_new, spindle, coulomb, p, f, jac, True)
    size = 0.0
    for i in range(y_new.size):
        out[i] = y_new[i] - r[i] - hc * f[i]
        if i > 0:
            size = max(size, abs(out[i]) / (_SCALE[i] + 1e-9 * abs(y_ref[i])))
    return size


@njit_cached()
def _stage(p, t, hc, r, y_ref, y_new, f, jac, residual, delta, trial):
    """Solve the implicit stage y_new - hc y'(t, y_new) = r for y_new by Newton's method with
    the exact Jacobian, from the guess in ``y_new`` (overwritten with the solution).

    Newton stops when the corrections of w and z fall below 1e-9 relative (1e-12 rad/s
    absolute on w, 1e-16 rad on z). A correction that raises the residual is halved until it
    does not: the friction law (at |w| = v_th) and the dead zone have kinks across which plain
    Newton can cycle, and an accepted unconverged stage is an error of the size of the
    correction. ``f``, ``jac``, ``residual``, ``delta`` and ``trial`` are work arrays.

    Returns
    -------
    bool
        Whether Newton converged within :data:`NEWTON_ITERATIONS` iterations (the last iterate
        is kept either way).
    """
    n = y_new.size
    spindle, coulomb = forcing(t, p)
    size = _residual(y_new, r, y_ref, spindle, coulomb, hc, p, f, jac, residual)
    for _ in range(NEWTON_ITERATIONS):
        for i in range(n):
            delta[i] = residual[i]
        _newton_correction(jac, hc, delta, n)
        converged = abs(delta[1]) <= 1e-12 + 1e-9 * abs(y_new[1] - delta[1])
        if n == 3:
            converged = converged and abs(delta[2]) <= 1e-16 + 1e-9 * abs(y_new[2] - delta[2])
        if converged:
            # a correction this small cannot raise the residual: take it without checking
            for i in range(n):
                y_new[i] -= delta[i]
            return True
        fraction = 1.0
        for _ in range(HALVINGS):
            for i in range(n):
                trial[i] = y_new[i] - fraction * delta[i]
            trial_size = _residual(trial, r, y_ref, spindle, coulomb, hc, p, f, jac, residual)
            if trial_size <= size or trial_size <= 1.0:
                break
            fraction *= 0.5
        y_new[:] = trial
        size = trial_size
    return False


@njit_cached()
def periodic_change(values, end, per, period, limit):
    """How far the samples of the ``period`` revolutions ending at sample ``end`` are from
    repeating the ``period`` revolutions before them (``per`` samples a revolution): the
    largest change of a sample from the one ``period`` revolutions earlier, over the
    peak-to-peak of the later revolutions. 0 when they repeat exactly (also without motion),
    inf when a motion-less stretch follows a moving one.

    The scan stops as soon as the change exceeds ``limit`` (then the value returned is only
    known to exceed it): the integration tests every revolution and is interested only in
    whether the change is within its tolerance.
    """
    span = period * per
    low = values[end]
    high = values[end]
    for j in range(end - span, end):
        low = min(low, values[j])
        high = max(high, values[j])
    bound = limit * (high - low)
    change = 0.0
    for j in range(end - span, end + 1):
        change = max(change, abs(values[j] - values[j - span]))
        if change > bound:
            break
    if change == 0.0:
        return 0.0
    return change / (high - low) if high > low else np.inf


@njit_cached()
def motion_period(phi, w, end, per, tolerance, longest):
    """The smallest number of revolutions m <= ``longest`` after which the motion repeats to
    ``tolerance`` at sample ``end`` (the end of a revolution): the rotation and the rotation
    rate over the last m revolutions both within ``tolerance`` of those over the m before
    (:func:`periodic_change`); 0 if there is none (or fewer than 2 m revolutions so far)."""
    revolutions = end // per
    for period in range(1, longest + 1):
        if revolutions < 2 * period:
            break
        if (
            periodic_change(phi, end, per, period, tolerance) <= tolerance
            and periodic_change(w, end, per, period, tolerance) <= tolerance
        ):
            return period
    return 0


# Inlined into advance's loop (numba's inline): called, a TR-BDF2 integration took 1.4-1.7 times as long.
@njit_cached(inline="always")
def _tr_bdf2_step(p, k, step, y, rate, y_new, y_gamma, r, f, jac, residual, delta, trial):
    """One TR-BDF2 step of :func:`advance`, from step ``k - 1`` (state ``y`` and its rate
    ``rate``) to step ``k`` of ``step`` s: the new state in ``y_new``, its rate in ``rate``
    (``y`` is left as it was). ``y_gamma``, ``r``, ``f``, ``jac``, ``residual``, ``delta`` and
    ``trial`` are work arrays.

    Returns
    -------
    int
        Implicit stages accepted unconverged (0, 1 or 2).
    """
    n = y.size
    unconverged = 0
    hc = GAMMA * step / 2
    t = (k - 1) * step
    if np.isnan(rate[0]):  # at the start only
        spindle, coulomb = forcing(t, p)
        evaluate(y, spindle, coulomb, p, rate, jac, False)
    for i in range(n):
        r[i] = y[i] + hc * rate[i]
        y_gamma[i] = y[i] + GAMMA * step * rate[i]  # explicit Euler guess
    if not _stage(p, t + GAMMA * step, hc, r, y, y_gamma, f, jac, residual, delta, trial):
        unconverged += 1
    for i in range(n):
        r[i] = _BDF2_NEW * y_gamma[i] - _BDF2_OLD * y[i]
        y_new[i] = y[i] + (y_gamma[i] - y[i]) / GAMMA  # linear extrapolation guess
    if not _stage(p, k * step, hc, r, y, y_new, f, jac, residual, delta, trial):
        unconverged += 1
    for i in range(n):
        rate[i] = (y_new[i] - r[i]) / hc
    return unconverged


# Inlined into advance's loop, as _tr_bdf2_step.
@njit_cached(inline="always")
def _backward_euler_step(p, k, step, y, y_new, f, jac, residual, delta, trial):
    """One backward-Euler step of :func:`advance`, from step ``k - 1`` (state ``y``) to step
    ``k`` of ``step`` s: the new state in ``y_new`` (``y`` is left as it was). ``f``, ``jac``,
    ``residual``, ``delta`` and ``trial`` are work arrays.

    Returns
    -------
    int
        Implicit stages accepted unconverged (0 or 1).
    """
    y_new[:] = y
    if not _stage(p, k * step, step, y, y, y_new, f, jac, residual, delta, trial):
        return 1
    return 0


@njit_cached()
def advance(p, method, step, carried, first, last, every, revolution, tolerance, longest, phi_out, w_out, force_out):
    """Integrate from step ``first`` to step ``last`` (times ``first * step`` to
    ``last * step``, s) with ``method``, carrying the state in ``carried`` in place; stop
    early at the periodic state when ``tolerance`` > 0.

    :data:`TR_BDF2` (second order, L-stable; Bank et al. 1985, Hosea & Shampine 1996): a
    trapezoidal stage to t_n + gamma h, then BDF2 through y_n, y_gamma and y_n+1, both implicit
    with the same coefficient gamma h / 2 (gamma = 2 - sqrt 2)::

        y_g - (gamma h / 2) y'(y_g) = y_n + (gamma h / 2) y'(y_n)
        y_n+1 - (gamma h / 2) y'(y_n+1) = (y_g - (1 - gamma)^2 y_n) / (gamma (2 - gamma))

    The rate y'(y_n) that opens a step is the one the BDF2 stage of the step before implies,
    (y_n - r) / (gamma h / 2) with r its right-hand side (first the same as last: one
    evaluation of the model a step less, a fifth of the work; it differs from y'(y_n) only by
    Newton's residual). It is carried with the state, so that chunks stay bit for bit.

    :data:`BACKWARD_EULER` (first order, L-stable): y_n+1 - h y'(y_n+1) = y_n. Each implicit
    stage is solved by :func:`_stage`.

    The step number k is absolute (the time is ``k * step``) and a step depends only on ``y``
    and k, so integrating 0 to N in one call or in any number of consecutive calls is the same
    arithmetic, bit for bit: :mod:`shaftline.cpp.motion` calls it in chunks so that Python can
    handle Ctrl-C and report progress between them.

    Parameters
    ----------
    p : CarrierParameters
    method : int
        :data:`TR_BDF2` or :data:`BACKWARD_EULER`.
    step : float
        Time step, s.
    carried : ndarray
        The state (phi rad, w rad/s[, z rad]) at step ``first`` followed by its rate y'
        (NaN where not known: :func:`at_rest`); overwritten with those at the last step
        taken.
    first, last : int
        Step numbers at the start and end of the chunk, ``0 <= first <= last``.
    every : int
        Steps between output samples: sample ``k // every`` is written after each step k that
        is a multiple of ``every``.
    revolution : int
        Steps per shaft revolution, a multiple of ``every``.
    tolerance : float
        Periodicity tolerance; 0 integrates to ``last`` whatever the motion. At the end of
        each revolution the integration stops when the motion has become periodic with a
        period of at most ``longest`` revolutions (:func:`motion_period`).
    longest : int
        Longest period looked for, revolutions.
    phi_out, w_out, force_out : ndarray
        Rotation (rad), rotation rate (rad/s) and oil-spring force (N) per sample, filled in.

    Returns
    -------
    unconverged : int
        Number of implicit stages of the chunk accepted unconverged after
        :data:`NEWTON_ITERATIONS` iterations.
    end : int
        The last step taken: ``last``, or the end of the revolution found periodic.
    period : int
        The motion's period in revolutions if the integration stopped at the periodic state,
        else 0.
    """
    n = states(p)
    # Work on local copies of the state, written back at the end: LLVM may then assume that no
    # output array aliases them, which the caller's array does not allow (5-10 % of the time).
    y = carried[:n].copy()
    rate = carried[n:].copy()
    y_new = np.empty(n)
    y_gamma = np.empty(n)
    r = np.empty(n)
    trial = np.empty(n)
    f = np.empty(n)
    jac = np.empty((n, n))
    residual = np.empty(n)
    delta = np.empty(n)
    per = revolution // every
    unconverged = 0
    end = last
    period = 0
    for k in range(first + 1, last + 1):
        if method == TR_BDF2:
            unconverged += _tr_bdf2_step(p, k, step, y, rate, y_new, y_gamma, r, f, jac, residual, delta, trial)
        else:
            unconverged += _backward_euler_step(p, k, step, y, y_new, f, jac, residual, delta, trial)
        y[:] = y_new
        if k % every == 0:
            sample = k // every
            phi_out[sample] = y[0]
            w_out[sample] = y[1]
            force_out[sample] = spring(y[0], p)[0]
            if tolerance > 0.0 and k % revolution == 0:
                period = motion_period(phi_out, w_out, sample, per, tolerance, longest)
                if period:
                    end = k
                    break
    carried[:n] = y
    carried[n:] = rate
    return unconverged, end, period


@njit_cached()
def integrate(p, method, step, steps, every, revolution, tolerance, longest):
    """:func:`advance` from rest (y = 0 at t = 0) over at most ``steps`` steps of ``step`` s,
    in one compiled call (it cannot be interrupted).

    Returns
    -------
    phi, w, force : ndarray
        Rotation (rad), rotation rate (rad/s) and oil-spring force (N) every ``every`` steps,
        from t = 0 to the last step taken.
    unconverged : int
        Number of implicit stages accepted unconverged after :data:`NEWTON_ITERATIONS`
        iterations.
    end : int
        The last step taken.
    period : int
        The motion's period in revolutions if the integration stopped at the periodic state,
        else 0.
    """
    samples = steps // every + 1
    phi_out = np.zeros(samples)
    w_out = np.zeros(samples)
    force_out = np.zeros(samples)
    unconverged, end, period = advance(
        p, method, step, at_rest(p), 0, steps, every, revolution, tolerance, longest, phi_out, w_out, force_out
    )
    used = end // every + 1
    return phi_out[:used], w_out[:used], force_out[:used], unconverged, end, period
