"""The presentation of the film supports of ``[alignment]`` and of its influence matrices: their fields in results.json,
the report's and the summary's film and point-versus-film tables, and the notes on what
those tables have no columns for."""

from __future__ import annotations

import math
from typing import TYPE_CHECKING, Any

from shaftline.report.blocks import Paragraph, Table, fmt

if TYPE_CHECKING:
    from shaftline.shaft.alignment import InfluenceMatrix
    from shaftline.shaft.film_supports import CoupledResult


#: Units of the film-support fields of results.json.
FILM_UNITS = {
    "force_y": "N",
    "force_z": "N",
    "min_film_thickness": "m",
    "min_film_theta_deg": "deg",
    "min_film_z": "m",
    "max_pressure": "Pa",
    "max_pressure_theta_deg": "deg",
    "max_pressure_z": "m",
    "moment_y": "N m, first moment of the vertical film force about the bearing's mid-length",
    "moment_z": "N m, first moment of the horizontal film force about the bearing's mid-length",
    "support_point_y": "m, the vertical resultant's position from the bearing's mid-length, + forward (towards the "
    "bow); null where it lies outside the bearing (the film carries a couple)",
    "support_point_z": "m, the horizontal resultant's position, as support_point_y",
    "couple_planes": "the planes in which the film carries a couple (its resultant outside the bearing)",
    "attitude_angle_deg": "deg",
    "power_loss": "W",
    "side_leakage": "m^3/s",
    "centre_y": "m",
    "centre_z": "m",
    "line_load": "N/m",
    "stiffness": "rows F_y, F_z [N], M_y, M_z [N m]; columns y, z [m], tilt_y, tilt_z [rad]",
    "damping": "rows F_y, F_z [N], M_y, M_z [N m]; columns vy, vz [m/s], tilt rates [rad/s]",
    "coefficients_note": "empty, or why stiffness and damping are null (not available)",
    "asperity_load_share": "share of the film force carried by asperity contact (rough surfaces; 0 smooth)",
    "min_film_ratio": "h_min over the composite roughness (rough surfaces; null smooth)",
    "max_liner_deformation": "m (elastic liner; 0 without)",
    "max_reynolds_number": "largest local Reynolds number rho omega R h / mu (only with turbulence on or auto)",
    "turbulent": "whether the turbulence coefficients were applied (only with turbulence on or auto)",
}


def _turbulence_json(state: Any) -> dict[str, Any]:
    """The film's largest local Reynolds number and turbulence flag, with turbulence on or auto
    (the film solution has its Reynolds-number map then); nothing for a laminar film, whose
    JSON keeps its keys."""
    if state.turbulence is None:
        return {}
    return {"max_reynolds_number": state.turbulence.max_reynolds_number, "turbulent": state.turbulence.turbulent}


def influence_json(influence: InfluenceMatrix) -> dict[str, Any]:
    """An influence matrix with what it is: ``kind`` ("point" or "film_tangent"), its label and
    the condition a film tangent was taken in; ``matrix[i][j]`` = d reaction_i / d offset_j, N/m."""
    return {
        "bearings": influence.names,
        "matrix": influence.matrix.tolist(),
        "kind": influence.kind,
        "label": influence.label,
        "condition": influence.condition,
    }


