"""Whether the run column is the performed order (criticism.run_order), read whole over generated tables: 3-20
runs, 1-3 responses, failed runs (NaN), a constant response, run columns sorted by a response, against it, or
shuffled.  The response the run column follows and its rank correlation against scipy's Spearman coefficient
taken over the responses here, with every field of the JSON record and the quoted correlation; a design listed in a
standard order (2-3 factors, either level direction, centre runs first or last, printed backwards) at
correlation 1, and a shuffle of it tested for drift."""

from __future__ import annotations

import re

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy import stats

from demid.criticism.run_order import SORTED_CORRELATION, assess_run_order, standard_order_correlation
from demid.design import ccd_points


def _expected_follow(runs: np.ndarray, responses: dict[str, np.ndarray]):
    """(name, rho) of the response with the largest |Spearman rho| over its finite runs, at least the threshold;
    responses with fewer than four finite runs or one value are not read."""
    best = None
    for name, y in responses.items():
        ok = np.isfinite(y)
        if ok.sum() < 4 or len(set(y[ok])) == 1:
            continue
        rho = stats.spearmanr(runs[ok], y[ok]).statistic
        if abs(rho) >= SORTED_CORRELATION and (best is None or abs(rho) > abs(best[1])):
            best = (name, float(rho))
    return best


@st.composite
def _tables(draw):
    n = draw(st.integers(3, 20))
    seed = draw(st.integers(0, 10 ** 6))
    rng = np.random.default_rng(seed)
    runs = rng.permutation(n).astype(float) + 1
    responses = {}
    for j in range(draw(st.integers(1, 3))):
        kind = draw(st.sampled_from(["sorted", "against", "shuffled", "noisy", "constant"]))
        base = {"sorted": runs, "against": -runs, "shuffled": rng.permutation(runs),
                "noisy": runs + rng.normal(scale=0.15 * n, size=n), "constant": np.full(n, 3.0)}[kind]
        y = 10 + 0.5 * base * draw(st.sampled_from([1.0, 1e-4, 1e4]))
        failed = draw(st.integers(0, max(0, n - 2)))
        y[rng.choice(n, failed, replace=False)] = np.nan
        responses[f"y{j}"] = y
    return runs, responses


@given(table=_tables())
@settings(max_examples=60, deadline=None, derandomize=True)
def test_the_response_the_run_column_follows_and_its_correlation(table):
    runs, responses = table
    coded = np.random.default_rng(len(runs)).uniform(-1, 1, (len(runs), 2))  # no standard order
    out = assess_run_order(runs, coded, responses)
    expected = _expected_follow(runs, responses)
    record = out.to_json()
    if expected is None:
        assert out.reason != "sorted_by_response" and out.response is None
        return
    name, rho = expected
    assert (out.drift_tested, out.reason, out.response) == (False, "sorted_by_response", name)
    assert out.correlation == pytest.approx(rho, abs=1e-12)
    assert record == {"declared": "performed", "drift_tested": False, "reason": "sorted_by_response",
                      "rank_correlation": round(rho, 6), "follows_response": name, "message": out.message}
    quoted = re.search(rf"Spearman rank correlation of run and {name} ([+-]\d\.\d\d)\)", out.message)
    assert float(quoted.group(1)) == round(rho, 2) and out.message.startswith("Drift was not tested: ")


@pytest.mark.parametrize("k", [2, 3])
@pytest.mark.parametrize("centre_first", [False, True])
@pytest.mark.parametrize("direction", [1.0, -1.0])
def test_a_design_in_standard_order_is_recognised_and_a_shuffle_of_it_is_not(k, centre_first, direction):
    coded = direction * ccd_points(k, 1.5, 3)  # factorial points in Yates order, axial points, centre runs
    count = np.sum(np.abs(coded) > 1e-9, axis=1)
    order = np.lexsort((np.arange(len(coded)), -count if not centre_first else np.where(count == 0, -99, -count)))
    listed = coded[order]
    runs = np.arange(1, len(listed) + 1, dtype=float)
    assert standard_order_correlation(runs, listed) == pytest.approx(1.0, abs=1e-12)
    assert standard_order_correlation(runs[::-1], listed) == pytest.approx(1.0, abs=1e-12)  # printed backwards
    out = assess_run_order(runs, listed, {"y": np.zeros(len(runs))})
    assert (out.drift_tested, out.reason, out.correlation) == (False, "standard_order", pytest.approx(1.0))
    assert re.search(r"rank correlation (\d\.\d\d):", out.message).group(1) == "1.00"
    shuffled = np.random.default_rng(k).permutation(runs)
    rho = standard_order_correlation(shuffled, listed)
    assert 0.0 <= rho < 0.95
    tested = assess_run_order(shuffled, listed, {"y": np.zeros(len(runs))})
    assert (tested.drift_tested, tested.reason, tested.message) == (True, "", "")
    unknown = assess_run_order(shuffled, listed, {"y": np.zeros(len(runs))}, declared="unknown")
    assert (unknown.drift_tested, unknown.reason) == (False, "declared_unknown")
    with pytest.raises(ValueError):
        assess_run_order(shuffled, listed, {}, declared="random")


@pytest.mark.parametrize("k, columns", [(3, [2, 0, 1]), (4, [1, 3, 0, 2]), (5, [4, 3, 2, 1, 0])])
def test_a_standard_order_is_recognised_whichever_factor_the_table_lists_first(k, columns):
    """Up to four factors every naming of them is tried; beyond, the column order and its reverse."""
    coded = ccd_points(k, 1.5, 2)
    count = np.sum(np.abs(coded) > 1e-9, axis=1)
    listed = coded[np.lexsort((np.arange(len(coded)), -count))][:, columns]
    runs = np.arange(1, len(listed) + 1, dtype=float)
    assert standard_order_correlation(runs, listed) == pytest.approx(1.0, abs=1e-12)
