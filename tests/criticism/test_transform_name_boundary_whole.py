"""The name of a Box-Cox lambda (criticism.models.transform_name) at and around its 1e-9 matching distance from
log (0), sqrt (0.5) and inverse (-1): within 1e-9 it is the named transform, exactly 1e-9 away or farther it is
``boxcox:<lambda>``, whose printed lambda reads back to the lambda to six significant digits."""

from __future__ import annotations

import numpy as np
import pytest

from demid.criticism.models import TRANSFORM_NAMES, transform_name


def _offsets(value):
    """Lambdas near ``value`` with their distance from it as floating point computes it."""
    out = []
    for d in (1e-9, np.nextafter(1e-9, 0.0), np.nextafter(1e-9, 1.0), 5e-10, 2e-9, 1e-6):
        for lam in (value + d, value - d, np.nextafter(value + d, value), np.nextafter(value - d, value)):
            out.append(float(lam))
    return out


@pytest.mark.parametrize("value,name", list(TRANSFORM_NAMES.items()))
def test_a_lambda_is_named_only_strictly_within_1e_9(value, name):
    exact = 0
    for lam in _offsets(value):
        gap = abs(lam - value)
        exact += gap == 1e-9
        got = transform_name(lam)
        if gap < 1e-9:
            assert got == name, (lam, gap)
        else:
            assert got.startswith("boxcox:"), (lam, gap)
            assert float(got.split(":")[1]) == pytest.approx(lam, rel=5e-6, abs=5e-15)
    if value == 0.0:
        assert exact >= 2  # +-1e-9 itself: exactly on the distance, so not "log"
        assert transform_name(1e-9) == "boxcox:1e-09" and transform_name(-1e-9) == "boxcox:-1e-09"


def test_lambdas_far_from_every_name_print_their_value():
    for lam in (0.25, -0.5, 1.0, 2.0, -2.0, 0.333333333, 1e-3, -0.999):
        got = transform_name(lam)
        assert got == f"boxcox:{lam:g}" and float(got[7:]) == pytest.approx(lam, rel=5e-6)
