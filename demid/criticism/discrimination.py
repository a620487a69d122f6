"""Causes the runs cannot tell apart, and the runs that would decide between them.

When two or more catalogue causes explain the misfit about equally well, naming one of them is a guess.
Every cause of the first round is fitted as its extension of the quadratic (a step at every change-point),
paying 2 log C in AICc for the place it was chosen from among C.  The cause the tests point at is named
only when its extension's AICc leads the best one of every other kind by :data:`AMBIGUOUS_AICC` (6: an
evidence ratio exp(6/2) = 20:1, "strong" evidence on Kass & Raftery's scale of 2 log B, where 2-6 is only
"positive"; Burnham & Anderson: models within 4-7 of the best have considerably less support, not none).
Otherwise the verdict is ``ambiguous`` with the candidates -- the named cause and every kind within the
margin of it or fitted better -- and up to :data:`MAX_RUNS` new runs are proposed where the candidates'
predictions differ most relative to their prediction error (the T-optimal / Box-Hill criterion for
discriminating between models, the runs judged together: their estimation errors are shared; as in Box and
Hill's entropy criterion the spread of the predictions counts as well as their means, so that unequal scatter
is told from a wild run by replicates where the scatters differ), each new
run made after the existing ones (so a drift goes on, a step stays, an outlier does not recur), until the
separation is large enough to move the candidates' AICc apart by the margin with 80 % power.

In benchmarks/decide_causes.py (360 tables, seeds 0-19, n_null 199) strict wrong causes on catalogue defects
were 0.062 with margins of 2 and 4, 0.050 with 6 (the true cause among the candidates instead), and the
proposed runs named the truth after an ambiguous or wrong first verdict in 0.26 (2: no better than as many
random runs), 0.39 (4) and 0.47 (6) of the tables; at n_null 499, with the runs judged together and
confirming runs, 0.046 and 0.594 (random 0.406).  Counting the spread of the predictions (n_null 199): first
verdicts unchanged, named after the proposed runs 0.556 -> 0.611 (two log responses level with a cubic term and
one unequal scatter decided; one outlier no longer), right names still right after confirming runs 0.82 -> 0.91.
Each run chosen for the progress it makes towards every pair's target, capped at the target and summed over the
pairs (pair_progress), not for the least-separated pair's (the maximin): see benchmarks/decide_causes.py.
"""

from __future__ import annotations

import math
from itertools import combinations, product
from typing import TYPE_CHECKING

import numpy as np
from scipy import stats

from .. import run_purposes
from ..design import model_matrix
from .models import inv_boxcox, json_number, run_label

if TYPE_CHECKING:
    from .models import Data, Model

#: A cause is named only when its extension's AICc leads every rival kind's by this (see the module text).
AMBIGUOUS_AICC = 6.0

#: A cause named with a rival of another kind whose extension's AICc is within this of its own is named
#: with runs that would confirm it against the rival: a lead below 10 (evidence ratio 150:1) is "strong"
#: but not "very strong" on Kass & Raftery's scale, and a misnamed cause can only be corrected by runs
#: that separate it from the truth.  A cause with no rival that close is confirmed against the nearest kind
#: (naming.confirming_rivals): in benchmarks/decide_causes.py eight of the 32 tables misnamed or ambiguous first
#: (seeds 0-19) were misnamed by a margin of 10-35 and got no runs at all.
CONFIRM_AICC = 10.0

CONFIRM_PURPOSE = run_purposes.CONFIRM

#: At most this many discriminating runs are proposed.
MAX_RUNS = 4

#: Power with which the proposed runs should decide between two candidates.
DECIDING_POWER = 0.8


def target_separation(gap: float = 0.0) -> float:
    """Summed squared standardised separation d^2 two candidates' predictions need at the new runs so that,
    with probability DECIDING_POWER, the runs move their AICc apart by AMBIGUOUS_AICC beyond the ``gap`` the
    favoured one may already lead by: under the other candidate the new runs add d^2 + 2 d Z (Z standard
    normal) to the favoured one's -2 log-likelihood, so d^2 - 2 z_power d = AMBIGUOUS_AICC + gap."""
    z = float(stats.norm.ppf(DECIDING_POWER))
    d = z + math.sqrt(z * z + AMBIGUOUS_AICC + max(gap, 0.0))
    return d * d


