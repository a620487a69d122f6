"""Alias sets of third-order terms and the extra runs that would separate them.

Terms whose columns coincide once the quadratic is fitted (e.g. ``b^3`` and ``a^2:b``
in a CCD) form one alias set, tested once; :func:`separating_runs` proposes the
candidate runs that best split such a set.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import lru_cache
from itertools import product
from typing import TYPE_CHECKING

import numpy as np

from ..design import LEVERAGE_UNPREDICTABLE, model_matrix
from .models import orthonormal_basis, residualize

if TYPE_CHECKING:
    from ..design import Term


# =========================================================================== aliasing
@dataclass(frozen=True)
class AliasSet:
    """Extra terms the design cannot tell apart once the quadratic (or current model) is fitted.

    ``testable`` is False when the terms coincide with the model itself (e.g. ``a^3``
    with ``a`` in a face-centred CCD).  ``extra_runs`` are candidate design points
    (actual units) whose addition makes every member separately estimable.
    """

    representative: str
    members: tuple[str, ...]
    testable: bool
    extra_runs: tuple[dict, ...] = ()

    def to_json(self) -> dict:
        return {"representative": self.representative, "aliases": list(self.members),
                "testable": self.testable, "extra_runs": [dict(p) for p in self.extra_runs]}


@dataclass
class TermClass:
    """Candidate terms the design cannot tell apart, and their common direction in the runs."""
    terms: list[Term]
    direction: np.ndarray | None  # unit residualised column (None: not estimable)


def term_classes(coded: np.ndarray, base_terms: list[Term], candidates: list[Term],
                 extra_columns: np.ndarray | None = None, weights: np.ndarray | None = None
                 ) -> list[TermClass]:
    """Group candidate terms whose columns, residualised on the model, are collinear."""
    sw = np.ones(len(coded)) if weights is None else np.sqrt(weights)
    base = model_matrix(coded, base_terms)
    if extra_columns is not None and extra_columns.size:
        base = np.column_stack([base, extra_columns])
    q = orthonormal_basis(base * sw[:, None])
    hat = np.sum(q * q, axis=1)
    cols = model_matrix(coded, candidates) * sw[:, None]
    resid = residualize(q, cols)
    classes: list[TermClass] = []
    inestimable = []
    for j, t in enumerate(candidates):
        norm = float(np.linalg.norm(resid[:, j]))
        if norm <= 1e-7 * max(float(np.linalg.norm(cols[:, j])), 1e-300):
            inestimable.append(t)
            continue
        u = resid[:, j] / norm
        if np.max(hat + u * u) >= LEVERAGE_UNPREDICTABLE:
            # The term would all but fit one run exactly (leverage 1, or 1 blurred by rounded levels): not a
            # curvature the runs can show.
            inestimable.append(t)
            continue
        for c in classes:
            if abs(float(c.direction @ u)) >= 1 - 1e-7:
                c.terms.append(t)
                break
        else:
            classes.append(TermClass([t], u))
    return classes + [TermClass([t], None) for t in inestimable]


#: Log pseudo-determinants closer than this are a tie (candidate order decides); distinct candidates
#: differ by tenths.
_TIE = 1e-4


def candidate_points(n_factors: int, alpha: float) -> np.ndarray:
    """Coded points a proposed extra run is chosen from: every combination of the levels -alpha, -1, -0.5, 0,
    0.5, 1, alpha."""
    levels = sorted({-alpha, -1.0, -0.5, 0.0, 0.5, 1.0, alpha})
    return np.array(list(product(levels, repeat=n_factors)), dtype=float)


def _separation_criterion(coded, base_terms, members):
    base = model_matrix(coded, base_terms)
    q = orthonormal_basis(base)
    cols = model_matrix(coded, members)
    resid = residualize(q, cols)
    ev = np.linalg.eigvalsh(resid.T @ resid)
    keep = ev > max(float(np.sum(cols * cols)), 1e-300) * 1e-12
    return int(keep.sum()), float(np.sum(np.log(ev[keep]))) if keep.any() else -np.inf


def separating_runs(coded: np.ndarray, base_terms: list[Term], members: list[Term],
                    alpha: float) -> np.ndarray:
    """Coded points to add so that every member term becomes separately estimable.

    Greedy D-optimal choice among the candidate levels {-alpha, -1, -0.5, 0, 0.5,
    1, alpha}^k: each step adds the point that raises the rank of the members'
    residualised block, ties broken by its log pseudo-determinant.
    """
    coded = np.round(np.asarray(coded, dtype=float), 12)
    return _separating_runs_cached(coded.tobytes(), coded.shape, tuple(map(tuple, base_terms)),
                                   tuple(map(tuple, members)), float(alpha)).copy()


@lru_cache(maxsize=256)
def _separating_runs_cached(coded_bytes: bytes, shape: tuple, base_terms: tuple, members: tuple,
                            alpha: float) -> np.ndarray:
    coded = np.frombuffer(coded_bytes, dtype=float).reshape(shape)
    base_terms, members = list(base_terms), list(members)
    cands = candidate_points(coded.shape[1], alpha)
    cand_base, cand_members = model_matrix(cands, base_terms), model_matrix(cands, members)
    state = OneMoreRun.of(np.asarray(coded, dtype=float), base_terms, members, cand_base, cand_members)
    chosen = []
    rank, _ = _separation_criterion(np.asarray(coded, dtype=float), base_terms, members)
    while rank < len(members) and len(chosen) < len(members):
        ranks, logdets = state.criteria()
        best = _first_best(ranks, logdets, rank)
        if best is None:
            break
        chosen.append(cands[best])
        state = state.with_run(best, cands[best], base_terms, members)
        rank = int(ranks[best])
    return np.array(chosen).reshape(-1, coded.shape[1])


def _first_best(ranks: np.ndarray, logdets: np.ndarray, rank: int) -> int | None:
    """The candidate a scan in candidate order keeps, when one raises the rank above ``rank``: the first of
    the highest rank, replaced only by one of that rank whose log pseudo-determinant is more than
    :data:`_TIE` above the one kept so far (mirror-image candidates tie up to round-off: the first in
    candidate order wins a tie, so a last-bit change of the coding does not flip the suggestion to the
    mirror point)."""
    top = int(ranks.max())  # one per candidate point: 7^k of them, never none
    if top <= rank:
        return None
    best = None
    for i in np.flatnonzero(ranks == top).tolist():
        if best is None or logdets[i] > logdets[best] + _TIE:
            best = i
    return best


@dataclass
class OneMoreRun:
    """What adding each candidate run to the design does to the members' residual cross-product
    S = Z'(I - P_X)Z: when the candidate's base-model row x lies in the row space of the base matrix X,
    S + e e' / (1 + h), with e = z - B'x its prediction error of the members from the base model (B the
    least-squares coefficients) and h = x'(X'X)^+ x its leverage; when it does not, the new run is fitted
    exactly by a new base direction and S is unchanged (``outside``).  Built from one SVD of the design
    (7^k candidates: one SVD per candidate was 117,649 SVDs per step at six factors); a chosen run then
    updates h, e and S of every candidate by rank-one terms (:meth:`with_run`).
    """

    coded: np.ndarray
    cand_base: np.ndarray
    cand_members: np.ndarray
    inverse: np.ndarray      # (X'X)^+
    leverage: np.ndarray     # per candidate
    error: np.ndarray        # per candidate x member
    current: np.ndarray      # S
    column_ss: float         # sum of squares of the members' columns
    outside: np.ndarray | None  # candidates off the row space of X (None: X has full column rank)

    @classmethod
    def of(cls, coded, base_terms, members, cand_base, cand_members) -> OneMoreRun:
        base = model_matrix(coded, base_terms)
        cols = model_matrix(coded, members)
        u, s, vt = np.linalg.svd(base, full_matrices=False)
        keep = s > s[0] * 1e-10 if len(s) and s[0] > 0 else np.zeros(len(s), dtype=bool)
        u, s, v = u[:, keep], s[keep], vt[keep].T
        resid = residualize(u, cols)
        scaled = cand_base @ (v / s)                          # candidates in the base's row-space coordinates
        error = cand_members - scaled @ (u.T @ cols)          # z - B'x, with B = V S^-1 U' Z
        outside = None
        if v.shape[1] < v.shape[0]:  # a base the runs cannot estimate: a run off its row space adds a direction
            outside = np.linalg.norm(cand_base - (scaled * s) @ v.T, axis=1) > 1e-8 * np.maximum(
                np.linalg.norm(cand_base, axis=1), 1e-300)
            error[outside] = 0.0
        return cls(coded, cand_base, cand_members, (v / s ** 2) @ v.T, np.sum(scaled * scaled, axis=1), error,
                   resid.T @ resid, float(np.sum(cols * cols)), outside)

    def with_run(self, index: int, point: np.ndarray, base_terms, members) -> OneMoreRun:
        """The state after candidate ``index`` (coded ``point``) joins the design: (X'X)^-1, h, e and S by
        rank-one updates (Sherman-Morrison); rebuilt from an SVD when the base model is not estimable."""
        coded = np.vstack([self.coded, point])
        if self.outside is not None:
            return OneMoreRun.of(coded, base_terms, members, self.cand_base, self.cand_members)
        x, e = self.cand_base[index], self.error[index]
        spread = 1.0 + self.leverage[index]
        g = self.inverse @ x
        c = self.cand_base @ g                                # x_c' (X'X)^-1 x for every candidate
        z = self.cand_members[index]
        return OneMoreRun(coded, self.cand_base, self.cand_members, self.inverse - np.outer(g, g) / spread,
                          self.leverage - c * c / spread, self.error - np.outer(c, e / spread),
                          self.current + np.outer(e, e) / spread, self.column_ss + float(z @ z), None)

    def criteria(self) -> tuple[np.ndarray, np.ndarray]:
        """:func:`_separation_criterion` of the design plus each candidate run, for all candidates at once:
        S + w w' with w = e / sqrt(1 + h), in the eigenbasis of S (eigenvalues lam), has a pseudo-determinant
        larger by a factor 1 + sum(a^2 / lam) over the range of S, or |w_perp|^2 (and one rank) when w
        leaves it."""
        lam, basis = np.linalg.eigh(self.current)
        a = (self.error @ basis) / np.sqrt(1.0 + self.leverage)[:, None]
        floor = np.maximum(self.column_ss + np.sum(self.cand_members * self.cand_members, axis=1), 1e-300) * 1e-12
        in_range = lam[None, :] > floor[:, None]
        perp = np.sum(np.where(in_range, 0.0, a * a), axis=1)
        gains = perp > floor
        with np.errstate(divide="ignore", invalid="ignore"):
            base_logdet = np.sum(np.where(in_range, np.log(np.where(in_range, lam, 1.0)), 0.0), axis=1)
            along = np.sum(np.where(in_range, a * a / np.where(in_range, lam, 1.0), 0.0), axis=1)
            logdets = base_logdet + np.where(gains, np.log(np.where(gains, perp, 1.0)), np.log1p(along))
        ranks = in_range.sum(axis=1) + gains
        return ranks, np.where(ranks > 0, logdets, -np.inf)
