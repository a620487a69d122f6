"""pareto_front (demid.pareto) on the inputs a caller may hand it: Python lists, integer arrays, pandas Series with an
index of their own, NaN and infinite values (left out), against the brute-force front of
tests/test_pareto_properties.py over generated objectives with ties."""

from __future__ import annotations

import numpy as np
import pandas as pd
from hypothesis import Phase, given, settings
from hypothesis import strategies as st

from demid.pareto import pareto_front
from tests.test_pareto_properties import _brute_front

VALUES = st.lists(st.tuples(st.integers(-3, 3), st.integers(-3, 3)), min_size=1, max_size=25)


@given(points=VALUES, holes=st.lists(st.integers(0, 24), max_size=3), seed=st.integers(0, 1000))
@settings(max_examples=30, deadline=None, derandomize=True, phases=[Phase.explicit, Phase.generate])
def test_the_front_is_the_same_whatever_container_holds_the_objectives(points, holes, seed):
    first = np.array([p[0] for p in points], dtype=float)
    second = np.array([p[1] for p in points], dtype=float)
    for h in holes:
        if h < len(points):
            (first if h % 2 else second)[h] = np.nan if h % 3 else np.inf
    finite = np.flatnonzero(np.isfinite(first) & np.isfinite(second))
    want = [int(finite[i]) for i in _brute_front(first[finite], second[finite])]
    assert pareto_front(first, second).tolist() == want
    assert pareto_front(first.tolist(), second.tolist()).tolist() == want
    index = np.random.default_rng(seed).permutation(len(points)) + 100
    assert pareto_front(pd.Series(first, index=index), pd.Series(second, index=index)).tolist() == want
    if not holes:
        assert pareto_front(first.astype(int), second.astype(int)).tolist() == want
