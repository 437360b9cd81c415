"""The reference table of a bearing case's JSON fields (the README's), made from the units and
meanings the results declare in their fields (:mod:`shaftline.export`)."""

from __future__ import annotations

from shaftline.export import rows

__all__ = ["field_table"]


def field_table() -> str:
    """The Markdown table of every JSON field of a bearing case (the README's)."""
    from shaftline.film.dynamics import DynamicCoefficients
    from shaftline.film.geometry import JournalPosition
    from shaftline.film.results import BearingState, Equilibrium, LinerState, RoughContact, TurbulenceState
    from shaftline.film.stribeck import StribeckCurve

    table = rows(BearingState, (JournalPosition,))
    table += [row for row in rows(Equilibrium) if row[0] != "contact"]  # the state's, overridden
    table += rows(DynamicCoefficients)
    for kind, where in (
        (RoughContact, "with [bearing.surface] only"),
        (LinerState, "with [bearing.liner] only"),
        (TurbulenceState, "with [bearing.solver] turbulence on or auto only"),
    ):
        table += [(key, unit, f"{text} ({where})") for key, unit, text in rows(kind)]
    table.append(
        (
            "reynolds_number_map",
            "-",
            "local Reynolds number over the bore, rows from the aft edge, columns from the grid's first angle "
            "(with [bearing.solver] turbulence on or auto only)",
        )
    )
    table += [(f"stribeck.{key}", unit, f"{text} (`bearing stribeck` only)") for key, unit, text in rows(StribeckCurve)]
    return (
        "| key | unit | meaning |\n|---|---|---|\n"
        + "\n".join(f"| `{key}` | {unit} | {text} |" for key, unit, text in table)
        + "\n"
    )
