"""Can the run order be believed?  The one decision whether level 1 tests drift.

A drift test asks whether the residuals trend with the order the runs were performed
in.  Published tables are often printed in another order: sorted by a response, or in
the design's standard (Yates) order.  In either the ``run`` column is no record of when
a run was made, and a trend with it is an artefact (sorted by the response, the run
number follows the noise; in standard order it is confounded with the design's
structure, so any misfit can pose as drift).  Drift is therefore tested only when the
order is declared as performed (``run_order: performed``, the default) *and* the
``run`` column neither follows a response (|Spearman rank correlation| at least
:data:`SORTED_CORRELATION`) nor reproduces a standard order of the design (rank
correlation at least :data:`STANDARD_ORDER_CORRELATION` with one of them).
"""

from __future__ import annotations

from dataclasses import dataclass
from itertools import permutations

import numpy as np
from scipy import stats

#: Values of the ``run_order`` config key and of ``--run-order``.
RUN_ORDERS = ("performed", "unknown")

#: |Spearman rank correlation| of the run column with a response from which the run column is
#: taken to be sorted by that response.  A random order of 13 runs reaches it with probability about 1e-5.
SORTED_CORRELATION = 0.9

#: Rank correlation with a standard order of the design (replicates of a point, e.g. the centre
#: runs, taken in run order) from which the run column is taken to be that order.  Higher than
#: :data:`SORTED_CORRELATION` because the largest over the candidate orders is taken: random orders of
#: a 2-factor CCD reach it with probability below 0.1 % (13 runs; 10 runs: about 0.1 %).
STANDARD_ORDER_CORRELATION = 0.95

#: Coded values closer to 0 than this are on the centre level of their factor.
_ZERO = 1e-6

#: Above this many factors only the table's column order (and its reverse) names the factors.
_ALL_PERMUTATIONS_UP_TO = 4


@dataclass(frozen=True)
class RunOrder:
    """Whether drift is tested, and if not why and what the user can supply."""

    declared: str
    drift_tested: bool
    reason: str  # "", "declared_unknown", "sorted_by_response", "standard_order"
    correlation: float | None = None  # the rank correlation behind the reason
    response: str | None = None  # the response the run column follows
    why: str = ""  # why drift is not tested and what to supply, without the verdict

    @property
    def message(self) -> str:
        return f"Drift was not tested: {self.why}" if self.why else ""

    def to_json(self) -> dict:
        return {"declared": self.declared, "drift_tested": self.drift_tested, "reason": self.reason or None,
                "rank_correlation": None if self.correlation is None else round(float(self.correlation), 6),
                "follows_response": self.response, "message": self.message}


def assess_run_order(runs, coded: np.ndarray, responses: dict[str, np.ndarray],
                     declared: str = "performed") -> RunOrder:
    """Decide whether the run column is the order the runs were performed in.

    ``runs`` are the run numbers (row order when the table has no ``run`` column), ``coded``
    the design points in coded units (centre at 0), ``responses`` each response's values on
    the same rows (NaN for failed runs).
    """
    if declared not in RUN_ORDERS:
        raise ValueError(f"run_order must be one of {', '.join(RUN_ORDERS)}, not {declared!r}")
    runs = np.asarray(runs, dtype=float)
    if declared == "unknown":
        return RunOrder(declared, False, "declared_unknown", why=(
            "the run order is declared unknown (run_order: unknown). To test it, supply "
            "the order the runs were performed in as the run column and declare it (run_order: performed)."))
    follows = _follows_response(runs, responses)
    if follows is not None:
        name, rho = follows
        return RunOrder(declared, False, "sorted_by_response", rho, name, why=(
            f"the run order looks sorted by {name} (Spearman rank correlation of run and "
            f"{name} {rho:+.2f}), so a trend with it would only repeat the response. Supply the order the runs "
            f"were performed in as the run column, or declare it unknown (run_order: unknown; --run-order unknown)."))
    rho = standard_order_correlation(runs, coded)
    if rho >= STANDARD_ORDER_CORRELATION:
        return RunOrder(declared, False, "standard_order", rho, why=(
            f"the run order reproduces the design's standard order (rank correlation "
            f"{rho:.2f}: factorial points in Yates order, then axial, then centre runs, or a similar systematic "
            f"order), which is how tables are printed, not how randomised runs are made; a trend with it would "
            f"be confounded with the design's structure. Supply the order the runs were performed in as the run "
            f"column, or declare it unknown (run_order: unknown; --run-order unknown)."))
    return RunOrder(declared, True, "")


