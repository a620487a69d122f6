"""The combination a straight band identifies, as the JSON and the sentence give it, against the band written out:
y = t + s . (x - p) within ε |t| over a box of two factors (slopes and targets of either sign, a coding whose
centre is not the box's and whose unit is not 1).  Its equation in search units is s / |s| (the largest
coefficient positive) . x = c ± w with c the same combination of p and w = ε |t| / |s|, the band's half-width."""

from __future__ import annotations

import re

import numpy as np
import pytest

from demid.combinations.material import material_combinations
from demid.design import Coding
from demid.sampling.grid import admissible_set
from demid.spec import MaterialSpec

from .test_combination_material_whole import _linear


@pytest.mark.parametrize("seed, sign, target_sign", [(1, 1.0, 1.0), (2, -1.0, 1.0), (3, 1.0, -1.0), (4, -1.0, -1.0)])
def test_a_straight_bands_equation_is_its_normal_centre_line_and_half_width(seed, sign, target_sign):
    rng = np.random.default_rng(seed)
    lo = rng.uniform(-5.0, 5.0, 2)
    hi = lo + rng.uniform(1.0, 20.0, 2)
    tolerance, n, target = 0.02, 101, target_sign * 3.0
    spec = MaterialSpec.from_material("m", {
        "data": "x.csv", "design": {"type": "custom"},
        "factors": {"a": {"lower": float(lo[0]), "upper": float(hi[0])},
                    "b": {"lower": float(lo[1]), "upper": float(hi[1])}},
        "responses": {"y": {"target": target}},
        "scenarios": {"band": {"observables": ["y"], "tolerance": tolerance}}}, grid_points=n)
    point = lo + (hi - lo) * rng.uniform(0.4, 0.6, 2)
    slopes = np.array([1.0 / (hi[0] - lo[0]), sign * rng.uniform(0.5, 2.0) / (hi[1] - lo[1])]) * 3.0
    surrogate = _linear("y", slopes, target - slopes @ point)
    strict = {"band": admissible_set({"y": surrogate}, spec.domain, ["y"], {"y": target}, tolerance, n)}
    coding = Coding(("a", "b"), tuple((lo + hi) / 2 + rng.uniform(-1.0, 1.0, 2)), tuple((hi - lo) / 2.8))
    found = material_combinations({"y": surrogate}, spec, coding, strict, {})
    (entry,) = found.to_json()["sets"]

    normal = slopes / np.linalg.norm(slopes)
    normal = normal if normal[np.argmax(np.abs(normal))] > 0 else -normal
    np.testing.assert_allclose(entry["coefficients_search_units"], normal, atol=2e-3)
    scale = np.linalg.norm(slopes)
    half_width = tolerance * abs(target) / scale
    assert entry["constant"] == pytest.approx(normal @ point, abs=0.02 * half_width + 1e-9)
    assert entry["half_width"] == pytest.approx(half_width, rel=0.03)
    # the sentence: the same equation divided by the coefficient of the factor that loads most in coded units
    lead = int(np.argmax(np.abs(slopes * np.asarray(coding.unit))))
    other = 1 - lead
    text = re.fullmatch(r"(\w) ([+−]) ([\d.]+)·(\w) = (−?[\d.]+) ± ([\d.]+)", entry["statement"])
    assert text is not None, entry["statement"]
    assert (text.group(1), text.group(4)) == ("ab"[lead], "ab"[other])
    ratio = normal[other] / normal[lead]
    assert (text.group(2) == "−") == (ratio < 0)
    _close(float(text.group(3)), abs(ratio), text.group(3), rel=5e-3)
    _close(float(text.group(5).replace("−", "-")), normal @ point / normal[lead], text.group(5), rel=0.0,
           absolute=0.02 * half_width / abs(normal[lead]))
    _close(float(text.group(6)), half_width / abs(normal[lead]), text.group(6), rel=0.03)


def _close(shown: float, value: float, printed: str, rel: float, absolute: float = 0.0):
    """A printed number is the value to its last printed digit (and the estimate's own tolerance)."""
    digits = len(printed.split(".")[1]) if "." in printed else 0
    assert abs(shown - value) <= 0.5 * 10 ** -digits + rel * abs(value) + absolute + 1e-12, (shown, value)
