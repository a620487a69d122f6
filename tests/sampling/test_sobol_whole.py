"""Every field of the Sobol estimator (more than three factors) against the estimator written out in the test with
scipy's scrambled Sobol sequence and Student-t interval: the fraction, its standard error and interval, the replicate
and point counts, the evaluations and the unpolished spans, over generated studies of four or five factors (one on a
log scale or none), one to three observables with targets of either sign, replicate counts and confidence levels;
the admissible set built on it repeats those numbers and adds the evaluations of its own sample.  And the empty
state frame of the stored sets keeps its column types."""

from __future__ import annotations

import numpy as np
import pandas as pd
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy import stats
from scipy.stats import qmc

from demid.sampling import Domain
from demid.sampling.sobol import sobol_admissible_set, sobol_fraction
from demid.sampling.stored import STATE_COLUMNS, set_state_frame

SETTINGS = settings(max_examples=8, deadline=None, derandomize=True)


class Linear:
    """y = c0 + sum_i c_i x_i in actual units."""

    def __init__(self, coef):
        self.coef = np.asarray(coef, dtype=float)

    def predict(self, points):
        x = np.atleast_2d(np.asarray(points, dtype=float))
        return self.coef[0] + x @ self.coef[1:]


def _study(seed, dim, k, signs, log_first):
    rng = np.random.default_rng(seed)
    names = tuple(f"f{i}" for i in range(dim))
    lower = tuple(float(v) for v in rng.uniform(0.5, 1.5, dim))
    upper = tuple(lo + float(w) for lo, w in zip(lower, rng.uniform(1.0, 3.0, dim)))
    domain = Domain(names, lower, upper, log=tuple(log_first and i == 0 for i in range(dim)))
    observables = [f"y{j}" for j in range(k)]
    fields, targets = {}, {}
    centre = (np.array(lower) + np.array(upper)) / 2
    for j, o in enumerate(observables):
        slopes = rng.normal(size=dim) * signs[j]
        fields[o] = Linear(np.r_[signs[j] * 5.0, slopes])
        targets[o] = float(fields[o].predict(centre)[0]) * (1 + 0.05 * j)
    return domain, observables, fields, targets


def _written_out(domain, observables, fields, targets, tolerance, n_points, seed, replicates, confidence):
    """The documented estimator: 2**m points per replicate with 2**m * replicates nearest n_points, uniform in
    search units; a Student-t interval on the replicate means, clipped to [0, 1]; spans from admissible points."""
    m = max(1, int(round(np.log2(max(n_points / replicates, 2)))))
    lo = np.array([np.log10(v) if lg else v for v, lg in zip(domain.lower, domain.log)])
    hi = np.array([np.log10(v) if lg else v for v, lg in zip(domain.upper, domain.log)])
    rng = np.random.default_rng(seed)
    means, admissible = [], []
    for _ in range(replicates):
        u = lo + qmc.Sobol(len(lo), scramble=True, rng=rng).random_base2(m) * (hi - lo)
        x = np.where(np.array(domain.log), 10.0 ** u, u)
        worst = np.max([np.abs((fields[o].predict(x) - targets[o]) / targets[o]) for o in observables], axis=0)
        means.append(np.mean(worst <= tolerance))
        admissible.append(x[worst <= tolerance])
    means = np.array(means)
    se = means.std(ddof=1) / np.sqrt(replicates)
    half = stats.t.ppf(0.5 + confidence / 2, replicates - 1) * se
    points = np.vstack(admissible)
    return dict(fraction=means.mean(), std_error=se, ci_lower=max(0.0, means.mean() - half),
                ci_upper=min(1.0, means.mean() + half), points_per_replicate=2 ** m,
                evaluations=replicates * 2 ** m * len(observables),
                lower=points.min(axis=0) if len(points) else np.full(len(lo), np.nan),
                upper=points.max(axis=0) if len(points) else np.full(len(lo), np.nan))


@given(seed=st.integers(0, 10_000), dim=st.integers(4, 5), k=st.integers(1, 3),
       signs=st.lists(st.sampled_from([-1.0, 1.0]), min_size=3, max_size=3), log_first=st.booleans(),
       tolerance=st.sampled_from([0.05, 0.15, 0.4]), n_points=st.sampled_from([100, 256, 700]),
       replicates=st.sampled_from([4, 7, 16]), confidence=st.sampled_from([0.8, 0.95]))
@SETTINGS
def test_every_field_of_the_sobol_fraction_matches_the_estimator_written_out(
        seed, dim, k, signs, log_first, tolerance, n_points, replicates, confidence):
    domain, observables, fields, targets = _study(seed, dim, k, signs, log_first)
    got = sobol_fraction(fields, domain, observables, targets, tolerance, n_points, seed, replicates=replicates,
                         confidence=confidence, polish=False)
    want = _written_out(domain, observables, fields, targets, tolerance, n_points, seed, replicates, confidence)
    for name in ("fraction", "std_error", "ci_lower", "ci_upper"):
        assert getattr(got, name) == pytest.approx(want[name], rel=1e-12, abs=1e-15), name
    assert (got.replicates, got.points_per_replicate, got.evaluations, got.confidence) == (
        replicates, want["points_per_replicate"], want["evaluations"], confidence)
    np.testing.assert_allclose(got.lower, want["lower"], rtol=1e-12)
    np.testing.assert_allclose(got.upper, want["upper"], rtol=1e-12)


@given(seed=st.integers(0, 10_000), k=st.integers(1, 3),
       signs=st.lists(st.sampled_from([-1.0, 1.0]), min_size=3, max_size=3), log_first=st.booleans(),
       n=st.sampled_from([64, 200, 512]))
@settings(max_examples=4, deadline=None, derandomize=True)
def test_the_sobol_set_repeats_its_fraction_and_counts_its_own_sample_in_the_evaluations(seed, k, signs, log_first,
                                                                                         n):
    domain, observables, fields, targets = _study(seed, 4, k, signs, log_first)
    aset = sobol_admissible_set(fields, domain, observables, targets, 0.2, n)
    est = sobol_fraction(fields, domain, observables, targets, 0.2, n, seed=0)
    m = max(1, int(round(np.log2(max(n / 16, 2)))))
    sample_size = 2 ** max(1, int(np.ceil(np.log2(n))))  # the evaluation sample: the domain's Sobol points
    assert len(aset.points) == sample_size
    assert aset.evaluations == 16 * 2 ** m * k + sample_size * k
    assert aset.fraction == est.fraction
    assert aset.fraction_ci == (est.ci_lower, est.ci_upper)
    assert aset.fraction_error == pytest.approx((est.ci_upper - est.ci_lower) / 2, rel=1e-15)
    np.testing.assert_array_equal(aset.lower, est.lower)
    np.testing.assert_array_equal(aset.upper, est.upper)
    assert (aset.method, aset.tolerance, aset.factors, aset.observables) == (
        "scrambled Sobol", 0.2, domain.factors, tuple(observables))
    assert aset.n_refined_cells == 0 and aset.n_nodes == sample_size  # no grid cells: nothing refined


def test_the_state_frame_of_no_sets_has_the_columns_and_types_of_a_filled_one():
    empty = set_state_frame({})
    assert list(empty.columns) == STATE_COLUMNS and len(empty) == 0
    assert empty["method"].dtype == object
    for column in STATE_COLUMNS[1:]:
        assert pd.api.types.is_float_dtype(empty[column]), column