def _follows_response(runs: np.ndarray, responses: dict[str, np.ndarray]) -> tuple[str, float] | None:
    """The response whose ranks the run column follows most closely (of equally close ones the first listed), if
    |rho| >= the threshold."""
    best = None
    for name, y in responses.items():
        y = np.asarray(y, dtype=float)
        ok = np.isfinite(y) & np.isfinite(runs)
        if ok.sum() < 4 or np.ptp(y[ok]) == 0 or np.ptp(runs[ok]) == 0:
            continue
        rho = float(stats.spearmanr(runs[ok], y[ok])[0])
        if abs(rho) >= SORTED_CORRELATION and (best is None or abs(rho) > abs(best[1])):
            best = (name, rho)
    return best


def standard_order_correlation(runs, coded: np.ndarray) -> float:
    """Largest |Spearman rank correlation| of the run numbers with a standard order of the design.

    Standard orders considered, for every naming of the factors (all orders up to four
    factors; the column order and its reverse beyond) and both level directions (low or
    high first): points grouped by how many factors sit off their centre level (factorial,
    then edge points, then axial, with the centre runs last or first), within a group by
    which factors are off centre (first factor first), then in Yates order (first factor
    varying fastest); and the plain Yates order of all points (3^k factorials).
    """
    runs = np.asarray(runs, dtype=float)
    coded = np.round(np.asarray(coded, dtype=float), 6)
    n, d = coded.shape
    if n < 4 or np.ptp(runs) == 0:
        return 0.0
    run_rank = stats.rankdata(runs)
    orders = (permutations(range(d)) if d <= _ALL_PERMUTATIONS_UP_TO
              else [tuple(range(d)), tuple(reversed(range(d)))])
    best = 0.0
    for perm in orders:
        for sign in (1.0, -1.0):
            v = sign * coded[:, list(perm)]
            for key in _standard_keys(v):
                # replicates listed in run order (forwards) or against it (a table printed backwards)
                best = max(best, _rank_correlation(run_rank, _ranks(key, run_rank)),
                           -_rank_correlation(run_rank, _ranks(key, -run_rank)))
                if best >= 1.0 - 1e-12:
                    return best
    return best


def _standard_keys(v: np.ndarray):
    """Sort keys (columns, primary first) of the standard orders for one naming and direction."""
    off = np.abs(v) > _ZERO
    count = off.sum(axis=1)
    yates = [v[:, j] for j in reversed(range(v.shape[1]))]  # last factor slowest: first varies fastest
    which = [-off[:, j].astype(float) for j in range(v.shape[1])]
    centre_last = -count.astype(float)
    centre_first = np.where(count == 0, -np.inf, -count.astype(float))
    yield np.column_stack([centre_last, *which, *yates])
    yield np.column_stack([centre_first, *which, *yates])
    yield np.column_stack(yates)


def _ranks(key: np.ndarray, run_rank: np.ndarray) -> np.ndarray:
    """Ranks of the rows of ``key`` in lexicographic order (first column primary); replicates of a
    point (equal keys) in run order, as a table in standard order lists them."""
    rows = np.column_stack([key, run_rank])
    order = np.lexsort(rows.T[::-1])  # first column primary
    ordered = rows[order]
    new_row = np.ones(len(rows), dtype=bool)  # equal rows share a rank
    new_row[1:] = np.any(ordered[1:] != ordered[:-1], axis=1)
    ranks = np.empty(len(rows))
    ranks[order] = np.cumsum(new_row) - 1
    return ranks


def _rank_correlation(a: np.ndarray, b: np.ndarray) -> float:
    """Pearson correlation of two rankings of the same runs, neither constant: ``a`` the run numbers' ranks (not
    all equal: standard_order_correlation returns 0.0 first), ``b`` a ranking by key and run rank, whose last
    column breaks every tie between runs of different rank."""
    return float(np.corrcoef(a, b)[0, 1])
