"""Targets far from every simulated value judged alike on either side of zero: a response whose runs and target
are negated (a force, a displacement measured the other way) names the same targets, as far or not, with the same
power of ten, the range mirrored and the repaired value negated; over generated positive ranges from narrow to
several decades wide and targets spread over six decades each side of them (within one range of the runs, off by
a power of ten, far outside)."""

from __future__ import annotations

import numpy as np
import pandas as pd
import pytest

from demid.data import implausible_targets


@pytest.mark.parametrize("seed", range(5))
def test_a_negated_response_and_target_are_judged_as_the_original(seed):
    rng = np.random.default_rng(seed)
    lo = float(10.0 ** rng.uniform(-3, 3))
    hi = lo * float(rng.choice([1.05, 1.6, 4.0, 30.0]))
    y = np.concatenate([[lo, hi], rng.uniform(lo, hi, 3)])
    targets = lo * 10.0 ** np.linspace(-3.0, 3.0, 73) * rng.uniform(0.97, 1.03, 73)
    positive, negative = pd.DataFrame({"y": y}), pd.DataFrame({"y": -y})
    named = 0
    for target in targets:
        plus = implausible_targets(positive, {"y": float(target)})
        minus = implausible_targets(negative, {"y": -float(target)})
        assert set(plus) == set(minus), target
        if not plus:
            continue
        named += 1
        p, m = plus["y"], minus["y"]
        assert (m["lo"], m["hi"]) == (-p["hi"], -p["lo"])
        assert m["far"] is p["far"] and m["factor"] == p["factor"], target
        assert (m["repaired"] is None) == (p["repaired"] is None)
        if p["repaired"] is not None:
            assert m["repaired"] == -p["repaired"]
    assert 0 < named < len(targets)
