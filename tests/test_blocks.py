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


def _expected_ccd_blocks(coded: np.ndarray, n_blocks: int) -> list[int]:
    """The documented blocking written out point by point: centre runs dealt out in turn over every block, axial
    points in the last block, factorial points split by the signs of the highest interactions (one sign for two
    factorial blocks, the signs of x1..xk and x2..xk for four)."""
    out, centre_seen = [], 0
    for row in coded:
        nonzero = [v for v in row if abs(v) > 1e-6]
        if not nonzero:
            out.append(1 + centre_seen % n_blocks)
            centre_seen += 1
        elif n_blocks == 1:
            out.append(1)
        elif len(nonzero) < len(row):
            out.append(n_blocks)
        elif n_blocks == 2:
            out.append(1)
        else:
            assert n_blocks == 3
            out.append(2 if np.prod(np.sign(row)) > 0 else 1)
    return out


@pytest.mark.parametrize("k, n_blocks", [(2, 1), (2, 2), (2, 3), (3, 1), (3, 2), (3, 3), (4, 2), (4, 3), (5, 2),
                                         (5, 3)])
@pytest.mark.parametrize("centres", [1, 4, 7])
def test_ccd_blocks_put_axial_points_last_split_the_factorial_and_deal_out_the_centres(k, n_blocks, centres):
    from demid.blocks import ccd_blocks
    from demid.design import ccd_points

    coded = ccd_points(k, None, centres)
    rng = np.random.default_rng(k * 100 + n_blocks * 10 + centres)
    coded = coded[rng.permutation(len(coded))]  # the rule holds in any run order
    blocks = ccd_blocks(coded, n_blocks)
    assert list(blocks) == _expected_ccd_blocks(coded, n_blocks)
    factorial = np.all(np.abs(coded) > 1e-6, axis=1)
    # every factorial block holds an equal share of the factorial, balanced in each factor and each
    # two-factor interaction it is not confounded with (every one, from three factors on)
    for b in range(1, max(n_blocks - 1, 1) + 1):
        part = coded[factorial & (blocks == b)]
        assert len(part) == 2 ** k // max(n_blocks - 1, 1)
        assert np.allclose(part.sum(axis=0), 0.0)
        if k >= 3:
            pairs = [part[:, i] * part[:, j] for i in range(k) for j in range(i + 1, k)]
            assert np.allclose(np.sum(pairs, axis=1), 0.0)
    assert sorted(Counter(blocks[~np.any(np.abs(coded) > 1e-6, axis=1)]).values(), reverse=True)[0] \
        == -(-centres // n_blocks)
