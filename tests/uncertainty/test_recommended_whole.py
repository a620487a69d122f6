"""The uninformative observables and the recommended point's digits against their rules written out here, over
generated rankings: single-observable shares on both sides of 99 % (and exactly at it), gains finite or not, sets of
two observables that never count; the digits of widths across twelve decades, at and just off powers of ten."""

from __future__ import annotations

import math
import re
from decimal import Decimal

import numpy as np
import pandas as pd
import pytest
from hypothesis import Phase, given, settings, strategies as st

from demid.uncertainty.recommended import digits_for, uninformative_observables


@settings(max_examples=30, deadline=None, derandomize=True, phases=(Phase.explicit, Phase.generate))
@given(seed=st.integers(0, 100_000), count=st.integers(1, 4))
def test_an_observable_is_uninformative_from_a_99_percent_share_with_its_numbers_quoted(seed, count):
    rng = np.random.default_rng(seed)
    names = [f"y{j}" for j in range(count)]
    shares = {o: float(rng.choice([99.0, 100.0, rng.uniform(99.0, 100.0), rng.uniform(90.0, 99.0),
                                   np.nextafter(99.0, 0.0), rng.uniform(0.0, 50.0)])) for o in names}
    gains = {o: float(rng.choice([np.nan, rng.uniform(0, 0.2), rng.uniform(0, 5)])) for o in names}
    rows = [{"observables": o, "n_observables": 1, "feasible_fraction_pct": shares[o],
             "information_gain_bits": gains[o]} for o in names]
    # a pair whose share is high says nothing about a single observable
    if count > 1:
        rows.append({"observables": "+".join(names), "n_observables": len(names), "feasible_fraction_pct": 99.9,
                     "information_gain_bits": 0.01})
    order = rng.permutation(len(rows))
    found = uninformative_observables(pd.DataFrame([rows[i] for i in order]))
    expected = [o for o in (rows[i]["observables"] for i in order) if o in shares and shares[o] >= 99.0]
    assert list(found) == expected
    for o, reason in found.items():
        share = float(re.search(r"alone it leaves ([\d.e+-]+) % of the search range admissible", reason).group(1))
        assert share == pytest.approx(shares[o], rel=5e-3)
        assert "so it removes less than 1 % and its information gain is ~0" in reason
        quoted = re.search(r" \(([\d.]+) bit: the likelihood only tilts across the range\)$", reason)
        if np.isfinite(gains[o]):
            assert float(quoted.group(1)) == pytest.approx(gains[o], abs=0.005 + 1e-12)
        else:
            assert quoted is None and reason.endswith("~0")


def test_no_ranking_or_no_single_observables_gives_no_uninformative_observable():
    assert uninformative_observables(None) == {}
    assert uninformative_observables(pd.DataFrame(columns=["observables", "n_observables"])) == {}
    assert uninformative_observables(pd.DataFrame({"observables": ["a"], "feasible_fraction_pct": [100.0]})) == {}
    without_gain = uninformative_observables(pd.DataFrame({"observables": ["a"], "n_observables": [1],
                                                           "feasible_fraction_pct": [99.5]}))
    assert list(without_gain) == ["a"] and without_gain["a"].endswith("~0")


def _decimals(width: float) -> int:
    """Decimals that show a tenth of ``width``: the position of the tenth's leading digit (Decimal arithmetic)."""
    tenth = Decimal(repr(width)) / 10
    return max(0, -tenth.adjusted())


@pytest.mark.parametrize("exponent", range(-8, 5))
@pytest.mark.parametrize("mantissa", [1.0, 1.0000001, 2.5, 9.99])
def test_digits_show_a_tenth_of_the_width(exponent, mantissa):
    width = float(f"{mantissa}e{exponent}")
    assert digits_for(width) == _decimals(width)
    assert digits_for(-width) == 4 and digits_for(0.0) == 4 and digits_for(math.nan) == 4 and digits_for(math.inf) == 4
