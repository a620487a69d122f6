"""Targets far from every simulated value, against the rule written out here, over generated response ranges of
either sign and targets inside, on and just past one range beyond the runs, a power of ten away (a unit slip) or
a factor of three or more outside: which targets are named, their range, the power of ten and the value it gives,
whether they are far; and every number the warning quotes, read back.  Plus the bounds' slack on and past its edge."""

from __future__ import annotations

import re

import numpy as np
import pandas as pd
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from demid.data import check_bounds, far_target_warnings, implausible_targets
from demid.errors import InputError
from demid.spec import Factor


def _written_out(target, lo, hi):
    if lo == hi or lo <= target <= hi:
        return None
    repair = None
    for power in sorted((p for p in range(-6, 7) if p), key=abs):
        if lo <= target * 10.0 ** power <= hi:
            repair = (10.0 ** power, target * 10.0 ** power)
            break
    far = not (lo - (hi - lo) <= target <= hi + (hi - lo))
    if lo > 0 and target > 0:
        ratio = target * 3 <= lo or target >= hi * 3
    elif hi < 0 and target < 0:
        ratio = -target * 3 <= -hi or -target >= -lo * 3
    else:
        ratio = False
    if not far and not (repair and ratio):
        return None
    return {"lo": lo, "hi": hi, "far": far, "factor": repair[0] if repair else None,
            "repaired": repair[1] if repair else None}


def _targets(lo, hi):
    r = hi - lo
    return [lo - r, hi + r, np.nextafter(lo - r, -np.inf), np.nextafter(hi + r, np.inf), (lo + hi) / 2, lo, hi,
            lo * 10, hi / 10, lo / 100, hi * 1000, -hi, 0.5 * lo, lo / 3, hi * 3, hi * 2.9, -lo * 7]


@given(lo=st.floats(-500, 500).filter(lambda v: abs(v) > 1e-3), width=st.floats(0.01, 3.0),
       sign=st.sampled_from([-1.0, 1.0]))
@settings(max_examples=20, deadline=None, derandomize=True)
def test_implausible_targets_and_their_warnings_follow_the_rule(lo, width, sign):
    lo = abs(lo) * sign
    hi = lo + abs(lo) * width
    y = np.array([lo, (lo + hi) / 2, hi, np.nan])
    for target in _targets(lo, hi):
        table = pd.DataFrame({"y": y, "z": [1.0, 1.0, 1.0, 1.0]})
        got = implausible_targets(table, {"y": target, "z": 5.0, "missing": 1.0})
        want = _written_out(target, lo, hi)
        assert "z" not in got and "missing" not in got  # a constant column, a response the table lacks
        if want is None:
            assert got == {}, target
            assert far_target_warnings(table, {"y": target}, "t.csv") == []
            continue
        assert got["y"]["far"] is want["far"] and got["y"]["factor"] == want["factor"], target
        assert (got["y"]["lo"], got["y"]["hi"]) == (lo, hi)
        if want["factor"] is not None:
            assert got["y"]["repaired"] == pytest.approx(want["repaired"], rel=1e-12)
        (text,) = far_target_warnings(table, {"y": target}, "t.csv", "m")
        said = re.search(r"the target (\S+) lies far outside every simulated value \((\S+) to (\S+)\) \(config key "
                         r"materials\.m\.responses\.y\.target\)", text)
        assert said, text
        shown = [float(v.replace("−", "-")) for v in said.groups()]
        assert shown == pytest.approx([float(f"{target:.6g}"), float(f"{lo:.4g}"), float(f"{hi:.4g}")], rel=1e-12)
        if want["factor"] is not None:
            times = re.search(r"repair: ([×÷])(\S+) → (\S+) lies inside the simulated range", text)
            assert times, text
            factor = float(times.group(2)) if times.group(1) == "×" else 1 / float(times.group(2))
            assert factor == pytest.approx(want["factor"]) and float(times.group(3)) == pytest.approx(
                float(f"{want['repaired']:.6g}"))
        else:
            assert "repair:" not in text


@pytest.mark.parametrize("offset, refused", [(0.0, False), (0.9e-6, False), (1.1e-6, True), (-0.9e-6, False),
                                             (-1.1e-6, True)])
def test_a_factor_value_beyond_its_bound_is_refused_past_a_millionth_of_the_range(offset, refused):
    factor = Factor("a", 2.0, 6.0, False, "a", "")
    value = 6.0 + offset * 4.0 if offset >= 0 else 2.0 + offset * 4.0
    table = pd.DataFrame({"run": [1, 2, 3], "a": [2.0, value, 4.0]})
    if not refused:
        check_bounds(table, (factor,), "t.csv")
        return
    with pytest.raises(InputError) as err:
        check_bounds(table, (factor,), "t.csv")
    assert err.value.run == 2 and err.value.column == "a"
    assert f"value {value:g} lies outside the declared bounds [2, 6] (config factors.a)" in str(err.value)


@pytest.mark.parametrize("rows", [(0, 3), (1, 2), (2, 4), (0, 4)])
def test_of_several_values_beyond_a_bound_the_first_row_of_the_table_is_named(rows):
    factor = Factor("a", 2.0, 6.0, False, "a", "")
    values = [3.0, 4.0, 5.0, 2.5, 5.5]
    wrong = iter([1.5, 7.25])
    for i in rows:
        values[i] = next(wrong)
    table = pd.DataFrame({"run": [14, 3, 9, 21, 5], "a": values})
    with pytest.raises(InputError) as err:
        check_bounds(table, (factor,), "t.csv")
    first = min(rows)
    assert err.value.run == table["run"][first] and err.value.column == "a"
    assert f"value {values[first]:g} lies outside the declared bounds [2, 6] (config factors.a)" in str(err.value)


@pytest.mark.parametrize("target, lo, hi", [(1.23, 10.0, 200.0), (4.56, 0.01, 0.5), (-4.56, -0.5, -0.01),
                                            (789.0, 5.0, 100.0), (0.0789, 0.5, 10.0), (-789.0, -100.0, -5.0)])
def test_a_far_target_two_point_shifts_bring_inside_looks_like_the_value_its_repair_names(target, lo, hi):
    """Two shifts of the decimal point land among the simulated values: the warning names one value, the one a
    power of ten brings inside with the fewest places (a tenth before ten times at one place)."""
    powers = sorted((p for p in range(-6, 7) if p), key=abs)
    inside = [target * 10.0 ** p for p in powers if lo <= target * 10.0 ** p <= hi]
    assert len(inside) == 2
    table = pd.DataFrame({"y": [lo, (lo + hi) / 2, hi]})
    (text,) = far_target_warnings(table, {"y": target}, "t.csv")
    said = re.search(r"and looks like (\S+) with the decimal point shifted; repair: [×÷]\S+ → (\S+) lies inside",
                     text)
    assert said, text
    assert float(said.group(1)) == pytest.approx(inside[0], rel=1e-9)
    assert float(said.group(2)) == pytest.approx(inside[0], rel=1e-9)
