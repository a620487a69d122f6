"""Canonical analysis against a textbook example and closed-form surfaces."""

import numpy as np
import pytest

from demid.canonical import canonical_analysis, quadratic_parts

TERMS = [(0, 0), (1, 0), (0, 1), (2, 0), (0, 2), (1, 1)]


def test_montgomery_example_11_2_maximum():
    # Montgomery, Design and Analysis of Experiments, Example 11.2 (chemical process yield, CCD, alpha = 1.414):
    # y = 79.94 + 0.995 x1 + 0.515 x2 - 1.376 x1^2 - 1.001 x2^2 + 0.250 x1 x2.
    # Printed: x_s = (0.389, 0.306), y_s = 80.21, lambda_1 = -0.9634, lambda_2 = -1.4141,
    # w1 = 0.2897 (x1 - 0.389) + 0.9571 (x2 - 0.306): a maximum inside the region.
    b0, b, big_b = quadratic_parts(TERMS, [79.94, 0.995, 0.515, -1.376, -1.001, 0.250], 2)
    c = canonical_analysis(b0, b, big_b, region_lower=[-1.414] * 2, region_upper=[1.414] * 2)
    assert c.stationary_coded == pytest.approx([0.389, 0.306], abs=1e-3)
    assert c.value == pytest.approx(80.21, abs=0.01)
    assert c.eigenvalues == pytest.approx([-0.9634, -1.4141], abs=1e-3)
    assert np.abs(c.eigenvectors[:, 0]) == pytest.approx([0.2897, 0.9571], abs=1e-3)
    assert c.kind == "maximum" and c.inside and not c.is_ridge


def test_saddle_closed_form():
    # y = 2 + x1 + x2 + x1^2 - 2 x2^2 + 0 x1 x2: B = diag(1, -2); x_s = -B^-1 b / 2 = (-0.5, 0.25)
    b0, b, big_b = quadratic_parts(TERMS, [2, 1, 1, 1, -2, 0], 2)
    c = canonical_analysis(b0, b, big_b, region_lower=[-1, -1], region_upper=[1, 1])
    assert c.kind == "saddle point"
    assert c.stationary_coded == pytest.approx([-0.5, 0.25])
    assert c.eigenvalues == pytest.approx([1, -2])
    assert c.value == pytest.approx(2 - 0.25 + 0.125)
    assert c.inside


def test_rotated_saddle_eigenvectors():
    # y = x1 x2: B = [[0, .5], [.5, 0]], eigenvalues +-0.5 along (1, 1)/sqrt2 and (1, -1)/sqrt2
    b0, b, big_b = quadratic_parts(TERMS, [0, 0, 0, 0, 0, 1], 2)
    c = canonical_analysis(b0, b, big_b, region_lower=[-1, -1], region_upper=[1, 1])
    assert c.eigenvalues == pytest.approx([0.5, -0.5])
    assert np.abs(c.eigenvectors) == pytest.approx(np.full((2, 2), 2 ** -0.5))
    assert c.kind == "saddle point"


def test_rising_ridge():
    # y = 10 + 2 x1 + 0.5 x2 + 0.01 x1^2 - 3 x2^2: |0.01| < 0.1 * 3, and the slope 2 along x1 carries the
    # response over the region: a rising ridge along x1; the ridge point nearest the centre is x2 = 0.5/6.
    b0, b, big_b = quadratic_parts(TERMS, [10, 2, 0.5, 0.01, -3, 0], 2)
    c = canonical_analysis(b0, b, big_b, region_lower=[-1, -1], region_upper=[1, 1])
    assert c.kind == "rising ridge"
    # the stationary point x1 = -2/(2*0.01) = -100 is far outside; rsm's threshold gives the ridge point
    assert c.stationary_coded == pytest.approx([-100, 0.5 / 6])
    assert not c.inside
    assert c.ridge_point_coded == pytest.approx([0, 0.5 / 6])
    assert c.ridge_value == pytest.approx(10 + 0.5 * 0.5 / 6 - 3 * (0.5 / 6) ** 2)
    assert np.abs(c.ridge_directions[:, 0]) == pytest.approx([1, 0])
    assert c.ridge_slopes == pytest.approx([2])


def test_stationary_ridge():
    # y = 10 + 0.001 x1 - 3 x2^2 + 0.01 x1^2: flat along x1 within the region
    b0, b, big_b = quadratic_parts(TERMS, [10, 0.001, 0, 0.01, -3, 0], 2)
    c = canonical_analysis(b0, b, big_b, region_lower=[-1, -1], region_upper=[1, 1])
    assert c.kind == "stationary ridge"
    assert c.stationary_coded == pytest.approx([-0.05, 0])    # -0.001 / (2 * 0.01)
    assert c.inside
    assert c.ridge_point_coded == pytest.approx([0, 0])


