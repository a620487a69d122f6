"""A weighted model's unequal-scatter evidence is not said to rest on one run: the leave-one-run-out test is
not run for weighted models (worst_deletion returns None), and rests_on_one_run passes that None on instead
of reading a deletion that does not exist."""
from __future__ import annotations

from dataclasses import replace

import numpy as np

from demid.criticism.catalogue import Hypothesis
from demid.criticism.level1 import prepare_data
from demid.criticism.models import Model, ModelForm
from demid.criticism.naming import why_not_singled_out
from demid.criticism.one_run import worst_deletion
from demid.criticism.verdict import rests_on_one_run

from ..generators import FACTORS, ccd_table


def test_weighted_model_scatter_does_not_rest_on_one_run():
    table, _ = ccd_table(5, 3, "clean")
    data, _ = prepare_data(table, FACTORS[3], "y", None, ())
    values = data.coded[:, 0] / data.alpha
    spec = replace(ModelForm(), weight_on=data.factors[0], weight_gamma=0.7,
                   weight_values=tuple(float(v) for v in values))
    model = Model(data, spec)
    assert np.ptp(model.w) > 0  # really weighted
    het = Hypothesis("heteroscedasticity", data.factors[1])
    assert worst_deletion(data, model, het) is None
    assert rests_on_one_run(data, model, het) is None
    assert why_not_singled_out(data, model, het, [het]) is None
