"""Figures of a gear scuffing rating: the contact along the path of contact at the highest torque
step, and SP against the torque steps with the 0.7 and 1 bands beside ISO's safety factor.

Each function draws into the axes it is given (``ax=``) and returns them; without axes it
makes a pyplot figure of its own (see :mod:`shaftline.report.plotting`).
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

import numpy as np

from shaftline.gears.scuffing import NO_SCUFFING, SCUFFING
from shaftline.report.plotting import figure_function

if TYPE_CHECKING:
    from shaftline.gears.study import GearResult


@figure_function(layout=(2, 3), size=(13, 7), sharex=True)
def along_path(result: GearResult, *, ax: Any) -> Any:
    """Hertz pressure, central film, Lambda, friction coefficient, frictional power intensity and
    ISO flash temperature along A..E, at the highest torque step and the test speed."""
    study, state = result.study, result.state
    pair = study.mesh.pair
    x = (state.path.position - pair.pitch_point) * 1e3
    top = len(study.torques) - 1
    c = state.contact
    panels = [
        (c.peak_pressure[top, 0] / 1e9, "Hertz pressure p_H [GPa]"),
        (c.central_film[top, 0] * 1e6, "central film h_c [µm]"),
        (c.film_ratio[top, 0], "Lambda [-]"),
        (c.friction[top, 0], "friction coefficient f (seed 002) [-]"),
        (c.power_intensity[top, 0] / 1e6, "f p_H |Δu| [MW/m²]"),
    ]
    flat = ax.ravel()
    for axis, (values, label) in zip(flat, panels, strict=False):
        axis.plot(x, values, "C0")
        axis.set_ylabel(label)
    flat[2].axhline(2.0, color="C2", ls=":", lw=0.8)
    last = flat[5]
    if result.iso is not None:
        last.plot(x, result.iso.flash[top, 0], "C3")
        last.set_ylabel("ISO flash temperature [K]")
    else:
        last.text(0.5, 0.5, "no [gears.iso]", ha="center", va="center", transform=last.transAxes)
    points = pair.points()
    for axis in flat:
        for name in "ABCDE":
            axis.axvline((points[name] - pair.pitch_point) * 1e3, color="0.7", lw=0.6, ls="--")
    for axis in ax[-1]:
        axis.set_xlabel("from the pitch point C [mm]")
    speed = float(study.speeds[0]) * 30.0 / np.pi
    ax[0][0].set_title(f"T = {study.torques[top]:g} N m, {speed:.0f} rpm", fontsize=9)
    return ax


@figure_function(size=(9, 4.8))
def sp_steps(result: GearResult, *, ax: Any) -> Any:
    """SP against the torque steps at the test speed, with the no-scuffing (< 0.7) and scuffing
    (> 1) bands, and ISO's S_B (and S_intS) on a second axis."""
    torques = result.study.torques
    sp = result.sp[:, 0]
    top = max(float(sp.max()) * 1.1, 1.3)
    ax.axhspan(0.0, NO_SCUFFING, color="C2", alpha=0.12, label="SP < 0.7: no scuffing")
    ax.axhspan(NO_SCUFFING, SCUFFING, color="C1", alpha=0.12, label="0.7-1: uncertain")
    ax.axhspan(SCUFFING, top, color="C3", alpha=0.12, label="SP > 1: scuffing")
    ax.plot(torques, sp, "C0o-", label="SP (seed 002 Eq. 7)")
    ax.set_ylim(0.0, top)
    ax.set_xlabel("pinion torque step [N m]")
    ax.set_ylabel("scuffing parameter SP [-]")
    if result.iso is not None:
        safety = ax.twinx()
        safety.semilogy(torques, result.iso.safety[:, 0], "C3s--", label="ISO S_B (TS 6336-20)")
        if result.integral is not None:
            safety.semilogy(torques, result.integral.safety[:, 0], "C4^:", label="ISO S_intS (TS 6336-21)")
        safety.axhline(1.0, color="C3", lw=0.8, ls=":")
        safety.set_ylabel("ISO/TS 6336-20/-21 safety S_B, S_intS [-]", color="C3")
        safety.legend(fontsize=7, loc="upper center")
    ax.legend(fontsize=7, loc="upper left")
    ax.set_title(f"Scuffing against torque at {float(result.study.speeds[0]) * 30.0 / np.pi:.0f} rpm")
    return ax
