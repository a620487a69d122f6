"""The published-values check (demid.published_values) section by section, on files that hold one section only,
each number at both ends of its possible range and just past them: the accepted ones pass, the others fail with the
key, the range in words and, for a fraction written in percent, the fraction it would be; and for_materials keeps
exactly the studied materials' entries."""

from __future__ import annotations

import re

import pytest

from demid.errors import InputError
from demid.published_values import check_published_values, for_materials, out_of_range

MATERIALS = {"m": {"responses": {"y": {}, "z": {}}, "scenarios": {"s": {}, "t": {}}, "factors": {"a": {}, "b": {}},
                   "pareto": {"error_of": "y"}}}


def _fails(content) -> str:
    with pytest.raises(InputError) as info:
        check_published_values(content, MATERIALS, "pub.yaml")
    return str(info.value)


# section, a builder of the file from one number, the possible range, whether a percentage hint applies
NUMBERS = [
    ("tolerances.m.s", lambda v: {"tolerances": {"m": {"s": v}}}, (0.0, 1.0), True),
    ("table2.m.y.r2", lambda v: {"table2": {"m": {"y": {"r2": v}}}}, (0.0, 1.0), True),
    ("table2.m.z.rmse", lambda v: {"table2": {"m": {"z": {"rmse": v}}}}, (0.0, None), False),
    ("table3.m.t.feasible_fraction_pct", lambda v: {"table3": {"m": {"t": {"feasible_fraction_pct": v}}}},
     (0.0, 100.0), False),
    ("table3.m.s.width.b", lambda v: {"table3": {"m": {"s": {"feasible_fraction_pct": 1, "width": {"b": v}}}}},
     (0.0, None), False),
    ("contractions (item 1).value", lambda v: {"contractions": [{"material": "m", "from": "s", "to": "t",
                                                                 "quantity": "fraction", "value": v}]},
     (-100.0, None), False),
    ("pareto.m.max_error", lambda v: {"pareto": {"m": {"max_error": v, "intervals": {"a": [0, 1]}}}}, (0.0, 1.0), True),
]


@pytest.mark.parametrize("key, build, bounds, percent", NUMBERS, ids=[n[0] for n in NUMBERS])
def test_each_number_is_accepted_at_its_ends_and_refused_past_them(key, build, bounds, percent):
    low, high = bounds
    for ok in [low, low + 0.5] + ([high] if high is not None else [1e6]):
        check_published_values(build(ok), MATERIALS, "pub.yaml")
    outside = [low - 0.25] + ([high + 0.25, 40.0, 100.0, 150.0] if high is not None else [])
    for value in outside:
        if high is not None and low <= value <= high:
            continue
        message = _fails(build(value))
        assert message.startswith(f"pub.yaml, key {key}: {value!r} is not a possible "), message
        if high is None:
            assert ("cannot be negative" if low == 0 else f"cannot be below {low:g}") in message
        else:
            assert f"it lies between {low:g} and {high:g}" in message
        hinted = percent and 1 < value <= 100
        assert ("written in percent?" in message) == hinted
        if hinted:
            assert message.endswith(f"{value:g} % is {value / 100:g}")


@pytest.mark.parametrize("value, low, high, percent", [(98.9, 0, 1, True), (1.0, 0, 1, True), (100.0, 0, 1, True),
                                                       (100.5, 0, 1, True), (1.5, 0, 1, False), (-3.0, 0, 1e9, True),
                                                       (-101.0, -100, float("inf"), False)])
def test_out_of_range_says_why_with_the_percent_hint_only_for_a_fraction_written_in_percent(value, low, high, percent):
    text = out_of_range(str(value), value, low, high, "thing", percent)
    if low <= value <= high:
        assert text == ""
        return
    hint = re.search(r"; written in percent\? (\S+) % is (\S+)$", text)
    assert (hint is not None) == (percent and 1 < value <= 100)
    if hint:
        assert float(hint.group(1)) == value and float(hint.group(2)) == pytest.approx(value / 100)


