import numpy as np
import pandas as pd
import pytest

from demid.pareto import pareto_analysis, pareto_front


def test_front_of_known_points():
    first = np.array([1, 2, 3, 4, 2, 5, 1])
    second = np.array([5, 3, 4, 1, 3, 0.5, 6])
    idx = pareto_front(first, second)
    assert idx.tolist() == [0, 1, 3, 5]  # duplicate (2,3) kept once, (3,4) and (1,6) dominated


def test_front_matches_brute_force():
    rng = np.random.default_rng(11)
    a, b = rng.random(400), rng.random(400)
    idx = set(pareto_front(a, b).tolist())
    brute = {i for i in range(400)
             if not np.any((a <= a[i]) & (b <= b[i]) & ((a < a[i]) | (b < b[i])))}
    assert idx == brute



@pytest.mark.parametrize("seed", range(5))
def test_front_with_ties_and_gaps_matches_brute_force_in_order(seed):
    """Tied values, exact duplicates, NaN and inf: the non-dominated points (of duplicates the first),
    in order of increasing first objective, ties by the second, then by index."""
    rng = np.random.default_rng(seed)
    for _ in range(300):
        n, levels = int(rng.integers(0, 40)), int(rng.integers(1, 6))
        a = rng.integers(0, levels, n).astype(float)
        b = rng.integers(0, levels, n).astype(float)
        a[rng.random(n) < 0.05] = np.nan
        b[rng.random(n) < 0.05] = np.inf
        ok = [i for i in range(n) if np.isfinite(a[i]) and np.isfinite(b[i])]
        front = [i for i in ok
                 if not any((a[j] <= a[i] and b[j] <= b[i] and (a[j] < a[i] or b[j] < b[i]))
                            or (a[j] == a[i] and b[j] == b[i] and j < i) for j in ok)]
        assert pareto_front(a, b).tolist() == sorted(front, key=lambda i: (a[i], b[i], i))

def test_analytic_front_on_a_line():
    # error = |x - 0.5|/0.5 relative to target 0.5 of D = x; objective S = y + (1 - x)
    x, y = np.meshgrid(np.linspace(0, 1, 101), np.linspace(0, 1, 101), indexing="ij")
    grid = pd.DataFrame({"x": x.ravel(), "y": y.ravel(), "D": x.ravel(), "S": y.ravel() + 1 - x.ravel()})
    res = pareto_analysis(grid, ["x", "y"], "D", 0.5, "S", 0.19)
    # Front: y = 0 and x >= 0.5 (larger x lowers S but raises the error).
    assert (res.front["y"] == 0).all() and (res.front["x"] >= 0.5 - 1e-12).all()
    iv = res.intervals.set_index("factor")
    assert iv.loc["x", "lower"] == pytest.approx(0.5) and iv.loc["x", "upper"] == pytest.approx(0.59)


def test_sort_order_is_the_two_key_lexsort_with_ties():
    """The front's sort (one quicksort, full sort of tied runs only) equals lexsort((second, first))."""
    import numpy as np

    from demid.pareto import by_first_then_second

    rng = np.random.default_rng(7)
    for _ in range(100):
        n = int(rng.integers(1, 400))
        first = rng.integers(0, 8, n) * 0.25  # many ties in both objectives
        second = rng.integers(0, 5, n).astype(float)
        first[rng.random(n) < 0.05] = np.nan
        first[rng.random(n) < 0.05] = -0.0
        idx = np.flatnonzero(np.isfinite(first))
        assert np.array_equal(by_first_then_second(first, second, idx), idx[np.lexsort((second[idx], first[idx]))])


def _bowl(best_x1: float):
    """y1 = 10 + 10 x1 (target 15) against y3 = 100 + 10 x2 + 10 (x1 - b)^2 + 5 (x3 - 0.4)^2 + 5 (x4 - 0.6)^2 on
    [0, 1]^4, b = ``best_x1``: the factor names, the surrogates, the domain and the front sampled from 4096 Sobol
    points (error cap 2 %)."""
    from demid.design import quadratic_terms
    from demid.sampling.domain import Domain
    from demid.sampling.grid import predict_grid
    from demid.surrogate import Surrogate

    names, terms = ["x1", "x2", "x3", "x4"], quadratic_terms(4)
    first = np.zeros(len(terms))
    first[[0, 1]] = [10.0, 10.0]
    second = np.zeros(len(terms))  # Intercept, x1..x4, six interactions, x1^2..x4^2
    second[[0, 1, 2, 3, 4]] = [100 + 10 * best_x1 ** 2 + 0.8 + 1.8, -20 * best_x1, 10.0, -4.0, -6.0]
    second[-4:] = [10.0, 0.0, 5.0, 5.0]
    surrogates = {y: Surrogate(y, names, terms, c, np.zeros((len(terms), len(terms))), 0.0, 30)
                  for y, c in (("y1", first), ("y3", second))}
    domain = Domain(tuple(names), (0.0,) * 4, (1.0,) * 4)
    grid = predict_grid(surrogates, domain, 4096)
    return names, surrogates, domain, pareto_analysis(grid, names, "y1", 15.0, "y3", 0.02)


