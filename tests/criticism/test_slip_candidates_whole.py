"""The slipped factor values level 1 judges (criticism.slips.slip_candidates), against a brute force written in the
test: every kept run x factor x decimal slip (x 10^-3 .. x 10^3 of a linear factor's actual value, -3 .. +3 decades
of a log factor's), in that order, whose value differs from the recorded one and whose coded value lies within
twice the design's reach (the largest |coded| of its runs) -- a value exactly at twice the reach is judged, the
next representable one beyond is not.  Over generated tables of 2-3 factors, a log factor, ranges on either side
of zero and dropped runs."""

from __future__ import annotations

import numpy as np
import pandas as pd
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from demid.criticism.level1 import prepare_data
from demid.criticism.models import Model, ModelForm
from demid.criticism.slips import count_slip_candidates, slip_candidates

POWERS = (-3, -2, -1, 1, 2, 3)


def _expected(data, model) -> list[tuple[int, int, int, float]]:
    units = data.coding.to_actual(model.coded)  # model units: log10 of a log factor
    centre, unit = np.array(data.coding.center), np.array(data.coding.unit)
    reach = 2.0 * np.max(np.abs(data.coded))
    out = []
    for pos, row in enumerate(np.flatnonzero(model.keep)):
        for j, name in enumerate(data.factors):
            for k in POWERS:
                recorded = units[pos, j]
                moved = recorded + k if name in data.log_factors else recorded * 10.0 ** k
                coded = (moved - centre[j]) / unit[j]
                if moved != recorded and np.isfinite(moved) and abs(coded) <= reach:
                    out.append((int(row), j, k, float(coded)))
    return out


@given(k=st.integers(2, 3), n_extra=st.integers(0, 6), seed=st.integers(0, 9999), log_first=st.booleans(),
       offset=st.sampled_from([-50.0, 0.0, 0.02, 3.0]), dropped=st.sampled_from([(), (1,), (0, 4)]))
@settings(max_examples=12, deadline=None, derandomize=True)
def test_every_judged_slip_in_order_against_a_brute_force(k, n_extra, seed, log_first, offset, dropped):
    rng = np.random.default_rng(seed)
    n = (k + 1) * (k + 2) // 2 + 4 + n_extra
    factors = [f"f{j}" for j in range(k)]
    cols = {"run": np.arange(1, n + 1)}
    for j, f in enumerate(factors):
        cols[f] = 10.0 ** rng.uniform(-1, 2, n) if (log_first and j == 0) else offset + rng.uniform(0.01, 5.0, n)
    cols["y"] = 3.0 + rng.standard_normal(n)
    log_factors = ("f0",) if log_first else ()
    data, _ = prepare_data(pd.DataFrame(cols), factors, "y", 1.0, log_factors, None)
    model = Model(data, ModelForm(dropped=dropped))
    got = [(c.row, c.factor, c.power, c.coded) for c in slip_candidates(data, model)]
    want = _expected(data, model)
    assert [g[:3] for g in got] == [w[:3] for w in want]
    np.testing.assert_allclose([g[3] for g in got], [w[3] for w in want], rtol=1e-12, atol=1e-12)
    assert count_slip_candidates(data, model) == len(want)


@pytest.mark.parametrize("level,judged", [(0.2, True), (float(np.nextafter(0.2, 1.0)), False)])
def test_a_slip_exactly_at_twice_the_designs_reach_is_judged(level, judged):
    """Coding centre 0 and unit 1 (runs from -1 to 1): a run recorded at 0.2 slipped x10 lies at 2.0, exactly twice
    the reach; one recorded a hair above 0.2 lands beyond it.  Runs recorded at 0 have no slip (0 x 10^k is 0)."""
    assert 0.2 * 10.0 == 2.0
    a = np.array([-1.0, 1.0, -1.0, 1.0, 0.0, 0.0, -1.0, 1.0, level, -0.5, 0.5, 0.0])
    b = np.array([-1.0, -1.0, 1.0, 1.0, -1.0, 1.0, 0.0, 0.0, 0.3, 0.5, -0.5, 0.0])
    table = pd.DataFrame({"run": np.arange(1, 13), "a": a, "b": b, "y": 1.0 + a + b ** 2 + 0.01 * np.arange(12)})
    data, _ = prepare_data(table, ["a", "b"], "y", 1.0, (), None)
    assert tuple(data.coding.center) == (0.0, 0.0) and tuple(data.coding.unit) == (1.0, 1.0)
    model = Model(data, ModelForm())
    cands = slip_candidates(data, model)
    assert [(c.row, c.factor, c.power) for c in cands] == [w[:3] for w in _expected(data, model)]
    assert not [c for c in cands if data.coded[c.row, c.factor] == 0.0]  # 0 times 10^k is no slip
    found = [c for c in cands if c.row == 8 and c.factor == 0 and c.power == 1]
    assert len(found) == int(judged)
    if judged:
        assert found[0].coded == 2.0
