"""Compiled fixed-step integrator of the blade-carrier motion (backward Euler + Newton).

Backward Euler is L-stable: steps far longer than the bristle period (2 pi / sqrt(sigma_0 / I),
about 1 ms) stay stable, and the pre-sliding state relaxes without the ringing an explicit
method shows. Its first-order error is checked against scipy's Radau at tight tolerance in
the tests. numba compiles it because the per-step work is a 3 x 3 Newton solve, which in
Python costs more in overhead than in arithmetic (bench: 32 s -> well under 2 s for 100
revolutions).
"""

from __future__ import annotations

import numpy as np
from numba import njit


@njit(cache=True)
def _interp_periodic(psi, angle, values):
    n = angle.size
    two_pi = 2.0 * np.pi
    x = (psi - angle[0]) % two_pi
    span = angle[1] - angle[0]
    k = int(x // span)
    if k >= n - 1:
        # last interval wraps to the first node
        w = (x - (angle[n - 1] - angle[0])) / (two_pi - (angle[n - 1] - angle[0]))
        return values[n - 1] * (1 - w) + values[0] * w
    w = (x - (angle[k] - angle[0])) / (angle[k + 1] - angle[k])
    return values[k] * (1 - w) + values[k + 1] * w


@njit(cache=True)
def _spring(phi, pitch, r_pin, k_oil, half_play, sin0):
    travel = r_pin * (np.sin(pitch + phi) - sin0)
    if abs(travel) > half_play:
        engaged = np.sign(travel) * (abs(travel) - half_play)
        arm = r_pin * np.cos(pitch + phi)
        force = k_oil * engaged
        return force, force * arm, k_oil * arm * arm
    return 0.0, 0.0, 0.0


@njit(cache=True)
def integrate(
    angle,
    spindle,
    coulomb,
    speed,
    inertia,
    k_oil,
    r_pin,
    pitch,
    half_play,
    lugre,
    s0,
    s1,
    ratio,
    v_s,
    v_th,
    step,
    steps,
    every,
    holding,
):
    """States (phi, w, z) sampled every ``every`` steps; returns phi, w, hydraulic force."""
    out = steps // every + 1
    phi_out = np.empty(out)
    w_out = np.empty(out)
    force_out = np.empty(out)
    sin0 = np.sin(pitch)
    phi, w, z = 0.0, 0.0, 0.0
    phi_out[0], w_out[0], force_out[0] = 0.0, 0.0, 0.0
    jac = np.zeros((3, 3))
    res = np.zeros(3)
    for n in range(1, steps + 1):
        t = n * step
        m_sp = _interp_periodic(speed * t, angle, spindle) - holding
        q_c = _interp_periodic(speed * t, angle, coulomb)
        p_new, w_new, z_new = phi, w, z
        for _ in range(12):
            force, m_hyd, k_hyd = _spring(p_new, pitch, r_pin, k_oil, half_play, sin0)
            if lugre:
                g = q_c * (1.0 + (ratio - 1.0) * np.exp(-((w_new / v_s) ** 2)))
                z_rate = w_new - s0 * abs(w_new) / g * z_new
                dzdz = -s0 * abs(w_new) / g
                dzdw = 1.0 - s0 * np.sign(w_new) / g * z_new
                acc = (m_sp - s0 * z_new - s1 * z_rate - m_hyd) / inertia
                res[0] = p_new - phi - step * w_new
                res[1] = w_new - w - step * acc
                res[2] = z_new - z - step * z_rate
                jac[0, 0], jac[0, 1], jac[0, 2] = 1.0, -step, 0.0
                jac[1, 0] = step * k_hyd / inertia
                jac[1, 1] = 1.0 + step * s1 * dzdw / inertia
                jac[1, 2] = step * (s0 + s1 * dzdz) / inertia
                jac[2, 0], jac[2, 1], jac[2, 2] = 0.0, -step * dzdw, 1.0 - step * dzdz
                delta = np.linalg.solve(jac, res)
                p_new -= delta[0]
                w_new -= delta[1]
                z_new -= delta[2]
                if abs(delta[1]) <= 1e-12 + 1e-9 * abs(w_new) and abs(delta[2]) <= 1e-16 + 1e-9 * abs(z_new):
                    break
            else:
                if abs(w_new) >= v_th:
                    q_fr = q_c * np.sign(w_new)
                    slope = 0.0
                else:
                    q_fr = q_c * w_new / v_th
                    slope = q_c / v_th
                acc = (m_sp - q_fr - m_hyd) / inertia
                r0 = p_new - phi - step * w_new
                r1 = w_new - w - step * acc
                a, b = 1.0, -step
                c, d = step * k_hyd / inertia, 1.0 + step * slope / inertia
                det = a * d - b * c
                d0 = (d * r0 - b * r1) / det
                d1 = (-c * r0 + a * r1) / det
                p_new -= d0
                w_new -= d1
                if abs(d1) <= 1e-12 + 1e-9 * abs(w_new):
                    break
        phi, w, z = p_new, w_new, z_new
        if n % every == 0:
            k = n // every
            phi_out[k], w_out[k] = phi, w
            force_out[k] = _spring(phi, pitch, r_pin, k_oil, half_play, sin0)[0]
    return phi_out, w_out, force_out
