"""A material with targets but no scenario (a study that only asks which measurement to make): the uncertainty
analysis still ranks every observable set, judged at the fallback tolerance, and recommends no point (there is no
scenario to recommend it for) instead of failing.  On observables linear in their own factor, the strict fraction
of a set is the product of its bands' shares, 2 ε |t| / |slope| over each factor's range, written out here."""

from __future__ import annotations

import numpy as np
import pytest

from demid.spec import FALLBACK_TOLERANCE, MaterialSpec
from demid.uncertainty.material import analyse_material

from .test_material_whole import _SIZES, _study


@pytest.mark.parametrize("seed", [3, 11])
def test_a_material_without_scenarios_ranks_its_observables_and_recommends_no_point(seed):
    spec, surrogates, targets, centres, slopes, (lo, hi) = _study(seed, True, False)
    bare = MaterialSpec.from_material("m", {
        "data": "x.csv", "design": {"type": "custom"},
        "factors": {"a": {"lower": float(lo[0]), "upper": float(hi[0])},
                    "b": {"lower": float(lo[1]), "upper": float(hi[1])}},
        "responses": {o: {"target": float(t)} for o, t in targets.items()}, "scenarios": {}})
    assert bare.scenarios == ()
    result = analyse_material(surrogates, bare, tolerances=[0.1], sizes=_SIZES)
    assert result.recommended is None and result.summary["recommended"] is None
    assert len(result.plausible) == 0 and result.uninformative == {}
    share = {o: 2 * FALLBACK_TOLERANCE * abs(targets[o]) / abs(slopes[o]) / (hi[k] - lo[k])
             for k, o in enumerate(("y0", "y1"))}
    expected = {"y0": share["y0"], "y1": share["y1"], "y0+y1": share["y0"] * share["y1"]}
    ranking = result.ranking.set_index("observables")
    assert sorted(ranking.index) == sorted(expected)
    for s, fraction in expected.items():
        assert ranking.loc[s, "feasible_fraction_pct"] == pytest.approx(100 * fraction, rel=1e-6)
        assert np.isfinite(ranking.loc[s, "information_gain_bits"]) and ranking.loc[s, "targets_reachable"]
    assert result.ranking["rank"].tolist() == [1, 2, 3]
    assert result.ranking["observables"].iloc[0] == "y0+y1"
