"""Every function of demid.tolerance against the bands written out here, over generated studies: 1-4 observables
of either sign (and a target of 0), each with its own absolute or relative tolerance or none, scenario tolerances
from 0.5 % to 30 %, polynomials of 1-3 factors whose intercept is not the first term; the rescaled surrogate's
predictions, standard errors and residual variance at random points, the grid's columns, the relative tolerances
level 2 judges by, and the round-off rule of same_tolerances on both sides of it."""

from __future__ import annotations

from types import SimpleNamespace

import numpy as np
import pandas as pd
import pytest
from hypothesis import Phase, given, settings, strategies as st

from demid.design import quadratic_terms
from demid.surrogate import Surrogate
from demid.tolerance import (band_scale, has_own_band, has_own_tolerance, observable_band, relative_tolerances,
                             rescaled_surrogate, same_tolerances, scenario_grid, scenario_scales, scenario_surrogates)


def _response(name, target, tolerance=None, tolerance_abs=None):
    return SimpleNamespace(name=name, target=target, tolerance=tolerance, tolerance_abs=tolerance_abs)


def _spec(responses):
    return SimpleNamespace(responses=list(responses), targets={r.name: r.target for r in responses if r.target is not None},
                           response=lambda name: next(r for r in responses if r.name == name))


def _expected_band(response, target, eps):
    if response.tolerance_abs is not None:
        return response.tolerance_abs
    return (response.tolerance if response.tolerance is not None else eps) * abs(target)


def _study(rng, count, k):
    responses, surrogates = [], {}
    for j in range(count):
        name = f"y{j}"
        target = 0.0 if rng.uniform() < 0.1 else float(rng.choice([-1, 1]) * 10.0 ** rng.uniform(-2, 3))
        kind = rng.integers(0, 3)
        own = {"tolerance_abs": float(rng.uniform(0.01, 2) * max(abs(target), 1))} if kind == 1 else \
            {"tolerance": float(rng.uniform(0.005, 0.3))} if kind == 2 else {}
        responses.append(_response(name, target, **own))
        terms = quadratic_terms(k)
        order = rng.permutation(len(terms))  # the intercept anywhere
        terms = [terms[i] for i in order]
        coef = rng.normal(size=len(terms)) * 5
        a = rng.normal(size=(len(terms), len(terms)))
        surrogates[name] = Surrogate(name, [f"f{i}" for i in range(k)], terms, coef, a @ a.T * 0.01,
                                     float(rng.uniform(0.01, 1)), 5)
    # a response without a target keeps its surrogate and has no scale
    responses.append(_response("free", None))
    return responses, surrogates


@settings(max_examples=25, deadline=None, derandomize=True, phases=(Phase.explicit, Phase.generate))
@given(seed=st.integers(0, 100_000), count=st.integers(1, 4), k=st.integers(1, 3),
       eps=st.sampled_from([0.005, 0.02, 0.1, 0.3]))
