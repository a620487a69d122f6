"""evaluate_set: which estimator judges a set, and the numbers it reports, against closed forms.

Linear surrogates y_i = x_i with targets 1/2 and tolerance 10 % keep the box [0.45, 0.55] of each
factor they name: the fraction is a product of widths, the spans are the box's edges.
"""

import numpy as np
import pytest

from demid.sampling import Domain
from demid.sampling.evaluate import EXACT_METHOD, evaluate_set, uses_exact
from demid.surrogate import Surrogate


def _linear(name, factors, slopes, offset=0.0, log_factors=()):
    d = len(factors)
    terms = [tuple([0] * d)] + [tuple(int(i == j) for j in range(d)) for i in range(d)]
    coef = np.array([offset, *slopes], dtype=float)
    return Surrogate(name, list(factors), terms, coef, np.zeros((d + 1, d + 1)), 0.0, 5, tuple(log_factors))


def _unit_domain(factors, log=None):
    d = len(factors)
    return Domain(tuple(factors), (0.0,) * d, (1.0,) * d, tuple(log or (False,) * d))


def test_three_factors_are_judged_exactly_with_the_boxs_fraction_and_spans():
    factors = ("a", "b", "c")
    surrogates = {f"y{i}": _linear(f"y{i}", factors, np.eye(3)[i]) for i in range(3)}
    domain = _unit_domain(factors)
    targets = {o: 0.5 for o in surrogates}
    assert uses_exact(surrogates, tuple(surrogates), domain)
    aset = evaluate_set(surrogates, domain, tuple(surrogates), targets, 0.1, 11)
    assert aset.method == EXACT_METHOD and aset.exact is not None
    assert aset.fraction == pytest.approx(0.1 ** 3, rel=1e-6)
    np.testing.assert_allclose(aset.lower, [0.45] * 3, atol=1e-9)
    np.testing.assert_allclose(aset.upper, [0.55] * 3, atol=1e-9)
    assert aset.fraction_error < 1e-6 * aset.fraction
    # two of the three: a slab of the whole c range
    two = evaluate_set(surrogates, domain, ("y0", "y1"), targets, 0.1, 11)
    assert two.fraction == pytest.approx(0.01, rel=1e-6)
    np.testing.assert_allclose(two.upper, [0.55, 0.55, 1.0], atol=1e-9)
    assert list(two.at_bound) == ["none", "none", "both"]


def test_exact_only_for_polynomials_in_at_most_three_factors_on_the_domains_scales():
    four = ("a", "b", "c", "d")
    surrogates = {"y": _linear("y", four, [1, 0, 0, 0])}
    assert not uses_exact(surrogates, ("y",), _unit_domain(four))
    three = ("a", "b", "c")
    lin = {"y": _linear("y", three, [1, 0, 0])}
    assert uses_exact(lin, ("y",), _unit_domain(three))
    log_domain = Domain(three, (1.0, 0.0, 0.0), (10.0, 1.0, 1.0), (True, False, False))
    assert not uses_exact(lin, ("y",), log_domain)  # the surrogate is linear in a, the domain logarithmic
    assert uses_exact({"y": _linear("y", three, [1, 0, 0], log_factors=("a",))}, ("y",), log_domain)
    assert not uses_exact({"y": _linear("y", ("b", "a", "c"), [1, 0, 0])}, ("y",), _unit_domain(three))
    # every observable must qualify, not one of them
    mixed = {"y": _linear("y", three, [1, 0, 0], log_factors=("a",)), "z": _linear("z", three, [0, 1, 0])}
    assert uses_exact(mixed, ("y",), log_domain) and not uses_exact(mixed, ("y", "z"), log_domain)
    assert not uses_exact(mixed, ("z", "y"), log_domain)


def test_four_factors_fall_back_to_a_sample_with_the_same_fraction():
    four = ("a", "b", "c", "d")
    surrogates = {"y": _linear("y", four, [1, 0, 0, 0])}
    aset = evaluate_set(surrogates, _unit_domain(four), ("y",), {"y": 0.5}, 0.1, 2 ** 12)
    assert aset.method != EXACT_METHOD and aset.exact is None
    assert aset.fraction == pytest.approx(0.1, abs=0.01)


