"""The state frame of a study whose sets are all sampled (four factors or more, or surrogates the exact method does
not take): every scenario's rows carry its method and no exact state, so the scenarios table still has every state
column, NaN, and the later steps evaluate such sets on their own."""

from __future__ import annotations

import numpy as np
import pandas as pd

from demid.sampling.grid import AdmissibleSet
from demid.sampling.stored import STATE_COLUMNS, set_state_frame


def _sampled(name_count: int, fraction: float) -> AdmissibleSet:
    factors = tuple(f"x{i + 1}" for i in range(name_count))
    return AdmissibleSet(observables=("y1",), tolerance=0.05, factors=factors, fraction=fraction,
                         node_fraction=fraction, n_nodes=4096, n_admissible_nodes=int(4096 * fraction),
                         n_refined_cells=0, lower=np.zeros(name_count), upper=np.ones(name_count),
                         mask=np.zeros(0, dtype=bool), method="scrambled Sobol")


def test_sets_all_sampled_leave_every_exact_state_column_empty():
    state = set_state_frame({"a": _sampled(4, 0.25), "b": _sampled(5, 0.0)})
    assert list(state.columns) == STATE_COLUMNS
    assert len(state) == 9  # one row per scenario and factor
    assert list(state["method"]) == ["scrambled Sobol"] * 9
    for column in STATE_COLUMNS[1:]:
        assert pd.api.types.is_float_dtype(state[column]), column
        assert state[column].isna().all(), column


def test_one_sampled_set_alone_has_the_columns_of_a_table_with_an_exact_one():
    state = set_state_frame({"only": _sampled(4, 0.5)})
    assert list(state.columns) == STATE_COLUMNS and len(state) == 4
    assert np.isnan(state["exact_fraction"].to_numpy(dtype=float)).all()
