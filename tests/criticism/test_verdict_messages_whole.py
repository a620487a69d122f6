"""The verdict's rules and sentences over generated findings: the strongest rival against a scan written in the
test, a run's other reading at and inside the Bayes-factor bounds, every number the unexplained, ambiguous and
confirming sentences quote parsed back, and the one-run rule at its p threshold."""
from __future__ import annotations

import math
import re
import types

import numpy as np
import pytest
from hypothesis import given, settings, strategies as st

from demid.criticism import verdict as V
from demid.criticism.catalogue import Hypothesis
from demid.criticism.discrimination import AMBIGUOUS_AICC
from demid.criticism.one_run import Deletion

KIND = {"outlier": "one run", "factor_level": "one run", "drift": "run order", "step": "run order"}
CAUSES = ["missing_term", "response_transform", "heteroscedasticity", "drift", "step", "outlier", "factor_level",
          "lack_of_fit"]


def _rival_by_scan(named, hypotheses):
    """The most significant test of another kind that beats the named kind's best p, unless that is below 1e-4
    or the named cause is a transform."""
    if named.cause == "response_transform":
        return None
    kind = KIND.get(named.cause, named.cause)
    own = min(g.logp for g in hypotheses if KIND.get(g.cause, g.cause) == kind)
    if math.exp(own) <= 1e-4:
        return None
    best = None
    for g in hypotheses:
        if KIND.get(g.cause, g.cause) != kind and g.logp < own and (best is None or g.logp < best.logp):
            best = g
    return best


@settings(max_examples=40, deadline=None, derandomize=True)
@given(causes=st.lists(st.sampled_from(CAUSES), min_size=1, max_size=6),
       logps=st.lists(st.floats(-15.0, -0.01), min_size=6, max_size=6), which=st.integers(0, 5))
def test_the_strongest_rival_is_the_most_significant_test_of_another_kind(causes, logps, which):
    hyps = [Hypothesis(c, i, logp=lp) for i, (c, lp) in enumerate(zip(causes, logps))]
    named = hyps[which % len(hyps)]
    assert V.strongest_rival(named, hyps) is _rival_by_scan(named, hyps)


def test_a_named_cause_at_the_overwhelming_p_has_no_rival_and_just_above_it_has():
    edge = math.log(V.OVERWHELMING_P)
    for own, has_rival in [(edge, False), (edge - 1e-9, False), (edge + 1e-9, True)]:
        named = Hypothesis("missing_term", None, logp=own)
        rival = Hypothesis("drift", "run", logp=own - 1.0)
        assert (V.strongest_rival(named, [named, rival]) is rival) == has_rival
    # a rival exactly as significant is not stronger
    named = Hypothesis("outlier", 3, logp=-3.0)
    assert V.strongest_rival(named, [named, Hypothesis("drift", "run", logp=-3.0)]) is None
    # a slip of another run is the same kind as an outlier: no rival
    assert V.strongest_rival(named, [named, Hypothesis("factor_level", None, logp=-5.0)]) is None


@pytest.mark.parametrize("factor, other", [(20.0, None), (19.999, "outlier"), (1.0, "outlier"),
                                           (0.0501, "outlier"), (0.05, None), (0.0, None)])
def test_a_slips_other_reading_inside_the_bayes_factor_bounds(factor, other):
    slip = Hypothesis("factor_level", types.SimpleNamespace(row=4), info={"bayes_factor": factor})
    assert V.other_reading_of_the_run(slip, [slip]) == other
    outlier = Hypothesis("outlier", 4)
    assert V.other_reading_of_the_run(outlier, [outlier, slip]) == (None if other is None else "factor_level")
    # a slip of another run is no reading of this one
    assert V.other_reading_of_the_run(Hypothesis("outlier", 5), [slip]) is None
    assert V.other_reading_of_the_run(Hypothesis("drift", "run"), [slip]) is None


def _entries(draw_p, n):
    return [{"cause": c, "detail": d, "p_family": p} for c, d, p in zip(
        ["lack_of_fit", "outlier", "missing_term", "drift"][:n], [None, "7", "a^3", "run"][:n], draw_p[:n])]


@settings(max_examples=20, deadline=None, derandomize=True)
@given(ps=st.lists(st.floats(1e-6, 0.2), min_size=4, max_size=4), n_fired=st.integers(1, 3),
       n_remaining=st.integers(0, 3), alpha=st.sampled_from([0.01, 0.05, 0.1]),
       kind=st.sampled_from(["none", "one_run", "rival"]), p_without=st.floats(0.001, 0.9),
       p_nominal=st.floats(1e-5, 0.04))
