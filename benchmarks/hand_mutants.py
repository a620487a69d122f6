"""Hand-written mutants: plausible developer bugs, each written by reading a module, not generated from its syntax.

The generated mutants of ``mutation.py`` change one operator, constant or call at a time.  A developer's bug is often
larger than that (a median taken as a mean, a covariance dropped from a variance, the wrong one of two observables
chosen, a number in a sentence computed from the wrong value), and the audits that found this suite's weak spots were
written by hand.  This file runs catalogues of such mutants against the same module test subsets (``mutation.TABLE``)
and in the same private copies of the source tree.

A catalogue is a file ``benchmarks/hand_written/<name>.py`` defining ``MUTANTS``, a list of :class:`HandMutant`:
the module, the exact source text replaced (it must occur exactly once in the module, or ``occurrence`` says which)
and its replacement, and what a user would read wrong.  A catalogue is written *before* tests are written against it;
its first run is its held-out score (``first_run``, written into the file with the survivors), and after tests are
added for its survivors the catalogue stays as a regression check (every mutant killed, or listed equivalent with the
reason)::

    python benchmarks/hand_mutants.py                       # every catalogue
    python benchmarks/hand_mutants.py criticism_models      # one catalogue
    python benchmarks/hand_mutants.py --check               # only check that every mutant applies (no tests run)
"""
from __future__ import annotations

import argparse
import ast
import importlib.util
import signal
import sys
from dataclasses import dataclass
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
import mutation  # noqa: E402  (the runner, TABLE, and the private source tree)

CATALOGUES = Path(__file__).resolve().parent / "hand_written"


@dataclass(frozen=True)
class HandMutant:
    path: str  # module path, a key of mutation.TABLE
    old: str  # exact source text replaced
    new: str  # its replacement
    reads_wrong: str  # what a user would read wrong
    occurrence: int = 0  # which occurrence of ``old`` (1, 2, ...) when it occurs more than once; 0: it must be unique
    equivalent: str = ""  # a reason, when the mutant behaves exactly like the original for every input

    @property
    def id(self) -> str:
        return f"{self.path}: {self.old.strip()!r} -> {self.new.strip()!r}"

    def apply(self, source: str) -> str:
        count = source.count(self.old)
        if count == 0:
            raise ValueError(f"{self.path}: the text to replace is not in the module: {self.old!r}")
        if count > 1 and not self.occurrence:
            raise ValueError(f"{self.path}: the text to replace occurs {count} times; say which (occurrence=): "
                             f"{self.old!r}")
        if self.occurrence > count:
            raise ValueError(f"{self.path}: occurrence {self.occurrence} of {count}: {self.old!r}")
        start = -1
        for _ in range(max(self.occurrence, 1)):
            start = source.index(self.old, start + 1)
        text = source[:start] + self.new + source[start + len(self.old):]
        ast.parse(text)  # a mutant must still be valid Python
        return text


def load(name: str) -> list[HandMutant]:
    path = CATALOGUES / f"{name}.py"
    spec = importlib.util.spec_from_file_location(f"hand_mutants_{name}", path)
    module = importlib.util.module_from_spec(spec)
    sys.modules[spec.name] = module
    spec.loader.exec_module(module)
    return list(module.MUTANTS)


def catalogue_names() -> list[str]:
    return sorted(p.stem for p in CATALOGUES.glob("*.py") if not p.stem.startswith("_"))


def check(mutants: list[HandMutant]) -> list[str]:
    """Problems that stop a mutant from running: a path not in TABLE, a text not found once, a syntax error."""
    problems = []
    for mu in mutants:
        if mu.path not in mutation.TABLE:
            problems.append(f"{mu.path}: not a row of mutation.TABLE")
            continue
        try:
            mu.apply((mutation.ROOT / mu.path).read_text(encoding="utf-8"))
        except (ValueError, SyntaxError) as exc:
            problems.append(str(exc).splitlines()[0])
    return problems


def run(mutants: list[HandMutant]) -> list[tuple[HandMutant, str]] | None:
    """Each mutant against its module's tests in a private tree; None when the unmutated tests fail."""
    by_module: dict[str, list[HandMutant]] = {}
    for mu in mutants:
        by_module.setdefault(mu.path, []).append(mu)
    return mutation.run_mutants(by_module, lambda source, mu: mu.apply(source),
                                lambda mu: "equivalent" if mu.equivalent else "survived", lambda mu: mu.id)


def summarise(name: str, results: list[tuple[HandMutant, str]]) -> str:
    killed = sum(s.startswith(("killed", "error")) for _, s in results)
    survived = [mu for mu, s in results if s == "survived"]
    equivalent = sum(s == "equivalent" for _, s in results)
    line = (f"{name}: {killed} of {killed + len(survived)} killed "
            f"({100.0 * killed / max(killed + len(survived), 1):.1f} %; {equivalent} listed equivalent)")
    print(line)
    for mu in survived:
        print(f"  survived: {mu.id}\n            a user reads wrong: {mu.reads_wrong}")
    return line


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("names", nargs="*", help="catalogues to run (default: all)")
    ap.add_argument("--check", action="store_true", help="only check that every mutant applies")
    args = ap.parse_args(argv)
    names = args.names or catalogue_names()
    unknown = sorted(set(names) - set(catalogue_names()))
    if unknown:
        ap.error(f"no catalogue named {', '.join(unknown)} in {CATALOGUES}")
    catalogues = {name: load(name) for name in names}
    problems = [p for muts in catalogues.values() for p in check(muts)]
    for p in problems:
        print(p)
    if problems or args.check:
        print(f"{sum(map(len, catalogues.values()))} mutants in {len(catalogues)} catalogues; "
              f"{len(problems)} problems")
        return 1 if problems else 0
    signal.signal(signal.SIGTERM, mutation._stop_children)
    mutation.preload()
    lines = []
    for name, muts in catalogues.items():
        print(f"=== {name} ===", flush=True)
        results = run(muts)
        if results is None:
            return 2
        lines.append(summarise(name, results))
    if len(lines) > 1:
        print("\n=== all catalogues ===")
        print("\n".join(lines))
    return 0


if __name__ == "__main__":
    sys.exit(main())
