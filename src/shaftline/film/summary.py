"""Flat, documented summaries of bearing results for tables and JSON."""

from __future__ import annotations

import math
from collections.abc import Callable
from typing import Any

import numpy as np

from shaftline.film.bearing import BearingState, Equilibrium
from shaftline.film.dynamics import DynamicCoefficients

#: (key, unit, description, value) for every scalar written to JSON. The README's
#: table of JSON fields is generated from the same list.
FIELDS: list[tuple[str, str, str, Callable[[BearingState], Any]]] = [
    (
        "eccentricity_ratio",
        "-",
        "journal eccentricity from the bore centre at mid-plane / radial clearance",
        lambda s: s.eccentricity_ratio,
    ),
    (
        "attitude_angle_deg",
        "deg",
        "load line to line of centres, positive in the sense of rotation",
        lambda s: math.degrees(s.attitude_angle),
    ),
    (
        "position_angle_deg",
        "deg",
        "bearing angle of the line of centres (from top, in the sense of rotation)",
        lambda s: math.degrees(s.position_angle),
    ),
    (
        "ey",
        "m",
        "vertical offset of the journal centre at mid-plane from the nominal bore axis",
        lambda s: s.position.ey,
    ),
    ("ez", "m", "horizontal (starboard) offset of the journal centre at mid-plane", lambda s: s.position.ez),
    ("tilt_y", "rad", "journal tilt in the vertical plane (dy/dx)", lambda s: s.position.tilt_y),
    ("tilt_z", "rad", "journal tilt in the horizontal plane (dz/dx)", lambda s: s.position.tilt_z),
    ("min_film_thickness", "m", "smallest film thickness h_min", lambda s: s.min_film_thickness),
    ("min_film_theta_deg", "deg", "bearing angle of h_min", lambda s: math.degrees(s.min_film_theta)),
    ("min_film_z", "m", "axial position of h_min from the aft edge", lambda s: s.min_film_z),
    ("max_pressure", "Pa", "largest film pressure p_max (gauge)", lambda s: s.max_pressure),
    ("max_pressure_theta_deg", "deg", "bearing angle of p_max", lambda s: math.degrees(s.max_pressure_theta)),
    ("max_pressure_z", "m", "axial position of p_max from the aft edge", lambda s: s.max_pressure_z),
    ("mean_pressure", "Pa", "load capacity / (L D)", lambda s: s.mean_pressure),
    ("load_capacity", "N", "magnitude of the film force", lambda s: s.load_capacity),
    ("force_y", "N", "vertical film force on the journal (+ up)", lambda s: s.force_y),
    ("force_z", "N", "horizontal film force on the journal (+ starboard)", lambda s: s.force_z),
    ("moment_y", "N m", "first moment of the vertical film force about mid-plane", lambda s: s.moment_y),
    ("moment_z", "N m", "first moment of the horizontal film force about mid-plane", lambda s: s.moment_z),
    (
        "load_centre_offset",
        "m",
        "axial position of the film resultant from mid-plane (+ forward)",
        lambda s: s.load_centre_offset,
    ),
    ("friction_force", "N", "shear force on the journal", lambda s: s.friction_force),
    ("friction_torque", "N m", "friction torque on the journal", lambda s: s.friction_torque),
    ("friction_coefficient", "-", "friction force / load capacity", lambda s: s.friction_coefficient),
    ("power_loss", "W", "friction power", lambda s: s.power_loss),
    (
        "inlet_flow",
        "m^3/s",
        "flow entering the film (groove supply, or across the line of maximum film)",
        lambda s: s.inlet_flow,
    ),
    ("side_leakage", "m^3/s", "net flow out through both bearing edges", lambda s: s.side_leakage),
    ("sommerfeld_number", "-", "(R/c)^2 eta N / P, N in rev/s", lambda s: s.sommerfeld_number),
    (
        "contact",
        "-",
        "true when the film reaches the solver's film floor (rough surfaces: the boundary limit 3σ "
        "below the mean plane; h_min, the mean-plane separation, is negative in boundary "
        "lubrication: docs/theory.md Sect. 17)",
        lambda s: s.contact,
    ),
]


