"""Elastic layer bonded to a rigid shell: the surface compliance of a bonded-layer solution.

A layer of thickness ``t``, Young's modulus ``E`` and Poisson's ratio ``nu``, bonded to a rigid
substrate (the bearing shell) and loaded by a normal pressure ``p`` on its free face (no shear),
has in the Fourier domain the surface normal displacement (away from the load, into the layer;
docs/theory.md Sect. 17, "Elastic layer")

    u^(k) = p^(k) * 2 (1 - nu^2) / E * F(|k| t, nu) / |k|,

    F(s, nu) = (kappa sinh 2s - 2s) / (kappa cosh 2s + 2 s^2 + (1 + kappa^2) / 2),  kappa = 3 - 4 nu,

the plane-strain solution of the layer for one wave of the load (an isotropic layer under a
normal load responds to a two-dimensional wave as to a plane one of the same |k|). ``F -> 1``
for ``|k| t -> oo``: the elastic half-space, ``u^ = 2 (1 - nu^2) p^ / (E |k|)`` (Johnson,
*Contact Mechanics*, 1985, Sect. 3.2, in Fourier form). ``F / s -> 4 (kappa - 1) / (1 + kappa)^2``
for ``s -> 0``, so ``u -> p t (1 + nu)(1 - 2 nu) / (E (1 - nu)) = p t / M``: the column model of
:mod:`shaftline.film.liner` is the layer's long-wave limit. For ``nu = 0.5`` (``kappa = 1``, an
incompressible layer) ``F ~ 2 s^3 / 3`` and ``u^ -> |k|^2 t^3 p^ / (3 G)``: the thin
incompressible layer's bulging law of Johnson (1985) Sect. 5.9; the layer model holds rubber,
the column model does not.

On the unwrapped bore the pressure is piecewise constant on cells centred on the nodes (``R dθ``
by ``dz``); the circumference is periodic (a Fourier series, exact) and the axial direction is
zero-padded to at least twice the bearing length, so a load near one end does not reach the
other through the wrap-around (the kernel decays within a few ``t``). The node displacement of
a piecewise-constant pressure is exact when every alias of each grid wavenumber is summed with
the cell's sinc factors (``sum_l K(k + 2 pi l / dx) sinc sinc``); :data:`ALIASES` of them are
summed (error below 3e-4 of the self-compliance of a half-space cell, docs/theory.md). The bore's
curvature is neglected: a plane layer, right for ``t << R`` (the liner is at most
:data:`~shaftline.film.liner.MAX_THICKNESS_RATIO` of the radius). The liner's free end faces
at the bearing ends are not modelled: the layer runs on beyond them unloaded.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import lru_cache

import numpy as np
import scipy.fft as sfft

__all__ = ["ALIASES", "ElasticLayer", "layer_factor", "layer_compliance", "layer_operator"]

#: Aliases summed on each side in each direction (``(2 A + 1)^2`` terms per wavenumber).
ALIASES = 8
#: Below this ``s = |k| t`` the layer factor is its long-wave limit (the closed form loses
#: digits to cancellation there; the next term is of relative order s^2 < 1e-8).
SMALL_WAVE = 1e-4


def layer_factor(s: np.ndarray | float, poisson: float) -> np.ndarray:
    """``F(s, nu)`` of the bonded layer (module docstring), the ratio of its surface compliance
    to the half-space's at the same wavenumber; ``s = |k| t``.

    Written with ``exp(-2 s)`` so that it neither overflows nor loses digits for large ``s``.

    >>> round(float(layer_factor(50.0, 0.3)), 12)  # a thick layer is the half-space
    1.0
    >>> round(float(layer_factor(1e-3, 0.3)) / 1e-3, 6)  # thin: F / s -> (1 - 2 nu) / (2 (1 - nu)^2)
    0.408163
    """
    s = np.asarray(s, dtype=float)
    kappa = 3.0 - 4.0 * poisson
    e2 = np.exp(-2.0 * s)
    e4 = e2 * e2
    numerator = kappa * (1.0 - e4) - 4.0 * s * e2
    denominator = kappa * (1.0 + e4) + (4.0 * s * s + 1.0 + kappa * kappa) * e2
    return numerator / denominator


def layer_compliance(wavenumber: np.ndarray, thickness: float, modulus: float, poisson: float) -> np.ndarray:
    """Surface compliance ``u^ / p^`` (m/Pa, times m^2 of the transform) of the bonded layer at
    wavenumbers ``|k|`` (1/m): ``2 (1 - nu^2) / E * t * F(|k| t) / (|k| t)``, its long-wave
    limit ``t (1 + nu)(1 - 2 nu) / (E (1 - nu))`` (the column compliance) below
    :data:`SMALL_WAVE`."""
    k = np.abs(np.asarray(wavenumber, dtype=float))
    s = k * thickness
    kappa = 3.0 - 4.0 * poisson
    limit = 4.0 * (kappa - 1.0) / (1.0 + kappa) ** 2
    small = s < SMALL_WAVE
    ratio = np.where(small, limit, layer_factor(np.where(small, 1.0, s), poisson) / np.where(small, 1.0, s))
    return 2.0 * (1.0 - poisson**2) / modulus * thickness * ratio


@lru_cache(maxsize=16)
def _transfer(
    nz: int, nt: int, radius: float, dz: float, thickness: float, modulus: float, poisson: float, aliases: int
) -> tuple[np.ndarray, int]:
    """The discrete transfer function (rfft2 layout, rows the padded axial modes) and the
    padded axial length."""
    padded = sfft.next_fast_len(2 * nz, real=True)
    dx = radius * 2.0 * np.pi / nt
    kz = 2.0 * np.pi * np.fft.fftfreq(padded, d=dz)  # (padded,)
    kx = np.arange(nt // 2 + 1) / radius  # circumferential modes n / R, rfft half
    shift = np.arange(-aliases, aliases + 1)
    transfer = np.zeros((padded, kx.size))
    # Sum over the aliases of the circumferential wavenumber one at a time (2A + 1 passes over a
    # grid-sized array, vectorised over the nodes and the axial aliases).
    kz_all = kz[:, None] + (2.0 * np.pi / dz) * shift[None, :]  # (padded, 2A+1)
    sinc_z = np.sinc(kz_all * dz / (2.0 * np.pi))
    for lx in shift:
        kx_l = kx + (2.0 * np.pi / dx) * lx  # (nkx,)
        sinc_x = np.sinc(kx_l * dx / (2.0 * np.pi))
        k = np.hypot(kz_all[:, :, None], kx_l[None, None, :])  # (padded, 2A+1, nkx)
        transfer += np.einsum(
            "zak,za->zk", layer_compliance(k, thickness, modulus, poisson) * sinc_x[None, None, :], sinc_z
        )
    transfer.setflags(write=False)
    return transfer, padded


@dataclass(frozen=True, eq=False)
class ElasticLayer:
    """The discrete surface compliance of a bonded elastic layer on a bore grid, applied by FFT.

    Attributes
    ----------
    shape : tuple of int
        Grid (nz, nt): axial rows from end to end, circumferential columns (periodic).
    transfer : ndarray
        Node displacement per unit cell pressure for each Fourier mode, m/Pa (rfft2 layout of the
        padded grid ``(padded, nt // 2 + 1)``).
    padded : int
        Axial length of the zero-padded grid (at least ``2 nz``).
    """

    shape: tuple[int, int]
    transfer: np.ndarray
    padded: int
    half_end_cells: bool = False

    def apply(self, pressure: np.ndarray) -> np.ndarray:
        """Surface displacement (m) for cell pressures ``pressure`` (Pa), shape (..., nz, nt).

        With ``half_end_cells`` the two end rows' pressures are halved first: a bearing's end
        node carries the half cell inside the bearing (its trapezoid weight), spread here over a
        full cell centred on the node (the same force, its centre a quarter cell outwards)."""
        nz, nt = self.shape
        if self.half_end_cells:
            pressure = np.array(pressure, dtype=float)
            pressure[..., [0, -1], :] *= 0.5
        spectrum = sfft.rfft2(pressure, s=(self.padded, nt), axes=(-2, -1))
        return sfft.irfft2(spectrum * self.transfer, s=(self.padded, nt), axes=(-2, -1))[..., :nz, :]

    @property
    def self_compliance(self) -> float:
        """Displacement of a node under a unit pressure on its own cell only, m/Pa: the
        diagonal of the compliance matrix (the mean of the transfer over the modes)."""
        nz, nt = self.shape
        weights = np.full(self.transfer.shape[1], 2.0)
        weights[0] = 1.0
        if nt % 2 == 0:
            weights[-1] = 1.0
        return float((self.transfer * weights[None, :]).sum() / (self.padded * nt))


def layer_operator(
    shape: tuple[int, int],
    radius: float,
    dz: float,
    thickness: float,
    modulus: float,
    poisson: float,
    aliases: int = ALIASES,
    half_end_cells: bool = False,
) -> ElasticLayer:
    """The :class:`ElasticLayer` of a grid of ``shape`` (nz, nt) on a bore of ``radius`` (m), axial
    step ``dz`` (m), for a layer of ``thickness`` (m), ``modulus`` (Pa) and ``poisson``
    (``half_end_cells``: see :meth:`ElasticLayer.apply`).

    Examples
    --------
    Seed 001's liner (20 mm, 2320 MPa, 0.327) under 1 MPa over the whole bearing: the column law
    (5.881 um) inside, half of it at the end rows, where the load stops (a column liner would
    take the full 5.881 um there):

    >>> layer = layer_operator((41, 120), 0.1615, 0.03, 0.02, 2.32e9, 0.327, half_end_cells=True)
    >>> u = layer.apply(np.full((41, 120), 1e6))
    >>> round(float(u[20, 0]) * 1e6, 3), round(float(u[0, 0]) * 1e6, 3)
    (5.881, 2.941)
    """
    nz, nt = shape
    transfer, padded = _transfer(nz, nt, radius, dz, thickness, modulus, poisson, aliases)
    return ElasticLayer(shape=(nz, nt), transfer=transfer, padded=padded, half_end_cells=half_end_cells)
