"""The catalogue's tests at their limits (criticism.catalogue): lack of fit against the replicated runs is tested
with as little as one pure-error and one lack-of-fit degree of freedom (against the classical ANOVA written out
here) and not at all with none of either, nor when the replicates agree to the print; a round rejects a member
whose family-wise p equals the family level exactly, strongest evidence first, ties in the order of the
catalogue."""

from __future__ import annotations

from itertools import product

import numpy as np
import pandas as pd
import pytest
from scipy import stats

from demid.criticism.catalogue import CAUSES, Hypothesis, Round
from demid.criticism.level1 import prepare_data
from demid.criticism.models import Model, ModelForm
from tests.criticism.test_lack_of_fit_whole import lack_of_fit_by_hand

GRID = [(a, b) for a, b in product((-1.0, 0.0, 1.0), repeat=2)]


def _table(points, repeats, seed, print_digits=None):
    rng = np.random.default_rng(seed)
    rows = list(points) + [points[i] for i in repeats]
    a = np.array([p[0] for p in rows])
    b = np.array([p[1] for p in rows])
    y = 5.0 + a - 0.3 * b ** 2 + 0.6 * a ** 2 * b + 0.2 * rng.standard_normal(len(a))
    if print_digits is not None:
        y = np.round(5.0 + a - 0.3 * b ** 2 + 0.6 * a ** 2 * b, print_digits)  # misfit, replicates alike
    return pd.DataFrame({"run": np.arange(1, len(a) + 1), "a": a, "b": b, "y": y})


def _lack_of_fit(table):
    data, _ = prepare_data(table, ["a", "b"], "y", 1.0, (), None)
    model = Model(data, ModelForm())
    return [h for h in Round(data, model, 19, np.random.default_rng(0)).hypotheses if h.cause == "lack_of_fit"]


@pytest.mark.parametrize("points,repeats,df", [
    (GRID[:7], (0, 3), (1, 2)),              # 7 points: one lack-of-fit df, two pure-error df
    (GRID + [(0.5, 0.5)], (4,), (4, 1)),     # 10 points and one replicate: one pure-error df
    (GRID, (0, 4, 8), (3, 3)),
    (GRID[1:7], (0, 2, 4), None),            # 6 points for 6 terms: no lack-of-fit df
    (GRID, (), None)])                      # no replicate: no pure error
@pytest.mark.parametrize("seed", [0, 1])
def test_lack_of_fit_needs_one_degree_of_freedom_of_each_kind(points, repeats, df, seed):
    table = _table(points, repeats, seed)
    a, b, y = (table[c].to_numpy() for c in ("a", "b", "y"))
    x = np.column_stack([np.ones_like(a), a, b, a * b, a * a, b * b])
    assert np.linalg.matrix_rank(x) == 6 and len(y) - 6 >= 3
    found = _lack_of_fit(table)
    if df is None:
        assert found == []
        return
    (h,) = found
    f, df_lof, df_pe = lack_of_fit_by_hand(table)
    assert (df_lof, df_pe) == df and h.info["df"] == [df_lof, df_pe]
    assert h.statistic == pytest.approx(f, rel=1e-8)
    assert h.logp == pytest.approx(stats.f.logsf(f, df_lof, df_pe), rel=1e-8, abs=1e-12)


def test_replicates_that_agree_to_the_print_leave_lack_of_fit_untested():
    assert _lack_of_fit(_table(GRID, (0, 4, 8), 0, print_digits=3)) == []


@pytest.mark.parametrize("alpha", [0.05, 0.01, 0.1])
def test_a_member_at_exactly_the_family_level_is_rejected_strongest_first(alpha):
    rnd = Round.__new__(Round)
    causes = ["step", "outlier", "drift", "missing_term", "heteroscedasticity"]
    logps = [-6.0, -9.0, -9.0, -4.0, -7.0]  # the outlier and drift tie: the catalogue's order decides
    p_family = [alpha, alpha / 3, alpha / 2, float(np.nextafter(alpha, 1.0)), alpha / 10]
    rnd.hypotheses = [Hypothesis(c, None, logp=lp, p_family=p) for c, lp, p in zip(causes, logps, p_family)]
    rnd.hypotheses.append(Hypothesis("lack_of_fit", None, logp=-12.0, p_family=alpha))
    rejected = rnd.rejected(alpha)
    expected = sorted([h for h in rnd.hypotheses if h.cause in CAUSES and h.p_family <= alpha],
                      key=lambda h: (h.logp, CAUSES.index(h.cause)))
    assert [h.cause for h in rejected] == [h.cause for h in expected] == [
        "outlier", "drift", "heteroscedasticity", "step"]
    assert [h.cause for h in rnd.misfit(alpha)] == ["step", "outlier", "drift", "heteroscedasticity", "lack_of_fit"]
