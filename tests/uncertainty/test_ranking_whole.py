"""The observable ranking's whole table against its definition, recomputed from the table's own fractions and
the posteriors' gains (every subset once; each set's best proper subset, contraction and gain over it; the rank by
fraction; the order and the ranks), and each single observable's feasible fraction against a fine Monte Carlo
count of its band, over generated linear surrogates of two factors, 1-3 observables, target signs and tolerances."""

from __future__ import annotations

from dataclasses import dataclass
from itertools import combinations

import numpy as np
import pytest
from hypothesis import given, settings, strategies as st

from demid.sampling.domain import Domain
from demid.spec import join_observables
from demid.surrogate import Surrogate
from demid.uncertainty.posterior import NO_OBSERVABLE
from demid.uncertainty.ranking import rank_observable_sets

SQUARE = Domain(("a", "b"), (0.0, 0.0), (1.0, 1.0))


@dataclass
class _Posterior:
    information_gain_bits: float
    information_gain_error_bits: float


def _plane(name: str, coefficients) -> Surrogate:
    """y = c0 + c1 a + c2 b."""
    return Surrogate(name, ["a", "b"], [(0, 0), (1, 0), (0, 1)], np.asarray(coefficients, dtype=float), np.eye(3) * 1e-6,
                     0.01, 10)


@settings(max_examples=12, derandomize=True, deadline=None)
@given(seed=st.integers(0, 10_000), k=st.integers(1, 3), tolerance=st.sampled_from([0.03, 0.1, 0.2]),
       negative=st.booleans(), tied=st.booleans())
def test_the_ranking_table_is_its_definition(seed, k, tolerance, negative, tied):
    rng = np.random.default_rng(seed)
    names = [f"y{i}" for i in range(k)]
    sign = -1.0 if negative else 1.0
    surrogates, targets = {}, {}
    for name in names:
        c = np.array([sign * rng.uniform(5, 20), rng.uniform(-4, 4), rng.uniform(-4, 4)])
        surrogates[name] = _plane(name, c)
        at = rng.uniform(0.2, 0.8, 2)
        targets[name] = float(c[0] + c[1] * at[0] + c[2] * at[1])  # reached inside the square
    subsets = [s for size in range(1, k + 1) for s in combinations(names, size)]
    gains = {s: float(round(rng.uniform(0, 3), 1 if tied else 6)) for s in subsets}
    posteriors = {s: _Posterior(gains[s], 0.01 * (i + 1)) for i, s in enumerate(subsets)}
    frame = rank_observable_sets(surrogates, SQUARE, names, targets, {n: 1.0 for n in names}, tolerance, 41,
                                 posteriors=posteriors)

    by_name = {join_observables(s): s for s in subsets}
    assert sorted(frame["observables"]) == sorted(by_name) and len(frame) == len(subsets)
    frac = {(): 1.0, **{by_name[r.observables]: r.feasible_fraction_pct / 100 for r in frame.itertuples()}}
    gain = {(): 0.0, **gains}
    for r in frame.itertuples():
        s = by_name[r.observables]
        assert r.targets_reachable and r.n_observables == len(s) and r.tolerance == tolerance
        assert r.information_gain_bits == gains[s] and r.information_gain_error_bits == posteriors[s]. \
            information_gain_error_bits
        proper = [t for size in range(len(s)) for t in combinations(s, size)]
        best = min(proper, key=lambda t: (frac[t], -gain[t]))
        assert r.best_subset == (join_observables(best) or NO_OBSERVABLE)
        assert r.gain_vs_best_subset_bits == pytest.approx(gain[s] - gain[best], abs=1e-12)
        if frac[best] > 0:
            expected = 100 * (1 - frac[s] / frac[best])
            assert r.contraction_pct_vs_best_subset == pytest.approx(0.0 if abs(expected) < 1e-9 else expected,
                                                                      abs=1e-9)
        else:
            assert np.isnan(r.contraction_pct_vs_best_subset)
        # a fraction never exceeds one of its subsets' (every observable must be met)
        assert all(frac[s] <= frac[t] + 1e-12 for t in proper)
    # ranks by fraction: the smallest fraction first, ties sharing the lowest rank
    fractions = frame["feasible_fraction_pct"].to_numpy()
    for r, f in zip(frame["rank_by_fraction"], fractions):
        assert r == 1 + int(np.sum(fractions < f))
    # the order: information gain down, then fraction up; ranks 1..n
    keys = list(zip(-frame["information_gain_bits"], frame["feasible_fraction_pct"]))
    assert keys == sorted(keys) and list(frame["rank"]) == list(range(1, len(frame) + 1))


@pytest.mark.parametrize("seed", [0, 1, 2])
def test_a_single_observables_fraction_is_its_band_on_the_square(seed):
    """The share of the square where |y - t| <= tolerance |t|, against 400,000 uniform points (the grid's
    resolution bounds the difference)."""
    rng = np.random.default_rng(seed)
    c = np.array([(-1) ** seed * rng.uniform(8, 15), rng.uniform(-5, 5), rng.uniform(-5, 5)])
    target = float(c[0] + c[1] * 0.5 + c[2] * 0.4)
    tolerance = 0.1
    frame = rank_observable_sets({"y": _plane("y", c)}, SQUARE, ["y"], {"y": target}, {"y": 1.0}, tolerance, 101,
                                 posteriors={("y",): _Posterior(1.0, 0.1)})
    u = rng.uniform(0, 1, (400_000, 2))
    inside = np.abs(c[0] + u @ c[1:] - target) <= tolerance * abs(target)
    assert frame["feasible_fraction_pct"].iloc[0] == pytest.approx(100 * inside.mean(), abs=1.5)