def _coupled_json(coupled: CoupledResult) -> dict[str, Any]:
    """One condition's film supports: convergence, each film, and the point-support comparison."""
    return {
        "condition": coupled.condition.name,
        "converged": coupled.converged,
        "iterations": coupled.iterations,
        "film_solutions": coupled.film_solutions,
        "residual_history": coupled.residual_history,
        "force_residual": coupled.force_residual,
        "message": coupled.message,
        # The line's tangent influence coefficients at this condition's equilibrium (null when
        # it did not converge or a film grounded), as "influence_matrix" is written.
        "influence_matrix": None if coupled.influence is None else influence_json(coupled.influence),
        "films": [
            {
                "name": f.name,
                "contact": f.contact,
                "force_y": f.force_y,
                "force_z": f.force_z,
                "min_film_thickness": f.state.min_film_thickness,
                "min_film_theta_deg": math.degrees(f.state.min_film_theta),
                "min_film_z": f.state.min_film_z,
                "max_pressure": f.state.max_pressure,
                "max_pressure_theta_deg": math.degrees(f.state.max_pressure_theta),
                "max_pressure_z": f.state.max_pressure_z,
                "moment_y": f.moment_y,
                "moment_z": f.moment_z,
                "support_point_y": _finite(f.support_point_y),
                "support_point_z": _finite(f.support_point_z),
                "couple_planes": list(f.couple_planes),
                "eccentricity_ratio": f.state.eccentricity_ratio,
                "attitude_angle_deg": math.degrees(f.state.attitude_angle),
                "relative_slope": f.relative_slope,
                "power_loss": f.state.power_loss,
                "side_leakage": f.state.side_leakage,
                # Mixed lubrication and the liner: a water-lubricated, soft-lined stern tube.
                "asperity_load_share": f.state.asperity_load_share,
                "min_film_ratio": f.state.min_film_ratio if math.isfinite(f.state.min_film_ratio) else None,
                "max_liner_deformation": f.state.max_liner_deformation,
                **_turbulence_json(f.state),
                "centre_line": {
                    "z": f.z.tolist(),
                    "centre_y": f.centre_y.tolist(),
                    "centre_z": f.centre_z.tolist(),
                    "bore_y": f.bore_y.tolist(),
                    "bore_z": f.bore_z.tolist(),
                },
                "line_load": {"y": f.line_load[0].tolist(), "z": f.line_load[1].tolist()},
                # null when not available (an elastic liner that does not settle there): NaN is not JSON.
                "stiffness": f.stiffness.tolist() if all(map(math.isfinite, f.stiffness.flat)) else None,
                "damping": f.damping.tolist() if all(map(math.isfinite, f.damping.flat)) else None,
                "coefficients_note": f.coefficients_note,
            }
            for f in coupled.films
        ],
        "point_supports": [
            {
                "name": b.name,
                "reaction_y": b.reaction_y,
                "reaction_z": b.reaction_z,
                "contact": b.contact,
                "relative_slope": b.relative_slope,
            }
            for b in coupled.point_supports.bearings
        ],
    }


def _film_rows(coupled: CoupledResult) -> list[list[str]]:
    rows = []
    for f in coupled.films:
        state = f.state
        rows.append(
            [
                f.name,
                fmt(f.force_y, 1e-3),
                fmt(state.min_film_thickness, 1e6),
                f"{math.degrees(state.min_film_theta):.0f} / {state.min_film_z:.3f}",
                fmt(state.max_pressure, 1e-6),
                fmt(f.support_point_y, 1e3) if math.isfinite(f.support_point_y) else "couple",
                fmt(state.eccentricity_ratio, 1.0),
                f"{math.degrees(state.attitude_angle):.1f}",
                fmt(f.relative_slope, 1e3),
                fmt(state.power_loss, 1e-3),
                "CONTACT" if f.contact else "film",
            ]
        )
    return rows


FILM_HEADERS = [
    "bearing",
    "force [kN]",
    "h_min [µm]",
    "at θ [deg] / z [m]",
    "p_max [MPa]",
    "support pt [mm]",
    "ε",
    "attitude [deg]",
    "rel. slope [mrad]",
    "power [kW]",
    "state",
]


