"""The README's package map cannot rot: every module and folder it names exists, and every name in backticks
is a function, class or method of the module named last before it in its entry."""

from __future__ import annotations

import ast
import re
from pathlib import Path

import pytest

REPO = Path(__file__).resolve().parent.parent
MODULE = re.compile(r"(?<![\w/.])((?:[a-z_]+/)?[a-z_0-9]+\.py)\b")
NAME = re.compile(r"`([A-Za-z_]\w*(?:\.[A-Za-z_]\w*)?)`")
ENTRY = re.compile(r"^  (\S+(?: \S+)?)\s{2,}|^  (\S+)$")


def package_map(readme: str) -> list[str]:
    """The lines of the fenced block that follows "The package, one module per concept"."""
    after = readme.split("The package, one module per concept", 1)[1]
    block = after.split("```\n", 1)[1].split("```", 1)[0]
    return block.splitlines()


def references(lines: list[str]) -> list[tuple[str, Path, str | None]]:
    """(line, file or folder, name or None) for every module, folder and backticked name of the map, each
    resolved as a reader would: a bare module of a subpackage's entry lies in that subpackage."""
    found, section, package, current = [], None, None, None
    for line in lines:
        if line and not line.startswith(" "):
            section = line.split()[0]
            package = REPO / "demo" if section == "demo/" else None
            current = None
        elif ENTRY.match(line) and section == "demid/":
            key = line.split()[0]
            package = REPO / "demid" / key if key.endswith("/") else None
            current = None
            if package is not None:
                found.append((line, package, None))
        elif ENTRY.match(line):
            current = None
        tokens = sorted([(m.start(), "module", m.group(1)) for m in MODULE.finditer(line)]
                        + [(m.start(), "name", m.group(1)) for m in NAME.finditer(line)])
        for _, kind, text in tokens:
            if kind == "module":
                base = package if package is not None and "/" not in text else REPO / "demid"
                current = base / text
                found.append((line, current, None))
            elif current is not None:
                found.append((line, current, text))
            else:
                found.append((line, Path("<no module before it>"), text))
    return found


def defines(path: Path, name: str) -> bool:
    """``name`` (or ``Class.member``) is defined at the top level of ``path`` (a class's body for a member)."""
    tree = ast.parse(path.read_text(encoding="utf-8"))
    owner, _, member = name.partition(".")

    def names(body):
        out = {}
        for node in body:
            if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef, ast.ClassDef)):
                out[node.name] = node
            elif isinstance(node, (ast.Assign, ast.AnnAssign)):
                targets = node.targets if isinstance(node, ast.Assign) else [node.target]
                out.update({t.id: node for t in targets if isinstance(t, ast.Name)})
        return out

    top = names(tree.body)
    if owner not in top:
        return False
    return not member or (isinstance(top[owner], ast.ClassDef) and member in names(top[owner].body))


README_MAP = references(package_map((REPO / "README.md").read_text(encoding="utf-8")))


def test_the_map_names_the_decisions_and_the_modules_they_live_in():
    named = {(p.relative_to(REPO).as_posix(), n) for _, p, n in README_MAP if n}
    for decision in [("demid/story/verdicts.py", "factor_verdict"), ("demid/story/advice.py", "material_advice"),
                     ("demid/next_wave.py", "plan_next_wave"), ("demid/blocks.py", "block_effects"),
                     ("demid/scenario.py", "JudgedScenario.contains"), ("demid/story/words.py", "labelled")]:
        assert decision in named, decision


@pytest.mark.parametrize("line, path, name", README_MAP, ids=[f"{p.name}:{n or ''}" for _, p, n in README_MAP])
def test_every_module_and_name_of_the_readme_map_exists(line, path, name):
    assert path.exists(), f"the README's package map names {path}, which does not exist: {line.strip()}"
    if name is not None:
        assert path.is_file() and defines(path, name), f"{path.relative_to(REPO)} defines no {name}: {line.strip()}"
