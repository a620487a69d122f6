"""A wave placed over the whole search range, the numbers its outputs quote against computations written here: the
next domain is the box of the runs placed (each factor's smallest and largest), the reason's largest probability
of misclassifying a boundary run (the normal mass inside the band, scipy), the criticism's runs that do not fit in
the count, the predictions of each run, and the wave's expected value counted on its own runs; for targets of
either sign and counts 7-12."""

from __future__ import annotations

import json
import re

import numpy as np
import pandas as pd
import pytest
from scipy.stats import norm

from demid.design import model_matrix, quadratic_terms
from demid.next_wave import PURPOSE_BOUNDARY, PURPOSE_DECIDE, plan_next_wave
from demid.spec import MaterialSpec
from demid.wave_value import expected_contraction
from tests.test_boundary_runs import _linear, _study


@pytest.mark.parametrize("sign, count, deciding, aliased", [(1.0, 9, 0, True), (-1.0, 7, 9, True), (1.0, 12, 2, False),
                                                            (-1.0, 10, 1, True)])
def test_the_omega_waves_domain_reason_predictions_and_value_are_those_of_its_runs(sign, count, deciding, aliased):
    from demid.scenario import JudgedScenario

    table, spec, surrogates, plausible = _study(lambda x: sign * _linear(x), target=sign * 13.0)
    spec = MaterialSpec.from_material("m", {**spec.material_config(),
                                            "next_runs": {"count": count, "scenario": "", "margin": 0.1}})
    rows = [{"response": "y", "cause": "ambiguous", "detail": "", "aliases": "",
             "discriminating_runs": json.dumps([{"a": 0.25, "b": 0.75, "purpose": PURPOSE_DECIDE}] * deciding)}]
    if aliased:
        rows.append({"response": "y", "cause": "missing_term", "aliases": "a^3;a:b^2", "detail": "",
                     "discriminating_runs": "[]"})
    wave = plan_next_wave("m", table, surrogates, spec, plausible, pd.DataFrame(rows), z=2.0, analysed_over_omega=True)
    runs = wave.runs
    placed = runs[["a", "b"]].to_numpy(dtype=float)
    assert len(runs) == count
    assert wave.domain.to_dict("list") == {"material": ["m", "m"], "factor": ["a", "b"],
                                           "lower": list(placed.min(axis=0)), "upper": list(placed.max(axis=0))}
    assert runs["predicted_y"].to_numpy() == pytest.approx(surrogates["y"].predict(placed), rel=1e-9)
    # the earlier CCD runs determine the quadratic, so the criticism's runs may take the whole wave; the ones past
    # its count are left out and counted
    made = int((runs["purpose"] == PURPOSE_DECIDE).sum())
    assert made == min(deciding, count)
    left = re.search(r"; (\d+) more run\(s\) the criticism proposed do not fit in the wave's (\d+) runs", wave.reason)
    assert ((int(left[1]), int(left[2])) if left else (0, count)) == (deciding - made, count)
    boundary = placed[(runs["purpose"] == PURPOSE_BOUNDARY).to_numpy()]
    quoted = re.search(r"the largest probability of misclassifying one of their points is (\d\.\d\d)", wave.reason)
    if len(boundary):
        sur, target = surrogates["y"], spec.targets["y"]
        band = spec.scenarios[0].tolerance * abs(target)
        mean, sd = sur.predict(boundary), sur.se_prediction(boundary)
        p = norm.cdf((target + band - mean) / sd) - norm.cdf((target - band - mean) / sd)
        assert float(quoted[1]) == pytest.approx(np.max(np.minimum(p, 1 - p)), abs=0.005 + 1e-9)
    else:
        assert quoted[1] == "0.00"
    # the separating runs: as many as the reason says, after the criticism's, and with the earlier runs they make
    # a^3 and a:b^2 separately estimable over Omega (here the unit square, coded on [-1, 1])
    separating = (runs["purpose"] == "separate aliased terms a^3 = a:b^2 (y)").to_numpy()
    said = re.search(r", (\d+) to separate aliased terms the criticism found", wave.reason)
    assert (int(said[1]) if said else 0) == int(separating.sum())
    if separating.any():
        assert not separating[:made].any()
        coded = 2.0 * np.vstack([table[["a", "b"]].to_numpy(dtype=float), placed[:made], placed[separating]]) - 1.0
        terms = quadratic_terms(2) + [(3, 0), (1, 2)]
        assert np.linalg.matrix_rank(model_matrix(coded, terms)) == len(terms)
    elif aliased and count > made:
        coded = 2.0 * np.vstack([table[["a", "b"]].to_numpy(dtype=float), placed[:made]]) - 1.0
        terms = quadratic_terms(2) + [(3, 0), (1, 2)]
        assert np.linalg.matrix_rank(model_matrix(coded, terms)) == len(terms)  # nothing left to separate
    judged = JudgedScenario(spec, spec.scenarios[0], surrogates, 2.0)
    value = expected_contraction(judged, placed)
    assert wave.value["count"] == count
    for key in ("plausible_fraction_pct", "expected_fraction_pct"):
        assert wave.value[key] == pytest.approx(value[key], abs=1e-9)


def test_with_too_few_earlier_runs_the_design_keeps_its_share_and_the_criticisms_runs_only_the_rest():
    """Two earlier runs leave the quadratic four coefficients short: of a wave of 9, 4 are design runs and the
    criticism's 12 runs get the other 5, the 7 left out counted in the reason; the wave never exceeds its count."""
    table, spec, surrogates, plausible = _study(_linear)
    spec = MaterialSpec.from_material("m", {**spec.material_config(),
                                            "next_runs": {"count": 9, "scenario": "", "margin": 0.1}})
    findings = pd.DataFrame([{"response": "y", "cause": "ambiguous", "detail": "", "aliases": "",
                              "discriminating_runs": json.dumps([{"a": 0.25, "b": 0.75, "purpose": PURPOSE_DECIDE}] * 12)}])
    earlier = table.iloc[[0, 1]]
    rank = np.linalg.matrix_rank(model_matrix(2.0 * earlier[["a", "b"]].to_numpy(dtype=float) - 1.0, quadratic_terms(2)))
    assert rank == 2
    wave = plan_next_wave("m", earlier, surrogates, spec, plausible, findings, z=2.0, analysed_over_omega=True)
    purposes = wave.runs["purpose"].tolist()
    assert len(purposes) == 9 and purposes.count(PURPOSE_DECIDE) == 9 - (6 - rank)
    assert "; 7 more run(s) the criticism proposed do not fit in the wave's 9 runs" in wave.reason
