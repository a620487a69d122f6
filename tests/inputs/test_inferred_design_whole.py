"""What an inferred design says of itself, against the rule written out here, over generated families, factor
counts, axial distances (equal for every factor to a thousandth, face-centred, or one per factor) and centre-run
counts (the plural from two on, and for none): each number of the description read back, and the design the table
is then checked against (a two-level factorial as custom)."""

from __future__ import annotations

import re

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from demid.design_inference import InferredDesign


def _centres(text: str) -> int:
    said = re.search(r"(\d+) centre run(s?)\b", text)
    assert said, text
    assert (said.group(2) == "s") is (int(said.group(1)) != 1), text
    return int(said.group(1))


@given(k=st.integers(1, 4), centres=st.integers(0, 6), kind=st.sampled_from(["face", "equal", "near", "apart"]),
       alpha=st.floats(1.05, 2.5))
@settings(max_examples=60, deadline=None, derandomize=True)
def test_a_ccd_describes_its_factors_axial_distance_and_centre_runs(k, centres, kind, alpha):
    factors = tuple(f"x{i + 1}" for i in range(k))
    alphas = {"face": (1.0,) * k, "equal": (alpha,) * k,
              "near": tuple(alpha * (1 + 0.0009 * i / max(k - 1, 1)) for i in range(k)),
              "apart": tuple(alpha + 0.01 + 0.05 * i for i in range(k))}[kind]
    design = InferredDesign("ccd", factors, alphas, centres)
    text = design.describe()
    assert text.startswith(f"a {k}-factor central composite design (CCD), ")
    assert _centres(text) == centres
    if kind == "face":
        assert "face-centred, alpha = 1," in text
    elif kind in ("equal", "near") or k == 1:
        said = float(re.search(r"axial distance alpha = ([\d.e+-]+),", text).group(1))
        assert said == pytest.approx(np.mean(alphas), rel=1e-5)
    else:
        pairs = re.findall(r"([\d.]+) for (x\d)", text)
        assert [f for _, f in pairs] == list(factors)
        assert [float(a) for a, _ in pairs] == pytest.approx(list(alphas), rel=1e-3)
    assert design.design == {"type": "ccd", "alpha": alphas, "center_runs": centres, "inferred": True}


@pytest.mark.parametrize("family, start, checked", [
    ("box_behnken", "a 3-factor Box-Behnken design with ", "box_behnken"),
    ("two_level", "a 3-factor two-level factorial with ", "custom"),
    ("factorial", "a 3^3 full factorial, ", "factorial")])
@pytest.mark.parametrize("centres", [0, 1, 2, 5])
def test_the_other_families_describe_themselves_and_their_centre_runs(family, start, checked, centres):
    design = InferredDesign(family, ("a", "b", "c"), (1.0,) * 3, centres)
    text = design.describe()
    assert text.startswith(start) and _centres(text) == centres
    assert design.design["type"] == checked and design.design["center_runs"] == centres


def test_a_custom_design_says_each_factor_is_coded_from_its_range():
    design = InferredDesign("custom", ("a", "b"), (1.0, 1.0), 0)
    assert design.describe() == "no standard design (custom: each factor coded from its range)"
    assert design.design["type"] == "custom"
