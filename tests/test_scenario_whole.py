"""Every output of demid.scenario a user reads, over generated responses: the measurement σ and the words of its
basis (every quoted number parsed back and compared with σ computed here: configured σ, σ_rel |y*|, the default
tolerance / z, or none), the plausible set's basis in the notes (own tolerances, units, discrepancy), the
measurement bands in the judged surrogates' units (c = ε|y*| / a_k), the reference scenario, and the
implausibility under a planned wave's standard errors, z sqrt(se_new² + σ² + δ²), written out here."""

from __future__ import annotations

import re

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st

from demid.scenario import (judged_scenarios, measurement_sigma, measurement_sigmas, own_band_basis,
                            plausible_basis, reference_scenario, scenario_bands, sigma_basis)
from demid.spec import MaterialSpec
from tests.test_judged_scenario_properties import _surrogate

_NUMBER = r"[-+]?\d*\.?\d+(?:e[-+]?\d+)?"


def _numbers(text: str) -> list[float]:
    return [float(x) for x in re.findall(_NUMBER, text)]


_RESPONSE = st.fixed_dictionaries({
    "sign": st.sampled_from([1.0, -1.0]), "scale": st.sampled_from([0.003, 1.0, 450.0]),
    "sigma": st.sampled_from([None, "abs", "rel", "both"]), "band": st.sampled_from([None, "relative", "absolute"]),
    "delta": st.sampled_from([0.0, 0.07]), "unit": st.sampled_from(["-", "kPa"])})


def _config(o: dict, mantissa: float) -> dict:
    target = o["sign"] * o["scale"] * mantissa
    cfg = {"target": target, "unit": o["unit"]}
    if o["sigma"] in ("abs", "both"):
        cfg["sigma"] = 0.0123 * o["scale"]
    if o["sigma"] in ("rel", "both"):
        cfg["sigma_rel"] = 0.0271
    if o["band"] == "relative":
        cfg["tolerance"] = 0.043
    elif o["band"] == "absolute":
        cfg["tolerance_abs"] = 0.0317 * o["scale"]
    if o["delta"]:
        cfg["discrepancy"] = o["delta"] * o["scale"]
    return cfg


def _expected_sigma(cfg: dict, default_rel) -> float:
    if "sigma" in cfg:
        return cfg["sigma"]
    if "sigma_rel" in cfg:
        return cfg["sigma_rel"] * abs(cfg["target"])
    return 0.0 if default_rel is None else default_rel * abs(cfg["target"])


@given(o=_RESPONSE, mantissa=st.floats(1.0, 9.0), tolerance=st.sampled_from([None, 0.02, 0.15]),
       z=st.sampled_from([1.0, 2.0, 3.0]))
@settings(max_examples=60, deadline=None, derandomize=True)
def test_measurement_sigma_and_its_basis_quote_the_value_they_come_from(o, mantissa, tolerance, z):
    cfg = _config(o, mantissa)
    default_rel = None if tolerance is None else tolerance / z
    expected = _expected_sigma(cfg, default_rel)
    assert measurement_sigma(cfg, cfg["target"], default_rel) == np.float64(expected)
    assert measurement_sigma(None, cfg["target"]) == 0.0
    words = sigma_basis(cfg, default_rel, z)
    if "sigma" in cfg:
        assert words.startswith("config sigma = ") and np.isclose(_numbers(words)[0], cfg["sigma"], rtol=1e-5)
    elif "sigma_rel" in cfg:
        assert words.startswith("config sigma_rel = ") and np.isclose(_numbers(words)[0], 0.0271, rtol=1e-5)
    elif default_rel is not None:
        assert words.startswith("default sigma_rel = ") and words.endswith(f"(tolerance/{z:g})")
        assert np.isclose(_numbers(words)[0], tolerance / z, rtol=1e-5)
    else:
        assert words == "none (surrogate uncertainty only)"
    # the table's pair: one sigma and one basis per observable, the default from the tolerance read at z
    sigmas, bases = measurement_sigmas({"y": cfg, "w": {}}, ["y", "w"], {"y": cfg["target"], "w": -2.0}, tolerance, z)
    assert sigmas == {"y": expected, "w": 0.0 if default_rel is None else default_rel * 2.0}
    assert bases["y"] == words and bases["w"] == sigma_basis(None, default_rel, z)


@given(o=_RESPONSE, mantissa=st.floats(1.0, 9.0), tolerance=st.sampled_from([0.02, 0.15]),
       z=st.sampled_from([0.5, 2.0, 3.0]))
