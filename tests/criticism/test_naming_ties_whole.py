"""Which of two rival extensions level 1 names (criticism.naming.name_cause) when they fit about equally: between
an outlier and unequal scatter, and between drift and a step in run order (the step paying log C for its C
change-points), the higher log-likelihood decides; log-likelihoods equal to nine decimals are a tie, which the
stronger test (the one listed first among the rejected) wins.  The extensions' fits are stand-ins with the
log-likelihoods written here, so each margin lands exactly where it is meant to: 0, 4e-10 (a tie), 2e-9 (decided),
either way and in either order; the alternatives quote the other's log-likelihood and AICc against the named."""

from __future__ import annotations

import math
from types import SimpleNamespace

import numpy as np
import pytest

from demid.criticism import naming
from demid.criticism.catalogue import Hypothesis

_BASE = -12.5  # exactly representable at nine decimals: a margin below half a nano-unit rounds away


def _name(monkeypatch, rejected, loglik):
    """name_cause over ``rejected`` whose extensions fit with the log-likelihoods ``loglik`` (per hypothesis)."""
    fits = {id(h): SimpleNamespace(loglik=loglik[i], n_params=8, aicc=-2.0 * loglik[i] + 30.0)
            for i, h in enumerate(rejected)}
    monkeypatch.setattr(naming, "extend_for", lambda data, model, h: (SimpleNamespace(lam=None, key=id(h)), {}))
    monkeypatch.setattr(naming, "Model", lambda data, spec: fits[spec.key])
    data = SimpleNamespace(runs=np.arange(1, 14))
    return naming.name_cause(data, None, rejected)


@pytest.mark.parametrize("pair", ["scatter", "run order"])
@pytest.mark.parametrize("margin,second_wins", [(0.0, False), (4e-10, False), (-4e-10, False), (2e-9, True),
                                                (-2e-9, False), (0.3, True)])
@pytest.mark.parametrize("flip", [False, True])
def test_the_better_fit_decides_and_a_tie_to_nine_decimals_goes_to_the_stronger_test(monkeypatch, pair, margin,
                                                                                    second_wins, flip):
    if pair == "scatter":
        first, second = Hypothesis("outlier", 4, logp=-9.0), Hypothesis("heteroscedasticity", "a", logp=-8.0)
        price = 0.0
    else:
        first = Hypothesis("drift", "run", logp=-9.0)
        second = Hypothesis("step", 6, logp=-8.0, info={"change_points": 9})
        price = math.log(9)
    if flip:  # the step (or scatter) is the stronger test, listed first
        first, second = second, first
    prices = [price if h.cause == "step" else 0.0 for h in (first, second)]
    loglik = [_BASE + prices[0], _BASE + margin + prices[1]]
    other = Hypothesis("missing_term", "a^3", logp=-7.0, aliases=["a^3"])
    h, _, _, new, alternatives = _name(monkeypatch, [first, second, other], loglik + [_BASE - 40.0])
    assert h is (second if second_wins else first)
    assert new.loglik == loglik[1 if second_wins else 0]
    loser = first if second_wins else second
    alt = {a["cause"]: a for a in alternatives}
    assert set(alt) == {loser.cause, "missing_term"}
    assert alt[loser.cause]["loglik_vs_named"] == pytest.approx(loglik[0 if second_wins else 1] - new.loglik,
                                                                abs=1e-12)
    assert alt["missing_term"]["aicc_vs_named"] == pytest.approx(-2.0 * (_BASE - 40.0) + 2.0 * new.loglik, abs=1e-9)
