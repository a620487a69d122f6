"""The break-the-ridge advice against the angles written out here: on the straight band a + b = 1 (coded normal
(1, 1)/√2), a linear observable with coded gradient g lies arcsin(|g·t| / |g|) off the identified direction, t the
band's direction.  Generated over 1-4 other observables with weights of either sign and size, some without a
target, one constant (no gradient: never named, never scored), rankings that hold the gain or not: the one named is
the largest angle, every other is listed with its angle in config order, the ridge is broken from 30° on, and the
gain is the ranking's number."""

from __future__ import annotations

import functools
import re

import numpy as np
import pandas as pd
import pytest
from hypothesis import Phase, given, settings, strategies as st

from demid.combinations import break_ridge_advice, set_combinations
from demid.combinations.material import SHALLOW_ANGLE
from demid.design import Coding
from demid.spec import MaterialSpec

CODING = Coding(("a", "b"), (0.5, 0.5), (0.5, 0.5))
TANGENT = np.array([1.0, -1.0]) / np.sqrt(2)


class _Linear:
    def __init__(self, weights):
        self.weights = np.asarray(weights, dtype=float)

    def predict(self, points):
        return np.asarray(points, dtype=float) @ self.weights


@functools.cache
def _band():
    """The grid nodes of the band and their combinations (computed on first use: a failure is a test's)."""
    axis = np.linspace(0, 1, 201)
    pts = np.stack(np.meshgrid(axis, axis, indexing="ij"), axis=-1).reshape(-1, 2)
    band = pts[np.abs(pts.sum(axis=1) - 1) <= 0.02]
    res = set_combinations(CODING.to_coded(band), [-1, -1], [1, 1], ["a", "b"], scenario="band", set_name="strict",
                           step=[0.01, 0.01])
    assert res.identified and res.cut == "none"
    return band, res



def _angle(weights):
    g = np.asarray(weights, dtype=float) * np.asarray(CODING.unit)
    return float(np.degrees(np.arcsin(min(abs(g @ TANGENT) / np.linalg.norm(g), 1.0))))


@settings(max_examples=15, deadline=None, derandomize=True, phases=(Phase.explicit, Phase.generate))
@given(seed=st.integers(0, 100_000), count=st.integers(1, 4), constant=st.booleans(), with_ranking=st.booleans())
def test_the_advice_names_the_steepest_observable_and_quotes_every_angle(seed, count, constant, with_ranking):
    rng = np.random.default_rng(seed)
    names = [f"o{j}" for j in range(count)]
    weights = {o: rng.choice([-1, 1], 2) * 10.0 ** rng.uniform(-2, 2, 2) for o in names}
    targets = {o: rng.uniform() < 0.75 for o in names}
    responses = {"y1": {"target": 1.0}, **{o: ({"target": 2.0} if targets[o] else {}) | {"label": o.upper()}
                                           for o in names}}
    if constant:
        responses["flat"] = {"target": 3.0}
    spec = MaterialSpec.from_material("m", {
        "design": {"type": "ccd"}, "factors": {"a": {"lower": 0, "upper": 1}, "b": {"lower": 0, "upper": 1}},
        "responses": responses, "scenarios": {"band": {"observables": ["y1"], "tolerance": 0.02, "label": "Band"}}})
    surrogates = {"y1": _Linear([1, 1]), **{o: _Linear(w) for o, w in weights.items()}}
    if constant:
        surrogates["flat"] = _Linear([0.0, 0.0])
    angles = {o: _angle(w) for o, w in weights.items()}
    best = max(angles, key=angles.get)
    if sorted(angles.values())[-2:][0] > angles[best] - 1.0 if count > 1 else False:
        return  # two observables within a degree of each other: which is named is a matter of round-off
    gain = float(rng.uniform(0, 5))
    ranking = pd.DataFrame({"observables": [f"{best}+y1", "y1"], "information_gain_bits": [gain, 1.0]}) \
        if with_ranking else None
    band, result = _band()
    text = break_ridge_advice(result, band, surrogates, spec, CODING, ["y1"], ranking)

    assert text.startswith(f"*Band* identifies a combination and leaves its complement free: {best.upper()} changes "
                           "most along the set"), text
    said = float(re.search(r"its gradient lies (\d+)° off the identified direction", text).group(1))
    assert said == pytest.approx(angles[best], abs=1.0)
    listed = re.findall(r"(O\d) (\d+)°", text)
    assert [o for o, _ in listed] == [o.upper() for o in names if o != best]
    for o, value in listed:
        assert float(value) == pytest.approx(angles[o.lower()], abs=1.0)
    assert "FLAT" not in text and "flat" not in text and "nan" not in text
    measure = "adding its measurement" if targets[best] else "measuring it (it has no target yet)"
    assert f"), so {measure} " in text
    if abs(angles[best] - SHALLOW_ANGLE) > 1.0:
        assert (f"), so {measure} would break the ridge" in text) == (angles[best] >= SHALLOW_ANGLE)
        assert ("cuts the band at a shallow angle" in text) == (angles[best] < SHALLOW_ANGLE)
    if with_ranking and targets[best]:
        assert text.endswith(f"; with it the ranking gives {gain:.2f} bits.")
    else:
        assert "ranking gives" not in text and text.endswith(".")


def test_a_constant_observable_alone_gives_no_advice():
    spec = MaterialSpec.from_material("m", {
        "design": {"type": "ccd"}, "factors": {"a": {"lower": 0, "upper": 1}, "b": {"lower": 0, "upper": 1}},
        "responses": {"y1": {"target": 1.0}, "flat": {"target": 3.0}},
        "scenarios": {"band": {"observables": ["y1"], "tolerance": 0.02}}})
    band, result = _band()
    assert break_ridge_advice(result, band, {"y1": _Linear([1, 1]), "flat": _Linear([0, 0])}, spec, CODING,
                              ["y1"]) == ""
