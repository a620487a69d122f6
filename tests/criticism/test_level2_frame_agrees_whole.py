"""Level 2's table and its sentences never disagree on whether an observable is met (criticism.level2): the
table's within columns are Level2Result.within of each error alone, for errors exactly on the documented slack
(the tolerance + 1e-12, to the last bit), a bit either side of it, of either sign, with own tolerances or the
scenario's; the JSON's largest reference error and its within flag are read from the same errors."""

from __future__ import annotations

import numpy as np
import pytest

from demid.criticism.level2 import Level2Result


def _result(tolerance, tolerances, best, reference) -> Level2Result:
    r = object.__new__(Level2Result)
    r.tolerance, r.tolerances = tolerance, tolerances
    r.observables = list(best)
    r.targets = {o: 1.0 for o in best}
    r.best_values, r.best_errors = {o: 1.0 + e for o, e in best.items()}, dict(best)
    r.reference_values = {o: 1.0 + e for o, e in reference.items()}
    r.reference_errors = dict(reference)
    r.bottleneck, r.without, r.implied_bias, r.bias_candidates = None, {}, {}, []
    return r


@pytest.mark.parametrize("tolerance", [0.05, 0.1, 0.2, 0.3])
@pytest.mark.parametrize("own", [False, True])
def test_the_tables_within_columns_are_within_of_each_error_on_the_slack_and_a_bit_either_side(tolerance, own):
    edge = tolerance + 1e-12
    errors = [edge, -edge, np.nextafter(edge, 1.0), -np.nextafter(edge, 1.0), np.nextafter(edge, 0.0), 0.0]
    names = [f"y{i}" for i in range(len(errors))]
    best = dict(zip(names, errors))
    reference = dict(zip(names, errors[::-1]))
    r = _result(0.7 if own else tolerance, {o: tolerance for o in names} if own else {}, best, reference)
    frame = r.to_frame().set_index("observable")
    assert list(frame["within_tolerance"]) == [r.within({o: e}) for o, e in best.items()] \
        == [True, True, False, False, True, True]
    assert list(frame["within_tolerance_reference"]) == [r.within({o: e}) for o, e in reference.items()]
    assert r.reference_within is False and r.reference_max_error == float(np.nextafter(edge, 1.0))
    met = {o: e for o, e in reference.items() if abs(e) <= edge}
    r2 = _result(r.tolerance, r.tolerances, best, met)
    assert r2.reference_within is True and r2.reference_max_error == edge


def test_a_flagged_target_of_an_observable_level_2_does_not_judge_leaves_its_widening_advice():
    """The material flags targets of responses level 2 may not judge (one without a surrogate): the best point's
    bounds are still followed, and the result is the one without the flag, message included."""
    from demid.criticism import calibration_check
    from demid.sampling.domain import Domain
    from tests.criticism.test_level2_whole import _linear

    surrogates = {"y0": _linear("y0", ["a"], 10.0, [2.0]), "y1": _linear("y1", ["a"], 5.0, [1.0])}
    domain = Domain(("a",), (0.0,), (1.0,), (False,))
    targets = {"y0": 12.4, "y1": 6.2, "y2": 3.0}
    plain = calibration_check(surrogates, domain, targets, 0.01, 5)
    assert plain.widen == {"a": ["upper"]} and "Widen the range of a" in plain.message
    flagged = calibration_check(surrogates, domain, targets, 0.01, 5, implausible=("y2",))
    assert flagged.to_json() == plain.to_json()
