"""fit_material called without validation's coding, and predict_all over fields of two kinds.

Without a coding, fit_material infers the declared design's own (factorial levels at +-1, axial levels at +-alpha,
log10 units for a log-scale factor): the coded coefficients and the coding stored with the fits are those of least
squares written out here in that coding, for CCDs of two and three factors, rotatable and face-centred, linear and
log scales.  predict_all given a field that is not a quadratic (anything with ``predict``) returns that field's own
values next to the quadratics', in the order the fields were given."""

from __future__ import annotations

import numpy as np
import pandas as pd
import pytest

from demid.design import ccd_points, model_matrix, quadratic_terms
from demid.spec import MaterialSpec
from demid.surrogate import Surrogate, fit_material, predict_all

CASES = [  # (alpha, lower, upper, log factors by index, seed)
    (1.41421, [0.1, 2.0], [0.9, 18.0], (), 0),
    (1.0, [-3.0, 1e-3], [5.0, 1e-1], (1,), 1),
    (1.68179, [0.2, 1.0, -2.0], [0.6, 100.0, 2.0], (1,), 2),
]


def _study(alpha, lower, upper, logs, seed):
    """A CCD table (axial levels on the bounds, evenly spaced in log10 for a log factor), two noisy responses, and
    the spec that declares it; also each factor's expected centre and unit in search units."""
    rng = np.random.default_rng(seed)
    k = len(lower)
    lo = np.array([np.log10(v) if i in logs else v for i, v in enumerate(lower)])
    hi = np.array([np.log10(v) if i in logs else v for i, v in enumerate(upper)])
    centre, unit = (lo + hi) / 2, (hi - lo) / (2 * alpha)
    coded = ccd_points(k, alpha, 3)
    search = centre + coded * unit
    actual = np.column_stack([10 ** search[:, i] if i in logs else search[:, i] for i in range(k)])
    names = [f"f{i}" for i in range(k)]
    table = pd.DataFrame(actual, columns=names)
    table.insert(0, "run", np.arange(1, len(table) + 1))
    table["y"] = 5 + coded @ rng.normal(size=k) + 0.7 * coded[:, 0] ** 2 + rng.normal(0, 0.1, len(table))
    table["w"] = -2 + 0.5 * coded[:, -1] * coded[:, 0] + rng.normal(0, 0.1, len(table))
    table["status"] = "ok"
    factors = {n: {"lower": float(lower[i]), "upper": float(upper[i]), **({"scale": "log"} if i in logs else {})}
               for i, n in enumerate(names)}
    spec = MaterialSpec.from_material("m", {
        "data": "x.csv", "design": {"type": "ccd", "alpha": alpha, "center_runs": 3}, "factors": factors,
        "responses": {"y": {"target": 5.0}, "w": {}},
        "scenarios": {"y": {"observables": ["y"], "tolerance": 0.05}}})
    return table, spec, search, centre, unit


@pytest.mark.parametrize("case", CASES, ids=["rotatable-2", "face-centred-log", "rotatable-3-log"])
def test_fit_without_coding_uses_the_declared_designs_coding(case):
    table, spec, search, centre, unit = _study(*case)
    fits = fit_material(table, spec)
    assert [f.response for f in fits] == ["y", "w"]
    terms = quadratic_terms(len(centre))
    x = model_matrix((search - centre) / unit, terms)
    for fit in fits:
        np.testing.assert_allclose(fit.coding.center, centre, rtol=1e-9, atol=1e-12)
        np.testing.assert_allclose(fit.coding.unit, unit, rtol=1e-9)
        assert [tuple(t) for t in fit.terms] == [tuple(t) for t in terms]
        expected, *_ = np.linalg.lstsq(x, table[fit.response].to_numpy(), rcond=None)
        np.testing.assert_allclose(fit.results.params.to_numpy(), expected, rtol=1e-8, atol=1e-10)
        # the surrogate predicts the fitted values at the runs, in actual units
        np.testing.assert_allclose(fit.surrogate().predict(table[spec.factor_names].to_numpy()), x @ expected,
                                   rtol=1e-9, atol=1e-9)


class _Plane:
    """A field that is not a quadratic: 3 a - b + 1."""

    def predict(self, points):
        points = np.asarray(points, dtype=float)
        return 3 * points[:, 0] - points[:, 1] + 1


def test_predict_all_asks_other_fields_directly_and_keeps_their_order():
    terms = quadratic_terms(2)
    quad = Surrogate("q", ["a", "b"], terms, np.array([1.0, 2.0, -1.0, 0.5, 0.25, -0.75]), np.eye(6) * 1e-3, 0.1, 9)
    points = np.random.default_rng(4).uniform(-1, 1, (9, 2))
    a, b = points.T
    expected_q = 1 + 2 * a - b + 0.5 * a * b + 0.25 * a ** 2 - 0.75 * b ** 2
    out = predict_all({"plane": _Plane(), "q": quad}, points)
    assert list(out) == ["plane", "q"]
    np.testing.assert_allclose(out["plane"], 3 * a - b + 1, rtol=1e-12)
    np.testing.assert_allclose(out["q"], expected_q, rtol=1e-12)
