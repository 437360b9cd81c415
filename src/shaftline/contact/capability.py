"""Lubricated contacts as a capability: ``[contact]`` in a case file, ``shaftline contact
ehl``, ``contact`` in results.json, a section of the report."""

from __future__ import annotations

import math
from typing import TYPE_CHECKING, Any

from shaftline.helptext import strict_help
from shaftline.registry import BuildContext, Capability, Finding, Progress, Verb, no_progress
from shaftline.report.blocks import Block, Figure, Paragraph, Table

if TYPE_CHECKING:
    from shaftline.contact.case import ContactSection
    from shaftline.contact.lubricated import ContactState
    from shaftline.contact.study import ContactResult, ContactStudy

#: Fields of a :class:`ContactState` written to results.json, with their units.
STATE_FIELDS = {
    "peak_pressure": "Pa",
    "mean_pressure": "Pa",
    "half_width": "m",
    "max_shear": "Pa",
    "max_shear_depth": "m",
    "rolling_speed": "m/s",
    "sliding_speed": "m/s",
    "slide_roll": "",
    "central_film": "m",
    "minimum_film": "m",
    "thermal_factor": "",
    "film_ratio": "",
    "load_sharing": "",
    "full_film_friction": "",
    "mixed_friction": "",
    "thermal_correction": "",
    "friction": "",
    "power_intensity": "W/m^2",
}


def _number(value: Any) -> float | None:
    number = float(value)
    return number if math.isfinite(number) else None


def state_json(state: ContactState) -> dict[str, Any]:
    """A :class:`ContactState` as JSON: numbers at a point, lists over a sweep (NaN as null)."""
    import numpy as np

    out: dict[str, Any] = {}
    for name in STATE_FIELDS:
        array = np.asarray(getattr(state, name))
        out[name] = _number(array) if array.ndim == 0 else [_number(v) for v in array.ravel()]
    return out


