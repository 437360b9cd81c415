"""Errors raised for bad user input.

Every check on user input raises :class:`InputError` so that the command line
can print one line and exit with status 2, and a notebook user gets an
exception that names the offending field.
"""

from __future__ import annotations

import math
from collections.abc import Iterator, Mapping
from contextlib import contextmanager
from typing import Any


class InputError(ValueError):
    """A value given by the user is outside what the model accepts.

    Domain code names the field relative to the object or function that checks
    it, because it cannot know where a value came from: the dataclass attribute
    path (``"radial_clearance"``, ``"bore[1].slope"``, ``"grooves[0].angle"``) or
    the parameter (``"load_y"``). A reader of case files puts its own path in
    front with :meth:`within` (``"bearing.radial_clearance"``).

    Parameters
    ----------
    field : str
        Name of the input field, e.g. ``"radial_clearance"`` in the domain or
        ``"bearing.radial_clearance"`` once a case reader has placed it.
    value : Any
        The value that was given.
    unit : str
        Unit the value is expressed in (``""`` for dimensionless or text).
    allowed : str
        The allowed range or set of values, in words.
    in_file : bool
        The field names a place in a data file (``"log.csv: row 12, time"``), which stays
        as it is when the error is placed under a case-file table (:meth:`within`).
    """

    def __init__(self, field: str, value: Any, unit: str = "", allowed: str = "", in_file: bool = False) -> None:
        self.field = field
        self.value = value
        self.unit = unit
        self.allowed = allowed
        self.in_file = in_file
        if isinstance(value, str):
            shown = repr(value)  # text as the user wrote it; a unit is not appended to it
        else:
            # 12 significant digits: 0.45 mm reads 0.00045 m, not 0.00045000000000000004 m
            shown = f"{value:.12g}" if isinstance(value, float) else f"{value}"
            if unit:
                shown = f"{shown} {unit}"
        message = f"{field} = {shown}"
        if allowed:
            message += f": allowed {allowed}"
        super().__init__(message)

    def __reduce__(self) -> tuple[type[InputError], tuple[str, Any, str, str, bool]]:
        # Pickle by the constructor's arguments, not the message (the default): an error
        # raised in a worker process (shaftline.parallel) must reach the caller as itself.
        return type(self), (self.field, self.value, self.unit, self.allowed, self.in_file)

    def within(self, prefix: str, renames: Mapping[str, str] | None = None) -> InputError:
        """The same error with its field placed under ``prefix``.

        Domain objects name fields relative to themselves (``"radial_clearance"``,
        ``"grooves[0].angle"``); the case layer, which knows where each object came from,
        prefixes the path of its case-file table: ``within("operation")`` turns ``"speed"``
        into ``"operation.speed"``, and an index joins without a dot (``"[1].slope"`` under
        ``"bore"`` is ``"bore[1].slope"``). ``renames`` gives the path, in place of
        ``prefix`` and the name, of fields whose first part is named differently in the
        case file (``{"point_loads": "loads", "viscosity": "lubricant.viscosity"}``).
        """
        if self.in_file:
            return self
        head, sep, rest = self.field.partition(".")
        name, bracket, index = head.partition("[")
        if renames and name in renames:
            return InputError(f"{renames[name]}{bracket}{index}{sep}{rest}", self.value, self.unit, self.allowed)
        field = self.field
        if prefix:
            field = f"{prefix}{'' if field.startswith('[') else '.'}{field}" if field else prefix
        return InputError(field, self.value, self.unit, self.allowed)


@contextmanager
def located(prefix: str, renames: Mapping[str, str] | None = None) -> Iterator[None]:
    """Re-raise an :class:`InputError` of the block with its field under ``prefix``."""
    try:
        yield
    except InputError as error:
        raise error.within(prefix, renames) from None


class Interrupted(KeyboardInterrupt):
    """Ctrl-C during a run that kept something on disk: ``note`` says where and how to go on
    (the command line prints it under its "interrupted" line)."""

    def __init__(self, note: str) -> None:
        super().__init__(note)
        self.note = note


def interrupted_by_user(error: BaseException | None) -> bool:
    """True when ``error`` is Ctrl-C's ``KeyboardInterrupt`` or was caused by one: inside a compiled
    (numba) call it surfaces as a ``SystemError`` ("returned a result with an exception set") whose
    cause chain holds the ``KeyboardInterrupt``."""
    seen: set[int] = set()
    while error is not None and id(error) not in seen:
        if isinstance(error, KeyboardInterrupt):
            return True
        seen.add(id(error))
        error = error.__cause__ or error.__context__
    return False


class SolverFailure(RuntimeError):
    """A numerical method did not reach a solution for inputs it accepted (the command line
    reports it in one line with exit status 3: nothing to show, nothing written)."""


def require_finite(field: str, value: float, unit: str = "") -> float:
    """Return ``value`` as float, or raise :class:`InputError` if NaN or infinite."""
    try:
        number = float(value)
    except (TypeError, ValueError):
        raise InputError(field, value, unit, "a number") from None
    if not math.isfinite(number):
        raise InputError(field, value, unit, "a finite number")
    return number


def require_positive(field: str, value: float, unit: str = "") -> float:
    """Return ``value`` if it is finite and > 0, else raise :class:`InputError`."""
    number = require_finite(field, value, unit)
    if number <= 0.0:
        raise InputError(field, number, unit, "> 0")
    return number


def first_offending(values: Any, ok: Any) -> float:
    """The first element of ``values`` where the (broadcastable) mask ``ok`` is False, as a float:
    the value an :class:`InputError` on an array should quote (its first element may be fine).

    >>> first_offending([1.0, -2.0, -3.0], [True, False, False])
    -2.0
    """
    import numpy as np

    array = np.asarray(values, dtype=float)
    mask = ~np.asarray(ok, dtype=bool)
    shape = np.broadcast_shapes(array.shape, mask.shape)
    picked = np.broadcast_to(array, shape)[np.broadcast_to(mask, shape)]
    return float(picked[0]) if picked.size else float(np.ravel(array)[0])
