"""The HTML report: a jinja2 template with autoescaping over the sections' blocks.

Every piece of text a user wrote (case, condition and bearing names) reaches the page only
through the template, which escapes it. Figures are drawn into matplotlib figures that
pyplot does not manage and saved as PNG beside the page, so writing a report never changes
the backend of the session it runs in.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from pathlib import Path
from typing import TypeVar

from shaftline.report.blocks import (
    DataFile,
    Details,
    Figure,
    Heading,
    Paragraph,
    Preformatted,
    Section,
    Table,
    is_number,
)
from shaftline.report.plotting import fit_titles


def svg_name(file: str) -> str:
    """The name of the vector copy of a figure file (``maps.png`` -> ``maps.svg``)."""
    return str(Path(file).with_suffix(".svg"))


T = TypeVar("T")


def draw_figure(figure: Figure, path: Path) -> Path:
    """Draw ``figure`` and save it as a PNG at ``path`` and as an SVG beside it (the report
    shows the SVG: vector graphics print sharply)."""
    from matplotlib.figure import Figure as MatplotlibFigure

    plot = figure.plot
    canvas = MatplotlibFigure(figsize=plot.size, layout="constrained")
    axes = canvas.subplots(*plot.layout, sharex=plot.sharex)
    plot(*figure.args, ax=axes, **figure.kwargs)
    fit_titles(canvas)
    canvas.savefig(path, dpi=110)
    canvas.savefig(path.with_suffix(".svg"))
    return path


_KINDS: tuple[tuple[type, str], ...] = (
    (Paragraph, "paragraph"),
    (Heading, "heading"),
    (Table, "table"),
    (Figure, "figure"),
    (Details, "details"),
    (Preformatted, "preformatted"),
    (DataFile, "data"),
)


def _kind(block: object) -> str:
    for cls, name in _KINDS:
        if isinstance(block, cls):
            return name
    raise TypeError(f"not a report block: {block!r}")


def _nested(blocks: Sequence[object], kind: type[T]) -> list[T]:
    """The blocks of ``kind`` among ``blocks``, those folded in :class:`Details` included."""
    out: list[T] = []
    for block in blocks:
        if isinstance(block, kind):
            out.append(block)
        elif isinstance(block, Details):
            out += _nested(block.blocks, kind)
    return out


def render(
    title: str,
    description: str,
    source: str,
    sections: Sequence[Section],
    version: str,
    source_label: str = "case file",
    created: str = "",
) -> str:
    """The report page (figures are referred to as ``figures/<file>``); ``source`` is the
    input file, named ``source_label`` in the page; ``created`` the date and time of the run."""
    from jinja2 import Environment, PackageLoader, select_autoescape

    environment = Environment(
        loader=PackageLoader("shaftline", "report/templates"),
        autoescape=select_autoescape(default=True, default_for_string=True),
        trim_blocks=True,
        lstrip_blocks=True,
    )
    environment.filters["kind"] = _kind
    environment.filters["svg"] = svg_name
    environment.tests["number"] = is_number
    return environment.get_template("report.html").render(
        title=title,
        description=description,
        source=source,
        source_label=source_label,
        version=version,
        sections=sections,
        created=created,
    )


def write_report(
    folder: Path,
    title: str,
    description: str,
    source: str,
    sections: Sequence[Section],
    version: str,
    source_label: str = "case file",
    progress: Callable[[str], None] | None = None,
) -> Path:
    """Draw every figure of ``sections`` into ``folder/figures`` (PNG and SVG) and write
    ``folder/report.html``, dated now."""
    from datetime import datetime

    created = datetime.now().astimezone().isoformat(timespec="seconds")
    figures = folder / "figures"
    figures.mkdir(parents=True, exist_ok=True)
    blocks = [block for section in sections for block in _nested(section.blocks, Figure)]
    for k, block in enumerate(blocks):
        if progress is not None:
            progress(f"drawing figure {k + 1} of {len(blocks)}")
        draw_figure(block, figures / block.file)
    files = [block for section in sections for block in _nested(section.blocks, DataFile)]
    if files:
        (folder / "data").mkdir(parents=True, exist_ok=True)
    for data in files:
        if progress is not None:
            progress(f"writing {data.file}")
        data.write(folder / "data" / data.file)
    path = folder / "report.html"
    page = render(title, description, source, sections, version, source_label, created)
    path.write_text(page, encoding="utf-8")
    return path
