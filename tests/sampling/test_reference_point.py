"""Where a chosen parameter set lies relative to the admissible set: inside, or how far outside."""

import numpy as np
import pytest

from demid.criticism import reference_point_position
from demid.design import quadratic_terms
from demid.spec import MaterialSpec
from demid.surrogate import Surrogate


def _disk_material(reference):
    # y = a^2 + b^2 on [-1, 1]^2, target 0.25 at 20 %: annulus 0.2 <= r^2 <= 0.3
    coef = np.array([0, 0, 0, 0, 1.0, 1.0])
    sur = Surrogate("y", ["a", "b"], quadratic_terms(2), coef, np.zeros((6, 6)), 0.0, 7)
    cfg = MaterialSpec.from_material("m", {
        "design": {"type": "ccd"}, "factors": {"a": {"lower": -1, "upper": 1}, "b": {"lower": -1, "upper": 1}},
        "responses": {"y": {"target": 0.25}}, "reference_point": reference,
        "scenarios": {"ring": {"observables": ["y"], "tolerance": 0.2}}})
    return {"y": sur}, cfg


def test_point_inside():
    sur, cfg = _disk_material({"a": 0.5, "b": 0.0})
    (row,) = reference_point_position(sur, cfg, 201)
    assert row["inside"] and row["distance_pct_of_range"] == 0.0


def test_point_outside_distance_to_ring():
    sur, cfg = _disk_material({"a": 0.0, "b": 0.0})
    (row,) = reference_point_position(sur, cfg, 401)
    assert not row["inside"]
    # nearest admissible radius sqrt(0.2) = 0.447; ranges are 2 wide -> 22.4 % of the range
    assert row["distance_pct_of_range"] == pytest.approx(100 * np.sqrt(0.2) / 2, abs=0.3)
