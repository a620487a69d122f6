"""An observable's own tolerance reaches the posteriors, the information gain and the ranking, as it reaches
the sets.

Known answer: y1 = a and y2 = b on [0, 1]^2, exact (no standard error), no σ configured.  The likelihood
width is then the observable's band read as a z-sigma band, σ = a_k / z, so the posterior of y1 alone is
a normal of that σ around a = y1*, truncated to [0, 1], and its information gain against the uniform prior
is minus its differential entropy in bits (scipy's truncated normal, independent of demid's quadrature).
"""

from __future__ import annotations

from dataclasses import replace

import numpy as np
import pytest
from scipy import stats

from demid.spec import MaterialSpec
from demid.uncertainty import analyse_material

from .test_uncertainty import linear

TOLERANCE, Z = 0.1, 2.0
TARGETS = {"y1": 0.5, "y2": 0.6}
SIZES = {"plausible": 101, "sweep": 21, "posterior": 801}


def _material(**own):
    responses = {name: {"target": target, **own.get(name, {})} for name, target in TARGETS.items()}
    return MaterialSpec.from_material("m", {
        "design": {"type": "ccd"}, "factors": {"a": {"lower": 0.0, "upper": 1.0}, "b": {"lower": 0.0, "upper": 1.0}},
        "responses": responses, "scenarios": {"both": {"observables": ["y1", "y2"], "tolerance": TOLERANCE}}})


def _surrogates():
    return {"y1": replace(linear(0.0, [1.0, 0.0]), response="y1"),
            "y2": replace(linear(0.0, [0.0, 1.0]), response="y2")}


def _gain_bits(centre: float, sigma: float) -> float:
    """KL(truncated normal on [0, 1] || uniform on [0, 1]) in bits = -entropy / ln 2."""
    law = stats.truncnorm((0.0 - centre) / sigma, (1.0 - centre) / sigma, loc=centre, scale=sigma)
    return -float(law.entropy()) / np.log(2.0)


def _single_gains(result) -> dict[str, float]:
    rows = result.ranking[result.ranking["n_observables"] == 1]
    return dict(zip(rows["observables"], rows["information_gain_bits"].astype(float)))


def _first_single(result) -> str:
    return str(result.ranking.loc[result.ranking["n_observables"] == 1, "observables"].iloc[0])


@pytest.mark.parametrize("own", [{"tolerance_abs": 0.2}, {"tolerance": 0.4}])
def test_an_own_tolerance_moves_the_information_gain_and_the_ranking(own):
    plain = analyse_material(_surrogates(), _material(), z=Z, tolerances=[TOLERANCE], sizes=SIZES)
    gains = _single_gains(plain)
    # without an own tolerance: σ = ε |y*| / z for both, so y1 (the smaller target) is the narrower posterior
    assert gains["y1"] == pytest.approx(_gain_bits(0.5, TOLERANCE * 0.5 / Z), abs=0.01)
    assert gains["y2"] == pytest.approx(_gain_bits(0.6, TOLERANCE * 0.6 / Z), abs=0.01)
    assert _first_single(plain) == "y1"

    # y1's own band is ±0.2 (absolute, or 0.4 x |0.5|): σ = 0.2 / z, a wider posterior, less information
    loose = analyse_material(_surrogates(), _material(y1=own), z=Z, tolerances=[TOLERANCE], sizes=SIZES)
    moved = _single_gains(loose)
    assert moved["y1"] == pytest.approx(_gain_bits(0.5, 0.2 / Z), abs=0.01)
    assert moved["y1"] < gains["y1"] - 1.0
    assert moved["y2"] == pytest.approx(gains["y2"], abs=1e-9)  # the other observable is untouched
    assert _first_single(loose) == "y2"
    # the information-gain table says the same number, and the notes name the own tolerance as the σ's basis
    table = loose.information_gain.drop_duplicates("observables").set_index("observables")
    assert float(table.loc["y1", "information_gain_bits"]) == pytest.approx(moved["y1"], abs=1e-12)
    basis = loose.notes[1]
    assert "y1: default sigma" in basis and "own tolerance" in basis
    assert "y2: default sigma_rel = 0.05 (tolerance/2)" in basis
