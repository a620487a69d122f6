"""Known answers for the value of a next wave: the updated standard error is the one of the refit with the
new runs stacked under the old (the information adds), and the plausible fractions before and after are counted
on the evaluation grid by brute force, with a least-squares fit written here in its own basis."""

from __future__ import annotations

import numpy as np
import pytest

from demid.scenario import JudgedScenario
from demid.spec import MaterialSpec
from demid.surrogate import fit_response
from demid.wave_value import STOP_CONTRACTION, _updated_se, expected_contraction

from .helpers import make_ccd_table


def _basis(points: np.ndarray) -> np.ndarray:
    """The full quadratic in two factors, in actual units and an order of its own: the standard error of the
    fitted mean does not depend on how the same space of polynomials is written."""
    a, b = points[:, 0], points[:, 1]
    return np.column_stack([np.ones_like(a), a, b, a * a, a * b, b * b])


def _fit(seed: int, noise: float = 0.3):
    def responses(x):
        a, b = x[:, 0], x[:, 1]
        return {"y": 10 + 4 * a + 3 * b + 2 * a * b - 3 * a ** 2}

    table = make_ccd_table(responses, [0.0, 0.0], [1.0, 1.0], noise=noise, seed=seed).rename(
        columns={"x1": "a", "x2": "b"})
    surrogate = fit_response(table, ["a", "b"], "y", alpha=1.41421).surrogate()
    x = _basis(table[["a", "b"]].to_numpy(dtype=float))
    y = table["y"].to_numpy(dtype=float)
    beta, *_ = np.linalg.lstsq(x, y, rcond=None)
    s2 = float(np.sum((y - x @ beta) ** 2) / (len(y) - x.shape[1]))
    return surrogate, x, beta, s2


def _spec(sigma: float, target: float) -> MaterialSpec:
    material = {"data": "x.csv", "design": {"type": "custom"},
                "factors": {"a": {"lower": 0.0, "upper": 1.0}, "b": {"lower": 0.0, "upper": 1.0}},
                "responses": {"y": {"target": target, "sigma": sigma}},
                "scenarios": {"s": {"observables": ["y"], "tolerance": 0.01}}}
    return MaterialSpec.from_material("m", material, grid_points=201)


@pytest.mark.parametrize("seed", [1, 2])
def test_updated_se_is_the_se_of_the_fit_with_the_new_runs_stacked_under_the_old(seed):
    surrogate, x, _, s2 = _fit(seed)
    rng = np.random.default_rng(seed)
    points = rng.uniform(0, 1, size=(50, 2))
    new_runs = rng.uniform(0, 1, size=(7, 2))
    f = _basis(points)
    # the full quadratic is fitted: the surrogate's own se is the textbook s^2 f'(X'X)^-1 f
    assert surrogate.resid_var == pytest.approx(s2, rel=1e-9)
    now = np.sqrt(s2 * np.einsum("ij,jk,ik->i", f, np.linalg.inv(x.T @ x), f))
    np.testing.assert_allclose(surrogate.se_mean(points), now, rtol=1e-7)
    stacked = np.vstack([x, _basis(new_runs)])
    expected = np.sqrt(s2 * np.einsum("ij,jk,ik->i", f, np.linalg.inv(stacked.T @ stacked), f))
    got = _updated_se(surrogate, points, new_runs)
    np.testing.assert_allclose(got, expected, rtol=1e-7)
    assert np.all(got < now)  # information only adds


