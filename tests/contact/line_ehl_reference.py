"""A numerical solution of the isothermal EHL line contact, the reference the film formulas are
checked against (docs/validation.md, "Lubricated contacts"; docs/theory.md Sect. 15.2).

Not part of the package: a test reference written independently of ``shaftline.contact.ehl``.
The steady problem in Hertzian units (x = b X, p = p_H P, h = b^2/R H, Venner & Lubrecht 2000,
Ch. 10) is solved by a semi-smooth Newton method on the complete coupled system:

* Reynolds, ``d/dX (rho H^3 / (eta lambda) dP/dX) - d(rho H)/dX = 0`` with
  ``lambda = 12 eta0 u R^2 / (b^3 p_H)`` on the mean entraining speed u, written as the
  complementarity ``min(P, -R(P)) = 0`` (Reynolds' outlet condition: P >= 0 and no flow
  created where the film has cavitated); central differences for the Poiseuille term, a
  second-order upwind difference for the wedge term;
* the gap ``H = H0 + X^2/2 - 1/pi int P(S) ln|X - S| dS`` of two elastic half-spaces in plane
  strain, with the pressure piecewise constant over each cell and the cell integrals of ln
  exact;
* the load balance ``int P dX = pi/2``, which fixes H0;
* viscosity by Roelands (z from Barus' alpha at p = 0, p_0 = 1.96e8 Pa) or Barus; density
  constant or by Dowson & Higginson.

Each Newton step solves the dense (n - 1)^2 system directly; the local partial derivatives of
the Reynolds residual are taken by complex step (exact to round-off) on four interleaved node
colours.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

ROELANDS_PRESSURE = 1.96e8  # Pa


@dataclass(frozen=True)
class LineFilm:
    """A converged solution: central film (at X = 0) and minimum film in metres, the grid
    in Hertzian units and the Newton iterations it took."""

    central: float
    minimum: float
    x: np.ndarray
    pressure: np.ndarray
    film: np.ndarray
    iterations: int


def _cell_log_integrals(x: np.ndarray, dx: float) -> np.ndarray:
    """int over cell j of ln|x_i - s| ds, from F(t) = t ln|t| - t."""

    def antiderivative(t: np.ndarray) -> np.ndarray:
        safe = np.where(t == 0.0, 1.0, t)
        return np.where(t == 0.0, 0.0, safe * np.log(np.abs(safe)) - safe)

    d = x[:, None] - x[None, :]
    return antiderivative(d + dx / 2) - antiderivative(d - dx / 2)


def solve_line_ehl(
    load_per_length: float,
    reduced_radius: float,
    reduced_modulus: float,
    mean_speed: float,
    viscosity: float,
    alpha: float,
    *,
    viscosity_law: str = "roelands",
    compressible: bool = False,
    inlet: float = -8.0,
    outlet: float = 2.0,
    nodes: int = 601,
    max_iterations: int = 200,
) -> LineFilm:
    """Film of a steady, isothermal, fully flooded line contact.

    Parameters
    ----------
    load_per_length : N/m.
    reduced_radius : m, R with 1/R = 1/R1 + 1/R2.
    reduced_modulus : Pa, E' = 2 / ((1 - nu1^2)/E1 + (1 - nu2^2)/E2).
    mean_speed : m/s, (u1 + u2) / 2.
    viscosity : Pa s, at ambient pressure.
    alpha : 1/Pa, Barus' pressure-viscosity coefficient (Roelands' z is taken from it).
    inlet, outlet : ends of the domain in Hertzian half-widths b.
    nodes : grid nodes (uniform).
    """
    b = np.sqrt(8.0 * load_per_length * reduced_radius / (np.pi * reduced_modulus))
    hertz_pressure = 2.0 * load_per_length / (np.pi * b)
    lam = 12.0 * viscosity * mean_speed * reduced_radius**2 / (b**3 * hertz_pressure)
    x = np.linspace(inlet, outlet, nodes)
    dx = float(x[1] - x[0])
    elastic = -_cell_log_integrals(x, dx) / np.pi  # H = H0 + X^2/2 + elastic @ P

    eta_bar: Callable[[np.ndarray], np.ndarray]
    if viscosity_law == "roelands":
        ln_scale = np.log(viscosity) + 9.67
        z = alpha * ROELANDS_PRESSURE / ln_scale

        def eta_bar(p: np.ndarray) -> np.ndarray:
            return np.exp(ln_scale * (-1.0 + (1.0 + hertz_pressure * p / ROELANDS_PRESSURE) ** z))

    else:

        def eta_bar(p: np.ndarray) -> np.ndarray:
            return np.exp(alpha * hertz_pressure * p)

    def rho_bar(p: np.ndarray) -> np.ndarray:
        if not compressible:
            return np.ones_like(p)
        q = hertz_pressure * p
        return 1.0 + 0.6e-9 * q / (1.0 + 1.7e-9 * q)

    def reynolds(p: np.ndarray, h: np.ndarray) -> np.ndarray:
        """Residual at the interior nodes 1 .. n-2 (p holds the two zero end values)."""
        eps = rho_bar(p) * h**3 / (eta_bar(p) * lam)
        flux = 0.5 * (eps[1:] + eps[:-1]) * (p[1:] - p[:-1]) / dx**2
        rh = rho_bar(p) * h
        wedge = np.empty_like(rh)
        wedge[2:] = (1.5 * rh[2:] - 2.0 * rh[1:-1] + 0.5 * rh[:-2]) / dx
        wedge[1] = (rh[1] - rh[0]) / dx
        return flux[1:] - flux[:-1] - wedge[1:-1]

    def gap(p: np.ndarray, h0: float) -> np.ndarray:
        return h0 + 0.5 * x**2 + elastic @ p

    # Scaled so that both arguments of min() are of order one.
    scale = dx**2

    def system(p: np.ndarray, h0: float) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        h = gap(p, h0)
        r = reynolds(p, h)
        return np.append(np.minimum(p[1:-1], -scale * r), p.sum() * dx - np.pi / 2), r, h

    interior = nodes - 2
    rows = np.arange(interior)

    def jacobian(p: np.ndarray, h: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """dR/dP (through P and through H) and dR/dH0 at the interior nodes."""
        by_p = np.zeros((interior, nodes))
        by_h = np.zeros((interior, nodes))
        step = 1e-30
        for colour in range(4):
            probe = np.zeros(nodes)
            probe[colour::4] = 1.0
            r_p = reynolds(p + 1j * step * probe, h.astype(complex)).imag / step
            r_h = reynolds(p.astype(complex), h + 1j * step * probe).imag / step
            # Row i (node i + 1) sees the nodes i - 1 .. i + 2: one of each colour.
            cols = rows - 1 + (colour - (rows - 1)) % 4
            ok = (cols >= 0) & (cols < nodes)
            by_p[rows[ok], cols[ok]] = r_p[ok]
            by_h[rows[ok], cols[ok]] = r_h[ok]
        return (by_p + by_h @ elastic)[:, 1:-1], by_h.sum(axis=1)

    # Start: Hertz pressure and a gap of 0.1 b^2/R at the centre.
    p = np.sqrt(np.clip(1.0 - x**2, 0.0, None))
    p[[0, -1]] = 0.0
    h0 = 0.1 - float(np.interp(0.0, x, gap(p, 0.0)))
    for iteration in range(max_iterations):
        f, r, h = system(p, h0)
        norm = float(np.linalg.norm(f))
        if norm < 1e-10:
            return LineFilm(
                central=float(np.interp(0.0, x, h)) * b**2 / reduced_radius,
                minimum=float(h.min()) * b**2 / reduced_radius,
                x=x,
                pressure=p,
                film=h,
                iterations=iteration,
            )
        d_p, d_h0 = jacobian(p, h)
        on_bound = p[1:-1] <= -scale * r
        a = np.zeros((interior + 1, interior + 1))
        a[:interior, :interior] = np.where(on_bound[:, None], np.eye(interior), -scale * d_p)
        a[:interior, interior] = np.where(on_bound, 0.0, -scale * d_h0)
        a[interior, :interior] = dx
        step_ = np.linalg.solve(a, -f)
        t = 1.0
        with np.errstate(invalid="ignore", over="ignore"):
            while True:  # backtracking on the residual norm, keeping the gap open
                trial = p.copy()
                trial[1:-1] += t * step_[:interior]
                f_trial, _, h_trial = system(trial, h0 + t * step_[interior])
                if (np.all(h_trial > 0.0) and np.linalg.norm(f_trial) < (1.0 - 1e-4 * t) * norm) or t < 1e-4:
                    break
                t *= 0.5
        p, h0 = trial, h0 + t * float(step_[interior])
    raise RuntimeError(f"line EHL reference: no convergence in {max_iterations} Newton iterations")
