"""Slope-boring design as a capability: ``[design]`` in a case file (on the case's ``[bearing]``),
``shaftline design slopes | robustness | sweep``, ``design`` in results.json, a section of the
report."""

from __future__ import annotations

from collections.abc import Sequence
from typing import TYPE_CHECKING, Any

from shaftline.registry import BuildContext, Capability, Command, Finding, Progress, no_progress
from shaftline.report.blocks import Block, DataFile, Figure, Heading, Paragraph, Table, fmt

if TYPE_CHECKING:
    from shaftline.design.case import DesignSection
    from shaftline.design.robustness import RobustnessResult
    from shaftline.design.search import SearchResult
    from shaftline.design.study import DesignResult, DesignStudy

#: Units of the quantities of a design in results.json.
UNITS = {
    "min_film_thickness": "m",
    "max_pressure": "Pa",
    "power_loss": "W",
    "side_leakage": "m^3/s",
    "support_offset": "m (|distance of the film resultant from L/2|)",
    "load_centre_offset": "m from L/2, + forward",
    "eccentricity_ratio": "-",
    "attitude_angle": "rad",
    "slope_k": "share of 2c/L (bore slope of segment k, aft first)",
    "knuckle_k": "share of L from the aft edge",
}


def _mm(offset: float) -> str:
    """A support-point offset (m) in mm to 0.01 mm: its numerical zero (1e-13 mm for the single
    slope, centred by symmetry) reads 0.00, not 8.336e-13.

    >>> _mm(8.336e-16), _mm(-1e-9), _mm(-0.0005683), _mm(float("nan"))
    ('0.00', '0.00', '-0.57', '-')
    """
    text = fmt(offset, 1e3)
    return text if text == "-" else f"{offset * 1e3 + 0.0:.2f}".replace("-0.00", "0.00")


def _design_rows(result: SearchResult, indices: Sequence[int] | Any) -> list[dict[str, Any]]:
    names = result.problem.parametrisation.names
    rows = []
    for i in indices:
        evaluation = result.evaluations[int(i)]
        rows.append(
            {
                "index": int(i),
                **{name: float(v) for name, v in zip(names, evaluation.x, strict=True)},
                **evaluation.values,
                "status": evaluation.status,
            }
        )
    return rows


def _robustness_json(result: RobustnessResult) -> dict[str, Any]:
    return {
        "limit": result.limit,
        "scenarios": [
            {
                "name": s.name,
                "speed_factor": s.speed_factor,
                "load_factor": s.load_factor,
                "temperature_change": s.temperature_change,
            }
            for s in result.scenarios
        ],
        "designs": [
            {
                "name": name,
                "x": result.designs[k].tolist(),
                "robust": bool(result.robust()[k]),
                "reference": result.reference[k].values,
                "scenarios": [
                    {"scenario": s.name, **e.values, "status": e.status, "passes": bool(p)}
                    for s, e, p in zip(result.scenarios, result.evaluations[k], result.passes()[k], strict=True)
                ],
                "deviation_min_film_thickness_percent": result.deviation("min_film_thickness")[k].tolist(),
                "deviation_max_pressure_percent": result.deviation("max_pressure")[k].tolist(),
            }
            for k, name in enumerate(result.names)
        ],
    }


def _front_table(result: SearchResult) -> Table:
    names = result.problem.parametrisation.names
    rows, marks = [], []
    for i in result.pareto:
        e = result.evaluations[int(i)]
        rows.append(
            [
                *(f"{v:.3f}" for v in e.x),
                fmt(e.values["min_film_thickness"], 1e6),
                fmt(e.values["max_pressure"], 1e-6),
                fmt(e.values["power_loss"], 1e-3),
                _mm(e.values["load_centre_offset"]),
                "knee" if int(i) == result.knee else "",
            ]
        )
        marks.append(["pass" if int(i) == result.knee else ""] * (len(names) + 5))
    headers = [*names, "h_min [µm]", "p_max [MPa]", "power [kW]", "support pt [mm]", ""]
    return Table(headers, rows, f"Non-dominated designs ({len(result.pareto)} of {len(result.evaluations)})", marks)


