"""The round-off floor of criticism includes the factors' printed precision: an exact quadratic (a
deterministic simulator) whose factor values were printed to 4-8 decimals is no defect, while a real
defect ten times that floor is still found."""

from __future__ import annotations

import numpy as np
import pandas as pd
import pytest

from demid.criticism import criticize
from demid.design import box_behnken_points, ccd_points, model_matrix, quadratic_terms
from demid.precision import round_off_floor
from demid.surrogate import fit_response

_DESIGNS = {"ccd2": lambda: ccd_points(2, 1.41421, 3), "ccd3": lambda: ccd_points(3, 1.68179, 3),
            "bbd3": lambda: box_behnken_points(3, 3)}
_PRINTS = [(4, 3), (5, 6), (6, 9), (7, 4), (8, 9)]  # (factor decimals, response decimals)


def _exact_table(design, seed, factor_decimals, response_decimals, defect=None):
    """An exact quadratic of the unrounded factor values, as a table prints it (factors and response rounded);
    factors in units of very different sizes so the rounding of one matters more than of another."""
    rng = np.random.default_rng(seed)
    coded = _DESIGNS[design]()
    k = coded.shape[1]
    centre = rng.uniform(0.2, 20, k)
    unit = centre * rng.uniform(0.1, 0.4, k)
    beta = rng.normal(0, 1, len(quadratic_terms(k)))
    beta[0] = rng.uniform(20, 200)
    y = 10 * model_matrix(coded, quadratic_terms(k)) @ beta
    if defect is not None:
        y = y + defect(coded)
    names = [f"x{i + 1}" for i in range(k)]
    table = pd.DataFrame(np.round(coded * unit + centre, factor_decimals), columns=names)
    table.insert(0, "run", rng.permutation(len(y)) + 1)
    table["y"] = np.round(y, response_decimals)
    return table.sort_values("run").reset_index(drop=True), names


def _floor(table, names):
    fit = fit_response(table, names, "y")
    return round_off_floor(fit.y, fit.factor_round_off), fit


@pytest.mark.parametrize("design", sorted(_DESIGNS))
@pytest.mark.parametrize("seed", range(4))
def test_an_exact_quadratic_with_printed_factors_gives_no_finding(design, seed):
    for factor_decimals, response_decimals in _PRINTS:
        table, names = _exact_table(design, seed, factor_decimals, response_decimals)
        _, fit = _floor(table, names)
        result = criticize(table, names, "y", fit=fit, run_order="unknown", n_null=199)
        assert result.verdict == "adequate" and not result.findings, (factor_decimals, response_decimals,
                                                                        [f.cause for f in result.findings])


def test_the_floor_grows_with_the_factors_rounding_and_only_then():
    table, names = _exact_table("ccd2", 0, 4, 9)
    fit = fit_response(table, names, "y")
    # independently: the fitted gradient at each run times each factor's half-place, as a variance q^2/12
    h = 1e-6
    grad = np.zeros((len(table), 2))
    x = table[names].to_numpy(dtype=float)
    sur = fit.surrogate()
    for j in range(2):
        step = np.zeros(2)
        step[j] = h
        grad[:, j] = (sur.predict(x + step) - sur.predict(x - step)) / (2 * h)
    expected = np.sqrt(np.sum((grad * 1e-4) ** 2 / 12, axis=1))
    assert fit.factor_round_off == pytest.approx(expected, rel=1e-4)
    assert round_off_floor(fit.y, fit.factor_round_off) > 10 * round_off_floor(fit.y)
    exact, names = _exact_table("ccd2", 0, 12, 9)
    exact_fit = fit_response(exact, names, "y")
    assert round_off_floor(exact_fit.y, exact_fit.factor_round_off) == pytest.approx(round_off_floor(exact_fit.y),
                                                                                    rel=1e-3)


@pytest.mark.parametrize("design", sorted(_DESIGNS))
@pytest.mark.parametrize("seed", range(3))
def test_a_missing_term_ten_times_the_floor_is_still_found(design, seed):
    factor_decimals, response_decimals = _PRINTS[seed + 1]
    clean, names = _exact_table(design, seed, factor_decimals, response_decimals)
    floor, _ = _floor(clean, names)

    def cubic(coded):
        # the part of one cubic term the quadratic cannot absorb (on a Box-Behnken design x1^3 is x1 itself:
        # x1^2 x2 there), with a root mean square over the runs ten times the floor
        shape = coded[:, 0] ** 3 if design.startswith("ccd") else coded[:, 0] ** 2 * coded[:, 1]
        x = model_matrix(coded, quadratic_terms(coded.shape[1]))
        shape = shape - x @ np.linalg.lstsq(x, shape, rcond=None)[0]
        return 10 * floor * shape / np.sqrt(np.mean(shape ** 2))

    table, names = _exact_table(design, seed, factor_decimals, response_decimals, defect=cubic)
    result = criticize(table, names, "y", fit=fit_response(table, names, "y"), run_order="unknown", n_null=499)
    assert [f.cause for f in result.findings][:1] == ["missing_term"], result.verdict
