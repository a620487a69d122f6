"""A transformed model's back-transform (criticism.models.inv_boxcox): the closed form (1 + lambda z)^(1/lambda)
(exp(z) for the log) wherever its logarithm lies within +-700, and e^(+-700) beyond, so that a surrogate
extrapolated far outside its runs predicts a finite value (e^700 is about 1e304, 17,000 times below overflow,
so relative errors and differences of such values stay finite too).  Checked on both sides of the cap for the
log, sqrt, inverse and other lambdas, at logarithms just inside and just outside it (where a lambda reaches it)."""

from __future__ import annotations

import numpy as np
import pytest

from demid.criticism.models import inv_boxcox


@pytest.mark.parametrize("lam", [0.0, 0.5, -1.0, 2.0, -0.25, 0.01])
def test_the_back_transform_is_the_closed_form_within_the_cap_and_the_cap_beyond(lam):
    # logarithms of the back-transformed value, inside and beyond +-700
    logs = np.array([-720.0, -700.5, -699.5, -3.0, 0.0, 2.5, 699.5, 700.5, 720.0])
    if lam != 0:
        # the z whose back-transform has these logarithms, where z is a double and 1 + lambda z is not below the
        # 1e-12 floor the back-transform puts under it (for lambda < 0 only the lower cap is in reach, for
        # lambda > 0 the lower one only when lambda is small)
        logs = logs[(lam * logs > np.log(1e-12) + 1) & (lam * logs < 700)]
    z = logs if lam == 0 else np.expm1(lam * logs) / lam
    got = inv_boxcox(z, lam)
    expected = np.exp(np.clip(logs, -700.0, 700.0))
    np.testing.assert_allclose(got, expected, rtol=1e-9)
    assert np.all(np.isfinite(got)) and np.all(got > 0)
    assert got.max() <= np.exp(700.0) and got.min() >= np.exp(-700.0)
