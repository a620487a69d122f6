"""Tests for demid.uncertainty against exact answers (closed forms, exact areas, statsmodels)."""

from __future__ import annotations

import numpy as np
import pandas as pd
import pytest
from numpy.testing import assert_allclose
from scipy import stats

from demid import uncertainty as unc
from demid.admissibility import Domain, admissible_set
from demid.design import ccd_points, model_matrix, quadratic_terms, rotatable_alpha
from demid.spec import MaterialSpec
from demid.story.measurements import measurement_order
from demid.surrogate import Surrogate, fit_response

SQUARE = Domain(("a", "b"), (0.0, 0.0), (1.0, 1.0))


# --------------------------------------------------------------------------- fixtures
def quadratic(coefficients, factors=("a", "b"), covariance=None, log_factors=()) -> Surrogate:
    """Exact quadratic surrogate; coefficients follow quadratic_terms order."""
    k = len(factors)
    terms = quadratic_terms(k)
    coef = np.zeros(len(terms))
    coef[:len(coefficients)] = coefficients
    cov = np.zeros((len(terms), len(terms))) if covariance is None else covariance
    return Surrogate("y", list(factors), terms, coef, cov, 0.0, 1, tuple(log_factors))


def ring(center, factors=("a", "b")) -> Surrogate:
    """y = |x - center|^2, whose level sets are circles (spheres)."""
    center = np.asarray(center, dtype=float)
    k = len(center)
    coef = np.concatenate([[np.sum(center ** 2)], -2 * center, np.zeros(k * (k - 1) // 2), np.ones(k)])
    return quadratic(coef, factors)


def linear(intercept, slopes, variance_intercept=0.0, factors=("a", "b")) -> Surrogate:
    """y = intercept + slopes . x with se_mean = sqrt(variance_intercept) everywhere."""
    k = len(factors)
    p = len(quadratic_terms(k))
    cov = np.zeros((p, p))
    cov[0, 0] = variance_intercept
    return quadratic(np.concatenate([[intercept], slopes]), factors, cov)


@pytest.fixture(scope="module")
def mortar_like():
    """Three noisy responses on a rotatable 13-run CCD, fitted by OLS (mortar-like bands)."""
    alpha = rotatable_alpha(2)
    coded = ccd_points(2, alpha, 5)
    lo, hi = np.array([0.0757, 0.5]), np.array([0.9243, 12.5])
    x = (lo + hi) / 2 + coded * (hi - lo) / (2 * alpha)
    rng = np.random.default_rng(5)
    table = pd.DataFrame(x, columns=["mu_r", "gamma"])
    table.insert(0, "run", np.arange(1, len(x) + 1))
    m, g = x.T
    table["d5"] = 110.81 - 18 * (m - 0.12) - 2.2 * (g - 6.2) + 4 * (m - 0.12) ** 2 + rng.normal(0, 1.2, len(x))
    table["d10"] = 122.45 - 24 * (m - 0.12) - 2.0 * (g - 6.2) + 6 * (m - 0.12) ** 2 + rng.normal(0, 1.9, len(x))
    table["d15"] = 131.95 - 30 * (m - 0.12) - 1.6 * (g - 6.2) + 9 * (m - 0.12) ** 2 + rng.normal(0, 1.8, len(x))
    fits = {r: fit_response(table, ["mu_r", "gamma"], r, alpha=alpha) for r in ("d5", "d10", "d15")}
    domain = Domain(("mu_r", "gamma"), tuple(lo), tuple(hi))
    targets = {"d5": 110.81, "d10": 122.45, "d15": 131.95}
    return fits, {r: f.surrogate() for r, f in fits.items()}, domain, targets


# --------------------------------------------------------------------------- sigma and se_mean
def test_se_mean_matches_statsmodels_mean_se(mortar_like):
    fits, surrogates, domain, _ = mortar_like
    points = np.random.default_rng(0).uniform(domain.lower, domain.upper, size=(25, 2))
    for name, fit in fits.items():
        exog = pd.DataFrame(model_matrix(fit.coding.to_coded(points), fit.terms), columns=fit.term_names)
        frame = fit.results.get_prediction(exog).summary_frame(alpha=0.05)
        assert_allclose(surrogates[name].predict(points), frame["mean"], rtol=1e-10)
        assert_allclose(surrogates[name].se_mean(points), frame["mean_se"], rtol=1e-8)


def test_measurement_sigma_sources():
    assert unc.measurement_sigma({"sigma": 0.4, "sigma_rel": 0.1}, 120.0) == 0.4
    assert unc.measurement_sigma({"sigma_rel": 0.01}, -200.0) == pytest.approx(2.0)
    assert unc.measurement_sigma({}, 50.0, default_rel=0.01) == pytest.approx(0.5)
    assert unc.measurement_sigma(None, 50.0) == 0.0
    sigma, basis = unc.measurement_sigmas({"a": {"sigma_rel": 0.02}, "b": {}}, ["a", "b"],
                                          {"a": 10.0, "b": 100.0}, tolerance=0.02)
    assert sigma == pytest.approx({"a": 0.2, "b": 1.0})
    assert basis["a"].startswith("config sigma_rel") and "tolerance/2" in basis["b"]


# --------------------------------------------------------------------------- plausible sets
def test_plausibility_field_is_exactly_the_widened_band(mortar_like):
    """|ŷ - y*| <= z sqrt(se² + σ² + δ²): with σ configured the tolerance plays no part."""
    _, surrogates, domain, targets = mortar_like
    points = np.random.default_rng(1).uniform(domain.lower, domain.upper, size=(5000, 2))
    yhat = surrogates["d15"].predict(points)
    se = surrogates["d15"].se_mean(points)
    band = 0.02 * targets["d15"]
    for sigma, delta in ((0.7, 0.0), (0.7, 0.4), (None, 0.0), (None, 0.5)):
        field = unc.PlausibilityField(surrogates["d15"], targets["d15"], 0.02, 2.0, sigma=sigma, discrepancy=delta)
        s = band / 2.0 if sigma is None else sigma  # no sigma: the tolerance band is the 2-sigma band
        plausible = np.abs(yhat - targets["d15"]) <= 2.0 * np.sqrt(se ** 2 + s ** 2 + delta ** 2)
        assert np.array_equal(np.abs(field.predict(points) - targets["d15"]) <= band, plausible)
        assert 0.02 < plausible.mean() < 1


def test_plausible_set_contains_strict_set_without_configured_sigma(mortar_like):
    _, surrogates, domain, targets = mortar_like
    for observables in (["d15"], ["d5", "d10", "d15"]):
        strict = admissible_set(surrogates, domain, observables, targets, 0.02, 101)
        plausible = unc.plausible_admissible_set(surrogates, domain, observables, targets, 0.02, 101, z=2.0)
        assert plausible.fraction > strict.fraction > 0
        assert np.all(plausible.mask[strict.mask])
        assert np.all(plausible.lower <= strict.lower) and np.all(plausible.upper >= strict.upper)
        same = unc.plausible_admissible_set(surrogates, domain, observables, targets, 0.02, 101, z=0.0)
        assert same.fraction == strict.fraction


def test_plausible_set_with_exact_surrogate_and_sigma_equals_strict_set_at_z_sigma():
    """No surrogate error: the plausible band is z·σ alone, not ε + z·σ (no double counting)."""
    sur = {"y": ring([0.47, 0.52])}
    target, eps, sigma, z = 0.09, 0.02, 0.0009, 2.0
    plausible = unc.plausible_admissible_set(sur, SQUARE, ["y"], {"y": target}, eps, 81, z=z, sigma={"y": sigma})
    same = admissible_set(sur, SQUARE, ["y"], {"y": target}, z * sigma / target, 81)
    assert plausible.fraction == pytest.approx(same.fraction, rel=1e-12)
    assert plausible.fraction == pytest.approx(2 * np.pi * target * (z * sigma / target), rel=2e-3)
    # without sigma the tolerance is the band: the plausible set is the strict one
    alone = unc.plausible_admissible_set(sur, SQUARE, ["y"], {"y": target}, eps, 81, z=z)
    strict = admissible_set(sur, SQUARE, ["y"], {"y": target}, eps, 81)
    assert alone.fraction == pytest.approx(strict.fraction, rel=1e-12)


def test_robust_identifiability_frame_contract(mortar_like):
    _, surrogates, domain, targets = mortar_like
    scenarios = {"d15_only": (["d15"], 0.02), "full_sequence": (["d5", "d10", "d15"], 0.02)}
    frame = unc.plausible_identifiability_frame(surrogates, domain, scenarios, targets, 61, z=2.0)
    assert list(frame.columns[:13]) == unc.PLAUSIBLE_COLUMNS
    assert len(frame) == 4
    assert (frame["strict_fraction_error_pct"] < 0.01 * frame["strict_fraction_pct"]).all()
    assert (frame["robust_fraction_pct"] >= frame["strict_fraction_pct"]).all()
    assert (frame["robust_width"] >= frame["strict_width"] - 1e-12).all()


# --------------------------------------------------------------------------- tolerance sweep
def test_tolerance_sweep_is_monotone(mortar_like):
    _, surrogates, domain, targets = mortar_like
    scenarios = {"d15_only": (["d15"], 0.02), "full_sequence": (["d5", "d10", "d15"], 0.025)}
    frame = unc.tolerance_sweep(surrogates, domain, scenarios, targets, [0.005, 0.01, 0.02, 0.05, 0.1], 61)
    assert list(frame.columns[:8]) == unc.SWEEP_COLUMNS
    for name, rows in frame.groupby("scenario"):
        first = rows.drop_duplicates("tolerance")
        assert first["tolerance"].is_monotonic_increasing
        assert np.all(np.diff(first["feasible_fraction_pct"]) >= 0)
        assert (first["fraction_error_pct"] < 0.05 * first["feasible_fraction_pct"] + 1e-9).all()
        for _, per_factor in rows.groupby("factor"):
            widths = per_factor["width"].to_numpy()
            widths = widths[np.isfinite(widths)]
            assert np.all(np.diff(widths) >= -1e-12)
    assert 0.025 in set(frame.loc[frame["scenario"] == "full_sequence", "tolerance"])
    fig = unc.tolerance_sweep_figure(frame, "mortar-like")
    _assert_sweep_figure_shows(fig, frame)


def _assert_sweep_figure_shows(fig, frame):
    """Panel 1: fraction vs tolerance per scenario; one panel per factor: width vs tolerance."""
    factors = list(dict.fromkeys(frame["factor"]))
    assert len(fig.axes) == 1 + len(factors)
    for k, (_, rows) in enumerate(frame.groupby("scenario", sort=False)):
        first = rows.drop_duplicates("tolerance").sort_values("tolerance")
        keep = first["feasible_fraction_pct"].to_numpy() > 0
        line = fig.axes[0].lines[k]
        assert_allclose(line.get_xdata(), 100 * first["tolerance"].to_numpy()[keep])
        assert_allclose(line.get_ydata(), first["feasible_fraction_pct"].to_numpy()[keep])
        for ax, factor in zip(fig.axes[1:], factors):
            sub = rows[rows["factor"] == factor].sort_values("tolerance")
            assert_allclose(ax.lines[k].get_ydata(), sub["width"].to_numpy())


def _assert_posterior_figure_shows(fig, posteriors):
    for k, post in enumerate(posteriors.values()):
        for i, ax in enumerate(fig.axes):
            assert_allclose(ax.lines[k].get_xdata(), post.axes_actual[i])
            assert_allclose(ax.lines[k].get_ydata(), post.marginals[i])


# --------------------------------------------------------------------------- posterior
def test_linear_gaussian_posterior_matches_truncated_normal():
    """y = 2 + 3a with sigma and se_mean constant: the a-posterior is a truncated normal."""
    domain = Domain(("a", "b"), (0.0, 0.0), (10.0, 1.0))
    sigma, var_mean = 1.5, 0.25
    sur = {"y": linear(2.0, [3.0, 0.0], var_mean)}
    mu = 0.8  # close to the lower bound, so the truncation matters
    sd = np.sqrt(sigma ** 2 + var_mean) / 3.0
    post = unc.grid_posterior(sur, domain, ["y"], {"y": 2.0 + 3.0 * mu}, {"y": sigma}, 401)
    exact = stats.truncnorm((0.0 - mu) / sd, (10.0 - mu) / sd, loc=mu, scale=sd)
    assert_allclose([post.credible_lower[0], post.credible_upper[0]], exact.ppf([0.025, 0.975]), rtol=2e-4)
    assert post.mean[0] == pytest.approx(exact.mean(), rel=1e-4)
    kl_bits = (np.log(10.0) - exact.entropy()) / np.log(2)
    assert post.information_gain_bits == pytest.approx(kl_bits, rel=1e-4)
    assert post.information_gain_error_bits < 1e-3
    # b is not observed: its marginal is the uniform prior
    assert_allclose([post.credible_lower[1], post.credible_upper[1], post.mean[1]], [0.025, 0.975, 0.5], atol=1e-9)
    assert_allclose(post.marginals[1], 1.0, atol=1e-9)


def test_information_gain_adds_for_independent_observables():
    domain = Domain(("a", "b"), (-5.0, -5.0), (5.0, 5.0))
    surrogates = {"p": linear(0.0, [1.0, 0.0]), "q": linear(0.0, [0.0, 2.0])}
    surrogates["q"].response = "q"
    targets, sigma = {"p": 0.3, "q": -1.0}, {"p": 0.4, "q": 0.6}
    posts = unc.subset_posteriors(surrogates, domain, ["p", "q"], targets, sigma, 301)
    wide = [(np.log(10.0) - stats.norm(scale=s).entropy()) / np.log(2) for s in (0.4, 0.3)]
    assert posts[("p",)].information_gain_bits == pytest.approx(wide[0], rel=1e-6)
    assert posts[("q",)].information_gain_bits == pytest.approx(wide[1], rel=1e-6)
    assert posts[("p", "q")].information_gain_bits == pytest.approx(sum(wide), rel=1e-6)
    frame = unc.information_gain_frame(posts)
    assert list(frame.columns[:7]) == unc.INFORMATION_GAIN_COLUMNS
    assert len(frame) == 6
    fig = unc.posterior_figure(posts, "independent")
    _assert_posterior_figure_shows(fig, posts)
    # p alone: a normal density of sd 0.4 around 0.3 in a (b stays flat at the prior 1/10)
    a = posts[("p",)].axes_actual[0]
    assert_allclose(fig.axes[0].lines[0].get_ydata(), stats.norm(0.3, 0.4).pdf(a), rtol=1e-3, atol=1e-6)
    assert_allclose(fig.axes[1].lines[0].get_ydata(), 0.1, rtol=1e-9)


def test_log_factor_posterior_quantiles_in_actual_units():
    """Prior uniform in log10(b); y linear in log10(b): quantiles are 10**(normal quantiles)."""
    domain = Domain(("a", "b"), (0.0, 1e-3), (1.0, 1e1), (False, True))
    sur = {"y": quadratic([0.0, 0.0, 1.0], ("a", "b"), log_factors=("b",))}
    post = unc.grid_posterior(sur, domain, ["y"], {"y": -1.0}, {"y": 0.2}, 201)
    assert_allclose([post.credible_lower[1], post.credible_upper[1]],
                    10.0 ** stats.norm(-1.0, 0.2).ppf([0.025, 0.975]), rtol=1e-4)
    assert post.mean[1] == pytest.approx(10.0 ** -1.0 * np.exp((0.2 * np.log(10)) ** 2 / 2), rel=1e-4)


def test_log_factor_marginal_is_tabulated_at_actual_values():
    """The marginal table gives a log factor's axis in actual units (10 ** the log10 grid) and its density per
    log10 unit: here the normal density of sd 0.2 around -1 (the bounds lie 10 sd away)."""
    domain = Domain(("a", "b"), (0.0, 1e-3), (1.0, 1e1), (False, True))
    sur = {"y": quadratic([0.0, 0.0, 1.0], ("a", "b"), log_factors=("b",))}
    post = unc.grid_posterior(sur, domain, ["y"], {"y": -1.0}, {"y": 0.2}, 201)
    frame = post.marginal_frame()
    b = frame[frame["factor"] == "b"]
    assert_allclose(b["value"], 10.0 ** np.linspace(-3.0, 1.0, 201), rtol=1e-12)
    assert_allclose(b["density"], stats.norm(-1.0, 0.2).pdf(np.linspace(-3.0, 1.0, 201)), rtol=1e-3, atol=1e-9)
    assert_allclose(frame.loc[frame["factor"] == "a", "value"], np.linspace(0.0, 1.0, 201), rtol=1e-12)


def test_gaussian_loglik_is_the_normal_log_density_with_the_surrogates_error():
    """log N(y*; yhat(x), sigma^2 + se(x)^2), against scipy's normal log density."""
    sur = linear(0.5, [2.0, -1.0], variance_intercept=0.09)
    points = np.array([[0.0, 0.0], [0.3, 0.8], [1.0, 0.1]])
    scale = np.sqrt(0.4 ** 2 + sur.se_mean(points) ** 2)
    assert_allclose(unc.gaussian_loglik(sur, points, 1.2, 0.4),
                    stats.norm(sur.predict(points), scale).logpdf(1.2), rtol=1e-12)


def test_qmc_posterior_draws_the_requested_number_of_points_in_eight_scrambles(monkeypatch):
    """Above three factors the posterior weighs sobol_points prior points: 8 scrambles of sobol_points / 8."""
    from scipy.stats import qmc

    drawn = []
    base2 = qmc.Sobol.random_base2

    def spy(self, m):
        drawn.append(m)
        return base2(self, m)

    monkeypatch.setattr(qmc.Sobol, "random_base2", spy)
    factors = ("a", "b", "c", "d")
    domain = Domain(factors, (0.0,) * 4, (1.0,) * 4)
    sur = {"y": linear(2.0, [3.0, 0.0, 0.0, 0.0], 0.25, factors)}
    unc.subset_posteriors(sur, domain, ["y"], {"y": 3.0}, {"y": 1.5}, 11, sobol_points=2 ** 12)
    assert drawn == [9] * 8  # 2^9 = 2^12 / 8


def test_zero_variance_likelihood_is_rejected():
    with pytest.raises(ValueError, match="sigma"):
        unc.grid_posterior({"y": ring([0.5, 0.5])}, SQUARE, ["y"], {"y": 0.1}, {"y": 0.0}, 21)


# --------------------------------------------------------------------------- ranking and advice
def test_ranking_and_advice():
    domain = Domain(("a", "b"), (-5.0, -5.0), (5.0, 5.0))
    surrogates = {"p": linear(10.0, [1.0, 0.0]), "q": linear(10.0, [0.0, 2.0]), "w": linear(10.0, [0.1, 0.1])}
    for name, sur in surrogates.items():
        sur.response = name
    targets = {"p": 10.3, "q": 9.0, "w": 10.0}
    sigma = {o: 0.05 * targets[o] for o in targets}
    ranking = unc.rank_observable_sets(surrogates, domain, ["p", "q", "w"], targets, sigma, 0.1, 101)
    assert list(ranking.columns[:5]) == unc.RANKING_COLUMNS
    assert len(ranking) == 7
    assert ranking["rank"].tolist() == list(range(1, 8))
    assert ranking["observables"].iloc[0] == "p+q+w"
    assert np.all(np.diff(ranking["information_gain_bits"]) <= 0)
    row = ranking.set_index("observables").loc["p+q"]
    frac = ranking.set_index("observables")["feasible_fraction_pct"]
    assert row["best_subset"] in ("p", "q")
    assert row["contraction_pct_vs_best_subset"] == pytest.approx(
        100 * (1 - frac["p+q"] / min(frac["p"], frac["q"])))
    lines = measurement_order(ranking, labels={"q": "shape"})
    assert lines[0].startswith("As a first measurement, shape")
    assert any(line.startswith("From p, adding shape gains") and "shrinks the admissible fraction" in line
               for line in lines)
    assert len(lines) == 1 + 3 + 3


# --------------------------------------------------------------------------- numerical accuracy
def test_plane_band_fraction_matches_sampling():
    rng = np.random.default_rng(3)
    for d in (2, 3):
        center = rng.normal(0, 0.5, 6)
        increments = rng.normal(0, 1.0, (d, 6))
        increments[0, 0] = 1e-9  # nearly flat along one axis
        exact = unc.plane_band_fraction(center, increments, 0.3)
        u = (np.stack(np.meshgrid(*[(np.arange(200 if d == 2 else 60) + 0.5) / (200 if d == 2 else 60) - 0.5]
                                  * d, indexing="ij")).reshape(d, -1))
        sampled = [np.mean(np.abs(c + inc @ u) <= 0.3) for c, inc in zip(center, increments.T)]
        assert_allclose(exact, sampled, atol=0.01 if d == 3 else 0.005)


@pytest.mark.parametrize("fraction", [1e-2, 1e-3, 1e-4])
def test_fraction_with_error_meets_target_on_annulus(fraction):
    r0 = 0.3
    eps = fraction / (2 * np.pi * r0 ** 2)  # annulus area pi r0^2 (1+eps) - pi r0^2 (1-eps)
    rng = np.random.default_rng(11)
    for _ in range(3):
        sur = {"y": ring(0.5 + rng.uniform(-0.05, 0.05, 2))}
        est = unc.fraction_with_error(sur, SQUARE, ["y"], {"y": r0 ** 2}, eps, 81)
        true_error = abs(est.fraction - fraction)
        assert true_error / fraction <= 0.02
        assert est.error >= true_error
        assert est.relative_error <= 0.02
        assert est.evaluations < 15_000


def test_fraction_with_error_reports_grid_error_and_3d_shell():
    sur = {"y": ring([0.5, 0.48, 0.51], ("a", "b", "c"))}
    cube = Domain(("a", "b", "c"), (0.0, 0.0, 0.0), (1.0, 1.0, 1.0))
    eps, target = 0.05, 0.09
    exact = 4 / 3 * np.pi * target ** 1.5 * ((1 + eps) ** 1.5 - (1 - eps) ** 1.5)
    grid = admissible_set(sur, cube, ["y"], {"y": target}, eps, 31)
    est = unc.fraction_with_error(sur, cube, ["y"], {"y": target}, eps, 31, reference=grid)
    assert abs(est.fraction - exact) <= est.error <= 0.02 * exact
    assert abs(est.grid_fraction - exact) <= est.grid_error


def test_polish_spans_recovers_exact_annulus_extent():
    center, r0, eps = np.array([0.43, 0.56]), 0.2, 0.1
    sur = {"y": ring(center)}
    aset = admissible_set(sur, SQUARE, ["y"], {"y": r0 ** 2}, eps, 41)
    lower, upper = unc.polish_spans(sur, SQUARE, ["y"], {"y": r0 ** 2}, eps, aset)
    outer = r0 * np.sqrt(1 + eps)
    assert_allclose(lower, center - outer, atol=1e-7)
    assert_allclose(upper, center + outer, atol=1e-7)
    assert np.all(lower <= aset.lower) and np.all(upper >= aset.upper)
    assert np.max(np.abs(aset.lower - (center - outer))) > 1e-4  # the grid alone is visibly off


def test_polish_spans_thin_set_without_admissible_nodes():
    """A thin annulus that the 11-point grid nodes miss: starts come from the least-violating nodes."""
    center, r0, eps = np.array([0.503, 0.4977]), 0.3, 0.002
    sur = {"y": ring(center)}
    aset = admissible_set(sur, SQUARE, ["y"], {"y": r0 ** 2}, eps, 11)
    assert aset.n_admissible_nodes == 0 and aset.fraction > 0 and np.isfinite(aset.upper).all()
    outer = r0 * np.sqrt(1 + eps)
    # the grid's spans come from admissible sub-points: inside the exact extent (polishing widens them)
    assert np.all(aset.lower >= center - outer) and np.all(aset.upper <= center + outer)
    lower, upper = unc.polish_spans(sur, SQUARE, ["y"], {"y": r0 ** 2}, eps, aset)
    assert_allclose(upper, center + outer, atol=1e-7)
    assert_allclose(lower, center - outer, atol=1e-7)


@pytest.mark.parametrize("eps", [1.0, 0.5])
def test_sobol_interval_covers_exact_4d_ball_and_shell(eps):
    factors = ("a", "b", "c", "d")
    domain = Domain(factors, (0.0,) * 4, (1.0,) * 4)
    sur = {"y": ring([0.5, 0.5, 0.49, 0.52], factors)}
    target = 0.09
    exact = np.pi ** 2 / 2 * target ** 2 * ((1 + eps) ** 2 - max(1 - eps, 0.0) ** 2)
    covered = 0
    for seed in range(20):
        res = unc.sobol_fraction(sur, domain, ["y"], {"y": target}, eps, 2 ** 16, seed, polish=seed == 19)
        covered += res.ci_lower <= exact <= res.ci_upper
        assert res.ci_upper - res.ci_lower < 0.05 * exact
    assert covered >= 17  # nominal 95 %: P(covered <= 16 of 20) is 1.6 %
    assert res.evaluations == 2 ** 16 and res.points_per_replicate == 2 ** 12
    assert res.upper[0] == pytest.approx(0.5 + np.sqrt(target * (1 + eps)), abs=1e-7)  # polished
    assert res.lower[3] == pytest.approx(0.52 - np.sqrt(target * (1 + eps)), abs=1e-7)


def test_qmc_posterior_above_three_factors_matches_truncated_normal():
    factors = ("a", "b", "c", "d")
    domain = Domain(factors, (0.0, 0.0, 0.0, 0.0), (10.0, 1.0, 1.0, 1.0))
    sur = {"y": linear(2.0, [3.0, 0.0, 0.0, 0.0], 0.25, factors)}
    mu, sd = 0.8, np.sqrt(1.5 ** 2 + 0.25) / 3.0
    exact = stats.truncnorm((0.0 - mu) / sd, (10.0 - mu) / sd, loc=mu, scale=sd)
    post = unc.subset_posteriors(sur, domain, ["y"], {"y": 2.0 + 3.0 * mu}, {"y": 1.5}, 51, seed=1)[("y",)]
    assert post.information_gain_bits == pytest.approx((np.log(10.0) - exact.entropy()) / np.log(2), rel=1e-4)
    assert post.information_gain_error_bits < 1e-3
    assert_allclose([post.credible_lower[0], post.credible_upper[0]], exact.ppf([0.025, 0.975]), atol=2e-3)
    assert post.mean[0] == pytest.approx(exact.mean(), rel=1e-4)
    assert_allclose(post.mean[1:], 0.5, atol=1e-3)


# --------------------------------------------------------------------------- one material end to end
def _material_cfg(factors: dict, responses: dict, scenarios: dict) -> MaterialSpec:
    return MaterialSpec.from_material("m", {"design": {"type": "ccd"}, "factors": factors, "responses": responses,
                                            "scenarios": scenarios})


def test_analyse_material_two_factors(mortar_like):
    _, surrogates, domain, targets = mortar_like
    cfg = _material_cfg(
        {f: {"lower": lo, "upper": hi, "label": f.upper()} for f, lo, hi in zip(domain.factors, domain.lower,
                                                                                 domain.upper)},
        {"d5": {"target": targets["d5"], "sigma": 0.5}, "d10": {"target": targets["d10"]},
         "d15": {"target": targets["d15"], "sigma_rel": 0.004, "label": "d_15"}},
        {"d15_only": {"observables": ["d15"], "tolerance": 0.02},
         "full_sequence": {"observables": ["d5", "d10", "d15"], "tolerance": 0.02, "label": "all three sizes"}})
    result = unc.analyse_material(surrogates, cfg, tolerances=[0.01, 0.05],
                                  sizes={"plausible": 61, "sweep": 41, "posterior": 61})
    # the legend texts: the configured label of each labelled scenario, none for a scenario named by its key
    assert result.scenario_labels == {"full_sequence": "all three sizes"}
    assert list(result.plausible.columns[:13]) == unc.PLAUSIBLE_COLUMNS and len(result.plausible) == 4
    assert set(result.sweep["tolerance"]) == {0.01, 0.02, 0.05}
    assert len(result.ranking) == 7 and len(result.information_gain) == 14
    assert "config sigma = 0.5" in result.notes[0] and "tolerance/2" in result.notes[1]
    assert "d_15" in " ".join(measurement_order(result.ranking, cfg.response_labels))
    _assert_sweep_figure_shows(result.sweep_figure("t"), result.sweep)


def test_analyse_material_four_factors_uses_sobol():
    factors = ("a", "b", "c", "d")
    sur = {"y": ring([0.5, 0.5, 0.49, 0.52], factors)}
    cfg = _material_cfg({f: {"lower": 0.0, "upper": 1.0} for f in factors}, {"y": {"target": 0.09}},
                        {"shell": {"observables": ["y"], "tolerance": 0.5}})
    result = unc.analyse_material(sur, cfg, tolerances=[0.2],
                                  sizes={"plausible": 2 ** 12, "sweep": 2 ** 10, "posterior": 21,
                                         "posterior_points": 2 ** 12})
    exact = np.pi ** 2 / 2 * 0.09 ** 2 * (1.5 ** 2 - 0.5 ** 2)
    row = result.plausible.iloc[0]
    assert row["strict_fraction_pct"] == pytest.approx(100 * exact, abs=0.6)
    # Randomised QMC is no worse than plain Monte Carlo, whose 95 % half-width with 4096 points
    # is 1.96 sqrt(p (1 - p) / 4096) = 0.83 percentage points here.
    plain_mc = 100 * 1.96 * np.sqrt(exact * (1 - exact) / 2 ** 12)
    assert 0.05 * plain_mc < row["strict_fraction_error_pct"] < plain_mc
    assert row["robust_fraction_pct"] == row["strict_fraction_pct"]  # exact surrogate: no se_mean
    assert row["strict_upper"] == pytest.approx(0.5 + np.sqrt(0.09 * 1.5), abs=1e-6)
    assert "Sobol" in result.notes[2] and result.ranking["information_gain_bits"].iloc[0] > 0


def test_robust_identifiability_frame_known_answers():
    """y1 = a and y2 = b with targets 0.5 at 10 %: the strict set is the box [0.45, 0.55]^2 (1 % of the unit
    square, widths 0.1); with sigma = 0.02 and no surrogate error the plausible band is 0.5 +- 2 sigma, the box
    [0.46, 0.54]^2 (0.64 %, widths 0.08).  Fractions and their errors are in percent; a strict set handed in is
    reported as it is when exact, recomputed exactly when it is a grid set."""
    from dataclasses import replace

    from demid.sampling.evaluate import EXACT_METHOD, evaluate_set

    surrogates = {"y1": linear(0.0, [1.0, 0.0]), "y2": linear(0.0, [0.0, 1.0])}
    surrogates["y2"].response = "y2"
    targets, scenarios = {"y1": 0.5, "y2": 0.5}, {"both": (["y1", "y2"], 0.1)}
    two = unc.plausible_identifiability_frame(surrogates, SQUARE, {"a": (["y1"], 0.1), **scenarios}, targets, 41,
                                           z=2.0, sigma={"y1": 0.02, "y2": 0.02})
    assert list(two.index) == [0, 1, 2, 3]  # one row per scenario and factor, numbered through
    frame = two[two["scenario"] == "both"].reset_index(drop=True)
    assert_allclose(frame["strict_fraction_pct"], 1.0, rtol=1e-6)
    assert_allclose(frame[["strict_lower", "strict_upper", "strict_width"]].to_numpy(), [[0.45, 0.55, 0.1]] * 2,
                    atol=1e-9)
    assert_allclose(frame[["robust_lower", "robust_upper", "robust_width"]].to_numpy(), [[0.46, 0.54, 0.08]] * 2,
                    atol=1e-6)
    plausible = unc.summarise_set(surrogates, SQUARE, ("y1", "y2"), targets, 0.1, 41, z=2.0,
                               sigma={"y1": 0.02, "y2": 0.02})
    assert frame["robust_fraction_pct"].iloc[0] == pytest.approx(100 * plausible.fraction, rel=1e-12)
    assert frame["robust_fraction_error_pct"].iloc[0] == pytest.approx(100 * plausible.error, rel=1e-12)
    assert 0 < plausible.error and abs(plausible.fraction - 0.0064) <= plausible.error + 1e-9
    exact = evaluate_set(surrogates, SQUARE, ("y1", "y2"), targets, 0.1, 41)
    assert frame["strict_fraction_error_pct"].iloc[0] == pytest.approx(100 * exact.fraction_error, rel=1e-12)
    assert frame["method"].iloc[0] == EXACT_METHOD
    # an exact strict set handed in is the one reported (here marked by a fraction of its own)
    marked = replace(exact, fraction=0.02)
    given = unc.plausible_identifiability_frame(surrogates, SQUARE, scenarios, targets, 41, z=2.0,
                                             sigma={"y1": 0.02, "y2": 0.02}, strict_sets={"both": marked})
    assert_allclose(given["strict_fraction_pct"], 2.0, rtol=1e-12)
    # a grid set on the same grid is not: the exact set is computed
    grid = unc.admissible_set(surrogates, SQUARE, ("y1", "y2"), targets, 0.1, 41)
    assert grid.exact is None
    regridded = unc.plausible_identifiability_frame(surrogates, SQUARE, scenarios, targets, 41, z=2.0,
                                                 sigma={"y1": 0.02, "y2": 0.02}, strict_sets={"both": grid})
    assert_allclose(regridded["strict_fraction_pct"], 100 * exact.fraction, rtol=1e-12)
    assert (regridded["method"] == EXACT_METHOD).all()


def test_an_even_grid_sweep_errors_are_those_of_the_set_alone():
    """The fraction's error is estimated on the odd grid (n rounded up), which an even n's predictions do not
    fill: the sweep's errors at an even n are those of the set computed alone.  (A surrogate linear in b on a
    log10 b axis is no polynomial of the search units, so the grid judges the set.)"""
    domain = Domain(("a", "b"), (0.0, 1.0), (1.0, 10.0), (False, True))
    sur = {"y": linear(0.0, [1.0, 0.1])}
    frame = unc.tolerance_sweep(sur, domain, {"s": (["y"], 0.1)}, {"y": 0.8}, [0.05], 40)
    for eps in (0.05, 0.1):
        alone = unc.summarise_set(sur, domain, ("y",), {"y": 0.8}, eps, 40, polish=False)
        rows = frame[frame["tolerance"] == eps]
        assert_allclose(rows["fraction_error_pct"], 100 * alone.error, rtol=1e-12)
        assert_allclose(rows["feasible_fraction_pct"], 100 * alone.fraction, rtol=1e-12)
        assert alone.error > 0


def test_tolerance_sweep_fractions_and_spans_are_the_closed_form_annulus_and_the_nominal_row_reuses_table_3():
    """y = |x - c|^2 with target T on the unit square: the strict set at tolerance eps is the annulus
    T(1 - eps) <= r^2 <= T(1 + eps), of area 2 pi T eps, spanning c +- sqrt(T(1 + eps)) in each factor.  The
    nominal row is the strict set passed in (Table 3's, computed at another resolution), to the last bit."""
    from demid.sampling.evaluate import evaluate_set

    surrogates, target, nominal = {"y": ring([0.5, 0.5])}, 0.04, 0.05
    strict = evaluate_set(surrogates, SQUARE, ("y",), {"y": target}, nominal, 61)
    frame = unc.tolerance_sweep(surrogates, SQUARE, {"s": (["y"], nominal)}, {"y": target}, [0.02, 0.1], 21,
                                strict_sets={"s": strict})
    rows = frame.drop_duplicates("tolerance").set_index("tolerance")
    assert list(rows.index) == [0.02, nominal, 0.1]
    for eps in rows.index:
        assert rows.loc[eps, "feasible_fraction_pct"] == pytest.approx(100 * 2 * np.pi * target * eps, rel=1e-6)
        at = frame[frame["tolerance"] == eps]
        half = np.sqrt(target * (1 + eps))
        assert_allclose(at["lower"], 0.5 - half, rtol=1e-6)
        assert_allclose(at["upper"], 0.5 + half, rtol=1e-6)
        assert_allclose(at["width"], 2 * half, rtol=1e-6)
    assert rows.loc[nominal, "feasible_fraction_pct"] == 100.0 * strict.fraction
    assert rows.loc[nominal, "fraction_error_pct"] == 100.0 * strict.fraction_error


def test_measurement_sigma_of_a_negative_target_and_a_response_without_config():
    """A negative target's default sigma is default_rel |y*|; a response absent from the config has no
    sigma of its own: the tolerance read as a two-sigma band, -40 at 4 %: 0.02 x 40 = 0.8."""
    assert unc.measurement_sigma(None, -40.0, default_rel=0.02) == pytest.approx(0.8)
    assert unc.sigma_basis(None) == "none (surrogate uncertainty only)"
    sigma, basis = unc.measurement_sigmas({}, ["c"], {"c": -40.0}, tolerance=0.04)
    assert sigma == {"c": pytest.approx(0.8)}
    assert basis == {"c": "default sigma_rel = 0.02 (tolerance/2)"}