@pytest.mark.parametrize("seed, sigma", [(1, 0.01), (2, 0.05), (3, 1.0)])
def test_fractions_and_contraction_are_counted_on_the_grid(seed, sigma):
    surrogate, x, beta, s2 = _fit(seed)
    new_runs = np.random.default_rng(seed).uniform(0, 1, size=(12, 2))
    target, z = 12.5, 2.0
    value = expected_contraction(JudgedScenario(_spec(sigma, target), _spec(sigma, target).scenarios[0],
                                                {"y": surrogate}, z), new_runs)
    axis = np.linspace(0.0, 1.0, 201)
    grid = np.column_stack([g.ravel() for g in np.meshgrid(axis, axis, indexing="ij")])
    f = _basis(grid)
    miss = np.abs(f @ beta - target)

    def plausible(inverse):
        se2 = s2 * np.einsum("ij,jk,ik->i", f, inverse, f)
        return miss <= z * np.sqrt(se2 + sigma ** 2)

    stacked = np.vstack([x, _basis(new_runs)])
    now = plausible(np.linalg.inv(x.T @ x)).mean()
    after = plausible(np.linalg.inv(stacked.T @ stacked)).mean()
    one_node = 100.0 / len(grid)  # a node on the band's edge may fall either way by round-off
    assert value["count"] == 12 and value["scenario"] == "s"
    assert value["plausible_fraction_pct"] == pytest.approx(100 * now, abs=2 * one_node)
    assert value["expected_fraction_pct"] == pytest.approx(100 * after, abs=2 * one_node)
    assert value["expected_contraction"] == pytest.approx(1 - after / now, abs=1e-3)
    assert value["stop"] == bool(1 - after / now < STOP_CONTRACTION)


def test_an_empty_plausible_set_has_no_contraction_and_no_stop():
    surrogate, *_ = _fit(1)
    spec = _spec(0.01, 1e6)  # far beyond every prediction
    value = expected_contraction(JudgedScenario(spec, spec.scenarios[0], {"y": surrogate}, 2.0), np.full((3, 2), 0.5))
    assert value["plausible_fraction_pct"] == 0.0
    assert np.isnan(value["expected_contraction"]) and value["stop"] is False


def _quadratic_basis(points: np.ndarray) -> np.ndarray:
    k = points.shape[1]
    cols = [np.ones(len(points))] + [points[:, i] for i in range(k)]
    cols += [points[:, i] * points[:, j] for i in range(k) for j in range(i, k)]
    return np.column_stack(cols)


@pytest.mark.parametrize("k", [3, 4])
def test_fractions_in_three_and_four_factors_match_a_dense_random_sample(k):
    # three factors are counted on a grid, four on a Sobol sample over the search box [0, 2]^k; both are checked
    # against the fraction of 400 000 uniform points of the box (standard error below 0.1 percentage point)
    def responses(x):
        return {"y": 5 + x.sum(axis=1) + 0.5 * x[:, 0] * x[:, 1] - 0.8 * x[:, 0] ** 2}

    table = make_ccd_table(responses, [0.0] * k, [2.0] * k, noise=0.2, seed=k)
    names = [f"x{i + 1}" for i in range(k)]
    surrogate = fit_response(table, names, "y", alpha=1.41421).surrogate()
    x = _quadratic_basis(table[names].to_numpy(dtype=float))
    y = table["y"].to_numpy(dtype=float)
    beta, *_ = np.linalg.lstsq(x, y, rcond=None)
    s2 = float(np.sum((y - x @ beta) ** 2) / (len(y) - x.shape[1]))
    target, sigma, z = 9.0, 0.1, 2.0
    material = {"data": "x.csv", "design": {"type": "custom"},
                "factors": {n: {"lower": 0.0, "upper": 2.0} for n in names},
                "responses": {"y": {"target": target, "sigma": sigma}},
                "scenarios": {"s": {"observables": ["y"], "tolerance": 0.01}}}
    spec = MaterialSpec.from_material("m", material, grid_points=21)
    new_runs = np.random.default_rng(k).uniform(0, 2, size=(20, k))
    value = expected_contraction(JudgedScenario(spec, spec.scenarios[0], {"y": surrogate}, z), new_runs)
    points = np.random.default_rng(100 + k).uniform(0, 2, size=(400_000, k))
    f = _quadratic_basis(points)
    miss = np.abs(f @ beta - target)
    stacked = np.vstack([x, _quadratic_basis(new_runs)])
    fractions = []
    for design in (x, stacked):
        se2 = s2 * np.einsum("ij,jk,ik->i", f, np.linalg.inv(design.T @ design), f)
        fractions.append(100 * np.mean(miss <= z * np.sqrt(se2 + sigma ** 2)))
    assert 5 < fractions[0] < 95  # a set neither empty nor everything
    assert value["plausible_fraction_pct"] == pytest.approx(fractions[0], abs=1.0)
    assert value["expected_fraction_pct"] == pytest.approx(fractions[1], abs=1.0)


