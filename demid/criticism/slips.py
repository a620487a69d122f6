"""Slipped factor values (cause ``factor_level``): a run whose response fits another value of one factor, a
decimal point or unit prefix off by one to three places; the candidates, the drop of the residual sum of
squares when a run is moved, and the Bayes factor of the best slip against a mean shift of the run.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np
from scipy import stats

from ..design import LEVERAGE_UNPREDICTABLE, model_matrix
from .models import orthonormal_basis

if TYPE_CHECKING:
    from .models import Data, Model


# Slips of a recorded factor value tried by ``factor_level``: a decimal point or unit prefix off by one
# to three places (x 10^k); on log-scaled factors the same slips shift log10 by k.
_SLIP_POWERS = (-3, -2, -1, 1, 2, 3)
_SLIP_PRIOR = {1: 0.5, 2: 0.25, 3: 0.25}
# A slip is only judged where the runs can predict: moved values beyond this multiple of the design's
# reach (its largest coded level) would be quadratic extrapolation, which fits a wild run by chance.
_SLIP_REACH = 2.0
#: Cells (candidates x columns of responses) of the slip ratios held at once.
SLIP_CELLS = 2 ** 16
#: ... but at least this many candidates at once (with 2,000 null draws: 4 MB a temporary), so that the
#: arithmetic, not the loop, sets the cost.
SLIP_MIN_CANDIDATES = 256


# =========================================================================== factor-level slips
@dataclass(frozen=True)
class SlipCandidate:
    """Run ``row`` (index into the data) with factor ``factor`` at ``coded`` instead of its recorded level."""

    row: int
    factor: int
    power: int
    coded: float


def slip_candidates(data: Data, m: Model) -> list[SlipCandidate]:
    """Every kept run x factor x decimal slip whose value differs from the recorded one (in that order: run,
    then factor, then slip)."""
    coded, judged = _slipped_levels(data, m)
    kept = np.flatnonzero(m.keep)
    return [SlipCandidate(int(kept[pos]), int(j), _SLIP_POWERS[k], float(coded[pos, j, k]))
            for pos, j, k in zip(*np.nonzero(judged))]


def count_slip_candidates(data: Data, m: Model) -> int:
    """len(slip_candidates(data, m)), without building them."""
    return int(np.count_nonzero(_slipped_levels(data, m)[1]))


def _slipped_levels(data: Data, m: Model) -> tuple[np.ndarray, np.ndarray]:
    """The coded value of every run x factor x slip (runs, factors, slips) and whether it is a candidate (a
    different, finite value within the design's reach), all runs at once: a slip moves one coordinate, whose
    coded value is its own (coded = (actual - centre) / unit, coordinate by coordinate)."""
    model_units = data.coding.to_actual(m.coded)
    reach = _SLIP_REACH * float(np.max(np.abs(data.coded)))
    on_log = np.array([name in data.log_factors for name in data.factors])[None, :, None]
    shifts = np.array(_SLIP_POWERS, dtype=float)
    scales = np.array([10.0 ** k for k in _SLIP_POWERS])
    recorded = model_units[:, :, None]
    with np.errstate(over="ignore", invalid="ignore"):
        moved = np.where(on_log, recorded + shifts, recorded * scales)  # (runs, factors, slips)
        coded = (moved - np.array(data.coding.center)[None, :, None]) / np.array(data.coding.unit)[None, :, None]
        judged = (moved != recorded) & np.isfinite(moved) & (np.abs(coded) <= reach)
    return coded, judged


def moved_rows(m: Model, cands: list[SlipCandidate]) -> np.ndarray:
    """Model-matrix rows (K, p) of the candidates (run-order column unchanged)."""
    pos = _positions(m, cands)
    coded = m.coded[pos]  # a copy: fancy indexing
    coded[np.arange(len(cands)), [c.factor for c in cands]] = [c.coded for c in cands]
    rows = model_matrix(coded, m.mean_terms)
    beyond = m.x[pos, len(m.mean_terms):]  # blocks, drift, step: unchanged
    return np.column_stack([rows, beyond]) if beyond.shape[1] else rows


def _positions(m: Model, cands: list[SlipCandidate]) -> np.ndarray:
    """Each candidate's run as a position among the model's kept runs."""
    kept = np.flatnonzero(m.keep)
    lookup = np.full(len(m.keep), -1)
    lookup[kept] = np.arange(len(kept))
    return lookup[np.fromiter((c.row for c in cands), dtype=int, count=len(cands))]


def slip_ratios(m: Model, cands: list[SlipCandidate], y: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Per column of y (n, B): max over candidates of SSE / SSE(run moved), and the arg max (the first
    candidate, in the list's order, that reaches it).

    Moving run i changes one row of the model matrix, x_i to r = x_i + d (d nonzero only in the terms of the
    slipped factor); with the fit without run i (beta_(i), A_(i) = (X_(i)'X_(i))^-1),
    SSE(moved) = SSE_(i) + (y_i - r' beta_(i))^2 / (1 + r' A_(i) r).
    The fit without run i comes from the full fit (A = (X'X)^-1, beta, residuals e, leverage h_i) by
    the leave-one-out identities A_(i) = A + A x_i x_i' A / (1 - h_i), beta_(i) = beta - A x_i e_i / (1 - h_i),
    SSE_(i) = SSE - e_i^2 / (1 - h_i), so y_i - r' beta_(i) = e_i - d' beta + r' A x_i e_i / (1 - h_i): one fit
    in all, not one per run (n fits of n runs: quadratic in the number of runs), and the candidates taken
    SLIP_CELLS / B at a time.
    """
    x = m.x
    rows = moved_rows(m, cands)
    run_pos = _positions(m, cands)
    factor = np.fromiter((c.factor for c in cands), dtype=int, count=len(cands))
    q = orthonormal_basis(x)
    a = np.linalg.pinv(x.T @ x)
    beta = a @ (x.T @ y)
    # y - x beta from the orthonormal basis, by BLAS: (n, B) products, far larger than residualize's
    resid = y - q @ (q.T @ y)
    sse0 = np.sum(resid ** 2, axis=0)
    # a moved SSE below this is read as this (sse0 / 0 would be no number)
    sse_floor = 1e-300 * np.maximum(sse0, 1e-300)
    best = np.zeros(y.shape[1])
    arg = np.zeros(y.shape[1], dtype=int)
    judged = np.flatnonzero(m.hat[run_pos] < LEVERAGE_UNPREDICTABLE)
    terms_of = _slipped_terms(rows - x[run_pos], factor)
    width = max(SLIP_MIN_CANDIDATES, SLIP_CELLS // max(y.shape[1], 1))
    columns = np.arange(y.shape[1])
    for ks in (judged[s:s + width] for s in range(0, len(judged), width)):
        i = run_pos[ks]
        d_beta = _changed_fit(rows[ks] - x[i], factor[ks], beta, terms_of)
        sse_moved = _moved_sse(x[i], rows[ks], a, d_beta, resid[i], sse0)
        np.maximum(sse_moved, sse_floor, out=sse_moved)
        np.copyto(sse_moved, np.inf, where=np.isnan(sse_moved))  # no number: no improvement
        top = np.argmin(sse_moved, axis=0)  # the largest ratio sse0 / sse_moved, the first candidate on a tie
        val = sse0 / sse_moved[top, columns]
        better = val > best
        best = np.where(better, val, best)
        arg = np.where(better, ks[top], arg)
    return best, arg


def _slipped_terms(d: np.ndarray, factor: np.ndarray) -> dict[int, np.ndarray]:
    """factor -> the model-matrix columns its slips change (d, the candidates' row changes (K, p)): the
    terms of that factor, a quarter of them with six factors."""
    return {int(j): np.flatnonzero(np.any(d[factor == j] != 0, axis=0)) for j in np.unique(factor)}


def _changed_fit(d: np.ndarray, factor: np.ndarray, beta: np.ndarray, terms_of: dict) -> np.ndarray:
    """d' beta (K, B) for row changes d (K, p), each nonzero only in the terms of its candidate's factor
    (``terms_of``, :func:`_slipped_terms`): per factor over those columns, not every one."""
    out = np.zeros((len(d), beta.shape[1]))
    for j in np.unique(factor):
        rows, cols = factor == j, terms_of[int(j)]
        if len(cols):
            out[rows] = d[rows][:, cols] @ beta[cols]
    return out


def _moved_sse(xi, r, a, d_beta, ei, sse0) -> np.ndarray:
    """SSE with the run moved (K, B) of K candidates: their runs' model rows xi, moved rows r, the change of
    the fit d' beta and the runs' residuals ei (K, B).  ``d_beta`` and ``ei`` are overwritten: the (K, B)
    arrays are most of the job's slip search, so each step works in place instead of making a new one."""
    ax = xi @ a.T
    c1 = (1.0 / (1.0 - np.einsum("kp,kp->k", xi, ax)))[:, None]  # 1 / (1 - h)
    rax = np.einsum("kp,kp->k", r, ax)[:, None]
    g = np.einsum("kp,kp->k", r @ a, r)[:, None] + rax ** 2 * c1
    scaled = ei * c1  # e / (1 - h)
    e_moved = np.subtract(ei, d_beta, out=d_beta)
    e_moved += np.multiply(scaled, rax, out=scaled)  # e - d' beta + r'A x e / (1 - h)
    sse_without = np.multiply(ei, ei, out=ei)
    sse_without *= c1
    np.subtract(sse0[None, :], sse_without, out=sse_without)
    np.maximum(sse_without, 0.0, out=sse_without)
    e_moved *= e_moved
    e_moved *= 1.0 / (1.0 + g)
    sse_without += e_moved
    return sse_without


def slip_fit(m: Model, same_run: list[SlipCandidate], n_factors: int) -> tuple[SlipCandidate, dict]:
    """The most probable slip of the run, how well it fits, and the Bayes factor of "a slip" against
    "a mean shift" for the run.

    t_moved / t_recorded: the run's prediction error from the other runs (in standard errors) at the
    slipped and at the recorded value.  The Bayes factor compares the run's response given the other
    runs under a slip (prior over the slips: half on one decimal place, a quarter each on two and three,
    spread evenly over factors and directions) with a mean shift of unknown size, uniform over the
    observed range of the response; one run can only favour a slip when it lands close to what a
    slip predicts, compared with how many slips there are and how wide the responses range.
    """
    pos = int(np.flatnonzero(np.flatnonzero(m.keep) == same_run[0].row)[0])
    x = m.x
    others = np.ones(len(m.z), dtype=bool)
    others[pos] = False
    a = np.linalg.pinv(x[others].T @ x[others])
    beta = a @ (x[others].T @ m.z[others])
    resid = m.z[others] - x[others] @ beta
    s = math.sqrt(float(resid @ resid) / max(int(others.sum()) - m.rank, 1))
    rows = moved_rows(m, same_run)
    se = s * np.sqrt(1.0 + np.einsum("kp,pq,kq->k", rows, a, rows))
    t = (m.z[pos] - rows @ beta) / se
    weight = np.array([_SLIP_PRIOR[abs(d.power)] / (2 * n_factors) for d in same_run])
    mass = weight * stats.norm.pdf(t) / se
    spread = float(np.ptp(m.z))
    k = int(np.argmax(mass))  # the slip that best explains the run, a priori simpler slips first
    t_recorded = float((m.z[pos] - x[pos] @ beta) / (s * math.sqrt(1.0 + x[pos] @ a @ x[pos])))
    return same_run[k], {"t_moved": float(t[k]), "t_recorded": t_recorded,
                         "bayes_factor": float(np.sum(mass)) * spread if spread > 0 else 0.0}
