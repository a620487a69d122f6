"""The run-order record written to the level 1 JSON: no reason is null, not an empty string; a reason is its word."""

from __future__ import annotations

import json

import numpy as np

from demid.criticism.run_order import RunOrder, assess_run_order


def test_drift_tested_writes_a_null_reason():
    rng = np.random.default_rng(3)
    coded = np.array([[-1, -1], [1, -1], [-1, 1], [1, 1], [-1.41, 0], [1.41, 0], [0, -1.41], [0, 1.41],
                      [0, 0], [0, 0], [0, 0]], dtype=float)
    runs = np.array([7, 2, 10, 4, 1, 9, 5, 11, 3, 8, 6], dtype=float)
    y = rng.normal(size=len(runs))
    order = assess_run_order(runs, coded, {"y": y})
    assert order.drift_tested and order.reason == ""
    record = order.to_json()
    assert record["reason"] is None
    assert json.loads(json.dumps(record))["reason"] is None
    assert record["message"] == "" and record["drift_tested"] is True


def test_a_reason_is_written_as_its_word():
    assert RunOrder("unknown", False, "declared_unknown").to_json()["reason"] == "declared_unknown"
    assert RunOrder("performed", True, "").to_json()["reason"] is None
