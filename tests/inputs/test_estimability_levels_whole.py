"""Which factors the refusal of a rank-deficient quadratic says are at fewer than three levels (demid.estimability),
over generated factorial tables of 3-4 factors, each at two or three levels, with one more run whose value of one
other factor sits 0, 3e-7, 3e-6 or 3e-5 coded units off a level: levels are told apart as the replicate rule tells design
points apart (equal to six decimals, demid.design.REPLICATE_DECIMALS), so a value 3e-7 off is its level and one
3e-6 off is a level of its own; the factors named are exactly those, in column order."""

from __future__ import annotations

import re
from itertools import product

import numpy as np
import pytest
from hypothesis import Phase, given, settings
from hypothesis import strategies as st

from demid.design import REPLICATE_DECIMALS
from demid.errors import InputError
from demid.estimability import require_estimable


@given(k=st.integers(3, 4), middle=st.lists(st.booleans(), min_size=2, max_size=2), shifted=st.data(),
       off=st.sampled_from([0.0, 3e-7, 3e-6, 3e-5]), sign=st.sampled_from([-1.0, 1.0]))
@settings(max_examples=24, deadline=None, derandomize=True, phases=[Phase.explicit, Phase.generate])
def test_the_factors_named_at_fewer_than_three_levels_follow_the_replicate_rule(k, middle, shifted, off, sign):
    # the first factor at two levels (the quadratic cannot be estimated), the last at three (the runs are on no
    # sphere), the others either
    three = [False, *middle[:k - 2], True]
    levels = [(-1.0, 0.0, 1.0) if t else (-1.0, 1.0) for t in three]
    runs = np.array(list(product(*levels)) * 2)
    j = shifted.draw(st.integers(1, k - 1))  # the first factor stays at two levels
    extra = runs[0].copy()
    extra[j] = sign * (1.0 + off)
    coded = np.vstack([runs, extra])
    factors = [f"x{i}" for i in range(k)]
    assert REPLICATE_DECIMALS == 6
    distinct = [len({round(float(v), 6) for v in coded[:, i]}) for i in range(k)]
    expected = [f for f, n in zip(factors, distinct) if n < 3]
    assert expected[0] == "x0"
    with pytest.raises(InputError) as info:
        require_estimable(coded, np.ones(len(coded), dtype=bool), None, "t.csv", "y", factors)
    detail = info.value.detail
    assert detail.startswith("the quadratic model cannot be estimated (rank "), detail
    named = re.search(r"\(([^()]*) at fewer than three levels: a squared term needs three\)", detail)
    assert named, detail
    assert named.group(1).split(", ") == expected
