"""The factor-level slips against a brute force written here: every candidate (run x factor x decimal slip)
found by a loop over runs, factors and slips, and each candidate's SSE ratio from a least-squares refit of the
table with that run moved (one fit per candidate), on 2-3 factors, a log-scaled factor, several seeds and
response columns; the same answer whatever the number of candidates held at once."""

from __future__ import annotations

import numpy as np
import pandas as pd
import pytest

from demid.criticism import slips
from demid.criticism.level1 import prepare_data
from demid.criticism.models import Model, ModelForm
from demid.criticism.slips import slip_candidates, slip_ratios
from demid.design import LEVERAGE_UNPREDICTABLE


def _table(seed: int, k: int, n: int, log_first: bool) -> tuple[pd.DataFrame, list[str], tuple[str, ...]]:
    rng = np.random.default_rng(seed)
    names = [f"f{j}" for j in range(k)]
    u = rng.uniform(-1, 1, (n, k))
    actual = 2.0 + 1.5 * u  # positive levels between 0.5 and 3.5
    if log_first:
        actual[:, 0] = 10.0 ** (u[:, 0] - 2.0)  # 0.001 .. 0.1, log-spaced
    y = 10 + u @ rng.uniform(-2, 2, k) + 0.4 * u[:, 0] ** 2 + 0.05 * rng.standard_normal(n)
    frame = pd.DataFrame(actual, columns=names)
    frame.insert(0, "run", np.arange(1, n + 1))
    frame["y"] = y
    return frame, names, (names[0],) if log_first else ()


def _model(seed, k, n, log_first):
    table, names, logs = _table(seed, k, n, log_first)
    data, _ = prepare_data(table, names, "y", 1.0, logs, None)
    return data, Model(data, ModelForm())


def _candidates_by_loop(data, m):
    """Run by run, factor by factor, slip by slip: the moved value, its coded value, kept within the reach."""
    units = data.coding.to_actual(m.coded)
    reach = 2.0 * np.max(np.abs(data.coded))
    out = []
    for pos, row in enumerate(np.flatnonzero(m.keep)):
        for j, name in enumerate(data.factors):
            for power in (-3, -2, -1, 1, 2, 3):
                v = units[pos, j]
                moved = v + power if name in data.log_factors else v * 10.0 ** power
                coded = (moved - data.coding.center[j]) / data.coding.unit[j]
                if moved != v and np.isfinite(moved) and abs(coded) <= reach:
                    out.append((int(row), j, power, coded))
    return out


def _ratio_by_refit(m, cands, y):
    """SSE / SSE(run moved) per candidate and column, each from a refit of the moved model matrix."""
    rows = slips.moved_rows(m, cands)
    pos_of = {int(r): i for i, r in enumerate(np.flatnonzero(m.keep))}
    sse0 = np.sum((y - m.x @ np.linalg.lstsq(m.x, y, rcond=None)[0]) ** 2, axis=0)
    out = np.full((len(cands), y.shape[1]), -np.inf)
    for c, cand in enumerate(cands):
        i = pos_of[cand.row]
        if m.hat[i] >= LEVERAGE_UNPREDICTABLE:
            continue
        x = m.x.copy()
        x[i] = rows[c]
        sse = np.sum((y - x @ np.linalg.lstsq(x, y, rcond=None)[0]) ** 2, axis=0)
        out[c] = sse0 / sse
    return out


@pytest.mark.parametrize("seed,k,n,log_first", [(0, 2, 24, False), (1, 3, 40, True), (2, 2, 60, True),
                                                (3, 3, 31, False)])
def test_the_candidates_are_the_loops(seed, k, n, log_first):
    data, m = _model(seed, k, n, log_first)
    found = [(c.row, c.factor, c.power, c.coded) for c in slip_candidates(data, m)]
    expected = _candidates_by_loop(data, m)
    assert [f[:3] for f in found] == [e[:3] for e in expected]
    np.testing.assert_allclose([f[3] for f in found], [e[3] for e in expected], rtol=1e-12, atol=1e-12)
    assert all(isinstance(f[3], float) and isinstance(f[2], int) for f in found)


@pytest.mark.parametrize("seed,k,n,log_first", [(4, 2, 24, False), (5, 3, 40, True), (6, 2, 50, False)])
@pytest.mark.parametrize("cells", [None, 7, 50])
def test_each_columns_best_slip_is_the_refits(seed, k, n, log_first, cells, monkeypatch):
    """The best ratio per column and the first candidate reaching it, as refits give them; unchanged when the
    candidates are taken a few at a time (7 or 50 cells: chunks that split a run's slips)."""
    data, m = _model(seed, k, n, log_first)
    cands = slip_candidates(data, m)
    rng = np.random.default_rng(seed)
    y = np.column_stack([m.z, m.fitted_z[:, None] + 0.05 * rng.standard_normal((len(m.z), 4))])
    y[3, 1] *= 10.0  # one column with a run far off: a slip can explain it
    if cells is not None:
        monkeypatch.setattr(slips, "SLIP_CELLS", cells)
        monkeypatch.setattr(slips, "SLIP_MIN_CANDIDATES", 1)
    best, arg = slip_ratios(m, cands, y)
    brute = _ratio_by_refit(m, cands, y)
    np.testing.assert_allclose(best, np.maximum(brute.max(axis=0), 0.0), rtol=1e-7)
    for b in range(y.shape[1]):
        reached = np.flatnonzero(brute[:, b] >= brute[:, b].max() * (1 - 1e-9))
        assert arg[b] in reached, (b, arg[b], reached)


@pytest.mark.parametrize("seed,k,n,log_first", [(7, 2, 24, False), (8, 3, 40, True)])
def test_the_count_is_the_lists_length(seed, k, n, log_first):
    from demid.criticism.slips import count_slip_candidates

    data, m = _model(seed, k, n, log_first)
    assert count_slip_candidates(data, m) == len(_candidates_by_loop(data, m)) > 0
