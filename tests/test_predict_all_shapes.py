"""predict_all at one point given as a flat vector, at many points and in chunks that split them: every surrogate's
values are those of its own predict on the same points (two surrogates sharing terms, one on other terms)."""

from __future__ import annotations

import numpy as np
import pytest

from demid.design import quadratic_terms
from demid.surrogate import Surrogate, predict_all


def _surrogate(name, coef, terms):
    p = len(terms)
    return Surrogate(name, ["a", "b"], terms, np.asarray(coef, dtype=float), np.eye(p) * 0.01, 0.1, 13)


@pytest.fixture
def surrogates():
    quad, linear = quadratic_terms(2), [t for t in quadratic_terms(2) if sum(t) <= 1]
    return {"y1": _surrogate("y1", [1.0, 2.0, -3.0, 0.5, 0.25, -1.5], quad),
            "y2": _surrogate("y2", [-4.0, 0.1, 0.2, 0.3, 0.4, 0.5], quad),
            "y3": _surrogate("y3", [7.0, -1.0, 2.0], linear)}


def test_one_flat_point_gives_one_value_per_surrogate(surrogates):
    point = np.array([0.3, -0.7])
    out = predict_all(surrogates, point)
    for name, sur in surrogates.items():
        assert out[name].shape == (1,)
        assert out[name][0] == pytest.approx(float(sur.predict(point.reshape(1, -1))[0]), rel=1e-12)


@pytest.mark.parametrize("chunk", [1, 3, 65_536])
def test_many_points_in_chunks_match_each_surrogates_predict(surrogates, chunk):
    points = np.random.default_rng(3).uniform(-2, 2, (7, 2))
    out = predict_all(surrogates, points, chunk=chunk)
    for name, sur in surrogates.items():
        np.testing.assert_allclose(out[name], sur.predict(points), rtol=1e-12)


@pytest.mark.parametrize("chunk", [1, 4, 22, 23])
def test_standard_error_of_the_mean_in_chunks_is_the_quadratic_form_at_every_point(chunk):
    """se_mean(x) = sqrt(m(x)' C m(x)), m(x) the row of the surrogate's terms at x: every one of 23 points, in
    chunks of 1, 4, 22 or 23 points (a grid larger than one chunk is evaluated chunk by chunk)."""
    terms = quadratic_terms(2)
    root = np.random.default_rng(11).normal(size=(len(terms), len(terms)))
    sur = Surrogate("y", ["a", "b"], terms, np.arange(1.0, 7.0), root @ root.T / 10, 0.1, 13)
    points = np.random.default_rng(chunk).uniform(-2, 2, (23, 2))
    got = sur.se_mean(points, chunk=chunk)
    for x, value in zip(points, got):
        row = np.array([x[0] ** t[0] * x[1] ** t[1] for t in terms])
        assert value == pytest.approx(np.sqrt(row @ sur.covariance @ row), rel=1e-12)
