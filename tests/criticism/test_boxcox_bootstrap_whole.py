"""The Box-Cox test's parametric bootstrap (catalogue.Round._boxcox_bootstrap) against a bootstrap written here:
null tables y* = fitted + sigma N(0, 1) drawn a batch of n_null at a time, the all-positive ones kept, the
likelihood ratio of each (lambda on the grid -2..2 in steps of 0.05 against lambda = 1, the full quadratic refitted
with numpy for every lambda), p = (exceedances + 1) / (draws used + 1).  The search stops as soon as n_null
positive draws are used: when the first batch is all positive, it draws that batch alone (the random stream after
it, which the family's other draws read, is that of one batch)."""
from __future__ import annotations

import numpy as np
import pandas as pd
import pytest
from scipy import special

from demid.criticism.catalogue import Round
from demid.criticism.level1 import prepare_data
from demid.criticism.models import Model, ModelForm, orthonormal_basis


def _quadratic(a, b):
    return np.column_stack([np.ones_like(a), a, b, a * b, a * a, b * b])


def _lr(y: np.ndarray, x: np.ndarray) -> float:
    """Box-Cox likelihood ratio of the best lambda on the test grid against no transform."""
    lams = np.round(np.arange(-2.0, 2.0001, 0.05), 10)
    n = len(y)
    prof = []
    for lam in lams:
        z = special.boxcox(y, lam)
        sse = np.sum((z - x @ np.linalg.lstsq(x, z, rcond=None)[0]) ** 2)
        prof.append(-0.5 * n * np.log(sse / n) + (lam - 1.0) * np.sum(np.log(y)))
    prof = np.array(prof)
    return 2.0 * (prof.max() - prof[int(np.flatnonzero(lams == 1.0)[0])])


def _bootstrap_by_hand(fitted, sigma, x, lr_obs, n_null, seed, max_batches=20):
    rng = np.random.default_rng(seed)
    lrs = []
    for _ in range(max_batches):
        draws = fitted[:, None] + sigma * rng.standard_normal((len(fitted), n_null))
        lrs += [_lr(draws[:, j], x) for j in np.flatnonzero(np.all(draws > 0, axis=0))][: n_null - len(lrs)]
        if len(lrs) == n_null:
            break
    exceed = sum(lr >= lr_obs - 1e-9 for lr in lrs)
    return (exceed + 1.0) / (len(lrs) + 1.0), len(lrs), rng


@pytest.mark.parametrize("offset, noise, n_null, batches",
                         [(20.0, 0.05, 15, "one"), (0.1, 0.2, 9, "several"), (0.0, 0.5, 9, "all twenty")])
def test_the_bootstrap_p_and_its_draws_are_those_written_out(offset, noise, n_null, batches):
    """offset 20: every null table positive, one batch; near 0 with a wide scatter some null tables have a
    response <= 0 and further batches are drawn until n_null are used, or the twenty batches run out first."""
    levels = np.linspace(-1.0, 1.0, 4)
    a, b = (g.ravel() for g in np.meshgrid(levels, levels))
    y = offset + np.exp(1.5 * a + 0.4 * b) * np.exp(noise * np.random.default_rng(3).standard_normal(len(a)))
    table = pd.DataFrame({"run": np.arange(1, len(a) + 1), "a": a, "b": b, "y": y})
    data, _ = prepare_data(table, ["a", "b"], "y", 1.0, (), None)
    model = Model(data, ModelForm())
    rnd = Round(data, model, 19, np.random.default_rng(0))
    x = _quadratic(a, b)
    fitted = x @ np.linalg.lstsq(x, y, rcond=None)[0]
    sigma = np.sqrt(np.sum((y - fitted) ** 2) / (len(y) - 6))
    lr_obs = _lr(y, x)
    rng = np.random.default_rng(7)
    p, used = rnd._boxcox_bootstrap(model, orthonormal_basis(model.xw), lr_obs, n_null, rng)
    want_p, want_used, rng_by_hand = _bootstrap_by_hand(fitted, sigma, x, lr_obs, n_null, 7)
    assert used == want_used
    assert (used == n_null) == (batches != "all twenty")
    assert p == pytest.approx(want_p, rel=1e-12)
    # the stream after the bootstrap: no batch drawn beyond the one that completed n_null
    assert rng.bit_generator.state == rng_by_hand.bit_generator.state
    if batches == "one":
        one_batch = np.random.default_rng(7)
        one_batch.standard_normal((len(y), n_null))
        assert rng.bit_generator.state == one_batch.bit_generator.state
