"""The tolerance sweep with the scenarios' strict sets handed in: only the nominal row of a strict sweep is the
handed-in exact set (marked here by a fraction of its own); every other tolerance, and every row of a plausible
sweep (z > 0), is computed.  Against y = a over the unit square, target 0.5: the band |a - 0.5| <= ε/2 holds a
fraction ε of the square and spans 0.5 ± ε/2, written out here, at tolerances below and above the nominal one."""

from __future__ import annotations

from dataclasses import replace

import numpy as np
import pytest

from demid.sampling.domain import Domain
from demid.sampling.evaluate import evaluate_set
from demid.uncertainty.sweep import tolerance_sweep

from .test_uncertainty import linear

DOMAIN = Domain(("a", "b"), (0.0, 0.0), (1.0, 1.0))
TARGETS = {"y": 0.5}
NOMINAL = 0.1


@pytest.mark.parametrize("z", [0.0, 2.0])
def test_only_the_nominal_row_of_a_strict_sweep_is_the_given_set(z):
    surrogates = {"y": linear(0.0, [1.0, 0.0])}
    exact = evaluate_set(surrogates, DOMAIN, ("y",), TARGETS, NOMINAL, 21)
    marked = replace(exact, fraction=0.02)
    frame = tolerance_sweep(surrogates, DOMAIN, {"s": (["y"], NOMINAL)}, TARGETS, [0.2, 0.05], 21, z=z,
                            strict_sets={"s": marked}, polish=True)
    assert frame["tolerance"].tolist() == [0.05, 0.05, 0.1, 0.1, 0.2, 0.2]
    assert frame["factor"].tolist() == ["a", "b"] * 3
    for eps, rows in frame.groupby("tolerance"):
        # no surrogate error and no sigma: the plausible band at z is the tolerance band, the same set
        expected = 2.0 if (eps == NOMINAL and z == 0) else 100 * eps
        assert rows["feasible_fraction_pct"].tolist() == pytest.approx([expected] * 2, rel=1e-6), (eps, z)
        a = rows.set_index("factor").loc["a"]
        if not (eps == NOMINAL and z == 0):  # the marked set keeps the exact set's spans
            np.testing.assert_allclose([a["lower"], a["upper"], a["width"]], [0.5 - eps / 2, 0.5 + eps / 2, eps],
                                       atol=1e-9)
        b = rows.set_index("factor").loc["b"]
        np.testing.assert_allclose([b["lower"], b["upper"], b["width"]], [0.0, 1.0, 1.0], atol=1e-9)
        assert (rows["fraction_error_pct"] >= 0).all() and (rows["fraction_error_pct"] < 0.5).all()
