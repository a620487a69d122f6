"""Names in a config that would give two rules, or one rule for two materials, the same output file.

Snakemake refuses such a workflow with an AmbiguousRuleException that names rules and wildcards, not
the config key that caused it: materials ``mortar`` and ``mortar_transcription`` (``mortar``'s
``validated/mortar_transcription.parquet`` is ``mortar_transcription``'s ``validated/{material}.parquet``),
or ``paper_figure: surface`` (``figures/surface_{material}.png`` is already the surface figure).
Every output pattern is written out for every material it applies to, and the first file written twice
is named with the config key to change.
"""

from __future__ import annotations

import re

_WILDCARD = re.compile(r"\{([A-Za-z_][A-Za-z0-9_]*)(?:,[^{}]*)?\}")
#: Values tried for the wildcards that number waves and runs: the names decide a clash, not the numbers.
_NUMBERED = {"wave": "1", "run": "1"}


def ambiguous_output(patterns, materials: dict) -> str:
    """The error line for the first output file two patterns (or one pattern for two materials) would
    both write, or "".  ``patterns``: (output pattern, {wildcard: regex constraint}) of every rule;
    ``materials``: the config's ``materials``."""
    writers: dict[str, tuple[str, str]] = {}  # concrete file -> (pattern, material)
    for pattern, constraints in patterns:
        names = set(_WILDCARD.findall(pattern))
        if "material" not in names or names - {"material", "paper_figure", *_NUMBERED}:
            continue
        for material, block in materials.items():
            allowed = constraints.get("material")
            if allowed and not re.fullmatch(allowed, material):
                continue
            values = dict(_NUMBERED, material=material, paper_figure=(block or {}).get("paper_figure") or "")
            if "paper_figure" in names and not values["paper_figure"]:
                continue
            path = _WILDCARD.sub(lambda m: values[m.group(1)], pattern)
            first = writers.setdefault(path, (pattern, material))
            if first != (pattern, material):
                return _clash(path, first, (pattern, material))
    return ""


def _clash(path: str, first: tuple[str, str], second: tuple[str, str]) -> str:
    (pattern_a, material_a), (pattern_b, material_b) = first, second
    if "{paper_figure" in pattern_a + pattern_b:
        material = material_a if "{paper_figure" in pattern_a else material_b
        return (f"config key materials.{material}.paper_figure: the name gives {path}, a file the material's "
                "results already have; choose another name")
    return (f"config key materials.{material_b}: the names '{material_a}' and '{material_b}' both give {path}; "
            "rename one of the materials")
