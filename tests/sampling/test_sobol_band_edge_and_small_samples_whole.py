"""The Sobol estimator (more than three factors) at two edges a valid study reaches: a prediction exactly at the end
of its tolerance band is admissible (the band is closed, |y - y*| <= eps |y*|, as on the grid and in the exact
set), and the smallest samples a material may ask for (its ``grid_points`` override goes down to 5) still get,
per replicate, the power of two whose total is nearest the request on a log scale (at least two points)."""

from __future__ import annotations

import numpy as np
import pytest

from demid.sampling import Domain
from demid.sampling.sobol import sobol_admissible_set, sobol_fraction

from ..helpers import Linear

_NAMES = ("f0", "f1", "f2", "f3")


@pytest.mark.parametrize("target, value", [(100.0, 102.0), (100.0, 98.0), (-50.0, -51.0), (-50.0, -49.0)])
def test_a_prediction_exactly_at_the_end_of_its_band_is_admissible_everywhere(target, value):
    """A response the factors do not move, predicted exactly at y* (1 +- 0.02): every point meets the target
    within 2 %, so the whole range is admissible, with no sampling error; a hair further out, none is."""
    domain = Domain(_NAMES, (0.0, 1.0, 2.0, 0.5), (1.0, 3.0, 5.0, 4.0))
    assert abs(value - target) / abs(target) == 0.02  # the band's end, exactly
    on_edge = {"y": Linear(value, np.zeros(4))}
    est = sobol_fraction(on_edge, domain, ["y"], {"y": target}, 0.02, 256, seed=0, polish=False)
    assert (est.fraction, est.std_error, est.ci_lower, est.ci_upper) == (1.0, 0.0, 1.0, 1.0)
    # the spans are the extreme sample points, inside the range and close to its ends
    assert np.all(est.lower >= domain.lower) and np.all(est.upper <= domain.upper)
    width = np.array(domain.upper) - np.array(domain.lower)
    assert np.all(est.lower - np.array(domain.lower) < 0.05 * width)
    assert np.all(np.array(domain.upper) - est.upper < 0.05 * width)
    aset = sobol_admissible_set(on_edge, domain, ["y"], {"y": target}, 0.02, 256)
    assert (aset.fraction, aset.node_fraction, aset.n_admissible_nodes) == (1.0, 1.0, aset.n_nodes)
    assert aset.best_error == 0.02

    beyond = {"y": Linear(np.nextafter(value, 2 * value - target), np.zeros(4))}
    est = sobol_fraction(beyond, domain, ["y"], {"y": target}, 0.02, 256, seed=0, polish=False)
    assert est.fraction == 0.0 and np.isnan(est.lower).all() and np.isnan(est.upper).all()


@pytest.mark.parametrize("n_points", [5, 16, 24, 32, 40, 44, 46, 64, 100, 256])
@pytest.mark.parametrize("replicates", [4, 16])
def test_each_replicate_holds_the_power_of_two_whose_total_is_nearest_the_requested_sample(n_points, replicates):
    domain = Domain(_NAMES, (0.0,) * 4, (1.0,) * 4)
    field = {"y": Linear(1.0, np.ones(4))}  # y from 1 to 5, the target 2.5 in the middle
    est = sobol_fraction(field, domain, ["y"], {"y": 2.5}, 0.1, n_points, seed=3, replicates=replicates,
                         polish=False)
    nearest = min(range(1, 30), key=lambda m: abs(np.log2(replicates * 2 ** m) - np.log2(n_points)))
    assert est.points_per_replicate == 2 ** nearest
    assert est.replicates == replicates and est.evaluations == replicates * 2 ** nearest
    # every replicate's share is a count over its own points
    assert est.fraction * replicates * 2 ** nearest == pytest.approx(round(est.fraction * replicates * 2 ** nearest))
