"""A simulated material's next wave over the search range: runs where the set's boundary is decided, inside the
wave's count, and in a part of the set the refocused box would cut off."""

from __future__ import annotations

import json

import numpy as np
import pandas as pd
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from demid.next_wave import PURPOSE_DECIDE, plan_next_wave
from demid.spec import MaterialSpec
from demid.surrogate import fit_material
from demid.uncertainty import plausible_identifiability_frame

from .helpers import make_ccd_table

TARGET, TOL = 13.0, 0.02
BAND = TOL * TARGET
GRID = np.array([[a, b] for a in np.linspace(0, 1, 201) for b in np.linspace(0, 1, 201)])


def _linear(x):
    """y = 10 + 4 a + 2 b: the set |y - 13| <= 0.26 is the strip between two parallel lines."""
    return 10 + 4 * x[:, 0] + 2 * x[:, 1]


def _boundary_distance(x):
    """Distance of each point to the nearer of the strip's two edge lines 4 a + 2 b = 3 -/+ 0.26 (closed form)."""
    level = 4 * x[:, 0] + 2 * x[:, 1]
    return np.minimum(np.abs(level - (3 - BAND)), np.abs(level - (3 + BAND))) / np.sqrt(20.0)


def _study(response, target=TARGET, tolerance=TOL, count=9, noise=0.05, z=2.0, margin=0.1):
    """A noisy CCD over [0, 1]^2 of ``response``, its quadratic fit and plausible frame (as the analysis writes it)."""
    table = make_ccd_table(lambda x: {"y": response(x)}, [0, 0], [1, 1], noise=noise, seed=4)
    table = table.rename(columns={"x1": "a", "x2": "b"})
    table["status"] = "ok"
    spec = MaterialSpec.from_material("m", {
        "data": "planted.csv", "design": {"type": "ccd", "alpha": 1.41421, "center_runs": 5},
        "factors": {"a": {"lower": 0.0, "upper": 1.0}, "b": {"lower": 0.0, "upper": 1.0}},
        "responses": {"y": {"target": target}}, "scenarios": {"y": {"observables": ["y"], "tolerance": tolerance}},
        "next_runs": {"count": count, "scenario": "", "margin": margin}})
    return table, spec, *_fit(table, spec, z)


def _fit(table, spec, z):
    surrogates = {f.response: f.surrogate() for f in fit_material(table, spec)}
    target, tolerance = spec.targets["y"], spec.scenarios[0].tolerance
    plausible = plausible_identifiability_frame(surrogates, spec.domain, {"y": (("y",), tolerance)}, {"y": target}, 201,
                                          z=z)
    return surrogates, plausible


def test_the_runs_lie_near_the_true_boundary_far_more_than_a_space_filling_design():
    """On a strip whose edges are known in closed form, with scatter of 0.2 (three quarters of the band), half the
    wave's runs lie within 0.05 of an edge (the median distance), where a space-filling design's median is over
    three times farther.  (A design on the band at twice the plausible set's z, the runs before, had a median
    of 0.155: its runs filled the band instead of straddling its edges.)"""
    table, spec, surrogates, plausible = _study(_linear, noise=0.2)
    wave = plan_next_wave("m", table, surrogates, spec, plausible, z=2.0, analysed_over_omega=True)
    median = float(np.median(_boundary_distance(wave.runs[["a", "b"]].to_numpy(dtype=float))))
    space_filling = float(np.median(_boundary_distance(GRID)))
    assert space_filling > 0.15  # premise: the edges are a small part of the range
    assert len(wave.runs) == 9 and median <= 0.05, wave.runs


def test_the_wave_runs_spread_along_the_boundary():
    """The space-filling factor keeps a wave's runs apart: no two closer than a sixth of the spacing of a uniform
    design of every run (earlier and new), n^(-1/2) in two factors."""
    table, spec, surrogates, plausible = _study(_linear)
    wave = plan_next_wave("m", table, surrogates, spec, plausible, z=2.0, analysed_over_omega=True)
    x = wave.runs[["a", "b"]].to_numpy(dtype=float)
    gaps = np.linalg.norm(x[:, None, :] - x[None, :, :], axis=2)[np.triu_indices(len(x), 1)]
    assert gaps.min() >= (len(table) + len(x)) ** -0.5 / 6


@pytest.fixture(scope="module")
def linear_study():
    return _study(_linear)


@given(count=st.integers(7, 20), deciding=st.integers(0, 25), spread=st.lists(st.floats(0, 1), min_size=2,
                                                                                   max_size=2))
