"""The runs a wave owes before it places its own: the criticism's deciding and confirming runs, and the
D-optimal augmentation of a quadratic design (greedy, given the earlier runs) that the refocused box and the
separating runs use.  Split from :mod:`demid.next_wave`, which composes them into a wave."""

from __future__ import annotations

from itertools import product
from typing import TYPE_CHECKING

import numpy as np
import pandas as pd

from . import run_purposes
from .design import model_matrix, parse_term, quadratic_terms

if TYPE_CHECKING:
    from .sampling import Domain

# A share of the design runs supports the whole refocused box: with every run on the band, the box's
# fit extrapolates at its edges and corners and admits false regions there (benchmarks/next_wave.py).
# A quarter rather than a third: where the set is small in the box, each corner run sits far from the
# set's boundary, which decides the symmetric difference, so a third of the runs there lost to random
# runs (benchmarks/next_wave.py, 32 seeds: wins 0.69 -> 0.73, confirmed on seeds 100-131: 0.63 -> 0.69).
BOX_SHARE = 1 / 4


def candidate_points(k: int) -> np.ndarray:
    levels = (-1.0, -0.5, 0.0, 0.5, 1.0) if k <= 3 else (-1.0, 0.0, 1.0)
    return np.array(list(product(levels, repeat=k)))


def d_optimal_augment(existing: np.ndarray, count: int, k: int, candidates: np.ndarray | None = None) -> np.ndarray:
    """``count`` coded points from ``candidates`` (default: the box's grid), added one at a time, each
    maximising det(X'X) of the full quadratic over existing + chosen points.  By the rank-one update
    det(M + f f') = det(M) (1 + f' M^-1 f) that is the candidate of largest prediction variance
    f' M^-1 f.  A candidate is used once before any repeats; ties go to the candidate farthest from
    the points already there (then candidate order)."""
    terms = quadratic_terms(k)
    cands = candidate_points(k) if candidates is None or not len(candidates) else np.asarray(candidates, dtype=float)
    f = model_matrix(cands, terms)
    current = np.asarray(existing, dtype=float).reshape(-1, k)
    # A tiny ridge keeps M invertible while the first runs are still fewer than the coefficients.
    info = model_matrix(current, terms).T @ model_matrix(current, terms) + 1e-9 * np.eye(len(terms))
    dist = (np.min(np.linalg.norm(cands[:, None, :] - current[None, :, :], axis=2), axis=1)
            if len(current) else np.full(len(cands), np.inf))
    used = dist < 1e-9
    chosen = []
    for _ in range(count):
        if used.all():
            used[:] = False
        variance = np.einsum("ij,ij->i", f @ np.linalg.inv(info), f)
        key = np.where(used, -np.inf, np.round(np.log1p(np.maximum(variance, 0.0)), 9))
        top = np.flatnonzero(key == key.max())
        best = int(top[np.argmax(np.round(dist[top], 9))])
        used[best] = True
        chosen.append(cands[best])
        info += np.outer(f[best], f[best])
        dist = np.minimum(dist, np.linalg.norm(cands - cands[best], axis=1))
    return np.array(chosen).reshape(-1, k)


def aliased_findings(findings: pd.DataFrame | None, factors: list[str]) -> list[tuple[tuple, list[str]]]:
    """Alias sets (as term tuples) named by missing-term findings, with the responses naming them."""
    if findings is None or not len(findings) or "cause" not in findings:
        return []
    out: dict[tuple, list[str]] = {}
    for _, row in findings[findings["cause"] == "missing_term"].iterrows():
        names = [n for n in str(row["aliases"]).split(";") if n]
        if len(names) < 2:
            continue
        members = tuple(parse_term(n, factors) for n in names)
        out.setdefault(members, []).append(str(row["response"]))
    return list(out.items())


