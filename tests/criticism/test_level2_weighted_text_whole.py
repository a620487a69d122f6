"""How level 2 words a weighted error (criticism.level2): with one tolerance for every observable, a percentage;
with the observables' own tolerances, a multiple of them to two significant digits down to 0.005 of them
(inclusive), below that "a negligible fraction of their own tolerances".  The multiple is parsed back against the
ratio computed here."""

from __future__ import annotations

import re
from types import SimpleNamespace

import numpy as np
import pytest

from demid.criticism.level2 import _weighted
from demid.criticism.messages import percent_text


@pytest.mark.parametrize("tolerance", [0.2, 0.1, 0.05, 1.0])
@pytest.mark.parametrize("ratio", [0.005, 0.0049, 0.006, 0.37, 1.0, 2.5, 14.0])
def test_a_weighted_error_is_a_multiple_of_the_own_tolerances_down_to_half_a_percent(tolerance, ratio):
    value = ratio * tolerance
    r = SimpleNamespace(uniform=False, tolerance=tolerance)
    text = _weighted(r, value)
    if value / tolerance >= 0.005:
        found = re.fullmatch(r"(\S+) times their own tolerances", text)
        assert found and float(found.group(1)) == float(f"{value / tolerance:.2g}")
        assert float(found.group(1)) == pytest.approx(ratio, rel=0.05)
    else:
        assert text == "a negligible fraction of their own tolerances"
    assert _weighted(SimpleNamespace(uniform=True, tolerance=tolerance), value) == percent_text(value)


def test_exactly_half_a_percent_of_the_tolerances_is_quoted():
    assert 0.001 / 0.2 == 0.005  # to the last bit
    assert _weighted(SimpleNamespace(uniform=False, tolerance=0.2), 0.001) == "0.005 times their own tolerances"
    below = float(np.nextafter(0.001, 0.0))
    assert _weighted(SimpleNamespace(uniform=False, tolerance=0.2), below) == "a negligible fraction of their own " \
                                                                             "tolerances"
