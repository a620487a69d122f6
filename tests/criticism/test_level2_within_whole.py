"""Whether level 2 reads a point as within its tolerances (criticism.level2.Level2Result.within): a prediction
exactly a tolerance off its target (7.7 for 7, 10 %; 3.6 for 3, 20 %; -2.4 for -3, 20 %) gives a relative error a
few units of the last bit above the tolerance, and is within it (the documented 1e-12 slack); one 1e-9 of the
target further is not; own tolerances per observable are read, and the scenario's tolerance for the others."""

from __future__ import annotations

import numpy as np
import pytest

from demid.criticism.level2 import Level2Result
from demid.formulas import relative_error


def _result(tolerance: float, tolerances: dict, reference_errors: dict) -> Level2Result:
    r = object.__new__(Level2Result)
    r.tolerance, r.tolerances, r.reference_errors = tolerance, tolerances, reference_errors
    return r


@pytest.mark.parametrize("target,tolerance", [(7.0, 0.1), (3.0, 0.2), (-3.0, 0.2), (0.3, 0.05), (11.0, 0.05)])
@pytest.mark.parametrize("own", [False, True])
def test_a_prediction_exactly_a_tolerance_off_is_within_it_and_a_hair_more_is_not(target, tolerance, own):
    at_edge = target + tolerance * abs(target)
    beyond = at_edge + 1e-9 * abs(target)
    e_edge = float(relative_error(np.array(at_edge), np.array(target)))
    e_beyond = float(relative_error(np.array(beyond), np.array(target)))
    assert e_edge > tolerance  # round-off puts it above the tolerance
    scenario = 0.5 if own else tolerance
    tolerances = {"a": tolerance} if own else {}
    for errors, within in (({"a": e_edge}, True), ({"a": e_beyond}, False), ({"a": -e_edge}, True),
                           ({"a": e_edge, "b": 0.49 if own else 0.0}, True),
                           ({"a": 0.0, "b": 0.51 if own else tolerance * 1.01}, False)):
        r = _result(scenario, tolerances, errors)
        assert r.within(errors) == within, errors
        assert r.reference_within == within
    assert _result(scenario, tolerances, None).reference_within is None


@pytest.mark.parametrize("target,tolerance", [(7.0, 0.1), (-3.0, 0.2)])
def test_the_tables_within_columns_read_an_error_exactly_a_tolerance_off_as_within(target, tolerance):
    e_edge = float(relative_error(np.array(target + tolerance * abs(target)), np.array(target)))
    e_beyond = e_edge + 1e-9
    r = _result(tolerance, {"b": 0.3}, {"a": e_edge, "b": 0.3 + 1e-9})
    r.observables, r.targets = ["a", "b"], {"a": target, "b": 1.0}
    r.best_values, r.best_errors = {"a": 0.0, "b": 0.0}, {"a": e_beyond, "b": 0.3 + 5e-14}
    r.reference_values = {"a": 0.0, "b": 0.0}
    r.bottleneck, r.without, r.implied_bias, r.bias_candidates = None, {}, {}, []
    frame = r.to_frame()
    assert list(frame["tolerance"]) == [tolerance, 0.3]
    assert list(frame["within_tolerance"]) == [False, True]
    assert list(frame["within_tolerance_reference"]) == [True, False]
