"""Lack of fit against the replicated runs, on small tables and on long ones (the group sums' path above
ASYMPTOTIC_RUNS runs): the between-groups sum of squares against np.bincount's group sums, and the catalogue's
F and nominal p against the classical ANOVA written out with numpy (pure error within replicate groups)."""
from __future__ import annotations

import numpy as np
import pandas as pd
import pytest
from hypothesis import given, settings, strategies as st
from scipy import stats

from demid.criticism.catalogue import ASYMPTOTIC_RUNS, Round, _between_groups_ss
from demid.criticism.level1 import prepare_data
from demid.criticism.models import Model, ModelForm


def lack_of_fit_by_hand(table: pd.DataFrame) -> tuple[float, int, int]:
    """The lack-of-fit F of the full quadratic in columns a, b against y, and its two degrees of freedom (lack of
    fit, pure error), from least squares and the replicate groups' means written out."""
    a, b, y = (table[c].to_numpy() for c in ("a", "b", "y"))
    x = np.column_stack([np.ones_like(a), a, b, a * b, a * a, b * b])
    sse = float(np.sum((y - x @ np.linalg.lstsq(x, y, rcond=None)[0]) ** 2))
    _, group = np.unique(np.column_stack([a, b]), axis=0, return_inverse=True)
    group = group.ravel()
    means = np.bincount(group, weights=y) / np.bincount(group)
    sspe = float(np.sum((y - means[group]) ** 2))
    df_pe = len(y) - group.max() - 1
    df_lof = len(y) - 6 - df_pe
    return ((sse - sspe) / df_lof) / (sspe / df_pe), df_lof, df_pe


@settings(max_examples=12, deadline=None, derandomize=True)
@given(n_groups=st.integers(1, 40), n_cols=st.sampled_from([1, 3, 8]), seed=st.integers(0, 999),
       large=st.booleans())
def test_the_between_groups_sum_of_squares_is_each_groups_squared_sum_over_its_size(n_groups, n_cols, seed, large):
    rng = np.random.default_rng(seed)
    group = np.concatenate([np.arange(n_groups), rng.integers(0, n_groups, 3 * n_groups)])
    rng.shuffle(group)
    e = rng.standard_normal((len(group), n_cols))
    counts = np.bincount(group, minlength=n_groups)
    sums = np.stack([np.bincount(group, weights=e[:, b], minlength=n_groups) for b in range(n_cols)], axis=1)
    want = np.sum(sums ** 2 / counts[:, None], axis=0)
    got = _between_groups_ss(group, n_groups, large)(e)
    assert got.shape == (n_cols,)
    np.testing.assert_allclose(got, want, rtol=1e-10)


def _replicated_table(points_per_side, replicates, seed, curve):
    rng = np.random.default_rng(seed)
    levels = np.linspace(1.0, 3.0, points_per_side)
    a, b = (g.ravel() for g in np.meshgrid(levels, levels))
    a, b = np.repeat(a, replicates), np.repeat(b, replicates)
    order = rng.permutation(len(a))
    a, b = a[order], b[order]
    y = 5.0 + a - 0.3 * b ** 2 + curve * a ** 3 + 0.2 * rng.standard_normal(len(a))
    return pd.DataFrame({"run": np.arange(1, len(a) + 1), "a": a, "b": b, "y": y})


@pytest.mark.parametrize("points_per_side, replicates, curve", [(4, 3, 0.3), (5, 12, 0.05), (6, 9, 0.0)])
def test_the_catalogues_lack_of_fit_is_the_classical_anova(points_per_side, replicates, curve):
    table = _replicated_table(points_per_side, replicates, points_per_side, curve)
    assert (len(table) > ASYMPTOTIC_RUNS) == (replicates >= 9)
    data, _ = prepare_data(table, ["a", "b"], "y", 1.0, (), None)
    model = Model(data, ModelForm())
    h = next(h for h in Round(data, model, 19, np.random.default_rng(0)).hypotheses if h.cause == "lack_of_fit")
    f, df_lof, df_pe = lack_of_fit_by_hand(table)
    assert h.statistic == pytest.approx(f, rel=1e-8)
    assert h.logp == pytest.approx(stats.f.logsf(f, df_lof, df_pe), rel=1e-8, abs=1e-12)
    assert h.info["df"] == [df_lof, df_pe]