#: Results of rough surfaces (``geometry.surface``, a ``[bearing.surface]`` table), written only
#: for a rough film: a smooth film's JSON keeps exactly its keys.
MIXED_FIELDS: list[tuple[str, str, str, Callable[[BearingState], Any]]] = [
    ("min_film_ratio", "-", "h_min / composite RMS roughness sigma (lambda)", lambda s: s.min_film_ratio),
    (
        "lubrication_regime",
        "-",
        "boundary (lambda < 1), mixed (1-3) or full film (> 3), from h_min",
        lambda s: s.lubrication_regime,
    ),
    ("asperity_load", "N", "magnitude of the asperity contact force (Greenwood-Tripp)", lambda s: s.asperity_load),
    (
        "asperity_load_share",
        "-",
        "share of the carried load on the asperities (their force along the total force / total force)",
        lambda s: s.asperity_load_share,
    ),
    ("max_asperity_pressure", "Pa", "largest asperity contact pressure", lambda s: s.max_asperity_pressure),
    ("contact_area_ratio", "-", "real asperity contact area / bore area", lambda s: s.contact_area_ratio),
    ("fluid_friction_force", "N", "friction force of the film's shear", lambda s: s.fluid_friction_force),
    (
        "boundary_friction_force",
        "N",
        "friction force of the asperities (boundary coefficient x asperity load)",
        lambda s: s.boundary_friction_force,
    ),
]


#: Results of an elastic liner (``geometry.liner``, a ``[bearing.liner]`` table), written only
#: with one: a rigid bore's JSON keeps exactly its keys.
LINER_FIELDS: list[tuple[str, str, str, Callable[[BearingState], Any]]] = [
    (
        "max_liner_deformation",
        "m",
        "largest liner deformation (column or layer model); film, h_min and p_max include the deformation",
        lambda s: s.max_liner_deformation,
    ),
]


#: Results of a turbulent-film model (``[solver] turbulence`` on or auto), written only then: a
#: laminar case's JSON keeps exactly its keys.
TURBULENCE_FIELDS: list[tuple[str, str, str, Callable[[BearingState], Any]]] = [
    (
        "max_reynolds_number",
        "-",
        "largest local Reynolds number rho omega R h / mu of the film",
        lambda s: s.max_reynolds_number,
    ),
    (
        "turbulent",
        "-",
        "whether the turbulence coefficients were applied (on, or auto above 41.3 sqrt(R/c))",
        lambda s: s.turbulent,
    ),
]


def _clean(value: Any) -> Any:
    if isinstance(value, (bool, np.bool_)):
        return bool(value)
    if isinstance(value, (float, np.floating)):
        return float(value) if math.isfinite(value) else None
    return value


def state_summary(state: BearingState) -> dict[str, Any]:
    """Scalar results of a film solution, keyed as in :data:`FIELDS` (and :data:`MIXED_FIELDS`
    for rough surfaces)."""
    fields = FIELDS + MIXED_FIELDS if state.asperity_pressure is not None else FIELDS
    if state.liner_deformation is not None:
        fields = fields + LINER_FIELDS
    if state.reynolds_number is not None:
        fields = fields + TURBULENCE_FIELDS
    return {key: _clean(getter(state)) for key, _, _, getter in fields}


def units(mixed: bool = False, liner: bool = False, turbulence: bool = False) -> dict[str, str]:
    """Unit of every key of :func:`state_summary` (with ``mixed``, of the rough-surface keys too;
    with ``liner``, of the elastic liner's; with ``turbulence``, of the turbulent film's)."""
    fields = (FIELDS + MIXED_FIELDS if mixed else FIELDS) + (LINER_FIELDS if liner else [])
    fields = fields + (TURBULENCE_FIELDS if turbulence else [])
    return {key: unit for key, unit, _, _ in fields}


def equilibrium_summary(equilibrium: Equilibrium, coefficients: DynamicCoefficients | None = None) -> dict[str, Any]:
    """Scalar results of an equilibrium, with stiffness and damping when given."""
    out = state_summary(equilibrium.state)
    out.update(
        {
            "load_y": equilibrium.load_y,
            "load_z": equilibrium.load_z,
            "converged": equilibrium.converged,
            "contact": bool(equilibrium.contact),
            "iterations": equilibrium.iterations,
            "force_residual": equilibrium.residual,
        }
    )
    # Present but null where the film does not carry the load (no linearisation there).
    out["stiffness"] = coefficients.stiffness.tolist() if coefficients is not None else None
    out["damping"] = coefficients.damping.tolist() if coefficients is not None else None
    for key in ("stiffness_4x4", "damping_4x4"):
        matrix = getattr(coefficients, key) if coefficients is not None else None
        out[key] = matrix.tolist() if matrix is not None else None
    return {k: _clean(v) for k, v in out.items()}


