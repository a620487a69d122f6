"""A fit's user-facing outputs against least squares written out with numpy and scipy, in a parametrisation of
its own (one intercept per block, the block-averaged surface a linear combination of them): the coefficient
table (coded estimates, standard errors, t and p), the predictor's surface in actual units and its standard
errors of the mean and of a new run, the residual variance and degrees of freedom, every block's shift and
standard error, the influence table (fitted values, residuals, leave-one-out residuals, leverage, externally
studentised residuals, Cook's distance) and the stored frame read back, over generated tables of one to three
factors (one of them on a log scale or none), one to three blocks and run counts above the parameters."""

from __future__ import annotations

import numpy as np
import pandas as pd
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy import stats

from demid.design import model_matrix, model_units, quadratic_terms
from demid.surrogate import fit_response, surrogates_from_frame, surrogates_to_frame

SETTINGS = settings(max_examples=10, deadline=None, derandomize=True)


def _table(rng, k, n, n_blocks, log_first):
    lower = rng.uniform(0.5, 2.0, k)
    upper = lower + rng.uniform(1.0, 5.0, k)
    x = rng.uniform(lower, upper, size=(n, k))
    factors = [f"f{i}" for i in range(k)]
    table = pd.DataFrame(x, columns=factors)
    table.insert(0, "run", rng.permutation(np.arange(1, n + 1)))
    z = model_units(x, factors, ("f0",) if log_first else ())
    table["y"] = 5 + z @ rng.normal(size=k) + 0.3 * (z ** 2).sum(axis=1) + rng.normal(scale=0.4, size=n)
    blocks = None
    if n_blocks > 1:
        blocks = np.array([f"b{i % n_blocks}" for i in range(n)], dtype=object)
        rng.shuffle(blocks)
        table["block"] = blocks
        table["y"] += np.array([{"b0": 0.0, "b1": 1.5, "b2": -2.0}[b] for b in blocks])
    return table, factors, blocks


def _written_out(fit, table, factors, blocks):
    """Least squares with one intercept per block and the polynomial's other terms, in coded units."""
    terms = quadratic_terms(len(factors))
    coded = fit.coding.to_coded(model_units(table[factors].to_numpy(), factors, fit.log_factors))
    poly = model_matrix(coded, terms)[:, 1:]
    levels = list(dict.fromkeys(blocks)) if blocks is not None else ["all"]
    labels = blocks if blocks is not None else np.array(["all"] * len(table), dtype=object)
    onehot = np.column_stack([(labels == lv).astype(float) for lv in levels])
    x = np.column_stack([onehot, poly])
    y = table["y"].to_numpy()
    n, q = x.shape
    theta = np.linalg.solve(x.T @ x, x.T @ y)
    resid = y - x @ theta
    s2 = resid @ resid / (n - q)
    cov = s2 * np.linalg.inv(x.T @ x)
    # the block-averaged polynomial's coefficients: the mean of the block intercepts, then the other terms
    b = len(levels)
    to_poly = np.zeros((len(terms), q))
    to_poly[0, :b] = 1.0 / b
    to_poly[1:, b:] = np.eye(len(terms) - 1)
    hat = np.diag(x @ np.linalg.solve(x.T @ x, x.T))
    return dict(x=x, y=y, theta=theta, resid=resid, s2=s2, cov=cov, to_poly=to_poly, levels=levels, b=b, n=n, q=q,
                hat=hat, coded=coded, terms=terms)


@given(seed=st.integers(0, 10_000), k=st.integers(1, 3), n_blocks=st.integers(1, 3), log_first=st.booleans(),
       extra=st.integers(3, 12))
