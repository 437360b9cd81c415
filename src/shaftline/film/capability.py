"""The stern-tube bearing film as a capability: ``[bearing]`` in a case file,
``shaftline bearing solve``, ``bearing`` in results.json, a section of the report.

This module is the worked example of docs/architecture.md: the schema lives in
:mod:`shaftline.film.case`, the study and its solution in :mod:`shaftline.film.study`,
the figures in :mod:`shaftline.film.figures`; this class ties them to the pipeline.
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING, Any

from shaftline.helptext import strict_help
from shaftline.registry import BuildContext, Capability, Finding, Progress, Verb, no_progress
from shaftline.report.blocks import Block, Figure, Heading, Paragraph, Table, fmt

if TYPE_CHECKING:
    import numpy as np

    from shaftline.film.case import BearingSection
    from shaftline.film.stribeck import StribeckCurve
    from shaftline.film.study import BearingCase, BearingResult, BearingStudy, BearingStudyResult

#: Largest peak film pressure a class rule allows, Pa: NK's 40 MPa as quoted in seed 004
#: Sect. 2.2.1 (line 497 of the text); above it a result is not a stern-tube bearing's.
PEAK_PRESSURE_LIMIT = 40e6
#: Smallest film the Bureau Veritas rule accepts, m (seed 004 Sect. 2.2.1): a design criterion.
MIN_FILM_CRITERION = 30e-6

#: A load-centre offset below this is rounding of a symmetric film (the Newton residual's
#: moment over the load, 1e-17 m on seed 001's aligned rig), shown as 0 in the table: a real
#: offset of a misaligned or bent journal is millimetres (the JSON keeps the value).
ROUNDING_OFFSET = 1e-9  # m


def _shown(key: str, value: Any) -> Any:
    """A table value as shown: a load-centre offset at rounding level as 0."""
    if key == "load_centre_offset" and isinstance(value, float) and abs(value) < ROUNDING_OFFSET:
        return 0.0
    return value


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
#: Rows added for rough surfaces ([bearing.surface]).
MIXED_TABLE_ROWS = [
    ("λ = h_min/σ [-]", "min_film_ratio", 1.0, 4),
    ("asperity load share [%]", "asperity_load_share", 100.0, 3),
    ("peak asperity pressure [MPa]", "max_asperity_pressure", 1e-6, 3),
    ("real contact area [%]", "contact_area_ratio", 100.0, 3),
    ("boundary friction [N]", "boundary_friction_force", 1.0, 4),
    ("fluid friction [N]", "fluid_friction_force", 1.0, 4),
]


#: ``--strict`` of ``bearing solve`` and ``bearing stribeck``: the findings of
#: :meth:`BearingFilm.findings` with and without ``criterion``.
BEARING_STRICT = strict_help(
    "a case runs in mixed or boundary lubrication on rough surfaces (the asperities carry load) or its h_min is "
    f"below {MIN_FILM_CRITERION * 1e6:g} µm (Bureau Veritas)",
    "a film at its floor (contact), an equilibrium that does not converge, a heat balance that does not close, "
    f"h_min below three times the roughness of a smooth film, or p_max above {PEAK_PRESSURE_LIMIT / 1e6:g} MPa",
)


class BearingFilm(Capability["BearingSection", "BearingStudy", "BearingStudyResult"]):
    key = "bearing"
    title = "Stern-tube bearing film"
    verbs = (
        Verb(("bearing", "solve"), "Solve the bearing film at equilibrium under the case load.", strict=BEARING_STRICT),
        Verb(
            ("bearing", "stribeck"),
            "Solve the bearing, then sweep its speed: the Stribeck curve, h_min and the lift-off speed.",
            options={"task": "stribeck"},
            strict=BEARING_STRICT,
        ),
    )
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
        from shaftline.film.solve import solve_study

        return solve_study(
            study,
            lambda name: progress(f"solving {name}"),
            workers=options.get("workers"),
            scheduler=options.get("scheduler"),
            stribeck=options.get("task") == "stribeck",
        )

    def to_json(self, result: BearingStudyResult) -> dict[str, Any]:
        return result.to_dict()

    def findings(self, result: BearingStudyResult) -> list[Finding]:
        out: list[Finding] = []
        for run in result.cases:
            name, equilibrium, state = run.case.name, run.equilibrium, run.equilibrium.state
            if run.thermal is not None and not run.thermal.converged:
                out.append(
                    Finding(
                        f"{name}: the heat balance does not close — the film would run hotter than "
                        f"{run.thermal.effective_temperature:.4g} °C, the top of the lubricant's viscosity data; "
                        "the results are those at that temperature, not a solution."
                    )
                )
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
                        "the numbers are not a solution." + _unresolved_contact_zone(run.case, state.film)
                    )
                )
            roughness = run.case.surface_roughness
            rough = state.rough
            if rough is not None and not equilibrium.contact:
                if rough.lubrication_regime != "full film":
                    out.append(
                        Finding(
                            f"{name}: {rough.lubrication_regime} lubrication — h_min/σ = {rough.min_film_ratio:.3g}; "
                            f"the asperities carry {100 * rough.asperity_load_share:.3g} % of the load (peak "
                            f"{rough.max_asperity_pressure / 1e6:.3g} MPa) and give "
                            f"{100 * rough.boundary_friction_force / max(state.friction_force, 1e-300):.3g} % of the "
                            "friction (Greenwood-Tripp contact with Patir-Cheng flow factors): "
                            + (
                                "wear is expected (seed 001, Sect. 5.3)."
                                if rough.asperity_load_share >= 0.01
                                else "light asperity contact, below the 1 % of the load that defines the "
                                "transition speed: wear is possible."
                            ),
                            criterion=True,
                        )
                    )
            elif not equilibrium.contact and state.min_film_thickness < 3.0 * roughness:
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
        if result.stribeck is not None:
            out += _stribeck_findings(result.stribeck, result.cases[0].case)
        return out

    def _table(self, result: BearingStudyResult) -> Table:
        from shaftline.film.turbulence import transition_reynolds

        summaries = self.to_json(result)["cases"]
        rows = [
            [label] + [fmt(_shown(key, s[key]), scale, digits) for s in summaries]
            for label, key, scale, digits in TABLE_ROWS
        ]
        if any("min_film_ratio" in s for s in summaries):
            rows += [
                [label] + [fmt(s[key], scale, digits) if key in s else "smooth" for s in summaries]
                for label, key, scale, digits in MIXED_TABLE_ROWS
            ]
            rows.append(["lubrication regime"] + [s.get("lubrication_regime") or "smooth" for s in summaries])
        if any(run.thermal is not None for run in result.cases):
            for label, key in (
                ("inlet temperature [°C]", "inlet_temperature"),
                ("effective temperature [°C]", "effective_temperature"),
                ("outlet (hottest) temperature [°C]", "outlet_temperature"),
            ):
                rows.append(
                    [label]
                    + [
                        fmt(getattr(run.thermal, key), 1.0, 4) if run.thermal is not None else "-"
                        for run in result.cases
                    ]
                )
            rows.append(
                ["heat balance closed"]
                + [
                    ("yes" if run.thermal.converged else "NO") if run.thermal is not None else "-"
                    for run in result.cases
                ]
            )
        if any("max_reynolds_number" in s for s in summaries):
            rows.append(
                ["max local Reynolds number [-]"]
                + [fmt(s["max_reynolds_number"], 1.0, 4) if "max_reynolds_number" in s else "-" for s in summaries]
            )
            # The Taylor-vortex onset beside the flag: `auto` turns on there, below the Re_h of
            # 1000-2000 often quoted for turbulence in journal bearings (theory 17).
            rows.append(
                ["turbulent film (Taylor onset Re_h)"]
                + [
                    (
                        ("yes" if s["turbulent"] else "no")
                        + f" ({transition_reynolds(run.case.geometry.radius, run.case.geometry.radial_clearance):.0f})"
                    )
                    if "turbulent" in s
                    else "-"
                    for run, s in zip(result.cases, summaries, strict=True)
                ]
            )
        if any("max_liner_deformation" in s for s in summaries):
            rows.append(
                ["max liner deformation [µm]"]
                + [
                    fmt(s["max_liner_deformation"], 1e6, 4) if "max_liner_deformation" in s else "rigid"
                    for s in summaries
                ]
            )
        rows.append(["converged"] + ["yes" if s["converged"] else "NO" for s in summaries])
        rows.append(["contact (film at floor)"] + ["YES" if s["contact"] else "no" for s in summaries])
        return Table(["quantity"] + [s["name"] for s in summaries], rows, "Bearing film at equilibrium")

    def summary(self, result: BearingStudyResult) -> list[Block]:
        blocks: list[Block] = [self._table(result)]
        if result.stribeck is not None:
            blocks.append(_stribeck_table(result))
        return blocks

    def report(self, result: BearingStudyResult) -> list[Block]:
        blocks: list[Block] = [
            Paragraph(
                "Film equilibrium under the case load with the journal tilt held at the given misalignment. "
                "Pressures are gauge; θ from the top of the bore in the sense of rotation; z from the aft edge."
            ),
            self._table(result),
        ]
        blocks += _coefficient_tables(result)
        blocks += _study_blocks(result)
        for index, run in enumerate(result.cases):
            blocks += _case_figures(index, run)
        return blocks


def _coefficient_tables(result: BearingStudyResult) -> list[Block]:
    """The film's stiffness and damping of every case that has them, and its moment-by-tilt
    block where the 4 x 4 coefficients were found."""
    blocks: list[Block] = []
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
    return blocks


def _study_blocks(result: BearingStudyResult) -> list[Block]:
    """The blocks of the study as a whole: the Stribeck curve (table and figure) and the
    comparison of the base case with its variants."""
    from shaftline.film import figures

    blocks: list[Block] = []
    if result.stribeck is not None:
        blocks.append(_stribeck_table(result))
        blocks.append(
            Figure(
                "bearing_stribeck.png",
                figures.stribeck,
                (result.stribeck, result.cases[0].case.name),
                caption="Stribeck curve (friction coefficient) and h_min against speed, with the "
                "lubrication regimes of lambda = h_min/σ and the transition speed (asperity share below 1 %)",
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
    return blocks


def _case_figures(index: int, run: BearingResult) -> list[Block]:
    """The heading and figures of case ``index`` of a study: film and pressure, and the
    contact, liner and Reynolds-number maps where the case has them, and its profiles."""
    from shaftline.film import figures

    state, name = run.equilibrium.state, run.case.name
    blocks: list[Block] = [Heading(name)]
    blocks.append(
        Figure(
            f"bearing_{index}_maps.png",
            figures.film_and_pressure_maps,
            (state, name),
            caption=f"{name}: film and pressure",
        )
    )
    if state.rough is not None:
        blocks.append(
            Figure(
                f"bearing_{index}_contact.png",
                figures.contact_maps,
                (state, name),
                caption=f"{name}: asperity contact pressure and film-thickness ratio λ = h/σ",
            )
        )
    if state.liner is not None:
        model = run.case.geometry.liner.model if run.case.geometry.liner is not None else "column"
        blocks.append(
            Figure(
                f"bearing_{index}_liner.png",
                figures.liner_maps,
                (state, name),
                caption=f"{name}: liner deformation ({model} model) and the film including it",
            )
        )
    if state.turbulence is not None:
        blocks.append(
            Figure(
                f"bearing_{index}_reynolds.png",
                figures.reynolds_map,
                (state, name),
                caption=f"{name}: local Reynolds number ρωRh/μ of the film (turbulence coefficients "
                f"{'applied' if state.turbulence.turbulent else 'not applied'})",
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


def _stribeck_table(result: BearingStudyResult) -> Table:
    import numpy as np

    curve = result.stribeck
    assert curve is not None
    # the lowest friction of the speeds that are solutions (converged, not at the floor)
    solutions = ~curve.stalled & ~curve.contact.astype(bool)
    lowest_friction, lowest_speed = "- (no speed carried by the film)", "-"
    if solutions.any():
        lowest = int(np.where(solutions, curve.friction_coefficient, np.inf).argmin())
        lowest_friction = fmt(float(curve.friction_coefficient[lowest]))
        lowest_speed = fmt(curve.speed[lowest] * 30 / math.pi)
    transition = "-" if curve.transition_speed is None else fmt(curve.transition_speed * 30.0 / math.pi, 1, 4)
    if curve.transition_uncertain:
        transition += " (uncertain: among speeds not converged)"
    rows = [
        ["speeds [rpm]", f"{fmt(curve.speed[0] * 30 / math.pi)} to {fmt(curve.speed[-1] * 30 / math.pi)}"],
        ["transition speed, asperity share < 1 % [rpm]", transition],
        ["lowest friction coefficient [-]", lowest_friction],
        ["at [rpm]", lowest_speed],
        ["speeds in contact (load not carried)", str(int(curve.contact.sum()))],
    ]
    # A rough film that stalls above its boundary limit is not contact (docs/theory.md, "Boundary
    # lubrication"): said apart, so that a curve with such speeds is not read as all converged.
    stalled = int(curve.stalled.sum())
    if stalled:
        rows.append(["speeds not converged (above the contact limit)", str(stalled)])
    if curve.max_reynolds_number is not None and curve.turbulent is not None:
        # turbulence on or auto: where the coefficients applied, so the curve's change of slope
        # there is not read as a regime change of the asperity contact.
        turbulent = np.flatnonzero(curve.turbulent)
        onset = "-" if turbulent.size == 0 else fmt(curve.speed[turbulent[0]] * 30 / math.pi)
        rows += [
            ["largest local Reynolds number [-]", fmt(float(np.nanmax(curve.max_reynolds_number)))],
            ["turbulent film from [rpm]", onset],
        ]
    return Table(["Stribeck curve", result.cases[0].case.name], rows, "Stribeck curve of the base case")


CAPABILITY = BearingFilm()


def _unresolved_contact_zone(case: BearingCase, film: np.ndarray) -> str:
    """For a rigid rough bore whose contact zone (the film within sigma of its minimum) spans fewer
    nodes than the settling needs, what a user can change ("" otherwise): on such a grid the
    discrete film force jumps as the minimum moves between nodes and Newton stalls (docs/theory.md,
    "Rigid rough bore at low speed")."""
    from shaftline.film.surfaces import contact_zone_nodes, nodes_to_resolve_contact_zone

    surface = case.geometry.surface
    if surface is None or case.geometry.liner is not None:
        return ""
    needed = case.options.settling.zone_nodes
    zone = contact_zone_nodes(film, surface.sigma)
    if zone >= needed:
        return ""
    return (
        f" The rough contact zone (film within σ of its minimum) spans {zone} of the {film.shape[1]} nodes round "
        f"the bore, too few for the discrete film force to have a root Newton can follow (at least "
        f"{needed} needed): set [bearing.solver] circumferential_nodes to about "
        f"{nodes_to_resolve_contact_zone(film, surface.sigma, needed)}, or model the liner ([bearing.liner]), which "
        'widens the zone (docs/theory.md, "Rigid rough bore at low speed").'
    )


def _stribeck_findings(curve: StribeckCurve, case: BearingCase) -> list[Finding]:
    """The speeds of a Stribeck curve whose equilibrium stalled above the contact limit (their
    points are not solutions), with what would resolve a rigid rough bore's contact zone there:
    near ε = 1 the zone (film within σ of its minimum) is 2 sqrt(2σ/c) wide (docs/theory.md, "Rigid
    rough bore at low speed"), so ``SettleOptions.zone_nodes`` + 1 nodes
    across it (one for the count's rounding) need that many times 2 pi over its width round the bore.
    Advisory (``criterion``) while the transition speed rests on solved speeds: the rest of the
    curve stands, and the table counts them too; not acceptable when the transition lies among
    them (``StribeckCurve.transition_uncertain``)."""
    stalled = curve.stalled
    if not stalled.any():
        return []
    rpm = curve.speed[stalled] * 30.0 / math.pi
    text = (
        f"Stribeck curve: {int(stalled.sum())} of {curve.speed.size} speeds ({fmt(float(rpm.min()))} to "
        f"{fmt(float(rpm.max()))} rpm) did not converge above the contact limit; their points are not solutions "
        "(drawn apart, without a regime)."
    )
    if curve.transition_uncertain:
        text += (
            " The transition speed rests on them: it lies among speeds that did not converge, so it is not a result."
        )
    geometry, nodes = case.geometry, case.options.circumferential_nodes
    zone_nodes = case.options.settling.zone_nodes
    if geometry.surface is not None and geometry.liner is None:
        width = 2.0 * math.sqrt(2.0 * geometry.surface.sigma / geometry.radial_clearance)  # rad, at ε = 1
        needed = math.ceil((zone_nodes + 1) * 2.0 * math.pi / width)
        needed += needed % 2
        if needed > nodes:
            text += (
                f" Near ε = 1 the rough contact zone (film within σ of its minimum) is {math.degrees(width):.2g}° "
                f"wide, {nodes * width / (2.0 * math.pi):.2g} of the {nodes} nodes round the bore (at least "
                f"{zone_nodes} needed for a root Newton can follow): [bearing.solver] circumferential_nodes "
                f'of about {needed} resolve it, or model the liner (docs/theory.md, "Rigid rough bore at low speed").'
            )
    # Advisory while the transition speed rests on solved speeds (the curve's other points
    # stand); not acceptable when it does not.
    return [Finding(text, criterion=not curve.transition_uncertain)]
