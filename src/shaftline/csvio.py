"""Reading measurement and table files: named numeric columns with errors that name the row."""

from __future__ import annotations

import warnings
from pathlib import Path

import numpy as np

from shaftline.errors import InputError


def read_columns(
    path: str | Path, columns: list[str], field: str, order_matters: bool = False
) -> dict[str, np.ndarray]:
    """Numeric columns of a CSV file with a header line, as arrays by name.

    Raises :class:`InputError` (naming ``field``) for a missing file, other columns than
    ``columns`` (in that order when ``order_matters``), a non-numeric or empty field, and
    NaN or infinite values (naming the file's row, counting the header as row 1).
    """
    path = Path(path)
    try:
        with path.open(encoding="utf-8") as handle:
            header = [name.strip() for name in handle.readline().split(",")]
    except UnicodeDecodeError:
        raise InputError(field, str(path), "", "a CSV text file in UTF-8") from None
    except OSError:
        raise InputError(field, str(path), "", "an existing CSV file") from None
    expected = columns if order_matters else sorted(columns)
    if (header if order_matters else sorted(header)) != expected:
        raise InputError(field, str(path), "", "columns " + ", ".join(columns))
    try:
        # numpy's C reader: a day of 10 Hz samples reads in a fraction of a second. A file of
        # a header alone is reported below, not warned about.
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", UserWarning)
            table = np.loadtxt(path, delimiter=",", skiprows=1, dtype=float, ndmin=2)
    except UnicodeDecodeError:
        raise InputError(field, str(path), "", "a CSV text file in UTF-8") from None
    except ValueError as exc:
        raise InputError(field, str(path), "", f"numbers in every field ({exc})") from None
    if table.shape[0] == 0 or table.shape[1] != len(header):
        raise InputError(field, str(path), "", f"rows of {len(header)} numbers below the header")
    bad = np.argwhere(~np.isfinite(table))
    if bad.size:
        row, column = (int(v) for v in bad[0])
        raise InputError(f"{path.name}: row {row + 2}, {header[column]}", "NaN", "", "a number", in_file=True)
    return {name: table[:, k] for k, name in enumerate(header)}
