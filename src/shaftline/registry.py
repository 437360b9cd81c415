"""The capability registry: one entry per thing shaftline can analyse.

A capability (the stern-tube bearing film, the shaft alignment, ...) is one small class
that says how its case-file table looks, how the table becomes domain objects, how they
are solved, and how the result is written as JSON, shown in the terminal and laid out in
the report. The command line, ``shaftline run``, the JSON document and the HTML report
iterate over the registry; none of them knows a capability by name.

Adding a capability touches its own package and one line of :data:`CAPABILITY_MODULES`
(see docs/architecture.md for the recipe). A capability module must stay cheap to
import: the command line imports every one of them to list its verbs, so heavy modules
(scipy, numba, matplotlib) are imported inside the methods that need them.
"""

from __future__ import annotations

import importlib
from collections.abc import Callable, Iterator, Mapping, Sequence
from contextlib import contextmanager
from dataclasses import dataclass, field
from pathlib import Path
from typing import TYPE_CHECKING, Any, ClassVar, Generic, TypeVar

if TYPE_CHECKING:
    from shaftline.cases.types import CaseInfo, Section
    from shaftline.report.blocks import Block

#: Modules holding a ``CAPABILITY`` instance, in the order of the report and the JSON.
CAPABILITY_MODULES: tuple[str, ...] = (
    "shaftline.film.capability",
    "shaftline.shaft.capability",
    "shaftline.wear.capability",
    "shaftline.cpp.capability",
    "shaftline.contact.capability",
    "shaftline.gears.capability",
    # after film: [design] builds on [bearing] (Capability.needs)
    "shaftline.design.capability",
    "shaftline.monitor.capability",
)


@dataclass(frozen=True)
class Tally:
    """A progress report that counts: ``done`` of ``total`` items of one step of a long run
    (the evaluations of a design search); the command line draws it as a bar with an ETA.

    Attributes
    ----------
    label : str
        The step, e.g. ``"design search"``; a new label starts a new bar.
    done, total : int
        Items finished and items in the step.
    unit : str
        What is counted (plural), e.g. ``"evaluations"``.
    detail : str
        What the items found so far, with units, e.g. ``"best h_min 41.2 µm"``.

    Examples
    --------
    >>> str(Tally("design search", 80, 1600, "evaluations", "best h_min 41.2 µm"))
    'design search: 80/1600 evaluations, best h_min 41.2 µm'
    """

    label: str
    done: int
    total: int
    unit: str = "evaluations"
    detail: str = ""

    def __str__(self) -> str:
        return f"{self.label}: {self.done}/{self.total} {self.unit}" + (f", {self.detail}" if self.detail else "")


#: A callback that reports what is being solved (the command line shows it): a short text, or
#: a :class:`Tally` from a step that counts its items.
Progress = Callable[[str | Tally], None]


def no_progress(_: str | Tally) -> None:
    """A :data:`Progress` that shows nothing."""


@dataclass(frozen=True)
class Verb:
    """A command-line verb that runs one capability on case files.

    Attributes
    ----------
    path : tuple of str
        Words of the command: ``("bearing", "solve")`` is ``shaftline bearing solve``.
    help : str
        One line for ``--help``.
    options : mapping
        Keyword arguments passed to :meth:`Capability.solve`.
    many : bool
        The verb takes several case files and compares their results
        (:meth:`Capability.compare`); with one file it is an ordinary run.
    strict : str
        Help of its ``--strict`` option (:func:`shaftline.commandline.strict_help`): what of
        this verb's result then also exits with status 3; empty for the generic text.
    """

    path: tuple[str, ...]
    help: str
    options: Mapping[str, Any] = field(default_factory=dict)
    many: bool = False
    strict: str = ""


@dataclass(frozen=True)
class Command:
    """A command-line verb of a capability that is not a run of case files (a tool on a
    data file, say): ``function`` is a typer command with its own annotated parameters."""

    path: tuple[str, ...]
    function: Callable[..., None]


@dataclass(frozen=True)
class BuildContext:
    """What building a case section may need besides the section itself.

    Attributes
    ----------
    case : CaseInfo
        The case's name and description.
    base_dir : Path
        Folder that relative file names in the case are read from (the case file's).
    inputs : list of Path
        The data files named by the case so far (:meth:`path` adds them), so that no output
        of the run can replace one.
    studies : dict
        The studies built so far, by capability key: those a capability :attr:`~Capability.needs`
        are built before it (e.g. ``[design]`` takes its film from ``[bearing]``).
    warnings : list of str
        What a build left out of, or changed from, what the file asked for by default, that the
        reader must not miss (e.g. default scenarios a lubricant cannot take): one sentence each,
        shown before solving and at the top of the report and kept in the JSON.
    kept : list of Path
        Files the run reads and writes in place and that outlive it (a trend database): like
        the inputs, no output of the run may replace one or sit in a result folder holding one;
        unlike them, they are not fingerprinted (they change with every run and may be large).
    """

    case: CaseInfo
    base_dir: Path
    inputs: list[Path] = field(default_factory=list)
    studies: dict[str, Any] = field(default_factory=dict)
    warnings: list[str] = field(default_factory=list)
    kept: list[Path] = field(default_factory=list)

    def path(self, name: str) -> Path:
        """A data file named in the case, relative to the case file unless absolute; the
        file is recorded as an input of the run."""
        path = Path(name).expanduser()
        path = path if path.is_absolute() else self.base_dir / path
        self.inputs.append(path)
        return path


