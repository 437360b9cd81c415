"""The jobs behind the command line, usable the same way from a notebook.

``solve_bearings`` and ``solve_alignment`` run what a case asks for; ``write_outputs``
writes JSON, figures and the HTML report into a folder, atomically (a temporary
folder renamed into place), so a failed run never leaves half an output.
"""

from __future__ import annotations

import json
import math
import os
import shutil
import tempfile
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from markupsafe import Markup

import shaftline
from shaftline.cases.alignment_schema import AlignmentCase
from shaftline.cases.schema import BearingCase, Case
from shaftline.film.bearing import Equilibrium, JournalBearing
from shaftline.film.dynamics import DynamicCoefficients, dynamic_coefficients
from shaftline.film.summary import EXTRA_UNITS, equilibrium_summary, units
from shaftline.report import alignment_figures, figures
from shaftline.report.html import Section, image, render, table
from shaftline.shaft.alignment import AlignmentModel, ConditionResult, InfluenceMatrix
from shaftline.shaft.jackup import JackUpCurve, JackUpFit, jack_up, reaction_from_jack_curve
from shaftline.shaft.offsets import OffsetPlan, offsets_from_reactions, optimise_offsets
from shaftline.shaft.rules import RuleCheck, check_rules
from shaftline.shaft.sag_gap import SagGap, sag_and_gap


@dataclass(frozen=True)
class BearingRun:
    """Result of one bearing problem of a case."""

    case: BearingCase
    equilibrium: Equilibrium
    coefficients: DynamicCoefficients | None

    def summary(self) -> dict[str, Any]:
        out = {"name": self.case.name}
        out.update(equilibrium_summary(self.equilibrium, self.coefficients))
        return out


def solve_bearing(case: BearingCase) -> BearingRun:
    """Equilibrium under the case load, then stiffness and damping there."""
    bearing = JournalBearing(case.geometry, case.operating, case.options)
    equilibrium = bearing.equilibrium(case.load_y, case.load_z, tilt_y=case.tilt_y, tilt_z=case.tilt_z)
    coefficients = None
    if equilibrium.converged and not equilibrium.contact:
        coefficients = dynamic_coefficients(bearing, equilibrium.state)
    return BearingRun(case=case, equilibrium=equilibrium, coefficients=coefficients)


def solve_bearings(case: Case, progress: Callable[[str], None] | None = None) -> list[BearingRun]:
    """Solve the base case and every variant of ``case``."""
    runs = []
    for bearing_case in case.bearings:
        if progress is not None:
            progress(bearing_case.name)
        runs.append(solve_bearing(bearing_case))
    return runs


def results_document(
    case: Case, runs: list[BearingRun], alignment: AlignmentRun | None = None, wear: Any = None, cpp: Any = None
) -> dict[str, Any]:
    """JSON document: the bearing film's base case at top level, further variants in
    ``variants``, the alignment under ``alignment`` and service wear under ``wear``."""
    document: dict[str, Any] = {"shaftline_version": shaftline.__version__, "case": case.name}
    if runs:
        summaries = [run.summary() for run in runs]
        document.update(summaries[0])
        document["variants"] = summaries[1:]
        document["units"] = {**units(), **EXTRA_UNITS}
    if alignment is not None:
        document["alignment"] = alignment.summary()
    if wear is not None:
        document["wear"] = wear.summary()
    if cpp is not None:
        document["cpp"] = cpp.summary()
    return document


def dumps(document: dict[str, Any]) -> str:
    return json.dumps(document, indent=2, allow_nan=False)


def write_text_atomic(path: Path, text: str) -> None:
    """Write ``text`` to ``path`` through a temporary file in the same folder."""
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    fd, temporary = tempfile.mkstemp(dir=path.parent, prefix=f".{path.name}.", suffix=".tmp")
    try:
        with os.fdopen(fd, "w", encoding="utf-8") as handle:
            handle.write(text)
        os.replace(temporary, path)
    except BaseException:
        Path(temporary).unlink(missing_ok=True)
        raise


