"""The hand-written mutant catalogues (benchmarks/hand_written/*.py) still apply to the code they were written on.

Each mutant replaces an exact text of its module; once that text is edited away, the catalogue would silently lose the
mutant.  Every mutant must name a row of the mutation benchmark's TABLE, find its text exactly once (or at the
occurrence it names), and still parse; a text a module no longer holds is reported with the catalogue to update.
"""

import sys
from pathlib import Path

import pytest

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "benchmarks"))
import hand_mutants  # noqa: E402

NAMES = hand_mutants.catalogue_names()


def test_there_are_catalogues_to_check():
    assert NAMES, f"no catalogue in {hand_mutants.CATALOGUES}"


@pytest.mark.parametrize("name", NAMES)
def test_every_hand_written_mutant_applies_and_changes_its_module(name):
    mutants = hand_mutants.load(name)
    assert mutants, name
    assert hand_mutants.check(mutants) == []
    for mu in mutants:
        source = (hand_mutants.mutation.ROOT / mu.path).read_text(encoding="utf-8")
        assert mu.apply(source) != source, mu.id
        assert mu.reads_wrong.strip(), mu.id


def test_a_text_not_in_the_module_or_found_twice_is_reported():
    missing = hand_mutants.HandMutant("demid/numbers.py", "no such text in the module", "x", reads_wrong="-")
    twice = hand_mutants.HandMutant("demid/numbers.py", "value", "other", reads_wrong="-")
    chosen = hand_mutants.HandMutant("demid/numbers.py", "value", "other", reads_wrong="-", occurrence=2)
    problems = hand_mutants.check([missing, twice, chosen])
    assert len(problems) == 2
    assert "not in the module" in problems[0] and "occurs" in problems[1]
