"""Causes the runs cannot tell apart, and the runs that would decide between them.

When two or more catalogue causes explain the misfit about equally well, naming one of them is a guess.
"About equally" is measured by the AICc of their one-parameter extensions: within
:data:`AMBIGUOUS_AICC` of the best, the Akaike weights of the two are no further apart than e (2.7:1),
so the runs give no real preference (Burnham & Anderson's rule of thumb: models within 2 have
substantial support).  The verdict is then ``ambiguous`` with the candidates, and up to
:data:`MAX_RUNS` new runs are proposed where the candidates' predictions differ most relative to
their prediction error (the T-optimal / Box-Hill criterion for discriminating between models): each
new run made after the existing ones (so a drift or a step continues, an outlier does not recur).
"""

from __future__ import annotations

import math
from itertools import combinations, product
from typing import TYPE_CHECKING

import numpy as np
from scipy import stats

from .models import _inv_boxcox, _num, _run_value

if TYPE_CHECKING:
    from .models import _Data, _Model

#: Candidates whose extensions' AICc lie within this of the best are not told apart by the runs.
AMBIGUOUS_AICC = 2.0

#: At most this many discriminating runs are proposed.
MAX_RUNS = 4

#: Summed squared standardised separation the proposed runs aim for: a difference of means found by a
#: two-sided 5 % test with 80 % power, (z_0.975 + z_0.8)^2.
TARGET_SEPARATION = float((stats.norm.ppf(0.975) + stats.norm.ppf(0.8)) ** 2)

PURPOSE = "decide between causes"

#: Causes of one run: an outlier and a slipped factor value of the same run are one candidate.
_ONE_RUN = ("outlier", "factor_level")

#: A drift and a step both say the response changed with run order: they are one candidate kind, and
#: between them the better fit is named (the step paying for its change-point, level1.step_price).  Kept
#: apart, a 14-SD drift over 13 runs that happens to fit a step at run 9 as well was reported ambiguous
#: (tests/criticism/test_criticism.py); the message of either says what changed and suggests a block column.
_RUN_ORDER = ("drift", "step")


def candidate_kind(cause: str, detail) -> tuple:
    if cause in _ONE_RUN:
        return ("one run", str(detail))
    return ("run order",) if cause in _RUN_ORDER else (cause,)


def close_candidates(entries: list[dict]) -> list[dict]:
    """Candidates (dicts with cause, detail, aicc) within AMBIGUOUS_AICC of the best, one per kind, best
    first; a single candidate when one stands out."""
    ranked = sorted((e for e in entries if e.get("aicc") is not None and math.isfinite(e["aicc"])),
                    key=lambda e: e["aicc"])
    if not ranked:
        return []
    best = ranked[0]["aicc"]
    out, kinds = [], set()
    for e in ranked:
        kind = candidate_kind(e["cause"], e["detail"])
        if e["aicc"] - best <= AMBIGUOUS_AICC and kind not in kinds:
            kinds.add(kind)
            out.append(e)
    return out


def _grid(data: _Data) -> np.ndarray:
    """Candidate points in coded units: the design's levels (-alpha, -1, 0, 1, alpha) in every factor,
    within the design's reach (no farther from the centre than its farthest run)."""
    levels = sorted({-data.alpha, -1.0, 0.0, 1.0, data.alpha})
    pts = np.array(list(product(levels, repeat=len(data.factors))), dtype=float)
    reach = float(np.max(np.linalg.norm(data.coded, axis=1))) + 1e-9
    return pts[np.linalg.norm(pts, axis=1) <= reach]


def _prediction(model: _Model, points: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Mean and variance of a new run's response at the points under the model (original scale; a
    transform by the delta method; unequal scatter at the points' covariate)."""
    rows = model.new_run_row(points)
    xtx_inv = np.linalg.pinv(model.xw.T @ model.xw)
    eta = rows @ model.beta
    sigma2 = model.ssr / max(model.df_resid, 1)
    var_eta = sigma2 * np.einsum("ij,jk,ik->i", rows, xtx_inv, rows)
    spec = model.spec
    noise = np.full(len(points), sigma2)
    if spec.weight_on is not None and spec.weight_on in model.data.factors:
        v = points[:, model.data.factors.index(spec.weight_on)] / model.data.alpha
        noise = sigma2 * np.exp(spec.weight_gamma * v)
    mean = _inv_boxcox(eta, spec.lam)
    var = var_eta + noise
    if spec.lam is not None:
        slope = np.abs(_inv_boxcox(eta + 1e-6, spec.lam) - _inv_boxcox(eta - 1e-6, spec.lam)) / 2e-6
        var = var * slope ** 2
    return mean, var


def discriminating_runs(data: _Data, models: list[_Model], labels: list[str]) -> list[dict]:
    """Up to MAX_RUNS points where the candidate models' predictions differ most relative to their
    prediction error (maximin over pairs of the standardised squared difference), fewest first: the
    runs stop once their summed separation of every pair reaches TARGET_SEPARATION."""
    if len(models) < 2:
        return []
    points = _grid(data)
    preds = [_prediction(m, points) for m in models]
    pairs = list(combinations(range(len(models)), 2))
    sep = np.column_stack([(preds[a][0] - preds[b][0]) ** 2 / np.maximum(preds[a][1] + preds[b][1], 1e-300)
                           for a, b in pairs])  # (points, pairs)
    chosen: list[int] = []
    total = np.zeros(len(pairs))
    for _ in range(MAX_RUNS):
        gain = np.min(total[None, :] + sep, axis=1)
        # a point already chosen may be chosen again (a replicate), but a new point is preferred on ties
        order = np.lexsort((np.isin(np.arange(len(points)), chosen), -np.round(gain, 9)))
        best = int(order[0])
        chosen.append(best)
        total = total + sep[best]
        if np.min(total) >= TARGET_SEPARATION:
            break
    out = []
    for i in chosen:
        run = data.point_dict(points[i])
        run["purpose"] = PURPOSE
        run["expected"] = {label: _num(p[0][i]) for label, p in zip(labels, preds)}
        run["separation"] = _num(float(np.min(sep[i])))
        out.append(run)
    return out


def candidate_label(cause: str, detail) -> str:
    return f"{cause} ({_run_value(detail) if not isinstance(detail, str) else detail})"
