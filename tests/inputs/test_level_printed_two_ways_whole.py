"""A level of an inferred design printed two ways (demid.design_inference): one factorial run of a factor whose
value is off the other runs at its level by a last-digit slip is still read at the value the others print, so the
inferred axial distance of every factor is the design's, the family a CCD and the centre runs counted; over
generated CCDs of 3-4 factors (four or more runs per factorial level), axial distances from 1.1 to 2.5, linear and
log ranges away from the origin, any run order and a slip of either sign on either factorial level."""

from __future__ import annotations

import numpy as np
import pandas as pd
import pytest

from demid.design import ccd_points
from demid.design_inference import infer_design


@pytest.mark.parametrize("seed", range(8))
def test_one_run_off_its_level_does_not_move_the_inferred_axial_distance(seed):
    rng = np.random.default_rng(seed)
    k, alpha, centres = int(rng.integers(3, 5)), float(rng.uniform(1.1, 2.5)), int(rng.integers(1, 5))
    coded = ccd_points(k, alpha, centres)[rng.permutation(2 ** k + 2 * k + centres)]
    logs = rng.random(k) < 0.4
    centre, half = rng.uniform(-40, 40, k), rng.uniform(0.05, 20, k)
    centre[logs], half[logs] = rng.uniform(-3, 2, logs.sum()), rng.uniform(0.1, 0.8, logs.sum())
    model = centre + coded * half  # model units: log10 for a log factor
    j = int(rng.integers(0, k))
    level = float(rng.choice([-1.0, 1.0]))
    row = int(rng.choice(np.flatnonzero(np.isclose(coded[:, j], level) & np.all(np.abs(coded) == 1, axis=1))))
    model[row, j] += float(rng.choice([-1, 1])) * rng.uniform(2e-4, 2e-3) * half[j]  # within the level's merge
    actual = np.where(logs, 10.0 ** model, model)
    names = [f"f{i}" for i in range(k)]
    table = pd.DataFrame(actual, columns=names)
    table.insert(0, "run", np.arange(1, len(table) + 1))

    inferred = infer_design(table, names, "t.csv", log_factors=tuple(n for n, g in zip(names, logs) if g))

    assert inferred.family == "ccd"
    assert inferred.factors == tuple(names)
    assert inferred.center_runs == centres
    assert inferred.alpha == pytest.approx((alpha,) * k, rel=1e-9)
