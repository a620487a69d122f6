"""A step in run order as its finding reads it (criticism.level1.criticize): the first shifted run, how many runs came
before it (the runs of smaller label, not counting the first shifted one) and the shift, against least squares with
the quadratic and a 0/1 column of the runs from that run on, written out here.  A rotatable CCD with five centre runs,
rows in design order and run labels shuffled, spaced 1 or 10 apart."""
from __future__ import annotations

import re

import numpy as np
import pandas as pd
import pytest

from demid.criticism.level1 import criticize
from demid.design import ccd_points, model_matrix, quadratic_terms


@pytest.mark.parametrize("seed, spacing, first", [(1, 10, 6), (2, 1, 9)])
def test_a_steps_first_run_runs_before_and_shift(seed, spacing, first):
    rng = np.random.default_rng(seed)
    coded = ccd_points(2, 2 ** 0.5, 5)
    labels = spacing * (rng.permutation(len(coded)) + 1)
    x = model_matrix(coded, quadratic_terms(2))
    after = (labels >= spacing * first).astype(float)
    y = 50 + 3 * x @ rng.normal(size=6) + 0.2 * rng.standard_normal(len(coded)) + 6.0 * after
    table = pd.DataFrame({"run": labels, "a": 2 * coded[:, 0] + 5, "b": coded[:, 1] + 1, "y": y})
    result = criticize(table, ["a", "b"], "y", n_null=99)
    step = result.findings[0]
    assert (step.cause, step.detail) == ("step", spacing * first)
    before = int(np.sum(labels < spacing * first))
    assert step.info["runs_before"] == before == first - 1
    shift = np.linalg.lstsq(np.column_stack([x, after]), y, rcond=None)[0][-1]
    assert step.info["step_size"] == pytest.approx(shift, rel=1e-9)
    said = re.search(r"the runs from run (\d+) on are shifted by ([+-][\d.]+) against the (\d+) runs before",
                     step.message)
    assert said and int(said.group(1)) == spacing * first and int(said.group(3)) == before
    assert float(said.group(2)) == pytest.approx(shift, rel=5e-4)
