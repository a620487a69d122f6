"""A level-1 finding's "Almost as likely" sentence (criticism.level1's finding of a round): it lists, in the
order given, the alternatives whose log-likelihood is less than 2 units below the named cause's -- one exactly 2
below is not listed, one a bit less is, one without a likelihood is not -- and the finding keeps every
alternative in its info; an outlier planted in a 2-factor CCD gives the named cause."""

from __future__ import annotations

import numpy as np
import pytest

from demid.criticism.catalogue import Round
from demid.criticism.level1 import _finding, prepare_data
from demid.criticism.messages import CAUSE_WORDS
from demid.criticism.models import Model, ModelForm
from demid.criticism.naming import name_cause
from tests.generators import FACTORS, ccd_table


@pytest.fixture(scope="module")
def named():
    table, _ = ccd_table(3, 2, "outlier", size=9.0)
    data, _ = prepare_data(table, FACTORS[2], "y", None, ())
    model = Model(data, ModelForm())
    rejected = Round(data, model, 99, np.random.default_rng(0)).rejected(0.05)
    return data, model, name_cause(data, model, rejected)


def _alternative(cause, detail, loglik):
    return {"cause": cause, "detail": detail, "p_value": 0.01, "loglik_vs_named": loglik, "aicc_vs_named": None}


@pytest.mark.parametrize("gaps", [(-2.0, float(np.nextafter(-2.0, 0.0)), -0.5, None, -2.5),
                                  (-0.0, -2.0, -1.0, -3.0, None), (-2.0, -2.0, -2.5, None, -7.0)])
def test_almost_as_likely_lists_the_alternatives_less_than_two_log_likelihood_units_below(named, gaps):
    data, model, (h, spec, info, new, _) = named
    assert h.cause == "outlier"
    kinds = [("heteroscedasticity", "a"), ("drift", "run"), ("missing_term", "a^3"), ("step", 4),
             ("response_transform", "log")]
    alternatives = [_alternative(c, d, g) for (c, d), g in zip(kinds, gaps)]
    finding = _finding(data, "y", model, h, spec, dict(info), new, alternatives)
    close = [f"{CAUSE_WORDS[a['cause']]} {a['detail']}" for a in alternatives
             if a["loglik_vs_named"] is not None and a["loglik_vs_named"] > -2.0]
    if close:
        assert finding.message.endswith(" Almost as likely: " + "; ".join(close) + ".")
    else:
        assert "Almost as likely" not in finding.message
    assert finding.info["alternatives"] == alternatives


def test_another_run_of_the_named_cause_almost_as_likely_is_listed(named):
    # a second outlying run fitted nearly as well is a close alternative like any other cause
    data, model, (h, spec, info, new, _) = named
    assert h.cause == "outlier"
    others = [r for r in data.runs.tolist() if r != h.detail][:2]
    alternatives = [_alternative("outlier", others[0], -0.5), _alternative("outlier", others[1], -2.5)]
    finding = _finding(data, "y", model, h, spec, dict(info), new, alternatives)
    assert finding.message.endswith(f" Almost as likely: {CAUSE_WORDS['outlier']} {others[0]}.")
