"""HTML report: one section per capability, assembled from a jinja2 template."""

from __future__ import annotations

from dataclasses import dataclass

from jinja2 import Environment, PackageLoader, select_autoescape
from markupsafe import Markup, escape

import shaftline


@dataclass(frozen=True)
class Section:
    """A report section: a heading and its HTML body (already escaped where needed)."""

    title: str
    html: Markup


def _is_number(text: str) -> bool:
    try:
        float(str(text).split()[0])
    except (ValueError, IndexError):
        return False
    return True


def table(headers: list[str], rows: list[list[str]]) -> Markup:
    """An HTML table from text cells (escaped); numbers right-aligned, text left-aligned."""
    head = "".join(f"<th>{escape(h)}</th>" for h in headers)
    body = "".join(
        "<tr>" + "".join(f"<td class='{'num' if _is_number(c) else 'text'}'>{escape(c)}</td>" for c in row) + "</tr>"
        for row in rows
    )
    return Markup(f"<table><thead><tr>{head}</tr></thead><tbody>{body}</tbody></table>")


def image(path: str, alt: str) -> Markup:
    return Markup(f'<img src="{escape(path)}" alt="{escape(alt)}">')


def render(title: str, description: str, case_file: str, sections: list[Section]) -> str:
    environment = Environment(loader=PackageLoader("shaftline", "report/templates"), autoescape=select_autoescape())
    template = environment.get_template("report.html")
    return template.render(
        title=title,
        description=description,
        case_file=case_file,
        version=shaftline.__version__,
        sections=sections,
    )
