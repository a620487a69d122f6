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
