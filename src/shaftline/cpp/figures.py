"""Figures of the CPP blade bearing: spindle against friction torque with the fretting
windows, the fretting coefficient, and the carrier's fretting motion.

Each function draws into the axes it is given (``ax=``) and returns them; without axes it
makes a pyplot figure of its own (see :mod:`shaftline.report.plotting`).
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

import numpy as np

from shaftline.report.plotting import figure_function

if TYPE_CHECKING:
    from shaftline.cpp.study import BladeBearingResult


@figure_function(layout=(2, 1), size=(10, 7), sharex=True)
def torques(result: BladeBearingResult, *, ax: Any) -> Any:
    """Spindle torque against the friction torque over a revolution with the gross-fretting
    windows (top) and the thrust-based fretting coefficient (bottom); ``ax`` is two axes."""
    top, bottom = ax
    loads, friction, coefficient = result.study.loads, result.friction, result.coefficient
    degrees = np.degrees(loads.angle)
    spindle = loads.spindle_torque / 1e3
    top.plot(degrees, spindle, "C0", label="spindle torque M_sp")
    top.plot(degrees, np.sign(spindle) * friction.total / 1e3, "C3", label="friction torque x sgn(M_sp)")
    for windows, color in ((coefficient.windows_positive, "C1"), (coefficient.windows_negative, "C2")):
        for a, b in windows:
            top.axvspan(np.degrees(a), np.degrees(b), color=color, alpha=0.2)
    top.set_ylabel("torque [kN m]")
    top.legend(fontsize=8)
    top.set_title("shaded: gross fretting (spindle torque overcomes friction)")
    bottom.plot(degrees, result.f_fret, "C0", label="f_fret = Z M_sp / (T R0.7)")
    for value in result.critical:
        if value is not None:
            bottom.axhline(value, color="k", ls="--", lw=0.8)
    bottom.set_xlabel("blade position [deg] (0 = top)")
    bottom.set_ylabel("fretting coefficient [-]")
    bottom.legend(fontsize=8)
    bottom.set_xlim(0, 360)
    return ax


@figure_function(size=(10, 4))
def motion(result: BladeBearingResult, *, ax: Any) -> Any:
    """Carrier displacement at the bearing radius over the last two simulated revolutions."""
    m = result.motion
    if m is None:
        raise ValueError("the result has no carrier motion")
    speed = result.study.speed
    revolutions = min(m.revolutions, 2)
    keep = m.time >= m.time[-1] - revolutions * 2 * np.pi / speed
    degrees = np.degrees(speed * (m.time[keep] - m.time[keep][0]))
    ax.plot(degrees, m.rotation[keep] * result.study.bearing.radius * 1e6, "C0")
    ax.set_xlabel(f"blade position over the last {revolutions} revolutions [deg]")
    ax.set_ylabel("carrier displacement at bearing radius [µm]")
    ax.set_title(
        f"Fretting motion: amplitude {m.amplitude[-1] * 1e6:.0f} µm, "
        f"sliding {m.sliding_per_revolution[-1] * 1e3:.2f} mm per revolution"
    )
    return ax
