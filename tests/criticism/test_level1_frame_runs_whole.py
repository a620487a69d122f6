"""Level 1's table and alias sets where the earlier tests held something fixed (criticism.level1): the runs for the
next wave ride on the row they serve -- the unexplained row when nothing is named, the first finding's row when
causes are named -- and nowhere else; an alias set gets separating runs only when it holds more than one term or
cannot be estimated (a single estimable term needs none), each set's runs those of
aliasing.separating_runs for its terms."""

from __future__ import annotations

import json
from dataclasses import replace
from types import SimpleNamespace

import pandas as pd
import pytest

from demid.criticism import criticize
from demid.criticism.aliasing import separating_runs
from demid.criticism.level1 import prepare_data
from demid.design import parse_term, quadratic_terms
from tests.generators import FACTORS, ccd_table


@pytest.fixture(scope="module")
def clean():
    table, _ = ccd_table(4, 2, "clean")
    return table, criticize(table, FACTORS[2], "y", n_null=99)


def _finding(cause):
    return SimpleNamespace(cause=cause, detail="a^3", aliases=[], p_value=0.01, loo_rmse_baseline=1.0,
                           loo_rmse_extended=0.5, delta_aicc=-4.0, message=f"{cause} found")


def test_the_next_waves_runs_ride_on_the_row_they_serve(clean):
    _, result = clean
    runs = [{"mu_r": 0.5, "gamma": 8.0, "purpose": "decide", "replicate_of": 3}]
    unexplained = replace(result, verdict="unexplained", discriminating_runs=runs,
                          unexplained={"detail": "lack_of_fit", "p_value": 0.003, "message": "misfit"})
    frame = unexplained.to_frame()
    assert list(frame["cause"]) == ["unexplained"]
    assert json.loads(frame["discriminating_runs"].iloc[0]) == runs
    named = replace(result, verdict="defect", findings=[_finding("missing_term"), _finding("drift")],
                    discriminating_runs=runs)
    frame = named.to_frame()
    assert list(frame["cause"]) == ["missing_term", "drift"]
    assert json.loads(frame["discriminating_runs"].iloc[0]) == runs and pd.isna(frame["discriminating_runs"].iloc[1])
    assert "discriminating_runs" not in replace(named, discriminating_runs=[]).to_frame()


def test_alias_sets_get_separating_runs_only_for_several_terms_or_none_estimable():
    table, _ = ccd_table(4, 3, "clean")  # a^3 with a:b^2 and a:c^2, ..., and a:b:c alone
    result = criticize(table, FACTORS[3], "y", n_null=99)
    data, _ = prepare_data(table, FACTORS[3], "y", None, ())
    assert result.alias_sets
    for a in result.alias_sets:
        terms = [parse_term(t, FACTORS[3]) for t in a.members]
        if len(terms) == 1 and a.testable:
            assert a.extra_runs == ()
        else:
            expected = separating_runs(data.coded, quadratic_terms(3), terms, data.alpha)
            assert a.extra_runs == tuple(data.point_dict(p) for p in expected)
    assert any(len(a.members) == 1 and a.testable for a in result.alias_sets)
    assert any(a.extra_runs for a in result.alias_sets)
