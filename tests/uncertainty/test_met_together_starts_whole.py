"""Whether the targets of a pair can be met together when one of them alone is met along a whole line across the
range and the pair only at one end of that line: the search finds the joint point (a witness written here meets
both targets), at any tolerance and sign of the targets, with or without a factor neither response moves; and it
says no once the tolerance is below the pair's closest approach on that line."""

from __future__ import annotations

import numpy as np
import pytest

from demid.design import quadratic_terms
from demid.sampling.domain import Domain
from demid.surrogate import Surrogate
from demid.uncertainty.ranking import _met_together


def _quadratic(name: str, factors, coefficients: dict) -> Surrogate:
    """A full quadratic in actual units with the given coefficients (term exponents -> value), the others zero."""
    terms = quadratic_terms(len(factors))
    coef = np.array([float(coefficients.get(tuple(int(e) for e in t), 0.0)) for t in terms])
    return Surrogate(name, list(factors), terms, coef, np.zeros((len(terms), len(terms))), 0.0, 1, ())


def _pair(sign: float, inert: bool):
    """y1 = b, met at b = 20 for every a; y2 = 10 + (a - 3.8)^2, whose target 14 lies at a = 5.8 only (its other
    root, 1.8, is below the range): both are met near (5.8, 20), and y2 rises away from the range's lower end,
    where nothing meets it.  ``sign`` -1 negates responses and targets."""
    factors = ["a", "b", "c"] if inert else ["a", "b"]
    return _line_and_well(sign, factors, (2.0, 10.0, -1.0), (6.0, 30.0, 1.0), 3.8, 2.0)


def _line_and_well(sign: float, factors, lower, upper, centre: float, half_width: float):
    """y1 = b with target 20 and y2 = 10 + (a - centre)^2 with target 10 + half_width^2 (met at centre +- half_width),
    over the first len(factors) of ``lower`` and ``upper``; ``sign`` -1 negates responses and targets."""
    domain = Domain(tuple(factors), lower[:len(factors)], upper[:len(factors)])
    zero = (0,) * len(factors)

    def term(**exponents):
        return tuple(exponents.get(f, 0) for f in factors)

    surrogates = {
        "y1": _quadratic("y1", factors, {term(b=1): sign}),
        "y2": _quadratic("y2", factors, {zero: sign * (10 + centre ** 2), term(a=1): -sign * 2 * centre,
                                         term(a=2): sign}),
    }
    return domain, surrogates, {"y1": sign * 20.0, "y2": sign * (10 + half_width ** 2)}


@pytest.mark.parametrize("sign", [1.0, -1.0])
@pytest.mark.parametrize("inert", [False, True])
@pytest.mark.parametrize("tolerance", [0.005, 0.02, 0.05])
def test_a_pair_met_only_at_one_end_of_the_line_where_one_target_alone_is_met_is_found(sign, inert, tolerance):
    domain, surrogates, targets = _pair(sign, inert)
    witness = np.array([[5.8, 20.0, 0.3][:domain.dim]])
    errors = [abs(float(surrogates[o].predict(witness)[0]) - t) / abs(t) for o, t in targets.items()]
    assert max(errors) <= 1e-12  # the witness meets both targets
    assert _met_together(surrogates, domain, ["y1", "y2"], targets, tolerance)


@pytest.mark.parametrize("sign", [1.0, -1.0])
def test_a_pair_whose_second_target_lies_beyond_the_range_is_not_met_together(sign):
    """With y2's target moved to 14 + 2.5 (met at a = 3.8 + sqrt(6.5) = 6.35, beyond the upper end 6), y2's
    closest approach is at a = 6: |10 + 2.2^2 - 16.5| / 16.5 = 0.1006; below it no point meets both."""
    domain, surrogates, targets = _pair(sign, False)
    targets["y2"] = sign * 16.5
    closest = abs(10 + 2.2 ** 2 - 16.5) / 16.5
    assert not _met_together(surrogates, domain, ["y1", "y2"], targets, 0.99 * closest)
    assert _met_together(surrogates, domain, ["y1", "y2"], targets, 1.01 * closest)


@pytest.mark.parametrize("sign", [1.0, -1.0])
@pytest.mark.parametrize("n_inert", [0, 2])
def test_a_pair_met_between_nodes_is_found_when_every_best_node_is_a_near_miss_at_the_range_end(sign, n_inert):
    """y2 = 10 + (a - 3.91)^2 with target 10 + 1.92^2: met at a = 5.83 and, just outside the range [2, 6], at 1.99.
    Every node at a = 2, b = 20 misses y2 by 0.28 % (beside factors neither response moves, all equally good), the
    nodes near a = 5.83 by 5 % or more; at a tolerance of 0.2 % the pair is met only near (5.83, 20)."""
    factors = ["a", "b", "c", "d"][:2 + n_inert]
    domain, surrogates, targets = _line_and_well(sign, factors, (2.0, 10.0, 0.0, 0.0), (6.0, 30.0, 1.0, 1.0), 3.91,
                                                 1.92)
    witness = np.array([[5.83, 20.0, 0.5, 0.5][:len(factors)]])
    assert max(abs(float(surrogates[o].predict(witness)[0]) - t) / abs(t) for o, t in targets.items()) <= 1e-12
    assert _met_together(surrogates, domain, ["y1", "y2"], targets, 0.002)
