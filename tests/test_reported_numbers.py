"""Known answers for numbers the report prints (not only for the decisions made from them).

Each reference is computed here from its definition with statsmodels/scipy, independently of the
code under test.
"""

from __future__ import annotations

import numpy as np
import pytest
import statsmodels.api as sm
from scipy import optimize, special, stats

from demid.criticism import criticize

from .generators import FACTORS, ccd_table
from .test_criticism import quadratic_ols

GRID_STEP = 0.01  # the lambda grid the interval is read on


@pytest.mark.parametrize("seed, size", [(13, 3.0), (4, 2.5), (21, 3.0)])
def test_box_cox_lambda_and_its_interval(seed, size):
    """λ̂ maximises the profile likelihood; the 95 % interval is where the likelihood ratio in F form,
    df·(exp(LR/n) − 1), stays below F(0.95; 1, df), df = n − p − 1 (p: the quadratic's terms)."""
    table, _ = ccd_table(seed, 2, "log", size)
    finding = next(f for f in criticize(table, FACTORS[2], "y").findings if f.cause == "response_transform")
    y = table["y"].to_numpy(float)
    x = quadratic_ols(table, FACTORS[2]).model.exog
    n, df = len(y), len(y) - x.shape[1] - 1

    def profile(lam):
        return -0.5 * n * np.log(sm.OLS(special.boxcox(y, lam), x).fit().ssr / n) + (lam - 1) * np.log(y).sum()

    best = optimize.minimize_scalar(lambda v: -profile(v), bounds=(-3, 3), method="bounded",
                                    options={"xatol": 1e-6})
    lam_hat, top = best.x, -best.fun
    crit = stats.f.ppf(0.95, 1, df)

    def excess(lam):
        return df * np.expm1(2 * (top - profile(lam)) / n) - crit

    lo = optimize.brentq(excess, -3, lam_hat)
    hi = optimize.brentq(excess, lam_hat, 3)
    assert finding.info["lambda_hat"] == pytest.approx(lam_hat, abs=GRID_STEP)
    reported_lo, reported_hi = finding.info["lambda_ci"]
    # the grid's inside points: the reported ends lie within one step inside the exact ends
    assert lo - 1e-9 <= reported_lo <= lo + GRID_STEP + 1e-9
    assert hi - GRID_STEP - 1e-9 <= reported_hi <= hi + 1e-9


# --------------------------------------------------------------------------- closest approach of an empty set
def _linear_in_a(name: str, slope: float = 1.0, offset: float = 0.0):
    from demid.design import quadratic_terms
    from demid.surrogate import Surrogate

    coef = np.array([offset, slope, 0.0, 0.0, 0.0, 0.0])  # Intercept, a, b, a:b, a^2, b^2
    return Surrogate(name, ["a", "b"], quadratic_terms(2), coef, np.zeros((6, 6)), 0.0, 7)


@pytest.mark.parametrize("upper, best_a, best_error", [
    (3.0, 4.0 / 3.0, 1.0 / 3.0),   # interior: (a - 1)/1 = (2 - a)/2
    (1.2, 1.2, 0.4),               # cut by the bound: |1.2 - 2|/2
])
def test_closest_approach_of_an_empty_set(upper, best_a, best_error):
    """y1 = y2 = a with targets 1 and 2 cannot both be met within 10 %: the largest relative error is
    smallest where the two errors are equal, max(|a − 1|/1, |a − 2|/2), or at the bound."""
    from demid.sampling import Domain
    from demid.sampling.evaluate import evaluate_set

    surrogates = {"y1": _linear_in_a("y1"), "y2": _linear_in_a("y2")}
    domain = Domain(("a", "b"), (0.0, 0.0), (upper, 1.0), (False, False))
    aset = evaluate_set(surrogates, domain, ("y1", "y2"), {"y1": 1.0, "y2": 2.0}, 0.1, 101)
    assert aset.fraction == 0
    assert aset.best_error == pytest.approx(best_error, abs=1e-7)
    assert aset.best_point[0] == pytest.approx(best_a, abs=1e-6)