def test_a_four_factor_front_is_refined_to_the_known_optimum():
    """Above three factors the front comes from Sobol points: 4096 of them left a handful of front points and
    intervals outside the optimum.  y1 = 10 + 10 x1 (target 15: error |x1 - 0.5| / 1.5) against
    y3 = 100 + 10 x2 + 10 (x1 - 0.3)^2 + 5 (x3 - 0.4)^2 + 5 (x4 - 0.6)^2 on [0, 1]^4: under an error cap e the
    optimum is x1 = 0.5 - 1.5 e, x2 = 0, x3 = 0.4, x4 = 0.6, so below 2 % x1 lies in (0.47, 0.5]."""
    from demid.pareto import front_intervals, polish_front

    names, surrogates, domain, sampled = _bowl(0.3)
    front = polish_front(surrogates, domain, names, "y1", 15.0, "y3", 0.02, sampled.front)
    iv = front_intervals(front, names, 0.02).set_index("factor")
    assert iv.loc["x1", "lower"] == pytest.approx(0.47, abs=2e-3) and iv.loc["x1", "upper"] == pytest.approx(0.5, abs=1e-4)
    for name, value in (("x2", 0.0), ("x3", 0.4), ("x4", 0.6)):
        assert iv.loc[name, ["lower", "upper"]].to_numpy(float) == pytest.approx([value, value], abs=1e-3), name
    # the sampled front alone is far from it (the premise of the refinement)
    raw = sampled.intervals.set_index("factor")
    assert raw.loc["x3", "upper"] - raw.loc["x3", "lower"] > 0.01 or raw.loc["x2", "upper"] > 0.01


@pytest.mark.parametrize("best_x1", [0.3, 0.7])
def test_every_polished_front_point_is_the_optimum_at_its_error(best_x1):
    """y1 = 10 + 10 x1 against the target 15 (error e = |10 x1 - 5| / 15) and y3 = 100 + 10 x2 + 10 (x1 - b)^2
    + 5 (x3 - 0.4)^2 + 5 (x4 - 0.6)^2 on [0, 1]^4, b = 0.3 (under-predicting y1 pays) or 0.7 (over-predicting
    does): at error e the least y3 is 100 + 10 (0.2 - 1.5 e)^2, up to the front's end at e = 2/15, where y3 = 100.
    Every polished point lies on that curve, the front runs from e = 0 to its end, and its columns are the
    factors, the error and the objective."""
    from demid.pareto import polish_front

    names, surrogates, domain, sampled = _bowl(best_x1)
    front = polish_front(surrogates, domain, names, "y1", 15.0, "y3", 0.02, sampled.front)
    assert list(front.columns) == [*names, "error", "objective"]
    e = front["error"].to_numpy()
    assert np.all(e <= 2 / 15 * (1 + 1e-6))  # the polish meets each cap to a millionth
    assert front["objective"].to_numpy() == pytest.approx(100 + 10 * (0.2 - 1.5 * e) ** 2, abs=1e-5)
    assert e.min() <= 0.02 / 20 + 1e-12 and e.max() == pytest.approx(2 / 15, abs=1e-6)  # first cap: 0.02 / 20
    x1 = front["x1"].to_numpy()
    side = -1.0 if best_x1 < 0.5 else 1.0
    assert x1 == pytest.approx(0.5 + side * 1.5 * e, abs=1e-5)
    # beyond the cap the front is polished at 20 even steps up to its end, found by the polish itself when the
    # sampled front stops short of it
    short = sampled.front[sampled.front["error"] <= 0.05]
    assert short["error"].max() < 0.06
    tail = polish_front(surrogates, domain, names, "y1", 15.0, "y3", 0.02, short)
    e = np.sort(tail["error"].to_numpy())
    assert e.max() == pytest.approx(2 / 15, abs=1e-5)  # the end as L-BFGS-B finds the least y3
    assert np.all(np.diff(e[e >= 0.02]) <= (2 / 15 - 0.02) / 20 + 1e-6)
    assert tail["objective"].to_numpy() == pytest.approx(100 + 10 * (0.2 - 1.5 * tail["error"].to_numpy()) ** 2,
                                                         abs=1e-5)
