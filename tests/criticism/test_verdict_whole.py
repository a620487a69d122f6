"""An adequate verdict's power caveat (criticism.verdict.power_caveat) read whole over generated studies: runs,
spare degrees of freedom, tests in the family, family level, a specific test's share and residual scatter from
1e-4 to 1e6, the size in response units on either side of ten thousand and at it exactly.  The detectable size
against the noncentral t (two-sided, Bonferroni over the family) solved here, and every number of the message
parsed back."""

from __future__ import annotations

import re

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy import optimize, stats

from demid.criticism.verdict import plain_number, power_caveat


def _detectable(df_resid: int, n_tests: float, alpha: float) -> float:
    d = df_resid - 1
    crit = stats.t.ppf(1 - alpha / n_tests / 2, d)
    return optimize.brentq(lambda k: stats.nct.sf(crit, d, k) + stats.nct.sf(crit, d, -k) - 0.8, 1e-3, 60)


def _size_text(size: float) -> str:
    """No exponent from ten thousand on (thousands separated), three significant digits below."""
    return f"{size:,.0f}" if abs(size) >= 1e4 else f"{size:.3g}"


@given(n_runs=st.integers(9, 60), spare=st.integers(3, 30), n_tests=st.integers(1, 12),
       alpha=st.sampled_from([0.01, 0.05, 0.1]), share=st.sampled_from([1.0, 0.5, 0.25]),
       scale=st.floats(-4, 6))
@settings(max_examples=25, deadline=None, derandomize=True)
def test_the_power_caveats_numbers_and_sentence(n_runs, spare, n_tests, alpha, share, scale):
    resid_std = 10.0 ** scale
    out = power_caveat("y", n_runs, spare, n_tests, alpha, resid_std, specific_share=share)
    k = _detectable(spare, n_tests / share, alpha)
    assert out["detectable_sd"] == pytest.approx(k, rel=1e-6)
    assert out["detectable"] == pytest.approx(k * resid_std, rel=1e-6) and out["power"] == 0.8
    said = re.fullmatch(r"y: adequate — none of the (\d+) tests fired at the family-wise (\S+) % level\. With (\d+) "
                        r"runs the tests find a departure of about (\S+) residual standard deviations \((\S+) in "
                        r"response units: one shifted run, or an omitted term of that size\) with (\d+) % "
                        r"probability; smaller defects may be present\.", out["message"])
    assert said is not None, out["message"]
    assert (int(said.group(1)), float(said.group(2)), int(said.group(3))) == (n_tests, 100 * alpha, n_runs)
    assert said.group(4) == f"{k:.1f}" and int(said.group(6)) == 80
    assert said.group(5) == _size_text(out["detectable_sd"] * resid_std)


@pytest.mark.parametrize("target", [9999.4, 10000.0, 10000.6, 123456.7])
def test_a_size_at_ten_thousand_and_either_side_is_written_without_an_exponent_from_it_on(target):
    k = power_caveat("y", 14, 8, 5, 0.05, 1.0)["detectable_sd"]  # the size per residual sd (tested above)
    resid_std = target / k
    for _ in range(8):  # the scatter whose size in response units is the target to the last bit
        size = k * resid_std
        resid_std = np.nextafter(resid_std, np.inf if size < target else -np.inf) if size != target else resid_std
    assert k * resid_std == target
    out = power_caveat("y", 14, 8, 5, 0.05, resid_std)
    size = out["detectable_sd"] * resid_std
    assert f"({_size_text(size)} in response units" in out["message"]
    assert ("(10,000 in response units" in out["message"]) == (size >= 1e4 and round(size) == 10000)
    assert plain_number(target) == _size_text(target) if target >= 1e4 else plain_number(target) == f"{target:.4g}"
