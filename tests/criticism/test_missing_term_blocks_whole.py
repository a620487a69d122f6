"""The missing-term test of runs made in blocks is the partial F-test of the term given the quadratic and the
blocks: a cubic term planted in a 2-factor CCD whose runs fall into three blocks with shifted responses, each
catalogue entry's statistic and nominal p-value against statsmodels (nested least-squares fits with one column per
later block)."""

from __future__ import annotations

import numpy as np
import pytest
import statsmodels.api as sm

from demid.criticism import criticize
from demid.design import model_matrix, parse_term, quadratic_terms
from tests.generators import FACTORS, ccd_table


def test_a_missing_terms_test_on_blocked_runs_is_the_partial_f_test_given_the_blocks():
    table, _ = ccd_table(0, 2, "term", 3.0, term="mu_r^2:gamma")
    block = np.minimum((table["run"].to_numpy() - 1) * 3 // len(table), 2)
    table["y"] += 7.0 * block
    table["block"] = [f"wave {b + 1}" for b in block]
    result = criticize(table, FACTORS[2], "y", n_null=19)
    x_actual = table[FACTORS[2]].to_numpy(dtype=float)
    lo, hi = x_actual.min(axis=0), x_actual.max(axis=0)
    coded = (x_actual - (lo + hi) / 2) / ((hi - lo) / 2)
    onehot = (block[:, None] == np.arange(1, 3)[None, :]).astype(float)
    x = np.column_stack([model_matrix(coded, quadratic_terms(2)), onehot])
    y = table["y"].to_numpy()
    base = sm.OLS(y, x).fit()
    entries = [e for e in result.catalogue if e["cause"] == "missing_term" and e["p_nominal"] is not None]
    assert entries
    for e in entries:
        term = parse_term(e["aliases"][0], FACTORS[2])
        f, p, _ = sm.OLS(y, np.column_stack([x, model_matrix(coded, [term])])).fit().compare_f_test(base)
        assert e["statistic"] == pytest.approx(f, rel=1e-8)
        assert e["p_nominal"] == pytest.approx(p, rel=1e-8)
