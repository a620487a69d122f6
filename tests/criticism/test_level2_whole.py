"""Level 2 (criticism.level2.calibration_check) read whole over generated linear simulations: 1-2 factors on boxes
away from the origin, 1-4 observables with targets of either sign, own tolerances or none.  With linear responses
the minimax problems are linear programmes, solved here with scipy's linprog: the best point's largest weighted
error, feasibility, the error left without each observable and the bias it would need, the error left with a
shared relative bias; the extensions' table
(parameters, measurements, spare ones, notes) and every count the message quotes about them."""

from __future__ import annotations

import re

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy import optimize

from demid.criticism.level2 import calibration_check
from demid.design import quadratic_terms
from demid.sampling import Domain
from demid.surrogate import Surrogate


def _linear(name: str, factors: list[str], intercept: float, slopes) -> Surrogate:
    terms = quadratic_terms(len(factors))
    coef = np.zeros(len(terms))
    coef[0], coef[1:1 + len(factors)] = intercept, slopes
    return Surrogate(name, factors, terms, coef, np.zeros((len(terms), len(terms))), 0.0, 7)


def _smallest_bias_lp(a: np.ndarray, b: np.ndarray, w: np.ndarray, lo, hi, row: int) -> float:
    """min |a_row + b_row x| over the points x of the box where the other rows' largest weighted |error| is
    smallest (two linear programmes: that smallest value, then the least |error| of ``row`` under it)."""
    others = [j for j in range(len(a)) if j != row]
    best = _minimax_lp(a[others], b[others], w[others], lo, hi, shared=False)
    d = b.shape[1]
    rows, rhs = [], []
    for sign in (1.0, -1.0):
        for j in others:  # w_j |a_j + b_j x| <= best
            rows.append(np.concatenate([sign * w[j] * b[j], [0.0]]))
            rhs.append(best * (1 + 1e-9) + 1e-12 - sign * w[j] * a[j])
        rows.append(np.concatenate([sign * b[row], [-1.0]]))  # |a_row + b_row x| <= u
        rhs.append(-sign * a[row])
    res = optimize.linprog(np.concatenate([np.zeros(d), [1.0]]), A_ub=np.array(rows), b_ub=np.array(rhs),
                           bounds=list(zip(lo, hi)) + [(0, None)], method="highs")
    assert res.status == 0
    return float(res.fun)


def _minimax_lp(a: np.ndarray, b: np.ndarray, w: np.ndarray, lo, hi, shared: bool) -> float:
    """min over x in the box (and a shared bias delta) of max_k w_k |a_k + b_k x - delta|: a linear programme in
    (x, t, delta)."""
    k, d = b.shape
    extra = 1 if shared else 0
    cost = np.zeros(d + 1 + extra)
    cost[d] = 1.0
    rows, rhs = [], []
    for sign in (1.0, -1.0):
        for j in range(k):
            row = np.zeros(d + 1 + extra)
            row[:d], row[d] = sign * w[j] * b[j], -1.0
            if shared:
                row[d + 1] = -sign * w[j]
            rows.append(row)
            rhs.append(-sign * w[j] * a[j])
    bounds = list(zip(lo, hi)) + [(0, None)] + ([(None, None)] if shared else [])
    res = optimize.linprog(cost, A_ub=np.array(rows), b_ub=np.array(rhs), bounds=bounds, method="highs")
    assert res.status == 0
    return float(res.fun)


@st.composite
def _studies(draw):
    d, k = draw(st.integers(1, 2)), draw(st.integers(1, 4))
    rng = np.random.default_rng(draw(st.integers(0, 10 ** 6)))
    factors = ["a", "b"][:d]
    lo = rng.uniform(-5, 5, d)
    hi = lo + rng.uniform(0.5, 4, d)
    names = [f"y{j}" for j in range(k)]
    slopes = rng.normal(size=(k, d)) * draw(st.sampled_from([1.0, 100.0]))
    intercepts = rng.normal(size=k) * 5 + 20 * rng.choice([-1, 1], size=k)
    mid = intercepts + slopes @ ((lo + hi) / 2)
    targets = mid * rng.uniform(0.8, 1.25, k)  # the sign of the response at mid-box: negative ones too
    own = draw(st.sampled_from([None, "some"]))
    tolerances = None if own is None else {names[0]: 0.02, names[-1]: 0.08}
    return factors, lo, hi, names, slopes, intercepts, targets, tolerances