PURPOSE = run_purposes.DECIDE

#: Causes of one run: an outlier and a slipped factor value of the same run are one candidate.
_ONE_RUN = ("outlier", "factor_level")

#: A drift and a step both say the response changed with run order, but they differ in what later runs give
#: (a drift goes on, a step stays): they are candidates of different kinds, and so are steps at different
#: change-points (a replicate of a run between them, made later, tells which side of the step it was on).
#: Each pays for its choice (a step among its change-points, extensions.step_price) before they are compared.


def candidate_kind(cause: str, detail) -> tuple:
    """The kind a cause counts as when candidates are compared: one per run for a shifted run or slipped value,
    one per change-point for a step."""
    if cause in _ONE_RUN:
        return ("one run", str(detail))
    return ("step", str(detail)) if cause == "step" else (cause,)


def close_candidates(entries: list[dict], named: tuple | None = None, margin: float | None = None) -> list[dict]:
    """Candidates (dicts with cause, detail, aicc) the runs do not tell apart from the named cause, one per
    kind, best first; a single candidate when it stands out.

    Without ``named``: every kind whose best extension lies within AMBIGUOUS_AICC of the best one.  With
    ``named`` (cause, detail): the named cause and every kind whose best extension is better than the named
    one's or within AMBIGUOUS_AICC of it -- a cause picked by the strongest test but fitted worse than a
    rival is not named over it.  ``margin`` replaces AMBIGUOUS_AICC."""
    ranked = sorted((e for e in entries if e.get("aicc") is not None and math.isfinite(e["aicc"])),
                    key=lambda e: e["aicc"])
    if not ranked:
        return []
    anchor = ranked[0]
    if named is not None:
        anchor = next((e for e in ranked if (e["cause"], e["detail"]) == tuple(named)), None)
        if anchor is None:
            return []
    margin = AMBIGUOUS_AICC if margin is None else margin
    out, kinds = [], set()
    for e in ranked:
        kind = candidate_kind(e["cause"], e["detail"])
        if kind in kinds:
            continue
        kinds.add(kind)
        if e["aicc"] - anchor["aicc"] <= margin:  # the anchor too: its own difference is 0
            out.append(e)
    if named is not None and anchor not in out:  # another entry of its kind was better: the named one leads
        out = [anchor] + [e for e in out if candidate_kind(e["cause"], e["detail"])
                          != candidate_kind(anchor["cause"], anchor["detail"])]
        out.sort(key=lambda e: e["aicc"])
    return out


def candidate_grid(data: Data) -> np.ndarray:
    """Candidate points in coded units: the data's own (a next wave's box grid) when it has them, else the
    design's levels (-alpha, -1, 0, 1, alpha) in every factor, within the design's reach (no farther from
    the centre than its farthest run)."""
    if data.run_candidates is not None:
        return np.asarray(data.run_candidates, dtype=float)
    levels = sorted({-data.alpha, -1.0, 0.0, 1.0, data.alpha})
    pts = np.array(list(product(levels, repeat=len(data.factors))), dtype=float)
    reach = float(np.max(np.linalg.norm(data.coded, axis=1))) + 1e-9
    return pts[np.linalg.norm(pts, axis=1) <= reach]


