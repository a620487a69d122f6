"""Two edges of the catalogue a researcher's table can land on exactly.

A response that is exactly 0 somewhere (a count, a response measured from a baseline) gets no Box-Cox test: a
power transform is defined on positive values only, so the catalogue leaves it out rather than fail; the smallest
positive response keeps it.  Replicates that agree to round-off (their root-mean-square pure error at most the
response's round-off floor, demid.precision.round_off_floor) leave lack of fit undefined, as in the ANOVA; just
above the floor the test is made, and its F is the classical one written out here with numpy."""
from __future__ import annotations

import numpy as np
import pandas as pd
import pytest

from demid.criticism import criticize
from demid.criticism.catalogue import Round
from demid.criticism.level1 import prepare_data
from demid.criticism.models import Model, ModelForm
from demid.precision import round_off_floor


def _round(table: pd.DataFrame) -> Round:
    data, _ = prepare_data(table, ["a", "b"], "y", 1.0, (), None)
    return Round(data, Model(data, ModelForm()), 19, np.random.default_rng(0))


def _exponential_table(smallest: float) -> pd.DataFrame:
    levels = np.linspace(1.0, 3.0, 4)
    a, b = (g.ravel() for g in np.meshgrid(levels, levels))
    rng = np.random.default_rng(0)
    y = np.exp(0.8 * a + 0.3 * b) * (1 + 0.02 * rng.standard_normal(len(a)))
    return pd.DataFrame({"run": np.arange(1, len(a) + 1), "a": a, "b": b, "y": y - y.min() + smallest})


@pytest.mark.parametrize("smallest, tested", [(0.0, False), (1e-3, True)])
def test_a_response_of_exactly_zero_gets_no_box_cox_test(smallest, tested):
    table = _exponential_table(smallest)
    assert (table["y"].min() == 0.0) == (not tested)
    causes = [h.cause for h in _round(table).hypotheses]
    assert ("response_transform" in causes) == tested
    assert "missing_term" in causes and "outlier" in causes  # the rest of the catalogue is tested either way
    result = criticize(table, ["a", "b"], "y", n_null=99)
    assert ("response_transform" in [c["cause"] for c in result.catalogue]) == tested


def _replicated_cubic(rms_over_floor: float) -> tuple[pd.DataFrame, float]:
    """A 3x3 factorial run twice, a cubic in a (lack of fit), each pair's two runs apart by a round-off-sized
    amount chosen so that the pure error's root mean square is ``rms_over_floor`` times the floor."""
    levels = np.array([1.0, 2.0, 3.0])
    a, b = (np.repeat(g.ravel(), 2) for g in np.meshgrid(levels, levels))
    rng = np.random.default_rng(0)
    base = 10 + a - 0.3 * b ** 2 + 0.4 * a ** 3 + np.repeat(0.2 * rng.standard_normal(9), 2) + np.pi * 1e-3
    floor = round_off_floor(base)
    # a pair at base +- d has pure-error SS 2 d^2 on one degree of freedom: rms = sqrt(2) d
    y = base + np.tile([1.0, -1.0], 9) * rms_over_floor * floor / np.sqrt(2)
    return pd.DataFrame({"run": np.arange(1, 19), "a": a, "b": b, "y": y}), floor


def _classical_lack_of_fit(table: pd.DataFrame) -> tuple[float, float]:
    """(the pure error's root mean square, the lack-of-fit F) of the full quadratic, written out."""
    a, b, y = (table[c].to_numpy() for c in ("a", "b", "y"))
    x = np.column_stack([np.ones_like(a), a, b, a * b, a * a, b * b])
    sse = float(np.sum((y - x @ np.linalg.lstsq(x, y, rcond=None)[0]) ** 2))
    group = np.repeat(np.arange(9), 2)
    sspe = float(np.sum((y - (np.bincount(group, weights=y) / 2)[group]) ** 2))
    return np.sqrt(sspe / 9), ((sse - sspe) / 3) / (sspe / 9)


@pytest.mark.parametrize("rms_over_floor, tested", [(0.5, False), (0.9, False), (1.1, True), (2.0, True)])
def test_replicates_agreeing_to_round_off_leave_lack_of_fit_untested(rms_over_floor, tested):
    table, floor = _replicated_cubic(rms_over_floor)
    rms, f = _classical_lack_of_fit(table)
    assert rms / round_off_floor(table["y"]) == pytest.approx(rms_over_floor, rel=1e-3)
    found = [h for h in _round(table).hypotheses if h.cause == "lack_of_fit"]
    assert bool(found) == tested
    if tested:  # the F of a pure error of round-off is huge, and the catalogue's is the classical one (to the
        # round-off of a pure error of 1e-8 carried through the residuals' sums of squares)
        assert found[0].statistic == pytest.approx(f, rel=2e-2)
        assert found[0].info["df"] == [3, 9]
