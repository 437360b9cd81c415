"""The blade-carrier equations of motion, written once, and the fixed-step integrator.

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

:func:`rhs` and :func:`jacobian` (the analytic, exact Jacobian of the right-hand side) serve
scipy's Radau through thin Python wrappers; :func:`advance` (backward Euler over a range of
steps) calls the same :func:`rates` and :func:`rates_jacobian` inside its Newton loop.
:mod:`shaftline.cpp.motion` calls :func:`advance` in chunks of about 0.1 s, carrying the
state between them, because Python handles Ctrl-C only when compiled code returns to it;
:func:`backward_euler` is the same integration in one call. Backward Euler is L-stable:
steps far longer than the bristle period (2 pi / sqrt(sigma_0 / I), about 1 ms) stay stable,
and the pre-sliding state relaxes without the ringing an explicit method shows. numba
compiles all of it because the per-step work is a 3 x 3 Newton solve, which in Python costs
more in overhead than in arithmetic.

This module imports numba; :mod:`shaftline.cpp.motion` imports it only when integrating.
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np
from numba import njit

from shaftline.friction.kernels import (
    finite_slope_force,
    finite_slope_force_slope,
    lugre_state_rate,
    lugre_state_rate_partials,
    stribeck_level,
    stribeck_level_slope,
)

TWO_PI = 2.0 * np.pi

#: Newton iterations per backward-Euler step before the step is accepted unconverged.
NEWTON_ITERATIONS = 20

#: Halvings of a Newton correction that raises the residual, at most (2^-30 of the step).
HALVINGS = 30

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


@njit(cache=True)
def forcing(t, p):
    """(M_sp - M_hyd,mean, Q_c) at time t, s: the tables at psi = speed t, N m.

    Linear interpolation in the closed tables, so unequally spaced angles are exact nodes of
    the interpolant and the last interval wraps to the first node.
    """
    psi = (p.speed * t - p.angle[0]) % TWO_PI + p.angle[0]
    spindle = np.interp(psi, p.angle, p.spindle_torque) - p.holding_moment
    return spindle, np.interp(psi, p.angle, p.coulomb_torque)


@njit(cache=True)
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


@njit(cache=True)
def rates(y, spindle, coulomb, p, out):
    """Right-hand side y' for the loads ``spindle``, ``coulomb`` (N m), written into ``out``."""
    w = y[1]
    moment = spring(y[0], p)[1]
    out[0] = w
    if p.lugre:
        z = y[2]
        level = stribeck_level(w, coulomb, p.static_ratio * coulomb, p.stribeck_velocity)
        z_rate = lugre_state_rate(z, w, p.stiffness, level)
        out[1] = (spindle - p.stiffness * z - p.damping * z_rate - moment) / p.inertia
        out[2] = z_rate
    else:
        out[1] = (spindle - finite_slope_force(w, coulomb, p.threshold_velocity) - moment) / p.inertia


@njit(cache=True)
def rates_jacobian(y, spindle, coulomb, p, out):
    """d y' / d y of :func:`rates`, written into ``out`` (n x n), exact.

    It includes the Stribeck slope of g(w) in d z'/d w and the change of the pin's arm in the
    spring moment; both only speed up Newton's convergence, the solution is that of
    :func:`rates`.
    """
    w = y[1]
    stiffness = spring(y[0], p)[2]
    out[0, 0] = 0.0
    out[0, 1] = 1.0
    out[1, 0] = -stiffness / p.inertia
    if p.lugre:
        z = y[2]
        static = p.static_ratio * coulomb
        level = stribeck_level(w, coulomb, static, p.stribeck_velocity)
        slope = stribeck_level_slope(w, coulomb, static, p.stribeck_velocity)
        d_dz, d_dw = lugre_state_rate_partials(z, w, p.stiffness, level, slope)
        out[0, 2] = 0.0
        out[1, 1] = -p.damping * d_dw / p.inertia
        out[1, 2] = -(p.stiffness + p.damping * d_dz) / p.inertia
        out[2, 0] = 0.0
        out[2, 1] = d_dw
        out[2, 2] = d_dz
    else:
        out[1, 1] = -finite_slope_force_slope(w, coulomb, 0.0, p.threshold_velocity) / p.inertia


@njit(cache=True)
def states(p):
    """Number of states: 3 with LuGre (phi, w, z), 2 with the static law (phi, w)."""
    return 3 if p.lugre else 2


@njit(cache=True)
def rhs(t, y, p):
    """y'(t, y), the right-hand side for scipy's solve_ivp (allocates its result)."""
    spindle, coulomb = forcing(t, p)
    out = np.empty(y.size)
    rates(y, spindle, coulomb, p, out)
    return out


@njit(cache=True)
def jacobian(t, y, p):
    """d y'/d y (t, y), the Jacobian for scipy's solve_ivp (allocates its result)."""
    spindle, coulomb = forcing(t, p)
    out = np.empty((y.size, y.size))
    rates_jacobian(y, spindle, coulomb, p, out)
    return out


@njit(cache=True)
def spring_force(phi, p):
    """Oil-spring (yoke) force for each rotation in ``phi``, N."""
    force = np.empty(phi.size)
    for k in range(phi.size):
        force[k] = spring(phi[k], p)[0]
    return force


@njit(cache=True)
def _solve_in_place(a, b, n):
    """Solve a x = b for n <= 3 by Gaussian elimination with partial pivoting; x replaces b.

    Cheaper than a LAPACK call for these sizes (no copies, no allocation).
    """
    for col in range(n):
        pivot = col
        for row in range(col + 1, n):
            if abs(a[row, col]) > abs(a[pivot, col]):
                pivot = row
        if pivot != col:
            for c in range(n):
                a[col, c], a[pivot, c] = a[pivot, c], a[col, c]
            b[col], b[pivot] = b[pivot], b[col]
        for row in range(col + 1, n):
            factor = a[row, col] / a[col, col]
            for c in range(col, n):
                a[row, c] -= factor * a[col, c]
            b[row] -= factor * b[col]
    for row in range(n - 1, -1, -1):
        total = b[row]
        for c in range(row + 1, n):
            total -= a[row, c] * b[c]
        b[row] = total / a[row, row]


