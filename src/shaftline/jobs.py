"""The jobs behind the command line, usable the same way from a notebook.

``solve_bearings`` runs every bearing problem of a case; ``write_bearing_outputs``
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
from shaftline.cases.schema import BearingCase, Case
from shaftline.film.bearing import Equilibrium, JournalBearing
from shaftline.film.dynamics import DynamicCoefficients, dynamic_coefficients
from shaftline.film.summary import EXTRA_UNITS, equilibrium_summary, units
from shaftline.report import figures
from shaftline.report.html import Section, image, render, table


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


def results_document(case: Case, runs: list[BearingRun]) -> dict[str, Any]:
    """JSON document: the base case's fields at top level, further variants in ``variants``."""
    summaries = [run.summary() for run in runs]
    document: dict[str, Any] = {"shaftline_version": shaftline.__version__, "case": case.name}
    document.update(summaries[0])
    document["variants"] = summaries[1:]
    document["units"] = {**units(), **EXTRA_UNITS}
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


def write_bearing_outputs(case: Case, runs: list[BearingRun], out: Path, case_file: str) -> Path:
    """Write ``results.json``, figures and ``report.html`` into ``out`` (atomically)."""
    with atomic_folder(out) as folder:
        (folder / "results.json").write_text(dumps(results_document(case, runs)), encoding="utf-8")
        section = bearing_section(runs, folder)
        html = render(case.name, case.description, case_file, [section])
        (folder / "report.html").write_text(html, encoding="utf-8")
    return Path(out)