@contextmanager
def atomic_folder(out: Path) -> Iterator[Path]:
    """Yield a temporary folder that replaces ``out`` only if the block completes."""
    out = Path(out)
    out.parent.mkdir(parents=True, exist_ok=True)
    temporary = Path(tempfile.mkdtemp(dir=out.parent, prefix=f".{out.name}."))
    try:
        yield temporary
        if out.exists():
            old = out.with_name(f".{out.name}.old")
            shutil.rmtree(old, ignore_errors=True)
            out.rename(old)
            temporary.rename(out)
            shutil.rmtree(old, ignore_errors=True)
        else:
            temporary.rename(out)
    except BaseException:
        shutil.rmtree(temporary, ignore_errors=True)
        raise


def _fmt(value: float, scale: float = 1.0, digits: int = 4) -> str:
    if value is None or (isinstance(value, float) and not math.isfinite(value)):
        return "-"
    return f"{value * scale:.{digits}g}"


#: (label, key, scale, digits) of the rows in the results tables.
TABLE_ROWS = [
    ("eccentricity ratio ε [-]", "eccentricity_ratio", 1.0, 4),
    ("attitude angle [deg]", "attitude_angle_deg", 1.0, 4),
    ("h_min [µm]", "min_film_thickness", 1e6, 4),
    ("h_min at θ [deg]", "min_film_theta_deg", 1.0, 4),
    ("h_min at z [m]", "min_film_z", 1.0, 4),
    ("p_max [MPa]", "max_pressure", 1e-6, 4),
    ("p_max at θ [deg]", "max_pressure_theta_deg", 1.0, 4),
    ("p_max at z [m]", "max_pressure_z", 1.0, 4),
    ("mean pressure [MPa]", "mean_pressure", 1e-6, 4),
    ("load centre from L/2 [m]", "load_centre_offset", 1.0, 4),
    ("friction coefficient [-]", "friction_coefficient", 1.0, 4),
    ("power loss [kW]", "power_loss", 1e-3, 4),
    ("inlet flow [l/min]", "inlet_flow", 6e4, 4),
    ("side leakage [l/min]", "side_leakage", 6e4, 4),
    ("Sommerfeld number S [-]", "sommerfeld_number", 1.0, 4),
]


def bearing_table_rows(runs: list[BearingRun]) -> tuple[list[str], list[list[str]]]:
    summaries = [run.summary() for run in runs]
    headers = ["quantity"] + [s["name"] for s in summaries]
    rows = [[label] + [_fmt(s[key], scale, digits) for s in summaries] for label, key, scale, digits in TABLE_ROWS]
    rows.append(["converged"] + ["yes" if s["converged"] else "NO" for s in summaries])
    rows.append(["contact (film at floor)"] + ["YES" if s["contact"] else "no" for s in summaries])
    return headers, rows


def bearing_section(runs: list[BearingRun], folder: Path) -> Section:
    """Report section of the stern-tube bearing: table, stiffness/damping, figures."""
    figure_dir = folder / "figures"
    figure_dir.mkdir(exist_ok=True)
    headers, rows = bearing_table_rows(runs)
    parts = [
        Markup(
            "<p>Film equilibrium under the case load with the journal tilt held at the given "
            "misalignment. Pressures are gauge; θ from the top of the bore in the sense of rotation; "
            "z from the aft edge.</p>"
        ),
        table(headers, rows),
    ]
    coefficient_rows = []
    for run in runs:
        if run.coefficients is None:
            continue
        k, c = run.coefficients.stiffness, run.coefficients.damping
        coefficient_rows.append(
            [run.case.name]
            + [_fmt(v, 1e-9) for v in (k[0, 0], k[0, 1], k[1, 0], k[1, 1])]
            + [_fmt(v, 1e-9) for v in (c[0, 0], c[0, 1], c[1, 0], c[1, 1])]
        )
    if coefficient_rows:
        parts.append(Markup("<h3>Film stiffness [kN/µm] and damping [kN·s/µm]</h3>"))
        parts.append(table(["case", "Kyy", "Kyz", "Kzy", "Kzz", "Cyy", "Cyz", "Czy", "Czz"], coefficient_rows))
    if len(runs) > 1:
        path = figures.comparison(
            [r.case.name for r in runs], [r.equilibrium.state for r in runs], figure_dir / "bearing_comparison.png"
        )
        parts.append(image(f"figures/{path.name}", "comparison of variants"))
    for index, run in enumerate(runs):
        state = run.equilibrium.state
        name = run.case.name
        parts.append(Markup(f"<h3>{Markup.escape(name)}</h3>"))
        for maker, stem in (
            (figures.film_and_pressure_maps, "maps"),
            (figures.circumferential_profile, "circumferential"),
            (figures.axial_profiles, "axial"),
        ):
            path = maker(state, name, figure_dir / f"bearing_{index}_{stem}.png")
            parts.append(image(f"figures/{path.name}", f"{name} {stem}"))
    return Section("Stern-tube bearing film", Markup("").join(parts))


