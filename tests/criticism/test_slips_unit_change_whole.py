"""A slip whose change of the model-matrix row is exactly 1 in every term it touches (criticism.slips.slip_ratios):
a factor on -8, 1, 10 (centre 1, unit 9), whose centre run slipped x10 lands on 10, coded 1, so its linear and
squared terms both change by exactly 1 (and its interactions by the other factor's coded value, 0 at the centre).
The SSE ratio of every candidate, alone or with the others, against a least-squares refit of the table with the run
moved (the brute force of test_slips_brute_force.py); 2-3 factors, two response columns."""

from __future__ import annotations

import itertools

import numpy as np
import pandas as pd
import pytest

from demid.criticism.level1 import prepare_data
from demid.criticism.models import Model, ModelForm
from demid.criticism.slips import moved_rows, slip_candidates, slip_ratios
from tests.criticism.test_slips_brute_force import _ratio_by_refit


def _model(k: int, seed: int):
    levels = [(-8.0, 1.0, 10.0)] + [(2.0, 3.0, 4.0)] * (k - 1)
    points = np.array(list(itertools.product(*levels)) + [[1.0] + [3.0] * (k - 1)] * 2)
    names = [f"f{j}" for j in range(k)]
    rng = np.random.default_rng(seed)
    u = (points - points.mean(axis=0)) / np.ptp(points, axis=0)
    y = 5.0 + u @ rng.uniform(-2, 2, k) + 0.7 * u[:, 0] ** 2 + 0.05 * rng.standard_normal(len(points))
    table = pd.DataFrame(points, columns=names)
    table.insert(0, "run", np.arange(1, len(points) + 1))
    table["y"] = y
    data, _ = prepare_data(table, names, "y", 1.0, (), None)
    return data, Model(data, ModelForm())


@pytest.mark.parametrize("k,seed", [(2, 0), (2, 1), (3, 2)])
def test_a_slip_changing_its_terms_by_exactly_one_is_scored_as_a_refit_scores_it(k, seed):
    data, m = _model(k, seed)
    cands = slip_candidates(data, m)
    unit = [c for c in cands if c.factor == 0 and c.power == 1 and c.coded == 1.0
            and not data.coded[c.row, 1:].any()]  # the centre runs slipped x10
    assert len(unit) == 3
    change = moved_rows(m, unit) - m.x[[int(np.flatnonzero(np.flatnonzero(m.keep) == c.row)[0]) for c in unit]]
    assert set(np.unique(change[change != 0])) == {1.0}  # every term it touches changes by exactly 1
    rng = np.random.default_rng(seed)
    y = np.column_stack([m.z, m.fitted_z + 0.05 * rng.standard_normal(len(m.z))])
    y[unit[0].row, 1] += 3.0  # that run far off in the second column
    for subset in (unit[:1], unit, cands):
        best, arg = slip_ratios(m, subset, y)
        brute = _ratio_by_refit(m, subset, y)
        np.testing.assert_allclose(best, np.maximum(brute.max(axis=0), 0.0), rtol=1e-9)
        for b in range(y.shape[1]):
            assert brute[arg[b], b] >= brute[:, b].max() * (1 - 1e-9)
