"""The recommended point (demid/uncertainty/recommended.py) against an independent search: for 2 and 3 factors
(linear and log) the grid minimiser of a known implausibility, found here on the grid built with numpy; for
4 factors a point inside the search range close to the known optimum; the digits a value is shown with; and the
uninformative observables with the numbers their reason quotes."""

from __future__ import annotations

import re

import numpy as np
import pandas as pd
import pytest

from demid.spec import MaterialSpec
from demid.uncertainty.recommended import (UNINFORMATIVE_FRACTION, digits_for, recommended_point,
                                           uninformative_observables)

_BOUNDS = [(-3.0, -1.0, False), (0.01, 10.0, True), (2.0, 7.0, False), (1.0, 1000.0, True)]


def _spec(d: int) -> MaterialSpec:
    factors = {f"f{i}": {"lower": lo, "upper": hi, **({"scale": "log"} if log else {})}
               for i, (lo, hi, log) in enumerate(_BOUNDS[:d])}
    return MaterialSpec.from_material("m", {
        "data": "x.csv", "design": {"type": "custom"}, "factors": factors, "responses": {"y": {"target": 1.0}},
        "scenarios": {"s": {"observables": ["y"], "tolerance": 0.05}}})


class _Judged:
    """A scenario whose implausibility is known: the largest distance from ``centre`` in search units, per factor
    over ``scale`` (a box-shaped plausible set of half-widths ``scale`` around ``centre``)."""

    name = "s"

    def __init__(self, spec, centre, scale):
        self.spec, self.centre, self.scale = spec, np.asarray(centre), np.asarray(scale)

    def implausibility(self, points):
        search = self.spec.domain.to_search(np.asarray(points, dtype=float))
        return np.max(np.abs(search - self.centre) / self.scale, axis=1)

    def contains(self, points):
        return self.implausibility(points) <= 1.0


def _search_range(spec):
    lo, hi = spec.domain.search_bounds()
    return np.asarray(lo), np.asarray(hi)


@pytest.mark.parametrize("d, n, nodes", [(1, 33, 33), (2, 21, 21), (2, 101, 101), (2, 401, 401), (3, 41, 41),
                                         (3, 101, 61)])
@pytest.mark.parametrize("where, scale", [(0.37, 0.2), (0.91, 0.02), (0.013, 0.5)])
def test_the_recommended_point_is_the_grid_node_of_least_implausibility(d, n, nodes, where, scale):
    """Up to two factors every grid has ``n`` nodes per axis; three factors at most 61."""
    spec = _spec(d)
    lo, hi = _search_range(spec)
    centre = lo + (where + 0.05 * np.arange(d)) % 1.0 * (hi - lo)
    judged = _Judged(spec, centre, scale * (hi - lo))
    found = recommended_point(judged, n=n)
    axes = [np.linspace(a, b, nodes) for a, b in zip(lo, hi)]
    grid = np.array(np.meshgrid(*axes, indexing="ij")).reshape(d, -1).T
    values = np.max(np.abs(grid - centre) / (scale * (hi - lo)), axis=1)
    best = grid[np.argmin(values)]
    assert found["scenario"] == "s"
    assert list(found["point"]) == spec.factor_names
    point = spec.domain.to_search(np.array([list(found["point"].values())]))[0]
    assert point == pytest.approx(best, rel=1e-9, abs=1e-12)
    assert found["implausibility"] == pytest.approx(values.min(), rel=1e-9)
    assert found["plausible"] is bool(values.min() <= 1.0)


def test_four_factors_are_searched_over_the_whole_range_and_only_there():
    spec = _spec(4)
    lo, hi = _search_range(spec)
    for where in (0.1, 0.5, 0.93):
        centre = lo + where * (hi - lo)
        found = recommended_point(_Judged(spec, centre, 0.5 * (hi - lo)))
        point = spec.domain.to_search(np.array([list(found["point"].values())]))[0]
        assert np.all(point >= lo) and np.all(point <= hi)
        # 2^14 scrambled Sobol points: one lies within a tenth of the range of any point on every axis
        assert np.all(np.abs(point - centre) <= 0.1 * (hi - lo)), (where, point, centre)
        assert found["implausibility"] <= 0.2 and found["plausible"] is True


@pytest.mark.parametrize("width, digits", [(8.76, 1), (0.0091, 4), (0.5, 2), (1.0, 1), (0.1, 2), (0.099, 3),
                                           (12.0, 0), (1e4, 0), (3.2e-5, 6), (0.0, 4), (-1.0, 4),
                                           (float("nan"), 4), (float("inf"), 4)])
