"""CPP blade bearings as a capability: ``[cpp]`` in a case file, ``shaftline cpp fretting``
and ``shaftline cpp motion``, ``cpp`` in results.json, a section of the report."""

from __future__ import annotations

import math
from collections.abc import Sequence
from typing import TYPE_CHECKING, Any

from shaftline.helptext import strict_help
from shaftline.registry import BuildContext, Capability, Comparison, Finding, Progress, Verb, no_progress
from shaftline.report.blocks import Block, Figure, Heading, Paragraph, Table

if TYPE_CHECKING:
    from shaftline.cpp.case import CppSection
    from shaftline.cpp.study import BladeBearingResult, BladeBearingStudy


#: Display unit and scale of the values of each study parameter.
STUDY_DISPLAY = {
    "holding_moment": ("kN m", 1e-3),
    "backlash": ("mm", 1e3),
    "oil_stiffness": ("MN/m", 1e-6),
    "water_inertia": ("kg m²", 1.0),
    "spindle_scale": ("", 1.0),
}


def finite_or_none(value: float | None) -> float | None:
    """``value`` if it is a finite number, else None (JSON has no infinity)."""
    return value if value is not None and math.isfinite(value) else None


def periodicity(motion: dict[str, Any]) -> str:
    """The periodic state of a motion's JSON in words: reached or not, the period, the change
    from one cycle to the next and the tolerance."""
    change = motion["periodic_change"]
    if change is None and motion["revolutions"] < 2:
        return f"not judged (fewer than two revolutions; tolerance {motion['periodic_tolerance']:.0e})"
    if change is None:
        return "not reached: the carrier came to rest after moving"
    cycle = "every revolution" if motion["period"] == 1 else f"every {motion['period']} revolutions"
    if motion["periodic"]:
        return f"reached: repeats {cycle} to {change:.0e} (tolerance {motion['periodic_tolerance']:.0e})"
    return (
        f"not reached: closest {cycle}, change {change:.0e} > tolerance {motion['periodic_tolerance']:.0e}; "
        "settled values from the second half"
    )


#: ``--strict`` of the cpp verbs: BladeBearings.findings has one finding, a criterion.
CPP_STRICT = strict_help(
    "the blade bearing frets grossly: the spindle torque overcomes the friction torque both ways every "
    "revolution (with several case files, in any of them)"
)


