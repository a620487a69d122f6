"""The surrogate choice's rule, number by number: kriging judges a response's sets when its leave-one-out error
(1 - Q²) is at most half the quadratic's, or at most 0.8 of it where the quadratic misfits (Q² < 0.9); the
sentence that keeps the quadratic quotes the share that applied."""

import re

import numpy as np
import pytest

from demid.surrogate_choice import (CHOICE_PRESS_RATIO, MISFIT_PRESS_RATIO, QUADRATIC_ADEQUATE_Q2, choice_text,
                                    prefers_kriging, required_ratio)


def _by_definition(q2_q: float, q2_k: float) -> bool:
    if not np.isfinite(q2_k):
        return False
    if not np.isfinite(q2_q):
        return True
    share = 0.8 if q2_q < 0.9 else 0.5
    return (1 - q2_k) <= share * (1 - q2_q)


def test_the_constants_are_the_documented_ones():
    assert (CHOICE_PRESS_RATIO, MISFIT_PRESS_RATIO, QUADRATIC_ADEQUATE_Q2) == (0.5, 0.8, 0.9)


@pytest.mark.parametrize("q2_q, q2_k, expected", [
    (0.30, 0.441, True),    # misfitting quadratic: 0.559 <= 0.8 x 0.70
    (0.30, 0.43, False),    # 0.57 > 0.56
    (0.487, 0.716, True),   # a ridge's wave: 0.284 <= 0.410 (the half margin alone said no: 0.284 > 0.257)
    (0.899, 0.92, True),    # just misfitting: 0.08 <= 0.0808
    (0.90, 0.92, False),    # adequate: 0.08 > 0.05
    (0.90, 0.951, True),    # 0.049 <= 0.05
    (0.96, 0.975, False),
    (0.96, 0.98, True),
    (-0.5, -0.1, True),     # neither predicts, kriging's error 1.1 <= 0.8 x 1.5
    (-0.5, -0.3, False),
    (float("nan"), 0.2, True),
    (0.5, float("nan"), False),
])
def test_prefers_kriging_at_the_margins(q2_q, q2_k, expected):
    assert prefers_kriging(q2_q, q2_k) is expected
    assert _by_definition(q2_q, q2_k) is expected


def test_prefers_kriging_over_a_grid_of_q2_pairs():
    grid = np.round(np.linspace(-1.0, 1.0, 81), 6)
    for q2_q in grid:
        for q2_k in grid:
            assert prefers_kriging(float(q2_q), float(q2_k)) == _by_definition(float(q2_q), float(q2_k)), (q2_q, q2_k)


def test_required_ratio_switches_at_the_adequate_q2():
    assert required_ratio(0.8999) == 0.8 and required_ratio(0.9) == 0.5 and required_ratio(-3.0) == 0.8


@pytest.mark.parametrize("q2_q, q2_k, share", [(0.95, 0.96, "0.5"), (0.6, 0.62, "0.8")])
def test_the_sentence_keeping_the_quadratic_quotes_the_share_that_applied(q2_q, q2_k, share):
    from collections import namedtuple

    row = namedtuple("Row", "response q2 surrogate q2_quadratic q2_kriging")("θ", q2_q, "quadratic", q2_q, q2_k)
    text = choice_text("θ", row)
    quoted = re.search(r"error to ([0-9.]+) of the quadratic's", text)
    assert quoted and quoted.group(1) == share, text