class LubricatedContact(Capability["ContactSection", "ContactStudy", "ContactResult"]):
    key = "contact"
    title = "Lubricated contact: Hertz pressure, EHL film and mixed friction"
    verbs = (
        Verb(
            ("contact", "ehl"),
            "Hertz pressure, EHL film, Lambda and mixed friction (seed 002) of a lubricated contact, with "
            "load and speed sweeps.",
            # what LubricatedContact.findings judges, with and without ``criterion``
            strict=strict_help(
                "the contact runs boundary-dominated at the operating point (seed 002 Eq. 2)",
                "seed 002's thermal correction clipped to 0 beyond its fit range (friction 0: no result)",
            ),
        ),
    )

    def schema(self) -> type[ContactSection]:
        from shaftline.contact.case import ContactSection

        return ContactSection

    def build(self, section: ContactSection, context: BuildContext) -> ContactStudy:
        from shaftline.contact.case import build_study

        return build_study(section, context)

    def solve(self, study: ContactStudy, progress: Progress = no_progress, **options: Any) -> ContactResult:
        from shaftline.contact.study import solve_contact

        return solve_contact(study, lambda step: progress(f"solving {step}"))

    def to_json(self, result: ContactResult) -> dict[str, Any]:
        from shaftline.contact.ehl import REGIMES

        study, op = result.study, result.operating
        model, lubricant = study.model, study.model.lubricant
        regime = int(op.regime)
        return {
            "units": {
                **{k: v for k, v in STATE_FIELDS.items() if v},
                "load": "N/m" if model.geometry == "line" else "N",
                "temperature": "degC",
                "viscosity": "Pa s",
                "alpha": "1/Pa",
                "radius": "m",
            },
            "geometry": model.geometry,
            "film_method": model.film,
            "thermal_method": model.thermal_method,
            "load": study.load,
            "temperature": study.temperature,
            "radius_x": study.radius_x,
            "radius_y": None if math.isinf(study.radius_y) else study.radius_y,
            "reduced_modulus": study.surfaces.modulus,
            "lubricant": {
                "name": lubricant.name,
                "viscosity": float(lubricant.viscosity.dynamic_viscosity(study.temperature)),
                "alpha": float(lubricant.alpha(study.temperature)),
                "limiting_shear_ratio": lubricant.limiting_shear_ratio,
                "source": lubricant.source,
            },
            "lubrication": result.lubrication,
            "warnings": list(result.warnings),
            "ehl_regime": REGIMES[regime] if regime >= 0 else None,
            "operating": state_json(op),
            "speed_sweep": {"factor": [float(v) for v in study.speed_factors], **state_json(result.speed_sweep)},
            "load_sweep": {"factor": [float(v) for v in study.load_factors], **state_json(result.load_sweep)},
        }

    def _table(self, result: ContactResult) -> Table:
        study, op = result.study, result.operating
        line = study.model.geometry == "line"

        def f(value: Any, scale: float, digits: str) -> str:
            number = float(value)
            return "-" if not math.isfinite(number) else format(number * scale, digits)

        rows = [
            ["load", f(study.load, 1e-3, ".1f") + " N/mm" if line else f(study.load, 1.0, ".4g") + " N"],
            [
                "peak / mean Hertz pressure [GPa]",
                f"{f(op.peak_pressure, 1e-9, '.3f')} / {f(op.mean_pressure, 1e-9, '.3f')}",
            ],
            ["contact half-width [mm]", f(op.half_width, 1e3, ".4f")],
            [
                "largest subsurface shear [MPa] at depth [mm]",
                f"{f(op.max_shear, 1e-6, '.0f')} at {f(op.max_shear_depth, 1e3, '.4f')}",
            ],
            [
                "rolling / sliding speed [m/s], S",
                f"{f(op.rolling_speed, 1, '.3g')} / {f(op.sliding_speed, 1, '.3g')}, {f(op.slide_roll, 1, '.3f')}",
            ],
            [
                f"central / minimum film [µm] ({study.model.film})",
                f"{f(op.central_film, 1e6, '.3f')} / {f(op.minimum_film, 1e6, '.3f')}",
            ],
            [f"thermal reduction ({study.model.thermal_method})", f(op.thermal_factor, 1, ".3f")],
            ["Lambda, film load share g", f"{f(op.film_ratio, 1, '.3f')}, {f(op.load_sharing, 1, '.3f')}"],
            ["lubrication", result.lubrication],
            [
                "f_c, f_a, c",
                ", ".join(
                    (
                        f(op.full_film_friction, 1, ".4f"),
                        f(op.mixed_friction, 1, ".4f"),
                        f(op.thermal_correction, 1, ".3f"),
                    )
                ),
            ],
            ["friction coefficient f", f(op.friction, 1, ".4f")],
            ["frictional power intensity [MW/m²]", f(op.power_intensity, 1e-6, ".1f")],
        ]
        from shaftline.contact.ehl import REGIMES

        source = "Moes' asymptotes" if line else "point-contact map"
        rows.insert(6, [f"EHL regime ({source}, theory 15.2)", REGIMES[int(op.regime)]])
        return Table(
            ["quantity", "value"], rows, f"Lubricated contact, {study.model.lubricant.name} at {study.temperature:g} °C"
        )

    def findings(self, result: ContactResult) -> list[Finding]:
        op = result.operating
        found = []
        if float(op.thermal_correction) <= 0.0:
            # extrapolate clipped Eq. 6's c to 0: a friction of 0 is no result (issue 14 (g))
            found.append(
                Finding(
                    "seed 002's thermal correction (Eq. 6) was clipped to c = 0 beyond its fit range of eta0 p_H u at "
                    "the operating point: friction and frictional power come out 0 - not a result; the correlation "
                    "does not cover this oil, load and speed.",
                    criterion=False,
                )
            )
        if result.lubrication != "boundary-dominated":
            return found
        return [
            *found,
            Finding(
                f"the contact runs boundary-dominated: Lambda = {float(op.film_ratio):.2f}, the film carries "
                f"{float(op.load_sharing):.0%} of the load (seed 002 Eq. 2); friction {float(op.friction):.3f}.",
                criterion=True,
            ),
        ]

    def _warnings(self, result: ContactResult) -> list[Block]:
        return [Paragraph(f"Extrapolated: {text}", "warn") for text in result.warnings]

    def summary(self, result: ContactResult) -> list[Block]:
        return [*self._warnings(result), self._table(result)]

    def report(self, result: ContactResult) -> list[Block]:
        from shaftline.contact import figures

        lubricant = result.study.model.lubricant
        return [
            *self._warnings(result),
            self._table(result),
            Paragraph(f"Lubricant data: {lubricant.source}", "note"),
            Figure(
                "contact_stribeck.png", figures.stribeck, (result,), caption="friction against Lambda (speed sweep)"
            ),
            Figure("contact_sweeps.png", figures.sweeps, (result,), caption="pressure and film against load and speed"),
        ]


CAPABILITY = LubricatedContact()
