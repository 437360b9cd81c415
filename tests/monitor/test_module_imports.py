"""The modules of shaftline.monitor import one another without a circle.

Imports under ``if TYPE_CHECKING:`` are left out (they never run); imports inside functions
count, as they run when the function does.
"""

from __future__ import annotations

import ast
from pathlib import Path

import shaftline.monitor

PACKAGE = Path(shaftline.monitor.__file__).parent
NAMES = {path.stem for path in PACKAGE.glob("*.py")} - {"__init__"}


def _runtime_imports(tree: ast.AST) -> set[str]:
    """Modules of the package that ``tree`` imports when it runs."""
    found: set[str] = set()

    def visit(node: ast.AST) -> None:
        for child in ast.iter_child_nodes(node):
            if isinstance(child, ast.If) and "TYPE_CHECKING" in ast.unparse(child.test):
                for other in child.orelse:
                    visit_statement(other)
                continue
            visit_statement(child)

    def visit_statement(node: ast.AST) -> None:
        if isinstance(node, ast.ImportFrom) and node.module:
            modules = [node.module] + [f"{node.module}.{alias.name}" for alias in node.names]
        elif isinstance(node, ast.Import):
            modules = [alias.name for alias in node.names]
        else:
            modules = []
        for module in modules:
            head, _, name = module.rpartition(".")
            if head == "shaftline.monitor" and name in NAMES:
                found.add(name)
        visit(node)

    visit(tree)
    return found


def _graph() -> dict[str, set[str]]:
    return {
        name: _runtime_imports(ast.parse((PACKAGE / f"{name}.py").read_text(encoding="utf-8"))) - {name}
        for name in NAMES
    }


def _circle(graph: dict[str, set[str]]) -> list[str] | None:
    """One import circle of ``graph`` (its modules in order), or None."""
    state: dict[str, int] = {}  # 1: on the current path, 2: done
    path: list[str] = []

    def walk(name: str) -> list[str] | None:
        state[name] = 1
        path.append(name)
        for other in sorted(graph[name]):
            if state.get(other) == 1:
                return path[path.index(other) :] + [other]
            if other not in state and (found := walk(other)) is not None:
                return found
        path.pop()
        state[name] = 2
        return None

    for name in sorted(graph):
        if name not in state and (found := walk(name)) is not None:
            return found
    return None


def test_the_monitor_modules_import_each_other_without_a_circle():
    assert _circle(_graph()) is None


def test_processing_and_study_share_their_records_through_identified():
    graph = _graph()
    assert "study" in graph["processing"] and "processing" not in graph["study"]
    assert graph["identified"] == set()


def test_the_circle_finder_finds_one():
    assert _circle({"a": {"b"}, "b": {"c"}, "c": {"a"}}) == ["a", "b", "c", "a"]
    assert _circle({"a": {"b"}, "b": set()}) is None
