"""Level 2's tolerance and miss in words (criticism.messages): with one tolerance for every observable, "by 3.10 %"
(the largest error whatever its sign; "by at most" only when asked), else the observable that misses most against
its own tolerance, its error, the multiple of its tolerance and the tolerance itself; the tolerances listed each
with its percentage, in brackets unless told otherwise.  Every number is parsed back and compared with the value
computed here, over one to four observables, errors of either sign and shared, equal or own tolerances."""

from __future__ import annotations

import re

import numpy as np
import pytest

from demid.criticism.messages import level2_miss_text, level2_tolerance_text

NAMES = ["d5", "rho", "aor", "w"]


def _close(text: str, exact_pct: float) -> bool:
    """A percentage as printed ("3.10 %", "12.5 %") is ``exact_pct`` to two decimals below 10 %, one above."""
    m = re.fullmatch(r"(\d+\.\d+) %", text)
    assert m, text
    decimals = 2 if exact_pct < 10 else 1
    assert len(m.group(1).split(".")[1]) == decimals, text
    return abs(float(m.group(1)) - exact_pct) <= 10.0 ** -decimals / 2 + 1e-9


def _draw(rng):
    k = int(rng.integers(1, 5))
    names = NAMES[:k]
    tolerance = float(rng.choice([0.02, 0.05, 0.1]))
    errors = {o: float(rng.uniform(0.0003, 0.4) * rng.choice([-1, 1])) for o in names}
    kind = rng.integers(0, 3)
    if kind == 0:
        tolerances = None
    elif kind == 1:  # each written out, all the scenario's
        tolerances = {o: tolerance for o in names}
    else:
        tolerances = {o: float(rng.choice([0.003, 0.01, tolerance, 0.15])) for o in names}
        tolerances[names[-1]] = 0.0033  # at least one of its own
    return errors, tolerance, tolerances


@pytest.mark.parametrize("seed", range(3))
def test_the_miss_quotes_the_largest_error_or_the_worst_against_its_own_tolerance(seed):
    rng = np.random.default_rng(seed)
    for _ in range(40):
        errors, tolerance, tolerances = _draw(rng)
        own = {o: (tolerances or {}).get(o, tolerance) for o in errors}
        shared = all(v == tolerance for v in own.values())
        for at_most in (None, False, True):
            text = (level2_miss_text(errors, tolerance, tolerances) if at_most is None else
                    level2_miss_text(errors, tolerance, tolerances, at_most=at_most))
            if shared:
                lead = "by at most " if at_most else "by "
                assert text.startswith(lead), text
                assert _close(text[len(lead):], 100 * max(abs(e) for e in errors.values())), text
                continue
            ratios = {o: abs(e) / own[o] for o, e in errors.items()}
            worst = max(ratios, key=ratios.get)
            m = re.fullmatch(r"(\S+) by (.+ %) \((.+) its tolerance of (.+ %)\)", text)
            assert m and m.group(1) == worst, text
            assert _close(m.group(2), 100 * abs(errors[worst])), text
            assert _close(m.group(4), 100 * own[worst]), text
            if ratios[worst] >= 0.005:
                times = re.fullmatch(r"(\S+) times", m.group(3))
                assert times and float(times.group(1)) == float(f"{ratios[worst]:.2g}"), text
            else:
                assert m.group(3) == "a negligible fraction of", text


@pytest.mark.parametrize("seed", range(2))
def test_the_tolerances_are_one_percentage_or_each_observables_own_listed_in_order(seed):
    rng = np.random.default_rng(10 + seed)
    for _ in range(30):
        errors, tolerance, tolerances = _draw(rng)
        own = tolerances or {}
        if all(v == tolerance for v in own.values()):
            for text in (level2_tolerance_text(tolerance, tolerances),
                         level2_tolerance_text(tolerance, tolerances, brackets=False)):
                assert _close(text, 100 * tolerance), text
            continue
        inner = level2_tolerance_text(tolerance, tolerances, brackets=False)
        outer = level2_tolerance_text(tolerance, tolerances)
        assert inner.startswith("their own tolerances: ")
        listed = inner[len("their own tolerances: "):]
        assert outer == f"their own tolerances ({listed})"
        items = listed.split(", ")
        assert [item.split(" ", 1)[0] for item in items] == list(own)
        for item, (o, v) in zip(items, own.items()):
            assert _close(item.split(" ", 1)[1], 100 * v), item


def test_a_worst_miss_below_half_a_percent_of_its_tolerance_is_called_negligible():
    errors, own = {"d5": 0.0004, "rho": -0.0001}, {"d5": 0.15, "rho": 0.15}  # 0.27 % and 0.07 % of their tolerance
    assert level2_miss_text(errors, 0.02, own) == "d5 by 0.04 % (a negligible fraction of its tolerance of 15.0 %)"
    errors["rho"] = -0.00076  # 0.0051 of its tolerance: quoted
    assert level2_miss_text(errors, 0.02, own) == "rho by 0.08 % (0.0051 times its tolerance of 15.0 %)"
