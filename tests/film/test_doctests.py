"""The examples in the film package's docstrings run and give what they show.

Same check as ``pytest --doctest-modules src/shaftline/film``, kept here so that the
plain test run covers it.
"""

from __future__ import annotations

import doctest
import importlib
import pkgutil

import pytest

import shaftline.film

MODULES = sorted(f"shaftline.film.{info.name}" for info in pkgutil.iter_modules(shaftline.film.__path__))


@pytest.mark.parametrize("name", MODULES)
def test_docstring_examples(name):
    result = doctest.testmod(importlib.import_module(name), optionflags=doctest.ELLIPSIS)
    assert result.failed == 0


def test_the_examples_are_found():
    """Guards the test above against passing on docstrings it never read."""
    with_examples = {
        test.name for name in MODULES for test in doctest.DocTestFinder().find(importlib.import_module(name))
    }
    assert {"shaftline.film.bearing.JournalBearing", "shaftline.film.problem.BearingProblem"} <= with_examples
