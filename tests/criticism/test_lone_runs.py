"""A run the others cannot predict (a lone centre run, leverage 1 or 1 blurred by rounded printed levels)
leaves the fit unchecked at its point: no "does not predict" from its leave-one-out error, no finding
on it, and the verdict says which run and what would check it."""

from __future__ import annotations

import warnings

import numpy as np
import pytest

from demid.criticism import criticize
from demid.surrogate import fit_response
from tests.generators import FACTORS, ccd_table


def _lone_centre_table(seed: int, digits: int | None, k: int = 2):
    """A rotatable CCD with one of its centre runs kept, factor levels printed to ``digits`` significant digits."""
    table, _ = ccd_table(seed, k, "clean", 0.0)
    factors = FACTORS[k]
    centre = (table[factors] - table[factors].median()).abs().sum(axis=1) < 1e-9
    table = table[~centre | (centre.cumsum() == 1)].reset_index(drop=True)
    if digits is not None:
        for f in factors:
            table[f] = table[f].map(lambda v: float(f"{v:.{digits}g}"))
    centre_run = int(table.loc[(table[factors] - table[factors].median()).abs().sum(axis=1) < 1e-9, "run"].iloc[0])
    return table, factors, centre_run


def _leverage(table, factors) -> np.ndarray:
    """Hat diagonal of the full quadratic, computed here from scratch (centred, scaled columns)."""
    x = table[factors].to_numpy(float)
    z = (x - x.mean(axis=0)) / x.std(axis=0)
    cols = [np.ones(len(z))] + [z[:, i] for i in range(z.shape[1])]
    cols += [z[:, i] * z[:, j] for i in range(z.shape[1]) for j in range(i + 1, z.shape[1])]
    cols += [z[:, i] ** 2 for i in range(z.shape[1])]
    m = np.column_stack(cols)
    return np.einsum("ij,jk,ik->i", m, np.linalg.pinv(m.T @ m), m)


@pytest.mark.parametrize("digits", [None, 4, 3])
@pytest.mark.parametrize("seed", range(4))
def test_a_lone_centre_run_leaves_q2_undefined_instead_of_condemning_the_fit(seed, digits):
    table, factors, centre_run = _lone_centre_table(seed, digits)
    lev = _leverage(table, factors)
    assert lev[table["run"].to_numpy() == centre_run][0] > 0.99  # the premise, checked independently
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        fit = fit_response(table, factors, "y")
        result = criticize(table, factors, "y", n_null=499)
    assert np.isnan(fit.statistics().q2)
    assert result.verdict != "does_not_predict"
    assert all(str(f.detail) != str(centre_run) for f in result.findings)
    assert result.verdict_detail["unpredictable_runs"] == [centre_run]
    assert f"Run {centre_run} alone fixes the quadratic" in result.verdict_detail["message"]


@pytest.mark.parametrize("seed", range(3))
def test_an_outlier_elsewhere_is_still_found_beside_a_lone_centre_run(seed):
    table, factors, centre_run = _lone_centre_table(seed, 3)
    rng = np.random.default_rng(100 + seed)
    row = int(rng.choice(np.flatnonzero(table["run"].to_numpy() != centre_run)))
    table.loc[row, "y"] += 30.0 * rng.choice([-1, 1])  # 30 noise SDs (the generator's noise is 1)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        result = criticize(table, factors, "y", n_null=499)
    assert result.findings and result.findings[0].cause == "outlier"
    assert int(result.findings[0].detail) == int(table.loc[row, "run"])


def test_a_well_replicated_centre_keeps_its_q2():
    table, _ = ccd_table(0, 2, "clean", 0.0)
    fit = fit_response(table, FACTORS[2], "y")
    assert np.isfinite(fit.statistics().q2) and not fit.fitted_exactly.any()
