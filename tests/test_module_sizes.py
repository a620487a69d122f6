"""Every module of the package fits on a reader's screen in a few pages, and every function in one: no module
over 500 lines, no function (or method) over 80.  Counted here with ``ast`` from the source, so a module that
grows past it is named, with the way out (split it by concept, as demid/report/ is split by section)."""

from __future__ import annotations

import ast
from pathlib import Path

PACKAGE = Path(__file__).resolve().parents[1] / "demid"
MAX_MODULE_LINES = 500
MAX_FUNCTION_LINES = 80


def long_modules(root: Path = PACKAGE, limit: int = MAX_MODULE_LINES) -> list[str]:
    """``path: lines`` of every module of ``root`` longer than ``limit`` lines."""
    found = []
    for path in sorted(root.rglob("*.py")):
        lines = len(path.read_text(encoding="utf-8").splitlines())
        if lines > limit:
            found.append(f"{path.relative_to(root.parent)}: {lines} lines")
    return found


def long_functions(root: Path = PACKAGE, limit: int = MAX_FUNCTION_LINES) -> list[str]:
    """``path:line name: lines`` of every function or method of ``root`` longer than ``limit`` lines
    (decorators and docstring included)."""
    found = []
    for path in sorted(root.rglob("*.py")):
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"), str(path))):
            if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef)):
                first = min([node.lineno] + [d.lineno for d in node.decorator_list])
                lines = node.end_lineno - first + 1
                if lines > limit:
                    found.append(f"{path.relative_to(root.parent)}:{node.lineno} {node.name}: {lines} lines")
    return found


def test_the_counts_see_a_long_module_and_a_long_function(tmp_path):
    pkg = tmp_path / "demid"
    pkg.mkdir()
    (pkg / "short.py").write_text("def f():\n    return 1\n")
    body = "".join(f"    x{i} = {i}\n" for i in range(80))
    (pkg / "long.py").write_text("class C:\n    @staticmethod\n    def g():\n" + body.replace("    ", "        ")
                                 + "\n" * 420)
    assert long_modules(pkg) == ["demid/long.py: 503 lines"]
    assert long_functions(pkg) == ["demid/long.py:3 g: 82 lines"]
    assert long_functions(pkg, limit=82) == [] and long_modules(pkg, limit=503) == []


def test_no_module_over_500_lines():
    found = long_modules()
    assert not found, "split these modules by concept: " + "; ".join(found)


def test_no_function_over_80_lines():
    found = long_functions()
    assert not found, "split these functions into named steps: " + "; ".join(found)