# --------------------------------------------------------------------------- the exact fraction's error estimate
@pytest.mark.parametrize("target, tolerance", [(0.04, 0.5), (0.09, 0.2), (0.01, 0.9)])
def test_exact_fraction_error_bounds_the_annulus_area(target, tolerance):
    """y = (a − ½)² + (b − ½)² within ε of t is an annulus of area π·t·2ε (inside the unit square):
    the reported fraction is that area to within its reported error, and the error is small."""
    from demid.design import quadratic_terms
    from demid.sampling import Domain
    from demid.sampling.evaluate import evaluate_set
    from demid.surrogate import Surrogate

    coef = np.array([0.5, -1.0, -1.0, 0.0, 1.0, 1.0])  # Intercept, a, b, a:b, a^2, b^2
    sur = Surrogate("y", ["a", "b"], quadratic_terms(2), coef, np.zeros((6, 6)), 0.0, 7)
    domain = Domain(("a", "b"), (0.0, 0.0), (1.0, 1.0), (False, False))
    aset = evaluate_set({"y": sur}, domain, ("y",), {"y": target}, tolerance, 101)
    area = np.pi * target * 2 * tolerance
    assert 0 <= aset.fraction_error <= 1e-6
    assert abs(aset.fraction - area) <= aset.fraction_error + 1e-12
    radius = np.sqrt(target * (1 + tolerance))
    np.testing.assert_allclose(aset.lower, [0.5 - radius] * 2, atol=1e-9)
    np.testing.assert_allclose(aset.upper, [0.5 + radius] * 2, atol=1e-9)


# --------------------------------------------------------------------------- the typo screen's prediction
@pytest.mark.parametrize("seed", range(3))
def test_typo_flag_prediction_and_its_error_from_the_other_runs(tmp_path, seed):
    """The flag's prediction and standard error are those of an OLS fit without the run (statsmodels'
    ``get_prediction(...).se_obs``); its studentised residual is statsmodels' external one."""
    from demid.data import read_printed, validate_material
    from demid.design import model_matrix, model_units, quadratic_terms
    from demid.transcription import likely_typos

    from .helpers import make_ccd_table
    from .test_likely_typos import _cfg

    table = make_ccd_table(lambda x: {"y": 100 + 20 * x[:, 0] - 3 * x[:, 1] + 8 * x[:, 0] ** 2},
                           [0.1, 1], [0.9, 11], noise=0.3, seed=seed, decimals=2)
    true_value = table.loc[table["run"] == 5, "y"].iloc[0]
    path = tmp_path / "t.csv"
    table.to_csv(path, index=False)
    lines = [ln if not ln.startswith("5,") else ",".join(ln.split(",")[:-1] + [f"{true_value / 10:.3f}"])
             for ln in path.read_text().splitlines()]
    path.write_text("\n".join(lines) + "\n")
    vt = validate_material("m", _cfg(path))
    (flag,) = likely_typos(vt, _cfg(path), read_printed(path, vt.table))

    data = vt.table
    x = model_matrix(vt.coding.to_coded(model_units(data[["x1", "x2"]].to_numpy(float), ["x1", "x2"], ())),
                     quadratic_terms(2))
    y = data["y"].to_numpy(float)
    i = int(np.flatnonzero(data["run"].to_numpy() == 5)[0])
    full = sm.OLS(y, x).fit()
    others = np.arange(len(y)) != i
    without = sm.OLS(y[others], x[others]).fit()
    prediction = without.get_prediction(x[i:i + 1])
    assert flag["predicted_from_other_runs"] == pytest.approx(float(prediction.predicted_mean[0]), rel=1e-9)
    assert flag["prediction_se"] == pytest.approx(float(prediction.se_obs[0]), rel=1e-9)
    assert flag["student_resid"] == pytest.approx(full.get_influence().resid_studentized_external[i], rel=1e-9)
    # flagged at the family-wise 5 % level: Bonferroni over the runs, t with n - p - 1 degrees of freedom
    assert full.outlier_test(method="bonf")[i, 2] < 0.05
