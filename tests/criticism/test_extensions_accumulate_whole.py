"""A cause's extension adds to the model it extends, never replaces it (criticism.extensions.extend_for): on a
model that already carries an extra term, a dropped run and a moved factor value (an earlier round's findings),
each cause's form is that model's form with its one field extended -- the term appended, the run dropped too,
the slip moved too, drift or the step set -- and an outlier's quoted values are the run's observation and the
prediction of a least-squares refit without it; the drift and step sizes are the coefficients of that refit."""

from __future__ import annotations

from dataclasses import replace

import numpy as np
import pytest

from demid.criticism.aliasing import TermClass
from demid.criticism.catalogue import Hypothesis
from demid.criticism.extensions import drift_per_run, extend_for, step_size
from demid.criticism.models import Model, ModelForm
from demid.criticism.slips import SlipCandidate
from demid.design import model_matrix, parse_term
from tests.criticism.test_models_properties import _data


@pytest.fixture(scope="module", params=[0, 1])
def earlier(request):
    data = _data(request.param, 3)
    spec = ModelForm(extra_terms=(parse_term("a^2:b", ["a", "b"]),), dropped=(4,), moved=((1, 0, 0.5),))
    return data, Model(data, spec)


def test_each_cause_extends_the_earlier_form_by_its_own_field(earlier):
    data, model = earlier
    spec = model.spec
    term = parse_term("a:b^2", ["a", "b"])
    cases = {
        "missing_term": (Hypothesis("missing_term", TermClass([term], None), ["a:b^2"]),
                         replace(spec, extra_terms=spec.extra_terms + (term,))),
        "drift": (Hypothesis("drift", "run"), replace(spec, drift=True)),
        "step": (Hypothesis("step", 7), replace(spec, step=7)),
        "outlier": (Hypothesis("outlier", 9), replace(spec, dropped=(4, 9))),
        "factor_level": (Hypothesis("factor_level", SlipCandidate(row=6, factor=1, power=1, coded=-0.25),
                                    info={"t_moved": 1.0, "bayes_factor": 30.0, "t_recorded": 5.0}),
                         replace(spec, moved=((1, 0, 0.5), (6, 1, -0.25)))),
    }
    for cause, (h, expected) in cases.items():
        form, _ = extend_for(data, model, h)
        assert form == expected, cause
        assert Model(data, form).n_params == model.n_params + (cause in ("outlier", "step", "drift",
                                                                        "missing_term")), cause


def test_an_outliers_values_drift_and_step_are_those_of_refits(earlier):
    data, model = earlier
    keep = model.keep.copy()
    coded = data.coded.copy()
    coded[1, 0] = 0.5  # the earlier moved value
    x = model_matrix(coded, list(data.base_terms) + list(model.spec.extra_terms))
    _, info = extend_for(data, model, Hypothesis("outlier", 9))
    others = keep.copy()
    others[9] = False
    beta = np.linalg.lstsq(x[others], data.y[others], rcond=None)[0]
    assert info["observed"] == data.y[9]
    assert info["predicted_without"] == pytest.approx(float(x[9] @ beta), rel=1e-9)
    runs = data.runs.astype(float)
    drift = Model(data, extend_for(data, model, Hypothesis("drift", "run"))[0])
    column = (runs - runs[keep].mean()) / np.ptp(runs)
    beta = np.linalg.lstsq(np.column_stack([x, column])[keep], data.y[keep], rcond=None)[0]
    assert drift_per_run(drift) == pytest.approx(beta[-1] / np.ptp(runs), rel=1e-8)
    step = Model(data, extend_for(data, model, Hypothesis("step", 7))[0])
    after = (runs >= runs[7]).astype(float)
    beta = np.linalg.lstsq(np.column_stack([x, after])[keep], data.y[keep], rcond=None)[0]
    assert step_size(step) == pytest.approx(beta[-1], rel=1e-8)
