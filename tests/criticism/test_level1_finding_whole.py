"""A level-1 finding of unequal scatter (criticism.level1's finding of a round) read whole, over replicated CCDs
whose scatter grows with one factor: the variance weight's gamma profiled here with statsmodels' WLS, and every
number the finding reports or its message quotes against it -- the spread ratio, the AICc gained, the
leave-one-out gain in percent -- with the covariates the runs do not tell apart (aliases, the sentence naming
them and the AICc margin it quotes) and the alternatives almost as likely, from the finding's own alternatives."""

from __future__ import annotations

import re

import numpy as np
import pandas as pd
import pytest
import statsmodels.api as sm
from scipy import optimize

from demid.criticism import criticize
from demid.criticism.catalogue import GAMMA_BOUND
from demid.criticism.discrimination import AMBIGUOUS_AICC
from demid.criticism.level1 import prepare_data
from demid.criticism.messages import CAUSE_WORDS
from demid.design import model_matrix, quadratic_terms
from tests.generators import FACTORS, design


def _aicc(llf: float, n: int, k: int) -> float:
    return -2 * llf + 2 * k * n / (n - k - 1)


def _scatter_table(seed: int, mean_follows: str, growth: float) -> pd.DataFrame:
    """A replicated CCD (26 runs) whose scatter grows ``growth``-fold across one factor's range; the mean
    follows that factor (so the predicted value is nearly that factor) or the other one."""
    factors, coding, coded, alpha = design(2, replicates=3)
    rng = np.random.default_rng(seed)
    j = seed % 2
    lead = coded[:, j] if mean_follows == "same" else coded[:, 1 - j]
    y = (100 + 15 * lead + 2 * coded[:, 0] * coded[:, 1]
         + rng.normal(size=len(coded)) * growth ** (coded[:, j] / (2 * alpha)))
    table = pd.DataFrame(coding.to_actual(coded), columns=factors)
    table.insert(0, "run", rng.permutation(len(coded)) + 1)
    table["y"] = y
    return table.sort_values("run").reset_index(drop=True)


def _profiled_gamma(y: np.ndarray, x: np.ndarray, v: np.ndarray) -> tuple[float, float]:
    """(gamma, log-likelihood) of the WLS fit with weights exp(-gamma v), gamma maximising the likelihood over
    the catalogue's range of gamma."""
    def negll(g):
        return -sm.WLS(y, x, weights=np.exp(-g * v)).fit().llf
    res = optimize.minimize_scalar(negll, bounds=(-GAMMA_BOUND, GAMMA_BOUND), method="bounded", options={"xatol": 1e-9})
    return float(res.x), -float(res.fun)


@pytest.mark.parametrize("seed,mean_follows,growth", [(0, "same", 30.0), (1, "same", 30.0), (0, "other", 30.0),
                                                     (1, "same", 8.0), (2, "other", 8.0), (6, "same", 8.0)])
def test_a_scatter_findings_numbers_aliases_and_sentences(seed, mean_follows, growth):
    table = _scatter_table(seed, mean_follows, growth)
    res = criticize(table, FACTORS[2], "y", n_null=199)
    f = res.findings[0]
    assert f.cause == "heteroscedasticity"
    alternatives = f.info.get("alternatives", [])
    # covariates of the same cause within the AICc margin, best first, follow the named one as aliases
    close_scatter = [a["detail"] for a in sorted(alternatives, key=lambda a: a["aicc_vs_named"])
                     if a["cause"] == "heteroscedasticity" and a["aicc_vs_named"] <= AMBIGUOUS_AICC]
    assert f.aliases == ([f.detail] + close_scatter if close_scatter else [])
    sentence = re.search(r"The scatter follows (.+?) as well or nearly so \(AICc at most (\S+) worse\): these runs "
                         r"do not tell which; the runs proposed to confirm it are chosen to tell them apart\.",
                         f.message)
    if close_scatter:
        words = ["the predicted value" if d == "fitted" else d for d in close_scatter]
        assert sentence is not None and sentence.group(1) == ", ".join(words)
        assert float(sentence.group(2)) == AMBIGUOUS_AICC
    else:
        assert sentence is None and "as well or nearly so" not in f.message
    likely = [a for a in alternatives if a["loglik_vs_named"] > -2.0 and a["detail"] not in close_scatter]
    if likely:
        listed = "; ".join(f"{CAUSE_WORDS[a['cause']]} {a['detail']}" for a in likely)
        assert f" Almost as likely: {listed}." in f.message
    else:
        assert "Almost as likely" not in f.message

    data, _ = prepare_data(table, FACTORS[2], "y", None, ())
    y, x = table["y"].to_numpy(), model_matrix(data.coded, quadratic_terms(2))
    base = sm.OLS(y, x).fit()
    n = len(y)
    assert f.compared_runs == n
    if f.detail != "fitted":
        gamma, llf = _profiled_gamma(y, x, data.coded[:, data.factors.index(f.detail)] / data.alpha)
        ratio = np.exp(gamma)  # the scatter's sd at coded +alpha over -alpha
        assert f.info["sd_ratio"] == pytest.approx(ratio, rel=1e-4)
        assert f.delta_aicc == pytest.approx(_aicc(llf, n, x.shape[1] + 2) - _aicc(base.llf, n, x.shape[1] + 1),
                                             abs=1e-4)
    spread = re.search(r"residual spread about (\S+) times larger at the (high|low) end", f.message)
    r = f.info["sd_ratio"]
    assert (float(spread.group(1)), spread.group(2)) == (round(max(r, 1 / r), 1), "high" if r >= 1 else "low")
    base_loo = np.sqrt(np.mean((base.resid / (1 - base.get_influence().hat_matrix_diag)) ** 2))
    assert f.loo_rmse_baseline == pytest.approx(base_loo, rel=1e-9)
    ratio = f.loo_rmse_extended / base_loo
    if ratio < 0.995:
        assert int(re.search(r"cuts the leave-one-out error by (\d+) %", f.message).group(1)) == round(100 * (1 - ratio))
    elif ratio <= 1.005:
        assert "leaves the leave-one-out error unchanged" in f.message
    else:
        assert int(re.search(r"does not reduce the leave-one-out error \(\+(\d+) %\)", f.message).group(1)) == \
            round(100 * (ratio - 1))
