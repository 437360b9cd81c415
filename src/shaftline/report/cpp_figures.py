"""Figures of the CPP blade bearing: spindle vs friction torque with the fretting windows,
fretting coefficient, and the carrier's fretting motion."""

from __future__ import annotations

from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402


def torques(run, path: Path) -> Path:
    loads, friction, coefficient = run.case.loads, run.friction, run.coefficient
    degrees = np.degrees(loads.angle)
    fig, (top, bottom) = plt.subplots(2, 1, figsize=(10, 7), sharex=True, constrained_layout=True)
    spindle = loads.spindle_torque / 1e3
    top.plot(degrees, spindle, "C0", label="spindle torque M_sp")
    top.plot(degrees, np.sign(spindle) * friction.total / 1e3, "C3", label="friction torque x sgn(M_sp)")
    for windows, color in ((coefficient.windows_positive, "C1"), (coefficient.windows_negative, "C2")):
        for a, b in windows:
            top.axvspan(np.degrees(a), np.degrees(b), color=color, alpha=0.2)
    top.set_ylabel("torque [kN m]")
    top.legend(fontsize=8)
    top.set_title("shaded: gross fretting (spindle torque overcomes friction)")
    bottom.plot(degrees, run.f_fret, "C0", label="f_fret = Z M_sp / (T R0.7)")
    for value in run.critical:
        if value is not None:
            bottom.axhline(value, color="k", ls="--", lw=0.8)
    bottom.set_xlabel("blade position [deg] (0 = top)")
    bottom.set_ylabel("fretting coefficient [-]")
    bottom.legend(fontsize=8)
    bottom.set_xlim(0, 360)
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return path


def motion(run, path: Path) -> Path:
    m = run.motion
    revolutions = min(m.revolutions, 2)
    keep = m.time >= m.time[-1] - revolutions * 2 * np.pi / run.case.speed
    degrees = np.degrees(run.case.speed * (m.time[keep] - m.time[keep][0]))
    fig, ax = plt.subplots(figsize=(10, 4), constrained_layout=True)
    ax.plot(degrees, m.rotation[keep] * run.case.bearing.radius * 1e6, "C0")
    ax.set_xlabel(f"blade position over the last {revolutions} revolutions [deg]")
    ax.set_ylabel("carrier displacement at bearing radius [µm]")
    ax.set_title(
        f"Fretting motion: amplitude {m.amplitude[-1] * 1e6:.0f} µm, "
        f"sliding {m.sliding_per_revolution[-1] * 1e3:.2f} mm per revolution"
    )
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return path