def test_near_stationary_ridge_with_a_remote_stationary_point():
    # eigenvalues 0.19 and -8.89 (the shape of a published 3^2 analysis called a near-stationary ridge with its
    # stationary point far outside): slope 0.8 along the ridge puts x_s at -0.8 / 0.38 = -2.1, outside [-1, 1],
    # but moves the response by 0.8 * sqrt 2 over the region, less than the threshold 0.889 curvature would
    # (0.889 * 2): near-stationary.  Slope 1.9 (x_s at -5) carries it further: rising.
    b0, b, big_b = quadratic_parts(TERMS, [50, 0.8, 1.0, 0.19, -8.89, 0], 2)
    c = canonical_analysis(b0, b, big_b, region_lower=[-1, -1], region_upper=[1, 1])
    assert c.stationary_coded[0] == pytest.approx(-0.8 / 0.38)
    assert not c.inside
    assert c.eigenvalues == pytest.approx([0.19, -8.89])
    assert c.kind == "stationary ridge"
    b0, b, big_b = quadratic_parts(TERMS, [50, 1.9, 1.0, 0.19, -8.89, 0], 2)
    c = canonical_analysis(b0, b, big_b, region_lower=[-1, -1], region_upper=[1, 1])
    assert c.stationary_coded[0] == pytest.approx(-1.9 / 0.38)
    assert not c.inside and c.kind == "rising ridge"


def test_threshold_zero_gives_full_stationary_point():
    b0, b, big_b = quadratic_parts(TERMS, [10, 2, 0.5, 0.01, -3, 0], 2)
    c = canonical_analysis(b0, b, big_b, region_lower=[-1, -1], region_upper=[1, 1], threshold=0.0)
    assert c.kind == "saddle point"
    assert c.stationary_coded == pytest.approx([-100, 0.5 / 6])
    assert not c.inside


def test_montgomery_example_11_2_from_the_runs():
    # Montgomery, Design and Analysis of Experiments, Table 11.6 (time [min], temperature [°F], yield):
    # the fitted surface's canonical analysis as printed: x_s = (0.389, 0.306), i.e. 86.95 min and 176.53 °F,
    # y_s = 80.21, eigenvalues -0.9634 and -1.4141: a maximum
    import pandas as pd

    from demid.canonical import fit_canonical
    from demid.design import Coding
    from demid.surrogate import fit_response

    rows = [(80, 170, 76.5), (80, 180, 77.0), (90, 170, 78.0), (90, 180, 79.5), (85, 175, 79.9), (85, 175, 80.3),
            (85, 175, 80.0), (85, 175, 79.7), (85, 175, 79.8), (92.07, 175, 78.4), (77.93, 175, 75.6),
            (85, 182.07, 78.5), (85, 167.93, 77.0)]
    table = pd.DataFrame(rows, columns=["time", "temp", "y"])
    table.insert(0, "run", range(1, len(rows) + 1))
    fit = fit_response(table, ["time", "temp"], "y", coding=Coding(("time", "temp"), (85.0, 175.0), (5.0, 5.0)))
    c = fit_canonical(fit)
    assert c.eigenvalues == pytest.approx([-0.9634, -1.4141], abs=2e-4)
    assert c.stationary_coded == pytest.approx([0.389, 0.306], abs=1e-3)
    assert c.stationary_actual == pytest.approx([86.95, 176.53], abs=0.01)
    assert c.value == pytest.approx(80.21, abs=0.005)
    assert c.kind == "maximum" and c.inside
    json = c.to_json()
    assert set(json) >= {"stationary_coded", "stationary_actual", "eigenvalues", "eigenvectors", "kind", "inside"}


def test_canonical_text_of_a_singular_surface():
    # y = x1 + x2^2... with B singular (no x1^2 term): the stored JSON has null for x_s; the report says so
    import json
    from types import SimpleNamespace

    from demid.io import to_json_text
    from demid.report.rsm import canonical_text

    c = canonical_analysis(*quadratic_parts(TERMS, [1, 1, 0, 0, -2, 0], 2), region_lower=[-1, -1],
                           region_upper=[1, 1])
    assert c.kind == "rising ridge"
    stored = json.loads(to_json_text(c.to_json()))
    assert stored["stationary_coded"] == [None, None]
    spec = SimpleNamespace(factor=lambda f: SimpleNamespace(label=f))
    text = canonical_text(stored, ["a", "b"], spec, {"a": "A", "b": "B"}, "y")
    assert "no stationary point (the quadratic part is singular)" in text
    assert "A **rising ridge** along (A +1.000, B +0.000)" in text


