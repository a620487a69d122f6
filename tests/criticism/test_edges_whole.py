"""Level 2's edges (criticism.edges) read whole over generated domains: 1-3 factors, linear or log, ranges away
from zero, runs covering all or part of each range, reference points inside, on the edge of or beyond the runs'
range and the search range, physical limits on either side.  Which factors and sides are warned of, against the
runs' range computed here (in search units, with the documented 1e-3 of the range), every number the warnings
quote, and the widen sentences' sides and limits."""

from __future__ import annotations

import re

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st

from demid.criticism.edges import extrapolation_warnings, movable_sides, touching, widen_advice
from demid.criticism.models import short_number
from demid.sampling.domain import Domain

_TOL = 1e-3  # of the search range


@st.composite
def _studies(draw):
    d = draw(st.integers(1, 3))
    rng = np.random.default_rng(draw(st.integers(0, 10 ** 6)))
    factors = ["a", "b", "c"][:d]
    log = tuple(draw(st.booleans()) for _ in range(d))
    lo_s = rng.uniform(-3, 3, d)
    hi_s = lo_s + rng.uniform(0.5, 2, d)
    # the runs cover the range, or fall short of either end by 0.05 %-20 % of it (under and over the 0.1 %)
    short = [(draw(st.sampled_from([0.0, 0.0005, 0.002, 0.2])), draw(st.sampled_from([0.0, 0.0005, 0.002, 0.2])))
             for _ in range(d)]
    n = draw(st.integers(2, 8))
    runs_s = np.empty((n, d))
    for i, (a, b) in enumerate(short):
        span = hi_s[i] - lo_s[i]
        col = rng.uniform(lo_s[i] + a * span, hi_s[i] - b * span, n)
        col[0], col[-1] = lo_s[i] + a * span, hi_s[i] - b * span
        runs_s[:, i] = col
    where = draw(st.sampled_from(["inside", "on a bound", "beyond runs", "beyond range"]))
    ref_s = runs_s.mean(axis=0)
    if where == "on a bound":  # on the search range's end: inside it, outside the runs' range if they fall short
        j = draw(st.integers(0, d - 1))
        ref_s[j] = draw(st.sampled_from([lo_s[j], hi_s[j]]))
    elif where != "inside":
        j = draw(st.integers(0, d - 1))
        ref_s[j] = (lo_s[j] - 0.1 * (hi_s[j] - lo_s[j])) if where == "beyond range" else runs_s[:, j].min() - 0.01 * (
            hi_s[j] - lo_s[j]) if short[j][0] > 0.01 else ref_s[j]

    def actual(s, i):
        return 10.0 ** s if log[i] else s

    domain = Domain(tuple(factors), tuple(actual(lo_s[i], i) for i in range(d)),
                    tuple(actual(hi_s[i], i) for i in range(d)), log)
    runs = np.column_stack([actual(runs_s[:, i], i) for i in range(d)])
    reference = {f: float(actual(ref_s[i], i)) for i, f in enumerate(factors)}
    return domain, runs, reference, lo_s, hi_s, runs_s, ref_s