@pytest.mark.parametrize("log", [(False,), (False, True), (True, False, False), (False, True, False, True),
                                 (True,) * 5])
def test_the_points_a_waves_value_is_estimated_on_fill_the_search_range(log):
    """Grid nodes up to three factors, scrambled Sobol points above: inside the search range and reaching within
    a few per cent of both ends of every factor."""
    from demid.sampling.domain import Domain
    from demid.wave_value import _evaluation_points

    d = len(log)
    lower = tuple(0.01 * (i + 1) if lg else -3.0 + i for i, lg in enumerate(log))
    upper = tuple(100.0 * (i + 1) if lg else 5.0 + 2 * i for i, lg in enumerate(log))
    domain = Domain(tuple(f"f{i}" for i in range(d)), lower, upper, log)
    lo, hi = domain.search_bounds()
    points = domain.to_search(_evaluation_points(domain))
    assert np.all(points >= lo - 1e-9) and np.all(points <= hi + 1e-9)
    assert np.all(points.min(axis=0) <= lo + 0.03 * (hi - lo)) and np.all(points.max(axis=0) >= hi - 0.03 * (hi - lo))


def test_new_runs_shrink_the_means_error_by_the_bayesian_update_of_a_diagonal_covariance():
    """A fit whose covariance has zeros off its diagonal still learns from new runs: the updated covariance is
    (C⁻¹ + F'F/s²)⁻¹, here with every matrix invertible."""
    from demid.design import model_matrix, quadratic_terms
    from demid.surrogate import Surrogate

    terms = quadratic_terms(2)
    cov = np.diag(np.linspace(0.5, 2.0, len(terms)))
    surrogate = Surrogate("y", ["a", "b"], terms, np.ones(len(terms)), cov, 0.8, 7)
    new_runs = np.array([[0.5, -0.5], [1.0, 1.0], [-1.0, 0.0], [0.0, 0.3], [0.2, 0.9], [-0.7, -0.8], [0.9, -0.2]])
    points = np.array([[0.0, 0.0], [0.5, -0.5], [0.8, 0.8]])
    found = _updated_se(surrogate, points, new_runs)
    f_new, f = model_matrix(new_runs, terms), model_matrix(points, terms)
    updated = np.linalg.inv(np.linalg.inv(cov) + f_new.T @ f_new / 0.8)
    assert np.allclose(found, np.sqrt(np.einsum("ij,jk,ik->i", f, updated, f)), rtol=1e-9)
    assert np.all(found < surrogate.se_mean(points))


@pytest.mark.parametrize("resid_var", [0.0, 0.4])
def test_a_surrogate_without_coefficient_uncertainty_keeps_its_error_whatever_the_new_runs(resid_var):
    """No covariance (an exact surrogate) or no residual variance: the update has no information to add to, and
    the mean's error stays the surrogate's own (zero), not the error of a fit to the new runs alone."""
    from demid.design import quadratic_terms
    from demid.surrogate import Surrogate
    from demid.wave_value import _updated_se

    terms = quadratic_terms(2)
    zero = np.zeros((len(terms), len(terms)))
    sur = Surrogate("y", ["a", "b"], terms, np.arange(1.0, len(terms) + 1.0), zero, resid_var, 5)
    points = np.random.default_rng(1).uniform(0.0, 1.0, (30, 2))
    new_runs = np.random.default_rng(2).uniform(0.0, 1.0, (9, 2))
    assert np.array_equal(_updated_se(sur, points, new_runs), sur.se_mean(points))
    assert not np.any(sur.se_mean(points))
