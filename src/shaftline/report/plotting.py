"""What figure functions share: axes of their own when none are given.

A figure function draws into the axes it is given (``ax=``) and returns them, as in
scikit-fem and python-control, so a notebook user can place it in a figure of their own.
Without ``ax`` it makes a new pyplot figure of its declared layout and size, shown by
whatever backend the user has. The report passes axes of a figure that is not managed by
pyplot and saves it itself, so nothing here switches the user's backend.
"""

from __future__ import annotations

import functools
from collections.abc import Callable
from typing import Any


class FigureFunction:
    """A figure function with its layout of axes (rows, columns) and size (inches).

    Calling it with ``ax=None`` makes the axes with pyplot; the report calls it with the
    axes of its own figure.
    """

    def __init__(
        self, function: Callable[..., Any], layout: tuple[int, int], size: tuple[float, float], sharex: bool
    ) -> None:
        self.function = function
        self.layout = layout
        self.size = size
        self.sharex = sharex
        functools.update_wrapper(self, function)

    def __call__(self, *args: Any, ax: Any = None, **kwargs: Any) -> Any:
        if ax is None:
            import matplotlib.pyplot as plt

            _, ax = plt.subplots(*self.layout, figsize=self.size, sharex=self.sharex, layout="constrained")
        return self.function(*args, ax=ax, **kwargs)


def figure_function(
    layout: tuple[int, int] = (1, 1), size: tuple[float, float] = (8.0, 4.5), sharex: bool = False
) -> Callable[[Callable[..., Any]], FigureFunction]:
    """Declare a figure function's axes layout and size (decorator)."""

    def wrap(function: Callable[..., Any]) -> FigureFunction:
        return FigureFunction(function, layout, size, sharex)

    return wrap


#: Share of its grid cell's width a panel title may take before it is wrapped: the cell holds
#: the axes and their colour bar, and a title is centred on the axes, so on an 11-inch figure of
#: two map panels (colour bars 0.9 inch) a title wider than 0.84 of the cell reaches the edge.
TITLE_ROOM = 0.8


def fit_titles(figure: Any) -> None:
    """Wrap each axes title of ``figure`` wider than its panel's share of the figure onto more
    lines (at spaces): a long case name ahead of a panel's title was cut at the figure's edge.
    The report applies this to each figure before saving it. Only the titles' text is measured
    (no layout pass: a full draw of the figure cost a fifth of the report's drawing time)."""
    import textwrap

    width = figure.bbox.width
    for axes in figure.axes:
        title = axes.title
        text = title.get_text()
        spec = axes.get_subplotspec()
        if not text or "\n" in text or spec is None:
            continue
        columns = spec.get_gridspec().ncols
        span = spec.colspan.stop - spec.colspan.start
        room = TITLE_ROOM * width * span / columns
        needed = title.get_window_extent().width
        if needed > room:
            # characters per line in proportion to the room (a title is one font, one size)
            title.set_text(textwrap.fill(text, max(int(len(text) * room / needed), 12)))


def plain(text: str) -> str:
    """User text (a case, condition or bearing name) as matplotlib shows it literally: a
    pair of ``$`` would otherwise start mathtext, and an unpaired one fails to draw."""
    return text.replace("$", r"\$")