def _robustness_table(result: RobustnessResult) -> Table:
    headers = ["design", "operating point", *(s.name for s in result.scenarios), "verdict"]
    rows, marks = [], []
    passes, robust = result.passes(), result.robust()
    for k, name in enumerate(result.names):
        rows.append(
            [
                name,
                fmt(result.reference[k].values["min_film_thickness"], 1e6),
                *(fmt(e.values["min_film_thickness"], 1e6) for e in result.evaluations[k]),
                "robust" if robust[k] else "FAILS",
            ]
        )
        marks.append(["", "", *("pass" if p else "fail" for p in passes[k]), "pass" if robust[k] else "fail"])
    return Table(headers, rows, f"h_min [µm] in each scenario (limit {result.limit * 1e6:.0f} µm)", marks)


def _ratio(result: DesignResult) -> float:
    """psi_x of the searched problem: its journal's chord tilt over 2c/L."""
    g = result.problem.film.geometry
    return result.problem.tilt_y * g.length / (2.0 * g.radial_clearance)


def _sweep_text(result: DesignResult) -> str:
    """What the sweep's journal is (on the coupled alignment, not the coupled journal)."""
    import numpy as np

    study = result.study
    load = f"{np.hypot(result.problem.load_y, result.problem.load_z) / 1e3:.1f} kN"
    if study.coupled is None:
        return (
            f"One search per psi_x on the {study.shaft} shaft at the operating point of [bearing] (load {load}); "
            "psi_x is the journal's chord tilt over 2c/L."
        )
    return (
        f"One search per psi_x on the linear shaft at the coupled operating point of {study.coupled.bearing}: a "
        f"straight journal tilted vertically by psi_x 2c/L, under the coupled film force ({load}), with the "
        f"coupled speed, lubricant and horizontal tilt. The coupled journal itself has psi_x = {_ratio(result):.3g} "
        "and a bend, which the sweep leaves out: it shows how the best bore moves if the misalignment differs from "
        "the computed one (the search above is on the coupled journal)."
    )


def _deviation_table(result: RobustnessResult) -> Table:
    """Change of h_min and p_max from each design's operating point, % (seed 004 Tables 5-14/5-15)."""
    hmin, pmax = result.deviation("min_film_thickness"), result.deviation("max_pressure")
    rows = []
    for k, name in enumerate(result.names):
        rows.append([f"{name}: Δh_min", *(f"{v:+.1f}" for v in hmin[k])])
        rows.append([f"{name}: Δp_max", *(f"{v:+.1f}" for v in pmax[k])])
    headers = ["change [%]", *(s.name for s in result.scenarios)]
    return Table(headers, rows, "Deviations from the operating point, % (as seed 004 Tables 5-14/5-15)")


