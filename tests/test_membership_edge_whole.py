"""The membership test's documented side at its very edge: a point whose implausibility is exactly
``1 + MEMBERSHIP_SLACK`` lies in the set (strict and plausible), and the next float above it does not.  The
surrogate is a constant whose miss and band are exactly representable, so the ratio is that float exactly."""

from __future__ import annotations

import numpy as np

from demid.design import quadratic_terms
from demid.scenario import MEMBERSHIP_SLACK, judged_scenarios
from demid.spec import MaterialSpec
from demid.surrogate import Surrogate

TARGET = 2.0
TOLERANCE = 0.5  # the band a = 0.5 * |2.0| = 1.0 exactly


def _judged(miss: float, z: float):
    terms = quadratic_terms(2)
    coef = np.zeros(len(terms))
    coef[0] = TARGET - miss  # in [1, 2): exact, and TARGET - it == miss exactly (Sterbenz)
    cov = np.zeros((len(terms), len(terms)))
    surrogate = Surrogate("y", ["a", "b"], terms, coef, cov, 0.0, 5, ())
    spec = MaterialSpec.from_material("m", {
        "data": "x.csv", "design": {"type": "custom"},
        "factors": {"a": {"lower": 0.0, "upper": 1.0}, "b": {"lower": 0.0, "upper": 1.0}},
        "responses": {"y": {"target": TARGET}},
        "scenarios": {"s": {"observables": ["y"], "tolerance": TOLERANCE}}})
    return judged_scenarios(spec, {"y": surrogate}, z)["s"]


def test_a_point_exactly_on_the_edge_plus_the_slack_is_in_the_set():
    edge = 1.0 + MEMBERSHIP_SLACK
    above = np.nextafter(edge, 2.0)
    points = np.array([[0.0, 0.0], [0.5, 0.5], [1.0, 1.0]])
    for miss, inside in ((edge, True), (above, False), (1.0, True)):
        assert TARGET - (TARGET - miss) == miss
        judged = _judged(miss, 0.0)
        ratio = judged.implausibility(points, plausible=False)
        assert np.all(ratio == miss / 1.0), (ratio, miss)
        assert judged.contains(points, plausible=False).tolist() == [inside] * 3
        # z = 0: the plausible set is the strict set
        assert judged.contains(points).tolist() == [inside] * 3
