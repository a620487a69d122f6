"""The slipped-factor member's p-values (catalogue.Round._factor_level) counted here one by one: the observed
ratio and each of the b null draws (a parametric bootstrap sharing the round's first b normal draws per run) get
p = (1 + number of null draws at least as large) / (b + 1), ties to 1e-12 counted as at least as large: p-values
on the grid 1/(b + 1) .. 1, the smallest null draw's exactly 1.  2-3 factors, 19 or 99 null draws."""
from __future__ import annotations

import math

import numpy as np
import pandas as pd
import pytest

from demid.criticism.catalogue import Round
from demid.criticism.level1 import prepare_data
from demid.criticism.models import Model, ModelForm
from demid.criticism.slips import slip_candidates, slip_ratios


def _table(k: int, seed: int) -> pd.DataFrame:
    rng = np.random.default_rng(seed)
    levels = np.array([1.0, 2.0, 4.0])
    grid = np.array(np.meshgrid(*[levels] * k, indexing="ij")).reshape(k, -1).T
    y = 3 + grid @ rng.uniform(0.5, 2.0, k) + 0.1 * (grid ** 2).sum(axis=1) + 0.2 * rng.standard_normal(len(grid))
    return pd.DataFrame({"run": np.arange(1, len(grid) + 1), **{f"f{j}": grid[:, j] for j in range(k)}, "y": y})


@pytest.mark.parametrize("k, n_null, seed", [(2, 19, 0), (2, 99, 1), (3, 19, 2)])
def test_the_slip_members_p_values_are_counts_of_null_draws(k, n_null, seed):
    table = _table(k, seed)
    data, _ = prepare_data(table, [f"f{j}" for j in range(k)], "y", 1.0, ())
    model = Model(data, ModelForm())
    h = next(h for h in Round(data, model, n_null, np.random.default_rng(seed)).hypotheses
             if h.cause == "factor_level")
    eps = np.random.default_rng(seed).standard_normal((len(model.y), n_null))  # the round's first draws
    sigma = math.sqrt(model.ssr / model.df_resid)
    ratio, _ = slip_ratios(model, slip_candidates(data, model),
                           np.column_stack([model.z, model.fitted_z[:, None] + sigma * eps]))
    t_obs, null = float(ratio[0]), [float(v) for v in ratio[1:]]
    assert len(null) == n_null

    def p(t):
        return (1 + sum(v >= t - 1e-12 for v in null)) / (n_null + 1)

    assert h.statistic == t_obs
    assert math.exp(h.logp) == pytest.approx(p(t_obs), rel=1e-12)
    p_null = np.exp(h.null_logp)
    np.testing.assert_allclose(p_null, [p(v) for v in null], rtol=1e-12)
    assert p_null.max() == pytest.approx(1.0, rel=1e-12) and p_null.min() >= 1 / (n_null + 1) - 1e-15
