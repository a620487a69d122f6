"""The scenario the next wave refocuses on by default, over generated studies with scenarios of different
sizes: the one with the most observables, ties broken by the smallest tolerance, then the config order."""

from __future__ import annotations

from hypothesis import given, settings
from hypothesis import strategies as st

from demid.next_wave import refocus_scenario
from demid.spec import MaterialSpec

NAMES = ["y1", "y2", "y3", "y4"]


@st.composite
def scenario_sets(draw):
    count = draw(st.integers(1, 4))
    scenarios = {}
    for k in range(count):
        observables = draw(st.lists(st.sampled_from(NAMES), min_size=1, max_size=4, unique=True))
        scenarios[f"s{k}"] = {"observables": observables, "tolerance": draw(st.sampled_from([0.02, 0.05, 0.1]))}
    return scenarios


@given(scenario_sets())
@settings(max_examples=40, deadline=None, derandomize=True)
def test_default_refocus_is_the_scenario_with_most_observables(scenarios):
    material = {"data": "x.csv", "design": {"type": "custom"},
                "factors": {"a": {"lower": 0.0, "upper": 1.0}, "b": {"lower": 0.0, "upper": 1.0}},
                "responses": {n: {"target": 1.0 + i} for i, n in enumerate(NAMES)}, "scenarios": scenarios}
    spec = MaterialSpec.from_material("m", material, grid_points=11)
    chosen = refocus_scenario(spec)
    most = max(len(s["observables"]) for s in scenarios.values())
    assert len(scenarios[chosen]["observables"]) == most
    tied = [name for name, s in scenarios.items() if len(s["observables"]) == most]
    tightest = min(scenarios[name]["tolerance"] for name in tied)
    assert scenarios[chosen]["tolerance"] == tightest
    assert chosen == next(name for name in tied if scenarios[name]["tolerance"] == tightest)


@given(k=st.integers(1, 4), seed=st.integers(0, 10_000), log_mask=st.integers(0, 15))
@settings(max_examples=20, deadline=None, derandomize=True)
def test_the_box_points_are_the_boxs_grid_in_actual_units(k, seed, log_mask):
    """A box anywhere in a search range of any sign and scale (log factors in log10 units): its points are the
    grid of levels -1, -0.5, 0, 0.5, 1 (three levels above three factors) mapped onto [lo, hi], every level
    combination once, in the grid's order."""
    import itertools

    import numpy as np

    from demid.next_wave import box_points

    from .generators import random_domain

    rng = np.random.default_rng(seed)
    domain, lo_s, hi_s = random_domain(rng, k, log_mask, lower=(-3.0, 3.0), width=(0.5, 4.0))
    log = domain.log
    a, b = rng.uniform(0.0, 0.5, k), rng.uniform(0.5, 1.0, k)
    lo, hi = lo_s + a * (hi_s - lo_s), lo_s + b * (hi_s - lo_s)
    levels = (0.0, 0.25, 0.5, 0.75, 1.0) if k <= 3 else (0.0, 0.5, 1.0)
    expected = np.array([[lo[i] + t * (hi[i] - lo[i]) for i, t in enumerate(c)]
                         for c in itertools.product(levels, repeat=k)])
    expected = np.where(log, 10.0 ** expected, expected)
    points = box_points(domain, lo, hi)
    assert points.shape == expected.shape
    assert np.allclose(points, expected, rtol=1e-12, atol=0.0)


@given(offset=st.sampled_from([0.0, -250.0, 1000.0, 2.5e5]), width=st.sampled_from([1e-3, 0.05, 1.0, 300.0]),
       side=st.sampled_from(["lower", "upper", "none"]))
@settings(max_examples=30, deadline=None, derandomize=True)
def test_the_box_reason_names_a_factor_only_where_the_box_narrows_its_range(offset, width, side):
    """A box equal to the current range keeps it, whatever the factor's scale and distance from zero (a narrow
    range far from zero included); a box 1 % in from one end names that factor with its new bounds."""
    import re

    import numpy as np

    from demid.next_wave import _box_reason

    spec = MaterialSpec.from_material("m", {
        "data": "x.csv", "design": {"type": "custom"},
        "factors": {"t": {"lower": offset, "upper": offset + width}, "b": {"lower": 0.0, "upper": 1.0}},
        "responses": {"y": {"target": 1.0}}, "scenarios": {"s": {"observables": ["y"], "tolerance": 0.05}},
        "next_runs": {"count": 9, "scenario": "", "margin": 0.1}})
    lo, hi = (np.array(v, dtype=float) for v in spec.domain.search_bounds())
    if side == "lower":
        lo[0] += 0.01 * width
    elif side == "upper":
        hi[0] -= 0.01 * width
    text = _box_reason(spec, spec.scenarios[0], lo, hi, lo, hi, False)
    if side == "none":
        assert text == ("The plausible set of scenario 's' (y) reaches (within the margin) every edge of the "
                        "current range, so the range is kept")
    else:
        said = re.fullmatch(r"Refocused on the plausible set of scenario 's' \(y\) with a margin of 0\.1 of the "
                            r"range: t (\S+)–(\S+)", text)
        assert said, text
        assert [float(said[1]), float(said[2])] == [float(f"{lo[0]:.4g}"), float(f"{hi[0]:.4g}")]
    assert _box_reason(spec, spec.scenarios[0], lo, hi, lo, hi, True) == \
        "Scenario 's' (y) has no plausible point, so the current range is kept"
