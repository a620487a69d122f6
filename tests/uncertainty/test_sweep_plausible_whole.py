"""The tolerance sweep's and the strict-and-plausible table's every column against a closed form, over generated
studies: 2-3 factors on ranges away from the origin, 1-3 observables each linear in its own factor
(y_k = t_k + s_k (x_k - c_k), targets and slopes of either sign, some bands cut by the box's faces), 1-3
scenarios of different sizes, several tolerances.  The strict set is then the box |x_k - c_k| <= ε|t_k| / |s_k|
clipped to the domain, the plausible set the box |x_k - c_k| <= z sqrt(se² + σ_k²) / |s_k| (σ_k configured, or
ε|t_k| / z; two factors), so every fraction, bound and width is written out here."""

from __future__ import annotations

import numpy as np
import pandas as pd
from hypothesis import given, settings
from hypothesis import strategies as st

from demid.sampling import Domain
from demid.uncertainty.plausible import plausible_identifiability_frame
from demid.uncertainty.sweep import tolerance_sweep

from .test_uncertainty import linear


def _study(seed: int, dim: int, n_obs: int):
    rng = np.random.default_rng(seed)
    factors = ("a", "b", "c")[:dim]
    lo = rng.uniform(-3.0, 3.0, dim)
    hi = lo + rng.uniform(0.5, 4.0, dim)
    domain = Domain(factors, tuple(lo), tuple(hi))
    surrogates, targets, centres, slopes = {}, {}, {}, {}
    for k in range(n_obs):
        name = f"y{k}"
        target = rng.choice([-1.0, 1.0]) * rng.uniform(0.5, 50.0)
        slope = rng.choice([-1.0, 1.0]) * abs(target) * rng.uniform(0.3, 3.0) / (hi[k] - lo[k])
        # the centre inside the range, sometimes near a face so the band is cut
        centre = lo[k] + (hi[k] - lo[k]) * rng.choice([rng.uniform(0.3, 0.7), 0.01, 0.99])
        coef = np.zeros(dim)
        coef[k] = slope
        surrogate = linear(target - slope * centre, coef, 0.0, factors)
        surrogate.response = name
        surrogates[name], targets[name], centres[name], slopes[name] = surrogate, target, centre, slope
    return domain, surrogates, targets, centres, slopes


def _box(domain, observables, targets, centres, slopes, half_of):
    """Per factor the clipped interval of the box set; the fraction of the domain it fills."""
    lower, upper = np.array(domain.lower, float), np.array(domain.upper, float)
    for o in observables:
        k = int(o[1:])
        half = half_of(o) / abs(slopes[o])
        lower[k] = max(lower[k], centres[o] - half)
        upper[k] = min(upper[k], centres[o] + half)
    ranges = np.array(domain.upper) - np.array(domain.lower)
    return lower, upper, float(np.prod((upper - lower) / ranges))


def _scenarios(n_obs: int, tolerance: float) -> dict:
    names = [f"y{k}" for k in range(n_obs)]
    scenarios = {"all": (names, tolerance)}
    if n_obs > 1:
        scenarios["last"] = (names[-1:], 2 * tolerance)
    if n_obs > 2:
        scenarios["pair"] = (names[:2], tolerance / 2)
    return scenarios


@given(seed=st.integers(0, 10_000), dim=st.sampled_from([2, 3]), n_obs=st.integers(1, 3),
       nominal=st.sampled_from([0.01, 0.05]), extra=st.sampled_from([(0.02,), (0.005, 0.1), (0.05, 0.2)]))
@settings(max_examples=8, deadline=None, derandomize=True)
def test_sweep_rows_are_the_clipped_boxes_of_every_scenario_at_every_tolerance(seed, dim, n_obs, nominal, extra):
    n_obs = min(n_obs, dim)
    domain, surrogates, targets, centres, slopes = _study(seed, dim, n_obs)
    scenarios = _scenarios(n_obs, nominal)
    frame = tolerance_sweep(surrogates, domain, scenarios, targets, list(extra), 21)
    expected_columns = ["scenario", "observables", "tolerance", "feasible_fraction_pct", "factor", "lower",
                        "upper", "width", "fraction_error_pct"]
    assert list(frame.columns) == expected_columns and list(frame.index) == list(range(len(frame)))
    rows = []
    for name, (observables, tol) in scenarios.items():
        for eps in sorted(set(extra) | {tol}):
            lower, upper, fraction = _box(domain, observables, targets, centres, slopes,
                                          lambda o: eps * abs(targets[o]))
            for k, f in enumerate(domain.factors):
                rows.append((name, "+".join(observables), eps, 100 * fraction, f, lower[k], upper[k],
                             upper[k] - lower[k]))
    expected = pd.DataFrame(rows, columns=expected_columns[:-1])
    pd.testing.assert_frame_equal(frame[expected_columns[:-1]], expected, check_exact=False, rtol=1e-7, atol=1e-9)
    assert (frame["fraction_error_pct"] >= 0).all() and (frame["fraction_error_pct"] < 1e-3).all()


@given(seed=st.integers(0, 10_000), n_obs=st.integers(1, 2), z=st.sampled_from([1.0, 2.0, 3.0]), se_share=st.sampled_from([0.0, 0.5]),
       sigma_share=st.sampled_from([None, 0.3, 1.5]))
