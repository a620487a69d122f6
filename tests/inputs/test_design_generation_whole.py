"""The run-sheet generator's checks and small outputs (demid.design_generation), each against its rule written out
here, on and past every bound: factor ranges (equal ends, either sign, unusable magnitudes, malformed text), the
axial distance (1 itself, just below, not finite, the named ones for 1-6 factors), the counts (factors 0-7 per
design type, centre runs -1 to 2), the blocks (type, count, centre runs per block), the 3^k factorial's extra centre
runs, the config fragment read back as YAML and a factor named twice."""

from __future__ import annotations

from itertools import product

import numpy as np
import pytest
import yaml

from demid.design_generation import (FactorRange, _check_blocks, _check_counts, coded_points, factorial_points,
                                     fragment_yaml, generate_sheet, parse_alpha, parse_factor)
from demid.errors import InputError


@pytest.mark.parametrize("text, expected", [
    ("a=0:1", FactorRange("a", 0.0, 1.0)), (" mu_r = -0.5:-0.25", FactorRange("mu_r", -0.5, -0.25)),
    ("E=1e7:1e9", FactorRange("E", 1e7, 1e9)), ("h=-1e-30:1e-30", FactorRange("h", -1e-30, 1e-30))])
def test_a_valid_factor_range_is_read_with_its_name_stripped(text, expected):
    assert parse_factor(text) == expected


@pytest.mark.parametrize("text, message", [
    ("a=1:1", "--factor a: LOW must be below HIGH, found 1:1"),
    ("a=2:1", "--factor a: LOW must be below HIGH, found 2:1"),
    ("a0:1", "--factor: expected NAME=LOW:HIGH, found 'a0:1'"),
    ("a=0-1", "--factor: expected NAME=LOW:HIGH, found 'a=0-1'"),
    ("=0:1", "--factor: expected NAME=LOW:HIGH, found '=0:1'"),
    ("a=0:x", "--factor a: LOW and HIGH must be numbers, found '0:x'"),
    ("a=0:1e31", "--factor a: found '1e31', outside the magnitudes demid computes with (0, or 1e-30 to 1e30); "
                 "check the value, or give it in another unit"),
    ("a=1e-400:1", "--factor a: found '1e-400', too small for a float (it reads as 0); give it in another unit"),
    ("a=nan:1", "--factor a: found 'nan', not a number"),
    ("2a=0:1", "--factor: '2a' is not a valid column name (letters, digits, _; starts with a letter)")])
def test_a_bad_factor_range_is_one_line_naming_the_option(text, message):
    with pytest.raises(InputError) as info:
        parse_factor(text)
    assert info.value.detail == message


@pytest.mark.parametrize("k", [1, 2, 3, 4, 5, 6])
def test_the_named_axial_distances(k):
    assert parse_alpha("rotatable", k) == pytest.approx((2.0 ** k) ** 0.25, rel=1e-15)
    assert parse_alpha("face", k) == 1.0
    assert parse_alpha("1", k) == 1.0 and parse_alpha("1.5", k) == 1.5


@pytest.mark.parametrize("text", ["0.999", "0", "-1.5", "nan", "inf"])
def test_an_axial_distance_below_one_or_not_finite_is_refused(text):
    with pytest.raises(InputError) as info:
        parse_alpha(text, 3)
    assert info.value.detail == f"--alpha: a CCD needs alpha >= 1, found {text}"


def _count_problem(design_type, k, centres):
    """The documented count rules, in the order they are checked."""
    if centres < 0:
        return f"--center-runs: must be 0 or more, found {centres}"
    if design_type == "box_behnken" and not 3 <= k <= 5:
        return f"--type box_behnken: needs 3 to 5 factors, found {k}"
    if design_type == "factorial" and centres < 1:
        return "--center-runs: a 3^k factorial contains its centre point, so at least 1"
    if centres < 1:
        return f"--center-runs: a {design_type} design needs at least 1 centre run, found 0"
    if not 1 <= k <= 6:
        return f"--factor: 1 to 6 factors are supported, found {k}"
    return None


@pytest.mark.parametrize("design_type, k, centres", list(product(("ccd", "box_behnken", "factorial"), range(0, 8),
                                                                 (-1, 0, 1, 2))))
def test_the_counts_are_refused_exactly_outside_their_bounds(design_type, k, centres):
    want = _count_problem(design_type, k, centres)
    if want is None:
        _check_counts(design_type, k, centres)
    else:
        with pytest.raises(InputError) as info:
            _check_counts(design_type, k, centres)
        assert info.value.detail == want


