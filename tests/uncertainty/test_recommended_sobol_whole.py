"""The recommended point above three factors is the least implausible of the documented point set: 2^14 scrambled
Sobol points (seed 0) over the search box (log10 for log factors), written out here with scipy's generator, for
plausible sets centred anywhere in 4 and 5 factors; with its implausibility and membership at that point."""

from __future__ import annotations

import numpy as np
import pytest
from scipy.stats import qmc

from demid.uncertainty.recommended import recommended_point

from .test_recommended import _Judged, _search_range, _spec


# centres whose least implausible Sobol point is among the sample's last 2^13 (but the first): half the sample misses it
@pytest.mark.parametrize("d, where, scale", [(4, 0.37, 0.2), (4, 0.71, 0.02), (5, 0.37, 0.5), (5, 0.55, 0.1)])
def test_above_three_factors_the_point_is_the_least_implausible_of_two_to_the_fourteen_sobol_points(d, where, scale):
    spec = _spec(min(d, 4))
    if d == 5:  # a fifth factor, linear, on a range away from zero
        from demid.spec import MaterialSpec

        spec = MaterialSpec.from_material("m", {
            "data": "x.csv", "design": {"type": "custom"},
            "factors": {**{f.name: {"lower": f.lower, "upper": f.upper, **({"scale": "log"} if f.log else {})}
                           for f in spec.factors}, "f4": {"lower": 40.0, "upper": 90.0}},
            "responses": {"y": {"target": 1.0}}, "scenarios": {"s": {"observables": ["y"], "tolerance": 0.05}}})
    lo, hi = _search_range(spec)
    centre = lo + (where + 0.05 * np.arange(d)) % 1.0 * (hi - lo)
    judged = _Judged(spec, centre, scale * (hi - lo))
    found = recommended_point(judged)
    sample = lo + qmc.Sobol(d, scramble=True, seed=0).random(2 ** 14) * (hi - lo)
    values = np.max(np.abs(sample - centre) / (scale * (hi - lo)), axis=1)
    best = int(np.argmin(values))
    assert (best >= 2 ** 13) == (where != 0.37 or d == 5)
    point = spec.domain.to_search(np.array([list(found["point"].values())]))[0]
    np.testing.assert_allclose(point, sample[best], rtol=1e-12, atol=1e-12)
    assert found["implausibility"] == pytest.approx(values[best], rel=1e-9)
    assert found["plausible"] is bool(values[best] <= 1.0)
