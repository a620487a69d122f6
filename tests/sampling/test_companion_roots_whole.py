"""Roots of polynomials whose formal degree exceeds their true one, and the one-factor exact set of observables of
different degrees (a cubic next to a quadratic and a line: the lower ones padded with zero coefficients to the
common degree), against numpy's own roots and a set cut at them in model coordinates, written out in the test."""

from __future__ import annotations

import numpy as np
from numpy.polynomial import polynomial as P

from demid.sampling.exact import Polynomial, exact_set
from demid.sampling.roots import real_roots_unit


def _roots_in_unit(coef) -> np.ndarray:
    """Real roots in [0, 1] of one polynomial (ascending coefficients), by numpy's companion matrix."""
    roots = P.polyroots(np.trim_zeros(np.asarray(coef, dtype=float), "b"))
    real = roots.real[np.abs(roots.imag) < 1e-9]
    return np.sort(real[(real >= 0) & (real <= 1)])


def test_roots_of_padded_polynomials_match_numpy():
    rng = np.random.default_rng(613)
    for degree in (3, 4, 5):
        rows = []
        for true_degree in range(1, degree + 1):
            for _ in range(4):
                # roots placed inside [0, 1] (and some outside) so there is something to find
                inside = rng.uniform(0.05, 0.95, size=true_degree)
                inside[rng.uniform(size=true_degree) < 0.3] += 1.5
                coef = P.polyfromroots(inside) * rng.uniform(0.5, 3.0) * rng.choice([-1, 1])
                rows.append(np.concatenate([coef, np.zeros(degree - true_degree)]))
        rows = np.array(rows)
        got = real_roots_unit(rows.reshape(2, -1, degree + 1)).reshape(len(rows), degree)
        for coef, found in zip(rows, got):
            np.testing.assert_allclose(np.sort(found[np.isfinite(found)]), _roots_in_unit(coef), atol=1e-9)


def _set_by_hand(polys, targets, tolerance, lower, upper):
    """Fraction of [lower, upper] and span where every |p_k(z) - y_k| <= tolerance |y_k|: cut points from
    numpy's roots of p_k - y_k -+ tolerance |y_k| in z, each piece judged at its midpoint."""
    cuts = [lower, upper]
    for coef, y in zip(polys, targets):
        for level in (-1.0, 1.0):
            shifted = np.array(coef, dtype=float)
            shifted[0] -= y + level * tolerance * abs(y)
            roots = P.polyroots(np.trim_zeros(shifted, "b"))
            real = roots.real[np.abs(roots.imag) < 1e-9]
            cuts.extend(real[(real > lower) & (real < upper)])
    cuts = np.sort(cuts)
    mids = 0.5 * (cuts[1:] + cuts[:-1])
    ok = np.all([np.abs(P.polyval(mids, c) - y) <= tolerance * abs(y) for c, y in zip(polys, targets)], axis=0)
    if not ok.any():
        return 0.0, (np.nan, np.nan)
    length = float(np.sum(np.diff(cuts)[ok]))
    return length / (upper - lower), (cuts[:-1][ok].min(), cuts[1:][ok].max())


def test_one_factor_exact_set_of_a_cubic_a_quadratic_and_a_line():
    rng = np.random.default_rng(447)
    checked = 0
    for _ in range(40):
        lower = rng.uniform(-3, 2)
        upper = lower + rng.uniform(1, 4)
        # a point inside the box meets every target; the observables are of degree 3, 2 and 1 in z
        z0 = rng.uniform(lower + 0.2 * (upper - lower), upper - 0.2 * (upper - lower))
        polys = [rng.normal(size=4), rng.normal(size=3), rng.normal(size=2)]
        polys = [c if abs(c[-1]) > 0.2 else np.append(c[:-1], 0.5) for c in polys]
        targets = [P.polyval(z0, c) for c in polys]
        if min(abs(t) for t in targets) < 0.3:
            continue
        tolerance = float(rng.uniform(0.02, 0.3))
        aset = exact_set([Polynomial(np.arange(len(c))[:, None], c) for c in polys], targets, tolerance,
                         [lower], [upper])
        fraction, (first, last) = _set_by_hand(polys, targets, tolerance, lower, upper)
        assert fraction > 0
        np.testing.assert_allclose(aset.fraction, fraction, atol=1e-9)
        np.testing.assert_allclose(aset.model_spans[0], [first, last], atol=1e-9 * (upper - lower))
        checked += 1
    assert checked >= 20
