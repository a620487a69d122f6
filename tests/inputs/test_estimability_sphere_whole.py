"""The one-sphere test of the quadratic's estimability on and past its edge: usable runs whose squared distances from
the design centre spread by at most 1 % of the largest (printed levels put a spherical design only nearly on its
sphere) cannot separate the intercept from the squared terms and are refused; a spread a little above 1 % is no
sphere.  Over two to four factors, designs scaled up or down, with and without point types."""

from __future__ import annotations

import numpy as np
import pytest

from demid.design import ccd_points, classify_points
from demid.errors import InputError
from demid.estimability import require_estimable


def _ccd_without_centre(k: int, spread: float, scale: float) -> np.ndarray:
    """A CCD without centre runs whose axial runs' squared radius is (1 - spread) times the factorial's (k)."""
    alpha = np.sqrt(k * (1 - spread))
    return ccd_points(k, alpha, 0) * scale


@pytest.mark.parametrize("k", [2, 3, 4])
@pytest.mark.parametrize("scale", [1.0, 0.1, 7.0])
@pytest.mark.parametrize("spread, sphere", [(0.0, True), (0.0099, True), (0.00999, True), (0.0101, False),
                                            (0.02, False)])
def test_runs_within_one_percent_of_one_sphere_are_refused(k, scale, spread, sphere):
    coded = _ccd_without_centre(k, spread, scale)
    usable = np.ones(len(coded), dtype=bool)
    radius = np.sum(coded ** 2, axis=1)
    assert np.ptp(radius) / radius.max() == pytest.approx(spread, abs=1e-12)
    for types in (None, classify_points(coded, np.sqrt(k * (1 - spread)) * scale)):
        if sphere:
            with pytest.raises(InputError, match="every usable run lies at the same distance from the design "
                                                 "centre"):
                require_estimable(coded, usable, types, "t.csv", "y")
        else:
            require_estimable(coded, usable, types, "t.csv", "y")
