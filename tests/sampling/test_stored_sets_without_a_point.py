"""Stored strict sets asked for their reference distance when the material has no reference point (none, or an
empty mapping): the sets are read back as stored, with no distance (NaN) rather than an error."""

from __future__ import annotations

from dataclasses import replace

import numpy as np
import pytest

from demid.scenario import judged_scenarios
from demid.sampling.stored import stored_strict_sets

from .test_stored_sets_whole import _material


@pytest.mark.parametrize("point", [None, {}])
def test_a_material_without_a_reference_point_gets_its_sets_without_a_distance(point):
    spec, surrogates, frame, sets = _material(1, 1.0)
    spec = replace(spec, reference_point=point)
    stored = stored_strict_sets(frame, judged_scenarios(spec, surrogates, 2.0), reference=True)
    assert list(stored) == ["y1_only", "both"]
    for name, got in stored.items():
        assert got.fraction == sets[name].fraction
        assert np.isnan(got.exact.reference_distance)
        assert np.all(np.isnan(got.exact.nearest_point))