def prediction_parts(model: Model, points: np.ndarray, later: int = 1) -> tuple:
    """A new run's response at the points under the model, the run made ``later`` runs after the last one:
    (mean, jac, noise, param_cov) with the prediction's covariance over several runs
    jac param_cov jac' + diag(noise) -- the estimation error is shared by every run (a replicate does not
    average it away), the run's own scatter is not (original scale; a transform by the delta method;
    unequal scatter at the points' covariate)."""
    rows = model.new_run_row(points, later)
    eta = rows @ model.beta
    sigma2 = model.ssr / max(model.df_resid, 1)
    param_cov = sigma2 * np.linalg.pinv(model.xw.T @ model.xw)
    spec = model.spec
    noise = np.full(len(points), sigma2)
    if spec.weight_on is not None:
        noise = sigma2 * np.exp(spec.weight_gamma * _scatter_covariate(model, points))
    mean = inv_boxcox(eta, spec.lam)
    slope = np.ones(len(points))
    if spec.lam is not None:
        slope = np.abs(inv_boxcox(eta + 1e-6, spec.lam) - inv_boxcox(eta - 1e-6, spec.lam)) / 2e-6
    return mean, rows * slope[:, None], noise * slope ** 2, param_cov


def _scatter_covariate(model: Model, points: np.ndarray) -> np.ndarray:
    """The covariate unequal scatter follows, at the points: a factor scaled by the axial distance, or the
    predicted value, rescaled.  The latter is the unweighted fit's prediction (blocks at their average),
    so its value at a new point is that fit's, its coefficients recovered exactly from the runs' values."""
    data, spec = model.data, model.spec
    if spec.weight_on in data.factors:
        return points[:, data.factors.index(spec.weight_on)] / data.alpha
    x = model_matrix(data.coded, model.mean_terms)
    if data.blocks is not None:
        x = np.column_stack([x, data.blocks])
    coef = np.linalg.lstsq(x, np.asarray(spec.weight_values, dtype=float), rcond=None)[0]
    return model_matrix(points, model.mean_terms) @ coef[:len(model.mean_terms)]


def new_run_prediction(model: Model, points: np.ndarray, later: int = 1) -> tuple[np.ndarray, np.ndarray]:
    """Mean and variance of one new run's response at each of the points (see prediction_parts)."""
    mean, jac, noise, cov = prediction_parts(model, points, later)
    return mean, np.einsum("ij,jk,ik->i", jac, cov, jac) + noise


def joint_separation(chosen_a: list, chosen_b: list, parts_a: tuple, parts_b: tuple) -> np.ndarray:
    """delta' (S_a + S_b)^-1 delta of the chosen runs together with each candidate point (one value per
    point): the squared Mahalanobis distance between two models' predictions of the runs, their estimation
    errors correlated across the runs; plus the part their spreads S_a, S_b make (spread_separation).  chosen_*: (mean, jac row, noise) of each run chosen so far; parts_*:
    (mean, jac, noise, param_cov) at every point."""
    n_points = len(parts_a[0])

    def stacked(chosen, parts):
        mean, jac, noise, cov = parts
        means = np.column_stack([np.full(n_points, c[0]) for c in chosen] + [mean])  # (P, m)
        jacs = np.stack([np.broadcast_to(c[1], jac.shape) for c in chosen] + [jac], axis=1)  # (P, m, p)
        noises = np.column_stack([np.full(n_points, c[2]) for c in chosen] + [noise])
        covs = np.einsum("qij,jk,qlk->qil", jacs, cov, jacs)
        covs[:, np.arange(noises.shape[1]), np.arange(noises.shape[1])] += noises
        return means, covs

    mean_a, cov_a = stacked(chosen_a, parts_a)
    mean_b, cov_b = stacked(chosen_b, parts_b)
    delta = mean_a - mean_b
    total = cov_a + cov_b
    total[:, np.arange(delta.shape[1]), np.arange(delta.shape[1])] += 1e-300
    return np.einsum("qi,qi->q", delta, np.linalg.solve(total, delta[:, :, None])[:, :, 0]) \
        + spread_separation(cov_a, cov_b)