@njit(cache=True)
def _residual(y_new, y, spindle, coulomb, step, p, f, out):
    """Backward-Euler residual y_new - y - step y'(y_new) into ``out``; returns its size for the
    step control: the largest |residual| of w (and z) over its convergence scale at the step's
    start ``y`` (a scale fixed within the step, so a Newton correction is a descent direction).

    phi's residual is linear and vanishes after the first full Newton step, so it is left out.
    """
    rates(y_new, spindle, coulomb, p, f)
    size = 0.0
    for i in range(y.size):
        out[i] = y_new[i] - y[i] - step * f[i]
        if i > 0:
            size = max(size, abs(out[i]) / (_SCALE[i] + 1e-9 * abs(y[i])))
    return size


@njit(cache=True)
def advance(p, step, y, first, last, every, phi_out, w_out, force_out):
    """Backward Euler from step ``first`` to step ``last`` (times ``first * step`` to
    ``last * step``, s), carrying the state ``y`` in place.

    Each step solves y_new - y - step * y'(t_new, y_new) = 0 by Newton's method with the exact
    Jacobian, until the corrections of w and z fall below 1e-9 relative (1e-12 rad/s absolute
    on w, 1e-16 rad on z). A correction that raises the residual is halved until it does not:
    the friction law (at |w| = v_th) and the dead zone have kinks across which plain Newton can
    cycle, and an accepted unconverged step is an error of the size of the correction.

    The step number k is absolute (the time is ``k * step``) and a step depends only on ``y``
    and k, so integrating 0 to N in one call or in any number of consecutive calls is the same
    arithmetic, bit for bit: :mod:`shaftline.cpp.motion` calls it in chunks so that Python can
    handle Ctrl-C and report progress between them.

    Parameters
    ----------
    p : CarrierParameters
    step : float
        Time step, s.
    y : ndarray
        State (phi rad, w rad/s[, z rad]) at step ``first``; overwritten with that at ``last``.
    first, last : int
        Step numbers at the start and end of the chunk, ``0 <= first <= last``.
    every : int
        Steps between output samples: sample ``k // every`` is written after each step k that
        is a multiple of ``every``.
    phi_out, w_out, force_out : ndarray
        Rotation (rad), rotation rate (rad/s) and oil-spring force (N) per sample, filled in.

    Returns
    -------
    int
        Number of steps of the chunk accepted unconverged after :data:`NEWTON_ITERATIONS`
        iterations.
    """
    n = states(p)
    # Work on a local copy of the state, written back at the end: LLVM may then assume that no
    # output array aliases it, which the caller's array does not allow (5-10 % of the time).
    y_start = y
    y = y_start.copy()
    y_new = np.empty(n)
    trial = np.empty(n)
    f = np.empty(n)
    jac = np.empty((n, n))
    residual = np.empty(n)
    delta = np.empty(n)
    unconverged = 0
    for k in range(first + 1, last + 1):
        spindle, coulomb = forcing(k * step, p)
        y_new[:] = y
        size = _residual(y_new, y, spindle, coulomb, step, p, f, residual)
        converged = False
        for _ in range(NEWTON_ITERATIONS):
            rates_jacobian(y_new, spindle, coulomb, p, jac)
            for i in range(n):
                delta[i] = residual[i]
                for j in range(n):
                    jac[i, j] = (1.0 if i == j else 0.0) - step * jac[i, j]
            _solve_in_place(jac, delta, n)
            converged = abs(delta[1]) <= 1e-12 + 1e-9 * abs(y_new[1] - delta[1])
            if n == 3:
                converged = converged and abs(delta[2]) <= 1e-16 + 1e-9 * abs(y_new[2] - delta[2])
            if converged:
                # a correction this small cannot raise the residual: take it without checking
                for i in range(n):
                    y_new[i] -= delta[i]
                break
            fraction = 1.0
            for _ in range(HALVINGS):
                for i in range(n):
                    trial[i] = y_new[i] - fraction * delta[i]
                trial_size = _residual(trial, y, spindle, coulomb, step, p, f, residual)
                if trial_size <= size or trial_size <= 1.0:
                    break
                fraction *= 0.5
            y_new[:] = trial
            size = trial_size
        if not converged:
            unconverged += 1
        y[:] = y_new
        if k % every == 0:
            sample = k // every
            phi_out[sample] = y[0]
            w_out[sample] = y[1]
            force_out[sample] = spring(y[0], p)[0]
    y_start[:] = y
    return unconverged


@njit(cache=True)
def backward_euler(p, step, steps, every):
    """Backward Euler from rest (y = 0 at t = 0) over ``steps`` steps of ``step`` s, in one
    compiled call (:func:`advance` from 0 to ``steps``; it cannot be interrupted).

    Returns
    -------
    phi, w, force : ndarray
        Rotation (rad), rotation rate (rad/s) and oil-spring force (N) every ``every`` steps,
        from t = 0.
    unconverged : int
        Number of steps accepted unconverged after :data:`NEWTON_ITERATIONS` iterations.
    """
    samples = steps // every + 1
    phi_out = np.zeros(samples)
    w_out = np.zeros(samples)
    force_out = np.zeros(samples)
    unconverged = advance(p, step, np.zeros(states(p)), 0, steps, every, phi_out, w_out, force_out)
    return phi_out, w_out, force_out, unconverged
