"""Unequal scatter and the covariate it follows: the predicted value's scatter at new points, and covariates the
runs do not tell apart listed as aliases of the named one (as aliased terms are)."""

from __future__ import annotations

import numpy as np
import pandas as pd
import pytest
import statsmodels.api as sm

from demid.criticism import criticize, discrimination
from demid.criticism.catalogue import Hypothesis
from demid.criticism.extensions import extend_for
from demid.criticism.level1 import prepare_data
from demid.criticism.models import Model, ModelForm
from demid.design import model_matrix, quadratic_terms
from tests.generators import FACTORS, ccd_table, design


@pytest.mark.parametrize("seed", range(3))
def test_scatter_with_the_predicted_value_grows_at_new_points_as_the_unweighted_quadratic_predicts(seed):
    """The scatter a new run has under 'scatter grows with the predicted value': sigma^2 exp(gamma v), v the
    unweighted quadratic's prediction at the point rescaled as at the runs (statsmodels OLS, computed here).
    A constant scatter there (the factor covariates' rule applied to no factor) fails it."""
    table, _ = ccd_table(seed, 2, "het", 30.0)
    data, _ = prepare_data(table, FACTORS[2], "y", None, ())
    base = Model(data, ModelForm())
    model = Model(data, extend_for(data, base, Hypothesis("heteroscedasticity", "fitted"))[0])
    assert model.spec.weight_gamma != 0.0

    ols = sm.OLS(table["y"].to_numpy(), model_matrix(data.coded, quadratic_terms(2))).fit()
    fz = ols.fittedvalues
    centre, half = (fz.max() + fz.min()) / 2, np.ptp(fz) / 2
    points = discrimination.candidate_grid(data)
    v = (model_matrix(points, quadratic_terms(2)) @ ols.params - centre) / half
    noise = discrimination.prediction_parts(model, points)[2]
    sigma2 = model.ssr / model.df_resid
    assert noise == pytest.approx(sigma2 * np.exp(model.spec.weight_gamma * v), rel=1e-9)
    assert noise.max() > 1.5 * noise.min()  # it does vary from point to point


def _scatter_table(seed: int, mean_follows: str) -> tuple[pd.DataFrame, str]:
    """A replicated CCD (26 runs) whose scatter grows 30-fold across one factor; the mean follows that factor
    (so the predicted value is nearly that factor) or the other one."""
    factors, coding, coded, alpha = design(2, replicates=3)
    rng = np.random.default_rng(seed)
    j = seed % 2
    lead = coded[:, j] if mean_follows == "same" else coded[:, 1 - j]
    y = (100 + 15 * lead + 2 * coded[:, 0] * coded[:, 1]
         + rng.normal(size=len(coded)) * 30.0 ** (coded[:, j] / (2 * alpha)))
    table = pd.DataFrame(coding.to_actual(coded), columns=factors)
    table.insert(0, "run", rng.permutation(len(coded)) + 1)
    table["y"] = y
    return table.sort_values("run").reset_index(drop=True), factors[j]


@pytest.mark.parametrize("mean_follows", ["same", "other"])
def test_covariates_the_scatter_follows_about_as_well_are_listed_as_its_aliases(mean_follows):
    """Where the mean follows the scatter's factor, the predicted value is nearly that factor: the finding
    names one of the two and lists both (either may be the truth; the message says the runs do not tell which),
    and its confirming runs are chosen to separate them.  Where the mean follows the other factor, the scatter's
    factor is named alone."""
    named = 0
    for seed in range(6):
        table, factor = _scatter_table(seed, mean_follows)
        res = criticize(table, FACTORS[2], "y", n_null=199)
        if not res.findings:
            continue
        f = res.findings[0]
        assert f.cause == "heteroscedasticity"
        named += 1
        if mean_follows == "same":
            assert sorted(f.aliases) == sorted([factor, "fitted"]) and f.detail in f.aliases
            assert "do not tell which; the runs proposed to confirm it are chosen to tell them apart" in f.message
            labels = set(res.discriminating_runs[0]["expected"])
            assert {f"heteroscedasticity ({d})" for d in f.aliases} <= labels
        else:
            assert (f.detail, f.aliases) == (factor, [])
    assert named >= 4
