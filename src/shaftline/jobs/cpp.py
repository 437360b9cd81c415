"""CPP blade-bearing jobs: friction torque and fretting coefficient over a revolution,
hydraulic pressures, and the blade-carrier fretting motion."""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np
from markupsafe import Markup

from shaftline.cases.cpp_schema import CppCase
from shaftline.cpp.fretting import (
    FrettingCoefficient,
    critical_values,
    fretting_coefficient,
    thrust_fretting_coefficient,
)
from shaftline.cpp.hydraulics import hydraulic_pressures
from shaftline.cpp.loads import FrictionTorque, friction_torque
from shaftline.cpp.motion import CarrierModel, CarrierMotion, parameter_study, simulate_carrier
from shaftline.report import cpp_figures
from shaftline.report.html import Section, image, table


@dataclass(frozen=True)
class CppRun:
    case: CppCase
    friction: FrictionTorque
    coefficient: FrettingCoefficient
    f_fret: np.ndarray
    critical: tuple[float | None, float | None]
    pressures: dict[str, float]
    motion: CarrierMotion | None
    study: list[tuple[Any, float]] | None = None

    def summary(self) -> dict[str, Any]:
        c = self.coefficient
        out: dict[str, Any] = {
            "units": {"torque": "N m", "angle": "deg", "pressure": "Pa", "amplitude": "m", "sliding": "m"},
            "spindle_torque_mean": float(self.case.loads.spindle_torque.mean()),
            "friction_torque_mean": float(self.friction.total.mean()),
            "k_fret_max": c.maximum,
            "k_fret_min": c.minimum,
            "fretting_windows_positive_deg": [
                [float(np.degrees(a)), float(np.degrees(b))] for a, b in c.windows_positive
            ],
            "fretting_windows_negative_deg": [
                [float(np.degrees(a)), float(np.degrees(b))] for a, b in c.windows_negative
            ],
            "gross_fretting_both_ways": c.fretting,
            "f_fret_critical_positive": self.critical[0],
            "f_fret_critical_negative": self.critical[1],
            "distribution_factor_min": float(self.friction.distribution_factor.min()),
            "hydraulic_pressure": self.pressures,
        }
        if self.motion is not None:
            out["motion"] = {
                "revolutions": self.motion.revolutions,
                "fretting_amplitude": float(self.motion.amplitude[-1]),
                "sliding_per_revolution": float(self.motion.sliding_per_revolution[-1]),
                "pressure_fluctuation": float(self.motion.force_fluctuation[-1] / self.case.yoke_area),
            }
        if self.study is not None:
            out["study"] = {
                "parameter": self.case.study["parameter"],
                "values": [v for v, _ in self.study],
                "fretting_amplitude": [a for _, a in self.study],
            }
        return out


def solve_cpp(case: CppCase, motion: bool = True) -> CppRun:
    loads = case.loads
    friction = friction_torque(loads, case.bearing)
    coefficient = fretting_coefficient(loads.spindle_torque, friction.total, loads.angle)
    total_thrust = case.blades * float(loads.thrust.mean())
    f_fret = thrust_fretting_coefficient(loads.spindle_torque, total_thrust, case.blades, case.radius_07)
    pressures = hydraulic_pressures(
        float(loads.spindle_torque.mean()),
        float(friction.total.mean()),
        case.blades,
        case.pin_radius,
        case.pitch_angle,
        case.yoke_area,
        case.other_friction,
        case.counterbalance_pressure,
    )
    carrier = None
    study = None
    if motion and case.motion is not None:
        m = case.motion
        model = CarrierModel(
            inertia=m["inertia"],
            water_inertia=m["water_inertia"],
            speed=case.speed,
            angle=loads.angle,
            spindle_torque=loads.spindle_torque,
            coulomb_torque=friction.total,
            oil_stiffness=case.oil_stiffness,
            pin_radius=case.pin_radius,
            pitch_angle=case.pitch_angle,
            backlash=case.backlash,
            bearing_radius=case.bearing.radius,
            friction=m["friction"],
            stiffness=m["stiffness"],
            damping=m["damping"],
            stribeck_velocity=m["stribeck_velocity"],
            threshold_velocity=m["threshold_velocity"],
        )
        carrier = simulate_carrier(model, m["revolutions"])
        if case.study is not None:
            st = case.study
            motions = parameter_study(model, st["parameter"], st["values"], st["revolutions"])
            study = [(value, float(result.amplitude[-1])) for value, result in zip(st["values"], motions, strict=True)]
    return CppRun(
        case,
        friction,
        coefficient,
        f_fret,
        critical_values(coefficient, f_fret),
        pressures,
        carrier,
        study if carrier is not None and case.study is not None else None,
    )


def cpp_table_rows(run: CppRun) -> tuple[list[str], list[list[str]]]:
    s = run.summary()
    windows = lambda ws: ", ".join(f"{a:.0f}-{b:.0f}" for a, b in ws) or "none"  # noqa: E731
    rows = [
        ["mean spindle torque [kN m]", f"{s['spindle_torque_mean'] / 1e3:.1f}"],
        ["mean friction torque [kN m]", f"{s['friction_torque_mean'] / 1e3:.1f}"],
        ["k_fret max / min [-]", f"{s['k_fret_max']:.3f} / {s['k_fret_min']:.3f}"],
        ["gross fretting, M_sp > Q_fr [deg]", windows(s["fretting_windows_positive_deg"])],
        ["gross fretting, M_sp < -Q_fr [deg]", windows(s["fretting_windows_negative_deg"])],
        [
            "critical f_fret + / - [-]",
            f"{s['f_fret_critical_positive'] or float('nan'):.3f} / "
            f"{s['f_fret_critical_negative'] or float('nan'):.3f}",
        ],
        ["smallest load distribution factor u [-]", f"{s['distribution_factor_min']:.3f}"],
        [
            "hydraulic pressure ahead / holding / astern [bar]",
            " / ".join(f"{s['hydraulic_pressure'][k] / 1e5:.1f}" for k in ("ahead", "holding", "astern")),
        ],
    ]
    if "motion" in s:
        m = s["motion"]
        rows += [
            ["fretting amplitude at bearing radius [um]", f"{m['fretting_amplitude'] * 1e6:.1f}"],
            ["sliding per revolution [mm]", f"{m['sliding_per_revolution'] * 1e3:.3f}"],
            ["oil pressure fluctuation [bar]", f"{m['pressure_fluctuation'] / 1e5:.3f}"],
        ]
    return ["quantity", "value"], rows


def cpp_section(run: CppRun, folder: Path) -> Section:
    figure_dir = folder / "figures"
    figure_dir.mkdir(exist_ok=True)
    parts = [table(*cpp_table_rows(run))]
    path = cpp_figures.torques(run, figure_dir / "cpp_torques.png")
    parts.append(image(f"figures/{path.name}", "spindle and friction torque"))
    if run.motion is not None:
        path = cpp_figures.motion(run, figure_dir / "cpp_motion.png")
        parts.append(image(f"figures/{path.name}", "fretting motion"))
    if run.study is not None:
        parameter = run.case.study["parameter"]
        parts.append(Markup(f"<h3>Parameter study: {parameter}</h3>"))
        parts.append(table([parameter, "fretting amplitude [um]"], [[str(v), f"{a * 1e6:.1f}"] for v, a in run.study]))
    return Section("CPP blade bearing: friction and fretting", Markup("").join(parts))
