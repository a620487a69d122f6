"""The ranking's contraction and gain over the best subset, against the table's own columns: for every row,
``contraction_pct_vs_best_subset`` is 100 (1 - fraction / best subset's fraction) and ``gain_vs_best_subset_bits``
the difference of the two gains, whatever its sign.  A stored exact set of a pair may come out larger than its
single observables' sets (two estimates of nearly the same set); the table then shows the negative contraction
rather than hiding it, and only a difference below 1e-9 % is written as 0."""

from __future__ import annotations

from dataclasses import dataclass, replace

import numpy as np
import pytest

from demid.sampling import Domain
from demid.sampling.evaluate import evaluate_set
from demid.uncertainty.ranking import rank_observable_sets

from .test_uncertainty import linear


@dataclass
class _Posterior:
    information_gain_bits: float
    information_gain_error_bits: float


@pytest.mark.parametrize("ratio", [0.04, 0.5, 1.0, 1.0 + 1e-13, 1.004, 1.3])
def test_contraction_is_read_from_the_fractions_whatever_its_sign(ratio):
    square = Domain(("a", "b"), (0.0, 0.0), (1.0, 1.0))
    y, z = linear(0.0, [1.0, 0.0]), linear(0.0, [0.0, 1.0])
    y.response, z.response = "y", "z"
    surrogates, targets = {"y": y, "z": z}, {"y": 0.5, "z": 0.5}
    pair = evaluate_set(surrogates, square, ("y", "z"), targets, 0.1, 21)
    assert pair.exact is not None
    # y alone admits 10 % of the square (|a - 0.5| <= 0.05), z alone 10 % too (|b - 0.5| <= 0.05); the pair's
    # stored fraction is set at ``ratio`` times 10 %, below, at and above its single observables' fractions
    stored = {frozenset({"y", "z"}): replace(pair, fraction=0.1 * ratio)}
    posteriors = {("y",): _Posterior(1.0, 0.01), ("z",): _Posterior(0.7, 0.02), ("y", "z"): _Posterior(2.5, 0.03)}
    frame = rank_observable_sets(surrogates, square, ["y", "z"], targets, {"y": 0.05, "z": 0.05}, 0.1, 21,
                                 posteriors=posteriors, strict_sets=stored).set_index("observables")
    pct = frame["feasible_fraction_pct"]
    np.testing.assert_allclose(pct[["y", "z"]], [10.0, 10.0], rtol=1e-9)
    assert pct["y+z"] == pytest.approx(10.0 * ratio, rel=1e-12)
    for name, row in frame.iterrows():
        best = row["best_subset"]
        best_pct = 100.0 if best == "(none)" else pct[best]
        best_gain = 0.0 if best == "(none)" else frame.loc[best, "information_gain_bits"]
        expected = 100.0 * (1.0 - row["feasible_fraction_pct"] / best_pct)
        if abs(expected) < 1e-9:
            assert row["contraction_pct_vs_best_subset"] == 0.0
        else:
            assert row["contraction_pct_vs_best_subset"] == pytest.approx(expected, rel=1e-9)
        assert row["gain_vs_best_subset_bits"] == pytest.approx(row["information_gain_bits"] - best_gain, abs=1e-12)
    # the pair's best subset is y: as narrow as z, with the larger gain
    assert frame.loc["y+z", "best_subset"] == "y"
    assert np.sign(frame.loc["y+z", "contraction_pct_vs_best_subset"]) == (np.sign(1.0 - ratio)
                                                                            if abs(1.0 - ratio) > 1e-11 else 0.0)