@settings(max_examples=40, deadline=None, derandomize=True)
def test_plausible_basis_and_the_own_band_basis_quote_each_source(o, mantissa, tolerance, z):
    cfg = _config(o, mantissa)
    spec = MaterialSpec.from_material("m", {
        "data": "x.csv", "design": {"type": "custom"},
        "factors": {"a": {"lower": 0.0, "upper": 1.0}, "b": {"lower": 0.0, "upper": 1.0}},
        "responses": {"y": cfg}, "scenarios": {"s": {"observables": ["y"], "tolerance": tolerance}}})
    response, target = spec.response("y"), cfg["target"]
    text = plausible_basis(spec, "y")
    parts = text.split("; ")
    if "sigma" in cfg or "sigma_rel" in cfg:
        assert parts[0] == sigma_basis(response.sigma_config)
    else:
        assert parts[0] == "no sigma configured: the tolerance band is the measurement band (σ = ε·|y*|/z)"
    rest = parts[1:]
    if "tolerance_abs" in cfg:
        unit = "" if o["unit"] == "-" else " kPa"
        assert rest[0].startswith("own tolerance ±") and rest[0].endswith(unit)
        assert np.isclose(_numbers(rest[0])[0], cfg["tolerance_abs"], rtol=1e-5)
        rest = rest[1:]
    elif "tolerance" in cfg:
        assert rest[0] == "own tolerance 0.043"
        rest = rest[1:]
    if o["delta"]:
        assert rest[0].startswith("discrepancy δ = ")
        assert np.isclose(_numbers(rest[0])[0], cfg["discrepancy"], rtol=1e-5)
        rest = rest[1:]
    assert rest == []
    # the default σ's basis: the band (own, else the scenario's) read as a z-sigma measurement band
    words = own_band_basis(response, target, tolerance, z)
    if "tolerance_abs" in cfg:
        sigma, band, zq = _numbers(words.replace("±", " "))
        assert words.startswith("default sigma = ") and "own tolerance ±" in words
        assert np.isclose(sigma, cfg["tolerance_abs"] / z, rtol=1e-5)
        assert np.isclose(band, cfg["tolerance_abs"], rtol=1e-5) and zq == z
    elif "tolerance" in cfg:
        assert words.startswith("default sigma_rel = ") and words.endswith(f"(own tolerance/{z:g})")
        assert np.isclose(_numbers(words)[0], 0.043 / z, rtol=1e-5)
    else:
        assert words == sigma_basis(None, tolerance / z, z)


@given(responses=st.lists(_RESPONSE, min_size=1, max_size=3), tolerance=st.sampled_from([0.02, 0.1]),
       z=st.sampled_from([1.0, 2.0, 3.0]), seed=st.integers(0, 500))
@settings(max_examples=30, deadline=None, derandomize=True)
def test_bands_reference_scenario_and_implausibility_under_a_planned_waves_se(responses, tolerance, z, seed):
    rng = np.random.default_rng(seed)
    cfgs = {f"y{k}": _config(o, rng.uniform(1.0, 9.0)) for k, o in enumerate(responses)}
    names = list(cfgs)
    scenarios = {"all": {"observables": names, "tolerance": tolerance},
                 "first": {"observables": names[:1], "tolerance": tolerance / 2}}
    spec = MaterialSpec.from_material("m", {
        "data": "x.csv", "design": {"type": "custom"},
        "factors": {"a": {"lower": 0.0, "upper": 1.0}, "b": {"lower": 0.0, "upper": 1.0}},
        "responses": cfgs, "scenarios": scenarios})
    scales, sigmas, deltas = {}, {}, {}
    for o, cfg in cfgs.items():
        band = cfg.get("tolerance_abs", cfg.get("tolerance", tolerance) * abs(cfg["target"]))
        scales[o] = tolerance * abs(cfg["target"]) / band
        configured = "sigma" in cfg or "sigma_rel" in cfg
        sigmas[o] = _expected_sigma(cfg, None) if configured else band / z
        deltas[o] = cfg.get("discrepancy", 0.0)
    bands = scenario_bands(spec, names, tolerance)
    for o, cfg in cfgs.items():
        configured = "sigma" in cfg or "sigma_rel" in cfg
        if not configured and not deltas[o]:
            assert o not in bands
            continue
        assert np.isclose(bands[o].discrepancy, scales[o] * deltas[o], rtol=1e-12)
        if configured:
            assert np.isclose(bands[o].sigma, scales[o] * sigmas[o], rtol=1e-12)
        else:
            assert bands[o].sigma is None
    # the reference scenario: the one with the most observables (ties: the smaller tolerance)
    ref = reference_scenario(spec, names)
    expected_tolerance = tolerance if len(names) > 1 else tolerance / 2
    assert (ref.name, ref.observables, ref.tolerance, ref.label) == ("reference", tuple(names), expected_tolerance,
                                                                     "reference")
    surrogates = {o: _surrogate(o, cfg["target"] * 1.01, abs(cfg["target"]) * rng.uniform(-0.2, 0.2, 2),
                                0.02 * abs(cfg["target"])) for o, cfg in cfgs.items()}
    judged = judged_scenarios(spec, surrogates, z)["all"]
    assert (judged.name, judged.observables, judged.tolerance) == ("all", tuple(names), tolerance)
    points = rng.uniform(0.0, 1.0, (300, 2))
    planned = {o: rng.uniform(0.0, 0.05, len(points)) * abs(cfg["target"]) for o, cfg in cfgs.items()}
    expected = np.zeros(len(points))
    for o, cfg in cfgs.items():
        miss = np.abs(surrogates[o].predict(points) - cfg["target"])
        half = z * np.sqrt(planned[o] ** 2 + sigmas[o] ** 2 + deltas[o] ** 2)
        expected = np.maximum(expected, miss / half)
    # the planned se is given in the judged (rescaled) units, as the wave value passes it
    got = judged.implausibility(points, se={o: scales[o] * planned[o] for o in names})
    np.testing.assert_allclose(got, expected, rtol=1e-9)
    clear = np.abs(expected - 1.0) > 1e-9
    inside = judged.contains(points, se={o: scales[o] * planned[o] for o in names})
    assert np.array_equal(inside[clear], (expected <= 1.0)[clear])