#: (key, unit, description) of the equilibrium's own fields in JSON.
EXTRA_FIELDS: list[tuple[str, str, str]] = [
    ("load_y", "N", "applied vertical load on the journal (− downward)"),
    ("load_z", "N", "applied horizontal load (+ starboard)"),
    ("converged", "-", "equilibrium reached within the tolerance"),
    ("iterations", "-", "Newton iterations"),
    ("force_residual", "N", "magnitude of film force + load at the end"),
    ("stiffness", "N/m, [[Kyy, Kyz], [Kzy, Kzz]]", "film stiffness matrix in (y, z); null where the film fails"),
    ("damping", "N s/m, [[Cyy, Cyz], [Czy, Czz]]", "film damping matrix in (y, z); null where the film fails"),
    (
        "stiffness_4x4",
        "rows (Fy, Fz) in N, (My, Mz) in N m; columns (ey, ez) per m, (tilt_y, tilt_z) per rad",
        "-d(Fy, Fz, My, Mz)/d(ey, ez, tilt_y, tilt_z): film stiffness with the tilt (moment) terms, "
        "M the first moments about mid-plane as moment_y, moment_z; `stiffness` is its top-left block; "
        "null where the film fails",
    ),
    (
        "damping_4x4",
        "as stiffness_4x4, per m/s and per rad/s",
        "-d(Fy, Fz, My, Mz)/d(vy, vz, tilt rates): film damping with the tilt terms; `damping` is "
        "its top-left block; null where the film fails",
    ),
]
EXTRA_UNITS = {key: unit for key, unit, _ in EXTRA_FIELDS}


#: (key, unit, description) of the ``stribeck`` block of ``shaftline bearing stribeck``.
STRIBECK_FIELDS: list[tuple[str, str, str]] = [
    ("stribeck.speed_rpm", "rpm", "speeds of the sweep (the base case's load and tilt)"),
    ("stribeck.friction_coefficient", "-", "friction force / load at each speed (the Stribeck curve)"),
    ("stribeck.asperity_load_share", "-", "share of the load on the asperities at each speed"),
    ("stribeck.min_film_thickness", "m", "h_min at each speed"),
    ("stribeck.min_film_ratio", "-", "h_min / sigma at each speed (null for smooth surfaces)"),
    (
        "stribeck.lubrication_regime",
        "-",
        "boundary, mixed or full film at each speed (null when smooth, and at a speed that did not converge)",
    ),
    ("stribeck.converged", "-", "equilibrium reached at each speed"),
    ("stribeck.contact", "-", "load not carried within the clearance at each speed"),
    (
        "stribeck.max_reynolds_number",
        "-",
        "largest local Reynolds number at each speed (with [bearing.solver] turbulence on or auto only)",
    ),
    (
        "stribeck.turbulent",
        "-",
        "whether the turbulence coefficients applied at each speed (with turbulence on or auto only)",
    ),
    (
        "stribeck.transition_speed_rpm",
        "rpm",
        "speed above which the asperities carry less than 1 % of the load, from the converged speeds and "
        "those in contact (share 1) (null: not crossed in the range)",
    ),
    (
        "stribeck.transition_uncertain",
        "-",
        "true where a speed that did not converge lies where the transition could be: the transition "
        "speed is then not a result (exit 3)",
    ),
]


def field_table() -> str:
    """The Markdown table of every JSON field of a bearing case (the README's)."""
    rows = [(key, unit, text) for key, unit, text, _ in FIELDS] + EXTRA_FIELDS
    rows += [(key, unit, f"{text} (with [bearing.surface] only)") for key, unit, text, _ in MIXED_FIELDS]
    rows += [(key, unit, f"{text} (with [bearing.liner] only)") for key, unit, text, _ in LINER_FIELDS]
    rows += [
        (key, unit, f"{text} (with [bearing.solver] turbulence on or auto only)")
        for key, unit, text, _ in TURBULENCE_FIELDS
    ]
    rows.append(
        (
            "reynolds_number_map",
            "-",
            "local Reynolds number over the bore, rows from the aft edge, columns from the grid's first angle "
            "(with [bearing.solver] turbulence on or auto only)",
        )
    )
    rows += [(key, unit, f"{text} (`bearing stribeck` only)") for key, unit, text in STRIBECK_FIELDS]
    return (
        "| key | unit | meaning |\n|---|---|---|\n"
        + "\n".join(f"| `{key}` | {unit} | {text} |" for key, unit, text in rows)
        + "\n"
    )
