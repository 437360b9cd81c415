"""The HTML report: a jinja2 template with autoescaping over the sections' blocks.

Every piece of text a user wrote (case, condition and bearing names) reaches the page only
through the template, which escapes it. Figures are drawn into matplotlib figures that
pyplot does not manage and saved as PNG beside the page, so writing a report never changes
the backend of the session it runs in.
"""

from __future__ import annotations

from collections.abc import Sequence
from pathlib import Path

from shaftline.report.blocks import Figure, Heading, Paragraph, Section, Table


def _is_number(text: str) -> bool:
    try:
        float(str(text).split()[0])
    except (ValueError, IndexError):
        return False
    return True


def draw_figure(figure: Figure, path: Path) -> Path:
    """Draw ``figure`` and save it as a PNG at ``path``."""
    from matplotlib.figure import Figure as MatplotlibFigure

    plot = figure.plot
    canvas = MatplotlibFigure(figsize=plot.size, layout="constrained")
    axes = canvas.subplots(*plot.layout, sharex=plot.sharex)
    plot(*figure.args, ax=axes, **figure.kwargs)
    canvas.savefig(path, dpi=110)
    return path


def _kind(block: object) -> str:
    for cls, name in ((Paragraph, "paragraph"), (Heading, "heading"), (Table, "table"), (Figure, "figure")):
        if isinstance(block, cls):
            return name
    raise TypeError(f"not a report block: {block!r}")


def render(
    title: str,
    description: str,
    source: str,
    sections: Sequence[Section],
    version: str,
    source_label: str = "case file",
) -> str:
    """The report page (figures are referred to as ``figures/<file>``); ``source`` is the
    input file, named ``source_label`` in the page."""
    from jinja2 import Environment, PackageLoader, select_autoescape

    environment = Environment(
        loader=PackageLoader("shaftline", "report/templates"),
        autoescape=select_autoescape(default=True, default_for_string=True),
        trim_blocks=True,
        lstrip_blocks=True,
    )
    environment.filters["kind"] = _kind
    environment.tests["number"] = _is_number
    return environment.get_template("report.html").render(
        title=title,
        description=description,
        source=source,
        source_label=source_label,
        version=version,
        sections=sections,
    )


def write_report(
    folder: Path,
    title: str,
    description: str,
    source: str,
    sections: Sequence[Section],
    version: str,
    source_label: str = "case file",
) -> Path:
    """Draw every figure of ``sections`` into ``folder/figures`` and write ``folder/report.html``."""
    figures = folder / "figures"
    figures.mkdir(parents=True, exist_ok=True)
    for section in sections:
        for block in section.blocks:
            if isinstance(block, Figure):
                draw_figure(block, figures / block.file)
    path = folder / "report.html"
    path.write_text(render(title, description, source, sections, version, source_label), encoding="utf-8")
    return path
