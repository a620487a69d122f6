"""The plausible set's fields over generated surrogates, targets of either sign and any magnitude, measurement
bands given, assumed or with a discrepancy, and mean or predictive errors: each number against its formula
computed apart (|ŷ − y*| ≤ z·√(se² + σ² + δ²), σ = ε·|y*|/z when no σ is given), and the field's defining
property: its strict band holds exactly where the plausible band does."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from demid.design import quadratic_terms
from demid.sampling.residuals import (MeasurementBand, PlausibilityField, _fields, plausibility_fields,
                                      relative_residuals, residual_evaluator)
from demid.surrogate import Surrogate

SETTINGS = settings(max_examples=40, deadline=None, derandomize=True)


def _surrogate(name: str, seed: int, scale: float) -> Surrogate:
    rng = np.random.default_rng(seed)
    terms = quadratic_terms(2)
    a = rng.normal(size=(len(terms), len(terms)))
    return Surrogate(name, ["a", "b"], terms, scale * rng.normal(size=len(terms)), 0.01 * scale ** 2 * a @ a.T,
                     float(rng.uniform(0.01, 1.0)) * scale ** 2, 10)


def _independent(sur: Surrogate, points):
    """ŷ and the standard error of the mean from the quadratic's terms written out (a, b, ab, a², b² order free)."""
    m = np.column_stack([np.prod(points ** np.array(t), axis=1) for t in sur.terms])
    return m @ sur.coefficients, np.sqrt(np.einsum("ij,jk,ik->i", m, sur.covariance, m))


bands = st.one_of(st.none(), st.floats(0.001, 5.0), st.builds(MeasurementBand, st.one_of(st.none(), st.floats(0.001, 5.0)),
                                                              st.floats(0.0, 3.0)))


@given(seed=st.integers(0, 10_000), sign=st.sampled_from([-1.0, 1.0]), power=st.integers(-3, 3),
       tolerance=st.floats(0.01, 0.5), z=st.sampled_from([0.5, 1.0, 2.0, 3.0]), band=bands,
       predictive=st.booleans())
@SETTINGS
def test_a_fields_band_is_the_plausible_band_for_any_target_sign_and_measurement_band(seed, sign, power, tolerance,
                                                                                        z, band, predictive):
    scale = 10.0 ** power
    sur = _surrogate("y", seed, scale)
    points = np.random.default_rng(seed + 1).uniform(-1.5, 1.5, size=(60, 2))
    yhat, se = _independent(sur, points)
    target = sign * scale * float(np.median(np.abs(yhat)) + 0.1)
    band_sd = band.sigma if isinstance(band, MeasurementBand) else band
    discrepancy = band.discrepancy if isinstance(band, MeasurementBand) else 0.0
    if predictive:
        field = PlausibilityField(sur, target, tolerance, z, band_sd, True, discrepancy)
    else:
        field = plausibility_fields({"y": sur}, ["y"], {"y": target}, tolerance, z, {"y": band} if band is not None
                                    else None)["y"]
    sigma = tolerance * abs(target) / z if band_sd is None else band_sd
    assert field.measurement_sd == pytest.approx(sigma, rel=1e-12)
    se_used = np.sqrt(se ** 2 + sur.resid_var) if predictive else se
    half = z * np.sqrt(se_used ** 2 + sigma ** 2 + discrepancy ** 2)
    np.testing.assert_allclose(field.uncertainty(points), half / z, rtol=1e-10)
    np.testing.assert_allclose(field.half_width(points), half, rtol=1e-10)
    # a caller's standard error replaces the surrogate's
    given_se = np.full(len(points), 0.3 * scale)
    np.testing.assert_allclose(field.half_width(points, given_se),
                               z * np.sqrt(0.09 * scale ** 2 + sigma ** 2 + discrepancy ** 2), rtol=1e-10)
    pred = field.predict(points)
    np.testing.assert_allclose(pred, target + (yhat - target) * tolerance * abs(target) / half, rtol=1e-9,
                               atol=1e-12 * abs(target))
    strict = np.abs(pred - target) <= tolerance * abs(target)
    plausible = np.abs(yhat - target) <= half
    margin = np.abs(np.abs(yhat - target) - half) > 1e-9 * half
    np.testing.assert_array_equal(strict[margin], plausible[margin])


@given(seed=st.integers(0, 10_000), sign=st.sampled_from([-1.0, 1.0]), tolerance=st.floats(0.01, 0.5))
@SETTINGS
def test_without_z_a_field_is_its_surrogate(seed, sign, tolerance):
    sur = _surrogate("y", seed, 1.0)
    points = np.random.default_rng(seed).uniform(-1, 1, size=(20, 2))
    field = PlausibilityField(sur, sign * 2.0, tolerance, 0.0)
    assert field.measurement_sd == 0.0
    np.testing.assert_allclose(field.predict(points), _independent(sur, points)[0], rtol=1e-12)
    fields = _fields({"y": sur}, ["y"], {"y": sign * 2.0}, tolerance, 0.0, None)
    assert fields["y"] is sur
    assert isinstance(_fields({"y": sur}, ["y"], {"y": sign * 2.0}, tolerance, 1.0, None)["y"], PlausibilityField)


@given(seed=st.integers(0, 10_000), n_obs=st.integers(1, 4), signs=st.lists(st.sampled_from([-1.0, 1.0]), min_size=4,
                                                                            max_size=4),
       z=st.sampled_from([0.0, 1.0, 2.0]))
@SETTINGS
def test_the_residual_evaluator_gives_each_observables_relative_residual_in_order(seed, n_obs, signs, z):
    names = [f"y{i}" for i in range(n_obs)]
    surs = {o: _surrogate(o, seed + i, 10.0 ** i) for i, o in enumerate(names)}
    targets = {o: signs[i] * 10.0 ** i * (1.0 + i) for i, o in enumerate(names)}
    points = np.random.default_rng(seed).uniform(-1, 1, size=(15, 2))
    observables = names[::-1]  # the caller's order, not the dictionary's
    fields = _fields(surs, observables, targets, 0.1, z, None)
    got = residual_evaluator(fields, observables, targets)(points)
    assert got.shape == (n_obs, len(points))
    for row, o in zip(got, observables):
        y = fields[o].predict(points)
        np.testing.assert_allclose(row, (y - targets[o]) / abs(targets[o]), rtol=1e-12)
    predictions = {o: surs[o].predict(points) for o in names}
    rel = relative_residuals(predictions, targets, observables)
    for row, o in zip(rel, observables):
        np.testing.assert_allclose(row, (predictions[o] - targets[o]) / abs(targets[o]), rtol=1e-12)
