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

    from demid.pareto import _by_first_then_second

    rng = np.random.default_rng(7)
    for _ in range(100):
        n = int(rng.integers(1, 400))
        first = rng.integers(0, 8, n) * 0.25  # many ties in both objectives
        second = rng.integers(0, 5, n).astype(float)
        first[rng.random(n) < 0.05] = np.nan
        first[rng.random(n) < 0.05] = -0.0
        idx = np.flatnonzero(np.isfinite(first))
        assert np.array_equal(_by_first_then_second(first, second, idx), idx[np.lexsort((second[idx], first[idx]))])
