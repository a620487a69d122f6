"""The catalogue's step test on a long table (criticism.catalogue.Round) read whole: from running sums a block of
null draws at a time (above ASYMPTOTIC_RUNS runs) against one residualised step column per change-point (the
small-table path, forced here), over blocks of one, several and all null draws, with and without a step planted:
the change-point named, its F, nominal p, the number of change-points and the simulated null maximum of every
draw."""

from __future__ import annotations

import numpy as np
import pytest

from demid.criticism import catalogue
from demid.criticism.catalogue import Round
from demid.criticism.level1 import prepare_data
from demid.criticism.models import Model, ModelForm
from tests.criticism.test_large_studies import _table


def _step_hypothesis(table, n_null: int, by_sums: bool, monkeypatch):
    data, _ = prepare_data(table, ["a", "b"], "y", 1.0, (), None)
    monkeypatch.setattr(catalogue, "ASYMPTOTIC_RUNS", 0 if by_sums else 10 ** 9)
    rnd = Round(data, Model(data, ModelForm()), n_null, np.random.default_rng(7))
    (h,) = [h for h in rnd.hypotheses if h.cause == "step"]
    return h


@pytest.mark.parametrize("cells", [1, 300 * 5, 2 ** 22])
@pytest.mark.parametrize("shift", [0.0, 0.5])
def test_the_step_test_from_running_sums_is_the_one_built_column_by_column(cells, shift, monkeypatch):
    table = _table(120, 3)
    table.loc[table["run"] > 80, "y"] += shift
    n_null = 13
    direct = _step_hypothesis(table, n_null, False, monkeypatch)
    monkeypatch.setattr(catalogue, "STEP_CELLS", cells)  # null draws a column, five columns, or all at a time
    by_sums = _step_hypothesis(table, n_null, True, monkeypatch)
    assert by_sums.detail == direct.detail
    assert by_sums.info == direct.info and direct.info["change_points"] == 120 - 3  # from run 3 to run n - 1
    assert by_sums.statistic == pytest.approx(direct.statistic, rel=1e-9)
    assert by_sums.logp == pytest.approx(direct.logp, rel=1e-9, abs=1e-12)
    assert np.shape(by_sums.null_logp) == (n_null,)
    np.testing.assert_allclose(by_sums.null_logp, direct.null_logp, rtol=1e-9, atol=1e-12)
    if shift:
        assert int(table.loc[direct.detail, "run"]) == 81 and direct.logp < np.log(1e-6)
