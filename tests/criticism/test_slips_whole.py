"""Every factor-level slip candidate can be the one found (criticism.slips.slip_ratios): responses built so that
moving one run's factor value, the first candidate, the last, and others between, fits them exactly, on 2-3
factors and a log-scaled factor, all candidates at once or a few at a time; the best ratio and the candidate named
against the brute-force refits of tests/criticism/test_slips_brute_force.py."""

from __future__ import annotations

import numpy as np
import pytest

from demid.criticism import slips
from demid.criticism.slips import slip_candidates, slip_ratios
from demid.design import LEVERAGE_UNPREDICTABLE
from tests.criticism.test_slips_brute_force import _model, _ratio_by_refit


@pytest.mark.parametrize("seed,k,n,log_first", [(11, 2, 20, False), (12, 3, 30, True)])
@pytest.mark.parametrize("cells", [None, 5])
def test_the_slip_that_fits_a_response_exactly_is_found_first_last_or_between(seed, k, n, log_first, cells,
                                                                             monkeypatch):
    data, m = _model(seed, k, n, log_first)
    cands = slip_candidates(data, m)
    rows = slips.moved_rows(m, cands)
    pos_of = {int(r): i for i, r in enumerate(np.flatnonzero(m.keep))}
    judged = [c for c, cand in enumerate(cands) if m.hat[pos_of[cand.row]] < LEVERAGE_UNPREDICTABLE]
    planted = sorted({judged[0], judged[1], judged[len(judged) // 2], judged[-1]})
    rng = np.random.default_rng(seed)
    columns = []
    for c in planted:  # the table as it would be had candidate c's moved value been recorded
        x = m.x.copy()
        x[pos_of[cands[c].row]] = rows[c]
        columns.append(x @ rng.normal(size=x.shape[1]) + 1e-3 * rng.standard_normal(len(x)))
    y = np.column_stack(columns)
    if cells is not None:
        monkeypatch.setattr(slips, "SLIP_CELLS", cells)
        monkeypatch.setattr(slips, "SLIP_MIN_CANDIDATES", 1)
    best, arg = slip_ratios(m, cands, y)
    brute = _ratio_by_refit(m, cands, y)
    np.testing.assert_allclose(best, brute.max(axis=0), rtol=1e-7)
    for b, c in enumerate(planted):
        top = np.flatnonzero(brute[:, b] >= brute[:, b].max() * (1 - 1e-9))
        assert arg[b] == top[0] and best[b] > 100  # the first candidate reaching the largest ratio
        # the planted slip, or one that moves the same run's value to the same place
        assert cands[arg[b]].row == cands[c].row
