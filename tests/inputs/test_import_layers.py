"""No import circles in the package, counting imports inside functions too, and an input layer that
imports nothing above it.

The graph is built here from the source with ``ast``, independently of any other tool: every
``import``/``from … import`` statement anywhere in a module (module level, functions, methods) is an
edge, except those under ``if TYPE_CHECKING:``, which never run.  A circle is a strongly connected
component of more than one module (or a module importing itself).
"""

from __future__ import annotations

import ast
from pathlib import Path


PACKAGE = Path(__file__).resolve().parents[2] / "demid"


def _module_name(path: Path, root: Path) -> str:
    parts = ["demid", *path.relative_to(root).with_suffix("").parts]
    return ".".join(parts[:-1] if parts[-1] == "__init__" else parts)


def package_modules(root: Path = PACKAGE) -> dict[str, Path]:
    return {_module_name(p, root): p for p in sorted(root.rglob("*.py"))}


def _is_type_checking(test: ast.expr) -> bool:
    return (isinstance(test, ast.Name) and test.id == "TYPE_CHECKING") or (
        isinstance(test, ast.Attribute) and test.attr == "TYPE_CHECKING")


def _import_nodes(tree: ast.AST):
    """Every import statement, skipping the bodies of ``if TYPE_CHECKING:`` (their ``else`` runs)."""
    stack = [tree]
    while stack:
        node = stack.pop()
        if isinstance(node, (ast.Import, ast.ImportFrom)):
            yield node
        if isinstance(node, ast.If) and _is_type_checking(node.test):
            stack.extend(node.orelse)
            continue
        stack.extend(ast.iter_child_nodes(node))


def _owner(name: str, modules) -> str | None:
    """The deepest module of the package that ``name`` lies in."""
    while name:
        if name in modules:
            return name
        name = name.rpartition(".")[0]
    return None


def import_edges(modules: dict[str, Path]) -> dict[str, set[str]]:
    edges = {m: set() for m in modules}
    for module, path in modules.items():
        is_package = path.name == "__init__.py"
        for node in _import_nodes(ast.parse(path.read_text(), str(path))):
            if isinstance(node, ast.Import):
                targets = [alias.name for alias in node.names]
            else:
                if node.level:
                    base = module.split(".") if is_package else module.split(".")[:-1]
                    base = base[:len(base) - (node.level - 1)]
                    stem = ".".join(base + ([node.module] if node.module else []))
                else:
                    stem = node.module or ""
                # ``from pkg import sub`` imports the submodule when ``sub`` is one
                targets = [f"{stem}.{alias.name}" for alias in node.names]
            for target in targets:
                owner = _owner(target, modules)
                if owner is not None and owner != module:
                    edges[module].add(owner)
    return edges


def circles(edges: dict[str, set[str]]) -> list[list[str]]:
    """Strongly connected components of more than one module (Tarjan, iterative)."""
    index, low, on_stack, stack, found = {}, {}, set(), [], []
    counter = 0
    for root in sorted(edges):
        if root in index:
            continue
        work = [(root, iter(sorted(edges[root])))]
        index[root] = low[root] = counter
        counter += 1
        stack.append(root)
        on_stack.add(root)
        while work:
            node, children = work[-1]
            for child in children:
                if child not in index:
                    index[child] = low[child] = counter
                    counter += 1
                    stack.append(child)
                    on_stack.add(child)
                    work.append((child, iter(sorted(edges[child]))))
                    break
                if child in on_stack:
                    low[node] = min(low[node], index[child])
            else:
                work.pop()
                if work:
                    low[work[-1][0]] = min(low[work[-1][0]], low[node])
                if low[node] == index[node]:
                    component = []
                    while True:
                        member = stack.pop()
                        on_stack.discard(member)
                        component.append(member)
                        if member == node:
                            break
                    if len(component) > 1:
                        found.append(sorted(component))
    return found


def test_the_cycle_finder_finds_planted_circles(tmp_path):
    pkg = tmp_path / "demid"
    (pkg / "sub").mkdir(parents=True)
    (pkg / "__init__.py").write_text("")
    (pkg / "a.py").write_text("from .b import x\n")
    (pkg / "b.py").write_text("def f():\n    from .sub.c import y\n")
    (pkg / "sub" / "__init__.py").write_text("")
    (pkg / "sub" / "c.py").write_text("from typing import TYPE_CHECKING\nif TYPE_CHECKING:\n    from ..d import z\n"
                                       "def g():\n    from .. import a\n")
    (pkg / "d.py").write_text("from .sub import c\n")
    modules = package_modules(pkg)
    edges = import_edges(modules)
    assert edges["demid.sub.c"] == {"demid.a"}  # the TYPE_CHECKING import is no edge
    assert edges["demid.d"] == {"demid.sub.c"}
    assert circles(edges) == [["demid.a", "demid.b", "demid.sub.c"]]
    (pkg / "b.py").write_text("x = 1\n")
    assert circles(import_edges(modules)) == []


