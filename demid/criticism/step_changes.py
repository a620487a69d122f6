"""The step cause's change-points: in run order, each one's step column residualised on the model, and the
projections of residual columns on them (from running sums above a few hundred runs, so the test's cost stays
linear in the runs).  Used by :class:`demid.criticism.catalogue.Round` and the rival steps of
:mod:`demid.criticism.naming`."""

from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np

from .models import residualize

if TYPE_CHECKING:
    from .models import Model

#: A step in run order leaves at least this many runs on each side (a shift of the first or last run alone
#: is an outlier).
STEP_MIN_RUNS = 2


#: Change-points whose step columns are held at once: the columns are n long and there are about n
#: change-points, so all of them at once would be an n x n matrix (800 MB at 10,000 runs).
STEP_CHUNK = 256


#: Cells (runs x null draws) of the step test's cumulative sums held at once.
STEP_CELLS = 2 ** 22


def step_direction_chunks(m: Model, q: np.ndarray, size: int | None = None):
    """Change-points in run order (index into the data of the first run after each) and their step columns
    residualised on the model and normalised (n, C), ``size`` change-points at a time; change-points the model
    already explains (a block boundary) are left out."""
    size = size or STEP_CHUNK
    kept = np.flatnonzero(m.keep)
    order = kept[np.argsort(m.data.runs[kept].astype(float), kind="stable")]
    starts, cols = [], []
    for c in range(STEP_MIN_RUNS, len(order) - STEP_MIN_RUNS + 1):
        col = m.step_column(m.keep, int(order[c])) * m.sw
        r = residualize(q, col[:, None])[:, 0]
        if np.linalg.norm(r) > 1e-6 * max(np.linalg.norm(col), 1e-300):
            starts.append(int(order[c]))
            cols.append(r / np.linalg.norm(r))
        if len(cols) == size:
            yield starts, np.column_stack(cols)
            starts, cols = [], []
    if cols:
        yield starts, np.column_stack(cols)


def step_projections(m: Model, q: np.ndarray, e: np.ndarray) -> tuple[list[int], np.ndarray]:
    """Change-points in run order and the projections (C, B) of residual columns e (n, B) on their unit step
    columns: :func:`step_direction_chunks`' change-points and numbers from cumulative sums in run order, O(n B)
    instead of a residualised column per change-point (n^2 B).

    The step column of change-point c is sw (1[run >= run_c] - f_c), f_c the share of runs at or after it; on
    the orthonormal basis q of the weighted model, its residual r_c has u_c = r_c / |r_c| with
    |r_c|^2 = |col_c|^2 - |q'col_c|^2 and u_c'e = (col_c'e - (q'col_c)'(q'e)) / |r_c|, and every part of col_c
    is a sum over the runs from c on in run order."""
    kept = np.flatnonzero(m.keep)
    n = len(kept)
    order = np.argsort(m.data.runs[kept].astype(float), kind="stable")  # positions among the kept runs
    labels = m.data.runs[kept].astype(float)[order]
    candidates = np.arange(STEP_MIN_RUNS, n - STEP_MIN_RUNS + 1)  # none below 2 STEP_MIN_RUNS runs: (0, B) out
    first = np.searchsorted(labels, labels[candidates], side="left")  # tied labels step together
    sw = m.sw[order]

    def suffix(v):  # sums over sorted positions s.. n-1, for s = 0..n (reverse cumulative sum, small tails exact)
        out = np.zeros((n + 1,) + v.shape[1:])
        out[:n] = np.cumsum(v[::-1], axis=0)[::-1]
        return out[first]

    share = (n - first) / n  # the step column's mean over the kept runs, as Model.step_column subtracts
    sw2_after = suffix(sw * sw)
    q_after, q_sw = suffix(sw[:, None] * q[order]), q.T @ m.sw
    col_norm2 = sw2_after * (1 - 2 * share) + share ** 2 * float(sw @ sw)
    q_col = q_after - share[:, None] * q_sw[None, :]
    r_norm2 = np.maximum(col_norm2 - np.sum(q_col * q_col, axis=1), 0.0)
    keep = np.sqrt(r_norm2) > 1e-6 * np.maximum(np.sqrt(col_norm2), 1e-300)  # not a block boundary
    e_sorted = e[order]
    col_e = suffix(sw[:, None] * e_sorted)[keep] - share[keep, None] * (sw @ e_sorted)[None, :]
    proj = (col_e - q_col[keep] @ (q.T @ e)) / np.sqrt(r_norm2[keep])[:, None]
    return [int(kept[order[c]]) for c in candidates[keep]], proj


def step_starts(m: Model, q: np.ndarray) -> list[int]:
    """The change-points :func:`step_direction_chunks` tests."""
    return [start for starts, _ in step_direction_chunks(m, q) for start in starts]
