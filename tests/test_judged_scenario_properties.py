"""A judged scenario's implausibility and membership over generated studies: 1-3 observables with targets of
either sign, each with the scenario's tolerance, its own relative or absolute tolerance, a configured σ or
σ_rel or none, a discrepancy δ or none, z of 0, 0.5, 1, 2 or 3: I(x) = max_k |ŷ_k - y_k*| / H_k with H_k the band a_k
(strict, or z = 0) or z sqrt(se² + σ_k² + δ_k²), σ_k = a_k / z when none is configured, written out here in the
responses' own units; a point is in the set exactly when I <= 1; the likelihood width is σ_k."""

from __future__ import annotations

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st

from demid.design import quadratic_terms
from demid.scenario import MEMBERSHIP_SLACK, judged_scenarios
from demid.spec import MaterialSpec
from demid.surrogate import Surrogate

_OBSERVABLE = st.fixed_dictionaries({
    "sign": st.sampled_from([1.0, -1.0]), "scale": st.sampled_from([0.01, 1.0, 300.0]),
    "band": st.sampled_from(["scenario", "relative", "absolute"]), "sigma": st.sampled_from([None, "abs", "rel"]),
    "delta": st.sampled_from([0.0, 0.2]), "se": st.sampled_from([0.0, 0.05, 0.3])})


def _surrogate(name: str, intercept: float, slopes, se: float) -> Surrogate:
    terms = quadratic_terms(2)
    coef = np.zeros(len(terms))
    coef[:3] = intercept, *slopes
    cov = np.zeros((len(terms), len(terms)))
    cov[0, 0] = se ** 2
    return Surrogate(name, ["a", "b"], terms, coef, cov, 0.0, 5, ())


@given(observables=st.lists(_OBSERVABLE, min_size=1, max_size=3), z=st.sampled_from([0.0, 0.5, 1.0, 2.0, 3.0]),
       tolerance=st.sampled_from([0.02, 0.1]), seed=st.integers(0, 1000))
@settings(max_examples=80, deadline=None, derandomize=True)
def test_implausibility_and_membership_are_the_documented_ratio_in_the_responses_units(observables, z, tolerance,
                                                                                       seed):
    rng = np.random.default_rng(seed)
    responses, surrogates, bands, sigmas, deltas = {}, {}, {}, {}, {}
    for k, o in enumerate(observables):
        name = f"y{k}"
        target = o["sign"] * o["scale"] * rng.uniform(1.0, 2.0)
        cfg = {"target": target}
        band = tolerance * abs(target)
        if o["band"] == "relative":
            cfg["tolerance"] = 0.05
            band = 0.05 * abs(target)
        elif o["band"] == "absolute":
            cfg["tolerance_abs"] = 0.03 * o["scale"]
            band = 0.03 * o["scale"]
        sigma = band / z if z > 0 else 0.0
        if o["sigma"] == "abs":
            cfg["sigma"] = sigma = 0.02 * o["scale"]
        elif o["sigma"] == "rel":
            cfg["sigma_rel"] = 0.015
            sigma = 0.015 * abs(target)
        if o["delta"]:
            cfg["discrepancy"] = o["delta"] * o["scale"]
        responses[name] = cfg
        bands[name], sigmas[name], deltas[name] = band, sigma, o["delta"] * o["scale"]
        # the response crosses its target inside the square
        slopes = o["scale"] * rng.uniform(-1.0, 1.0, 2)
        surrogates[name] = _surrogate(name, target - slopes @ rng.uniform(0.2, 0.8, 2), slopes, o["se"] * o["scale"])
    names = list(responses)
    spec = MaterialSpec.from_material("m", {
        "data": "x.csv", "design": {"type": "custom"},
        "factors": {"a": {"lower": 0.0, "upper": 1.0}, "b": {"lower": 0.0, "upper": 1.0}},
        "responses": responses, "scenarios": {"s": {"observables": names, "tolerance": tolerance}}})
    judged = judged_scenarios(spec, surrogates, z)["s"]
    points = rng.uniform(0.0, 1.0, (400, 2))
    strict = np.zeros(len(points))
    plausible = np.zeros(len(points))
    for o in names:
        target = responses[o]["target"]
        miss = np.abs(surrogates[o].predict(points) - target)
        strict = np.maximum(strict, miss / bands[o])
        se = observables[int(o[1:])]["se"] * observables[int(o[1:])]["scale"]
        half = z * np.sqrt(se ** 2 + sigmas[o] ** 2 + deltas[o] ** 2) if z > 0 else bands[o]
        plausible = np.maximum(plausible, miss / half)
    np.testing.assert_allclose(judged.implausibility(points, plausible=False), strict, rtol=1e-9)
    np.testing.assert_allclose(judged.implausibility(points), plausible, rtol=1e-9)
    for found, ratio in ((judged.contains(points), plausible), (judged.contains(points, plausible=False), strict)):
        clear = np.abs(ratio - 1.0) > 1e-9  # away from the edge, where round-off decides
        assert np.array_equal(found[clear], (ratio <= 1.0)[clear])
    assert MEMBERSHIP_SLACK < 1e-9
    if z > 0:
        expected_sd = {o: sigmas[o] if "sigma" in responses[o] or "sigma_rel" in responses[o] else bands[o] / z
                       for o in names}
        got = judged.likelihood_sd
        # in the judged surrogates' units: an own band rescales by c = eps |y*| / a_k
        for o in names:
            c = tolerance * abs(responses[o]["target"]) / bands[o]
            assert np.isclose(got[o], c * expected_sd[o], rtol=1e-12), (o, got[o], c * expected_sd[o])