@SETTINGS
def test_every_output_of_a_fit_against_least_squares_written_out(seed, k, n_blocks, log_first, extra):
    rng = np.random.default_rng(seed)
    n = len(quadratic_terms(k)) + n_blocks + extra
    table, factors, blocks = _table(rng, k, n, n_blocks, log_first)
    fit = fit_response(table, factors, "y", log_factors=("f0",) if log_first else ())
    w = _written_out(fit, table, factors, blocks)
    beta, cov_poly = w["to_poly"] @ w["theta"], w["to_poly"] @ w["cov"] @ w["to_poly"].T
    se = np.sqrt(np.diag(cov_poly))
    df = w["n"] - w["q"]

    coef = fit.coefficients()
    assert list(coef["term"]) == fit.term_names and (coef["response"] == "y").all()
    np.testing.assert_allclose(coef["coefficient_coded"], beta, rtol=1e-8, atol=1e-10)
    np.testing.assert_allclose(coef["std_err_coded"], se, rtol=1e-7)
    np.testing.assert_allclose(coef["t_value"], beta / se, rtol=1e-7, atol=1e-9)
    np.testing.assert_allclose(coef["p_value"], 2 * stats.t.sf(np.abs(beta / se), df), rtol=1e-6, atol=1e-12)

    sur = fit.surrogate()
    probe = table[factors].to_numpy() * rng.uniform(0.9, 1.1, size=(n, k))
    coded_probe = fit.coding.to_coded(model_units(probe, factors, fit.log_factors))
    m = model_matrix(coded_probe, w["terms"])
    np.testing.assert_allclose(sur.predict(probe), m @ beta, rtol=1e-9, atol=1e-9)
    se_mean = np.sqrt(np.einsum("ij,jk,ik->i", m, cov_poly, m))
    np.testing.assert_allclose(sur.se_mean(probe), se_mean, rtol=1e-6)
    # in chunks of fewer points than the probe (a large grid is evaluated chunk by chunk): the same values
    np.testing.assert_allclose(sur.se_mean(probe, chunk=k + 1), se_mean, rtol=1e-6)
    np.testing.assert_allclose(sur.predict(probe, chunk=k + 1), m @ beta, rtol=1e-9, atol=1e-9)
    np.testing.assert_allclose(sur.se_prediction(probe), np.sqrt(se_mean ** 2 + w["s2"]), rtol=1e-6)
    assert sur.resid_var == pytest.approx(w["s2"], rel=1e-9) and sur.resid_df == df

    effects = fit.block_effects()
    if n_blocks == 1:
        assert effects == {}
    else:
        assert list(effects) == w["levels"]
        for j, label in enumerate(w["levels"]):
            contrast = np.zeros(w["q"])
            contrast[:w["b"]] = -1.0 / w["b"]
            contrast[j] += 1.0
            shift, shift_se = effects[label]
            assert shift == pytest.approx(contrast @ w["theta"], rel=1e-7, abs=1e-9)
            assert shift_se == pytest.approx(np.sqrt(contrast @ w["cov"] @ contrast), rel=1e-6)

    infl = fit.influence()
    e, h = w["resid"], w["hat"]
    s2_without = (e @ e - e ** 2 / (1 - h)) / (df - 1)
    np.testing.assert_array_equal(infl["run"], table["run"])
    np.testing.assert_allclose(infl["observed"], w["y"])
    np.testing.assert_allclose(infl["fitted"], w["y"] - e, rtol=1e-9)
    np.testing.assert_allclose(infl["residual"], e, rtol=1e-7, atol=1e-9)
    np.testing.assert_allclose(infl["leverage"], h, rtol=1e-8)
    np.testing.assert_allclose(infl["loo_residual"], e / (1 - h), rtol=1e-7, atol=1e-9)
    np.testing.assert_allclose(infl["student_resid"], e / np.sqrt(s2_without * (1 - h)), rtol=1e-6, atol=1e-9)
    np.testing.assert_allclose(infl["cooks_d"], e ** 2 * h / (w["q"] * w["s2"] * (1 - h) ** 2), rtol=1e-6,
                               atol=1e-12)
    assert fit.press == pytest.approx(np.sum((e / (1 - h)) ** 2), rel=1e-8)

    back = surrogates_from_frame(surrogates_to_frame([fit]), factors)["y"]
    np.testing.assert_allclose(back.predict(probe), sur.predict(probe), rtol=1e-12, atol=1e-12)
    np.testing.assert_allclose(back.se_mean(probe), se_mean, rtol=1e-6)
    assert (back.resid_var, back.resid_df, back.log_factors) == (sur.resid_var, df, sur.log_factors)