@given(study=_studies())
@settings(max_examples=50, deadline=None, derandomize=True)
def test_extrapolation_warnings_name_the_sides_and_numbers_of_the_runs_range(study):
    domain, runs, reference, lo_s, hi_s, runs_s, ref_s = study
    out = extrapolation_warnings(domain, runs, reference)
    span = hi_s - lo_s
    z = (runs_s - lo_s) / span
    u = (ref_s - lo_s) / span
    ranges = [w for w in out if w.startswith("Extrapolation: the search range")]
    expected = []
    for i, f in enumerate(domain.factors):
        sides = [s for s, beyond in (("lower", z[:, i].min() > _TOL), ("upper", z[:, i].max() < 1 - _TOL)) if beyond]
        if sides:
            lo_run, hi_run = runs[:, i].min(), runs[:, i].max()
            expected.append(f"Extrapolation: the search range of {f}, {short_number(domain.lower[i])} to "
                            f"{short_number(domain.upper[i])}, reaches beyond the runs, which cover "
                            f"{short_number(lo_run)} to {short_number(hi_run)}; predictions beyond them are the "
                            f"quadratic's extrapolation, not backed by any simulation. Narrow the range to the runs, "
                            f"or simulate runs out to the {' and '.join(sides)} bound.")
    assert ranges == expected
    beyond_range = [f for i, f in enumerate(domain.factors) if u[i] < -_TOL or u[i] > 1 + _TOL]
    said = [w for w in out if w.startswith("The reference point lies outside the search range")]
    assert len(said) == (1 if beyond_range else 0)
    if said:
        named = re.findall(r"(\w) = (\S+) \(search range (\S+) to ([^\s)]+)\)", said[0])
        assert [(f, v, lo, hi) for f, v, lo, hi in named] == [
            (f, short_number(reference[f]), short_number(domain.lower[i]), short_number(domain.upper[i]))
            for i, f in enumerate(domain.factors) if f in beyond_range]
    beyond_runs = [f for i, f in enumerate(domain.factors)
                   if u[i] < z[:, i].min() - _TOL or u[i] > z[:, i].max() + _TOL]
    outside = [w for w in out if w.startswith("Extrapolation: the reference point lies outside the range of the runs")]
    assert len(outside) == (1 if beyond_runs else 0)
    if outside:
        named = re.findall(r"(\w) = (\S+) \(runs: (\S+) to ([^\s)]+)\)", outside[0])
        assert named == [(f, short_number(reference[f]), short_number(runs[:, i].min()),
                          short_number(runs[:, i].max()))
                         for i, f in enumerate(domain.factors) if f in beyond_runs]
    assert extrapolation_warnings(domain, None, reference) == [] == extrapolation_warnings(domain, runs[:0], None)


@given(lower_limit=st.sampled_from([None, "at", "below"]), upper_limit=st.sampled_from([None, "at", "above"]),
       best=st.sampled_from(["none", "lower", "upper", "both"]), aset=st.sampled_from(["none", "lower", "upper", "both"]))
@settings(max_examples=40, deadline=None, derandomize=True)
def test_widen_advice_names_the_movable_sides_and_their_limits(lower_limit, upper_limit, best, aset):
    lo, hi = 2.0, 7.5
    limits = ({"at": lo, "below": 0.5, None: None}[lower_limit], {"at": hi, "above": 12.0, None: None}[upper_limit])
    domain = Domain(("a", "b"), (lo, 0.0), (hi, 1.0), (False, False), (limits, (None, None)))
    best_touch, set_touch = touching({"a": best, "b": "none"}), touching({"a": aset, "b": "none"})
    fixed = {s for s, kind in (("lower", lower_limit), ("upper", upper_limit)) if kind == "at"}
    expect_best = tuple(s for s in best_touch.get("a", ()) if s not in fixed)
    expect_set = tuple(s for s in set_touch.get("a", ()) if s not in fixed)
    assert movable_sides(domain, best_touch).get("a", ()) == expect_best
    out = widen_advice(domain, best_touch, set_touch)
    sides = [s for s in ("lower", "upper") if s in expect_best or s in expect_set]
    if not sides:
        assert out == []
        return
    (sentence,) = out
    assert sentence.startswith("Widen the range of a: ")
    assert (f"the best point lies on its {' and '.join(expect_best)} bound" in sentence) == bool(expect_best)
    assert (f"the admissible set reaches its {' and '.join(expect_set)} bound" in sentence) == bool(expect_set)
    parts = []
    for s in sides:
        limit = limits[0] if s == "lower" else limits[1]
        parts.append(f"{'below' if s == 'lower' else 'above'} {short_number(lo if s == 'lower' else hi)}"
                     + (f" ({'down' if s == 'lower' else 'up'} to its physical limit {short_number(limit)})"
                        if limit is not None else ""))
    assert sentence.endswith(f"Simulate runs {' and '.join(parts)} and search there.")
