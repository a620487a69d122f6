"""Which three-level family a set of coded points is read as, at the documented distance: the closest family
(points outside it plus its points without a run), None when even that one is more than one point in ten of the
family (at least one) away -- checked over 2-6 factors, each family, and distances on both sides of the limit."""

from __future__ import annotations

from itertools import product

import pytest

from demid.design_inference import _closest_three_level_family


def _families(k):
    full = {p for p in product((-1, 0, 1), repeat=k) if any(p)}
    corners = {p for p in full if 0 not in p}
    out = {"two_level": corners}
    if k >= 3:
        out["box_behnken"] = {p for p in full if sum(v != 0 for v in p) == 2}
        out["ccd"] = corners | {p for p in full if sum(v != 0 for v in p) == 1}
    return out


def _limit(size: int) -> int:
    return max(1, size // 10)  # "more than one point in ten (at least one)", read as whole points


@pytest.mark.parametrize("k", [2, 3, 4, 5, 6])
def test_a_family_missing_points_up_to_a_tenth_is_read_as_that_family_and_beyond_as_none(k):
    for name, family in _families(k).items():
        ordered = sorted(family)
        limit = _limit(len(family))
        within = set(ordered[limit:])  # `limit` runs missing
        assert _closest_three_level_family(within, k) == name, (k, name, limit)
        beyond = set(ordered[limit + 1:])
        if len(beyond) and all(len(beyond ^ other) > _limit(len(other))
                               for other in _families(k).values() if other is not family):
            assert _closest_three_level_family(beyond, k) is None, (k, name, limit + 1)


def test_the_documented_limit_at_six_factors():
    corners = sorted(_families(6)["two_level"])  # 64 points: one in ten is 6
    assert _closest_three_level_family(set(corners[6:]), 6) == "two_level"
    assert _closest_three_level_family(set(corners[7:]), 6) is None