@settings(max_examples=10, deadline=None, derandomize=True)
def test_plausible_table_is_the_strict_box_beside_the_widened_box(seed, n_obs, z, se_share, sigma_share):
    # two factors: the plausible set of three is refined on its grid for seconds a scenario
    dim = 2
    domain, surrogates, targets, centres, slopes = _study(seed, dim, n_obs)
    tolerance = 0.04
    se = {o: se_share * tolerance * abs(t) for o, t in targets.items()}
    for o, s in se.items():
        surrogates[o].covariance[0, 0] = s ** 2
    sigma = None if sigma_share is None else {o: sigma_share * tolerance * abs(t) for o, t in targets.items()}
    scenarios = _scenarios(n_obs, tolerance)
    frame = plausible_identifiability_frame(surrogates, domain, scenarios, targets, 41, z=z, sigma=sigma)
    assert list(frame.index) == list(range(len(frame)))
    at = 0
    for name, (observables, tol) in scenarios.items():
        strict = _box(domain, observables, targets, centres, slopes, lambda o: tol * abs(targets[o]))

        def widened(o):
            measurement = tol * abs(targets[o]) / z if sigma is None else sigma[o]
            return z * np.sqrt(se[o] ** 2 + measurement ** 2)

        robust = _box(domain, observables, targets, centres, slopes, widened)
        block = frame.iloc[at:at + dim]
        at += dim
        assert list(block["scenario"]) == [name] * dim and list(block["factor"]) == list(domain.factors)
        assert (block["observables"] == "+".join(observables)).all()
        assert (block["tolerance"] == tol).all() and (block["z"] == z).all()
        np.testing.assert_allclose(block["strict_fraction_pct"], 100 * strict[2], rtol=1e-7, atol=1e-9)
        np.testing.assert_allclose(block[["strict_lower", "strict_upper"]].to_numpy(),
                                   np.column_stack(strict[:2]), rtol=1e-7, atol=1e-9)
        np.testing.assert_allclose(block["strict_width"], strict[1] - strict[0], rtol=1e-7, atol=1e-9)
        # the plausible set on the grid: spans polished towards the boundary, never past it (a polished end is
        # an admissible point), within a small share of the range of it; the fraction within its own error
        span = np.array(domain.upper) - np.array(domain.lower)
        assert (block["robust_lower"].to_numpy() >= robust[0] - 1e-9 * span).all()
        assert (block["robust_upper"].to_numpy() <= robust[1] + 1e-9 * span).all()
        np.testing.assert_allclose(block["robust_lower"], robust[0], atol=2e-3 * span.max())
        np.testing.assert_allclose(block["robust_upper"], robust[1], atol=2e-3 * span.max())
        np.testing.assert_allclose(block["robust_width"], block["robust_upper"] - block["robust_lower"], rtol=1e-12)
        error = block["robust_fraction_error_pct"].iloc[0]
        assert (block["robust_fraction_error_pct"] == error).all() and 0 <= error < 1.0
        # (a straight band's boundary is refined to round-off: the error estimate may be below 1e-6 points)
        assert abs(block["robust_fraction_pct"].iloc[0] - 100 * robust[2]) <= error + 1e-6
        assert (block["strict_fraction_error_pct"] < 1e-3).all() and (block["strict_fraction_error_pct"] >= 0).all()
    assert at == len(frame)


def test_the_nominal_row_repeats_a_given_exact_set_and_recomputes_a_grid_set():
    """An exact strict set handed in is the nominal row as it is (here marked by a fraction of its own); a grid set
    is not reused (it may lie on another grid): the row is the set computed on the sweep's own grid."""
    from dataclasses import replace

    from demid.sampling.evaluate import evaluate_set
    from demid.sampling.grid import admissible_set

    domain = Domain(("a", "b"), (0.0, 0.0), (1.0, 1.0))
    surrogates = {"y": linear(0.0, [1.0, 0.0])}
    exact = evaluate_set(surrogates, domain, ("y",), {"y": 0.5}, 0.1, 21)
    marked = replace(exact, fraction=0.02)
    frame = tolerance_sweep(surrogates, domain, {"s": (["y"], 0.1)}, {"y": 0.5}, [0.2], 21, strict_sets={"s": marked})
    nominal = frame[frame["tolerance"] == 0.1]
    np.testing.assert_allclose(nominal["feasible_fraction_pct"], 2.0, rtol=1e-12)
    # b on a log axis: no polynomial of the search units, so the strict sets are grid sets
    log_domain = Domain(("a", "b"), (0.0, 1.0), (1.0, 10.0), (False, True))
    grid = admissible_set(surrogates, log_domain, ("y",), {"y": 0.5}, 0.1, 21)
    assert grid.exact is None
    frame = tolerance_sweep(surrogates, log_domain, {"s": (["y"], 0.1)}, {"y": 0.5}, [0.2], 21,
                            strict_sets={"s": replace(grid, fraction=0.02)})
    nominal = frame[frame["tolerance"] == 0.1]
    np.testing.assert_allclose(nominal["feasible_fraction_pct"], 10.0, rtol=1e-6)  # |a - 0.5| <= 0.05, all of b
