"""The catalogue's drift test when the run column lies (nearly) in the model's column space: a run column within
1e-7 of its own norm of the quadratic's columns is that column plus round-off, so drift is not tested (its
direction would be noise); just above that share it is.  The run column here is a factor's square (a table printed
by one factor's distance from the centre) plus a perturbation orthogonal to the model, of a chosen size, on a
replicated 3x3 factorial whose run column's norm is 2 (scaled by its range, as the model scales it): the
threshold is relative to that norm, not an absolute 1e-7."""

from __future__ import annotations

import numpy as np
import pytest

from demid.criticism.catalogue import Round
from demid.criticism.models import Data, Model, ModelForm
from demid.design import Coding, model_matrix, quadratic_terms


def _round(share: float, seed: int) -> tuple[Round, float]:
    """A round on a 3x3 factorial run twice whose run labels are 10 + 5 a² plus a perturbation orthogonal to the
    quadratic, ``share`` times the run column's norm; (the round, that norm)."""
    rng = np.random.default_rng(seed)
    levels = np.array([-1.0, 0.0, 1.0])
    coded = np.array([(a, b) for a in levels for b in levels] * 2)
    x = model_matrix(coded, quadratic_terms(2))
    q = np.linalg.qr(x)[0]
    v = rng.normal(size=len(coded))
    v -= q @ (q.T @ v)
    base = 10.0 + 5.0 * coded[:, 0] ** 2
    col = (base - base.mean()) / np.ptp(base)
    norm = float(np.linalg.norm(col))
    runs = base + v / np.linalg.norm(v) * share * norm * np.ptp(base)
    y = 50.0 + 3.0 * coded[:, 0] - 2.0 * coded[:, 1] + rng.normal(size=len(coded))
    data = Data("y", ["a", "b"], coded, y, runs, Coding(("a", "b"), (0.0, 0.0), (1.0, 1.0)), 1.0, (),
                quadratic_terms(2))
    return Round(data, Model(data, ModelForm()), 19, np.random.default_rng(seed)), norm


@pytest.mark.parametrize("seed", [0, 1])
def test_a_run_column_in_the_models_span_to_1e7_of_its_norm_is_not_tested_for_drift(seed):
    # between 1e-7 and 1e-7 times the norm (2): round-off of the norm's size, though above an absolute 1e-7
    rnd, norm = _round(0.6e-7, seed)
    assert norm == pytest.approx(2.0)
    assert norm * 0.6e-7 > 1e-7
    assert "drift" not in [h.cause for h in rnd.hypotheses]
    assert "drift" not in [h.cause for h in _round(0.0, seed)[0].hypotheses]
    # twice the share: a direction of its own, tested
    assert "drift" in [h.cause for h in _round(2e-7, seed)[0].hypotheses]
