"""A scenario's strict set is the same whether the caller hands over the fitted surrogates' grid predictions (as the
admissibility step does) or the scenario predicts them itself (as the criticism does), field for field, in a
material where another response has its own tolerance (so the handed-over predictions are transformed for the
scenario): the set, its spans and its closest approach.  The closest approach of an unreachable target is checked
against exact rational arithmetic on a target one unit in the last place above 1, where the nearest node wins by
that last place; a reachable band on a plane too."""

from __future__ import annotations

from fractions import Fraction

import numpy as np
import pytest

from demid.sampling.grid import predict_grid
from demid.scenario import judged_scenarios
from demid.spec import MaterialSpec
from tests.helpers import Linear
from tests.test_judged_scenario_properties import _surrogate

TARGET = 1.0000000000000002  # 1 + 2**-52


class Corners:
    """3 + 2**-51 at the origin, 3 at the far corner, 5 elsewhere: both corners miss the target by about 2,
    the far corner by 2**-51 less."""

    def predict(self, x):
        x = np.atleast_2d(np.asarray(x, dtype=float))
        out = np.full(len(x), 5.0)
        out[np.all(x == 0.0, axis=1)] = 3.0000000000000004
        out[np.all(x == 1.0, axis=1)] = 3.0
        return out


def _judged(field, target):
    spec = MaterialSpec.from_material("m", {
        "data": "x.csv", "design": {"type": "custom"},
        "factors": {"a": {"lower": 0.0, "upper": 1.0}, "b": {"lower": 0.0, "upper": 1.0}},
        "responses": {"y": {"target": target}, "w": {"target": 2.0, "tolerance_abs": 0.3}},
        "scenarios": {"s": {"observables": ["y"], "tolerance": 0.1}}})
    fitted = {"y": field, "w": _surrogate("w", 2.0, [0.5, 0.5], 0.1)}
    return judged_scenarios(spec, fitted, 2.0)["s"], spec, fitted


@pytest.mark.parametrize("field, target", [(Corners(), TARGET), (Linear(1.0, [2.0, 1.0]), 2.3)])
def test_the_strict_set_from_handed_over_predictions_is_the_scenarios_own(field, target):
    judged, spec, fitted = _judged(field, target)
    n = 5
    handed = judged.strict_set(n, predict_grid(fitted, spec.domain, n))
    own = judged.strict_set(n)
    for name in ("fraction", "node_fraction", "n_admissible_nodes", "best_error"):
        assert getattr(handed, name) == getattr(own, name), name
    for name in ("mask", "cell_fraction", "lower", "upper", "best_point"):
        np.testing.assert_array_equal(getattr(handed, name), getattr(own, name), err_msg=name)
    # the closest approach: the node whose prediction lies nearest the target, in exact arithmetic
    nodes = spec.domain.grid(n)
    miss = [abs(Fraction(float(v)) - Fraction(target)) for v in field.predict(nodes)]
    np.testing.assert_array_equal(handed.best_point, nodes[int(np.argmin(miss))])
