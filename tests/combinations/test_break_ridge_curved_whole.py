"""The break-the-ridge advice for an observable whose gradient turns along the band: its angle to the identified
direction differs from point to point, and the advice quotes the median over the band's points (every point of a
set this small, each once).  The band is the 21 nodes of a coarse grid on a + b = 1; the observables are quadratics
c2 a^2 + c1 b whose coded gradient (2 c2 a, c1) / 2 is written out here, so the median angle is computed without
demid; over coefficients of either sign, with and without a second observable."""

from __future__ import annotations

import re

import numpy as np
import pytest

from demid.combinations import break_ridge_advice, set_combinations
from demid.design import Coding
from demid.spec import MaterialSpec

CODING = Coding(("a", "b"), (0.5, 0.5), (0.5, 0.5))
TANGENT = np.array([1.0, -1.0]) / np.sqrt(2)
BAND = np.column_stack([np.linspace(0, 1, 21), 1 - np.linspace(0, 1, 21)])


class _Quadratic:
    """c2 a^2 + c1 b."""

    def __init__(self, c2: float, c1: float):
        self.c2, self.c1 = c2, c1

    def predict(self, points):
        p = np.asarray(points, dtype=float)
        return self.c2 * p[:, 0] ** 2 + self.c1 * p[:, 1]


class _Linear:
    def predict(self, points):
        return np.asarray(points, dtype=float) @ np.ones(2)


def _median_angle(c2: float, c1: float) -> float:
    g = np.column_stack([2 * c2 * BAND[:, 0], np.full(len(BAND), c1)]) * np.asarray(CODING.unit)
    share = np.abs(g @ TANGENT) / np.linalg.norm(g, axis=1)
    return float(np.degrees(np.arcsin(min(np.median(share), 1.0))))


@pytest.mark.parametrize("c2, c1, second", [(1.0, 0.3, None), (-2.0, 0.5, None), (1.5, -0.4, (0.2, 3.0)),
                                            (0.8, 0.15, (-0.1, -2.0))])
def test_the_advice_quotes_the_median_angle_over_every_point_of_a_small_band(c2, c1, second):
    res = set_combinations(CODING.to_coded(BAND), [-1, -1], [1, 1], ["a", "b"], scenario="band", set_name="strict",
                           step=[0.05, 0.05])
    assert res.identified and res.cut == "none"
    responses = {"y1": {"target": 1.0}, "o": {"target": 2.0, "label": "O"}}
    surrogates = {"y1": _Linear(), "o": _Quadratic(c2, c1)}
    angles = {"o": _median_angle(c2, c1)}
    if second is not None:
        responses["p"] = {"target": 2.0, "label": "P"}
        surrogates["p"] = _Quadratic(*second)
        angles["p"] = _median_angle(*second)
    spec = MaterialSpec.from_material("m", {
        "design": {"type": "ccd"}, "factors": {"a": {"lower": 0, "upper": 1}, "b": {"lower": 0, "upper": 1}},
        "responses": responses, "scenarios": {"band": {"observables": ["y1"], "tolerance": 0.02, "label": "Band"}}})
    best = max(angles, key=angles.get)
    text = break_ridge_advice(res, BAND, surrogates, spec, CODING, ["y1"])
    assert text.startswith(f"*Band* identifies a combination and leaves its complement free: {best.upper()} changes "
                           "most along the set"), text
    said = float(re.search(r"its gradient lies (\d+)° off the identified direction", text).group(1))
    assert abs(said - angles[best]) <= 0.5 + 1e-6, (said, angles)
    for name, value in re.findall(r"; ([OP]) (\d+)°", text):
        assert abs(float(value) - angles[name.lower()]) <= 0.5 + 1e-6
