"""The shape of the code, checked: no import circles in ``src/``, the size limits of modules and
functions (with the exceptions ``docs/architecture.md`` lists and explains), no module-level
mutable state in the film package, and the physics modules free of the case schema, the
registry, the report and the command line.

The imports are read from the source (``ast``), every ``import`` at any depth of a module
(a function's own imports run too), except those under ``if TYPE_CHECKING:``, which never run.
"""

from __future__ import annotations

import ast
import re
from collections.abc import Iterator
from pathlib import Path

import numpy as np
import pytest
from scipy.sparse import coo_matrix
from scipy.sparse.csgraph import connected_components

ROOT = Path(__file__).resolve().parents[1]
SRC = ROOT / "src"
ARCHITECTURE = ROOT / "docs" / "architecture.md"
MODULE_LINES = 100 * 8
FUNCTION_LINES = {"shaftline.film": 80, "": 100}
#: Modules of a capability package that face the user (its case schema, registry entry, report,
#: figures, command line); all others are its physics and numerics.
FACING = re.compile(r"\.(case(_\w+)?|capability|commands|presentation|summary|figures|trend_report|report)$")
#: What a physics module may not import.
USER_FACING = ("shaftline.cases", "shaftline.registry", "shaftline.report", "shaftline.cli", "shaftline.commandline")
#: Except the registry's progress protocol, which a long computation is handed to say how far it is.
PROGRESS = {"Progress", "Tally", "no_progress"}
PHYSICS_PACKAGES = ("film", "shaft", "design", "monitor", "cpp", "contact", "gears", "wear", "friction")


def modules() -> dict[str, Path]:
    found = {}
    for path in sorted(SRC.rglob("*.py")):
        parts = path.relative_to(SRC).with_suffix("").parts
        name = ".".join(parts[:-1] if parts[-1] == "__init__" else parts)
        found[name] = path
    return found


def _runtime_nodes(tree: ast.AST) -> Iterator[ast.AST]:
    """Every node of ``tree`` outside ``if TYPE_CHECKING:`` blocks."""
    for node in ast.iter_child_nodes(tree):
        if isinstance(node, ast.If) and "TYPE_CHECKING" in ast.unparse(node.test):
            yield from (n for child in node.orelse for n in [child, *_runtime_nodes(child)])
            continue
        yield node
        yield from _runtime_nodes(node)


def imported(name: str, path: Path, known: dict[str, Path]) -> set[str]:
    """The modules ``name`` imports when it runs: a ``from package import member`` is the member's
    module where the member is one, else the package."""
    package = name if path.name == "__init__.py" else name.rpartition(".")[0]
    out: set[str] = set()
    for node in _runtime_nodes(ast.parse(path.read_text())):
        if isinstance(node, ast.Import):
            out.update(alias.name for alias in node.names)
        elif isinstance(node, ast.ImportFrom):
            base = node.module or ""
            if node.level:
                anchor = package.split(".")[: len(package.split(".")) - node.level + 1]
                base = ".".join([*anchor, base] if base else anchor)
            for alias in node.names:
                out.add(f"{base}.{alias.name}" if f"{base}.{alias.name}" in known else base)
    return out


def import_graph() -> dict[str, set[str]]:
    known = modules()
    return {name: {m for m in imported(name, path, known) if m in known and m != name} for name, path in known.items()}


def circles(graph: dict[str, set[str]]) -> list[list[str]]:
    """The groups of modules that import each other, directly or round a circle."""
    names = sorted(graph)
    index = {name: k for k, name in enumerate(names)}
    edges = [(index[a], index[b]) for a in names for b in graph[a]]
    rows, cols = zip(*edges, strict=True) if edges else ((), ())
    matrix = coo_matrix((np.ones(len(edges)), (rows, cols)), shape=(len(names), len(names)))
    _, labels = connected_components(matrix, directed=True, connection="strong")
    groups = [[names[k] for k in np.flatnonzero(labels == label)] for label in np.unique(labels)]
    return [group for group in groups if len(group) > 1]


def listed_exceptions() -> dict[str, str]:
    """The size exceptions of docs/architecture.md: module or ``module:function`` → reason."""
    text = ARCHITECTURE.read_text()
    section = text.split("## Size limits", 1)[1].split("\n## ", 1)[0]
    rows = re.findall(r"^\| `([\w.:]+)` \| (.+?) \|$", section, flags=re.MULTILINE)
    return dict(rows)


def function_lengths() -> Iterator[tuple[str, int, int]]:
    for name, path in modules().items():
        limit = next(v for k, v in FUNCTION_LINES.items() if name.startswith(k))
        for node in ast.walk(ast.parse(path.read_text())):
            if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef)):
                yield f"{name}:{node.name}", node.end_lineno - node.lineno + 1, limit  # type: ignore[operator]


