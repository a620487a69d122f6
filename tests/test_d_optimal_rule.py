"""The next wave's D-optimal augmentation against its rule written out here, over generated starts (1-3 factors,
0-8 earlier runs on or off the box's grid, 1-14 runs to add, the box's grid or a generated candidate set): each
run added is a candidate of largest prediction variance f'M⁻¹f of the full quadratic, a candidate is used once
before any repeats, and ties go to the candidate farthest from the points already there, then candidate order."""

from __future__ import annotations

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st

from demid.design import model_matrix, quadratic_terms
from demid.wave_runs import candidate_points, d_optimal_augment


def _by_the_rule(existing: np.ndarray, count: int, k: int, cands: np.ndarray) -> np.ndarray:
    f = model_matrix(cands, quadratic_terms(k))
    points = [p for p in existing]
    m = model_matrix(existing, quadratic_terms(k)).T @ model_matrix(existing, quadratic_terms(k)) \
        + 1e-9 * np.eye(f.shape[1])
    used = np.array([any(np.linalg.norm(c - p) < 1e-9 for p in existing) for c in cands])
    chosen = []
    for _ in range(count):
        if used.all():
            used[:] = False
        variance = np.einsum("ij,ij->i", f @ np.linalg.inv(m), f)  # f'M⁻¹f per candidate
        key = np.where(used, -np.inf, np.round(np.log1p(np.maximum(variance, 0.0)), 9))
        ties = np.flatnonzero(key == key.max())
        far = [min((np.linalg.norm(cands[t] - p) for p in points), default=np.inf) for t in ties]
        far = np.round(far, 9)
        pick = int(ties[int(np.argmax(far))])  # the farthest, the first in candidate order among equals
        used[pick] = True
        chosen.append(cands[pick])
        points.append(cands[pick])
        m = m + np.outer(f[pick], f[pick])
    return np.array(chosen).reshape(-1, k)


@given(k=st.integers(1, 3), n_existing=st.integers(0, 8), count=st.integers(1, 14), seed=st.integers(0, 10_000),
       own_candidates=st.booleans())
@settings(max_examples=40, deadline=None, derandomize=True)
def test_each_added_run_maximises_the_determinant_with_ties_to_the_farthest_candidate(k, n_existing, count, seed,
                                                                                    own_candidates):
    rng = np.random.default_rng(seed)
    grid = candidate_points(k)
    existing = np.vstack([grid[rng.choice(len(grid), n_existing // 2, replace=False)],
                          rng.uniform(-1, 1, (n_existing - n_existing // 2, k))]) if n_existing else np.zeros((0, k))
    cands = rng.uniform(-1, 1, (int(rng.integers(3, 30)), k)) if own_candidates else grid
    found = d_optimal_augment(existing, count, k, cands if own_candidates else None)
    assert found.shape == (count, k)
    assert np.allclose(found, _by_the_rule(existing, count, k, cands))