def test_digits_show_a_value_to_a_tenth_of_its_interval(width, digits):
    assert digits_for(width) == digits
    if np.isfinite(width) and width > 0 and digits > 0:  # the tenth of the width is the last digit shown
        assert 10.0 ** -digits <= width / 10 + 1e-15 < 10.0 ** (1 - digits)


def test_an_observable_whose_band_leaves_the_range_is_uninformative_with_its_share_and_gain_quoted():
    assert UNINFORMATIVE_FRACTION == 0.99
    ranking = pd.DataFrame({
        "observables": ["a", "b", "c", "d", "a+b"], "n_observables": [1, 1, 1, 1, 2],
        "feasible_fraction_pct": [99.0, 98.99, 99.97, 100.0, 99.5],
        "information_gain_bits": [0.013, 0.5, float("nan"), 0.004, 0.0]})
    out = uninformative_observables(ranking)
    assert sorted(out) == ["a", "c", "d"]  # b removes just over 1 %; a pair is never named
    for name, share, bits in (("a", 99.0, "0.01"), ("c", 99.97, None), ("d", 100.0, "0.00")):
        text = out[name]
        assert float(re.search(r"alone it leaves ([\d.]+) %", text).group(1)) == pytest.approx(share, rel=5.1e-3)
        assert "so it removes less than 1 %" in text
        assert (f"({bits} bit:" in text) if bits else "bit" not in text
    assert uninformative_observables(None) == {} and uninformative_observables(ranking.iloc[0:0]) == {}
    assert uninformative_observables(ranking.drop(columns="n_observables")) == {}


@pytest.mark.parametrize("dim", [1, 2, 3, 4, 5, 6])
def test_the_analysis_sizes_are_odd_grids_up_to_three_factors_and_balanced_sobol_samples_above(dim):
    """A grid of odd size per axis holds the range's centre node; a scrambled Sobol sample is balanced only at a
    power of two, and 2^14 points or more keep a fraction's error below the 0.1 % the sizes were chosen for."""
    from demid.uncertainty.material import recommended_sizes

    sizes = recommended_sizes(dim)
    if dim <= 3:
        assert set(sizes) == {"plausible", "sweep", "posterior"}
        assert all(n % 2 == 1 and n >= 41 for n in sizes.values())
        assert sizes["plausible"] >= sizes["sweep"]
        return
    assert set(sizes) == {"plausible", "sweep", "posterior", "posterior_points"}
    for key in ("plausible", "sweep", "posterior_points"):
        n = sizes[key]
        assert n >= 2 ** 14 and n & (n - 1) == 0, (key, n)
    assert sizes["posterior_points"] >= sizes["plausible"] and 20 <= sizes["posterior"] <= 200  # histogram bins


@pytest.mark.parametrize("k", [1, 2, 3, 4, 5])
def test_the_notes_give_the_sizes_the_analysis_used_in_its_words_for_grid_and_sobol(k):
    """The sizes note: grid points per axis up to three factors, scrambled Sobol points (with the posterior's
    points and bins) above; the numbers are recommended_sizes' (or the caller's, merged over them)."""
    from demid.scenario import JudgedScenario, reference_scenario
    from demid.uncertainty.material import _notes, recommended_sizes

    factors = {f"f{i}": {"lower": 0.0, "upper": 1.0} for i in range(k)}
    spec = MaterialSpec.from_material("m", {
        "data": "x.csv", "design": {"type": "custom"}, "factors": factors, "responses": {"y": {"target": 2.0}},
        "scenarios": {"s": {"observables": ["y"], "tolerance": 0.05}}})
    reference = JudgedScenario(spec, reference_scenario(spec, ["y"]), {}, 2.0)
    sizes = recommended_sizes(k)
    notes = _notes(spec, reference, sizes, {}, (), {})
    if k <= 3:
        expected = (f"Plausible sets on {sizes['plausible']} grid points per axis, sweeps on {sizes['sweep']}, "
                    f"posteriors on {sizes['posterior']} grid points per axis.")
    else:
        expected = (f"Plausible sets on {2 ** 16} scrambled Sobol points, sweeps on {2 ** 14}, posteriors on "
                    f"{2 ** 16} scrambled Sobol points (51 histogram bins).")
    assert notes[2] == expected
    assert notes[0].startswith("Plausible sets: z = 2; y: ") and notes[1].startswith("Posteriors and ranking at "
                                                                                      "tolerance 0.05: y: ")
