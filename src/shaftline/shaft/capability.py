"""Shaft alignment as a capability: ``[alignment]`` in a case file, ``shaftline align``,
``alignment`` in results.json, a section of the report."""

from __future__ import annotations

import math
from typing import TYPE_CHECKING, Any

from shaftline.helptext import strict_help
from shaftline.registry import BuildContext, Capability, Finding, Progress, Verb, no_progress
from shaftline.report.blocks import Block, Details, Figure, Heading, Paragraph, Table, fmt
from shaftline.shaft.presentation import (
    COMPARISON_HEADERS,
    FILM_HEADERS,
    FILM_UNITS,
    NARROW_COMPARISON,
    NARROW_FILM,
    _comparison_rows,
    _count,
    _coupled_json,
    _film_notes,
    _film_rows,
    _finite,
    _narrowed,
    influence_json,
)

if TYPE_CHECKING:
    from shaftline.shaft.case import AlignmentSection
    from shaftline.shaft.coupled import CoupledResult, FilmBearingResult
    from shaftline.shaft.offsets import OffsetPlan
    from shaftline.shaft.rules import RuleCheck
    from shaftline.shaft.study import AlignmentResult, AlignmentStudy

#: Display unit and scale of each rule quantity.
RULE_UNITS = {
    "reaction": ("kN", 1e-3),
    "reaction_share": ("", 1.0),
    "mean_pressure": ("MPa", 1e-6),
    "relative_slope": ("mrad", 1e3),
}
RULE_HEADERS = ["result", "rule", "condition", "bearing", "value", "limit", "source", "confidence"]
#: The summary's table of failed checks, one row per rule and bearing: its worst value over the
#: conditions and how many conditions fail (the report lists each check with source and confidence).
SUMMARY_RULE_HEADERS = ["rule", "bearing", "worst", "limit", "fails in"]


def _check_json(check: RuleCheck) -> dict[str, Any]:
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


def failed_rule_rows(checks: list[RuleCheck], conditions: int) -> list[list[str]]:
    """The summary's rows of the failed checks (:data:`SUMMARY_RULE_HEADERS`): one per rule and bearing,
    in the order first failed, its value furthest past the limit and the failing conditions out of
    ``conditions``."""
    groups: dict[tuple[str, str], list[RuleCheck]] = {}
    for c in checks:
        if not c.passed:
            groups.setdefault((c.rule.id, c.bearing), []).append(c)
    rows = []
    for (rule_id, bearing), failed in groups.items():
        rule = failed[0].rule
        # a lower limit (">", ">=") is failed worst by the smallest value, an upper one by the largest
        pick = min if rule.comparison.startswith(">") else max
        worst = pick(c.value for c in failed)
        unit, scale = RULE_UNITS[rule.quantity]
        rows.append(
            [
                rule_id,
                bearing,
                f"{worst * scale:.4g} {unit}".rstrip(),
                f"{rule.comparison} {rule.limit * scale:.4g} {unit}".rstrip(),
                f"{len(failed)} of {conditions}",
            ]
        )
    return rows


def rule_check_rows(checks: list[RuleCheck]) -> list[list[str]]:
    """Table rows of rule checks, failures first."""
    rows = []
    for c in sorted(checks, key=lambda check: check.passed):
        unit, scale = RULE_UNITS[c.rule.quantity]
        rows.append(
            [
                "pass" if c.passed else "FAIL",
                c.rule.id,
                c.condition,
                c.bearing,
                f"{c.value * scale:.4g} {unit}".rstrip(),
                f"{c.rule.comparison} {c.rule.limit * scale:.4g} {unit}".rstrip(),
                c.rule.society,
                c.rule.confidence,
            ]
        )
    return rows



def _plan_json(plan: OffsetPlan, checks: list[RuleCheck]) -> dict[str, Any]:
    """The optimised offsets in results.json: offsets (m), objective, how the rounds went, checks."""
    return {
        "offsets": plan.offsets,
        "objective": plan.objective,
        "rounds": plan.iterations,
        "settled": plan.settled,
        "note": plan.note,
        "influence": plan.influence,
        "rule_checks": [_check_json(c) for c in checks],
    }