def spread_separation(cov_a: np.ndarray, cov_b: np.ndarray) -> np.ndarray:
    """The part of the separation that comes from the spread of two models' predictions, not their means:
    the symmetrised Kullback-Leibler divergence of N(0, S_a) and N(0, S_b), (tr(S_a^-1 S_b + S_b^-1 S_a) - 2m)/4
    for m runs (stacked (P, m, m)), on the scale of the mean part (which is the symmetrised divergence of their
    means when S_a = S_b).  Box & Hill's entropy criterion counts both: unequal scatter and a wild run differ
    mainly in what replicates at the noisy end give (wide scatter again, or the surface), not in their mean."""
    m = cov_a.shape[-1]
    ab = np.trace(np.linalg.solve(cov_a, cov_b), axis1=-2, axis2=-1)
    ba = np.trace(np.linalg.solve(cov_b, cov_a), axis1=-2, axis2=-1)
    return np.maximum((ab + ba - 2 * m) / 4.0, 0.0)


def pair_progress(progress: np.ndarray) -> np.ndarray:
    """How far the runs with each candidate point take the pairs towards deciding them (points, pairs): each
    pair's separation over its target, capped at 1 (beyond its target a pair is decided, more separation buys
    nothing), summed over the pairs; the least-separated pair breaks ties.  Not the maximin over pairs of
    T-optimal designs for several models: where no one point separates every pair (steps at three change-points
    differ each in the side of one run; a replicate of that run separates one pair and not the others) the
    maximin spends the runs where every pair differs a little and decides none of them."""
    return np.sum(np.minimum(progress, 1.0), axis=1) + 1e-3 * np.min(progress, axis=1)


def discriminating_runs(data: Data, models: list[Model], labels: list[str],
                        aiccs: list[float] | None = None, kinds: list | None = None,
                        purpose: str = PURPOSE) -> list[dict]:
    """Up to MAX_RUNS points where the candidate models' predictions differ most relative to their
    prediction error (T-optimal / Box-Hill: the squared Mahalanobis distance between two models' predictions of
    the runs together, plus the divergence of their spreads, over its target, capped and summed over the pairs:
    pair_progress), fewest first: the runs stop once the separation of every pair
    reaches its target_separation (the pair's AICc gap ``aiccs`` included: either may be the truth).  Models
    of one ``kinds`` entry (terms aliased on these runs) are separated from the other kinds' models, not
    from each other.  The i-th run is predicted as made i runs after the last one (a drift has gone on by
    then; a step has not)."""
    if len(models) < 2:
        return []
    points = candidate_grid(data)
    pairs = [(a, b) for a, b in combinations(range(len(models)), 2) if kinds is None or kinds[a] != kinds[b]]
    if not pairs:
        return []
    gaps = [abs(aiccs[a] - aiccs[b]) if aiccs is not None else 0.0 for a, b in pairs]
    target = np.array([target_separation(g) for g in gaps])
    chosen: list[tuple[int, list, np.ndarray]] = []
    for later in range(1, MAX_RUNS + 1):
        parts = [prediction_parts(m, points, later) for m in models]
        sep = np.column_stack([joint_separation([c[1][a] for c in chosen], [c[1][b] for c in chosen],
                                                parts[a], parts[b]) for a, b in pairs])  # (points, pairs)
        gain = pair_progress(sep / target[None, :])
        # a point already chosen may be chosen again (a replicate), but a new point is preferred on ties
        taken = np.isin(np.arange(len(points)), [c[0] for c in chosen])
        best = int(np.lexsort((taken, -np.round(gain, 9)))[0])
        chosen.append((best, [(p[0][best], p[1][best], p[2][best]) for p in parts], sep[best]))
        if np.all(sep[best] >= target):
            break
    out = []
    for i, run_of_model, sep_i in chosen:
        run = data.point_dict(points[i])
        run["purpose"] = purpose
        run["expected"] = {label: json_number(p[0]) for label, p in zip(labels, run_of_model)}
        run["separation"] = json_number(float(np.min(sep_i)))  # of every pair by the runs so far
        out.append(run)
    return out


def candidate_label(cause: str, detail) -> str:
    """A candidate as listed in a finding: "outlier (7)"."""
    return f"{cause} ({run_label(detail) if not isinstance(detail, str) else detail})"