def test_an_empty_set_keeps_the_grids_closest_approach_when_it_is_closer():
    """y = a + b on the unit square with target 3 cannot be met: its closest approach is the corner
    (1, 1), relative error |2 - 3| / 3."""
    factors = ("a", "b")
    surrogates = {"y": _linear("y", factors, [1, 1])}
    aset = evaluate_set(surrogates, _unit_domain(factors), ("y",), {"y": 3.0}, 0.1, 21, grid=True)
    assert aset.fraction == 0 and aset.fraction_error == 0
    assert aset.best_error == pytest.approx(1 / 3, abs=1e-9)
    np.testing.assert_allclose(aset.best_point, [1.0, 1.0], atol=1e-9)


@pytest.mark.parametrize("reference, distance, nearest", [
    ({"a": 0.2, "b": 0.5}, 0.25, [0.45, 0.5]),
    ({"a": 0.9, "b": 0.1}, float(np.hypot(0.35, 0.35)), [0.55, 0.45]),
    ({"a": 0.5, "b": 0.52}, 0.0, [0.5, 0.52]),
])
def test_reference_distance_to_the_box_and_its_nearest_point(reference, distance, nearest):
    """The reference point's distance to the square [0.45, 0.55]^2 (fractions of the unit search range)."""
    factors = ("a", "b")
    surrogates = {f"y{i}": _linear(f"y{i}", factors, np.eye(2)[i]) for i in range(2)}
    aset = evaluate_set(surrogates, _unit_domain(factors), ("y0", "y1"), {"y0": 0.5, "y1": 0.5}, 0.1, 11,
                        reference=reference)
    assert aset.exact.reference_distance == pytest.approx(distance, abs=1e-7)
    np.testing.assert_allclose(aset.exact.nearest_point, nearest, atol=1e-7)
    # on a log-scale factor the distance is measured in log10 units of the range
    log_domain = Domain(factors, (1.0, 0.0), (100.0, 1.0), (True, False))
    logged = {o: _linear(o, factors, np.eye(2)[i], log_factors=("a",)) for i, o in enumerate(("y0", "y1"))}
    far = evaluate_set(logged, log_domain, ("y0", "y1"), {"y0": 1.0, "y1": 0.5}, 0.1, 11,
                       reference={"a": 10 ** 0.4, "b": 0.5})
    assert far.exact.reference_distance == pytest.approx((0.9 - 0.4) / 2, abs=1e-7)


def test_closest_approach_of_an_empty_set_finds_the_deeper_of_two_wells():
    """y = 16 (a - 1/4)^2 (a - 3/4)^2 + a/10 has two wells; with target -1 no point comes within 10 % and the
    closest approach is the deeper well near a = 1/4 (brute force on a fine grid), not the one near 3/4."""
    from numpy.polynomial import polynomial as P

    coef = 16 * P.polymul(P.polyfromroots([0.25, 0.25]), P.polyfromroots([0.75, 0.75])) + np.array([0, 0.1, 0, 0, 0])
    terms = [(e, 0) for e in range(5)]
    surrogate = Surrogate("y", ["a", "b"], terms, coef, np.zeros((5, 5)), 0.0, 5)
    aset = evaluate_set({"y": surrogate}, _unit_domain(("a", "b")), ("y",), {"y": -1.0}, 0.1, 21)
    a = np.linspace(0.0, 1.0, 200_001)
    y = P.polyval(a, coef)
    assert aset.fraction == 0
    assert aset.best_error == pytest.approx(float(np.min(np.abs(y + 1.0))), abs=1e-8)
    assert aset.best_point[0] == pytest.approx(float(a[np.argmin(y)]), abs=1e-4)


def test_the_grid_is_evaluated_only_when_asked_for():
    """An exact set evaluates no nodes unless a caller needs the node mask (figures); with it, the mask is
    the n x n grid and the share of admissible nodes approaches the exact fraction."""
    factors = ("a", "b")
    surrogates = {f"y{i}": _linear(f"y{i}", factors, np.eye(2)[i]) for i in range(2)}
    args = (surrogates, _unit_domain(factors), ("y0", "y1"), {"y0": 0.5, "y1": 0.5}, 0.1, 101)
    plain = evaluate_set(*args)
    assert plain.n_nodes == 0 and plain.n_admissible_nodes == 0 and plain.n_refined_cells == 0
    assert plain.mask.size == 0 and np.isnan(plain.node_fraction)
    gridded = evaluate_set(*args, grid=True)
    assert gridded.fraction == pytest.approx(0.01, rel=1e-6)  # the numbers still come from the exact set
    assert gridded.mask.size == gridded.n_nodes == 101 ** 2
    # nodes 0.45, 0.46, ..., 0.55 per axis (11, the edges within round-off of the band)
    assert gridded.n_admissible_nodes in (9 ** 2, 10 ** 2, 11 ** 2)