class SlopeDesign(Capability["DesignSection", "DesignStudy", "DesignResult"]):
    key = "design"
    title = "Slope-boring design"
    needs = ("bearing", "alignment")
    parallel = True

    def schema(self) -> type[DesignSection]:
        from shaftline.design.case import DesignSection

        return DesignSection

    def build(self, section: DesignSection, context: BuildContext) -> DesignStudy:
        from shaftline.design.case import build_study

        return build_study(section, context)

    def solve(self, study: DesignStudy, progress: Progress = no_progress, **options: Any) -> DesignResult:
        from shaftline.design.study import solve_design

        return solve_design(
            study,
            progress,
            task=options.get("task", "all"),
            workers=options.get("workers"),
            scheduler=options.get("scheduler"),
        )

    def commands(self) -> Sequence[Command]:
        from shaftline.design.commands import robustness_command, slopes, sweep_command

        return (
            Command(("design", "slopes"), slopes),
            Command(("design", "robustness"), robustness_command),
            Command(("design", "sweep"), sweep_command),
        )

    def to_json(self, result: DesignResult) -> dict[str, Any]:
        study = result.study
        out: dict[str, Any] = {
            "units": UNITS,
            "shaft": study.shaft,
            "misalignment_ratio": _ratio(result),
            "load": [result.problem.load_y, result.problem.load_z],
            "tilt": [result.problem.tilt_y, result.problem.tilt_z],
            "variables": result.problem.parametrisation.names,
            "lower": result.problem.parametrisation.lower.tolist(),
            "upper": result.problem.parametrisation.upper.tolist(),
            "objectives": list(result.problem.objectives),
        }
        found = result.search
        if found is not None:
            out["search"] = {
                "algorithm": found.algorithm,
                "seed": found.seed,
                "evaluations": len(found.evaluations),
                "completed": found.completed,
                "pareto": _design_rows(found, found.pareto),
                "knee": _design_rows(found, [found.knee])[0] if found.knee is not None else None,
            }
        if result.robustness is not None:
            out["robustness"] = _robustness_json(result.robustness)
            out["robustness"]["left_out"] = [{"scenario": name, "why": why} for name, why in study.left_out]
        if result.profiles:
            out["comparison"] = {
                label: {
                    "min_film_thickness": state.min_film_thickness,
                    "max_pressure": state.max_pressure,
                    "power_loss": state.power_loss,
                    "load_centre_offset": state.load_centre_offset,
                }
                for label, state in result.profiles.items()
            }
        if result.sweep is not None:
            out["sweep_shaft"] = "linear" if study.coupled is not None else study.shaft
            out["sweep"] = [
                {"psi_x": ratio, "pareto": _design_rows(s, s.pareto)}
                for ratio, s in zip(result.sweep.ratios, result.sweep.searches, strict=True)
            ]
        return out

    def findings(self, result: DesignResult) -> list[Finding]:
        import numpy as np

        out = []
        found = result.search
        if found is not None and not found.pareto.size:
            out.append(
                Finding("the design search found no acceptable design (every one failed or broke a constraint).")
            )
        if found is not None and found.pareto.size:
            parametrisation = result.problem.parametrisation
            front = np.array([found.evaluations[int(i)].x for i in found.pareto])
            span = np.maximum(parametrisation.upper - parametrisation.lower, 1e-12)
            for k, name in enumerate(parametrisation.names):
                for side, bound in (("lower", parametrisation.lower[k]), ("upper", parametrisation.upper[k])):
                    share = float(np.mean(np.abs(front[:, k] - bound) <= 0.02 * span[k]))
                    if share >= 0.5:
                        out.append(
                            Finding(
                                f"the design front sits on the {side} bound of {name} ({bound:g}) in "
                                f"{share:.0%} of its designs: a wider bound may give better bores.",
                                criterion=True,
                            )
                        )
        if result.robustness is not None and not result.robustness.robust().any():
            out.append(
                Finding(
                    f"no chosen design keeps h_min >= {result.robustness.limit * 1e6:.0f} µm in every robustness "
                    "scenario.",
                    criterion=True,
                )
            )
        return out

    def _knee_text(self, result: DesignResult) -> Paragraph:
        found = result.search
        assert found is not None
        if found.knee is None:
            return Paragraph(f"{len(found.evaluations)} designs evaluated; {len(found.pareto)} non-dominated.")
        e = found.evaluations[found.knee]
        names = result.problem.parametrisation.names
        design = ", ".join(f"{n} {v:.3f}" for n, v in zip(names, e.x, strict=True))
        return Paragraph(
            f"{len(found.evaluations)} designs evaluated ({found.algorithm}, seed {found.seed}); "
            f"{len(found.pareto)} non-dominated. Knee: {design} — h_min {e.values['min_film_thickness'] * 1e6:.1f} µm, "
            f"p_max {e.values['max_pressure'] / 1e6:.3f} MPa, power {e.values['power_loss'] / 1e3:.3f} kW."
        )

    def summary(self, result: DesignResult) -> list[Block]:
        blocks: list[Block] = []
        if result.search is not None:
            blocks.append(self._knee_text(result))
        if result.robustness is not None:
            robust = result.robustness.robust()
            blocks.append(
                Paragraph(
                    f"Robustness: {int(robust.sum())} of {robust.size} chosen design(s) keep h_min >= "
                    f"{result.robustness.limit * 1e6:.0f} µm in all {len(result.robustness.scenarios)} scenarios.",
                    "text" if robust.any() else "warn",
                )
            )
            blocks.append(_robustness_table(result.robustness))  # the verdict per scenario, as in the report
        if result.sweep is not None:
            where = " (linear shaft at the coupled operating point)" if result.study.coupled is not None else ""
            blocks.append(
                Paragraph(
                    f"Misalignment sweep{where}: "
                    + "; ".join(
                        f"psi_x {r:g}: {len(s.pareto)} non-dominated"
                        for r, s in zip(result.sweep.ratios, result.sweep.searches, strict=True)
                    )
                    + "."
                )
            )
        return blocks

    def report(self, result: DesignResult) -> list[Block]:
        from shaftline.design import figures

        study = result.study
        source = "[bearing]" if study.coupled is None else f"the coupled alignment ({study.coupled.bearing})"
        blocks: list[Block] = [
            Paragraph(
                f"Bore of {result.problem.parametrisation.segments} slope segment(s) searched for "
                + ", ".join(result.problem.objectives)
                + f" at the operating point of {source}, {study.shaft} shaft, psi_x = {_ratio(result):.3g} "
                f"(journal chord over 2c/L), load {abs(result.problem.load_y) / 1e3:.1f} kN "
                "(slopes as shares of 2c/L, knuckles as shares of L from the aft edge)."
            )
        ]
        found = result.search
        if found is not None:
            blocks += [
                self._knee_text(result),
                _front_table(found),
                DataFile(
                    "design_evaluations.csv",
                    lambda path: found.table().to_csv(path, index=False),
                    f"every evaluated design ({len(found.evaluations)}, CSV)",
                ),
                DataFile(
                    "design_evaluations.parquet",
                    lambda path: found.table().to_parquet(path, index=False),
                    "the same as Parquet",
                ),
                Figure("design_pareto.png", figures.pareto_front, (found, result.profiles), caption="Pareto front"),
                Figure(
                    "design_maps.png",
                    figures.design_maps(result.problem.parametrisation.variables),
                    (found,),
                    caption="design maps",
                ),
            ]
        if result.profiles:
            rows = [
                [
                    label,
                    fmt(state.min_film_thickness, 1e6),
                    fmt(state.max_pressure, 1e-6),
                    fmt(state.power_loss, 1e-3),
                    _mm(state.load_centre_offset),
                ]
                for label, state in result.profiles.items()
            ]
            blocks += [
                Table(
                    ["bore", "h_min [µm]", "p_max [MPa]", "power [kW]", "support pt [mm]"],
                    rows,
                    "The knee beside no slope and the single slope",
                ),
                Figure(
                    "design_profiles.png",
                    figures.profiles_along_bearing,
                    (result.profiles,),
                    caption="film and pressure along the bearing",
                ),
            ]
        if result.robustness is not None:
            blocks.append(Heading("Robustness"))
            for name, why in study.left_out:
                blocks.append(Paragraph(f"The default scenario {name} is left out: {why}.", "warn"))
            blocks += [
                _robustness_table(result.robustness),
                _deviation_table(result.robustness),
                Figure(
                    "design_robustness.png",
                    figures.robustness_heatmap,
                    (result.robustness,),
                    caption="robustness",
                ),
            ]
        if result.sweep is not None:
            sweep = result.sweep
            blocks += [Heading("Misalignment sweep"), Paragraph(_sweep_text(result))]
            blocks.append(
                DataFile(
                    "design_sweep_fronts.csv",
                    lambda path: sweep.dominant().to_csv(path, index=False),
                    "the non-dominated designs of every psi_x (CSV)",
                )
            )
            for ratio, s in zip(result.sweep.ratios, result.sweep.searches, strict=True):
                table = _front_table(s)
                title = f"psi_x = {ratio:g}: " + (table.title or "")
                blocks.append(Table(table.headers, table.rows, title, table.marks))
        return blocks


CAPABILITY = SlopeDesign()
