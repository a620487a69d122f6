"""What validation says of a table run in blocks: orthogonal blocking with a centre run in every block is silent;
blocks without a centre run are named even when the blocking is orthogonal; blocking that is not orthogonal is said,
with the largest correlation of a block column (effect coded: +1 in the block, -1 in the last) with a term of the
quadratic, computed here from the coded runs.  Two and three factors, two and three blocks."""

from __future__ import annotations

from itertools import product

import numpy as np
import pandas as pd
import pytest

from demid.data import validate_material
from demid.spec import MaterialSpec

NOTE = "{src}, column 'block': "


def _write(path, coded, blocks, seed):
    """The runs at ``coded`` points (centre 2, unit 0.5 in every factor), a smooth response with noise, blocks."""
    rng = np.random.default_rng(seed)
    k = coded.shape[1]
    actual = np.round(2.0 + 0.5 * coded, 6)
    table = pd.DataFrame({"run": np.arange(1, len(coded) + 1),
                          **{f"x{i + 1}": actual[:, i] for i in range(k)},
                          "y": 10 + coded.sum(axis=1) + (coded ** 2).sum(axis=1) + 0.1 * rng.normal(size=len(coded)),
                          "block": blocks})
    table.to_csv(path, index=False)
    spec = MaterialSpec.from_material("m", {
        "data": str(path), "design": {"type": "custom"}, "responses": {"y": {"target": 12.0}},
        "factors": {f"x{i + 1}": {"lower": 2.0 - 0.5 * 2, "upper": 2.0 + 0.5 * 2} for i in range(k)}})
    return validate_material(spec), str(path)


def _worst_correlation(coded, blocks):
    """max |corr| of an effect-coded block column with a non-intercept term of the full quadratic."""
    k = coded.shape[1]
    terms = [coded[:, i] for i in range(k)] + [coded[:, i] * coded[:, j] for i in range(k) for j in range(i + 1, k)]
    terms += [coded[:, i] ** 2 for i in range(k)]
    levels = list(dict.fromkeys(blocks))
    blocks = np.asarray(blocks)
    columns = [np.where(blocks == lv, 1.0, np.where(blocks == levels[-1], -1.0, 0.0)) for lv in levels[:-1]]
    return max(abs(np.corrcoef(t, b)[0, 1]) for t in terms for b in columns)


def _ccd(k, alpha, centres_per_block):
    """Factorial runs (with the first block's centre runs) then axial runs (with the last block's)."""
    factorial = np.array(list(product((-1.0, 1.0), repeat=k)))
    axial = np.vstack([s * alpha * np.eye(k)[i] for i in range(k) for s in (-1, 1)])
    first, last = centres_per_block
    coded = np.vstack([factorial, np.zeros((first, k)), axial, np.zeros((last, k))])
    blocks = ["1"] * (len(factorial) + first) + ["2"] * (len(axial) + last)
    return coded, blocks


@pytest.mark.parametrize("k, centres", [(2, (3, 3)), (3, (4, 2))])
def test_orthogonal_blocks_each_with_a_centre_run_add_no_warning(tmp_path, k, centres):
    first, last = centres
    # orthogonal blocking: every square has the same mean in both blocks, 2^k / (2^k + first) = 2 alpha^2 / (2k + last)
    alpha = np.sqrt(2 ** k * (2 * k + last) / (2 * (2 ** k + first)))
    coded, blocks = _ccd(k, alpha, centres)
    assert _worst_correlation(coded, blocks) < 1e-3
    validated, src = _write(tmp_path / "t.csv", coded, blocks, k)
    assert validated.warnings == []


@pytest.mark.parametrize("k, n_blocks", [(2, 2), (2, 3), (3, 2)])
def test_orthogonal_blocks_without_centre_runs_are_named(tmp_path, k, n_blocks):
    """A face-centred design without centre runs, repeated once per block: the blocks are alike, so orthogonal."""
    once = np.array([p for p in product((-1.0, 0.0, 1.0), repeat=k) if any(p)])
    coded = np.vstack([once] * n_blocks)
    labels = ["night", "day", "late"][:n_blocks]
    blocks = [label for label in labels for _ in once]
    validated, src = _write(tmp_path / "t.csv", coded, blocks, 10 + k)
    names = ", ".join(labels)
    assert validated.warnings == [
        NOTE.format(src=src) + f"block(s) {names} have no centre run: their shift is estimated only through the "
        "quadratic; a blocked CCD puts centre runs in every block"]


@pytest.mark.parametrize("k, alpha, centres", [(2, np.sqrt(2.0), (1, 4)), (2, 1.6, (2, 2)), (3, 1.5, (3, 1))])
def test_blocking_that_is_not_orthogonal_is_said_with_its_largest_correlation(tmp_path, k, alpha, centres):
    coded, blocks = _ccd(k, alpha, centres)
    worst = _worst_correlation(coded, blocks)
    assert worst > 0.02
    validated, src = _write(tmp_path / "t.csv", coded, blocks, 20 + k)
    assert validated.warnings == [
        NOTE.format(src=src) + f"blocking is not orthogonal (largest correlation of a block with a model term "
        f"{worst:.3f}): the quadratic's coefficients are estimated adjusted for the blocks"]
