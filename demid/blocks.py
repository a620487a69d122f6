"""Runs made in blocks: the reserved table column ``block`` (any labels).

A CCD is often run in blocks (the factorial runs, then the axial runs; in DEM studies a first wave and
a later one, perhaps with another software version or machine), and each block may shift the response
as a whole.  With a ``block`` column every model carries one term per block beyond the first, in effect
(sum-to-zero) coding: the intercept is then the average over the blocks, so predictions, sets and
scenarios use the block-averaged surface (the response at the mean block effect).  Replicates count
towards pure error only within their block.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

#: The reserved table column holding each run's block label.
BLOCK_COLUMN = "block"

#: Coded values closer to 0 than this are on a factor's centre level.
_ZERO = 1e-6

#: Blocking counts as orthogonal when every block column correlates with each model term by less than this: the
#: levels of printed tables are rounded (alpha 1.414 for sqrt 2 leaves correlations of about 1e-4).
ORTHOGONAL_CORRELATION = 0.01


def block_labels(table) -> np.ndarray | None:
    """The table's block labels as strings (None without a ``block`` column or with a single block)."""
    if BLOCK_COLUMN not in getattr(table, "columns", ()):
        return None
    labels = np.array([label_text(v) for v in table[BLOCK_COLUMN]], dtype=object)
    return labels if len(set(labels)) > 1 else None


def label_text(value) -> str:
    """A block label as written: 1 and 1.0 both read '1'."""
    if isinstance(value, (int, np.integer)):
        return str(int(value))
    if isinstance(value, (float, np.floating)) and float(value).is_integer():
        return str(int(value))
    return str(value).strip()


def block_levels(labels) -> list[str]:
    """The block labels in order of first appearance."""
    return list(dict.fromkeys(labels))


def block_columns(labels, levels: list[str] | None = None) -> np.ndarray:
    """Effect-coded columns (n, B-1): +1 in block j, -1 in the last block, 0 elsewhere.

    The coefficients are the first B-1 blocks' departures from the average over blocks; the last one's is
    minus their sum (:func:`block_effects`)."""
    labels = np.asarray(labels, dtype=object)
    levels = block_levels(labels) if levels is None else levels
    out = np.zeros((len(labels), len(levels) - 1))
    for j, level in enumerate(levels[:-1]):
        out[labels == level, j] = 1.0
    out[labels == levels[-1], :] = -1.0
    return out


def block_effects(coefficients, covariance, levels: list[str]) -> dict[str, tuple[float, float]]:
    """{label: (effect, standard error)} from the B-1 effect-coded coefficients and their covariance."""
    beta = np.asarray(coefficients, dtype=float)
    cov = np.asarray(covariance, dtype=float)
    contrasts = np.vstack([np.eye(len(beta)), -np.ones((1, len(beta)))])
    effects = contrasts @ beta
    se = np.sqrt(np.maximum(np.einsum("ij,jk,ik->i", contrasts, cov, contrasts), 0.0))
    return {label: (float(e), float(s)) for label, e, s in zip(levels, effects, se)}


def pure_error_groups(coded: np.ndarray, labels=None) -> np.ndarray:
    """Integer group id per run: runs at the same design point (the one replicate rule,
    :func:`demid.design.replicate_keys`) *and* in the same block share an id."""
    from .design import replicate_groups, replicate_keys

    if labels is None:
        return replicate_groups(coded)
    level_index = {label: i for i, label in enumerate(block_levels(labels))}
    keys = np.column_stack([replicate_keys(coded), [level_index[label] for label in labels]])
    _, inverse = np.unique(keys, axis=0, return_inverse=True)
    return inverse.ravel()


@dataclass(frozen=True)
class BlockCheck:
    """How a table's blocks sit in its design: problems that stop the fit, and whether blocking is
    orthogonal (block effects then leave the quadratic's coefficients unchanged)."""

    levels: tuple[str, ...]
    runs: dict
    centre_runs: dict
    orthogonal: bool
    max_correlation: float
    problems: tuple[str, ...]
    notes: tuple[str, ...]

    def to_json(self) -> dict:
        return {"blocks": list(self.levels), "runs": dict(self.runs), "centre_runs": dict(self.centre_runs),
                "orthogonal": self.orthogonal, "max_correlation": round(self.max_correlation, 6),
                "notes": list(self.notes)}


