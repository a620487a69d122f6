"""Level 2's sentence on a shared relative bias (criticism.level2): where no point meets every target and the
measurements leave a spare one or none, "A shared relative bias of <delta> % on all targets would leave <error> at
one extra parameter" quotes the bias and the largest weighted error left *with* that bias (not the error without
it), as a percentage or, with own tolerances, as a multiple of them.  Both against linear programmes over linear
simulations: 1-2 factors, one or two more observables than factors, targets of either sign, own tolerances or none."""

from __future__ import annotations

import re

import numpy as np
import pytest

from demid.criticism.level2 import calibration_check
from demid.criticism.messages import percent_text
from demid.sampling import Domain
from tests.criticism.test_level2_whole import _linear, _minimax_lp


def _infeasible_study(seed):
    """The first draw of a seeded generator whose targets no point of the box meets together at 1 %."""
    rng = np.random.default_rng(seed)
    while True:
        d = int(rng.integers(1, 3))
        k = d + int(rng.integers(1, 3))
        lo = rng.uniform(-5, 5, d)
        hi = lo + rng.uniform(0.5, 4, d)
        slopes = rng.normal(size=(k, d)) * rng.choice([1.0, 30.0])
        intercepts = rng.normal(size=k) * 5 + 20 * rng.choice([-1, 1], size=k)
        targets = (intercepts + slopes @ ((lo + hi) / 2)) * rng.uniform(0.8, 1.25, k)
        scale = np.abs(targets)
        a, b = (intercepts - targets) / scale, slopes / scale[:, None]
        if _minimax_lp(a, b, np.ones(k), lo, hi, shared=False) > 0.03:
            return d, k, lo, hi, slopes, intercepts, targets, a, b


@pytest.mark.parametrize("seed", [0, 3])
@pytest.mark.parametrize("own", [False, True])
def test_the_shared_bias_sentence_quotes_the_bias_and_the_error_left_with_it(seed, own):
    d, k, lo, hi, slopes, intercepts, targets, a, b = _infeasible_study(seed)
    factors, names = ["a", "b"][:d], [f"y{j}" for j in range(k)]
    tolerance = 0.01
    tolerances = {names[0]: 0.004, names[-1]: 0.03} if own else None
    w = np.array([tolerance / (tolerances or {}).get(o, tolerance) for o in names])
    surrogates = {o: _linear(o, factors, c, g) for o, c, g in zip(names, intercepts, slopes)}
    domain = Domain(tuple(factors), tuple(lo), tuple(hi), (False,) * d)
    result = calibration_check(surrogates, domain, dict(zip(names, targets)), tolerance, 7, tolerances=tolerances)
    assert not result.feasible
    left = _minimax_lp(a, b, w, lo, hi, shared=True)
    quoted = re.search(r"A shared relative bias of ([+-][\d.]+) % on all targets would leave (.+?) at one extra "
                       r"parameter; ", result.message)
    assert float(quoted.group(1)) == pytest.approx(100 * result.shared_bias["delta"], abs=0.005 + 1e-9)
    if own:
        ratio = float(re.fullmatch(r"([\d.e+-]+) times their own tolerances", quoted.group(2)).group(1))
        assert ratio == pytest.approx(left / tolerance, rel=0.05)  # two significant digits
    else:
        assert quoted.group(2) == percent_text(left)
    # the error left with the bias, never more than without it
    assert left <= _minimax_lp(a, b, w, lo, hi, shared=False) + 1e-9
