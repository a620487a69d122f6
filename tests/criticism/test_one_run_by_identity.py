"""The run a whole-design cause rests on, from the one fit with every run: each run's deletion by the leave-one-out
identities against deleted_logp's refit per run (a missing term, drift and Box-Cox; a run of leverage 1 refitted),
and the run a drift rests on among 4,000 runs without a refit per run."""

from __future__ import annotations

import numpy as np
import pandas as pd
import pytest

from demid.criticism.level1 import prepare_data
from demid.criticism.models import Model, ModelForm
from demid.design import LEVERAGE_UNPREDICTABLE


def _cubic_table(n: int, seed: int) -> pd.DataFrame:
    rng = np.random.default_rng(seed)
    x = rng.uniform(0.05, 1.0, (n, 2))
    y = 20 + x[:, 0] - 0.5 * x[:, 1] + 0.4 * x[:, 0] ** 3 + 0.05 * rng.standard_normal(n)
    return pd.DataFrame({"run": np.arange(1, n + 1), "a": x[:, 0], "b": x[:, 1], "y": y})


@pytest.mark.parametrize("seed", range(4))
def test_deletions_by_identity_are_those_of_a_refit_without_each_run(seed):
    """A missing term's, drift's and Box-Cox's test without each run, from the one fit with every run, against
    :func:`deleted_logp`'s refit per run (two response columns); a run of leverage 1 is refitted."""
    from demid.criticism.catalogue import Round
    from demid.criticism.one_run import deleted_logp, deleted_logp_by_identity

    table = _cubic_table(40 + 5 * seed, seed)
    if seed == 3:
        table.loc[0, ["a", "b"]] = [3.0, 3.0]  # far out: the quadratic goes through it
    data, _ = prepare_data(table, ["a", "b"], "y", 1.0, (), None)
    m = Model(data, ModelForm())
    assert (seed == 3) == bool(np.any(m.hat >= LEVERAGE_UNPREDICTABLE))
    causes = set()
    for h in Round(data, m, 19, np.random.default_rng(0)).hypotheses:
        if h.cause in ("missing_term", "drift", "response_transform"):
            y = np.column_stack([m.z, m.z + 0.01 * np.random.default_rng(seed).standard_normal(len(m.z))])
            np.testing.assert_allclose(deleted_logp_by_identity(data, m, h, y), deleted_logp(data, m, h, y),
                                       rtol=1e-7, atol=1e-8)
            causes.add(h.cause)
    # the far run leaves no cubic term to test; drift and Box-Cox go through its refit
    assert causes == {"drift", "response_transform"} | ({"missing_term"} if seed != 3 else set())


def test_the_run_a_drift_rests_on_among_4000_runs_without_a_refit_per_run(monkeypatch):
    """Above LOO_REFIT_MAX_RUNS the run a drift rests on comes from the one fit: no run is refitted (4,000 refits of
    4,000 runs were a minute), and the run found is the one the identities give."""
    from demid.criticism import one_run
    from demid.criticism.catalogue import Hypothesis

    data, _ = prepare_data(_cubic_table(4000, 1), ["a", "b"], "y", 1.0, (), None)
    m = Model(data, ModelForm())
    refitted = []
    direct = one_run.deleted_logp
    monkeypatch.setattr(one_run, "deleted_logp",
                        lambda *args, **kw: refitted.append(args[4] if len(args) > 4 else kw.get("positions"))
                        or direct(*args, **kw))
    h = Hypothesis("drift", "run")
    worst = one_run.worst_deletion(data, m, h)
    assert refitted == []
    logp = one_run.deleted_logp_by_identity(data, m, h, m.z[:, None])[:, 0]
    assert worst.row == int(np.flatnonzero(m.keep)[int(np.argmax(logp))]) and 0.0 < worst.p_without <= 1.0
