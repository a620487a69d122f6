"""The refit engine on designs that cannot estimate every term (a two-level factorial and its centre runs under
a quadratic model: the squares are aliased with the intercept and with each other), against least squares
written out with numpy: the rank is numpy's (singular values below max(n, p) * eps times the largest are zero,
whatever the design's scale), so the lack-of-fit degrees of freedom, F and p, the leverages behind Q² and the
minimum-norm coded coefficients are those of the estimable part of the model.  Levels of the factorial points
from 0.1 to 2.9 coded units, 2-4 factors, 1-5 replicates and 0-6 centre runs: the round-off of an aliased
column's singular value grows with the design's largest one."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import Phase, given, settings
from hypothesis import strategies as st

from demid.design import Coding, model_matrix, quadratic_terms
from demid.transcription.engine import DesignFit, evaluate_designs, lack_of_fit_p
from tests.transcription.test_engine_whole import _check, _reference

SETTINGS = settings(max_examples=8, deadline=None, derandomize=True, phases=[Phase.explicit, Phase.generate])
COEFFICIENTS = {"b0": ("coded", 0), "b1": ("coded", 1)}


def _factorial_with_centre(k, level, replicates, centre_runs):
    corners = np.array([[(level if (r >> i) & 1 else -level) for i in range(k)] for r in range(2 ** k)])
    return np.vstack([np.tile(corners, (replicates, 1)), np.zeros((centre_runs, k))])


def _compare(k, level, replicates, centre_runs, seed):
    coded = _factorial_with_centre(k, level, replicates, centre_runs)
    terms = quadratic_terms(k)
    x = model_matrix(coded, terms)
    assert np.linalg.matrix_rank(x) < x.shape[1]  # the case under test: terms the design cannot estimate
    coding = Coding(tuple(f"x{i}" for i in range(k)), (0.0,) * k, (1.0,) * k)
    rng = np.random.default_rng(seed)
    y = rng.normal(size=(len(coded), 2)) * 4 - 3
    fit = DesignFit(coded, terms, coding, need_actual=False)
    assert fit.rank == np.linalg.matrix_rank(x)
    got = lack_of_fit_p(fit.evaluate(y, COEFFICIENTS))
    batch = lack_of_fit_p(evaluate_designs(np.stack([coded, coded]), y[:, 0], terms, None, COEFFICIENTS))
    for column in range(2):
        _check(got, _reference(coded, y[:, column], terms, coding), column, COEFFICIENTS)
        _check(batch, _reference(coded, y[:, 0], terms, coding), column, COEFFICIENTS)


# designs whose aliased columns keep a singular value of a few 1e-15 (above max(n, p) * eps alone)
@pytest.mark.parametrize("k, level, replicates, centre_runs", [
    (2, 2.9, 3, 1), (3, 2.9, 1, 0), (4, 1.3, 5, 1), (4, 2.9, 1, 1), (4, 2.9, 2, 6), (4, 2.9, 5, 3)])
def test_aliased_terms_of_a_scaled_factorial_are_left_out_as_numpy_would(k, level, replicates, centre_runs):
    _compare(k, level, replicates, centre_runs, seed=k * 100 + replicates)


@given(k=st.integers(2, 4), level=st.sampled_from([0.1, 1 / 3, 0.7, 1.0, 1.1, 1.3, 2.9]),
       replicates=st.integers(1, 5), centre_runs=st.integers(0, 6), seed=st.integers(0, 1000))
@SETTINGS
def test_every_statistic_of_a_design_that_cannot_estimate_its_squares(k, level, replicates, centre_runs, seed):
    _compare(k, level, replicates, centre_runs, seed)
