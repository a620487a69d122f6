"""Where a fit's studentised residuals stop refitting without each run: up to LOO_REFIT_MAX_RUNS runs (200 included)
they are statsmodels' own, from n refits, to the last bit; from 201 runs on they come from the scale identity
s_(i)^2 = (SSE - e_i^2 / (1 - h_i)) / (n - p - 1), written out here, to the last bit (the two agree to round-off
only).  Leverage and Cook's distance are statsmodels' on both sides."""

from __future__ import annotations

import numpy as np
import pandas as pd
import pytest

from demid.surrogate import LOO_REFIT_MAX_RUNS, fit_response


@pytest.mark.parametrize("n_runs, refit", [(LOO_REFIT_MAX_RUNS, True), (LOO_REFIT_MAX_RUNS + 1, False)])
def test_studentised_residuals_refit_up_to_the_limit_and_use_the_identity_past_it(n_runs, refit):
    assert LOO_REFIT_MAX_RUNS == 200
    rng = np.random.default_rng(3)
    x = rng.uniform(-1, 1, (n_runs, 2))
    table = pd.DataFrame(x, columns=["a", "b"])
    table["y"] = 1 + x[:, 0] + 0.5 * x[:, 1] ** 2 + rng.normal(0, 0.1, n_runs)
    fit = fit_response(table, ["a", "b"], "y")
    got = fit.influence()
    influence = fit.results.get_influence()
    e, h = fit.results.resid.to_numpy(), influence.hat_matrix_diag
    scale_without = (np.sum(e ** 2) - e ** 2 / (1 - h)) / (n_runs - 6 - 1)
    by_identity = influence.get_resid_studentized_external(sigma=np.sqrt(scale_without))
    by_refits = influence.summary_frame()["student_resid"].to_numpy()
    assert not np.array_equal(by_identity, by_refits)  # the table tells the two paths apart
    np.testing.assert_array_equal(got["student_resid"].to_numpy(), by_refits if refit else by_identity)
    np.testing.assert_allclose(got["leverage"].to_numpy(), h, rtol=1e-12)
    np.testing.assert_allclose(got["cooks_d"].to_numpy(), influence.cooks_distance[0], rtol=1e-12)