def check_blocks(coded: np.ndarray, labels, model_columns: np.ndarray) -> BlockCheck:
    """Blocks of a design: every block has runs and a centre run (so its shift is estimated apart from
    the curvature), the block terms are estimable beside the model, and whether they are orthogonal to
    the model's terms (a blocked CCD with the right centre runs and axial distance is; then the block
    effects do not change the other coefficients)."""
    labels = np.asarray(labels, dtype=object)
    levels = block_levels(labels)
    coded = np.asarray(coded, dtype=float)
    centre = np.all(np.abs(coded) < _ZERO, axis=1)
    runs = {lv: int(np.sum(labels == lv)) for lv in levels}
    centres = {lv: int(np.sum((labels == lv) & centre)) for lv in levels}
    problems, notes = [], []
    no_centre = [lv for lv in levels if centres[lv] == 0]
    if no_centre:
        notes.append(f"block(s) {', '.join(no_centre)} have no centre run: their shift is estimated only "
                     "through the quadratic; a blocked CCD puts centre runs in every block")
    b = block_columns(labels, levels)
    x = np.column_stack([model_columns, b])
    rank = np.linalg.matrix_rank(x)
    if rank < x.shape[1]:
        problems.append("the block terms cannot be estimated beside the quadratic (a block holds no run the "
                        "others do not explain, or the blocks split the design along a factor)")
    # orthogonal blocking: the block columns are uncorrelated with every non-intercept term
    terms = model_columns[:, 1:]
    tc = terms - terms.mean(axis=0)
    bc = b - b.mean(axis=0)
    with np.errstate(divide="ignore", invalid="ignore"):
        corr = (tc.T @ bc) / np.outer(np.linalg.norm(tc, axis=0), np.linalg.norm(bc, axis=0))
    corr = np.nan_to_num(corr)
    worst = float(np.max(np.abs(corr))) if corr.size else 0.0
    orthogonal = worst < ORTHOGONAL_CORRELATION
    notes.append("blocking is orthogonal: the block effects leave the quadratic's coefficients unchanged"
                 if orthogonal else
                 f"blocking is not orthogonal (largest correlation of a block with a model term {worst:.3f}): the "
                 "quadratic's coefficients are estimated adjusted for the blocks")
    return BlockCheck(tuple(levels), runs, centres, orthogonal, worst, tuple(problems), tuple(notes))


def ccd_blocks(coded: np.ndarray, n_blocks: int) -> np.ndarray:
    """Block number (1-based) of each point of a CCD in ``n_blocks`` blocks: the factorial points (with
    their share of the centre runs) in blocks 1..n_blocks-1 by halving on the highest-order interaction
    (two blocks: factorial | axial), the axial points in the last block; centre runs shared out in turn."""
    coded = np.asarray(coded, dtype=float)
    if n_blocks < 2:
        return np.ones(len(coded), dtype=int)
    off = np.abs(coded) > _ZERO
    n_off = off.sum(axis=1)
    factorial = n_off == coded.shape[1]
    centre = n_off == 0
    out = np.zeros(len(coded), dtype=int)
    out[~factorial & ~centre] = n_blocks  # the axial points
    factorial_blocks = n_blocks - 1
    if factorial_blocks == 1:
        out[factorial] = 1
    else:  # halve the factorial by the signs of the highest interactions
        signs = np.sign(coded[factorial])
        code = np.zeros(int(factorial.sum()), dtype=int)
        for i in range(int(np.log2(factorial_blocks))):
            code = code * 2 + (np.prod(signs[:, i:], axis=1) > 0)
        out[factorial] = 1 + code % factorial_blocks
    for i, row in enumerate(np.flatnonzero(centre)):
        out[row] = 1 + i % n_blocks
    return out
