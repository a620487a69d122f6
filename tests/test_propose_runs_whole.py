"""The refocused box's proposals over generated boxes (2-3 factors, ranges away from the origin), earlier runs inside
and counts from the quadratic's size up: as many runs and kinds as asked, every run inside the box, support and
off-band runs on the box's grid, band runs on the plausible points given, a quarter of the design over the whole
box, the box's quadratic determined by the earlier and new runs, and an alias set's members separately
estimable where the count leaves room (ranks computed with numpy)."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from demid.design import model_matrix, quadratic_terms
from demid.next_wave import propose_runs
from demid.wave_runs import candidate_points


def _members(k):
    return ((3,) + (0,) * (k - 1), (1, 2) + (0,) * (k - 2))  # a^3 and a:b^2


@given(k=st.integers(2, 3), seed=st.integers(0, 10_000), earlier=st.integers(0, 6), extra=st.integers(0, 5),
       band=st.sampled_from(["none", "few", "many"]), aliased=st.booleans())
@settings(max_examples=12, deadline=None, derandomize=True)
def test_proposals_fill_the_count_inside_the_box_and_determine_its_quadratic(k, seed, earlier, extra, band, aliased):
    rng = np.random.default_rng(seed)
    lo = rng.uniform(-50.0, 50.0, k)
    hi = lo + rng.uniform(0.5, 20.0, k)
    centre, half = (lo + hi) / 2, (hi - lo) / 2
    p = len(quadratic_terms(k))
    count = p + extra + (2 if aliased else 0)
    earlier_u = centre + rng.uniform(-1, 1, (earlier, k)) * half
    grid = candidate_points(k)
    plausible = None
    if band != "none":
        fine = np.array(np.meshgrid(*[np.linspace(-1, 1, 9)] * k, indexing="ij")).reshape(k, -1).T
        ring = np.abs(np.sum(fine ** 2, axis=1) - 0.5) <= (0.02 if band == "few" else 0.3)
        plausible = centre + fine[ring] * half
    alias_sets = [(_members(k), ["y"])] if aliased else []
    points, labels = propose_runs(lo, hi, earlier_u, count, alias_sets, plausible)
    assert points.shape == (count, k) and len(labels) == count
    assert np.all(points >= lo - 1e-9 * half) and np.all(points <= hi + 1e-9 * half)
    coded = (points - centre) / half
    kinds = [lab if isinstance(lab, str) else "separate" for lab in labels]
    assert set(kinds) <= {"support", "band", "box", "separate"}
    on_grid = [any(np.allclose(c, g, atol=1e-9) for g in grid) for c in coded]
    band_points = (plausible - centre) / half if plausible is not None else np.empty((0, k))
    for c, kind, grid_point in zip(coded, kinds, on_grid):
        if kind in ("support", "box"):
            assert grid_point
        elif kind == "band":
            assert any(np.allclose(c, q, atol=1e-9) for q in band_points)
    if plausible is None:  # no band: every design run comes from the box's grid
        assert "band" not in kinds and "box" not in kinds
    else:
        design = count - kinds.count("separate")
        assert kinds[:int(round(design / 4))] == ["support"] * int(round(design / 4))
    everything = np.vstack([(earlier_u - centre) / half, coded])
    assert np.linalg.matrix_rank(model_matrix(everything, quadratic_terms(k))) == p
    if aliased:
        terms = quadratic_terms(k) + list(_members(k))
        assert np.linalg.matrix_rank(model_matrix(everything, terms)) == p + 2