def _film_notes(coupled: CoupledResult) -> Paragraph | None:
    """The film results the table has no columns for, where a film has them: a couple the film
    carries (its resultant outside the bearing in a plane), rough surfaces
    (film ratio, asperity share), an elastic liner (its largest deformation), turbulence on or
    auto (largest local Reynolds number and whether the coefficients applied). A film that fell
    back to contact is said to be at its last journal line, not at an equilibrium, and its
    relative slope there is told apart from the alignment table's (the line solved with the
    bearing in contact); converged, the two are the same chord."""
    parts = []
    for f in coupled.films:
        state = f.state
        notes = []
        if f.contact:
            solved = coupled.condition.bearing(f.name).relative_slope
            notes.append(
                f"relative slope {f.relative_slope * 1e3:.4g} mrad at that line (the film table's); "
                f"{solved * 1e3:.4g} mrad with the bearing in contact at the bore (the alignment table's and "
                "the comparison's)"
            )
        if f.coefficients_note:
            notes.append(f.coefficients_note)
        for plane in f.couple_planes:
            force, moment = (f.force_y, f.moment_y) if plane == "vertical" else (f.force_z, f.moment_z)
            notes.append(
                f"the film carries a couple in the {plane} plane ({moment * 1e-3:.3g} kN m about mid-length with "
                f"{force * 1e-3:.3g} kN: its resultant lies {abs(moment / force) if force else math.inf:.3g} m from "
                "mid-length, outside the bearing, so it has no support point there)"
            )
        if state.rough is not None:
            notes.append(
                f"λ = h_min/σ {state.rough.min_film_ratio:.3g}, asperities carry "
                f"{state.rough.asperity_load_share * 100:.3g} % of the load "
                f"({state.rough.lubrication_regime} lubrication)"
            )
        if state.max_liner_deformation > 0:
            notes.append(f"liner deformed by up to {state.max_liner_deformation * 1e6:.3g} µm")
        if state.turbulence is not None:
            kind = "turbulent (coefficients applied)" if state.turbulence.turbulent else "laminar"
            notes.append(f"largest local Reynolds number {state.turbulence.max_reynolds_number:.4g}, {kind}")
        if notes:
            # A grounded film's state is the last journal line reached, not an equilibrium of
            # shaft and film: its asperity share is not the share of the bearing's load.
            where = (
                " (at the last journal line before the fall-back to contact, not an equilibrium)" if f.contact else ""
            )
            parts.append(f"{f.name}{where}: " + "; ".join(notes))
    if not parts:
        return None
    return Paragraph(f"Film bearings, {coupled.condition.name}: " + ". ".join(parts) + ".")


def _count(n: int, noun: str) -> str:
    """``"1 iteration"``, ``"3 iterations"``."""
    return f"{n} {noun}" + ("" if n == 1 else "s")


def _finite(value: float) -> float | None:
    """A float for the JSON, None (null) where it is nan: JSON has no nan."""
    return float(value) if math.isfinite(value) else None


def _comparison_rows(coupled: CoupledResult) -> list[list[str]]:
    rows = []
    for point, film in zip(coupled.point_supports.bearings, coupled.condition.bearings, strict=True):
        shift = film.reaction_y - point.reaction_y
        share = f"{100 * shift / point.reaction_y:+.1f}" if abs(point.reaction_y) > 1e-9 else "-"
        rows.append(
            [
                film.name,
                fmt(point.reaction_y, 1e-3),
                fmt(film.reaction_y, 1e-3),
                fmt(shift, 1e-3),
                share,
                fmt(point.relative_slope, 1e3),
                fmt(film.relative_slope, 1e3),
            ]
        )
    return rows


COMPARISON_HEADERS = [
    "bearing",
    "point [kN]",
    "film [kN]",
    "shift [kN]",
    "shift [%]",
    "rel. slope point [mrad]",
    "rel. slope film [mrad]",
]


#: Columns of the film tables kept in the terminal summary (80 columns).
NARROW_FILM = (0, 1, 2, 4, 5, 10)
NARROW_COMPARISON = (0, 1, 2, 4, 5, 6)


def _narrowed(headers: list[str], rows: list[list[str]], title: str, keep: tuple[int, ...] | None) -> Table:
    if keep is None:
        return Table(headers, rows, title)
    return Table([headers[k] for k in keep], [[row[k] for k in keep] for row in rows], title)
