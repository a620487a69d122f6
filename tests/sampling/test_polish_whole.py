"""Span ends polished to the set's boundary, against linear programming: generated sets of one or two linear
observables of either sign (an intersection of slabs) in two or three factors, one of them on a log scale (a slab
in search units), evaluated on coarse grids; the polished ends are the exact extremes, never inside the grid's,
and an empty set or one without finite spans is returned as it is."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy.optimize import linprog

from demid.sampling import Domain
from demid.sampling.grid import admissible_set
from demid.sampling.polish import polish_spans


class SearchLinear:
    """y = c + a . s, with s the point in search units (log10 for the log factors)."""

    def __init__(self, c, a, logs):
        self.c, self.a, self.logs = float(c), np.asarray(a, dtype=float), np.asarray(logs)

    def predict(self, x):
        s = np.array(np.atleast_2d(x), dtype=float)
        s[:, self.logs] = np.log10(s[:, self.logs])
        return self.c + s @ self.a


def _extremes(fields, targets, eps, lo, hi, i):
    a_ub, b_ub = [], []
    for o, f in fields.items():
        band = eps * abs(targets[o])
        a_ub += [f.a, -f.a]
        b_ub += [targets[o] + band - f.c, band - targets[o] + f.c]
    out = []
    for direction in (1.0, -1.0):
        cost = np.zeros(len(lo))
        cost[i] = direction
        res = linprog(cost, A_ub=np.array(a_ub), b_ub=np.array(b_ub), bounds=list(zip(lo, hi)), method="highs")
        out.append(res.x[i] if res.success else np.nan)
    return out


@given(seed=st.integers(0, 10_000), dim=st.integers(2, 3), k=st.integers(1, 2), sign=st.sampled_from([-1.0, 1.0]),
       log_first=st.booleans())
@settings(max_examples=8, deadline=None, derandomize=True)
def test_polished_ends_are_the_extremes_of_the_set(seed, dim, k, sign, log_first):
    rng = np.random.default_rng(seed)
    logs = [log_first and i == 0 for i in range(dim)]
    lower = np.where(logs, 0.1, rng.normal(size=dim))
    upper = np.where(logs, 100.0, lower + rng.uniform(1, 3, dim))
    domain = Domain(tuple(f"f{i}" for i in range(dim)), tuple(lower), tuple(upper), log=tuple(logs))
    lo, hi = domain.search_bounds()
    centre = (lo + hi) / 2
    fields, targets = {}, {}
    for j in range(k):
        a = rng.normal(size=dim) / (hi - lo) * sign
        fields[f"y{j}"] = SearchLinear(sign * 10.0, a, logs)
        targets[f"y{j}"] = float(sign * 10.0 + centre @ a + rng.uniform(-0.1, 0.1) * np.abs(a) @ (hi - lo))
    eps = 0.06
    aset = admissible_set(fields, domain, list(fields), targets, eps, 7)
    lower_p, upper_p = polish_spans(fields, domain, list(fields), targets, eps, aset)
    if aset.empty or not np.isfinite(aset.lower).all():
        np.testing.assert_array_equal(lower_p, aset.lower)
        np.testing.assert_array_equal(upper_p, aset.upper)
        return
    got = domain.to_search(np.array([lower_p, upper_p]))
    grid = domain.to_search(np.array([aset.lower, aset.upper]))
    for i in range(dim):
        s_lo, s_hi = _extremes(fields, targets, eps, lo, hi, i)
        assert got[0, i] == pytest.approx(s_lo, abs=1e-6 * (hi[i] - lo[i]))
        assert got[1, i] == pytest.approx(s_hi, abs=1e-6 * (hi[i] - lo[i]))
        assert got[0, i] <= grid[0, i] + 1e-12 and got[1, i] >= grid[1, i] - 1e-12
