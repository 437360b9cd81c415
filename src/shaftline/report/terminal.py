"""The terminal view of the same blocks the report shows (figures and details left out).

User text and units are printed literally: every cell is a rich ``Text``, never markup, so
``[kN]`` or a name with brackets shows as written.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import TYPE_CHECKING

from shaftline.report.blocks import Block, Heading, Paragraph, Preformatted, Table, is_number

if TYPE_CHECKING:
    from rich.console import Console

#: Style of a marked cell.
MARK_STYLES = {"pass": "green", "fail": "bold red", "": ""}


def print_blocks(console: Console, blocks: Sequence[Block]) -> None:
    """Print tables, headings and notes with rich; numeric columns right-aligned, text left."""
    from rich.table import Table as RichTable
    from rich.text import Text

    for block in blocks:
        if isinstance(block, Table):
            table = RichTable(title=Text(block.title) if block.title else None)
            for k, header in enumerate(block.headers):
                # a column of numbers (a "-" for a missing one) is right-aligned
                numeric = bool(block.rows) and all(is_number(row[k]) or row[k].strip() == "-" for row in block.rows)
                # fold long words rather than cut them: nothing is lost in a narrow terminal
                table.add_column(Text(header), justify="right" if numeric else "left", overflow="fold")
            for i, row in enumerate(block.rows):
                marks = block.marks[i] if block.marks else [""] * len(row)
                table.add_row(
                    *(Text(cell, style=MARK_STYLES.get(mark, "")) for cell, mark in zip(row, marks, strict=True))
                )
            console.print(table)
        elif isinstance(block, Paragraph):
            console.print(Text(block.text, style="bold red" if block.style == "warn" else ""))
        elif isinstance(block, Heading):
            console.print(Text(block.text, style="bold"))
        elif isinstance(block, Preformatted):
            console.print(Text(block.text))