class BladeBearings(Capability["CppSection", "BladeBearingStudy", "BladeBearingResult"]):
    key = "cpp"
    title = "CPP blade bearing: friction and fretting"
    verbs = (
        Verb(
            ("cpp", "fretting"),
            "Friction torque, fretting coefficient and hydraulic pressures over a revolution; with several "
            "case files, the propellers ranked by fretting risk.",
            options={"motion": False},
            many=True,
            strict=CPP_STRICT,
        ),
        Verb(
            ("cpp", "motion"),
            "Fretting motion of the blade carrier over revolutions (oil spring, backlash, friction law).",
            strict=CPP_STRICT,
        ),
    )

    def schema(self) -> type[CppSection]:
        from shaftline.cpp.case import CppSection

        return CppSection

    def build(self, section: CppSection, context: BuildContext) -> BladeBearingStudy:
        from shaftline.cpp.case import build_study

        return build_study(section, context)

    def solve(
        self, study: BladeBearingStudy, progress: Progress = no_progress, motion: bool = True, **options: Any
    ) -> BladeBearingResult:
        from shaftline.cpp.study import solve_blade_bearing

        return solve_blade_bearing(study, motion, lambda step: progress(f"solving {step}"))

    def to_json(self, result: BladeBearingResult) -> dict[str, Any]:
        from shaftline.cpp.study import settled_amplitude

        c = result.coefficient
        out: dict[str, Any] = {
            "units": {"torque": "N m", "angle": "deg", "pressure": "Pa", "amplitude": "m", "sliding": "m"},
            "spindle_torque_mean": float(result.study.loads.spindle_torque.mean()),
            "friction_torque_mean": float(result.friction.total.mean()),
            "k_fret_max": c.maximum,
            "k_fret_min": c.minimum,
            "fretting_windows_positive_deg": [[math.degrees(a), math.degrees(b)] for a, b in c.windows_positive],
            "fretting_windows_negative_deg": [[math.degrees(a), math.degrees(b)] for a, b in c.windows_negative],
            "gross_fretting_both_ways": c.fretting,
            "f_fret_critical_positive": result.critical[0],
            "f_fret_critical_negative": result.critical[1],
            "distribution_factor_min": float(result.friction.distribution_factor.min()),
            "hydraulic_pressure": result.pressures,
        }
        if result.motion is not None:
            m = result.motion
            out["motion"] = {
                "revolutions": m.revolutions,
                "revolutions_requested": m.requested_revolutions,
                "method": m.method,
                "periodic": m.periodic,
                "period": m.period,
                # null when not judged, or without bound (a carrier come to rest): JSON has no inf
                "periodic_change": finite_or_none(m.periodic_change),
                "periodic_tolerance": m.periodic_tolerance,
                "fretting_amplitude": float(m.amplitude[-1]),
                "fretting_amplitude_settled": dict(zip(("max", "mean", "min"), settled_amplitude(m), strict=True)),
                "sliding_per_revolution": float(m.sliding_per_revolution[-1]),
                "pressure_fluctuation": float(m.force_fluctuation[-1] / result.study.yoke_area),
            }
        if result.parameter_study is not None and result.study.study is not None:
            out["study"] = {
                "parameter": result.study.study.parameter,
                "values": [v for v, _ in result.parameter_study],
                "fretting_amplitude": [float(m.amplitude[-1]) for _, m in result.parameter_study],
                "fretting_amplitude_settled_max": [settled_amplitude(m)[0] for _, m in result.parameter_study],
                "revolutions": result.study.study.revolutions,
                "revolutions_integrated": [m.revolutions for _, m in result.parameter_study],
                "periodic": [m.periodic for _, m in result.parameter_study],
                "period": [m.period for _, m in result.parameter_study],
            }
        return out

    def _table(self, result: BladeBearingResult) -> Table:
        s = self.to_json(result)

        def windows(ws: list[list[float]]) -> str:
            return ", ".join(f"{a:.0f}-{b:.0f}" for a, b in ws) or "none"

        def critical(value: float | None) -> str:
            return "-" if value is None else f"{value:.3f}"

        rows = [
            ["mean spindle torque [kN m]", f"{s['spindle_torque_mean'] / 1e3:.1f}"],
            ["mean friction torque [kN m]", f"{s['friction_torque_mean'] / 1e3:.1f}"],
            ["k_fret max / min [-]", f"{s['k_fret_max']:.3f} / {s['k_fret_min']:.3f}"],
            ["gross fretting, M_sp > Q_fr [deg]", windows(s["fretting_windows_positive_deg"])],
            ["gross fretting, M_sp < -Q_fr [deg]", windows(s["fretting_windows_negative_deg"])],
            [
                "critical f_fret + / - [-]",
                f"{critical(s['f_fret_critical_positive'])} / {critical(s['f_fret_critical_negative'])}",
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
                [
                    "fretting amplitude at bearing radius, settled max / min [µm]",
                    f"{m['fretting_amplitude_settled']['max'] * 1e6:.1f} / "
                    f"{m['fretting_amplitude_settled']['min'] * 1e6:.1f}",
                ],
                ["sliding per revolution [mm]", f"{m['sliding_per_revolution'] * 1e3:.3f}"],
                ["oil pressure fluctuation [bar]", f"{m['pressure_fluctuation'] / 1e5:.3f}"],
                ["revolutions integrated (asked for)", f"{m['revolutions']} ({m['revolutions_requested']})"],
                ["periodic state", periodicity(m)],
            ]
        return Table(["quantity", "value"], rows, "CPP blade bearing")

    def findings(self, result: BladeBearingResult) -> list[Finding]:
        c = result.coefficient
        if not c.fretting:
            return []
        return [
            Finding(
                f"gross fretting in both directions every revolution: the spindle torque overcomes the friction "
                f"torque (k_fret from {c.minimum:.2f} to {c.maximum:.2f}); the blade bearing slides back and forth.",
                criterion=True,
            )
        ]

    def _unsettled(self, result: BladeBearingResult) -> list[Block]:
        """A warning when the motion was asked to stop at its periodic state and never reached
        it: its settled amplitudes are then extremes of the run's second half, not of a cycle."""
        m = result.motion
        if m is None or m.periodic or m.revolutions < 2 or m.periodic_change is None:
            return []  # periodic, too short to judge, or come to rest
        state = periodicity(
            {
                "periodic_change": m.periodic_change,
                "revolutions": m.revolutions,
                "period": m.period,
                "periodic": m.periodic,
                "periodic_tolerance": m.periodic_tolerance,
            }
        )
        return [
            Paragraph(
                f"The carrier motion did not become periodic in {m.revolutions} revolutions "
                f"({state}). The settled fretting amplitude is the extreme "
                "of the second half of the run and may still change with more revolutions; with "
                "backlash the motion may never repeat. Run more revolutions to see whether it settles.",
                "warn",
            )
        ]

    def summary(self, result: BladeBearingResult) -> list[Block]:
        return [*self._unsettled(result), self._table(result)]

    def report(self, result: BladeBearingResult) -> list[Block]:
        from shaftline.cpp import figures
        from shaftline.cpp.study import settled_amplitude

        blocks: list[Block] = [
            *self._unsettled(result),
            self._table(result),
            Figure("cpp_torques.png", figures.torques, (result,), caption="spindle and friction torque"),
        ]
        if result.motion is not None:
            blocks.append(Figure("cpp_motion.png", figures.motion, (result,), caption="fretting motion"))
        if result.parameter_study is not None and result.study.study is not None:
            st = result.study.study
            parameter = st.parameter
            unit, scale = STUDY_DISPLAY.get(parameter, ("", 1.0))
            blocks.append(Heading(f"Parameter study: {parameter.replace('_', ' ')}"))
            blocks.append(
                Paragraph(
                    f"At most {st.revolutions} revolutions per value, fewer where the motion became periodic first. "
                    "The amplitude is the largest of the settled revolutions (one cycle of a periodic motion, else "
                    "the second half): with backlash the motion need not repeat every revolution, so the last "
                    "revolution alone depends on how many were simulated."
                )
            )
            blocks.append(
                Table(
                    [
                        f"{parameter.replace('_', ' ')}{f' [{unit}]' if unit else ''}",
                        "fretting amplitude, settled max [µm]",
                        "settled min [µm]",
                        "revolutions",
                        "periodic",
                    ],
                    [
                        [
                            v if isinstance(v, str) else f"{v * scale:.4g}",
                            f"{settled_amplitude(m)[0] * 1e6:.1f}",
                            f"{settled_amplitude(m)[2] * 1e6:.1f}",
                            str(m.revolutions),
                            (f"every {m.period}" if m.period > 1 else "yes") if m.periodic else "no",
                        ]
                        for v, m in result.parameter_study
                    ],
                )
            )
        return blocks

    def compare(self, results: Sequence[tuple[str, BladeBearingResult]]) -> Comparison:
        from shaftline.cpp.study import rank

        ranking = rank(results)
        document = {
            "ranking": [
                {"case": name, "max_abs_k_fret": value, "gross_fretting_both_ways": both}
                for name, value, both in ranking
            ]
        }
        table = Table(
            ["case", "max |k_fret|", "fretting both ways"],
            [[name, f"{value:.3f}", "yes" if both else "no"] for name, value, both in ranking],
            "Fretting risk, highest first",
        )
        return Comparison(document, [table])


CAPABILITY = BladeBearings()