def test_a_file_with_any_one_section_alone_passes():
    sections = [{"source": "paper"}, {"targets": {"m": {"y": 1.0}}}, {"tolerances": {"m": {"s": 0.02}}},
                {"intervals": {"m": {"s": {"a": [0.1, 0.2]}}}}, {"search_domain": {"m": {"a": [0, 1]}}},
                {"scenario_sets": {"m": {"s": {"feasible_fraction_pct": 3}}}}, {"reference_points": {"m": {"a": 0.5}}},
                {"contractions": [{"material": "m", "from": "s", "to": "t", "quantity": "width", "factor": "a",
                                   "value": -50}]}, {}]
    for content in sections:
        check_published_values(content, MATERIALS, "pub.yaml")


def test_for_materials_keeps_the_studied_materials_and_the_source():
    content = {"source": "paper", "provenance": "typed", "targets": {"m": {"y": 1}, "other": {"y": 2}},
               "table3": {"other": {}}, "contractions": [{"material": "other"}, {"material": "m", "value": 1}]}
    kept = for_materials(content, ["m"])
    assert kept == {"source": "paper", "provenance": "typed", "targets": {"m": {"y": 1}}, "table3": {},
                    "contractions": [{"material": "m", "value": 1}]}


@pytest.mark.parametrize("content, key, words", [
    ({"targets": {"m": {"yy": 1}}}, "targets.m.yy", "'yy' is not a response of m; did you mean 'y'?"),
    ({"tolerances": {"m": {"q": 0.1}}}, "tolerances.m.q", "'q' is not a scenario of m (known: s, t)"),
    ({"intervals": {"m": {"s": {"b": [2, 1]}}}}, "intervals.m.s.b", "[2, 1] has its lower end above its upper end"),
    ({"search_domain": {"m": {"a": [1, 1]}}}, "search_domain.m.a",
     "[1, 1] has its lower end at its upper end; a search range needs lower < upper"),
    ({"scenario_sets": {"m": {"t": {"unresolved": ["a"]}}}}, "scenario_sets.m.t.unresolved",
     "'a' unresolved over its search range needs search_domain.m.a: [lower, upper]"),
    ({"contractions": [{"material": "m", "from": "s", "to": "t", "quantity": "fraction", "value": 1},
                       {"material": "m", "from": "s", "to": "u", "quantity": "fraction", "value": 1}]},
     "contractions (item 2).to", "'u' is not a scenario of m"),
    ({"contractions": [{"material": "m", "from": "s", "to": "t", "quantity": "fraction", "value": 1},
                       {"material": "m", "from": "s", "to": "t", "quantity": "width", "factor": "bb", "value": 1}]},
     "contractions (item 2).factor", "'bb' is not a factor of m; did you mean 'b'?"),
    ({"reference_points": {"m": {"a": 0.5, "bb": 2}}}, "reference_points.m.bb",
     "'bb' is not a factor of m; did you mean 'b'?"),
    ({"pareto": {"n": {"max_error": 0.1, "intervals": {}}}}, "", ""),
])
def test_a_slip_names_its_key_and_what_is_wrong(content, key, words):
    if not key:  # another study's material: not compared
        check_published_values(content, MATERIALS, "pub.yaml")
        return
    message = _fails(content)
    assert message.startswith(f"pub.yaml, key {key}: ") and words in message, message


def test_a_pareto_entry_needs_a_front_in_the_config():
    materials = {"m": {**MATERIALS["m"], "pareto": None}}
    with pytest.raises(InputError, match=r"key pareto\.m: the config computes no Pareto front for m"):
        check_published_values({"pareto": {"m": {"max_error": 0.1, "intervals": {}}}}, materials, "pub.yaml")


def test_a_list_where_a_list_is_due_asks_for_lower_and_upper_only_for_an_interval():
    assert _fails({"intervals": {"m": {"s": {"a": 0.5}}}}).endswith("key intervals.m.s.a: 0.5 should be a list, "
                                                                    "[lower, upper]")
    assert _fails({"contractions": 5}).endswith("key contractions: 5 should be a list")
    assert _fails({"scenario_sets": {"m": {"s": {"unresolved": "a"}}}}).endswith("'a' should be a list")


