"""Compiled scalar kernels of the friction laws (seed 000, Godjevac 2009, Sect. 4.4).

The one place where the Stribeck level, the LuGre bristle rate and the finite-slope static
law are written, with the partial derivatives an implicit integrator needs. The public
functions and classes of :mod:`shaftline.friction.models` and the blade-carrier equations of
motion (:mod:`shaftline.cpp._carrier`) both call these, so the two cannot drift apart.

Every kernel is branch-free numpy arithmetic, so numba compiles it for float64 scalars (inside
other compiled code: no allocation) and for float64 arrays (element by element) alike. Units
are the caller's: N and m/s for a translating contact, N m and rad/s for a rotating one.
This module imports numba; import it only where compiled code is wanted (the public API
imports it lazily, so that ``import shaftline.friction`` stays cheap).
"""

from __future__ import annotations

import numpy as np

from shaftline._compiled import njit_cached


@njit_cached()
def stribeck_level(velocity, coulomb_force, static_force, stribeck_velocity):
    """Stribeck level g(v) = F_c + (F_s - F_c) exp(-(|v| / v_s)^2) (Eq. 4.14).

    Parameters
    ----------
    velocity : float or ndarray
        Sliding velocity v, m/s (rad/s).
    coulomb_force, static_force : float
        F_c and the break-away level F_s, N (N m).
    stribeck_velocity : float
        v_s > 0, m/s (rad/s).

    Returns
    -------
    float or ndarray
        g(v) > 0, a magnitude, N (N m).
    """
    # (|v| / v_s)^2 == (v / v_s)^2 exactly in floating point: no abs needed
    return coulomb_force + (static_force - coulomb_force) * np.exp(-((velocity / stribeck_velocity) ** 2))


@njit_cached()
def stribeck_level_slope(velocity, coulomb_force, static_force, stribeck_velocity):
    """dg/dv of :func:`stribeck_level`, N s/m (N m s/rad); odd in v, zero at v = 0."""
    x = velocity / stribeck_velocity
    return -2.0 * x / stribeck_velocity * (static_force - coulomb_force) * np.exp(-(x**2))


@njit_cached()
def stribeck_level_and_slope(velocity, coulomb_force, static_force, stribeck_velocity):
    """(g(v), dg/dv) of :func:`stribeck_level` and :func:`stribeck_level_slope` with one
    exponential, for an implicit integrator that needs both at every Newton iteration."""
    x = velocity / stribeck_velocity
    excess = (static_force - coulomb_force) * np.exp(-(x**2))
    return coulomb_force + excess, -2.0 * x / stribeck_velocity * excess


@njit_cached()
def lugre_state_rate(z, velocity, stiffness, level):
    """Bristle rate z' = v - sigma_0 |v| z / g(v) (Eq. 4.13 with g of Eq. 4.14; Dahl for g = F_c).

    Parameters
    ----------
    z : float or ndarray
        Mean bristle deflection, m (rad).
    velocity : float or ndarray
        Sliding velocity, m/s (rad/s).
    stiffness : float
        sigma_0, N/m (N m/rad).
    level : float or ndarray
        g(v) at ``velocity``, N (N m).

    Returns
    -------
    float or ndarray
        z', m/s (rad/s).
    """
    return velocity - stiffness * np.abs(velocity) / level * z


@njit_cached()
def lugre_state_rate_partials(z, velocity, stiffness, level, level_slope):
    """Partial derivatives of :func:`lugre_state_rate`: (dz'/dz in 1/s, dz'/dv dimensionless).

    ``level_slope`` is dg/dv at ``velocity`` (:func:`stribeck_level_slope`; zero for Dahl).
    dz'/dv = 1 - sigma_0 z (sgn(v) g - |v| g') / g^2 is exact: it keeps the Stribeck slope, which
    is not small in gross sliding, where sgn(v) sigma_0 z / g tends to 1.
    """
    d_dz = -stiffness * np.abs(velocity) / level
    d_dv = 1.0 - stiffness * z * (np.sign(velocity) * level - np.abs(velocity) * level_slope) / level**2
    return d_dz, d_dv


@njit_cached()
def finite_slope_force(velocity, level, threshold_velocity):
    """Static law with a finite slope through zero velocity (Eq. 4.7; Eq. 4.8 for level = F_c).

    F = g sgn(v) for |v| >= v_th and (v / v_th) g within, i.e. g clip(v / v_th, -1, 1).

    Parameters
    ----------
    velocity : float or ndarray
        m/s (rad/s).
    level : float or ndarray
        Friction level g: F_c (Eq. 4.8) or the Stribeck level g(v) (Eq. 4.7), N (N m).
    threshold_velocity : float
        v_th > 0, m/s (rad/s).

    Returns
    -------
    float or ndarray
        Friction force (signed, opposing ``velocity`` in ``m x'' = F - F_fr``), N (N m).
    """
    return level * np.minimum(np.maximum(velocity / threshold_velocity, -1.0), 1.0)


@njit_cached()
def finite_slope_force_slope(velocity, level, level_slope, threshold_velocity):
    """dF/dv of :func:`finite_slope_force`, N s/m (N m s/rad).

    ``level_slope`` is dg/dv (zero for the constant level of Eq. 4.8). At |v| = v_th the
    outer (zero-slope) branch is taken, as the law's |v| >= v_th branch is.
    """
    ramp = np.minimum(np.maximum(velocity / threshold_velocity, -1.0), 1.0)
    return level_slope * ramp + level * (np.abs(velocity) < threshold_velocity) / threshold_velocity
