"""Every search range has a width in search units, so the extrapolation warnings divide by it unguarded: config
refuses a log-scale factor whose two bounds have the same log10 to the last bit (the one range a ``lower < upper``
check lets through with no width), with one line naming the key and both bounds; ends one step of log10 apart are
accepted.  Over generated ranges (linear and log, far from zero) the warnings name exactly the sides a run-free
margin wider than 0.1 % of the range leaves, computed here in search units."""

from __future__ import annotations

import re

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from demid.config import load_config
from demid.criticism.edges import extrapolation_warnings
from demid.errors import InputError
from demid.sampling.domain import Domain

_CONFIG = ("materials:\n"
           "  m:\n"
           "    data: m.csv\n"
           "    design: {{type: ccd, alpha: 1.41421, center_runs: 5}}\n"
           "    factors:\n"
           "      a: {{lower: 0.1, upper: 0.9}}\n"
           "      b: {{lower: {lower!r}, upper: {upper!r}, scale: log}}\n"
           "    responses:\n"
           "      y1: {{target: 115}}\n"
           "    scenarios:\n"
           "      y1_only: {{observables: [y1], tolerance: 0.02}}\n")


def _config(tmp_path, lower, upper):
    (tmp_path / "m.csv").write_text("run,a,b,y1\n1,0.5,1000,115\n", encoding="utf-8")
    path = tmp_path / "study.yaml"
    path.write_text(_CONFIG.format(lower=lower, upper=upper), encoding="utf-8")
    return path


def _upper_with_the_same_log10(lower):
    upper = np.nextafter(lower, np.inf)
    assert upper > lower and np.log10(upper) == np.log10(lower)
    return float(upper)


def test_a_log_range_with_no_width_in_log10_is_refused_naming_the_key_and_bounds(tmp_path):
    upper = _upper_with_the_same_log10(1000.0)
    with pytest.raises(InputError) as err:
        load_config(_config(tmp_path, 1000.0, upper), tmp_path)
    text = str(err.value)
    assert "\n" not in text
    assert re.search(r"materials\.m\.factors\.b: lower \(1000\.0\) and upper \(1000\.0000000000001\) have the same "
                     r"log10", text), text


def test_a_log_range_one_log10_step_wide_is_accepted(tmp_path):
    lower = 1000.0
    upper = _upper_with_the_same_log10(lower)
    while np.log10(upper) == np.log10(lower):
        upper = float(np.nextafter(upper, np.inf))
    config = load_config(_config(tmp_path, lower, upper), tmp_path)
    assert config["materials"]["m"]["factors"]["b"]["upper"] == upper


@settings(max_examples=25, deadline=None, derandomize=True)
@given(log=st.booleans(), origin=st.sampled_from([0.0, 3.7, -250.0, 1e4]), width=st.sampled_from([1e-3, 2.0, 400.0]),
       margins=st.tuples(st.sampled_from([0.0, 0.0005, 0.002, 0.3]), st.sampled_from([0.0, 0.0005, 0.002, 0.3])))
def test_warned_sides_are_the_run_free_margins_wider_than_a_thousandth(log, origin, width, margins):
    if log:
        origin, width = abs(origin) % 3 - 1.0, min(width, 2.0)  # log10 of the bounds
    lo_s, hi_s = origin, origin + width
    to_actual = (lambda s: 10.0 ** s) if log else (lambda s: s)
    domain = Domain(("x", "w"), (to_actual(lo_s), 0.0), (to_actual(hi_s), 1.0), (log, False))
    lo_s, hi_s = domain.search_bounds()[0][0], domain.search_bounds()[1][0]
    run_s = np.array([lo_s + margins[0] * width, 0.5 * (lo_s + hi_s), hi_s - margins[1] * width])
    runs = np.column_stack([to_actual(run_s), [0.0, 0.5, 1.0]])
    z = (domain.to_search(runs)[:, 0] - lo_s) / (hi_s - lo_s)
    sides = [s for s, beyond in (("lower", z.min() > 1e-3), ("upper", z.max() < 1 - 1e-3)) if beyond]
    warnings = extrapolation_warnings(domain, runs, None)
    if not sides:
        assert warnings == []
        return
    assert len(warnings) == 1
    assert warnings[0].startswith("Extrapolation: the search range of x,")
    assert warnings[0].endswith(f"simulate runs out to the {' and '.join(sides)} bound.")