def test_unexplained_evidence_quotes_its_numbers(ps, n_fired, n_remaining, alpha, kind, p_without, p_nominal):
    fired = _entries(ps, n_fired)
    remaining = [{**e, "p_family": p / 3} for e, p in zip(_entries(ps[::-1], n_remaining), ps[::-1])]
    tried = [{"cause": "missing_term", "detail": "a^3"}] if remaining else []
    candidate = None
    if kind == "one_run":
        candidate = {"cause": "heteroscedasticity", "detail": "a", "one_run": {"run": "12", "p_without": p_without}}
    elif kind == "rival":
        candidate = {"cause": "outlier", "detail": "3", "rival": {"cause": "drift", "detail": "run",
                                                                  "p_nominal": p_nominal}}
    out = V.unexplained_evidence("y", fired, tried, remaining, alpha, candidate)
    text = out["message"]
    assert out["p_value"] == min(e["p_family"] for e in fired + remaining)
    assert out["detail"] == ";".join(dict.fromkeys(e["cause"] for e in fired))
    assert float(re.search(r"family-wise ([\d.]+) % level", text).group(1)) == pytest.approx(100 * alpha)
    quoted = [float(v) for v in re.findall(r"family-wise p = ([\d.e+-]+)\)", text)]
    assert quoted == pytest.approx([e["p_family"] for e in fired + remaining], rel=1e-2)
    if kind == "one_run":
        assert float(re.search(r"nominal p = ([\d.e+-]+)\)", text).group(1)) == pytest.approx(p_without, rel=0.05)
        assert "rests on run 12 alone" in text
    elif kind == "rival":
        assert float(re.search(r"nominal p = ([\d.e+-]+)\)", text).group(1)) == pytest.approx(p_nominal, rel=0.05)
    else:
        assert "nominal p" not in text
    assert ("leaves misfit behind" in text) == bool(tried)


@settings(max_examples=20, deadline=None, derandomize=True)
@given(deltas=st.lists(st.one_of(st.none(), st.floats(0.0, 5.0)), min_size=2, max_size=4),
       points=st.lists(st.tuples(st.sampled_from([-1.0, 0.0, 0.5, 2.0]), st.sampled_from([1.0, 6.0])),
                       min_size=0, max_size=5))
def test_the_ambiguous_message_quotes_the_spread_the_lead_and_the_runs(deltas, points):
    candidates = [{"cause": c, "detail": d, "delta_aicc": x} for c, d, x in
                  zip(["missing_term", "outlier", "drift", "heteroscedasticity"], ["a^3", "4", "run", "b"], deltas)]
    runs = [{"a": a, "b": b, "purpose": "decide"} for a, b in points]
    text = V.ambiguous_message("y", candidates, runs)
    spread = max(x or 0.0 for x in deltas)
    assert float(re.search(r"lie within ([\d.]+) of each other", text).group(1)) == pytest.approx(spread, abs=0.051)
    assert float(re.search(r"a lead of less than ([\d.]+)", text).group(1)) == AMBIGUOUS_AICC
    assert int(re.search(r"ratio below (\d+):1", text).group(1)) == round(math.exp(AMBIGUOUS_AICC / 2))
    if runs:
        n = int(re.search(r" (\d+) more runs? made after these", text).group(1))
        assert n == len(runs)
        listed = re.search(r"made after these, at (.*), would decide", text).group(1).split("; ")
        counts = {}
        for a, b in points:
            counts[f"(a={a:g}, b={b:g})"] = counts.get(f"(a={a:g}, b={b:g})", 0) + 1
        assert listed == [p + (f" ×{c}" if c > 1 else "") for p, c in counts.items()]
    else:
        assert "would decide" not in text


@pytest.mark.parametrize("n_runs, n_rivals", [(1, 1), (2, 1), (3, 2), (1, 3)])
def test_the_confirming_message_counts_runs_and_names_rivals(n_runs, n_rivals):
    labels = ["cubic a", "outlier 3", "drift", "scatter b"][:n_rivals + 1]
    runs = [{"a": 0.5 * i, "expected": {label: 1.0 for label in labels}} for i in range(n_runs)]
    text = V.confirming_message(runs)
    assert re.search(r"every rival \((.*?): fitted", text).group(1) == ", ".join(labels[1:])
    assert int(re.search(r": (\d+) more runs?", text).group(1)) == n_runs
    assert ("more runs made" in text) == (n_runs > 1)
    assert f"where {labels[0]} and {'they' if n_rivals > 1 else 'it'} predict" in text


@pytest.mark.parametrize("p_without, named", [(0.05, False), (0.0501, True), (0.2, True), (0.01, False)])
def test_unequal_scatter_rests_on_one_run_above_its_p(monkeypatch, p_without, named):
    monkeypatch.setattr(V, "worst_deletion", lambda data, model, h: Deletion(3, p_without))
    got = V.rests_on_one_run(None, None, Hypothesis("heteroscedasticity", "a"))
    assert (got == Deletion(3, p_without)) if named else got is None
    assert V.rests_on_one_run(None, None, Hypothesis("missing_term", None)) is None


@pytest.mark.parametrize("x, text", [(19_668.4, "19,668"), (-25_000.0, "-25,000"), (10_000.0, "10,000")])
def test_plain_number_writes_large_numbers_with_separators(x, text):
    assert V.plain_number(x) == text
    assert "e" not in V.plain_number(9_999.0)


def test_the_detectable_departure_has_the_power_it_claims():
    from scipy import stats
    for df_resid, n_tests, alpha in [(4, 3, 0.05), (10, 8, 0.05), (30, 12, 0.01)]:
        k = V.detectable_departure(df_resid, n_tests, alpha)
        crit = stats.f.ppf(1 - alpha / n_tests, 1, df_resid - 1)
        assert stats.ncf.sf(crit, 1, df_resid - 1, k * k) == pytest.approx(V.POWER, abs=1e-6)
    assert V.detectable_departure(2, 3, 0.05) is None and V.detectable_departure(3, 3, 0.05) is not None
    assert V.detectable_departure(10, 0, 0.05) is None
