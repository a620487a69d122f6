"""A star design (centre and axial runs, no factorial points) cannot estimate any two-factor interaction: every
run has at most one factor away from the centre.  The refusal names exactly those terms, listed as a sentence
('f0:f1', 'f0:f1, f0:f2 and f1:f2', ...), one term named alone; the rank quoted is the design's own."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from demid.errors import InputError
from demid.estimability import require_estimable

SETTINGS = settings(max_examples=8, deadline=None, derandomize=True)


@given(k=st.integers(2, 4), alpha=st.sampled_from([1.0, 1.414, 2.0]))
@SETTINGS
def test_a_star_design_is_refused_naming_every_interaction(k, alpha):
    p = (k + 1) * (k + 2) // 2
    axial = np.vstack([sign * alpha * np.eye(k) for sign in (-1.0, 1.0)])
    coded = np.vstack([axial, np.zeros((p + 1 - 2 * k, k))])  # enough runs: only the rank can refuse
    factors = [f"f{i}" for i in range(k)]
    with pytest.raises(InputError) as info:
        require_estimable(coded, np.ones(len(coded), dtype=bool), None, "t.csv", "y", factors)
    interactions = [f"f{i}:f{j}" for i in range(k) for j in range(i + 1, k)]
    listed = interactions[0] if len(interactions) == 1 else ", ".join(interactions[:-1]) + f" and {interactions[-1]}"
    rank = p - len(interactions)
    assert info.value.detail == (f"the quadratic model cannot be estimated (rank {rank} of {p} terms): "
                                 f"the usable runs cannot tell {listed} apart")