def test_the_walker_sees_a_circle_and_ignores_type_checking(tmp_path):
    graph = {"a": {"b"}, "b": {"c"}, "c": {"a"}, "d": {"a"}}
    assert circles(graph) == [["a", "b", "c"]]
    module = tmp_path / "m.py"
    module.write_text(
        "from typing import TYPE_CHECKING\nif TYPE_CHECKING:\n    import shaftline.film\n"
        "def f():\n    import shaftline.export\n"
    )
    found = imported("shaftline.m", module, {"shaftline.export": module, "shaftline.film": module})
    assert "shaftline.export" in found and "shaftline.film" not in found


def test_no_import_circles_in_src():
    assert circles(import_graph()) == []


def test_no_module_above_the_limit_unless_listed():
    exceptions = listed_exceptions()
    long = {
        name: len(path.read_text().splitlines())
        for name, path in modules().items()
        if len(path.read_text().splitlines()) > MODULE_LINES
    }
    assert {name: lines for name, lines in long.items() if name not in exceptions} == {}


def test_no_function_above_the_limit_unless_listed():
    exceptions = listed_exceptions()
    long = {name: lines for name, lines, limit in function_lengths() if lines > limit and name not in exceptions}
    assert long == {}


def test_every_listed_exception_is_still_needed():
    """An exception that the code no longer needs is taken off the list, so the list stays true."""
    sizes = {name: len(path.read_text().splitlines()) > MODULE_LINES for name, path in modules().items()}
    sizes.update({name: lines > limit for name, lines, limit in function_lengths()})
    assert [name for name in listed_exceptions() if not sizes.get(name, False)] == []


MUTABLE = (ast.List, ast.Dict, ast.Set, ast.ListComp, ast.DictComp, ast.SetComp)
MUTABLE_CALLS = {
    "dict",
    "list",
    "set",
    "defaultdict",
    "OrderedDict",
    "deque",
    "WeakValueDictionary",
    "WeakKeyDictionary",
}
CHANGING = {"append", "extend", "insert", "update", "setdefault", "pop", "popitem", "clear", "add", "discard", "remove"}


def module_level_state(path: Path) -> list[str]:
    """State kept by a module: ``global`` statements, names bound at module level to an empty
    container (to be filled while the program runs) and module-level containers that the module
    changes (an item set or deleted, a changing method called). A table written out in full and
    only read is a constant, not state."""
    tree = ast.parse(path.read_text())
    found = [f"global {', '.join(node.names)}" for node in ast.walk(tree) if isinstance(node, ast.Global)]
    containers = {}
    for node in tree.body:
        if isinstance(node, (ast.Assign, ast.AnnAssign)) and node.value is not None:
            value = node.value
            call = isinstance(value, ast.Call) and ast.unparse(value.func).rpartition(".")[2] in MUTABLE_CALLS
            if isinstance(value, MUTABLE) or call:
                targets = node.targets if isinstance(node, ast.Assign) else [node.target]
                empty = call and not (value.args or value.keywords) or not call and not ast.unparse(value)[1:-1]
                containers.update({ast.unparse(target): empty for target in targets})
    changed = set()
    for node in ast.walk(tree):
        if isinstance(node, (ast.Assign, ast.AugAssign, ast.Delete)):
            for target in node.targets if isinstance(node, (ast.Assign, ast.Delete)) else [node.target]:
                if isinstance(target, ast.Subscript):
                    changed.add(ast.unparse(target.value))
        elif isinstance(node, ast.Call) and isinstance(node.func, ast.Attribute) and node.func.attr in CHANGING:
            changed.add(ast.unparse(node.func.value))
    found.extend(name for name, empty in containers.items() if empty or name in changed)
    return found


def test_module_level_state_is_seen(tmp_path):
    module = tmp_path / "m.py"
    module.write_text(
        "A = {}\nB: list[int] = []\nC = (1, 2)\nD = dict(a=1)\nE = {'a': 1}\nF = [1]\n"
        "def f(key):\n    global A\n    E[key] = 2\n    F.append(key)\n    D.get(key)\n"
    )
    assert module_level_state(module) == ["global A", "A", "B", "E", "F"]


def test_no_module_level_mutable_state_in_the_film_package():
    film = {name: module_level_state(path) for name, path in modules().items() if name.startswith("shaftline.film")}
    assert {name: state for name, state in film.items() if state} == {}


@pytest.mark.parametrize("package", PHYSICS_PACKAGES)
def test_physics_modules_import_no_schema_registry_report_or_command_line(package):
    graph = import_graph()
    physics = [n for n in graph if n.startswith(f"shaftline.{package}.") and not FACING.search(n)]
    known = modules()
    wrong = {}
    for name in physics:
        found = {m for m in imported(name, known[name], known) if m.startswith(USER_FACING)}
        for node in _runtime_nodes(ast.parse(known[name].read_text())):
            if isinstance(node, ast.ImportFrom) and node.module == "shaftline.registry":
                if {alias.name for alias in node.names} <= PROGRESS:
                    found.discard("shaftline.registry")
        for node in _runtime_nodes(ast.parse(known[name].read_text())):
            if isinstance(node, ast.Import | ast.ImportFrom) and "typer" in ast.unparse(node).split():
                found.add("typer")
        if found:
            wrong[name] = sorted(found)
    assert wrong == {}
