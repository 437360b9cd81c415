"""Figures of a lubricated contact: the Stribeck-like friction against Lambda with the
lubrication bands, and pressure and film over the load and speed sweeps.

Each function draws into the axes it is given (``ax=``) and returns them; without axes it
makes a pyplot figure of its own (see :mod:`shaftline.report.plotting`).
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

import numpy as np

from shaftline.contact.friction import FULL_FILM_RATIO
from shaftline.report.plotting import figure_function

if TYPE_CHECKING:
    from shaftline.contact.study import ContactResult

#: Lambda at which the Zhu-Hu film share g reaches 0.5 (boundary-dominated below).
BOUNDARY_RATIO = 0.2697


@figure_function(size=(8, 4.5))
def stribeck(result: ContactResult, *, ax: Any) -> Any:
    """Friction coefficient against Lambda over the speed sweep (slide-to-roll ratio kept), with
    the boundary-dominated (g < 0.5), mixed and full-film (Lambda >= 2) bands."""
    sweep, op = result.speed_sweep, result.operating
    lam = sweep.film_ratio
    ax.axvspan(
        min(lam.min(), BOUNDARY_RATIO) * 0.8,
        BOUNDARY_RATIO,
        color="C3",
        alpha=0.12,
        label="boundary-dominated (g < 0.5)",
    )
    ax.axvspan(BOUNDARY_RATIO, FULL_FILM_RATIO, color="C1", alpha=0.12, label="mixed")
    ax.axvspan(
        FULL_FILM_RATIO, max(lam.max(), FULL_FILM_RATIO) * 1.25, color="C2", alpha=0.12, label="full film (g = 1)"
    )
    ax.semilogx(lam, sweep.friction, "C0", lw=2, label="f = c f_a (seed 002)")
    ax.semilogx(lam, sweep.mixed_friction, "C0--", lw=1, label="f_a (Eq. 1)")
    ax.semilogx(lam, sweep.full_film_friction, "C4:", lw=1, label="f_c (Eq. 5)")
    ax.plot(float(op.film_ratio), float(op.friction), "ko", label="operating point")
    ax.set_xlabel("film thickness ratio Lambda = h_c / sqrt(Rq1² + Rq2²) [-]")
    ax.set_ylabel("friction coefficient [-]")
    factors = result.study.speed_factors
    ax.set_title(f"Friction against Lambda, speeds x{factors[0]:g}-{factors[-1]:g}, S = {float(op.slide_roll):.2f}")
    ax.legend(fontsize=7, loc="upper right")
    return ax


@figure_function(layout=(1, 2), size=(11, 4.2))
def sweeps(result: ContactResult, *, ax: Any) -> Any:
    """Hertz pressure and central film against load (left); central and minimum film and
    Lambda against rolling speed (right)."""
    left, right = ax
    study, load, speed = result.study, result.load_sweep, result.speed_sweep
    line = study.model.geometry == "line"
    loads = study.load * study.load_factors
    scale, unit = (1e-3, "N/mm") if line else (1.0, "N")
    left.plot(loads * scale, load.peak_pressure / 1e9, "C3", label="Hertz p_H")
    left.set_xlabel(f"load [{unit}]")
    left.set_ylabel("peak Hertz pressure [GPa]", color="C3")
    film = left.twinx()
    film.plot(loads * scale, load.central_film * 1e6, "C0", label="h_c")
    film.set_ylabel("central film [µm]", color="C0")
    left.set_title("Pressure and film against load")
    u = speed.rolling_speed
    right.loglog(u, speed.central_film * 1e6, "C0", label="h_c (thermal)")
    if np.all(np.isfinite(speed.minimum_film)):
        right.loglog(u, speed.minimum_film * 1e6, "C0--", label="h_min")
    right.set_xlabel("rolling speed u = (u1 + u2)/2 [m/s]")
    right.set_ylabel("film [µm]")
    ratio = right.twinx()
    ratio.semilogx(u, speed.film_ratio, "C2", label="Lambda")
    ratio.axhline(FULL_FILM_RATIO, color="C2", ls=":", lw=0.8)
    ratio.set_ylabel("Lambda [-]", color="C2")
    right.axvline(float(result.operating.rolling_speed), color="k", lw=0.8, ls="--")
    right.set_title("Film and Lambda against speed")
    right.legend(fontsize=7, loc="upper left")
    return ax