@given(study=_studies(), tolerance=st.sampled_from([0.01, 0.05]))
@settings(max_examples=10, deadline=None, derandomize=True)
def test_level_2s_errors_extensions_and_counts_against_linear_programmes(study, tolerance):
    factors, lo, hi, names, slopes, intercepts, targets, tolerances = study
    d, k = len(factors), len(names)
    surrogates = {o: _linear(o, factors, c, g) for o, c, g in zip(names, intercepts, slopes)}
    domain = Domain(tuple(factors), tuple(lo), tuple(hi), (False,) * d)
    result = calibration_check(surrogates, domain, dict(zip(names, targets)), tolerance, 11,
                               tolerances=tolerances)
    scale = np.abs(targets)
    a, b = (intercepts - targets) / scale, slopes / scale[:, None]
    own = np.array([(tolerances or {}).get(o, tolerance) for o in names])
    w = tolerance / own
    best = _minimax_lp(a, b, w, lo, hi, shared=False)
    assert result.best_max_error == pytest.approx(best, rel=1e-5, abs=1e-7)
    assert result.feasible == (best <= tolerance)
    x = np.array([result.best_point[f] for f in factors])
    errors = a + b @ x
    assert [result.best_errors[o] for o in names] == pytest.approx(errors, rel=1e-9, abs=1e-12)
    assert result.best_max_error == pytest.approx(float(np.max(w * np.abs(errors))), rel=1e-9)
    assert result.shared_bias["max_error"] == pytest.approx(_minimax_lp(a, b, w, lo, hi, shared=True),
                                                            rel=1e-5, abs=1e-7)
    without = {}
    for o in result.without:
        others = [i for i in range(k) if names[i] != o]
        without[o] = _minimax_lp(a[others], b[others], w[others], lo, hi, False)
        assert result.without[o] == pytest.approx(without[o], rel=1e-5, abs=1e-7)
        implied = 0.0 if result.feasible else _smallest_bias_lp(a, b, w, lo, hi, names.index(o))
        assert abs(result.implied_bias[o]) == pytest.approx(implied, rel=1e-4, abs=1e-6)
    assert sorted(result.without) == (sorted(names) if k > 1 else [])
    if result.feasible:
        assert (result.bottleneck, result.bias_candidates, result.biased_observable) == (None, [], None)
    elif without and all(abs(v - tolerance) > 1e-5 * tolerance for v in without.values()):
        # the observable whose removal leaves the least error (near-ties: the smaller bias), and those whose bias
        # alone would meet the rest, unique or not
        assert without[result.bottleneck] <= min(without.values()) + 1e-3 * tolerance
        candidates = [o for o in names if without[o] <= tolerance]
        assert result.bias_candidates == candidates
        assert result.biased_observable == (candidates[0] if len(candidates) == 1 else None)
    _check_extensions(result, d, k)


def _check_extensions(result, d: int, k: int) -> None:
    """The extensions' rows: parameters, spare measurements and their notes, and the message's counts."""
    rows = {row["model"]: row for row in result.extensions}
    expected = {"simulation as calibrated (no discrepancy)": d, "shared relative bias on all observables": d + 1,
                "bias on every observable": d + k}
    if result.bottleneck is not None and result.without:
        expected[f"bias on {result.bottleneck}"] = d + 1
    assert {m: row["n_params"] for m, row in rows.items()} == expected
    errors = {"simulation as calibrated (no discrepancy)": result.best_max_error, "bias on every observable": 0.0,
              "shared relative bias on all observables": result.shared_bias["max_error"]}
    if result.bottleneck is not None and result.without:
        errors[f"bias on {result.bottleneck}"] = result.without[result.bottleneck]
    assert {m: row["max_error"] for m, row in rows.items()} == pytest.approx(errors, rel=1e-12, abs=1e-15)
    for row in rows.values():
        spare = k - row["n_params"]
        assert (row["n_measurements"], row["spare_measurements"]) == (k, spare)
        assert row["note"].startswith("testable: %d spare" % spare if spare > 0 else
                                      "saturated" if spare == 0 else "not identifiable")
    message = result.message
    if result.feasible:
        assert "A shared relative bias" not in message
        return
    spare = k - d - 1
    said = re.search(r"(\d+) spare measurements? remains? to test it\.", message)
    assert (int(said.group(1)) if said else None) == (spare if spare > 0 else None)
    assert ("it uses the last spare measurement, so its fit cannot be taken as evidence of a bias" in message) == \
        (spare == 0)
    assert ("a shared relative bias on the targets is not identifiable" in message) == (spare < 0)
    unknowns = re.search(r"A bias on every observable \((\d+) unknowns for (\d+) measurements?\)", message)
    assert (int(unknowns.group(1)), int(unknowns.group(2))) == (d + k, k)
    if spare >= 0:
        quoted = re.search(r"A shared relative bias of ([+-][\d.]+) % on all targets", message)
        assert float(quoted.group(1)) == pytest.approx(100 * result.shared_bias["delta"], abs=0.005 + 1e-9)


def test_a_target_in_another_unit_stops_the_best_points_bounds_from_being_followed():
    """Two rising responses whose targets lie past the upper bound: the best point sits on it and level 2 advises
    widening; once either target is flagged implausible (far from every simulated value), where the best point
    sits says nothing and no widening is advised, whichever of the two it is."""
    surrogates = {"y0": _linear("y0", ["a"], 10.0, [2.0]), "y1": _linear("y1", ["a"], 5.0, [1.0])}
    domain = Domain(("a",), (0.0,), (1.0,), (False,))
    targets = {"y0": 12.4, "y1": 6.2}
    plain = calibration_check(surrogates, domain, targets, 0.01, 11)
    assert not plain.feasible and plain.best_point["a"] == pytest.approx(1.0)
    assert plain.widen == {"a": ["upper"]} and "Widen the range of a" in plain.message
    for flagged in (("y0",), ("y1",), ("y0", "y1")):
        result = calibration_check(surrogates, domain, targets, 0.01, 11, implausible=flagged)
        assert result.widen == {} and "Widen the range" not in result.message and result.reach == []
