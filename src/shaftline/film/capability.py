"""The stern-tube bearing film as a capability: ``[bearing]`` in a case file,
``shaftline bearing solve``, ``bearing`` in results.json, a section of the report.

This module is the worked example of docs/architecture.md: the schema lives in
:mod:`shaftline.film.case`, the study and its solution in :mod:`shaftline.film.study`,
the figures in :mod:`shaftline.film.figures`; this class ties them to the pipeline.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

from shaftline.registry import BuildContext, Capability, Finding, Progress, Verb, no_progress
from shaftline.report.blocks import Block, Figure, Heading, Paragraph, Table, fmt

if TYPE_CHECKING:
    from shaftline.film.case import BearingSection
    from shaftline.film.study import BearingStudy, BearingStudyResult

#: Largest peak film pressure a class rule allows, Pa: NK's 40 MPa as quoted in seed 004
#: Sect. 2.2.1 (line 497 of the text); above it a result is not a stern-tube bearing's.
PEAK_PRESSURE_LIMIT = 40e6
#: Smallest film the Bureau Veritas rule accepts, m (seed 004 Sect. 2.2.1): a design criterion.
MIN_FILM_CRITERION = 30e-6

#: (label, JSON key, scale, digits) of the rows of the results table.
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


class BearingFilm(Capability["BearingSection", "BearingStudy", "BearingStudyResult"]):
    key = "bearing"
    title = "Stern-tube bearing film"
    verbs = (Verb(("bearing", "solve"), "Solve the bearing film at equilibrium under the case load."),)
    parallel = True
    moved_tables = {
        "operation": "bearing.operation",
        "lubricant": "bearing.lubricant",
        "solver": "bearing.solver",
        "variants": "bearing.variants",
    }

    def schema(self) -> type[BearingSection]:
        from shaftline.film.case import BearingSection

        return BearingSection

    def build(self, section: BearingSection, context: BuildContext) -> BearingStudy:
        from shaftline.film.case import build_study

        return build_study(section, context)

    def solve(self, study: BearingStudy, progress: Progress = no_progress, **options: Any) -> BearingStudyResult:
        """The cases with :func:`shaftline.film.sweep` (``workers``, ``scheduler``: where)."""
        from shaftline.film.study import solve_study

        return solve_study(
            study,
            lambda name: progress(f"solving {name}"),
            workers=options.get("workers"),
            scheduler=options.get("scheduler"),
        )

    def to_json(self, result: BearingStudyResult) -> dict[str, Any]:
        from shaftline.film.summary import EXTRA_UNITS, equilibrium_summary, units

        return {
            "units": {**units(), **EXTRA_UNITS},
            "cases": [
                {"name": run.case.name, **equilibrium_summary(run.equilibrium, run.coefficients)}
                for run in result.cases
            ],
        }

    def findings(self, result: BearingStudyResult) -> list[Finding]:
        out: list[Finding] = []
        for run in result.cases:
            name, equilibrium, state = run.case.name, run.equilibrium, run.equilibrium.state
            if equilibrium.contact:
                out.append(
                    Finding(
                        f"{name}: the film does not carry the load — the journal reaches the film floor "
                        f"(h_min {state.min_film_thickness * 1e6:.2g} µm, contact); the figures show the position "
                        "at the floor."
                    )
                )
            elif not equilibrium.converged:
                out.append(
                    Finding(
                        f"{name}: the equilibrium did not converge (force residual {equilibrium.residual:.3g} N); "
                        "the numbers are not a solution."
                    )
                )
            roughness = run.case.surface_roughness
            if not equilibrium.contact and state.min_film_thickness < 3.0 * roughness:
                out.append(
                    Finding(
                        f"{name}: h_min {state.min_film_thickness * 1e6:.3g} µm is below three times the composite "
                        f"surface roughness ({roughness * 1e6:.3g} µm): mixed lubrication, where asperities touch and "
                        "the smooth-film model does not hold (film parameter below 3, Hamrock & Dowson 1981)."
                    )
                )
            if state.max_pressure > PEAK_PRESSURE_LIMIT:
                out.append(
                    Finding(
                        f"{name}: p_max {state.max_pressure / 1e6:.4g} MPa is above {PEAK_PRESSURE_LIMIT / 1e6:g} MPa, "
                        "the largest peak film pressure a class rule allows (NK, as quoted in seed 004 Sect. 2.2.1); "
                        "no stern-tube liner carries it."
                    )
                )
            if not equilibrium.contact and state.min_film_thickness < MIN_FILM_CRITERION:
                out.append(
                    Finding(
                        f"{name}: h_min {state.min_film_thickness * 1e6:.3g} µm is below "
                        f"{MIN_FILM_CRITERION * 1e6:g} µm (Bureau Veritas, as quoted in seed 004 Sect. 2.2.1).",
                        criterion=True,
                    )
                )
        return out

    def _table(self, result: BearingStudyResult) -> Table:
        summaries = self.to_json(result)["cases"]
        rows = [[label] + [fmt(s[key], scale, digits) for s in summaries] for label, key, scale, digits in TABLE_ROWS]
        rows.append(["converged"] + ["yes" if s["converged"] else "NO" for s in summaries])
        rows.append(["contact (film at floor)"] + ["YES" if s["contact"] else "no" for s in summaries])
        return Table(["quantity"] + [s["name"] for s in summaries], rows, "Bearing film at equilibrium")

    def summary(self, result: BearingStudyResult) -> list[Block]:
        return [self._table(result)]

    def report(self, result: BearingStudyResult) -> list[Block]:
        from shaftline.film import figures

        blocks: list[Block] = [
            Paragraph(
                "Film equilibrium under the case load with the journal tilt held at the given misalignment. "
                "Pressures are gauge; θ from the top of the bore in the sense of rotation; z from the aft edge."
            ),
            self._table(result),
        ]
        coefficient_rows = []
        tilt_rows = []
        for run in result.cases:
            if run.coefficients is None:
                continue
            k, c = run.coefficients.stiffness, run.coefficients.damping
            coefficient_rows.append(
                [run.case.name]
                + [fmt(v, 1e-9) for v in (k[0, 0], k[0, 1], k[1, 0], k[1, 1])]
                + [fmt(v, 1e-9) for v in (c[0, 0], c[0, 1], c[1, 0], c[1, 1])]
            )
            k4, c4 = run.coefficients.stiffness_4x4, run.coefficients.damping_4x4
            if k4 is not None and c4 is not None:
                # The moment-by-tilt block; the whole 4 x 4 is in the JSON.
                tilt_rows.append(
                    [run.case.name]
                    + [fmt(v, 1e-9) for v in (k4[2, 2], k4[2, 3], k4[3, 2], k4[3, 3])]
                    + [fmt(v, 1e-9) for v in (c4[2, 2], c4[2, 3], c4[3, 2], c4[3, 3])]
                )
        if coefficient_rows:
            blocks.append(
                Table(
                    ["case", "Kyy", "Kyz", "Kzy", "Kzz", "Cyy", "Cyz", "Czy", "Czz"],
                    coefficient_rows,
                    "Film stiffness [kN/µm] and damping [kN·s/µm]",
                )
            )
        if tilt_rows:
            blocks.append(
                Table(
                    ["case", "K My,ty", "K My,tz", "K Mz,ty", "K Mz,tz", "C My,ty", "C My,tz", "C Mz,ty", "C Mz,tz"],
                    tilt_rows,
                    "Film tilt stiffness [kN·m/µrad] and damping [kN·m·s/µrad]: moments about mid-length by "
                    "journal tilt (the full 4 × 4 with the force and offset terms is in the JSON)",
                )
            )
        if len(result.cases) > 1:
            blocks.append(
                Figure(
                    "bearing_comparison.png",
                    figures.comparison,
                    ([r.case.name for r in result.cases], [r.equilibrium.state for r in result.cases]),
                    caption="h_min, p_max and power loss of the base case and its variants",
                )
            )
        for index, run in enumerate(result.cases):
            state, name = run.equilibrium.state, run.case.name
            blocks.append(Heading(name))
            blocks.append(
                Figure(
                    f"bearing_{index}_maps.png",
                    figures.film_and_pressure_maps,
                    (state, name),
                    caption=f"{name}: film and pressure",
                )
            )
            blocks.append(
                Figure(
                    f"bearing_{index}_circumferential.png",
                    figures.circumferential_profile,
                    (state, name),
                    caption=f"{name}: around the bore in the plane of p_max",
                )
            )
            blocks.append(
                Figure(
                    f"bearing_{index}_axial.png",
                    figures.axial_profiles,
                    (state, name),
                    caption=f"{name}: along the bearing",
                )
            )
        return blocks


CAPABILITY = BearingFilm()
