"""Above LOO_REFIT_MAX_RUNS runs, the test of unequal scatter is redone only without the runs the
fixed-covariate identity ranks weakest (one_run._weakest_by_identity): the run and the p-value found must be
those of refitting without every run.  Here the scatter falls as a factor grows (the variance slope negative,
where the earlier tests' grew with it), one run off by 10 scatter widths; the ranking measures each run's
likelihood ratio from equal scatter (slope 0), and ranked from another slope it misses the run."""
from __future__ import annotations

import numpy as np
import pandas as pd

from demid.criticism.catalogue import Round
from demid.criticism.level1 import prepare_data
from demid.criticism.models import Model, ModelForm
from demid.criticism.one_run import deleted_logp, worst_deletion
from demid.surrogate import LOO_REFIT_MAX_RUNS


def test_the_screened_worst_deletion_is_the_one_of_every_deletion(k=2, slope=-1.5, seed=0, wild_pick=0):
    rng = np.random.default_rng(seed)
    n = LOO_REFIT_MAX_RUNS + 40
    x = rng.uniform(-1, 1, (n, k))
    y = 10 + 2 * x[:, 0] - x[:, 1] + 0.05 * np.exp(slope * x[:, 0]) * rng.standard_normal(n)
    y[wild_pick % n] += 0.5
    factors = [f"f{j}" for j in range(k)]
    table = pd.DataFrame({"run": np.arange(1, n + 1), **{f: x[:, j] for j, f in enumerate(factors)}, "y": y})
    data, _ = prepare_data(table, factors, "y", None, ())
    model = Model(data, ModelForm())
    hypotheses = [h for h in Round(data, model, 19, np.random.default_rng(seed)).hypotheses
                  if h.cause == "heteroscedasticity" and h.detail == "f0"]  # the factor the scatter follows
    assert len(hypotheses) == 1
    for h in hypotheses:
        every = deleted_logp(data, model, h, model.z[:, None])[:, 0]
        worst = worst_deletion(data, model, h)
        assert worst.row == int(np.flatnonzero(model.keep)[np.argmax(every)])
        assert abs(worst.p_without - np.exp(every.max())) <= 1e-12 * np.exp(every.max())