@pytest.mark.parametrize("slips, named", [
    ({"table2": {"m": {"y": {"r2": "high"}}}, "source": 5}, "source: 5 should be text"),
    ({"source": 5, "table2": {"m": {"y": {"r2": "high"}}}}, "source: 5 should be text"),
    ({"tolerances": {"m": {"s": "x"}}, "targets": {"m": {"y": "x"}}}, "targets.m.y: 'x' is not a number"),
    ({"table3": {"m": {"s": {"feasible_fraction_pct": 1, "width": {"b": "w"}}}}, "tolerances": {"m": {"t": "x"}}},
     "tolerances.m.t: 'x' is not a number"),
])
def test_of_several_slips_in_a_file_the_shallowest_is_named_then_the_first_by_key(slips, named):
    assert _fails(slips) == f"pub.yaml, key {named}"


def test_a_published_interval_may_be_a_single_point_but_a_search_range_may_not():
    check_published_values({"intervals": {"m": {"s": {"a": [0.5, 0.5], "b": ["2.0", "2.00"]}}}}, MATERIALS, "pub.yaml")
    check_published_values({"pareto": {"m": {"max_error": 0.1, "intervals": {"a": [3, 3]}}}}, MATERIALS, "pub.yaml")
    assert "lower end at its upper end" in _fails({"search_domain": {"m": {"b": [0.5, 0.5]}}})


def test_an_unknown_factor_of_an_interval_is_named_at_its_full_key():
    message = _fails({"intervals": {"m": {"t": {"a": [0, 1], "bb": [0, 1]}}}})
    assert message == "pub.yaml, key intervals.m.t.bb: 'bb' is not a factor of m; did you mean 'b'?"


def test_a_misspelt_name_is_suggested_when_it_is_the_only_one_known():
    materials = {"m": {"responses": {"angle": {}}, "scenarios": {"only": {}}, "factors": {"mu_r": {}}}}
    for content, key, words in [({"targets": {"m": {"angel": 30}}}, "targets.m.angel",
                                 "'angel' is not a response of m; did you mean 'angle'?"),
                                ({"reference_points": {"m": {"mu": 0.2}}}, "reference_points.m.mu",
                                 "'mu' is not a factor of m; did you mean 'mu_r'?"),
                                ({"tolerances": {"m": {"x": 0.1}}}, "tolerances.m.x",
                                 "'x' is not a scenario of m (known: only)")]:
        with pytest.raises(InputError) as info:
            check_published_values(content, materials, "pub.yaml")
        assert str(info.value) == f"pub.yaml, key {key}: {words}"


@pytest.mark.parametrize("content, named", [
    ({"pareto": {"m": {"intervals": {"a": [0, 1]}}}}, "pareto.m: 'max_error' is a required property"),
    ({"table3": {"m": {"s": {"width": {"a": 1}}}}}, "table3.m.s: 'feasible_fraction_pct' is a required property"),
    ({"table2": {"m": {"y": {}}}}, "table2.m.y: {} should be non-empty"),
])
def test_a_missing_entry_is_named_with_the_schema_s_words(content, named):
    assert _fails(content) == f"pub.yaml, key {named}"


def test_a_misspelt_material_of_a_contraction_is_named_at_its_item():
    materials = {"mortar": MATERIALS["m"]}
    content = {"contractions": [{"material": "mortar", "from": "s", "to": "t", "quantity": "fraction", "value": 1},
                                {"material": "mortr", "from": "s", "to": "t", "quantity": "fraction", "value": 1}]}
    with pytest.raises(InputError) as info:
        check_published_values(content, materials, "pub.yaml")
    assert str(info.value) == ("pub.yaml, key contractions (item 2).material: 'mortr' is not a material of the "
                               "config; did you mean 'mortar'?")
