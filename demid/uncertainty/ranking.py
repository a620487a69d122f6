"""Which experiment next: every non-empty subset of the observables ranked by
information gain and feasible-fraction contraction.  The ranking in words is advice, the story's
(:mod:`demid.story.measurements`).
"""

from __future__ import annotations

from itertools import combinations
from typing import TYPE_CHECKING

import numpy as np
import pandas as pd

from ..sampling import uses_grid
from ..sampling.evaluate import basin_nodes, closest_approach, relative_errors, start_nodes
from ..sampling.grid import predict_grid
from ..spec import join_observables
from .posterior import NO_OBSERVABLE, subset_posteriors
from .plausible import summarise_set

if TYPE_CHECKING:
    from ..sampling import Domain
    from ..surrogate import Surrogate


RANKING_COLUMNS = ["rank", "observables", "information_gain_bits", "feasible_fraction_pct",
                   "contraction_pct_vs_best_subset"]


# =========================================================================== which experiment next
def rank_observable_sets(surrogates: dict[str, Surrogate], domain: Domain, observables_with_targets,
                         targets: dict[str, float], sigma: dict[str, float], tolerance: float, n: int, *,
                         posteriors: dict | None = None, fraction_n: int | None = None,
                         sobol_points: int = 2 ** 16, strict_sets: dict | None = None) -> pd.DataFrame:
    """Rank every non-empty observable subset by information gain (bits), then by fraction.

    Columns: rank, observables, information_gain_bits, feasible_fraction_pct (strict, at
    ``tolerance``), contraction_pct_vs_best_subset = 100 (1 - Phi(S) / min_{T < S} Phi(T))
    over proper subsets T (the empty set is Omega, Phi = 1) and best_subset (that T), then
    gain_vs_best_subset_bits = IG(S) - max_{T < S} IG(T), n_observables, rank_by_fraction,
    information_gain_error_bits, targets_reachable.  ``strict_sets`` (frozenset of observables ->
    strict set at ``tolerance``) are reused instead of evaluating those subsets again where they are exact; a
    grid set may lie on another grid and is evaluated again, so every fraction of the table shares one grid.

    A set whose targets cannot be met anywhere in the domain within ``tolerance`` — one of them alone
    (:func:`reachable_targets`) or all together — has ``targets_reachable`` False and no information gain
    (NaN): its posterior piles up at the closest approach and measures the misfit, a discrepancy between
    simulation and experiment.  Such sets rank after every set whose targets are reachable.
    ``gain_vs_best_subset_bits`` is the gain over ``best_subset``, the proper subset with the smallest
    feasible fraction.
    """
    observables = tuple(observables_with_targets)
    subsets = [c for size in range(1, len(observables) + 1) for c in combinations(observables, size)]
    if posteriors is None:
        posteriors = subset_posteriors(surrogates, domain, observables, targets, sigma, n, subsets=subsets,
                                       sobol_points=sobol_points)
    fn = fraction_n or n
    grid = predict_grid({o: surrogates[o] for o in observables}, domain, fn) if uses_grid(domain.dim) else None
    frac = {(): 1.0}
    gain = {(): 0.0}
    for s in subsets:
        given = (strict_sets or {}).get(frozenset(s))
        frac[s] = summarise_set(surrogates, domain, s, targets, tolerance, fn, polish=False, with_error=False,
                                sobol_points=sobol_points, grid_predictions=grid,
                                grid_set=given if given is not None and given.exact is not None else None).fraction
        gain[s] = posteriors[s].information_gain_bits
    reachable = reachable_targets(surrogates, domain, observables, targets, tolerance,
                                  {o: frac[(o,)] for o in observables})
    # Targets each within reach may still not be met together: the posterior of such a set piles up at the
    # compromise and measures the misfit just the same.
    reachable_set: dict = {}
    for s in subsets:  # by size: a set whose smaller sets cannot be met cannot be met either
        reachable_set[s] = (all(reachable[o] for o in s)
                            and all(reachable_set[t] for t in combinations(s, len(s) - 1) if len(t) > 1)
                            and (frac[s] > 0 or len(s) == 1 or _met_together(surrogates, domain, s, targets,
                                                                             tolerance)))
    for s in subsets:
        if not reachable_set[s]:
            gain[s] = np.nan
    rows = []
    for s in subsets:
        proper = [t for size in range(len(s)) for t in combinations(s, size)]
        best = min(proper, key=lambda t: (frac[t], -gain[t]))
        contraction = 100.0 * (1.0 - frac[s] / frac[best]) if frac[best] > 0 else np.nan
        contraction = 0.0 if abs(contraction) < 1e-9 else contraction  # the same set: no -1.5e-11 %
        rows.append({
            "observables": join_observables(s), "information_gain_bits": gain[s],
            "feasible_fraction_pct": 100.0 * frac[s], "contraction_pct_vs_best_subset": contraction,
            "n_observables": len(s), "best_subset": join_observables(best) or NO_OBSERVABLE,
            "gain_vs_best_subset_bits": gain[s] - gain[best],
            "information_gain_error_bits": (posteriors[s].information_gain_error_bits if np.isfinite(gain[s])
                                            else np.nan),
            "tolerance": float(tolerance),
        })
    frame = pd.DataFrame(rows)
    reachable_rows = pd.Series([reachable_set[s] for s in subsets], index=frame.index)
    # an empty set is no narrowest one: sets with targets out of reach rank last here too
    by_fraction = frame["feasible_fraction_pct"].where(reachable_rows, np.inf)
    frame["rank_by_fraction"] = by_fraction.rank(method="min").astype(int)
    frame["targets_reachable"] = reachable_rows
    frame = frame.sort_values(["targets_reachable", "information_gain_bits", "feasible_fraction_pct"],
                              ascending=[False, False, True], kind="stable", na_position="last").reset_index(drop=True)
    frame.insert(0, "rank", np.arange(1, len(frame) + 1))
    return frame


