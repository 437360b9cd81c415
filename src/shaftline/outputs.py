"""Writing results without ever losing a user's data.

A result folder (``--out``) carries a manifest, ``shaftline-manifest.json``, listing the
files shaftline wrote there. A folder is used for results only if it does not exist, is
empty, or has that manifest; any other folder is refused before anything is solved, and
nothing in it is touched. An existing result folder is updated file by file: the run's
files are drawn into a staging folder first and moved into place (each an atomic rename)
only when all of them are ready, so an error or Ctrl-C leaves the folder as it was; files
the run does not write (a user's notes, files of an earlier run) stay. No output may be
one of the run's inputs. Files and folders get the permissions of the user's umask.
"""

from __future__ import annotations

import json
import os
import shutil
import tempfile
from collections.abc import Iterable, Iterator
from contextlib import contextmanager
from datetime import UTC, datetime
from pathlib import Path

from shaftline.errors import InputError

MANIFEST = "shaftline-manifest.json"


def _umask() -> int:
    # os.umask can only be read by setting it; set it straight back.
    mask = os.umask(0o022)
    os.umask(mask)
    return mask


def _share(path: Path) -> None:
    """Give a file or folder the permissions a new one gets from the user's umask (temporary
    files and folders are created private)."""
    mode = 0o777 if path.is_dir() else 0o666
    os.chmod(path, mode & ~_umask())


def _nearest_existing(path: Path) -> Path:
    for candidate in (path, *path.parents):
        if candidate.exists():
            return candidate
    return Path(path.anchor or ".")


def _writable(folder: Path, field: str, shown: Path) -> None:
    """Check that files can be made in ``folder`` (or in the nearest folder above it that
    exists) by making one and removing it."""
    where = _nearest_existing(folder)
    if not where.is_dir():
        raise InputError(field, str(shown), "", f"a path below a folder ({where} is a file)")
    try:
        fd, probe = tempfile.mkstemp(dir=where, prefix=".shaftline-probe-")
        os.close(fd)
        os.unlink(probe)
    except OSError as exc:
        raise InputError(field, str(shown), "", f"a place where files can be written ({exc.strerror})") from None


def _same(a: Path, b: Path) -> bool:
    return a.resolve() == b.resolve()


def check_folder(out: Path, inputs: Iterable[Path] = (), field: str = "--out") -> None:
    """Refuse ``out`` as a result folder, before any work, if it is a file, a folder holding
    other files than an earlier result, the working folder or one above it, a folder holding
    one of the run's ``inputs``, or not writable.

    Raises
    ------
    InputError
        Naming ``field``; nothing has been written.
    """
    out = Path(out)
    target = out.resolve()
    here = Path.cwd().resolve()
    if not out.name or target == here or target in here.parents or target == Path(target.anchor):
        raise InputError(field, str(out), "", "a folder of its own (not the working folder or one above it)")
    for source in inputs:
        holder = Path(source).resolve().parent
        if target == holder or target in holder.parents:
            raise InputError(field, str(out), "", f"a folder that does not hold the input {source}")
    if out.exists():
        if not out.is_dir():
            raise InputError(field, str(out), "", "a folder (this is a file)")
        if any(out.iterdir()) and not (out / MANIFEST).is_file():
            raise InputError(
                field, str(out), "", f"a new or empty folder, or a shaftline result folder (no {MANIFEST} here)"
            )
    _writable(out, field, out)


def check_file(path: Path, inputs: Iterable[Path] = (), field: str = "--json") -> None:
    """Refuse ``path`` as an output file, before any work, if it is a folder, one of the run's
    ``inputs`` or not writable."""
    path = Path(path)
    if path.is_dir():
        raise InputError(field, str(path), "", "a file name (this is a folder)")
    for source in inputs:
        if _same(path, Path(source)):
            raise InputError(field, str(path), "", "a file other than the run's inputs")
    if path.exists() and not os.access(path, os.W_OK):
        raise InputError(field, str(path), "", "a file that can be written")
    if _special(path):
        return  # written into, not replaced (staged_file): its folder need not take new files
    _writable(path.parent, field, path)


def _special(path: Path) -> bool:
    """An existing path that is no regular file or folder: a device such as /dev/null, a FIFO,
    a socket. Such a file is written into; replacing it would put a plain file in its place."""
    return path.exists() and not path.is_file() and not path.is_dir()


@contextmanager
def staged_file(path: Path) -> Iterator[Path]:
    """Yield a temporary file beside ``path`` that replaces it when the block completes. A
    special file (``/dev/null``, a FIFO) is not replaced: the temporary file, made in the
    system's temporary folder, is copied into it."""
    path = Path(path)
    special = _special(path)
    if not special:
        path.parent.mkdir(parents=True, exist_ok=True)
    folder = None if special else path.parent
    fd, temporary = tempfile.mkstemp(dir=folder, prefix=f".{path.name}.", suffix=".tmp")
    os.close(fd)
    try:
        yield Path(temporary)
        if special:
            with open(temporary, "rb") as source, open(path, "wb") as target:
                shutil.copyfileobj(source, target)
            Path(temporary).unlink()
        else:
            _share(Path(temporary))
            os.replace(temporary, path)
    except BaseException:
        Path(temporary).unlink(missing_ok=True)
        raise


def write_text(path: Path, text: str) -> None:
    """Write ``text`` to ``path`` through a temporary file (atomic replace)."""
    with staged_file(path) as temporary:
        temporary.write_text(text, encoding="utf-8")


def _manifest(out: Path, written: list[str]) -> dict[str, object]:
    import shaftline

    earlier: list[str] = []
    try:
        earlier = list(json.loads((out / MANIFEST).read_text(encoding="utf-8")).get("files", []))
    except (OSError, ValueError, AttributeError):
        pass
    return {
        "written_by": f"shaftline {shaftline.__version__}",
        "time": datetime.now(UTC).isoformat(timespec="seconds"),
        "files": sorted(set(written) | set(earlier)),
        # Files of an earlier run stay (they are not this run's to delete); this list tells which
        # of the folder's files the latest run wrote.
        "last_run": sorted(written),
    }


@contextmanager
def result_folder(out: Path) -> Iterator[Path]:
    """Yield a staging folder for the files of a result; when the block completes they are
    moved into ``out`` (made if needed), each replacing only its namesake, and the manifest
    is updated. On an error or an interrupt the staging folder goes and ``out`` is as before.

    Call :func:`check_folder` first: this function does not refuse a foreign folder.
    """
    out = Path(out)
    created = not out.exists()
    out.mkdir(parents=True, exist_ok=True)
    staging = Path(tempfile.mkdtemp(dir=out, prefix=".shaftline-staging-"))
    try:
        yield staging
        written = sorted(str(p.relative_to(staging)) for p in staging.rglob("*") if p.is_file())
        for name in written:
            source, destination = staging / name, out / name
            if not destination.parent.exists():
                destination.parent.mkdir(parents=True)
                _share(destination.parent)
            _share(source)
            os.replace(source, destination)
        write_text(out / MANIFEST, json.dumps(_manifest(out, written), indent=2) + "\n")
        if created:
            _share(out)
    except BaseException:
        shutil.rmtree(staging, ignore_errors=True)
        if created and not any(out.iterdir()):
            out.rmdir()
        raise
    shutil.rmtree(staging, ignore_errors=True)
