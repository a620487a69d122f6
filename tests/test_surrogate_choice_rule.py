"""The surrogate choice's rule, number by number: kriging judges a response's sets when its leave-one-out error
(1 - Q²) is at most half the quadratic's, or at most 0.8 of it where the quadratic misfits (lack of fit p <= 0.05
where replicates give the test, else Q² < 0.9); the sentence that keeps the quadratic quotes the share that
applied."""

import re

import numpy as np
import pytest

from demid.surrogate_choice import (CHOICE_PRESS_RATIO, MISFIT_P, MISFIT_PRESS_RATIO, QUADRATIC_ADEQUATE_Q2,
                                    choice_text, prefers_kriging, quadratic_misfits, required_ratio)

NAN = float("nan")


def _by_definition(q2_q: float, q2_k: float, lof_p: float = NAN) -> bool:
    if not np.isfinite(q2_k):
        return False
    if not np.isfinite(q2_q):
        return True
    misfits = lof_p <= 0.05 if np.isfinite(lof_p) else q2_q < 0.9
    share = 0.8 if misfits else 0.5
    return (1 - q2_k) <= share * (1 - q2_q)


def test_the_constants_are_the_documented_ones():
    assert (CHOICE_PRESS_RATIO, MISFIT_PRESS_RATIO, QUADRATIC_ADEQUATE_Q2, MISFIT_P) == (0.5, 0.8, 0.9, 0.05)


@pytest.mark.parametrize("q2_q, q2_k, lof_p, expected", [
    (0.85, 0.87, 0.30, False),   # Q² below 0.9 through scatter: no lack of fit, so the half margin (0.13 > 0.075)
    (0.85, 0.885, 0.05, True),   # lack of fit at p = 0.05: misfit, 0.115 <= 0.8 x 0.15
    (0.95, 0.961, 0.01, True),   # Q² 0.95 but lack of fit: 0.039 <= 0.8 x 0.05
    (0.95, 0.961, 0.051, False),  # no lack of fit: 0.039 > 0.025
    (0.30, 0.50, 0.20, False),   # a poor Q² with no lack of fit found: the half margin, 0.5 > 0.35
    (0.30, 0.50, NAN, True),     # no replicates: Q² < 0.9 is the sign, 0.5 <= 0.56
])
def test_lack_of_fit_decides_misfit_where_replicates_give_it(q2_q, q2_k, lof_p, expected):
    assert _by_definition(q2_q, q2_k, lof_p) is expected
    assert prefers_kriging(q2_q, q2_k, lof_p) is expected
    assert quadratic_misfits(q2_q, lof_p) is (lof_p <= 0.05 if np.isfinite(lof_p) else q2_q < 0.9)


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


def test_prefers_kriging_over_a_grid_of_q2_pairs_and_lack_of_fit():
    grid = np.round(np.linspace(-1.0, 1.0, 41), 6)
    for lof_p in (NAN, 0.001, 0.05, 0.0501, 0.6):
        for q2_q in grid:
            for q2_k in grid:
                assert prefers_kriging(float(q2_q), float(q2_k), lof_p) == _by_definition(float(q2_q), float(q2_k), lof_p)


def test_required_ratio_switches_at_the_adequate_q2_and_at_the_lack_of_fit_level():
    assert required_ratio(0.8999) == 0.8 and required_ratio(0.9) == 0.5 and required_ratio(-3.0) == 0.8
    assert required_ratio(0.99, 0.05) == 0.8 and required_ratio(0.99, 0.0501) == 0.5
    assert required_ratio(-3.0, 0.5) == 0.5


@pytest.mark.parametrize("q2_q, q2_k, lof_p, share", [(0.95, 0.96, NAN, "0.5"), (0.6, 0.62, NAN, "0.8"),
                                                      (0.6, 0.62, 0.4, "0.5"), (0.95, 0.955, 0.01, "0.8")])
def test_the_sentence_keeping_the_quadratic_quotes_the_share_that_applied(q2_q, q2_k, lof_p, share):
    from collections import namedtuple

    row = namedtuple("Row", "response q2 lof_p surrogate q2_quadratic q2_kriging")("θ", q2_q, lof_p, "quadratic", q2_q,
                                                                                  q2_k)
    text = choice_text("θ", row)
    quoted = re.search(r"error to ([0-9.]+) of the quadratic's", text)
    assert quoted and quoted.group(1) == share, text
