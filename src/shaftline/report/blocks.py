"""The content of a report section as data: notes, tables, figures and headings.

Capabilities describe what their section shows with these blocks; only
:mod:`shaftline.report.html` turns them into HTML (escaped by jinja2) and only
:mod:`shaftline.report.terminal` prints them. A capability never writes markup.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import TYPE_CHECKING, Any, Literal

if TYPE_CHECKING:
    from shaftline.report.plotting import FigureFunction


@dataclass(frozen=True)
class Paragraph:
    """A sentence or two. ``style`` is ``"text"``, ``"note"`` (small print) or ``"warn"``
    (a result the reader must not miss: a failed check, no convergence, contact)."""

    text: str
    style: Literal["text", "note", "warn"] = "text"


@dataclass(frozen=True)
class Heading:
    """A sub-heading inside a section."""

    text: str


@dataclass(frozen=True)
class Table:
    """A table of text cells; cells that read as numbers are right-aligned.

    ``marks`` optionally gives each cell a mark, ``"pass"``, ``"fail"`` or ``""``, that the
    report colours (a matrix of checks) and the terminal colours too.
    """

    headers: Sequence[str]
    rows: Sequence[Sequence[str]]
    title: str = ""
    marks: Sequence[Sequence[str]] | None = None


@dataclass(frozen=True)
class Details:
    """Blocks shown on demand (folded in the report, left out of the terminal)."""

    summary: str
    blocks: Sequence[Block]


@dataclass(frozen=True)
class Preformatted:
    """Text shown as written (the case file echoed in the report), in a fixed-width font."""

    text: str


@dataclass(frozen=True, eq=False)
class DataFile:
    """A data file written into the report's ``data`` folder and linked from the page (every
    design a search evaluated, say, too many rows for a table).

    Attributes
    ----------
    file : str
        File name inside ``data``.
    write : callable
        ``write(path)`` writes the file.
    caption : str
        The link's text.
    """

    file: str
    write: Callable[[Path], None]
    caption: str = ""


@dataclass(frozen=True, eq=False)
class Figure:
    """A figure drawn by a figure function of the capability.

    The report creates a figure with the axes layout and size the figure function
    declares (:func:`shaftline.report.plotting.figure_function`) and calls
    ``plot(*args, ax=axes, **kwargs)``.

    Attributes
    ----------
    file : str
        File name of the PNG inside the report's ``figures`` folder.
    plot : FigureFunction
        The figure function (it takes ``ax=`` and draws into it).
    args, kwargs :
        Its other arguments.
    caption : str
        Text under the figure (and its alt text).
    """

    file: str
    plot: FigureFunction
    args: tuple[Any, ...] = ()
    kwargs: Mapping[str, Any] = field(default_factory=dict)
    caption: str = ""


Block = Paragraph | Heading | Table | Figure | Details | Preformatted | DataFile


@dataclass(frozen=True)
class Section:
    """One capability's part of the report."""

    key: str
    title: str
    blocks: Sequence[Block]


def is_number(text: str) -> bool:
    """Whether a table cell reads as a number (possibly followed by a unit): it is right-aligned."""
    try:
        float(str(text).split()[0])
    except (ValueError, IndexError):
        return False
    return True


def fmt(value: float | None, scale: float = 1.0, digits: int = 4) -> str:
    """A number for a table: ``value * scale`` to ``digits`` significant digits, ``-`` if
    missing or not finite."""
    if value is None or value != value or value in (float("inf"), float("-inf")):
        return "-"
    return f"{value * scale:.{digits}g}"