@dataclass(frozen=True)
class Finding:
    """Something about a result the reader must not miss.

    Attributes
    ----------
    text : str
        One sentence, with the numbers.
    criterion : bool
        False: the result is not acceptable as it stands (no convergence, contact at the film
        floor, a physically absurd value) — the command exits with status 3. True: a design
        criterion is not met (a class-rule check, an allowable wear depth, an optimiser at its
        bound) — shown the same way, and exit status 3 only with ``--strict``.
    """

    text: str
    criterion: bool = False


@dataclass(frozen=True)
class Comparison:
    """Several cases' results set side by side (``shaftline cpp fretting A.toml B.toml``)."""

    document: dict[str, Any]
    blocks: list[Block]


SectionT = TypeVar("SectionT", bound="Section")
StudyT = TypeVar("StudyT")
ResultT = TypeVar("ResultT")


class Capability(Generic[SectionT, StudyT, ResultT]):
    """One analysis: its case-file table, problem, solution and presentation.

    Subclasses set the class attributes and implement :meth:`schema`, :meth:`build`,
    :meth:`solve`, :meth:`to_json`, :meth:`summary` and :meth:`report`; the rest is optional.

    Attributes
    ----------
    key : str
        Name of the case-file table (``[bearing]``) and of the result in ``results.json``.
    title : str
        Heading of the report section.
    verbs : tuple of Verb
        Command-line verbs that run this capability alone.
    moved_tables : mapping
        Top-level tables of an older case-file layout and where they live now, so that an
        old file gets a message saying where to move them.
    needs : tuple of str
        Keys of other capabilities whose tables this one builds on, one of them at least (in
        ``context.studies`` when :meth:`build` runs); those present are built first, also for a
        verb of this capability alone, but solved only when asked for themselves.
    parallel : bool
        :meth:`solve` spreads its work with :func:`shaftline.parallel.map` and takes its
        ``workers`` and ``scheduler`` keyword options (the command line's ``--workers`` and
        ``--scheduler`` reach it, on ``run`` and on the capability's own verbs).
    """

    key: ClassVar[str]
    title: ClassVar[str]
    verbs: ClassVar[tuple[Verb, ...]] = ()
    needs: ClassVar[tuple[str, ...]] = ()
    moved_tables: ClassVar[Mapping[str, str]] = {}
    parallel: ClassVar[bool] = False

    def schema(self) -> type[SectionT]:
        """The pydantic model of the case-file table (imported when first asked for, so
        that listing the verbs stays cheap)."""
        raise NotImplementedError

    def build(self, section: SectionT, context: BuildContext) -> StudyT:
        """Turn the validated case-file table into SI domain objects (raises ``InputError``)."""
        raise NotImplementedError

    def solve(self, study: StudyT, progress: Progress = no_progress, **options: Any) -> ResultT:
        """Solve the study. ``options`` come from the verb (:attr:`Verb.options`)."""
        raise NotImplementedError

    def to_json(self, result: ResultT) -> dict[str, Any]:
        """The result as plain JSON types, SI units (a ``units`` map says which)."""
        raise NotImplementedError

    def summary(self, result: ResultT) -> list[Block]:
        """What the terminal shows after a run: tables and short notes."""
        raise NotImplementedError

    def report(self, result: ResultT) -> list[Block]:
        """The body of the report section: notes, tables and figures."""
        raise NotImplementedError

    def findings(self, result: ResultT) -> list[Finding]:
        """What makes the result unacceptable, or fails a design criterion (shown at the top
        of the terminal output and the report; sets the exit status)."""
        return []

    def compare(self, results: Sequence[tuple[str, ResultT]]) -> Comparison:
        """Several cases' results side by side (for a verb with ``many=True``)."""
        raise NotImplementedError(f"{self.key} results cannot be compared")

    def commands(self) -> Sequence[Command]:
        """Further command-line verbs that are not runs of case files."""
        return ()


_loaded: dict[str, Capability[Any, Any, Any]] | None = None
_added: dict[str, Capability[Any, Any, Any]] = {}
_version = 0


def capabilities() -> dict[str, Capability[Any, Any, Any]]:
    """Every registered capability by key, in report order (built-ins first)."""
    global _loaded
    if _loaded is None:
        loaded = {}
        for name in CAPABILITY_MODULES:
            capability = importlib.import_module(name).CAPABILITY
            loaded[capability.key] = capability
        _loaded = loaded
    return {**_loaded, **_added}


def version() -> int:
    """A number that changes whenever the registry does (caches of the case schema key on it)."""
    return _version


def register(capability: Capability[Any, Any, Any]) -> None:
    """Add a capability (after the built-in ones). Its key must be new."""
    global _version
    if capability.key in capabilities() or capability.key == "case":
        raise ValueError(f"a capability named {capability.key!r} is registered already")
    _added[capability.key] = capability
    _version += 1


def unregister(key: str) -> None:
    """Remove a capability added with :func:`register`."""
    global _version
    del _added[key]
    _version += 1


@contextmanager
def registered(capability: Capability[Any, Any, Any]) -> Iterator[Capability[Any, Any, Any]]:
    """Register ``capability`` for the duration of a ``with`` block (tests, notebooks)."""
    register(capability)
    try:
        yield capability
    finally:
        unregister(capability.key)