def deciding_runs(findings: pd.DataFrame | None, factors: list[str]) -> list[dict]:
    """The runs the criticism proposes for the next wave (a row's ``discriminating_runs``): those that decide
    between causes it cannot tell apart first, then those that would confirm or correct a named cause; in the
    order proposed, each with its ``purpose``.  A replicate is kept (replicates are what tell a wild run from
    unequal scatter); a point that several responses propose is made as often as the one that proposes it
    most often, not once for each."""
    import json

    if findings is None or not len(findings) or "discriminating_runs" not in findings:
        return []
    proposed = []
    for _, row in findings.iterrows():
        text = row["discriminating_runs"]
        if isinstance(text, str) and text:
            proposed += [(run, str(row["response"])) for run in json.loads(text)]
    # decide first: until then no cause can be trusted (sorted is stable: the proposed order within each)
    proposed.sort(key=lambda item: item[0].get("purpose", run_purposes.DECIDE) != run_purposes.DECIDE)
    out, made, asked = [], {}, {}
    for run, response in proposed:
        key = tuple(float(run[f]) for f in factors)
        asked[key, response] = asked.get((key, response), 0) + 1
        if asked[key, response] > made.get(key, 0):
            made[key] = made.get(key, 0) + 1
            out.append({**{f: float(run[f]) for f in factors}, "response": response,
                        "purpose": run.get("purpose", run_purposes.DECIDE)})
    return out


#: A criticism run this far (a share of the search range) outside the next box is taken as meant on its bound: the
#: criticism writes its points rounded (criticism.models._Data.point_dict: on the box's grid to 6 significant
#: digits, as this module writes its own runs; on the design's levels to 4 digits of the design's range).
CRITICISM_ROUNDING = 1e-3


def criticism_runs_in_box(runs: list[dict], factors: list[str], domain: Domain, lo: np.ndarray,
                          hi: np.ndarray) -> tuple[list[dict], int]:
    """The criticism's runs that the next wave can use, and how many it cannot: its table keeps only runs inside
    the next box [lo, hi] (search units), so a run outside would be simulated for nothing.  A run outside by
    no more than the criticism's rounding is put on the bound."""
    if not runs:
        return [], 0
    u = domain.to_search(np.array([[r[f] for f in factors] for r in runs], dtype=float))
    cur_lo, cur_hi = domain.search_bounds()
    slack = CRITICISM_ROUNDING * (cur_hi - cur_lo)
    usable = np.all((u >= lo - slack) & (u <= hi + slack), axis=1)
    box = domain.to_actual(np.array([lo, hi]))
    out = []
    for run, ok, point in zip(runs, usable, u):
        if ok:
            out.append({**run, **{f: float(box[0, i] if point[i] < lo[i] else box[1, i] if point[i] > hi[i]
                                         else run[f]) for i, f in enumerate(factors)}})
    return out, int(np.sum(~usable))


def deciding_reason(deciding: list[dict]) -> str:
    """The reason's clause for the criticism's runs: how many, what for, for which responses."""
    parts = []
    for purpose, what in ((run_purposes.DECIDE, "to decide between causes the criticism cannot tell apart"),
                          (run_purposes.CONFIRM, "to confirm or correct a cause the criticism named")):
        runs = [d for d in deciding if d["purpose"] == purpose]
        if runs:
            parts.append(f"{len(runs)} run(s) {what} ({', '.join(dict.fromkeys(d['response'] for d in runs))})")
    return "; first " + ", then ".join(parts) if parts else ""


def full_rank(points: np.ndarray, k: int) -> int:
    """How many quadratic coefficients short of full rank the points are (0: estimable)."""
    m = model_matrix(points, quadratic_terms(k))
    return m.shape[1] - int(np.linalg.matrix_rank(m, tol=1e-8 * max(np.abs(m).max(), 1.0) * len(m)))


def design_count(count: int, n_deciding: int, earlier: np.ndarray, lo: np.ndarray, hi: np.ndarray) -> int:
    """How many of a wave's ``count`` runs are design runs, the criticism's ``n_deciding`` runs taking the others:
    ``count`` is the wave's whole budget.  The design keeps at least the runs the box's quadratic is short of
    given the ``earlier`` runs inside the box (search units), so that the next wave's fit is determined whatever
    the criticism's runs are (they may all be replicates of one point)."""
    k = len(lo)
    coded = (np.asarray(earlier, dtype=float).reshape(-1, k) - (lo + hi) / 2) / ((hi - lo) / 2)
    short = full_rank(coded, k) if len(coded) else len(quadratic_terms(k))
    return max(count - n_deciding, min(short, count))


def box_support_count(count: int, share: float | None = None) -> int:
    """How many of ``count`` design runs support the whole refocused box (the rest go on the band)."""
    return int(round((BOX_SHARE if share is None else share) * count))
