"""Known answers for a blocked design's check: runs and centre runs counted per block, and the largest
correlation of a block column with a model term, from numpy's own correlation coefficients."""

from __future__ import annotations

from collections import Counter

import numpy as np
import pytest

from demid.blocks import block_columns, check_blocks, label_text


def _ccd(alpha: float, centres: int) -> np.ndarray:
    factorial = [(a, b) for a in (-1, 1) for b in (-1, 1)]
    axial = [(-alpha, 0), (alpha, 0), (0, -alpha), (0, alpha)]
    return np.array(factorial + [(0, 0)] * centres + axial + [(0, 0)] * centres, dtype=float)


def _quadratic(coded: np.ndarray) -> np.ndarray:
    a, b = coded[:, 0], coded[:, 1]
    return np.column_stack([np.ones(len(a)), a, b, a * a, a * b, b * b])


@pytest.mark.parametrize("alpha, orthogonal", [(np.sqrt(2.0), True), (1.0, False), (1.2, False)])
def test_runs_centres_and_the_largest_block_correlation_of_a_two_block_ccd(alpha, orthogonal):
    # two blocks of 7: the factorial with 3 centre runs, the axial points with 3 more.  Blocking is orthogonal
    # when every factor's sum of squares per run is the same in each block: 4 / 7 = 2 alpha^2 / 7, alpha = sqrt 2
    coded = _ccd(alpha, 3)
    labels = np.array(["1"] * 7 + ["2"] * 7, dtype=object)
    check = check_blocks(coded, labels, _quadratic(coded))
    counts = Counter(labels)
    centre = np.all(coded == 0, axis=1)
    assert check.runs == {"1": counts["1"], "2": counts["2"]} == {"1": 7, "2": 7}
    assert check.centre_runs == {lv: int(np.sum(centre & (labels == lv))) for lv in ("1", "2")} == {"1": 3, "2": 3}
    block = block_columns(labels)[:, 0]
    expected = max(abs(np.corrcoef(col, block)[0, 1]) for col in _quadratic(coded)[:, 1:].T
                   if np.std(col) > 0)
    assert check.max_correlation == pytest.approx(expected, abs=1e-12)
    assert check.orthogonal is orthogonal
    assert not check.problems


def test_a_block_without_a_centre_run_is_named():
    coded = _ccd(np.sqrt(2.0), 2)
    labels = np.array(["a"] * 4 + ["b"] * 2 + ["c"] * 4 + ["b"] * 2, dtype=object)
    check = check_blocks(coded, labels, _quadratic(coded))
    assert check.runs == {"a": 4, "b": 4, "c": 4}
    assert check.centre_runs == {"a": 0, "b": 4, "c": 0}
    assert check.notes[0].startswith("block(s) a, c have no centre run")


@pytest.mark.parametrize("value, text", [(3, "3"), (np.int64(3), "3"), (3.0, "3"), (np.float64(2.0), "2"),
                                         (2.5, "2.5"), (" B1 ", "B1"), (np.float32(4.0), "4")])
def test_block_labels_are_written_as_typed(value, text):
    assert label_text(value) == text
