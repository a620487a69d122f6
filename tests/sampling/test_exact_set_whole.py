"""Every column of an exact set's table against computations made apart, over generated slabs (one linear
polynomial, either sign) in one to three factors, one of them on a log scale or none, and reference points inside
and outside the set: the spans from linear programming (in actual units), the fraction from a closed-form area or
a Monte Carlo count, the distance to the reference in fractions of the search range and the nearest point from a
projection onto the slab within the box, and every malformed input refused."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy.optimize import linprog, minimize

from demid.sampling.exact import Polynomial, exact_set


def _slab(seed, dim, sign):
    rng = np.random.default_rng(seed)
    lower = rng.normal(size=dim)
    upper = lower + rng.uniform(0.5, 2.5, dim)
    a = rng.normal(size=dim) / (upper - lower)
    exps = np.vstack([np.zeros(dim, dtype=int), np.eye(dim, dtype=int)])
    c = sign * 10.0
    target = float(c + (lower + upper) / 2 @ a + rng.uniform(-0.2, 0.2) * np.abs(a) @ (upper - lower))
    return Polynomial(exps, np.r_[c, a]), target, a, c, lower, upper


def _nearest(a, c, target, eps, lower, upper, ref):
    """The point of the slab within the box nearest ref, distances in fractions of each factor's range."""
    band = eps * abs(target)
    scale = upper - lower
    cons = [{"type": "ineq", "fun": lambda u: band - (c + (lower + scale * u) @ a - target)},
            {"type": "ineq", "fun": lambda u: band + (c + (lower + scale * u) @ a - target)}]
    r = (ref - lower) / scale
    res = minimize(lambda u: np.sum((u - r) ** 2), np.clip(r, 0, 1), jac=lambda u: 2 * (u - r), method="SLSQP",
                   bounds=[(0, 1)] * len(a), constraints=cons, options={"ftol": 1e-14, "maxiter": 500})
    return float(np.sqrt(res.fun)), lower + scale * res.x


@given(seed=st.integers(0, 10_000), dim=st.integers(1, 3), sign=st.sampled_from([-1.0, 1.0]),
       eps=st.sampled_from([0.01, 0.05]), log_first=st.booleans(), far=st.booleans())
@settings(max_examples=8, deadline=None, derandomize=True)
def test_every_column_of_an_exact_slab_s_table(seed, dim, sign, eps, log_first, far):
    poly, target, a, c, lower, upper = _slab(seed, dim, sign)
    rng = np.random.default_rng(seed + 1)
    ref = lower + (upper - lower) * (rng.choice([-0.05, 1.05], dim) if far else rng.uniform(0, 1, dim))
    log = tuple(log_first and i == 0 for i in range(dim))
    names = tuple(f"f{i}" for i in range(dim))
    es = exact_set([poly], [target], eps, lower, upper, reference=ref, factors=names, log=log)
    frame = es.to_frame()
    assert list(frame["factor"]) == list(names) and (frame["tolerance"] == eps).all()
    band = eps * abs(target)
    feasible = linprog(np.zeros(dim), A_ub=np.vstack([a, -a]), b_ub=[target + band - c, band - target + c],
                       bounds=list(zip(lower, upper)), method="highs").success
    if not feasible:
        assert es.fraction == 0.0 and np.isinf(es.reference_distance)
        return
    for i in range(dim):
        ends = []
        for direction in (1.0, -1.0):
            cost = np.zeros(dim)
            cost[i] = direction
            res = linprog(cost, A_ub=np.vstack([a, -a]), b_ub=[target + band - c, band - target + c],
                          bounds=list(zip(lower, upper)), method="highs")
            ends.append(res.x[i])
        want = 10.0 ** np.array(ends) if log[i] else np.array(ends)
        got = frame.loc[i, ["lower", "upper"]].to_numpy(dtype=float)
        np.testing.assert_allclose(got, want, rtol=1e-7, atol=1e-9 * (upper[i] - lower[i]))
        assert frame.loc[i, "width"] == pytest.approx(got[1] - got[0], rel=1e-12, abs=1e-15)
    u = np.random.default_rng(seed).uniform(lower, upper, size=(200_000, dim))
    assert es.fraction == pytest.approx(np.mean(np.abs(c + u @ a - target) <= band), abs=0.007)
    assert (frame["feasible_fraction"] == es.fraction).all() and (frame["fraction_error"] == es.fraction_error).all()
    assert 0 <= es.fraction_error < 1e-3
    distance, point = _nearest(a, c, target, eps, lower, upper, ref)
    assert es.reference_distance == pytest.approx(distance, abs=1e-6)
    want_point = np.where(log, 10.0 ** point, point)
    np.testing.assert_allclose(es.nearest_point, want_point, rtol=1e-5, atol=1e-5)
    np.testing.assert_allclose(frame["nearest_point"], es.nearest_point)
    assert (frame["reference_distance"] == es.reference_distance).all()
    if abs(c + ref @ a - target) <= band and np.all((ref >= lower) & (ref <= upper)):
        assert es.reference_distance == 0.0


@pytest.mark.parametrize("kwargs, message", [
    (dict(polys=[], targets=[]), "one target per polynomial"),
    (dict(targets=[1.0, 2.0]), "one target per polynomial"),
    (dict(lower=[0.0, 1.0], upper=[1.0, 1.0]), "lower < upper"),
    (dict(lower=[0.0] * 4, upper=[1.0] * 4), "1 to 3 factors"),
    (dict(targets=[0.0]), "non-zero"),
    (dict(targets=[np.inf]), "non-zero"),
    (dict(tolerance=0.0), "tolerance must be positive"),
    (dict(reference=[0.5]), "one finite value per factor"),
    (dict(reference=[0.5, np.nan]), "one finite value per factor")])
def test_malformed_inputs_are_refused(kwargs, message):
    args = dict(polys=[Polynomial(np.array([[0, 0], [1, 0]]), np.array([1.0, 2.0]))], targets=[2.0], tolerance=0.1,
                lower=[0.0, 0.0], upper=[1.0, 1.0], reference=None)
    args.update(kwargs)
    if len(args["lower"]) == 4:
        args["polys"] = [Polynomial(np.zeros((1, 4), dtype=int), np.array([1.0]))]
    with pytest.raises(ValueError, match=message):
        exact_set(args["polys"], args["targets"], args["tolerance"], args["lower"], args["upper"],
                  reference=args["reference"])


@pytest.mark.parametrize("dim", [1, 2, 3])
def test_a_reference_meeting_the_targets_outside_the_box_is_at_its_distance_from_the_box_s_part(dim):
    """y = x0 with the target 1 and a 10 % band: the slab 0.9 <= x0 <= 1.1, of which the box [0, 1]^d holds
    0.9 to 1; a reference at x0 = 1.05 meets the target but lies outside the box, 0.05 of the range from the set."""
    exps = np.vstack([np.zeros(dim, dtype=int), np.eye(dim, dtype=int)[:1]])
    poly = Polynomial(exps, np.array([0.0, 1.0]))
    ref = np.r_[1.05, np.full(dim - 1, 0.5)]
    es = exact_set([poly], [1.0], 0.1, np.zeros(dim), np.ones(dim), reference=ref)
    assert es.reference_distance == pytest.approx(0.05, abs=1e-7)
    np.testing.assert_allclose(es.nearest_point, np.r_[1.0, np.full(dim - 1, 0.5)], atol=1e-6)
    inside = exact_set([poly], [1.0], 0.1, np.zeros(dim), np.ones(dim), reference=np.r_[0.95, np.full(dim - 1, 0.5)])
    assert inside.reference_distance == 0.0
