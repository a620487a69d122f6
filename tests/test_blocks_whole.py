"""A table's blocks over generated tables, each output against a rule written here: labels as written (1 and
1.0 both '1', text stripped, one block is none), levels in order of first appearance, the effect-coded columns
(+1 in its block, -1 in the last, 0 elsewhere; 1-3 blocks), and the pure-error groups: two runs share a group
exactly when they are at the same design point and in the same block."""

from __future__ import annotations

import numpy as np
import pandas as pd
from hypothesis import given, settings
from hypothesis import strategies as st

from demid.blocks import block_columns, block_labels, block_levels, label_text, pure_error_groups

_FORMS = {"1": [1, 1.0, np.int64(1), " 1"], "2": [2, 2.0, np.float64(2.0), "2 "], "B": ["B", " B"]}


@given(seed=st.integers(0, 10_000), blocks=st.integers(1, 3), runs=st.integers(2, 14), k=st.integers(1, 3))
@settings(max_examples=60, deadline=None, derandomize=True)
def test_labels_levels_columns_and_pure_error_groups_follow_their_rules(seed, blocks, runs, k):
    rng = np.random.default_rng(seed)
    names = list(_FORMS)[:blocks]
    chosen = [names[int(i)] for i in rng.integers(0, blocks, runs)]
    written = [_FORMS[n][int(rng.integers(0, len(_FORMS[n])))] for n in chosen]
    table = pd.DataFrame({"block": pd.Series(written, dtype=object), "x": np.arange(runs)})
    assert [label_text(v) for v in written] == chosen
    labels = block_labels(table)
    if len(set(chosen)) < 2:
        assert labels is None
    else:
        assert list(labels) == chosen
    assert block_labels(table.drop(columns="block")) is None
    levels = block_levels(chosen)
    assert levels == [n for i, n in enumerate(chosen) if n not in chosen[:i]]
    columns = block_columns(chosen)
    assert columns.shape == (runs, len(levels) - 1)
    for i, label in enumerate(chosen):
        expected = [1.0 if label == level else 0.0 for level in levels[:-1]]
        if label == levels[-1]:
            expected = [-1.0] * (len(levels) - 1)
        assert list(columns[i]) == expected
    # design points drawn from a small pool, so some runs repeat a point (in one block or in two)
    pool = rng.choice([-1.0, 0.0, 1.0, 1.5], size=(4, k))
    coded = pool[rng.integers(0, 4, runs)]
    groups = pure_error_groups(coded, chosen)
    alone = pure_error_groups(coded)
    for i in range(runs):
        for j in range(runs):
            same_point = bool(np.all(coded[i] == coded[j]))
            assert (groups[i] == groups[j]) == (same_point and chosen[i] == chosen[j])
            assert (alone[i] == alone[j]) == same_point