def write_outputs(
    case: Case,
    runs: list[BearingRun],
    alignment: AlignmentRun | None,
    out: Path,
    case_file: str,
    wear: Any = None,
    cpp: Any = None,
) -> Path:
    """Write ``results.json``, figures and ``report.html`` into ``out`` (atomically)."""
    from shaftline.jobs.cpp import cpp_section
    from shaftline.jobs.wear import wear_section

    with atomic_folder(out) as folder:
        document = results_document(case, runs, alignment, wear, cpp)
        (folder / "results.json").write_text(dumps(document), encoding="utf-8")
        (folder / "figures").mkdir(exist_ok=True)
        sections = []
        if runs:
            sections.append(bearing_section(runs, folder))
        if alignment is not None:
            sections.append(alignment_section(alignment, folder))
        if wear is not None:
            sections.append(wear_section(wear, folder))
        if cpp is not None:
            sections.append(cpp_section(cpp, folder))
        html = render(case.name, case.description, case_file, sections)
        (folder / "report.html").write_text(html, encoding="utf-8")
    return Path(out)


# -- shaft alignment ---------------------------------------------------------------------------


@dataclass(frozen=True)
class AlignmentRun:
    """Everything an alignment case asked for."""

    case: AlignmentCase
    model: AlignmentModel
    results: list[ConditionResult]
    influence: InfluenceMatrix
    checks: list[RuleCheck]
    plan: OffsetPlan | None = None
    plan_checks: list[RuleCheck] | None = None
    sag_gap: SagGap | None = None
    jack: JackUpCurve | None = None
    jack_fit: JackUpFit | None = None
    reverse: tuple[dict[str, float], float] | None = None

    def summary(self) -> dict[str, Any]:
        out: dict[str, Any] = {
            "units": {
                "reaction_y": "N",
                "reaction_z": "N",
                "mean_pressure": "Pa",
                "shaft_slope": "rad",
                "relative_slope": "rad",
                "influence_matrix": "N/m",
                "offsets": "m",
                "sag": "m",
                "gap": "m",
                "max_stress": "Pa",
                "deflection": "m",
            },
            "conditions": [
                {
                    "name": r.name,
                    "max_stress": float(r.stress.max()),
                    "bearings": [
                        {
                            "name": b.name,
                            "reaction_y": b.reaction_y,
                            "reaction_z": b.reaction_z,
                            "mean_pressure": b.mean_pressure,
                            "contact": b.contact,
                            "shaft_slope": b.shaft_slope,
                            "relative_slope": b.relative_slope,
                        }
                        for b in r.bearings
                    ],
                    "elastic_line": {
                        "x": r.x.tolist(),
                        "deflection_y": r.deflection_y.tolist(),
                        "deflection_z": r.deflection_z.tolist(),
                        "rotation_y": r.rotation_y.tolist(),
                        "rotation_z": r.rotation_z.tolist(),
                        "moment_y": r.moment_y.tolist(),
                        "moment_z": r.moment_z.tolist(),
                        "shear_y": r.shear_y.tolist(),
                        "stress": r.stress.tolist(),
                    },
                }
                for r in self.results
            ],
            "influence_matrix": {"bearings": self.influence.names, "matrix": self.influence.matrix.tolist()},
            "rule_checks": [_check_dict(c) for c in self.checks],
            "slope_boring_angle": self.slope_boring_angle(),
        }
        if self.plan is not None:
            out["optimised_offsets"] = {
                "offsets": self.plan.offsets,
                "objective": self.plan.objective,
                "rule_checks": [_check_dict(c) for c in self.plan_checks or []],
            }
        if self.sag_gap is not None:
            out["sag_gap"] = {"flange_x": self.sag_gap.flange_x, "sag": self.sag_gap.sag, "gap": self.sag_gap.gap}
        if self.jack is not None:
            out["jack_up"] = {
                "bearing": self.jack.bearing,
                "jack_x": self.jack.jack_x,
                "reaction_before": self.jack.reaction_before,
                "liftoff_load": self.jack.liftoff_load,
                "correction_factor": self.jack.correction_factor,
                "curve": {"load": self.jack.loads.tolist(), "lift": self.jack.lifts.tolist()},
            }
            if self.jack_fit is not None:
                out["jack_up"]["measured"] = {
                    "knee_load": self.jack_fit.knee_load,
                    "reaction": self.jack_fit.reaction,
                    "residual": self.jack_fit.residual,
                }
        if self.reverse is not None:
            out["offsets_from_reactions"] = {"offsets": self.reverse[0], "rms_misfit": self.reverse[1]}
        return out

    def slope_boring_angle(self) -> dict[str, float]:
        """Per condition, the bore slope that would make the aft stern-tube bearing parallel to the shaft, rad."""
        aft = min(self.model.line.bearings, key=lambda b: b.x).name
        return {r.name: r.bearing(aft).shaft_slope for r in self.results}


