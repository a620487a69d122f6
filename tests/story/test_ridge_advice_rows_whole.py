"""A study whose set is a ridge gets the break-the-ridge advice among its advice rows: y1 = a + b pins the band
a + b = 1 and leaves a - b free; of the other observables, 'across' = a - b changes along the band (its gradient
90 degrees off the identified direction) and 'tilted' = a half as much (45 degrees).  The combinations' advice line
(as study_story reads it from combinations/{m}.json) becomes an add_observable row of the material's advice, beside
the ranking's own add-observable row, and the sentence quotes the angles computed here and the ranking's gain."""

from __future__ import annotations

import re

import numpy as np
import pandas as pd
import pytest

from demid.combinations.material import material_combinations
from demid.design import Coding, quadratic_terms
from demid.sampling.grid import admissible_set
from demid.spec import MaterialSpec
from demid.story.advice import StudyAdvice, material_advice
from demid.surrogate import Surrogate
from demid.uncertainty.posterior import NO_OBSERVABLE

CODING = Coding(("a", "b"), (0.5, 0.5), (0.5, 0.5))
TANGENT = np.array([1.0, -1.0]) / np.sqrt(2)  # along the band, coded
SLOPES = {"y1": (1.0, 1.0), "across": (1.0, -1.0), "tilted": (1.0, 0.0)}


def _linear(name, slopes):
    terms = quadratic_terms(2)
    coef = np.zeros(len(terms))
    coef[1:3] = slopes
    return Surrogate(name, ["a", "b"], terms, coef, np.zeros((len(terms), len(terms))), 0.0, 1)


def _angle(slopes) -> float:
    """Degrees between an observable's coded gradient and the band's normal's complement: arcsin(|g.t| / |g|)."""
    g = np.asarray(slopes) * np.asarray(CODING.unit)
    return float(np.degrees(np.arcsin(min(abs(g @ TANGENT) / np.linalg.norm(g), 1.0))))


def _ranking(gain_pair: float) -> pd.DataFrame:
    """The observable ranking's rows (the columns the advice reads) for y1 and one more observable."""
    return pd.DataFrame({
        "observables": ["y1+across", "y1+tilted", "y1", "across", "tilted"],
        "information_gain_bits": [gain_pair, 1.5, 1.0, 0.8, 0.6],
        "feasible_fraction_pct": [0.16, 1.9, 4.0, 4.0, 6.0],
        "best_subset": ["y1", "y1"] + [NO_OBSERVABLE] * 3,
        "n_observables": [2, 2, 1, 1, 1],
        "gain_vs_best_subset_bits": [gain_pair - 1.0, 0.5, 1.0, 0.8, 0.6],
        "targets_reachable": [True] * 5})


@pytest.mark.parametrize("gain_pair", [3.257, 4.5])
def test_a_ridge_gets_its_break_the_ridge_row_quoting_the_angles_and_the_gain(gain_pair):
    spec = MaterialSpec.from_material("m", {
        "data": "x.csv", "design": {"type": "custom"},
        "factors": {"a": {"lower": 0.0, "upper": 1.0}, "b": {"lower": 0.0, "upper": 1.0}},
        "responses": {"y1": {"target": 1.0}, "across": {"target": 0.0}, "tilted": {"target": 0.5}},
        "scenarios": {"band": {"observables": ["y1"], "tolerance": 0.02}}}, grid_points=201)
    surrogates = {name: _linear(name, s) for name, s in SLOPES.items()}
    strict = {"band": admissible_set({"y1": surrogates["y1"]}, spec.domain, ["y1"], {"y1": 1.0}, 0.02, 201)}
    ranking = _ranking(gain_pair)
    found = material_combinations(surrogates, spec, CODING, strict, {}, ranking)
    ridge = found.to_json()["advice"]  # what study_story hands on
    assert len(ridge) == 1  # premise: the band is a ridge with others at hand

    items = material_advice(spec, pd.DataFrame(columns=["scenario", "factor", "verdict"]), ranking=ranking,
                            ridge_advice=ridge)
    rows = StudyAdvice(items).to_frame()
    adds = rows[rows["kind"] == "add_observable"]
    # the ranking's own row (naming the observable) and the ridge's row, in that order
    assert adds["observable"].tolist() == ["across", ""]
    (text,) = adds.loc[adds["observable"] == "", "text"]
    assert text == ridge[0] and (adds["material"] == "m").all()
    assert adds["text"].iloc[0].startswith(f"Measure across as well: it adds {gain_pair - 1.0:.2f} bits")
    assert text.startswith("*band* identifies a combination and leaves its complement free: across changes most "
                           "along the set")
    said = re.search(r"its gradient lies (\d+)° off the identified direction; tilted (\d+)°\), so adding its "
                     r"measurement would break the ridge; with it the ranking gives ([\d.]+) bits\.$", text)
    assert said is not None, text
    assert int(said[1]) == round(_angle(SLOPES["across"])) == 90
    assert int(said[2]) == round(_angle(SLOPES["tilted"])) == 45
    assert said[3] == f"{gain_pair:.2f}"
    # the next step is the ranking's measurement; the ridge's row is advice, not a second step
    assert rows["decision"].tolist()[:2] == [True, False] and rows["kind"].iloc[0] == "add_observable"
