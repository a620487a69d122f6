"""One replicate rule: the ANOVA's pure error, the criticism's lack-of-fit test and the transcription check's
refits (single and batched) group the same runs as replicates."""

from __future__ import annotations

import numpy as np
import pandas as pd
import pytest

from demid.criticism.catalogue import Round
from demid.criticism.level1 import prepare_data
from demid.criticism.models import Model, ModelForm
from demid.design import REPLICATE_DECIMALS, Coding, ccd_points, model_matrix, quadratic_terms
from demid.surrogate import fit_response
from demid.transcription.engine import DesignFit, evaluate_designs


def _table(offset):
    """A rotatable CCD with 5 centre runs (coded = actual units), one centre run moved by ``offset`` in x1,
    responses with scatter (and a cubic, so lack of fit is there to test)."""
    rng = np.random.default_rng(7)
    coded = ccd_points(2, 1.41421, 5)
    coded[-1, 0] += offset
    y = 50 + model_matrix(coded, quadratic_terms(2)) @ rng.normal(0, 3, 6) + 2 * coded[:, 0] ** 3
    y += 0.3 * rng.standard_normal(len(y))
    return pd.DataFrame({"run": np.arange(1, len(y) + 1), "x1": coded[:, 0], "x2": coded[:, 1], "y": y})


def _pure_error_dfs(table):
    coding = Coding(("x1", "x2"), (0.0, 0.0), (1.0, 1.0))
    fit = fit_response(table, ["x1", "x2"], "y", coding=coding)
    anova = fit.anova().df_pure_error
    data, _ = prepare_data(table, ["x1", "x2"], "y", 1.41421, (), fit)
    lof = [h for h in Round(data, Model(data, ModelForm()), 99, np.random.default_rng(0)).hypotheses
           if h.cause == "lack_of_fit"]
    criticism = lof[0].info["df"][1]
    single = DesignFit(fit.coded, quadratic_terms(2), coding, False).df_pe
    batched = int(evaluate_designs(fit.coded[None], fit.y, quadratic_terms(2), None, {})["_df_pe"][0])
    return anova, criticism, single, batched


@pytest.mark.parametrize("offset, replicates", [
    (0.0, 5),
    (0.3 * 10.0 ** -REPLICATE_DECIMALS, 5),  # below the rule's place: still a replicate (9 decimals split it)
    (30 * 10.0 ** -REPLICATE_DECIMALS, 4),  # a point of its own
])
def test_anova_criticism_and_transcription_group_replicates_alike(offset, replicates):
    assert _pure_error_dfs(_table(offset)) == (replicates - 1,) * 4