def _check_dict(check: RuleCheck) -> dict[str, Any]:
    return {
        "rule": check.rule.id,
        "society": check.rule.society,
        "clause": check.rule.clause,
        "confidence": check.rule.confidence,
        "condition": check.condition,
        "bearing": check.bearing,
        "value": check.value,
        "comparison": check.rule.comparison,
        "limit": check.rule.limit,
        "passed": check.passed,
    }


def solve_alignment(case: AlignmentCase, progress: Callable[[str], None] | None = None) -> AlignmentRun:
    """All conditions, the influence matrix, rule checks and the procedures the case asks for."""
    step = progress or (lambda _: None)
    step("alignment conditions")
    model = AlignmentModel(case.line)
    results = model.solve()
    influence = model.influence_matrix()
    checks = check_rules(model, results, case.rules)
    plan = plan_checks = sag = jack = fit = reverse = None
    if case.optimise is not None:
        step("offset optimisation")
        plan = optimise_offsets(
            model, case.rules, case.optimise["adjustable"], case.optimise["objective"], case.optimise["bound"]
        )
        plan_checks = check_rules(model, plan.results, case.rules)
    if case.sag_gap is not None:
        step("sag and gap")
        sg = case.sag_gap
        sag = sag_and_gap(case.line, sg["flange_x"], sg["temporary_supports"], sg["condition"], sg["flange_diameter"])
    if case.jack_up is not None:
        step("jack-up")
        ju = case.jack_up
        jack = jack_up(case.line, ju["bearing"], ju["jack_x"], ju["condition"])
        if ju["measured"] is not None:
            fit = reaction_from_jack_curve(*ju["measured"], jack.correction_factor)
    if case.measured_reactions is not None:
        mr = case.measured_reactions
        reverse = offsets_from_reactions(model, mr["values"], mr["condition"], mr["reference"])
    return AlignmentRun(case, model, results, influence, checks, plan, plan_checks, sag, jack, fit, reverse)


def rule_check_rows(checks: list[RuleCheck]) -> list[list[str]]:
    rows = []
    for c in checks:
        unit = {
            "reaction": ("kN", 1e-3),
            "reaction_share": ("-", 1.0),
            "mean_pressure": ("MPa", 1e-6),
            "relative_slope": ("mrad", 1e3),
        }[c.rule.quantity]
        rows.append(
            [
                "pass" if c.passed else "FAIL",
                c.rule.id,
                c.condition,
                c.bearing,
                f"{c.value * unit[1]:.4g} {unit[0]}",
                f"{c.rule.comparison} {c.rule.limit * unit[1]:.4g}",
                c.rule.society,
                c.rule.confidence,
            ]
        )
    return rows


def alignment_table_rows(run: AlignmentRun) -> tuple[list[str], list[list[str]]]:
    headers = [
        "condition",
        "bearing",
        "reaction [kN]",
        "mean pressure [MPa]",
        "contact",
        "shaft slope [mrad]",
        "relative slope [mrad]",
    ]
    rows = []
    for result in run.results:
        for b in result.bearings:
            rows.append(
                [
                    result.name,
                    b.name,
                    _fmt(b.reaction_y, 1e-3),
                    _fmt(b.mean_pressure, 1e-6),
                    b.contact,
                    _fmt(b.shaft_slope, 1e3),
                    _fmt(b.relative_slope, 1e3),
                ]
            )
    return headers, rows


