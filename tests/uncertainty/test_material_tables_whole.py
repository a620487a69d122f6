"""One material's ranking and information-gain tables where the answers are closed-form: y0 = s a and y1 = s b
on the unit square (either sign), targets at the middle, so a set at tolerance ε keeps a share ε of each factor's
range; a third observable whose whole range lies far from its target.  Scenarios at a looser tolerance than the
reference one (the tolerance of the scenario with the most observables) hold the same observables, so only the
reference tolerance's strict sets may stand for the ranking's: every single and pair fraction is ε or ε² of Ω.
Sets with the far target carry neither an information gain nor its error, in every table; the others' gains are
the ranking's, one number."""

from __future__ import annotations

import numpy as np
import pytest

from demid.spec import MaterialSpec
from demid.uncertainty.material import analyse_material

from .test_uncertainty import linear

_SIZES = {"plausible": 21, "sweep": 11, "posterior": 21}


@pytest.mark.parametrize("sign, reference", [(1.0, 0.05), (-1.0, 0.02)])
def test_the_ranking_reads_strict_sets_at_its_own_tolerance_and_unreachable_sets_have_no_gain(sign, reference):
    surrogates = {"y0": linear(0.0, [10.0 * sign, 0.0]), "y1": linear(0.0, [0.0, 10.0 * sign]),
                  "y2": linear(20.0 * sign, [10.0 * sign, 0.0])}
    for name, sur in surrogates.items():
        sur.response = name
    scenarios = {"loose": {"observables": ["y0"], "tolerance": 0.2},
                 "loose_pair": {"observables": ["y0", "y1"], "tolerance": 0.3},
                 "all": {"observables": ["y0", "y1", "y2"], "tolerance": reference},
                 "far": {"observables": ["y2"], "tolerance": reference}}
    spec = MaterialSpec.from_material("m", {
        "data": "x.csv", "design": {"type": "custom"},
        "factors": {"a": {"lower": 0.0, "upper": 1.0}, "b": {"lower": 0.0, "upper": 1.0}},
        "responses": {o: {"target": 5.0 * sign} for o in surrogates}, "scenarios": scenarios})
    assert spec.reference_tolerance == reference
    result = analyse_material(surrogates, spec, tolerances=[0.1], sizes=_SIZES)

    ranking = result.ranking.set_index("observables")
    assert set(ranking["tolerance"]) == {reference}
    # |10 a - 5| <= 5 ε: a share ε of a's range; the pair: ε of each range
    assert ranking.loc["y0", "feasible_fraction_pct"] == pytest.approx(100 * reference, rel=1e-6)
    assert ranking.loc["y1", "feasible_fraction_pct"] == pytest.approx(100 * reference, rel=1e-6)
    assert ranking.loc["y0+y1", "feasible_fraction_pct"] == pytest.approx(100 * reference ** 2, rel=1e-6)
    far = [s for s in ranking.index if "y2" in s.split("+")]
    assert len(far) == 4 and not ranking.loc[far, "targets_reachable"].any()
    assert ranking.loc[far, "information_gain_bits"].isna().all()
    assert ranking.loc[far, "information_gain_error_bits"].isna().all()
    assert result.unreachable and set(result.unreachable) == set(far)

    gains = result.information_gain
    for observables, rows in gains.groupby("observables"):
        if observables in far:
            assert rows["information_gain_bits"].isna().all(), observables
            assert rows["information_gain_error_bits"].isna().all(), observables
        else:
            assert set(rows["information_gain_bits"]) == {ranking.loc[observables, "information_gain_bits"]}
            assert set(rows["information_gain_error_bits"]) == {ranking.loc[observables, "information_gain_error_bits"]}
            assert np.isfinite(rows["information_gain_bits"]).all() and np.isfinite(rows["information_gain_error_bits"]).all()