def _met_together(surrogates, domain, observables, targets, tolerance, starts: int = 8) -> bool:
    """Whether some point of the domain meets every target of the set within ``tolerance``, for sets too thin
    for the grid or Sobol sample.

    The largest relative error has a kink wherever two observables trade places, on which a simplex search
    stalls short of a set that exists; the squared excess over the tolerance is smooth and zero exactly on
    the set, so a bounded quasi-Newton search from the best nodes of a grid, and from the best nodes of its
    other basins, settles it.
    """
    from scipy import optimize

    obs = tuple(observables)

    def errors(u):
        return np.abs(relative_errors(surrogates, domain, obs, targets, u))

    def excess(u):
        return float(np.sum(np.maximum(errors(u)[:, 0] - tolerance, 0.0) ** 2))

    nodes = start_nodes(domain)
    node_errors = errors(nodes)
    worst = node_errors.max(axis=0)
    best = np.argsort(worst, kind="stable")[:starts]
    # and half as many again from other basins: a set that no point meets costs half as many searches more
    for u0 in nodes[np.concatenate([best, _other_basins(node_errors, worst, best, domain.dim, starts // 2)])]:
        res = optimize.minimize(excess, u0, method="L-BFGS-B", bounds=[(0.0, 1.0)] * domain.dim,
                                options={"ftol": 1e-15, "gtol": 1e-12, "maxiter": 500})
        if float(errors(np.clip(res.x, 0.0, 1.0)).max()) <= tolerance * (1 + 1e-6):
            return True
    return False


def _other_basins(node_errors: np.ndarray, worst: np.ndarray, tried: np.ndarray, dim: int, count: int) -> np.ndarray:
    """Up to ``count`` more start nodes: the best node of each basin of the grid's largest error whose errors differ
    from every node tried.  The best nodes alone may all lie in one basin (a near miss at a bound, over factors
    without effect) while the set lies between nodes elsewhere."""
    per_axis = int(round(len(worst) ** (1.0 / dim)))
    seen = {tuple(np.round(node_errors[:, i], 12)) for i in tried}
    out = []
    for i in basin_nodes(worst, per_axis, dim, len(worst)):
        key = tuple(np.round(node_errors[:, i], 12))
        if len(out) == count:
            break
        if key not in seen:
            seen.add(key)
            out.append(i)
    return np.asarray(out, dtype=int)


def reachable_targets(surrogates: dict[str, Surrogate], domain: Domain, observables, targets: dict[str, float],
                      tolerance: float, fractions: dict[str, float]) -> dict[str, bool]:
    """Per observable: can its surrogate meet its target within ``tolerance`` somewhere in the domain?

    ``fractions`` are the observables' own strict feasible fractions; a positive one settles it,
    otherwise the closest approach (min over the domain of the relative error) decides, so that
    a set too thin for a grid or Sobol sample is not taken for an unreachable target.
    """
    out = {}
    for o in observables:
        if fractions[o] > 0:
            out[o] = True
            continue
        closest, _ = closest_approach(surrogates, domain, (o,), targets, None)
        out[o] = bool(closest <= tolerance * (1 + 1e-9))
    return out
