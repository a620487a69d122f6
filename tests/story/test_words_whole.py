"""The shared words of the story and the report over generated inputs, each against a rule written here: a unit's
powers as superscripts (signs, decimals, braces), names sorted by their numbers, a mapping in the config's order
then the rest in natural order, and level 2's tolerance in words: one percentage when every observable is judged
at the scenario's tolerance, else each observable's own, labelled, in config order, every quoted number parsed
back."""

from __future__ import annotations

import re

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st

from demid.spec import MaterialSpec
from demid.story.words import in_order, level2_own_tolerances, level2_within, natural_key, unit_text

_SUPER = dict(zip("-0123456789.", "⁻⁰¹²³⁴⁵⁶⁷⁸⁹·"))


@given(parts=st.lists(st.tuples(st.sampled_from(["m", "J", "kg", "s", "N"]),
                                st.sampled_from(["", "^2", "^-2", "^{-1}", "^0.5", "^{3}", "^-10"])),
                      min_size=1, max_size=3))
@settings(max_examples=60, deadline=None, derandomize=True)
def test_a_units_powers_are_written_as_superscripts(parts):
    unit = " ".join(base + power for base, power in parts)
    expected = " ".join(base + "".join(_SUPER[c] for c in power.strip("^{}")) for base, power in parts)
    assert unit_text(unit) == expected
    assert unit_text("-") == unit_text(" - ") == unit_text("") == "–"


@given(numbers=st.lists(st.integers(0, 2000), min_size=1, max_size=8, unique=True),
       order=st.permutations(range(8)), known=st.integers(0, 8))
@settings(max_examples=60, deadline=None, derandomize=True)
def test_names_sort_by_their_numbers_and_a_mapping_reads_in_config_order_then_natural_order(numbers, order, known):
    names = [f"d{n}" for n in numbers]
    assert sorted(names, key=natural_key) == [f"d{n}" for n in sorted(numbers)]
    mapping = {name: i for i, name in enumerate(sorted(names))}  # text order, as JSON read back has it
    config = [names[i] for i in order if i < len(names)][:known] + ["absent"]
    got = in_order(mapping, config)
    listed = [n for n in config if n in mapping]
    rest = [f"d{n}" for n in sorted(numbers) if f"d{n}" not in listed]
    assert got == [(n, mapping[n]) for n in listed + rest]


def _spec(names, labels):
    return MaterialSpec.from_material("m", {
        "data": "x.csv", "design": {"type": "custom"},
        "factors": {"a": {"lower": 0.0, "upper": 1.0}, "b": {"lower": 0.0, "upper": 1.0}},
        "responses": {n: {"target": 1.0, **({"label": lab} if lab else {})} for n, lab in zip(names, labels)},
        "scenarios": {"s": {"observables": list(names), "tolerance": 0.02}}})


@given(count=st.integers(1, 4), tolerance=st.sampled_from([0.005, 0.02, 0.15]),
       own=st.lists(st.sampled_from([None, 0.003, 0.04, 0.25]), min_size=4, max_size=4),
       labelled=st.lists(st.booleans(), min_size=4, max_size=4), brackets=st.booleans())
@settings(max_examples=80, deadline=None, derandomize=True)
def test_level2s_tolerance_in_words_quotes_each_observables_own_in_config_order(count, tolerance, own, labelled,
                                                                                 brackets):
    names = [f"r{k}" for k in (10, 2, 31, 4)][:count]
    labels = [f"L{k}" if flag else "" for k, flag in zip(range(count), labelled)]
    tolerances = {n: (tolerance if v is None else v) for n, v in zip(names, own)}
    level2 = {"tolerance": tolerance, "observables": names,
              "tolerances": dict(sorted(tolerances.items()))}  # JSON sorts its keys
    text = level2_within(level2, _spec(names, labels), brackets=brackets)
    if all(v == tolerance for v in tolerances.values()):
        assert level2_own_tolerances(level2) is None
        assert text == f"{100 * tolerance:g} %"
        return
    assert list(level2_own_tolerances(level2).items()) == list(tolerances.items())
    head = "their own tolerances (" if brackets else "their own tolerances: "
    assert text.startswith(head) and text.endswith(")" if brackets else "%")
    items = text[len(head):].rstrip(")").split(", ")
    assert len(items) == count
    for item, name, label in zip(items, names, labels):
        shown, value = re.fullmatch(r"(\S+) ([\d.]+) %", item).groups()
        assert shown == (label or name)
        assert np.isclose(float(value), 100 * tolerances[name], rtol=0, atol=0.051)