class ShaftAlignment(Capability["AlignmentSection", "AlignmentStudy", "AlignmentResult"]):
    key = "alignment"
    title = "Shaft alignment"
    verbs = (
        Verb(
            ("align",),
            "Shaft alignment: elastic line, reactions, slopes, influence matrix and rule checks.",
            # what ShaftAlignment.findings judges, with and without ``criterion``
            strict=strict_help(
                "a class-rule check fails (also with the optimised offsets), the offset optimisation sits on its "
                "bound, or a film bearing is below its film limit at the operating speed (minimum speed)",
                "a film-supported alignment that does not converge or a film at its floor (solved as contact)",
            ),
        ),
    )
    moved_tables = {
        "shaft": "alignment.shaft",
        "bearings": "alignment.bearings",
        "propeller": "alignment.propeller",
        "conditions": "alignment.conditions",
        "loads": "alignment.loads",
        "masses": "alignment.masses",
        "distributed_loads": "alignment.distributed_loads",
    }

    def schema(self) -> type[AlignmentSection]:
        from shaftline.shaft.case import AlignmentSection

        return AlignmentSection

    def build(self, section: AlignmentSection, context: BuildContext) -> AlignmentStudy:
        from shaftline.shaft.case import build_study

        return build_study(section, context)

    def solve(self, study: AlignmentStudy, progress: Progress = no_progress, **options: Any) -> AlignmentResult:
        from shaftline.shaft.study import solve_alignment

        return solve_alignment(study, lambda step: progress(f"solving {step}"))

    def to_json(self, result: AlignmentResult) -> dict[str, Any]:
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
                for r in result.conditions
            ],
            "influence_matrix": influence_json(result.influence),
            "rule_checks": [_check_json(c) for c in result.checks],
            "slope_boring_angle": result.slope_boring_angle(),
        }
        if result.point_influence is not None:
            out["point_supports_influence_matrix"] = influence_json(result.point_influence)
        if result.coupled is not None:
            out["units"].update(FILM_UNITS)
            out["film_supports"] = [_coupled_json(c) for c in result.coupled]
        if result.lift_off is not None:
            lift = result.lift_off
            # nan (no speed: the films are below the limit at the operating speed) is null
            out["minimum_speed"] = {
                "speed": _finite(lift.speed),
                "speed_rpm": _finite(lift.speed * 30.0 / math.pi),
                "bracket": [_finite(v) for v in lift.bracket],
                "limit": lift.limit,
                "governing": lift.governing,
                "message": lift.message,
                "curve": {
                    "speeds": lift.speeds.tolist(),
                    "bearings": lift.names,
                    "min_film": lift.min_film.tolist(),
                    "contact": lift.contact.tolist(),
                },
            }
        if result.plan is not None:
            out["optimised_offsets"] = _plan_json(result.plan, result.plan_checks or [])
        if result.sag_gap is not None:
            sg = result.sag_gap
            out["sag_gap"] = {"flange_x": sg.flange_x, "sag": sg.sag, "gap": sg.gap}
        if result.jack is not None:
            jack = result.jack
            out["jack_up"] = {
                "bearing": jack.bearing,
                "jack_x": jack.jack_x,
                "reaction_before": jack.reaction_before,
                "liftoff_load": jack.liftoff_load,
                "correction_factor": jack.correction_factor,
                "curve": {"load": jack.loads.tolist(), "lift": jack.lifts.tolist()},
            }
            if result.jack_fit is not None:
                out["jack_up"]["measured"] = {
                    "knee_load": result.jack_fit.knee_load,
                    "reaction": result.jack_fit.reaction,
                    "residual": result.jack_fit.residual,
                }
        if result.reverse is not None:
            out["offsets_from_reactions"] = {"offsets": result.reverse[0], "rms_misfit": result.reverse[1]}
        return out

    def _reactions(self, result: AlignmentResult) -> list[Block]:
        """One table per condition, narrow enough for an 80-column terminal."""
        headers = ["bearing", "reaction [kN]", "mean p [MPa]", "contact", "slope [mrad]", "rel. slope [mrad]"]
        return [
            Table(
                headers,
                [
                    [
                        b.name,
                        fmt(b.reaction_y, 1e-3),
                        fmt(b.mean_pressure, 1e-6),
                        b.contact,
                        fmt(b.shaft_slope, 1e3),
                        fmt(b.relative_slope, 1e3),
                    ]
                    for b in r.bearings
                ],
                f"Shaft alignment: {r.name}",
            )
            for r in result.conditions
        ]

    def _rule_matrix(self, result: AlignmentResult) -> Table:
        """Rule checks as a matrix of conditions by bearings: pass, or FAIL with the rules failed."""
        bearings = [b.name for b in result.model.line.bearings]
        rows, marks = [], []
        for r in result.conditions:
            row, mark = [r.name], [""]
            for name in bearings:
                checks = [c for c in result.checks if c.condition == r.name and c.bearing == name]
                failed = [c.rule.id for c in checks if not c.passed]
                row.append("FAIL: " + ", ".join(failed) if failed else ("pass" if checks else "-"))
                mark.append("fail" if failed else "pass" if checks else "")
            rows.append(row)
            marks.append(mark)
        return Table(["condition", *bearings], rows, "Class-rule checks by condition and bearing", marks)

    def _verdict(self, result: AlignmentResult) -> Paragraph:
        failed = [c for c in result.checks if not c.passed]
        if failed:
            return Paragraph(f"Class-rule checks: {len(failed)} of {len(result.checks)} fail.", "warn")
        return Paragraph(f"Class-rule checks: all {len(result.checks)} pass.")

    def _film_report(self, result: AlignmentResult) -> list[Block]:
        from shaftline.film.figures import film_and_pressure_maps
        from shaftline.shaft import figures

        blocks: list[Block] = [
            Heading("Film supports (elastohydrodynamic alignment)"),
            Paragraph(
                "The bearings marked hydrodynamic are supported by their film: the shaft's elastic line across the "
                "bearing is the journal, and the film pressure acts back on the shaft as a distributed load. The "
                "support point is the axial position of the film's vertical resultant from the bearing's "
                "mid-length, + forward; where a plane's resultant lies outside the bearing the film carries a "
                "couple there and has no support point (the notes say so). "
                "The influence coefficients are the film-supported line's tangent at the first condition's "
                "equilibrium (the films' stiffness included; each condition's is in results.json), and offset "
                "optimisation and offsets from measured reactions are solved on the films; sag and gap and jack-up "
                "use the declared supports."
            ),
        ]
        for k, coupled in enumerate(result.coupled or []):
            blocks += self._film_blocks(coupled)
            blocks.append(self._support_moves(result, coupled))
            blocks.append(
                Figure(
                    f"alignment_point_vs_film_{k}.png",
                    figures.point_vs_film,
                    (coupled,),
                    caption=f"point vs film supports, {coupled.condition.name}",
                )
            )
            for j, film in enumerate(coupled.films):
                blocks.append(
                    Figure(
                        f"alignment_journal_{k}_{j}.png",
                        figures.journal_in_bore,
                        (film,),
                        caption=f"journal in the bore, {film.name}, {coupled.condition.name}",
                    )
                )
                blocks.append(
                    Figure(
                        f"alignment_film_maps_{k}_{j}.png",
                        film_and_pressure_maps,
                        (film.state, f"{film.name}, {coupled.condition.name}"),
                        caption=f"film and pressure maps, {film.name}, {coupled.condition.name}",
                    )
                )
        return blocks

    def _lift_off_text(self, result: AlignmentResult) -> Paragraph:
        lift = result.lift_off
        assert lift is not None
        limit = f"{lift.limit * 1e6:.2f} µm"
        if lift.message:
            return Paragraph(f"Minimum speed (film limit {limit}): {lift.message}.", "warn")
        return Paragraph(
            f"Minimum speed for a film of at least {limit} in every film bearing: {lift.speed * 30 / math.pi:.1f} rpm "
            f"(between {lift.bracket[0] * 30 / math.pi:.1f} and {lift.bracket[1] * 30 / math.pi:.1f} rpm; governed by "
            f"{lift.governing}; {lift.solutions} coupled solutions). The limit is the larger of the film parameter "
            "times the composite roughness and the class value."
        )

    def findings(self, result: AlignmentResult) -> list[Finding]:
        out = []
        lift = result.lift_off
        if lift is not None and math.isnan(lift.speed):
            out.append(
                Finding(
                    f"a film bearing is below the film limit of {lift.limit * 1e6:.2f} µm at the operating speed: "
                    f"{lift.message}.",
                    criterion=True,
                )
            )
        for coupled in result.coupled or []:
            if not coupled.converged:
                out.append(Finding(f"film-supported alignment, {coupled.condition.name}: {coupled.message}."))
            for film in coupled.films:
                if film.contact:
                    out.append(
                        Finding(
                            f"film-supported alignment, {coupled.condition.name}: the film of {film.name} is at its "
                            f"floor (h_min {film.state.min_film_thickness * 1e6:.2f} µm): it cannot carry its share, "
                            "so the bearing was solved as contact at the bore (edge loading)."
                        )
                    )
        failed = [c for c in result.checks if not c.passed]
        if failed:
            names = sorted({f"{c.rule.id} at {c.bearing} ({c.condition})" for c in failed})
            shown = "; ".join(names[:3]) + (f"; and {len(names) - 3} more" if len(names) > 3 else "")
            out.append(
                Finding(f"{len(failed)} of {len(result.checks)} class-rule checks fail: {shown}.", criterion=True)
            )
        study = result.study
        if result.plan is not None and study.optimise is not None:
            bound = study.optimise.bound
            at_bound = [name for name, value in result.plan.offsets.items() if abs(value) >= bound * (1 - 1e-6)]
            if at_bound:
                out.append(
                    Finding(
                        f"the offset optimisation sits on its bound of ±{bound * 1e3:g} mm at "
                        + ", ".join(at_bound)
                        + ": a wider bound may give a better alignment.",
                        criterion=True,
                    )
                )
            if not result.plan.settled:
                out.append(
                    Finding(
                        f"the offset optimisation did not settle in {result.plan.iterations} rounds: the offsets "
                        "shown are the last round's, not an optimum"
                        + (f"; {result.plan.note}." if result.plan.note else "."),
                        criterion=True,
                    )
                )
            plan_failed = [c for c in result.plan_checks or [] if not c.passed]
            if plan_failed:
                out.append(
                    Finding(
                        f"with the optimised offsets {len(plan_failed)} class-rule checks still fail.", criterion=True
                    )
                )
        return out

    def _support_moves(self, result: AlignmentResult, coupled: CoupledResult) -> Paragraph:
        """Where each film bearing's support point was with the declared supports, and is now."""
        model = result.model
        parts = []
        for film in coupled.films:
            index = [b.name for b in model.line.bearings].index(film.name)
            bearing = model.line.bearings[index]
            pick = model.supports.bearing == index
            reactions = coupled.point_supports.bearing(film.name).point_reactions
            total = float(reactions.sum())
            declared = (
                f"{(float(reactions @ model.supports.x[pick]) / total - bearing.x) * 1e3:+.0f} mm"
                if abs(total) > 0
                else "lifted"
            )
            point = coupled.point_supports.bearing(film.name)
            on_film = (
                f"{film.support_point_y * 1e3:+.0f} mm on the film"
                if math.isfinite(film.support_point_y)
                else "none on the film (its vertical resultant lies outside the bearing: a couple)"
            )
            parts.append(
                f"{film.name}: support point {declared} with the declared supports, {on_film} (vertical plane, "
                f"from mid-length, + forward); relative slope {point.relative_slope * 1e3:.3f} mrad on "
                f"points, {film.relative_slope * 1e3:.3f} mrad in the film"
            )
        return Paragraph("; ".join(parts) + ".")

    def _film_blocks(self, coupled: CoupledResult, narrow: bool = False) -> list[Block]:
        name = coupled.condition.name
        work = f"{_count(coupled.iterations, 'iteration')} ({_count(coupled.film_solutions, 'film solution')})"
        if not coupled.converged:
            state = f"NOT CONVERGED: {coupled.message}"
        elif coupled.contact:
            # "converged" there is the contact solution's: the film iteration itself stalled.
            state = f"the film iteration stopped after {work}; {coupled.message}"
        else:
            state = f"converged in {work}" + (f"; {coupled.message}" if coupled.message else "")
        blocks: list[Block] = [
            Paragraph(f"Film supports, {name}: {state}.", "text" if coupled.converged else "warn"),
            _narrowed(FILM_HEADERS, _film_rows(coupled), f"Film bearings: {name}", NARROW_FILM if narrow else None),
        ]
        notes = _film_notes(coupled)
        if notes is not None:
            blocks.append(notes)
        blocks += [
            _narrowed(
                COMPARISON_HEADERS,
                _comparison_rows(coupled),
                f"Point supports vs film supports: {name}",
                NARROW_COMPARISON if narrow else None,
            ),
        ]
        if not narrow:
            blocks += [self._coefficients(film, name) for film in coupled.films]
        return blocks

    def _coefficients(self, film: FilmBearingResult, condition: str) -> Table | Paragraph:
        """The 4 x 4 film stiffness and damping, in units a rotor-dynamics model takes (a note
        when they are not available)."""
        if film.coefficients_note:
            return Paragraph(f"Film stiffness and damping, {film.name}, {condition}: {film.coefficients_note}.", "warn")
        labels = ["y", "z", "tilt_y", "tilt_z"]
        scales = (1e-6, 1e-6, 1e-6, 1e-6)  # MN/m, MN/rad, MN m/m, MN m/rad
        rows = []
        for i, row in enumerate(("F_y", "F_z", "M_y", "M_z")):
            rows.append(
                [row]
                + [f"{film.stiffness[i, j] * scales[j]:.4g}" for j in range(4)]
                + [f"{film.damping[i, j] * 1e-6:.4g}" for j in range(4)]
            )
        headers = ["", *(f"K {c}" for c in labels), *(f"C {c}" for c in labels)]
        return Table(
            headers,
            rows,
            f"Film stiffness K (MN/m, MN/rad; MN m/m, MN m/rad) and damping C (MN s/m ...), {film.name}, {condition}",
        )

    def summary(self, result: AlignmentResult) -> list[Block]:
        blocks: list[Block] = [self._verdict(result), *self._reactions(result)]
        for coupled in result.coupled or []:
            blocks += self._film_blocks(coupled, narrow=True)
        if result.lift_off is not None:
            blocks.append(self._lift_off_text(result))
        failed = [c for c in result.checks if not c.passed]
        if failed:
            # One row per rule and bearing: the table of every check with each rule's source and
            # confidence folded every row over three lines at 80 columns; it is the report's.
            rows = failed_rule_rows(failed, len(result.conditions))
            blocks.append(
                Table(
                    SUMMARY_RULE_HEADERS,
                    rows,
                    "Failed class-rule checks: the worst value over the conditions and how many fail (each "
                    "check, with the rule's source and confidence: the report)",
                    marks=[["fail"] * len(SUMMARY_RULE_HEADERS) for _ in rows],
                )
            )
        return blocks

    def report(self, result: AlignmentResult) -> list[Block]:
        from shaftline.shaft import figures

        line = result.model.line
        blocks: list[Block] = [
            self._verdict(result),
            Paragraph(
                f"{len(result.conditions)} condition(s), {len(line.bearings)} bearings, "
                f"{result.model.mesh.nodes - 1} {line.beam_theory.replace('_', '-')} elements. Reactions + up; "
                "slopes dy/dx; the relative slope is the shaft's across the bearing less the bearing's own."
            ),
            *self._reactions(result),
            Heading("Class-rule checks"),
            self._rule_matrix(result),
            Details(
                f"every check ({len(result.checks)}): value, limit and source",
                [Table(RULE_HEADERS, rule_check_rows(result.checks))],
            ),
            Paragraph(
                "Slope-boring angle that would make the aft stern-tube bearing parallel to the shaft: "
                + ", ".join(f"{name}: {value * 1e3:.3f} mrad" for name, value in result.slope_boring_angle().items())
                + "."
            ),
            Figure(
                "alignment_elastic_line.png", figures.elastic_line, (line, result.conditions), caption="elastic line"
            ),
            Figure(
                "alignment_moment_shear.png", figures.moment_and_shear, (result.conditions,), caption="moment and shear"
            ),
            Figure("alignment_reactions.png", figures.reactions, (result.conditions,), caption="reactions"),
            Figure(
                "alignment_influence.png",
                figures.influence_heatmap,
                (result.influence,),
                caption=f"influence matrix, {result.influence.label}",
            ),
        ]
        if result.coupled is not None:
            blocks += self._film_report(result)
        if result.lift_off is not None:
            from shaftline.shaft.figures import lift_off_curve

            blocks += [
                Heading("Minimum speed for hydrodynamic operation"),
                self._lift_off_text(result),
                Figure("alignment_lift_off.png", lift_off_curve, (result.lift_off,), caption="lift-off curve"),
            ]
        study = result.study
        if result.plan is not None and study.optimise is not None:
            blocks.append(Heading(f"Optimised offsets ({study.optimise.objective})"))
            blocks.append(
                Table(["bearing", "added offset [mm]"], [[k, fmt(v, 1e3)] for k, v in result.plan.offsets.items()])
            )
            plan_failed = [c for c in result.plan_checks or [] if not c.passed]
            blocks.append(
                Paragraph(
                    f"With these offsets {len(plan_failed)} rule checks fail; objective {result.plan.objective:.4g}; "
                    f"{result.plan.iterations} rounds on {result.plan.influence}.",
                    "warn" if plan_failed else "text",
                )
            )
        if result.sag_gap is not None:
            sg = result.sag_gap
            blocks.append(Heading(f"Sag and gap at the flange at x = {sg.flange_x:.3f} m"))
            blocks.append(
                Paragraph(
                    f"sag {sg.sag * 1e3:.3f} mm (forward face higher +), gap {sg.gap * 1e3:.3f} mm (open at the top +)."
                )
            )
        if result.jack is not None:
            jack = result.jack
            measured = study.jack_up.measured if study.jack_up is not None else None
            text = (
                f"Bearing {jack.bearing}, jack at x = {jack.jack_x:.3f} m: modelled reaction "
                f"{jack.reaction_before / 1e3:.1f} kN, lift-off at {jack.liftoff_load / 1e3:.1f} kN, "
                f"correction factor {jack.correction_factor:.4f}."
            )
            if result.jack_fit is not None:
                text += (
                    f" Measured curve: knee at {result.jack_fit.knee_load / 1e3:.1f} kN, reaction "
                    f"{result.jack_fit.reaction / 1e3:.1f} kN."
                )
            blocks += [
                Heading("Jack-up"),
                Paragraph(text),
                Figure("alignment_jack.png", figures.jack_curve, (jack, measured, result.jack_fit), caption="jack-up"),
            ]
        if result.reverse is not None:
            offsets, misfit = result.reverse
            blocks += [
                Heading("Offsets from measured reactions"),
                Table(["bearing", "offset [mm]"], [[k, fmt(v, 1e3)] for k, v in offsets.items()]),
                Paragraph(f"RMS reaction misfit {misfit / 1e3:.3f} kN."),
            ]
        return blocks


CAPABILITY = ShaftAlignment()
