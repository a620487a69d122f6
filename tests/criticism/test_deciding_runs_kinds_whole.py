"""Which candidates the deciding and confirming runs separate (criticism.naming's runs of close candidates), against
the documented rule written out and handed to discrimination.discriminating_runs: deciding between causes (the
ambiguity), a missing term and the terms the runs alias with it are one kind (not separated from each other), an
outlier and a slipped value of the same run are one kind; confirming a named term, the runs also tell it from
its aliases (each alias a kind of its own), and still not a run's two readings from each other.  2-factor CCDs
where a^3 and a:b^2 are aliased on the runs."""

from __future__ import annotations

import pytest

from demid.criticism.discrimination import CONFIRM_PURPOSE, PURPOSE, candidate_label, discriminating_runs
from demid.criticism.models import Model, ModelForm
from demid.criticism.naming import _deciding_runs
from demid.design import parse_term
from tests.criticism.test_models_properties import _data


def _close(data):
    cubic, alias = parse_term("a^3", ["a", "b"]), parse_term("a:b^2", ["a", "b"])
    run = int(data.runs[4])
    return [
        {"cause": "missing_term", "detail": "a^3", "aicc": 10.0, "model": Model(data, ModelForm(extra_terms=(cubic,))),
         "aliased": ["a:b^2"], "aliased_models": [Model(data, ModelForm(extra_terms=(alias,)))]},
        {"cause": "outlier", "detail": run, "aicc": 11.5, "model": Model(data, ModelForm(dropped=(4,)))},
        {"cause": "factor_level", "detail": run, "aicc": 12.0,
         "model": Model(data, ModelForm(moved=((4, 0, float(data.coded[4, 0]) * 0.5 + 0.25),)))},
    ]


@pytest.mark.parametrize("seed", [0, 3, 7])
def test_deciding_runs_separate_kinds_and_confirming_runs_also_aliases(seed):
    data = _data(seed, 3)
    close = _close(data)
    models = [close[0]["model"], close[0]["aliased_models"][0], close[1]["model"], close[2]["model"]]
    labels = [candidate_label("missing_term", "a^3"), candidate_label("missing_term", "a:b^2"),
              candidate_label("outlier", close[1]["detail"]), candidate_label("factor_level", close[2]["detail"])]
    aiccs = [10.0, 10.0, 11.5, 12.0]
    one_run = ("one run", str(close[1]["detail"]))
    deciding = [("missing_term",), ("missing_term",), one_run, one_run]
    confirming = [("missing_term",), ("alias", labels[1]), one_run, one_run]
    for purpose, kinds in ((PURPOSE, deciding), (CONFIRM_PURPOSE, confirming)):
        expected = discriminating_runs(data, models, labels, aiccs, kinds, purpose)
        got = _deciding_runs(data, close, purpose, named=("missing_term", "a^3"))
        assert got == expected, purpose
        assert got and all(r["purpose"] == purpose for r in got)
    # the two rules give other runs here: the kinds matter
    assert discriminating_runs(data, models, labels, aiccs, deciding, PURPOSE) != \
        discriminating_runs(data, models, labels, aiccs, confirming, PURPOSE)