def test_a_stationary_point_on_a_face_of_the_region_is_inside():
    # B = I, b = (2, -2): x_s = -B^-1 b / 2 = (-1, 1), a corner of the box [-1, 1]^2 (both faces count as inside)
    c = canonical_analysis(0.0, np.array([2.0, -2.0]), np.eye(2), region_lower=[-1, -1], region_upper=[1, 1])
    assert c.kind == "minimum"
    assert c.stationary_coded == pytest.approx([-1, 1])
    assert c.inside
    # a hair beyond the lower face is outside
    c = canonical_analysis(0.0, np.array([2.0 + 1e-6, 0.0]), np.eye(2), region_lower=[-1, -1], region_upper=[1, 1])
    assert not c.inside


def test_a_largest_eigenvalue_of_one_is_no_singular_surface():
    # B = diag(-1, -0.5), b = (1, 1): x_s = (0.5, 1), y_s = b0 + b'x_s / 2 = 3 + 0.75 (a maximum)
    c = canonical_analysis(3.0, np.array([1.0, 1.0]), np.diag([-1.0, -0.5]), region_lower=[-2, -2],
                           region_upper=[2, 2])
    assert c.kind == "maximum"
    assert c.stationary_coded == pytest.approx([0.5, 1.0])
    assert c.value == pytest.approx(3.75)


@pytest.mark.parametrize("slope, kind", [(0.12, "stationary ridge"), (0.16, "rising ridge")])
def test_rising_is_judged_over_the_half_diagonal_of_the_region(slope, kind):
    # B = diag(-1, 0): a ridge along x2 with slope g = b2 and threshold 0.1 (0.1 max|lambda|).  Over the
    # region's radius R = half the diagonal of [-1, 1]^2 = sqrt 2 the slope moves the response by |g| R, a
    # curvature at the threshold by 0.1 R^2: rising iff |g| > 0.1 sqrt 2 = 0.1414
    c = canonical_analysis(0.0, np.array([0.0, slope]), np.diag([-1.0, 0.0]), region_lower=[-1, -1],
                           region_upper=[1, 1])
    assert c.threshold == pytest.approx(0.1)
    assert c.ridge_slopes == pytest.approx([slope])
    assert c.kind == kind


def test_fit_canonical_without_every_linear_term_takes_the_coded_unit_box():
    # a model without the x2 main effect: its runs' coded box cannot be read from the linear columns, so the
    # region is [-1, 1]^2; y = 1 + 0.4 x1 + x1^2 + x2^2 + 0 x1 x2 has x_s = (-0.2, 0), a minimum inside it
    from types import SimpleNamespace

    import pandas as pd
    import statsmodels.api as sm

    terms = [(0, 0), (1, 0), (2, 0), (0, 2), (1, 1)]
    grid = np.array([(a, b) for a in (-1.5, 0.0, 1.5) for b in (-1.0, 0.0, 1.0)])
    exog = np.column_stack([np.prod(grid ** np.array(t), axis=1) for t in terms])
    y = exog @ np.array([1.0, 0.4, 1.0, 1.0, 0.0])
    results = sm.OLS(y, pd.DataFrame(exog)).fit()
    fit = SimpleNamespace(factors=["a", "b"], terms=terms, results=results, log_factors=(),
                          coding=SimpleNamespace(to_actual=lambda coded: 10 * np.asarray(coded)))
    from demid.canonical import fit_canonical

    c = fit_canonical(fit)
    assert c.kind == "minimum" and c.inside
    assert c.stationary_coded == pytest.approx([-0.2, 0.0], abs=1e-9)
    assert c.stationary_actual == pytest.approx([-2.0, 0.0], abs=1e-8)
    assert c.value == pytest.approx(1 - 0.04, abs=1e-9)
    # y = -2.4 x1 + x1^2 + x2^2: x_s = (1.2, 0), inside the runs' x1 range [-1.5, 1.5] but outside [-1, 1]^2
    y = exog @ np.array([0.0, -2.4, 1.0, 1.0, 0.0])
    fit = SimpleNamespace(factors=["a", "b"], terms=terms, results=sm.OLS(y, pd.DataFrame(exog)).fit(),
                          log_factors=(), coding=SimpleNamespace(to_actual=lambda coded: np.asarray(coded)))
    c = fit_canonical(fit)
    assert c.stationary_coded == pytest.approx([1.2, 0.0], abs=1e-9)
    assert c.kind == "minimum" and not c.inside
