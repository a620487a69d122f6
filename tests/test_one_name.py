"""The plausible set has one name in code: ``plausible``.  Earlier studies' user-facing names stay readable
(the file ``robust_identifiability.csv``, ``uncertainty/<material>_robust.parquet``, the ``robust_*`` columns,
the config key ``robust_z``), and nothing else in the package, the workflow or its scripts says "robust" for it."""

import io
import re
import tokenize
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
KEPT = re.compile(r"robust_\*|robust_(z|identifiability|fraction_pct|fraction_error_pct|lower|upper|width)\b|_robust\.parquet")


def _sources():
    yield from sorted((ROOT / "demid").rglob("*.py"))
    yield from sorted((ROOT / "scripts").glob("*.py"))
    yield from sorted((ROOT / "workflow").rglob("*.smk"))
    yield ROOT / "Snakefile"


def robust_words(text: str) -> list[str]:
    """Every 'robust' in ``text`` that is not one of the kept user-facing names (nor 'most robust', which is
    about a point's distance from the set's edge, not the set's name)."""
    kept = KEPT.sub("", text)
    return [m.group(0) for m in re.finditer(r"(?<!most )\brobust\w*", kept, re.IGNORECASE)]


def test_robust_words_finds_the_old_name_and_keeps_the_user_facing_ones():
    assert robust_words('x = robust_admissible_set(a)\nrobust = 1\nsizes["robust"]') == [
        "robust_admissible_set", "robust", "robust"]
    assert robust_words('read("robust_identifiability.csv"); cfg["robust_z"]; row["robust_lower"]; '
                        '"uncertainty/{m}_robust.parquet"; the most robust point') == []


def test_the_plausible_set_has_one_name_in_code():
    found = {}
    for path in _sources():
        words = robust_words(path.read_text(encoding="utf-8"))
        if words:
            found[str(path.relative_to(ROOT))] = words
    assert not found, f"'robust' for the plausible set (call it plausible): {found}"