@settings(max_examples=25, deadline=None, derandomize=True)
def test_the_count_is_never_exceeded(linear_study, count, deciding, spread):
    """Over generated waves (count, how many runs the criticism proposes and where), the wave has exactly
    ``count`` runs, the criticism's first, all inside the search range."""
    table, spec, surrogates, plausible = linear_study
    spec = MaterialSpec.from_material("m", {**spec.material_config(), "next_runs": {"count": count, "scenario": "",
                                                                                     "margin": 0.1}})
    runs = [{"a": spread[0], "b": spread[1], "purpose": PURPOSE_DECIDE}] * deciding
    findings = pd.DataFrame([{"response": "y", "cause": "ambiguous", "detail": "outlier (3);step (9)", "aliases": "",
                              "discriminating_runs": json.dumps(runs)}])
    wave = plan_next_wave("m", table, surrogates, spec, plausible, findings, z=2.0, analysed_over_omega=True)
    assert len(wave.runs) == count
    assert wave.runs["purpose"].tolist()[:min(deciding, count)] == [PURPOSE_DECIDE] * min(deciding, count)
    assert wave.runs[["a", "b"]].apply(lambda c: c.between(0.0, 1.0)).all().all()
    box = wave.domain.set_index("factor")
    for f in ("a", "b"):  # the next domain is where the runs were placed
        assert box.at[f, "lower"] == wave.runs[f].min() and box.at[f, "upper"] == wave.runs[f].max()


def _two_strips(x):
    """y = 10 + 8 (a - 0.5)^2 + b: at the target 11.5 the set is two disjoint strips, one on each side of a = 0.5."""
    return 10 + 8 * (x[:, 0] - 0.5) ** 2 + x[:, 1]


def test_a_set_a_refocused_box_cuts_gets_runs_in_the_cut_part_and_is_not_cut():
    """Two disjoint admissible strips, and the refocused box of an earlier box-local analysis (planted: its
    plausible span of a is 0-0.45, the left strip only) cuts off the right one.  A wave placed in that box
    could not reach it; the wave over the search range puts runs in the cut part, and after two waves the
    set, analysed with every run over the range, covers the cut part and is close to the true set."""
    from demid.next_wave import planned_box
    from demid.scenario import JudgedScenario

    target, tolerance = 11.5, 0.02
    table, spec, surrogates, plausible = _study(_two_strips, target=target, tolerance=tolerance, noise=0.05)
    plausible = plausible.copy()
    plausible.loc[plausible["factor"] == "a", ["robust_lower", "robust_upper"]] = [0.0, 0.45]
    truth = np.abs(_two_strips(GRID) - target) <= tolerance * target
    lo, hi, _ = planned_box(spec, plausible)
    cut = truth & ~np.all((GRID >= lo) & (GRID <= hi), axis=1)
    assert cut.sum() >= 0.4 * truth.sum()  # premise: the box cuts off the right strip
    rng = np.random.default_rng(7)
    for wave_number in (1, 2):
        wave = plan_next_wave("m", table, surrogates, spec, plausible, z=2.0, analysed_over_omega=True)
        x = wave.runs[["a", "b"]].to_numpy(dtype=float)
        if wave_number == 1:
            near_cut = np.min(np.linalg.norm(x[:, None, :] - GRID[cut][None, :, :], axis=2), axis=1) <= 0.05
            assert near_cut.sum() >= 2, wave.runs
        new = pd.DataFrame({"run": np.arange(len(table) + 1, len(table) + 1 + len(x)), "a": x[:, 0], "b": x[:, 1],
                            "y": _two_strips(x) + 0.05 * rng.standard_normal(len(x)), "status": "ok"})
        table = pd.concat([table, new], ignore_index=True)
        surrogates, plausible = _fit(table, spec, 2.0)
    estimate = JudgedScenario(spec, spec.scenarios[0], surrogates, 2.0).contains(GRID, plausible=False)
    assert (estimate & cut).sum() >= 0.9 * cut.sum()
    assert (estimate ^ truth).sum() <= 0.3 * truth.sum()


@pytest.mark.parametrize("target, tolerance", [(13.0, 0.02), (11.5, 0.05), (-13.0, 0.02)])
def test_the_set_probability_is_the_normal_mass_inside_the_band_around_the_target(target, tolerance):
    """P(x in the strict set) for one observable is the normal probability of |y - y*| <= ε|y*| with y around the
    surrogate's prediction and its prediction standard error (written out here with scipy's normal), for targets
    of either sign and other tolerances; inflating the error flattens it toward the same mass of a wider normal."""
    from scipy.stats import norm

    from demid.boundary_runs import set_probability
    from demid.scenario import judged_scenarios

    sign = np.sign(target)
    table, spec, surrogates, _ = _study(lambda x: sign * _linear(x), target=target, tolerance=tolerance)
    judged = judged_scenarios(spec, surrogates, z=2.0)[spec.scenarios[0].name]
    points = GRID[::997]
    mean, se = surrogates["y"].predict(points), surrogates["y"].se_prediction(points)
    band = tolerance * abs(target)
    for inflation in (1.0, 3.0):
        sd = inflation * se
        expected = norm.cdf((target + band - mean) / sd) - norm.cdf((target - band - mean) / sd)
        np.testing.assert_allclose(set_probability(judged, points, inflation), expected, rtol=1e-9, atol=1e-12)