@pytest.mark.parametrize("k, blocks, centres", list(product((2, 3, 4), (1, 2, 3, 4), (1, 2, 3))))
def test_blocks_are_two_or_from_three_factors_three_each_with_a_centre_run(k, blocks, centres):
    coded = coded_points("ccd", k, 1.5, centres)
    allowed = (2, 3) if k >= 3 else (2,)
    if blocks not in allowed:
        with pytest.raises(InputError) as info:
            _check_blocks("ccd", k, centres, blocks, coded)
        assert info.value.detail.startswith(f"--blocks: a {k}-factor CCD is run in 2 blocks (factorial | axial)")
        assert info.value.detail.endswith(f", found {blocks}")
        assert ("or 3 (two half-factorials | axial)" in info.value.detail) == (k >= 3)
    elif centres < blocks:
        with pytest.raises(InputError) as info:
            _check_blocks("ccd", k, centres, blocks, coded)
        assert info.value.detail == (f"--center-runs: {blocks} blocks need a centre run each, found {centres} "
                                     "centre runs")
    else:
        labels = _check_blocks("ccd", k, centres, blocks, coded)
        assert sorted(set(labels.tolist())) == list(range(1, blocks + 1))
        centre = np.all(coded == 0, axis=1)
        assert all(np.any(centre & (labels == b)) for b in range(1, blocks + 1))
    with pytest.raises(InputError, match="only a ccd design is written in blocks"):
        _check_blocks("box_behnken", k, centres, blocks, coded)


@pytest.mark.parametrize("k", [1, 2, 3])
@pytest.mark.parametrize("centres", [0, 1, 2, 5])
def test_the_three_level_factorial_counts_its_own_centre_point_as_the_first(k, centres):
    points = factorial_points(k, centres)
    assert len(points) == 3 ** k + max(centres - 1, 0)
    assert int(np.sum(np.all(points == 0, axis=1))) == max(centres, 1)
    assert {tuple(p) for p in points} == set(product((-1.0, 0.0, 1.0), repeat=k))


@pytest.mark.parametrize("responses", [(), ("d", "h")])
def test_the_fragment_reads_back_as_the_material_config_after_its_comments(responses):
    factors = [FactorRange("mu", 0.1, 0.5), FactorRange("e", -2.0, 3.0), FactorRange("k", 1e3, 1e5)]
    sheet = generate_sheet("ccd", factors, center_runs=3, alpha="1.5", seed=4)
    text = fragment_yaml(sheet, "glass", "tables/glass.csv", responses)
    comments = [line for line in text.splitlines() if line.startswith("#")]
    assert text.startswith("\n".join(comments) + "\n")
    assert comments[0] == ("# Generated with the run sheet; add a target to each response that is measured," if responses
                           else "# Generated with the run sheet; add `responses:` (one per simulated response column, "
                                "with targets),")
    assert yaml.safe_load(text) == {"materials": {"glass": sheet.material_config("tables/glass.csv", responses)}}
    assert list(yaml.safe_load(text)["materials"]["glass"]["factors"]) == ["mu", "e", "k"]


@pytest.mark.parametrize("design_type, k, centres", [("ccd", 2, 5), ("ccd", 4, 3), ("box_behnken", 3, 3),
                                                     ("factorial", 2, 2)])
def test_without_a_seed_the_sheet_is_the_one_demid_design_writes_without_one(design_type, k, centres):
    """``demid design`` without --seed uses seed 0: the run order is numpy's default_rng(0) permutation of the
    standard order, and every run's factor values are its standard-order point's, in actual units."""
    factors = [FactorRange(f"x{i}", -1.0 - i, 2.0 + 3 * i) for i in range(k)]
    frame = generate_sheet(design_type, factors, center_runs=centres).to_frame()
    a = 2 ** (k / 4) if design_type == "ccd" else 1.0
    coded = coded_points(design_type, k, a, centres)
    order = np.random.default_rng(0).permutation(len(coded))
    assert list(frame["run"]) == list(range(1, len(coded) + 1)) and list(frame["std_order"]) == list(order + 1)
    for i, f in enumerate(factors):
        centre, half = (f.low + f.high) / 2, (f.high - f.low) / (2 * a)
        np.testing.assert_allclose(frame[f.name], centre + half * coded[order, i], rtol=1e-11, atol=1e-11)


@pytest.mark.parametrize("names, named", [(["a", "a"], "a"), (["mu_r", "h", "mu_r"], "mu_r"),
                                          (["b", "a", "b", "a"], "a"), (["z", "y", "x", "z", "y"], "y")])
def test_a_factor_named_twice_is_one_line_naming_the_alphabetically_first_repeated_name(names, named):
    factors = [FactorRange(n, 0.0, 1.0 + i) for i, n in enumerate(names)]
    repeated = [n for n in names if names.count(n) > 1]
    assert named == min(repeated)
    with pytest.raises(InputError) as err:
        generate_sheet("ccd", factors, center_runs=3)
    assert str(err.value) == f"--factor: '{named}' given more than once"
