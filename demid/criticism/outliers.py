"""The outlier member of the criticism's family: each run's externally studentised residual, and the largest
|t| of each simulated null table, a block of null draws at a time so that memory stays linear in the runs."""

from __future__ import annotations

import numpy as np
from scipy import stats

from ..design import LEVERAGE_UNPREDICTABLE


def outlier_stats(e: np.ndarray, hat: np.ndarray, df: int):
    """Externally studentised residuals t (n, B) of residuals e (n, B)."""
    ok = hat < LEVERAGE_UNPREDICTABLE  # the others cannot tell such a run's value (rounded levels suffice)
    h = np.where(ok, hat, 0.0)[:, None]
    sse = np.sum(e * e, axis=0)
    with np.errstate(divide="ignore", invalid="ignore"):
        s2 = (sse - e ** 2 / (1 - h)) / (df - 1)
        t = e / np.sqrt(np.maximum(s2, 1e-300) * (1 - h))
    t[~ok] = 0.0
    return t


#: Cells (runs x null draws) of the outlier statistics held at once: each of its temporaries stays small
#: enough to be reused instead of mapped afresh (at 10,000 runs x 2,000 draws a whole temporary is 160 MB).
OUTLIER_CELLS = 2 ** 20


def outlier_null_max(e: np.ndarray, hat: np.ndarray, df: int) -> np.ndarray:
    """Largest |t| (B,) of each column of e (n, B), a block of columns at a time (the same numbers)."""
    width = max(1, OUTLIER_CELLS // len(e))  # a round has runs to spare (Round tests from 3 residual df on)
    return np.concatenate([np.max(np.abs(outlier_stats(e[:, j:j + width], hat, df)), axis=0)
                           for j in range(0, e.shape[1], width)])


def outlier_logp(tmax, n, df):
    return np.minimum(0.0, np.log(2.0 * n) + stats.t.logsf(tmax, df - 1))
