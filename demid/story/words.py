"""Words the story and the report share: a unit in running text, a key written as its label, keys in the
config's order, level 2's tolerance in words.

The story (:mod:`demid.story`) writes the verdicts and the advice with these; the report renders with the
same, so a label or a unit reads the same in ``tables/advice.csv`` and in the report.
"""

from __future__ import annotations

import re

_SUPERSCRIPT = str.maketrans("-0123456789.", "⁻⁰¹²³⁴⁵⁶⁷⁸⁹·")


def unit_text(unit: str) -> str:
    """A config unit for running text: ``J m^-2`` -> ``J m⁻²``; dimensionless -> ``–``."""
    if not unit or unit.strip() == "-":
        return "–"
    return re.sub(r"\^\{?(-?[0-9.]+)\}?", lambda m: m.group(1).translate(_SUPERSCRIPT), unit)


def natural_key(name: str) -> list:
    """Sort key that reads digits as numbers: d5, d10, d15 (not d10, d15, d5)."""
    return [int(part) if part.isdigit() else part for part in re.split(r"(\d+)", str(name))]


def in_order(mapping: dict, names=()) -> list[tuple]:
    """``mapping``'s items in the order of ``names`` (the config's), then any other key in natural order:
    JSON read back has its keys sorted as text, which puts d10 before d5."""
    known = [n for n in names if n in mapping]
    rest = sorted((k for k in mapping if k not in set(known)), key=natural_key)
    return [(k, mapping[k]) for k in known + rest]


def level2_own_tolerances(level2: dict) -> dict | None:
    """Level 2's own tolerance per observable in config order, or None when every observable is judged at
    the scenario's (also for results written before own tolerances were recorded)."""
    from ..tolerance import same_tolerances

    own = dict(in_order(level2.get("tolerances") or {}, level2.get("observables") or ()))  # JSON sorts its keys
    return None if same_tolerances(level2["tolerance"], own) else own


def level2_within(level2: dict, spec, brackets: bool = True) -> str:
    """Level 2's tolerance in words: "2 %", or each observable's own (labelled)."""
    from ..criticism.messages import level2_tolerance_text

    own = level2_own_tolerances(level2)
    if own is None:
        return f"{100 * level2['tolerance']:g} %"
    return labelled(level2_tolerance_text(level2["tolerance"], own, brackets=brackets), spec)


def labelled(text: str, spec) -> str:
    """``text`` with every factor and response key that stands as a word (``mu_s=0.9``, ``angle_of_repose
    under-predicted``) written as its configured label; keys inside a config path (``responses.d5.target``)
    or a file name stay as they are."""
    names = {**{f.name: f.label for f in spec.factors}, **{r.name: r.label for r in spec.responses}}
    names = {k: v for k, v in names.items() if v and v != k}
    if not names or not text:
        return text
    words = [k for k in names if k in _ENGLISH_WORDS]  # "a": a factor only where a value or a bracket follows
    others = [k for k in names if k not in _ENGLISH_WORDS]

    def alternation(keys):
        return "|".join(re.escape(k) for k in sorted(keys, key=len, reverse=True))

    if others:
        text = re.compile(r"(?<![\w./`])(" + alternation(others) + r")(?![\w`]|\.\w)").sub(
            lambda m: names[m.group(1)], text)
    if words:
        text = re.compile(r"(?<![\w./`])(" + alternation(words) + r")(?=\s*[=≈]|[,;:)]|\.(?:\s|$)|$)").sub(
            lambda m: names[m.group(1)], text)
    return text


#: Short English words a factor or response may be called (``a``, ``in``): in running text they are read as
#: words, and replaced by the label only where a value, a bracket or punctuation follows (``a=0.1``, ``(a ≈ 2)``).
_ENGLISH_WORDS = frozenset({"a", "an", "and", "any", "are", "as", "at", "be", "but", "by", "can", "do", "for", "if",
                            "in", "is", "it", "its", "may", "no", "not", "of", "on", "one", "or", "per", "so", "the",
                            "to", "up", "was", "we"})
