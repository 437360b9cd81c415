"""The command line's progress display (shaftline.progress): a bar on a terminal, plain
periodic lines elsewhere, never the bar's control codes in a file or a pipe."""

from __future__ import annotations

import io
import time

from rich.console import Console

from shaftline.progress import ProgressDisplay, time_left
from shaftline.registry import Tally


def _search(show: ProgressDisplay, pause: float = 0.0) -> None:
    show("coupled alignment")
    for generation in range(1, 5):
        time.sleep(pause)
        show(Tally("design search", 10 * generation, 40, "evaluations", f"best h_min {40 + generation:.1f} µm"))
    show("films of the knee")


def test_not_a_terminal_prints_nothing_for_a_short_run():
    """A run shorter than the interval (every test's run, a quick search) leaves no line at all."""
    log = io.StringIO()
    with ProgressDisplay(Console(file=log), interval=30.0) as show:
        _search(show)
    assert log.getvalue() == ""


def test_not_a_terminal_prints_plain_lines_at_most_one_per_interval():
    """A long run's log (a batch job): plain lines with done/total, the best h_min and the time
    left, once the step has run an interval and then no more often than that, and the step's last
    line; text steps print nothing. A clock of 20 s per report against an interval of 30 s."""
    log = io.StringIO()
    ticks = iter(range(0, 1000, 20))
    with ProgressDisplay(Console(file=log, width=200), interval=30.0, clock=lambda: float(next(ticks))) as show:
        _search(show)
    lines = log.getvalue().splitlines()
    assert "\x1b" not in log.getvalue() and "━" not in log.getvalue()
    # every call reads the clock: the display starts at 20 s, the tallies come at 60, 80, 100 and
    # 120 s; 60 prints (40 s in), 80 is too soon after it, 100 prints (20 s per 10 evaluations
    # since the first: 20 s left), 120 is the last
    assert lines == [
        "design search: 10/40 evaluations, best h_min 41.0 µm",
        "design search: 30/40 evaluations, best h_min 43.0 µm, about 20 s left",
        "design search: 40/40 evaluations, best h_min 44.0 µm",
    ]


def test_a_terminal_gets_a_bar_that_is_cleared_at_the_end():
    log = io.StringIO()
    console = Console(file=log, force_terminal=True, width=160, color_system=None)
    with ProgressDisplay(console) as show:
        _search(show, pause=0.01)
    drawn = log.getvalue()
    assert "design search" in drawn and "20/40" in drawn and "best h_min 42.0 µm" in drawn and "━" in drawn
    assert "coupled alignment" in drawn and "films of the knee" in drawn
    # transient: the last thing written is the erasing of the bar (no frame left on the screen)
    assert drawn.rstrip().endswith(("\x1b[2K", "\x1b[?25h"))


def test_time_left_reads_in_plain_units():
    assert time_left(42.4) == "about 42 s left" and time_left(600.0) == "about 10 min 00 s left"
