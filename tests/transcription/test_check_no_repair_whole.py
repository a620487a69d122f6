"""The transcription check's verdict when no single-cell repair can be tried: a table whose printed cells are
all blank (nothing to re-read) and one published R² the refit does not reproduce.  With no repair and no
printed-statistic slip to consider (one statistic vouches for nothing), the table is not consistent, nothing is
explained and no cell is suspected; the refit's R² is numpy's least-squares R², written out here."""

from __future__ import annotations

import numpy as np
import pandas as pd

from demid.design import ccd_points, model_matrix, quadratic_terms
from demid.transcription.check import check_transcription


def _r2(coded, y):
    m = model_matrix(coded, quadratic_terms(coded.shape[1]))
    beta, *_ = np.linalg.lstsq(m, y, rcond=None)
    return 1 - float(np.sum((y - m @ beta) ** 2)) / float(np.sum((y - y.mean()) ** 2))


def test_a_disagreeing_table_with_no_repair_to_try_is_not_consistent():
    rng = np.random.default_rng(7)
    coded = ccd_points(2, 1.0, 3)
    y = 50 + coded @ np.array([4.0, -3.0]) + 2 * (coded ** 2).sum(axis=1) + rng.normal(size=len(coded))
    table = pd.DataFrame({"a": 3.0 + coded[:, 0], "b": 10.0 + 2.0 * coded[:, 1], "y": y})
    printed = pd.DataFrame({c: [""] * len(table) for c in table.columns})
    r2 = _r2(coded, y)
    wrong = "0.1234"
    assert abs(r2 - 0.1234) > 0.01
    result = check_transcription(table, ["a", "b"], "y", {"r2": wrong}, alpha=1.0, printed=printed)
    assert np.isclose(result.reproduced["r2"], r2, rtol=1e-9, atol=1e-12)
    assert result.agrees == {"r2": False}
    assert result.consistent is False
    assert result.explained is False and result.suspects == [] and result.printed_slip is None
    assert result.n_candidates == 0
    assert result.message.startswith(f"'y' disagrees with the source (r2 {r2:.6f} vs printed {wrong})")
    assert "No single-cell slip explains the disagreement" in result.message
