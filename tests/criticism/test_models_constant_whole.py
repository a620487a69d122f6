"""A model's summary when the response does not change (criticism.models): a constant response, or one that is
constant on the kept runs only, has no total sum of squares, so its R² is undefined and reported as None (not a
division by zero); every other field is still that of the least-squares fit written out here."""

from __future__ import annotations

import numpy as np
import pandas as pd
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from demid.criticism.level1 import prepare_data
from demid.criticism.models import Model, ModelForm


@given(n=st.integers(9, 16), seed=st.integers(0, 999), value=st.sampled_from([-3.5, 7.25, 1e4]),
       dropped=st.sampled_from([(), (1,)]))
@settings(max_examples=8, deadline=None, derandomize=True)
def test_a_response_constant_on_the_kept_runs_has_no_r2_and_the_fits_other_numbers(n, seed, value, dropped):
    rng = np.random.default_rng(seed)
    y = np.full(n, value)
    if dropped:
        y[dropped[0]] = value + 5.0  # the one run that differs is left out of the fit
    table = pd.DataFrame({"run": np.arange(1, n + 1), "a": rng.uniform(0, 1, n), "b": rng.uniform(0, 1, n), "y": y})
    data, _ = prepare_data(table, ["a", "b"], "y", 1.0, (), None)
    model = Model(data, ModelForm(dropped=dropped))
    summary = model.summary()
    kept = np.setdiff1d(np.arange(n), dropped)
    assert summary["r2"] is None
    assert summary["rmse"] == pytest.approx(0.0, abs=1e-9 * abs(value))
    assert summary["n_runs"] == len(kept)
    assert summary["excluded_runs"] == [int(table["run"][i]) for i in dropped]
    assert summary["n_params"] == 6 + 1 + len(dropped)
