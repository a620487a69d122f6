"""Canonical analysis of fitted CCDs over generated quadratics with a known stationary point and known
curvatures (two and three factors, maxima, minima and saddles, stationary points inside and beyond the runs'
box, axial distances of either kind): every number of the result against the surface it was fitted to."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import example, given, settings
from hypothesis import strategies as st
from scipy.stats import special_ortho_group

from demid.canonical import fit_canonical
from demid.surrogate import fit_response

from ..helpers import make_ccd_table


@given(k=st.sampled_from([2, 3]), seed=st.integers(0, 1000), signs=st.lists(st.sampled_from([-1.0, 1.0]), min_size=3,
                                                                            max_size=3),
       spread=st.floats(0.2, 2.2), alpha_kind=st.sampled_from(["rotatable", "face"]))
# a maximum inside the runs' box (axial runs at 1.414) but outside the factorial square [-1, 1]^2
@example(k=2, seed=0, signs=[-1.0, -1.0, -1.0], spread=1.25, alpha_kind="rotatable")
@settings(max_examples=20, deadline=None, derandomize=True)
def test_a_fitted_quadratics_stationary_point_curvatures_and_kind_are_those_it_was_built_with(k, seed, signs,
                                                                                               spread, alpha_kind):
    rng = np.random.default_rng(seed)
    alpha = 1.0 if alpha_kind == "face" else (2 ** k) ** 0.25
    curvatures = np.array(signs[:k]) * rng.uniform(0.5, 3.0, size=k)
    rotation = special_ortho_group.rvs(k, random_state=seed) if k > 1 else np.eye(1)
    big_b = rotation @ np.diag(curvatures) @ rotation.T
    stationary = rng.uniform(-1.0, 1.0, size=k) * spread
    peak = float(rng.uniform(-50.0, 50.0))
    lower, upper = rng.uniform(1.0, 5.0, size=k), rng.uniform(8.0, 20.0, size=k)
    centre, unit = (lower + upper) / 2, (upper - lower) / (2 * alpha)

    def responses(x):
        d = (x - centre) / unit - stationary
        return {"y": peak + np.einsum("ni,ij,nj->n", d, big_b, d)}

    table = make_ccd_table(responses, lower, upper, alpha=alpha, center_runs=3, seed=seed)
    factors = [f"x{i + 1}" for i in range(k)]
    c = fit_canonical(fit_response(table, factors, "y", alpha=alpha))
    np.testing.assert_allclose(c.eigenvalues, np.sort(curvatures)[::-1], rtol=1e-7, atol=1e-9)
    np.testing.assert_allclose(c.stationary_coded, stationary, atol=1e-7)
    np.testing.assert_allclose(c.stationary_actual, centre + unit * stationary, rtol=1e-8, atol=1e-8)
    assert c.value == pytest.approx(peak, abs=1e-7)
    assert c.kind == ("maximum" if np.all(curvatures < 0) else "minimum" if np.all(curvatures > 0)
                      else "saddle point")
    # the region is the runs' coded box: axial runs reach alpha along each axis
    assert c.inside == bool(np.all(np.abs(stationary) <= alpha + 1e-9))
    for j, vector in enumerate(c.eigenvectors.T):
        np.testing.assert_allclose(big_b @ vector, c.eigenvalues[j] * vector, atol=1e-7)


@given(seed=st.integers(0, 1000), past=st.sampled_from([1e-13, 1e-11, 5e-10]))
@settings(max_examples=10, deadline=None, derandomize=True)
def test_a_stationary_point_on_the_regions_edge_to_round_off_is_inside(seed, past):
    """A stationary point computed a little past a face of the box (round-off of the solve) is on it."""
    from demid.canonical import canonical_analysis

    rng = np.random.default_rng(seed)
    big_b = np.diag(rng.uniform(0.5, 2.0, size=2))
    b = rng.normal(size=2)
    xs = -0.5 * np.linalg.solve(big_b, b)
    for face in range(2):
        lower, upper = xs - 1.0, xs + 1.0
        lower[face] = xs[face] + past  # the point lies `past` outside the lower face
        c = canonical_analysis(0.0, b, big_b, region_lower=lower, region_upper=upper)
        assert c.inside
        lower[face] = xs[face] + 1e-6  # clearly outside
        assert not canonical_analysis(0.0, b, big_b, region_lower=lower, region_upper=upper).inside
