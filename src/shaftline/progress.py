"""What the command line shows while a case is solved: the :data:`~shaftline.registry.Progress`
reports of the capabilities drawn on standard error.

On a terminal, a spinner with the step's text; a step that counts its items
(:class:`~shaftline.registry.Tally`, e.g. the evaluations of a design search) becomes a bar with
done/total, what was found so far (the best h_min) and the time left. Elsewhere (a file, a
pipe, a batch job's log, a test's runner) nothing is drawn: a counting step prints one plain
line once it has run for ``interval`` seconds and then at most one per ``interval``, and a last
one when it ends, so a short run prints nothing and a long one leaves a readable log.

The library never imports this module: its functions take a callback (``progress``) and the
command line passes a :class:`ProgressDisplay`.
"""

from __future__ import annotations

import math
import time
from collections.abc import Callable
from types import TracebackType
from typing import Any

from rich.console import Console
from rich.progress import BarColumn, MofNCompleteColumn, Progress, ProgressColumn, SpinnerColumn, Task, TextColumn
from rich.text import Text

from shaftline.registry import Tally

__all__ = ["ProgressDisplay", "time_left"]

#: Seconds between the plain lines of a counting step when standard error is not a terminal.
PLAIN_INTERVAL = 30.0


def time_left(seconds: float) -> str:
    """``"about 1 min 05 s left"``; empty when not known (no item done yet).

    Examples
    --------
    >>> time_left(65.2), time_left(7.0), time_left(3725.0), time_left(0.2), time_left(float("nan"))
    ('about 1 min 05 s left', 'about 7 s left', 'about 1 h 02 min left', 'less than 1 s left', '')
    """
    if not math.isfinite(seconds):
        return ""
    if seconds < 1.0:
        return "less than 1 s left"
    if seconds < 60.0:
        return f"about {seconds:.0f} s left"
    if seconds < 3600.0:
        minutes, rest = divmod(round(seconds), 60)
        return f"about {minutes} min {rest:02d} s left"
    hours, rest = divmod(round(seconds) // 60, 60)
    return f"about {hours} h {rest:02d} min left"


class _Rate:
    """The time left of a counting step, from its pace since it was first reported (the first
    report may already count items resumed from a store, so it is the origin, not zero)."""

    def __init__(self, tally: Tally, now: float) -> None:
        self.label = tally.label
        self.origin = (now, tally.done)
        self.last = (now, tally.done)
        self.remaining = math.nan  # s at the last report

    def update(self, tally: Tally, now: float) -> None:
        start, first = self.origin
        self.last = (now, tally.done)
        done = tally.done - first
        self.remaining = (now - start) / done * max(0, tally.total - tally.done) if done > 0 else math.nan

    def left(self, now: float) -> float:
        """Seconds left now: the estimate of the last report, counted down since."""
        return self.remaining - (now - self.last[0])


class _WhenCounted(ProgressColumn):
    """A column drawn only for a step that counts (a text step is drawn as its text alone)."""

    def __init__(self, column: ProgressColumn) -> None:
        self.column = column
        super().__init__()

    def render(self, task: Task) -> Any:
        return self.column.render(task) if task.fields.get("counted") else Text("")


class _TimeLeft(ProgressColumn):
    def __init__(self, display: ProgressDisplay) -> None:
        self.display = display
        super().__init__()

    def render(self, task: Task) -> Text:
        rate = self.display._rate
        if not task.fields.get("counted") or rate is None or task.completed >= (task.total or 0):
            return Text("")
        return Text(time_left(rate.left(self.display.clock())), style="progress.remaining")


class ProgressDisplay:
    """A :data:`~shaftline.registry.Progress` callback that draws what it is told on ``console``.

    Use it as a context manager around the solve: the bar is removed when the block ends
    (also on Ctrl-C or an error), so only the results and the messages stay on the screen.

    Parameters
    ----------
    console : rich.console.Console
        Where to draw (the command line's standard error).
    interval : float
        Seconds between the plain lines of a counting step when ``console`` is not a terminal.
    clock : callable
        Seconds from any origin (default ``time.monotonic``).

    Examples
    --------
    >>> import io
    >>> from rich.console import Console
    >>> log = io.StringIO()
    >>> with ProgressDisplay(Console(file=log), interval=0.0) as show:
    ...     show("reading the case")
    ...     show(Tally("design search", 8, 16, "evaluations", "best h_min 40.1 µm"))
    ...     show(Tally("design search", 16, 16, "evaluations", "best h_min 42.0 µm"))
    >>> print(log.getvalue().strip())
    design search: 8/16 evaluations, best h_min 40.1 µm
    design search: 16/16 evaluations, best h_min 42.0 µm
    """

    def __init__(
        self, console: Console, interval: float = PLAIN_INTERVAL, clock: Callable[[], float] = time.monotonic
    ) -> None:
        self.console = console
        self.interval = interval
        self.clock = clock
        self.live = console.is_terminal and not console.is_dumb_terminal
        self._rate: _Rate | None = None
        self._printed = -math.inf  # when the last plain line was printed (monotonic s)
        self._started = clock()
        self._bar: Progress | None = None
        self._task: Any = None
        if self.live:
            self._bar = Progress(
                SpinnerColumn(),
                TextColumn("{task.description}"),
                _WhenCounted(BarColumn()),
                _WhenCounted(MofNCompleteColumn()),
                TextColumn("{task.fields[unit]}"),
                TextColumn("{task.fields[detail]}"),
                _TimeLeft(self),
                console=console,
                transient=True,
            )

    def __enter__(self) -> ProgressDisplay:
        self._started = self.clock()
        if self._bar is not None:
            self._bar.start()
            self._task = self._bar.add_task("solving", total=None, counted=False, unit="", detail="")
        return self

    def __exit__(
        self, kind: type[BaseException] | None, error: BaseException | None, trace: TracebackType | None
    ) -> None:
        if self._bar is not None:
            self._bar.stop()

    def __call__(self, report: str | Tally) -> None:
        now = self.clock()
        if not isinstance(report, Tally):
            self._rate = None
            if self._bar is not None:
                self._bar.update(self._task, description=str(report), counted=False, unit="", detail="")
                self._bar.refresh()
            return
        if self._rate is None or self._rate.label != report.label:  # a new step: a new bar and pace
            self._rate = _Rate(report, now)
            self._printed = -math.inf
        else:
            self._rate.update(report, now)
        if self._bar is not None:
            # one call, so that the refresh thread never draws half of it
            self._bar.reset(
                self._task,
                total=max(report.total, report.done),
                completed=report.done,
                description=report.label,
                counted=True,
                unit=report.unit,
                detail=f"· {report.detail}" if report.detail else "",
            )
            self._bar.refresh()  # reports come seconds apart: draw each at once
            return
        self._plain(report, now)

    def _plain(self, report: Tally, now: float) -> None:
        """A line when the step has run ``interval`` s and then one per ``interval``, and its last."""
        finished = report.done >= report.total and self._printed > -math.inf
        if not finished and (now - self._started < self.interval or now - self._printed < self.interval):
            return
        assert self._rate is not None
        left = time_left(self._rate.left(now)) if report.done < report.total else ""
        self.console.print(str(report) + (f", {left}" if left else ""), markup=False, highlight=False, soft_wrap=True)
        self._printed = now
