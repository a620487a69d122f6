"""A model extension that adds no factor (the same factors, another contact model): its sentence opens "Extending
the model of", whether the row carries no added factor as an empty text (a table row, or the report's row with
NaN filled) or as None (a row read from JSON), and is otherwise the sentence of a row that names its factors."""

from __future__ import annotations

import pytest

from demid.story.extensions import extension_sentence


def _row(added):
    return {"material": "ext", "extends": "base", "added_factors": added, "best_error_before": 0.237,
            "best_error_after": 0.012, "feasible_fraction_before_pct": 0.0, "feasible_fraction_after_pct": 12.5,
            "surrogate_q2_before": 0.9, "surrogate_q2_after": 0.8}


@pytest.mark.parametrize("missing", ["", None])
def test_an_extension_without_added_factors_reads_extending_the_model(missing):
    labels, factor_labels = {"base": "No rolling", "ext": "Rolling"}, {"mu_r": "μ_r", "e": "e_n"}
    text = extension_sentence(_row(missing), labels, factor_labels, "AoR")
    named = extension_sentence(_row("mu_r+e"), labels, factor_labels, "AoR")
    assert named.startswith("Adding μ_r, e_n to the model of No rolling (Rolling): ")
    assert text == "Extending" + named[len("Adding μ_r, e_n to"):]
