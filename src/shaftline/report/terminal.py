"""The terminal view of the same blocks the report shows (figures are left out)."""

from __future__ import annotations

from collections.abc import Sequence
from typing import TYPE_CHECKING

from shaftline.report.blocks import Block, Heading, Paragraph, Table

if TYPE_CHECKING:
    from rich.console import Console


def print_blocks(console: Console, blocks: Sequence[Block]) -> None:
    """Print tables, headings and notes with rich; user text is printed literally."""
    from rich.table import Table as RichTable
    from rich.text import Text

    for block in blocks:
        if isinstance(block, Table):
            table = RichTable(title=Text(block.title) if block.title else None)
            for k, header in enumerate(block.headers):
                table.add_column(Text(header), justify="left" if k == 0 else "right")
            for row in block.rows:
                table.add_row(*(Text(cell) for cell in row))
            console.print(table)
        elif isinstance(block, Paragraph):
            console.print(Text(block.text, style="bold red" if block.style == "warn" else ""))
        elif isinstance(block, Heading):
            console.print(Text(block.text, style="bold"))
