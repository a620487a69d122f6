"""Level 2's sentence on the reference point (criticism.level2.calibration_check's message) over generated linear
responses: 1-3 observables, targets of either sign, a reference point anywhere in the domain, met or missed.  The
errors the sentence quotes are parsed back and compared with (value - target) / |target| written out here, and
"meets" / "misses" with every |error| against the tolerance, also for a reference point exactly on the band's
edge (met: the band is closed)."""

from __future__ import annotations

import re

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from demid.criticism.level2 import calibration_check
from demid.design import quadratic_terms
from demid.sampling import Domain
from demid.surrogate import Surrogate


def _linear(name: str, offset: float, slope_a: float, slope_b: float) -> Surrogate:
    coef = np.array([offset, slope_a, slope_b, 0.0, 0.0, 0.0])  # Intercept, a, b, a:b, a^2, b^2
    return Surrogate(name, ["a", "b"], quadratic_terms(2), coef, np.zeros((6, 6)), 0.0, 7)


def _sentence(message: str) -> tuple[dict[str, float], str, str]:
    found = re.search(r"At the reference point the errors are (.*?): it (meets|misses) the ([\d.]+) % tolerance\.",
                      message)
    assert found, message
    errors = {}
    for item in found.group(1).split(", "):
        observable, value, unit = item.split(" ")
        assert unit == "%"
        errors[observable] = float(value.replace("\u2212", "-")) / 100
    return errors, found.group(2), found.group(3)


@given(seed=st.integers(0, 10 ** 5), k=st.integers(1, 3), tolerance=st.sampled_from([0.05, 0.1, 0.2]))
@settings(max_examples=8, deadline=None, derandomize=True)
def test_the_reference_sentence_quotes_each_error_and_whether_it_is_met(seed, k, tolerance):
    rng = np.random.default_rng(seed)
    names = [f"y{i + 1}" for i in range(k)]
    offsets, slopes = rng.uniform(-5, 5, k), rng.uniform(-2, 2, (k, 2))
    surrogates = {o: _linear(o, offsets[i], *slopes[i]) for i, o in enumerate(names)}
    domain = Domain(("a", "b"), (-1.0, 0.0), (1.0, 2.0), (False, False))
    reference = {"a": float(rng.uniform(-1, 1)), "b": float(rng.uniform(0, 2))}
    values = {o: offsets[i] + slopes[i] @ [reference["a"], reference["b"]] for i, o in enumerate(names)}
    # targets of either sign near the reference values: some met, some missed
    targets = {o: float(values[o] * (1 + rng.choice([-1, 1]) * rng.uniform(0, 2.5 * tolerance))
                        + rng.choice([0.0, 0.1])) for o in names}
    targets = {o: t if abs(t) > 0.05 else 0.5 for o, t in targets.items()}
    result = calibration_check(surrogates, domain, targets, tolerance, 9, reference_point=reference)
    expected = {o: (values[o] - targets[o]) / abs(targets[o]) for o in names}
    quoted, verdict, band = _sentence(result.message)
    assert list(quoted) == names
    for o in names:
        assert quoted[o] == pytest.approx(expected[o], abs=0.00005 + 1e-12)
    met = all(abs(e) <= tolerance + 1e-12 for e in expected.values())
    assert verdict == ("meets" if met else "misses")
    assert float(band) == pytest.approx(100 * tolerance, abs=1e-12)
    assert result.to_json()["reference_within"] is met


@pytest.mark.parametrize("sign", [1.0, -1.0])
@pytest.mark.parametrize("edge, verdict", [(0.1, "meets"), (0.1001, "misses")])
def test_a_reference_point_on_the_edge_of_the_band_meets_it(sign, edge, verdict):
    """y1 = a with target sign * 1, y2 = b with target 1, the reference point a = sign * (1 + edge), b = 1: y1's
    error is exactly the tolerance (to round-off) at edge 0.1, just beyond it at 0.1001."""
    surrogates = {"y1": _linear("y1", 0.0, 1.0, 0.0), "y2": _linear("y2", 0.0, 0.0, 1.0)}
    domain = Domain(("a", "b"), (-2.0, 0.0), (2.0, 2.0), (False, False))
    reference = {"a": sign * (1.0 + edge), "b": 1.0}
    result = calibration_check(surrogates, domain, {"y1": sign * 1.0, "y2": 1.0}, 0.1, 9, reference_point=reference)
    quoted, said, _ = _sentence(result.message)
    assert quoted == pytest.approx({"y1": sign * edge, "y2": 0.0}, abs=1e-9)
    assert said == verdict
