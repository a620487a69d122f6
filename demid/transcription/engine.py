"""The refit engine: every hypothesis of a table's design evaluated at once.

A response cell enters the fit linearly, so all response hypotheses are columns of one
matrix and are evaluated from the pseudo-inverse, the hat matrix and the replicate-group
projection; factor repairs that land on a design level are refitted in one batched SVD.
"""

from __future__ import annotations

from itertools import combinations
from typing import TYPE_CHECKING

import numpy as np
import pandas as pd

from ..design import LEVERAGE_ONE, model_matrix, nominal_levels, replicate_groups, replicate_keys
from ..formulas import f_tail
from ..errors import InputError
from .printed import _jsonable

if TYPE_CHECKING:
    from ..design import Coding, Term


_ALPHA_SLACK = 3e-4  # coded units: a table printed from alpha = 1.41421 against a declared 1.414

#: Up to this many runs pure error is the projection on the replicate groups (an n x n matrix); above it, the
#: deviations from each group's mean (the same value to round-off, without 800 MB at 10,000 runs).
_PROJECTION_RUNS = 256


def _group_deviations_ss(y: np.ndarray, groups: np.ndarray) -> np.ndarray:
    """Sum of squared deviations of each column of y (n, m) from its replicate group's mean."""
    size = np.bincount(groups)
    means = np.zeros((len(size), y.shape[1]))
    np.add.at(means, groups, y)
    means /= size[:, None]
    return np.sum((y - means[groups]) ** 2, axis=0)


# --------------------------------------------------------------------------- fitting engine
def _coded_to_actual_matrix(coding: Coding, terms: list[Term]) -> np.ndarray:
    """beta_actual = M @ beta_coded; same construction as SurrogateFit._coded_to_actual_matrix."""
    k = len(coding.factors)
    degree = max(max(t) for t in terms) if terms else 0
    levels = np.linspace(-1, 1, degree + 1)
    pts = np.array(np.meshgrid(*[levels] * k, indexing="ij")).reshape(k, -1).T
    return np.linalg.lstsq(model_matrix(coding.to_actual(pts), terms), model_matrix(pts, terms), rcond=None)[0]


def lack_of_fit_p(out: dict[str, np.ndarray]) -> dict[str, np.ndarray]:
    """``out`` with the lack-of-fit p-value (``lof_p``, NaN where the F is not finite) from its F and degrees
    of freedom."""
    lof_f = np.asarray(out["lof_f"], dtype=float)
    lof_p = np.full(lof_f.shape, np.nan)
    ok = np.isfinite(lof_f)
    if ok.any():
        lof_p[ok] = f_tail(lof_f[ok], out["_df_lof"][ok], out["_df_pe"][ok])
    out["lof_p"] = lof_p
    return out


def _statistics(sse, sst, press, ss_pe, n, p, rank, df_pe) -> dict[str, np.ndarray]:
    """The published statistics from the sums of squares; arrays over hypotheses, definitions as in
    :meth:`demid.surrogate.SurrogateFit.statistics` and :meth:`~demid.surrogate.SurrogateFit.anova`."""
    sse, sst, press, ss_pe = np.broadcast_arrays(*(np.asarray(a, dtype=float) for a in (sse, sst, press, ss_pe)))
    n = np.broadcast_to(n, sse.shape)
    df_res = n - np.broadcast_to(rank, sse.shape)
    df_pe = np.broadcast_to(df_pe, sse.shape)
    df_lof = df_res - df_pe
    with np.errstate(divide="ignore", invalid="ignore"):
        sst_ok = sst > 0
        has_df = n > p
        return {
            "r2": np.where(sst_ok, 1.0 - sse / sst, np.nan),
            "adj_r2": np.where(sst_ok & has_df, 1.0 - (sse / (n - p)) / (sst / (n - 1)), np.nan),
            "rmse": np.sqrt(sse / n),
            "resid_std": np.where(has_df, np.sqrt(sse / (n - p)), np.nan),
            "q2": np.where(sst_ok, 1.0 - press / sst, np.nan),
            "ss_model": sst - sse, "ss_residual": sse, "ss_lof": sse - ss_pe,
            "ss_pure_error": ss_pe, "ss_total": sst,
            "lof_f": np.where((df_lof > 0) & (df_pe > 0) & (ss_pe > 0),
                              ((sse - ss_pe) / df_lof) / (ss_pe / df_pe), np.nan),
            # lof_p is filled in by lack_of_fit_p, in one vectorised call over all hypotheses.
            "_df_lof": df_lof.astype(float), "_df_pe": df_pe.astype(float),
            "_n": n.astype(float), "_df_model_resid": (n - p).astype(float),
        }