#: The input layer and, per module, every demid module it may import (at module level or inside a function).
#: Reading and checking what a user gives -- the schema, the config checks, table reading, design inference,
#: the typo check and the MaterialSpec built from them -- is the bottom of the package: none of it imports a
#: fit, a set, a criticism, a figure or a report.  The last four entries are leaves the layer borrows (the
#: search box, a CSV precision constant, label typesetting, the simulation command's check); they import
#: only from the layer.  A new import here is a decision about the layer: add it to this table deliberately.
INPUT_LAYER = {
    "demid.errors": set(),
    "demid.numbers": set(),
    "demid.lazy": set(),
    "demid.precision": set(),
    "demid.formulas": set(),
    "demid.design": set(),
    "demid.blocks": {"demid.design"},
    "demid.schema": {"demid.errors", "demid.numbers"},
    "demid.config_text": {"demid.errors", "demid.schema"},
    "demid.published_values": {"demid.errors", "demid.schema"},
    "demid.config": {"demid.design", "demid.errors", "demid.plots.labels", "demid.published_values", "demid.schema",
                     "demid.simulation", "demid.spec", "demid.transcription.printed"},
    "demid.spec": {"demid.sampling.domain", "demid.schema"},
    "demid.design_check": {"demid.design", "demid.errors", "demid.precision", "demid.schema"},
    "demid.estimability": {"demid.design", "demid.errors"},
    "demid.design_inference": {"demid.design", "demid.errors", "demid.precision"},
    "demid.csv_cells": {"demid.errors", "demid.numbers"},
    "demid.data": {"demid.blocks", "demid.csv_cells", "demid.design", "demid.design_check", "demid.errors",
                   "demid.estimability", "demid.precision", "demid.transcription.typos"},
    "demid.transcription": {"demid.lazy", "demid.transcription.check", "demid.transcription.printed",
                            "demid.transcription.typos"},
    "demid.transcription.printed": {"demid.design", "demid.errors", "demid.formulas", "demid.published_values"},
    "demid.transcription.typos": {"demid.design", "demid.errors", "demid.precision", "demid.transcription.printed"},
    "demid.transcription.engine": {"demid.design", "demid.errors", "demid.formulas", "demid.transcription.printed"},
    "demid.transcription.check": {"demid.design", "demid.errors", "demid.io", "demid.transcription.engine",
                                  "demid.transcription.printed", "demid.transcription.typos"},
    "demid.sampling": {"demid.lazy", "demid.sampling.domain"},
    "demid.sampling.domain": {"demid.design"},
    "demid.io": set(),
    "demid.plots": {"demid.lazy"},
    "demid.plots.labels": set(),
    "demid.simulation": {"demid.errors", "demid.numbers"},
}


def _packages(module: str) -> list[str]:
    """The packages importing ``module`` runs first (``demid.transcription`` for ``demid.transcription.typos``);
    the lazy top-level ``demid`` package is left out."""
    parts = module.split(".")
    return [".".join(parts[:i]) for i in range(2, len(parts))]


def layer_violations(edges: dict[str, set[str]], layer: dict[str, set[str]]) -> list[str]:
    """Imports of a layer's modules that the layer does not allow, and imports that reach a module (or a
    package whose ``__init__`` would run) outside the layer."""
    found = []
    for module, allowed in layer.items():
        for target in sorted(edges.get(module, set())):
            if target not in allowed:
                found.append(f"{module} imports {target}")
            found += [f"{module} imports {target}, whose package {package} lies outside the layer"
                      for package in _packages(target) if package not in layer]
    return found


def test_the_layer_check_fails_when_the_table_reader_imports_the_fit(tmp_path):
    pkg = tmp_path / "demid"
    (pkg / "transcription").mkdir(parents=True)
    for name in ("__init__", "design", "surrogate", "transcription/__init__", "transcription/typos"):
        (pkg / f"{name}.py").write_text("")
    (pkg / "data.py").write_text("from .design import x\ndef read():\n    from .transcription.typos import y\n")
    layer = {"demid.design": set(), "demid.data": {"demid.design", "demid.transcription.typos"},
             "demid.transcription.typos": set()}
    modules = package_modules(pkg)
    assert layer_violations(import_edges(modules), layer) == [
        "demid.data imports demid.transcription.typos, whose package demid.transcription lies outside the layer"]
    layer["demid.transcription"] = set()
    assert layer_violations(import_edges(modules), layer) == []
    # the table reader climbing up to the fit, inside a function, is refused
    (pkg / "data.py").write_text("from .design import x\ndef read():\n    from .surrogate import fit\n")
    assert layer_violations(import_edges(modules), layer) == ["demid.data imports demid.surrogate"]
    (pkg / "transcription" / "typos.py").write_text("from typing import TYPE_CHECKING\nif TYPE_CHECKING:\n"
                                                     "    from ..surrogate import Surrogate\n")
    assert layer_violations(import_edges(modules), layer) == ["demid.data imports demid.surrogate"]


def test_the_input_layer_imports_nothing_above_it():
    edges = import_edges(package_modules())
    assert set(INPUT_LAYER) <= set(edges), f"not modules of demid: {sorted(set(INPUT_LAYER) - set(edges))}"
    for module, allowed in INPUT_LAYER.items():
        assert allowed <= set(INPUT_LAYER), f"{module} may import outside the layer: {allowed - set(INPUT_LAYER)}"
    found = layer_violations(edges, INPUT_LAYER)
    assert not found, "the input layer imports above itself: " + "; ".join(found)


def test_no_import_circles_in_the_package():
    found = circles(import_edges(package_modules()))
    assert not found, "import circles: " + "; ".join(" <-> ".join(c) for c in found)


if __name__ == "__main__":  # print the circles and their edges
    edges = import_edges(package_modules())
    for circle in circles(edges):
        print(circle)
        for m in circle:
            print("   ", m, "->", sorted(edges[m] & set(circle)))
