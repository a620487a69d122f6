"""Block effects and their standard errors over generated tables with 2-4 blocks: each block's effect and
standard error do not depend on which block the effect coding leaves out (the last one's is minus the sum of the
others, with every covariance), and the standard errors are those of the linear combinations of the fit."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from demid.blocks import block_effects
from demid.surrogate import fit_response
from tests.generators import FACTORS, ccd_table


@given(seed=st.integers(0, 10_000), k=st.sampled_from([2, 3]), blocks=st.integers(2, 4),
       replicates=st.integers(1, 2))
@settings(max_examples=12, deadline=None, derandomize=True)
def test_block_effects_do_not_depend_on_which_block_the_coding_leaves_out(seed, k, blocks, replicates):
    table, _ = ccd_table(seed, k, "clean", 0.0, replicates=replicates)
    rng = np.random.default_rng(seed)
    labels = np.array([f"wave {1 + i * blocks // len(table)}" for i in range(len(table))])
    shifts = {f"wave {j + 1}": s for j, s in enumerate(rng.normal(0, 3, blocks))}
    table["y"] += [shifts[b] for b in labels]
    table["block"] = labels
    first = fit_response(table, FACTORS[k], "y").block_effects()
    # the same rows the other way round: the blocks appear in reverse order, another block is left out
    again = fit_response(table.iloc[::-1].reset_index(drop=True), FACTORS[k], "y").block_effects()
    assert list(again) == list(first)[::-1]
    for label, (effect, se) in first.items():
        assert again[label][0] == pytest.approx(effect, rel=1e-7, abs=1e-9)
        assert again[label][1] == pytest.approx(se, rel=1e-7)
    assert sum(e for e, _ in first.values()) == pytest.approx(0.0, abs=1e-8)


@given(seed=st.integers(0, 10_000), blocks=st.integers(2, 5))
@settings(max_examples=25, deadline=None, derandomize=True)
def test_block_standard_errors_are_those_of_the_contrasts(seed, blocks):
    """Effects β_j of the first B−1 blocks and −Σβ of the last; the variance of a sum is the sum of every entry of
    the covariance (off-diagonal ones too), here checked against sampled coefficients."""
    rng = np.random.default_rng(seed)
    root = rng.normal(size=(blocks - 1, blocks - 1))
    cov = root @ root.T + 0.1 * np.eye(blocks - 1)
    beta = rng.normal(size=blocks - 1)
    levels = [f"b{j}" for j in range(blocks)]
    effects = block_effects(beta, cov, levels)
    assert effects["b0"][0] == pytest.approx(beta[0])
    assert effects[levels[-1]][0] == pytest.approx(-beta.sum())
    draws = rng.multivariate_normal(beta, cov, size=40_000)
    sampled = np.column_stack([draws, -draws.sum(axis=1)]).std(axis=0)
    for j, label in enumerate(levels):
        assert effects[label][1] == pytest.approx(sampled[j], rel=0.03)


def _effect_columns(labels: list[str], order: list[str]) -> np.ndarray:
    """Effect coding written out: one column per block but the last, +1 in it, -1 in the last block."""
    return np.array([[1.0 if lab == lv else -1.0 if lab == order[-1] else 0.0 for lv in order[:-1]]
                     for lab in labels])


@given(seed=st.integers(0, 10_000), k=st.sampled_from([2, 3]), blocks=st.integers(2, 3),
       orthogonal_blocks=st.booleans(), centres=st.integers(1, 6))
@settings(max_examples=25, deadline=None, derandomize=True)
def test_check_blocks_reports_counts_estimability_and_the_largest_correlation_of_a_block_with_a_term(
        seed, k, blocks, orthogonal_blocks, centres):
    """A CCD in blocks (the rotatable orthogonal blocking, or labels drawn at random): the blocks in order of
    first appearance, their runs and centre runs counted, the block terms' estimability by the rank of the
    model matrix with them, and the largest |Pearson correlation| of an effect-coded block column with a
    model term (numpy's corrcoef; 0 for a constant column), orthogonal below 0.01, quoted in the note."""
    from demid.blocks import ORTHOGONAL_CORRELATION, ccd_blocks, check_blocks
    from demid.design import ccd_points, model_matrix, quadratic_terms

    rng = np.random.default_rng(seed)
    coded = ccd_points(k, None, centres)
    number = ccd_blocks(coded, blocks) if orthogonal_blocks else rng.integers(1, blocks + 1, len(coded))
    order = rng.permutation(len(coded))
    coded, labels = coded[order], [f"day {n}" for n in np.asarray(number)[order]]
    model = model_matrix(coded, quadratic_terms(k))
    found = check_blocks(coded, labels, model)

    levels = list(dict.fromkeys(labels))
    assert list(found.levels) == levels
    centre = np.all(coded == 0, axis=1)
    assert found.runs == {lv: labels.count(lv) for lv in levels}
    assert found.centre_runs == {lv: int(sum(c for lab, c in zip(labels, centre) if lab == lv)) for lv in levels}
    b = _effect_columns(labels, levels)
    estimable = np.linalg.matrix_rank(np.column_stack([model, b])) == model.shape[1] + b.shape[1]
    assert (not found.problems) == estimable
    worst = 0.0
    for term in model[:, 1:].T:
        for column in b.T:
            if np.ptp(term) > 0 and np.ptp(column) > 0:
                worst = max(worst, abs(np.corrcoef(term, column)[0, 1]))
    assert found.max_correlation == pytest.approx(worst, abs=1e-12)
    assert found.orthogonal == (worst < ORTHOGONAL_CORRELATION)
    no_centre = [lv for lv in levels if found.centre_runs[lv] == 0]
    assert any(n.startswith(f"block(s) {', '.join(no_centre)} have no centre run") for n in found.notes) == \
        bool(no_centre)
    if not found.orthogonal:
        quoted = [n for n in found.notes if n.startswith("blocking is not orthogonal")]
        assert quoted and f"model term {worst:.3f})" in quoted[0]
    else:
        assert any(n.startswith("blocking is orthogonal") for n in found.notes)