def _add_coefficients(out: dict, beta: np.ndarray, to_actual: list | np.ndarray | None,
                      coefficients: dict[str, tuple[str, int]]) -> dict:
    """beta: (p, m) coded coefficients; to_actual: (p, p) map or one per hypothesis."""
    if not coefficients:
        return out
    actual = None
    if any(units == "actual" for units, _ in coefficients.values()):
        if isinstance(to_actual, np.ndarray):
            actual = to_actual @ beta
        else:
            actual = np.stack([m @ beta[:, i] for i, m in enumerate(to_actual)], axis=1)
    for key, (units, index) in coefficients.items():
        out[key] = (beta if units == "coded" else actual)[index]
    return out


class DesignFit:
    """One design (factor settings) and everything the statistics need about it.

    ``evaluate(Y)`` returns the statistics for every column of ``Y`` (responses
    on this design) at once: the fit is linear in y, so residuals, PRESS
    residuals, pure-error deviations and coefficients are matrix products with
    the pseudo-inverse, the hat matrix and the replicate-group projection.
    """

    def __init__(self, coded: np.ndarray, terms: list[Term], coding: Coding, need_actual: bool):
        x = model_matrix(coded, terms)
        n, p = x.shape
        u, s, vt = np.linalg.svd(x, full_matrices=False)
        tol = (s.max() if s.size else 0.0) * max(n, p) * np.finfo(float).eps  # numpy.linalg.matrix_rank's
        rank = int(np.sum(s > tol))
        self.x = x
        self.pinv = vt[:rank].T @ (u[:, :rank].T / s[:rank, None])
        self.hat = np.sum(u[:, :rank] ** 2, axis=1)
        # at least one run: check_transcription, the one caller, refuses a table without a response value
        groups = replicate_groups(coded)
        n_groups = int(groups.max()) + 1
        self.groups = groups
        self.group_mean = None
        if n <= _PROJECTION_RUNS:
            onehot = np.zeros((n, n_groups))  # runs x groups: as large as n x n without replicates
            onehot[np.arange(n), groups] = 1.0
            self.group_mean = onehot @ (onehot.T / onehot.sum(axis=0)[:, None])
        self.n, self.p, self.rank = n, p, rank
        self.df_pe = n - n_groups
        self.to_actual = _coded_to_actual_matrix(coding, terms) if need_actual else None

    def evaluate(self, y: np.ndarray, coefficients: dict[str, tuple[str, int]]) -> dict[str, np.ndarray]:
        y = np.asarray(y, dtype=float)
        beta = self.pinv @ y
        resid = y - self.x @ beta
        sse = np.sum(resid ** 2, axis=0)
        sst = np.sum((y - y.mean(axis=0)) ** 2, axis=0)
        if self.group_mean is None:
            ss_pe = _group_deviations_ss(y, self.groups)
        else:
            ss_pe = np.sum((y - self.group_mean @ y) ** 2, axis=0)
        if np.all(self.hat < LEVERAGE_ONE):
            press = np.sum((resid / (1.0 - self.hat)[:, None]) ** 2, axis=0)
        else:
            press = np.full(sse.shape, np.nan)
        out = _statistics(sse, sst, press, ss_pe, self.n, self.p, self.rank, self.df_pe)
        return _add_coefficients(out, beta, self.to_actual, coefficients)


def evaluate_designs(coded: np.ndarray, y: np.ndarray, terms: list[Term], to_actual: list | None,
                     coefficients: dict[str, tuple[str, int]]) -> dict[str, np.ndarray]:
    """Statistics of one response ``y`` (n,) on many designs ``coded`` (m, n, k), in one batched SVD."""
    m, n, _ = coded.shape
    x = np.stack([model_matrix(c, terms) for c in coded])
    p = x.shape[2]
    u, s, vt = np.linalg.svd(x, full_matrices=False)
    keep = s > s.max(axis=1, keepdims=True) * max(n, p) * np.finfo(float).eps
    rank = keep.sum(axis=1)
    u = u * keep[:, None, :]
    uty = np.einsum("mnq,n->mq", u, y)
    with np.errstate(divide="ignore"):
        s_inv = np.where(keep, 1.0 / s, 0.0)
    beta = np.einsum("mqp,mq->pm", vt, s_inv * uty)
    resid = y[None, :] - np.einsum("mnq,mq->mn", u, uty)
    hat = np.sum(u ** 2, axis=2)
    sse = np.sum(resid ** 2, axis=1)
    sst = np.full(m, np.sum((y - y.mean()) ** 2))
    with np.errstate(divide="ignore", invalid="ignore"):
        press = np.where(np.all(hat < LEVERAGE_ONE, axis=1), np.sum((resid / (1.0 - hat)) ** 2, axis=1), np.nan)
    # Replicates: the rule of demid.design.replicate_groups, for a batch of designs at once.
    if n <= _PROJECTION_RUNS:
        keys = replicate_keys(coded)
        same = np.all(keys[:, :, None, :] == keys[:, None, :, :], axis=3)
        size = same.sum(axis=2)
        ss_pe = np.sum((y[None, :] - (same @ y) / size) ** 2, axis=1)
        df_pe = n - np.rint(np.sum(1.0 / size, axis=1)).astype(int)
    else:  # one design at a time: the batch's (m, n, n) comparison would grow as runs squared times designs
        groups = [replicate_groups(c) for c in coded]
        ss_pe = np.array([_group_deviations_ss(y[:, None], g)[0] for g in groups])
        df_pe = np.array([n - (int(g.max()) + 1) for g in groups])
    out = _statistics(sse, sst, press, ss_pe, n, p, rank, df_pe)
    return _add_coefficients(out, beta, to_actual, coefficients)


