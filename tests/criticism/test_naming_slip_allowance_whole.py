"""When level 1 names a slipped factor level (criticism.naming.name_cause): its Bayes factor against a mean shift
of the run reaches SLIP_BAYES_FACTOR and no other extension but the outlier's beats it by more than its added
parameters, with one log-likelihood unit of allowance: the slip is named when its log-likelihood is at least
max over the others of (loglik - n_params + the slip's n_params) - 1.  The extensions' fits are stand-ins with the
log-likelihoods and parameter counts written here (dyadic numbers, so each margin is exact): margins of exactly
-1, just below, between -1 and +1, and the Bayes factor exactly at its threshold and just under; 1-3 other causes
whose raw and parameter-adjusted orders differ.  The whole return is checked against the rule written out."""

from __future__ import annotations

from types import SimpleNamespace

import numpy as np
import pytest

from demid.criticism import naming
from demid.criticism.catalogue import Hypothesis
from demid.criticism.verdict import SLIP_BAYES_FACTOR

_RUNS = np.arange(101, 114)  # run labels that are not row indexes


def _name(monkeypatch, rejected, fits):
    """name_cause over ``rejected`` whose extensions fit as ``fits`` (loglik, n_params per hypothesis)."""
    models = {id(h): SimpleNamespace(loglik=ll, n_params=k, aicc=-2.0 * ll + 2.0 * k + 0.25 * k * k)
              for h, (ll, k) in zip(rejected, fits)}
    monkeypatch.setattr(naming, "extend_for", lambda data, model, h: (SimpleNamespace(lam=None, key=id(h)), {}))
    monkeypatch.setattr(naming, "Model", lambda data, spec: models[spec.key])
    return naming.name_cause(SimpleNamespace(runs=_RUNS), None, rejected), models


def _slip(bf, row=3):
    return Hypothesis("factor_level", SimpleNamespace(row=row), logp=-6.0, info={"bayes_factor": bf}, p_family=0.02)


def _others(n):
    """1-3 other causes: a missing term, unequal scatter, a drift, each with its own parameter count."""
    pool = [Hypothesis("missing_term", "a^2", aliases=["a^2", "b^2"], logp=-7.0, p_family=0.01),
            Hypothesis("heteroscedasticity", "b", logp=-5.0, p_family=0.05),
            Hypothesis("drift", "run", logp=-4.0, p_family=0.2)]
    return pool[:n]


def _expected_detail(h):
    if h.cause == "factor_level":
        return int(_RUNS[h.detail.row])
    if h.cause == "outlier":
        return int(_RUNS[int(h.detail)])
    if h.cause == "missing_term":
        return h.aliases[0]
    return h.detail


# the others' (loglik, n_params) and the slip's n_params: the best other after the parameter adjustment is not the
# raw best
_CASES = {
    1: ([(-11.0, 9)], 8),                                 # adjusted max -12.0
    2: ([(-10.0, 11), (-11.5, 9)], 9),                    # adjusted: -10 - 2 = -12.0, -11.5 - 0 = -11.5 -> -11.5
    3: ([(-10.0, 12), (-12.0, 8), (-11.25, 10)], 10),     # adjusted: -12.0, -10.0, -11.25 -> -10.0
}


@pytest.mark.parametrize("n_others", [1, 2, 3])
@pytest.mark.parametrize("margin", [-1.0, -1.0 - 2.0 ** -20, -0.5, 0.75])
@pytest.mark.parametrize("slip_first,bf_offset", [(False, 0.0), (True, 0.0), (False, 2.0 ** -30),
                                                  (True, -2.0 ** -30)])
def test_the_slip_is_named_within_one_log_likelihood_unit_of_the_best_other_adjusted_for_parameters(
        monkeypatch, n_others, margin, bf_offset, slip_first):
    other_fits, k_slip = _CASES[n_others]
    others = _others(n_others)
    # an outlier reading of the same run, fitting far better: it is no rival of the slip's
    outlier = Hypothesis("outlier", 3, logp=-8.0, p_family=0.001)
    adjusted = [ll - k + k_slip for ll, k in other_fits]
    best_other = max(adjusted)
    slip = _slip(SLIP_BAYES_FACTOR + bf_offset)
    slip_fit = (best_other + margin, k_slip)
    outlier_fit = (best_other + 30.0, k_slip + 1)
    if slip_first:
        rejected, fits = [slip, *others, outlier], [slip_fit, *other_fits, outlier_fit]
    else:
        rejected, fits = [*others, slip, outlier], [*other_fits, slip_fit, outlier_fit]
    (h, spec, info, new, alternatives), models = _name(monkeypatch, rejected, fits)

    slip_named = bf_offset >= 0.0 and slip_fit[0] >= best_other - 1.0
    # otherwise the first non-slip cause listed: the missing term, which starts no scatter or run-order contest
    expected = slip if slip_named else others[0]
    assert h is expected
    assert new is models[id(expected)]
    assert spec.key == id(expected) and info == {}
    # the alternatives: every other rejected cause, in the order listed, with its numbers against the named
    rest = [c for c in rejected if c is not expected]
    assert [a["cause"] for a in alternatives] == [c.cause for c in rest]
    for a, c in zip(alternatives, rest):
        m = models[id(c)]
        assert a["detail"] == _expected_detail(c)
        assert a["p_value"] == c.p_family
        assert a["loglik_vs_named"] == m.loglik - new.loglik
        assert a["aicc_vs_named"] == m.aicc - new.aicc


@pytest.mark.parametrize("margin", [-1.0, -0.5, 0.0, 5.0])
def test_a_slip_beside_only_an_outlier_reading_is_named_whatever_the_outlier_fits(monkeypatch, margin):
    slip = _slip(SLIP_BAYES_FACTOR)
    outlier = Hypothesis("outlier", 3, logp=-8.0, p_family=0.001)
    (h, _, _, new, alternatives), models = _name(monkeypatch, [outlier, slip], [(-10.0, 9), (-10.0 + margin, 8)])
    assert h is slip and new.loglik == -10.0 + margin
    assert alternatives == [{"cause": "outlier", "detail": 104, "p_value": 0.001,
                             "loglik_vs_named": -margin, "aicc_vs_named": models[id(outlier)].aicc - new.aicc}]


def test_a_slip_below_its_bayes_factor_alone_names_nothing(monkeypatch):
    (result, _) = _name(monkeypatch, [_slip(SLIP_BAYES_FACTOR - 2.0 ** -30)], [(-10.0, 8)])
    assert result is None
    (h, _, _, new, alternatives), _ = _name(monkeypatch, [_slip(SLIP_BAYES_FACTOR)], [(-10.0, 8)])
    assert h.cause == "factor_level" and new.loglik == -10.0 and alternatives == []
