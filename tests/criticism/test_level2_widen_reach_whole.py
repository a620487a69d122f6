"""Which bounds level 2 advises widening when no point meets the targets and the best point sits on bounds
(criticism.level2): only those along which the worst-missed observable that some factor moves changes, and only
where the surrogate reaches its target band beyond the bound; planes whose reach is worked out here."""

from __future__ import annotations

import numpy as np
import pytest

from demid.criticism.level2 import calibration_check
from demid.sampling.domain import Domain
from demid.surrogate import Surrogate

TERMS = [(0, 0), (1, 0), (0, 1)]
DOMAIN = Domain(("a", "b"), (0.0, 0.0), (1.0, 1.0))


def _plane(name, c0, ca, cb) -> Surrogate:
    return Surrogate(name, ["a", "b"], TERMS, np.array([c0, ca, cb]), np.zeros((3, 3)), 0.0, 5)


@pytest.mark.parametrize("cb", [0.0, 1.0])
def test_level2_widens_only_bounds_the_worst_missed_observable_changes_along_and_reaches_beyond(cb):
    # y = 10 + 10 a + cb b on the unit square, target 25 (5 %): at most 20 + cb, the best point is a = 1 (and b = 1
    # when y rises with b); beyond a = 1 y meets its band's lower edge 23.75 at a = 1.375 - cb / 10; beyond b = 1
    # (cb = 1) at b = 3.75, 275 % of the range out; along b with cb = 0 y does not change at all
    result = calibration_check({"y": _plane("y", 10.0, 10.0, cb)}, DOMAIN, {"y": 25.0}, 0.05, 21)
    assert not result.feasible and result.best_point["a"] == pytest.approx(1.0)
    assert result.widen == {"a": ["upper"]}
    assert "Widen the range of a" in result.message and "Widen the range of b" not in result.message
    reach = [(r.factor, r.side, r.widen) for r in result.reach]
    if cb:
        assert result.best_point["b"] == pytest.approx(1.0)
        assert reach == [("a", "upper", True), ("b", "upper", False)]
        assert "only at b ≈ 3.75" in result.message
    else:  # b flat: its bound is judged nowhere
        assert reach == [("a", "upper", True)]


def test_level2_judges_widening_by_the_worst_missed_observable_a_factor_moves():
    # z is 5 everywhere against 10 (missed by 50 %, no factor moves it); y misses by less but moves with a: the
    # bound to widen is a's upper one, along which y reaches its band
    surrogates = {"y": _plane("y", 10.0, 10.0, 0.0), "z": _plane("z", 5.0, 0.0, 0.0)}
    result = calibration_check(surrogates, DOMAIN, {"y": 25.0, "z": 10.0}, 0.05, 21)
    assert result.unmoved == ["z"] and not result.feasible
    assert result.widen == {"a": ["upper"]}
    assert [(r.factor, r.side, r.observable) for r in result.reach] == [("a", "upper", "y")]


def test_level2_with_every_observable_unmoved_advises_widening_nothing():
    result = calibration_check({"z": _plane("z", 5.0, 0.0, 0.0)}, DOMAIN, {"z": 10.0}, 0.05, 21)
    assert result.unmoved == ["z"] and not result.feasible
    assert result.best_max_error == pytest.approx(0.5)
    assert result.widen == {} and result.reach == [] and "Widen the range" not in result.message
    assert "z is predicted the same everywhere in the search range" in result.message


def test_level2_met_on_a_corner_advises_widening_both_bounds_with_no_reach_of_a_missed_target():
    # y = 10 + 10 a + 10 b meets 30 only at the corner (1, 1): the best point sits on both upper bounds, and with
    # every target met there is no missing best point whose reach beyond a bound is estimated
    result = calibration_check({"y": _plane("y", 10.0, 10.0, 10.0)}, DOMAIN, {"y": 30.0}, 0.05, 21)
    assert result.feasible and result.best_max_error == pytest.approx(0.0, abs=1e-9)
    assert result.widen == {"a": ["upper"], "b": ["upper"]} and result.reach == []


def test_level2_with_an_empty_exact_set_reports_no_set_bounds():
    from demid.sampling.evaluate import evaluate_set

    surrogates = {"y": _plane("y", 10.0, 10.0, 0.0)}
    strict = evaluate_set(surrogates, DOMAIN, ("y",), {"y": 25.0}, 0.05, 21)
    assert strict.exact is not None and strict.exact.fraction == 0.0  # y is at most 20: no point meets 25
    result = calibration_check(surrogates, DOMAIN, {"y": 25.0}, 0.05, 21, strict_set=strict)
    assert not result.feasible and result.set_at_bound is None and result.to_json()["set_at_bound"] is None
    assert result.widen == {"a": ["upper"]}