def test_every_band_scale_and_rescaled_output_is_its_definition(seed, count, k, eps):
    rng = np.random.default_rng(seed)
    responses, surrogates = _study(rng, count, k)
    spec = _spec(responses)
    scales = scenario_scales(spec, eps)
    assert list(scales) == [r.name for r in responses if r.target is not None]
    points = rng.uniform(-2, 2, (50, k))
    for r in responses[:-1]:
        band = _expected_band(r, r.target, eps)
        got = observable_band(r, r.target, eps)
        assert type(got) is float and got == pytest.approx(band, rel=1e-15)
        c = eps * abs(r.target) / band if band > 0 else 1.0
        assert band_scale(r, r.target, eps) == pytest.approx(c, rel=1e-15) and scales[r.name] == band_scale(
            r, r.target, eps)
        assert has_own_band(r) == (r.tolerance is not None or r.tolerance_abs is not None)
        # the rescaled polynomial: y* + c (ŷ - y*), standard errors times c
        original = surrogates[r.name]
        rescaled = rescaled_surrogate(original, r.target, c)
        if c == 1.0:
            assert rescaled is original
        np.testing.assert_allclose(rescaled.predict(points), r.target + c * (original.predict(points) - r.target),
                                   rtol=1e-10, atol=1e-10 * (1 + abs(r.target)))
        np.testing.assert_allclose(rescaled.se_mean(points), c * original.se_mean(points), rtol=1e-10)
        assert rescaled.resid_var == pytest.approx(c ** 2 * original.resid_var, rel=1e-12)
        # where the original meets its own band the rescaled one meets the scenario's, and only there
        within = np.abs(original.predict(points) - r.target) <= band * (1 - 1e-9)
        assert np.all(np.abs(rescaled.predict(points) - r.target)[within] <= eps * abs(r.target) * (1 + 1e-9) + 1e-12)
    assert not has_own_band(responses[-1])
    own = any(has_own_band(r) for r in responses)
    assert has_own_tolerance(spec) == own

    judged = scenario_surrogates(surrogates, spec, eps)
    if not own:
        assert judged is surrogates
    assert list(judged) == list(surrogates)
    for r in responses[:-1]:
        np.testing.assert_allclose(judged[r.name].predict(points),
                                   rescaled_surrogate(surrogates[r.name], r.target, scales[r.name]).predict(points))

    # a grid frame may hold only some responses: the first is left out when there are several
    shown = [r for r in surrogates if count == 1 or r != responses[0].name]
    grid = pd.DataFrame({**{r: surrogates[r].predict(points) for r in shown}, "free": rng.normal(size=50)})
    moved = scenario_grid(grid, spec, eps)
    if not own:
        assert moved is grid
    else:
        assert list(moved.columns) == list(grid.columns)
        for r in (r for r in responses[:-1] if r.name in shown):
            c = scales[r.name]
            np.testing.assert_allclose(moved[r.name], r.target + c * (grid[r.name] - r.target), rtol=1e-12,
                                       atol=1e-12 * (1 + abs(r.target)))
        np.testing.assert_array_equal(moved["free"], grid["free"])
        np.testing.assert_array_equal(grid[shown[0]], surrogates[shown[0]].predict(points))  # the input unchanged
    assert scenario_grid(None, spec, eps) is None

    observables = [r.name for r in responses[:-1]]
    relative = relative_tolerances(spec, observables, eps)
    assert list(relative) == observables
    for r in responses[:-1]:
        expected = _expected_band(r, r.target, eps) / abs(r.target) if r.target else eps
        assert relative[r.name] == pytest.approx(expected, rel=1e-15)
    assert same_tolerances(eps, relative) == all(abs(v - eps) <= 1e-12 * eps for v in relative.values())


@pytest.mark.parametrize("eps", [0.05, 0.2, 1e-3])
def test_same_tolerances_holds_to_round_off_and_not_beyond(eps):
    assert same_tolerances(eps, {}) and same_tolerances(eps, None)
    assert same_tolerances(eps, {"a": eps, "b": eps * (1 + 5e-13)})
    assert same_tolerances(eps, {"a": eps * (1 - 5e-13)})
    assert not same_tolerances(eps, {"a": eps, "b": eps * (1 + 3e-12)})
    assert not same_tolerances(eps, {"a": eps * (1 - 3e-12)})
    assert not same_tolerances(eps, {"a": 2 * eps})


def test_an_own_band_of_zero_leaves_the_surrogate_unscaled():
    r = _response("y", 5.0, tolerance_abs=0.0)
    assert observable_band(r, 5.0, 0.1) == 0.0 and band_scale(r, 5.0, 0.1) == 1.0
    zero = _response("z", 0.0)
    assert band_scale(zero, 0.0, 0.1) == 1.0
    assert relative_tolerances(_spec([zero]), ["z"], 0.1) == {"z": 0.1}