def alignment_section(run: AlignmentRun, folder: Path) -> Section:
    figure_dir = folder / "figures"
    figure_dir.mkdir(exist_ok=True)
    headers, rows = alignment_table_rows(run)
    failed = [c for c in run.checks if not c.passed]
    parts = [
        Markup(
            f"<p>{len(run.results)} condition(s), {len(run.model.line.bearings)} bearings, "
            f"{run.model.mesh.nodes - 1} {run.model.line.beam_theory.replace('_', '-')} elements. "
            "Reactions + up; slopes dy/dx; the relative slope is the shaft's across the bearing less "
            "the bearing's own.</p>"
        ),
        table(headers, rows),
        Markup("<h3>Class-rule checks</h3>"),
        Markup(f"<p class='{'warn' if failed else 'note'}'>{len(failed)} of {len(run.checks)} checks fail.</p>"),
        table(
            ["result", "rule", "condition", "bearing", "value", "limit", "source", "confidence"],
            rule_check_rows(sorted(run.checks, key=lambda c: c.passed)),  # failures first
        ),
    ]
    angles = run.slope_boring_angle()
    parts.append(
        Markup(
            "<p>Slope-boring angle that would make the aft stern-tube bearing parallel to the shaft: "
            + ", ".join(f"{name}: {value * 1e3:.3f} mrad" for name, value in angles.items())
            + ".</p>"
        )
    )
    for maker, stem, args in (
        (alignment_figures.elastic_line, "elastic_line", (run.model, run.results)),
        (alignment_figures.moment_and_shear, "moment_shear", (run.results,)),
        (alignment_figures.reactions, "reactions", (run.results,)),
        (alignment_figures.influence_heatmap, "influence", (run.influence,)),
    ):
        path = maker(*args, figure_dir / f"alignment_{stem}.png")
        parts.append(image(f"figures/{path.name}", stem))
    if run.plan is not None:
        parts.append(Markup(f"<h3>Optimised offsets ({run.case.optimise['objective']})</h3>"))
        parts.append(table(["bearing", "added offset [mm]"], [[k, _fmt(v, 1e3)] for k, v in run.plan.offsets.items()]))
        plan_failed = [c for c in run.plan_checks or [] if not c.passed]
        parts.append(
            Markup(
                f"<p>With these offsets {len(plan_failed)} rule checks fail; objective {run.plan.objective:.4g}.</p>"
            )
        )
    if run.sag_gap is not None:
        parts.append(
            Markup(
                f"<h3>Sag and gap at the flange at x = {run.sag_gap.flange_x:.3f} m</h3>"
                f"<p>sag {run.sag_gap.sag * 1e3:.3f} mm (forward face higher +), "
                f"gap {run.sag_gap.gap * 1e3:.3f} mm (open at the top +).</p>"
            )
        )
    if run.jack is not None:
        path = alignment_figures.jack_curve(
            run.jack, figure_dir / "alignment_jack.png", run.case.jack_up["measured"], run.jack_fit
        )
        parts.append(Markup("<h3>Jack-up</h3>"))
        text = (
            f"<p>Bearing {run.jack.bearing}, jack at x = {run.jack.jack_x:.3f} m: modelled reaction "
            f"{run.jack.reaction_before / 1e3:.1f} kN, lift-off at {run.jack.liftoff_load / 1e3:.1f} kN, "
            f"correction factor {run.jack.correction_factor:.4f}."
        )
        if run.jack_fit is not None:
            text += (
                f" Measured curve: knee at {run.jack_fit.knee_load / 1e3:.1f} kN, reaction "
                f"{run.jack_fit.reaction / 1e3:.1f} kN."
            )
        parts.append(Markup(text + "</p>"))
        parts.append(image(f"figures/{path.name}", "jack-up"))
    if run.reverse is not None:
        parts.append(Markup("<h3>Offsets from measured reactions</h3>"))
        parts.append(table(["bearing", "offset [mm]"], [[k, _fmt(v, 1e3)] for k, v in run.reverse[0].items()]))
        parts.append(Markup(f"<p>RMS reaction misfit {run.reverse[1] / 1e3:.3f} kN.</p>"))
    return Section("Shaft alignment", Markup("").join(parts))