# --------------------------------------------------------------------------- design levels
def _estimate_coding(column: np.ndarray, nominal: np.ndarray, alpha: float, decimals: int) -> tuple[float, float]:
    """(centre, unit) that puts the most cells of a factor column on the nominal coded levels.

    Starts from the table's mid-range coding (Coding.from_levels) and tries every
    pair of distinct values on every pair of levels, so that one mistyped extreme
    does not shift the levels a repair may take.  A cell is on a level when it is
    within its printing precision (``decimals``) of it, plus ``_ALPHA_SLACK``;
    among codings with equally many cells on levels, the smallest squared
    deviation wins, then the mid-range coding.
    """
    lo, hi = float(column.min()), float(column.max())
    default = ((lo + hi) / 2, (hi - lo) / (2 * alpha) if hi > lo else 1.0)
    distinct = np.unique(column)
    if len(nominal) < 2 or len(distinct) < 2 or len(distinct) > 15:
        return default
    options = [default]
    for (ua, ub), (la, lb) in ((u, lv) for u in combinations(distinct, 2) for lv in combinations(nominal, 2)):
        unit = (ub - ua) / (lb - la)
        options.append((ua - la * unit, unit))
    centre = np.array([o[0] for o in options])[:, None]
    unit = np.array([o[1] for o in options])[:, None]
    coded = (column[None, :] - centre) / unit
    deviation = np.min(np.abs(coded[:, :, None] - nominal[None, None, :]), axis=2)
    hit = deviation <= 0.5 * 10.0 ** (-decimals) / np.abs(unit) + _ALPHA_SLACK
    hits = hit.sum(axis=1)
    spread = np.where(hit, deviation ** 2, 0.0).sum(axis=1)
    best = int(np.lexsort((np.arange(len(options)), np.round(spread, 12), -hits))[0])
    return float(centre[best, 0]), float(unit[best, 0])


def _design_levels(column: np.ndarray, design_type: str, alpha: float, decimals: int,
                   fixed: tuple[float, float] | None) -> tuple[np.ndarray, float]:
    """Nominal levels of the declared design for one factor column (model units), and its unit."""
    nominal = nominal_levels(design_type, alpha)
    centre, unit = fixed if fixed is not None else _estimate_coding(column, nominal, alpha, decimals)
    return centre + unit * nominal, abs(unit)


def _levels_for_cell(column: np.ndarray, row: int, nominal: np.ndarray, tolerance: float):
    """Values a cell may be repaired to: (exact, approximate) levels.

    A nominal level that another cell of the column prints is only reachable as
    exactly that printed value; a nominal level no other cell shows (an axial
    point, say) is reachable within ``tolerance``.  Values the other cells repeat
    are exact levels too (designs off the nominal grid).
    """
    others = np.delete(column, row)
    exact, loose = [], []
    for level in nominal:
        near = others[np.abs(others - level) <= tolerance]
        if near.size:
            values, counts = np.unique(near, return_counts=True)
            exact.append(values[np.argmax(counts)])
        else:
            loose.append(level)
    values, counts = np.unique(others, return_counts=True)
    exact.extend(values[counts >= 2])
    return np.unique(np.array(exact, dtype=float)), np.array(loose, dtype=float)


def _runs(table: pd.DataFrame) -> list:
    if "run" in table.columns:
        return [_jsonable(v) for v in table["run"].tolist()]
    return list(range(1, len(table) + 1))


def _numeric(table: pd.DataFrame, columns: list[str], source: str) -> np.ndarray:
    out = np.empty((len(table), len(columns)))
    for j, name in enumerate(columns):
        values = pd.to_numeric(table[name], errors="coerce").to_numpy(dtype=float)
        bad = np.flatnonzero(np.isnan(values) & table[name].notna().to_numpy())
        if bad.size:
            raise InputError(f"not a number: {table[name].iloc[bad[0]]!r}", source=source,
                             run=_runs(table)[bad[0]], column=name)
        out[:, j] = values
    return out
