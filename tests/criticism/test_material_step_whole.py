"""The criticism step's numbers on planes (criticism.material): the reference point's relative errors, whether it
meets each observable's own tolerance and how far it lies from each scenario's admissible set, and a finding's
effect on the feasible fraction and widths, against a dense grid and the geometry of a slab computed here."""

from __future__ import annotations

import numpy as np
import pytest

from demid.criticism.material import _identifiability_effect, reference_point_position
from demid.spec import MaterialSpec
from demid.surrogate import Surrogate

LINEAR = [(0, 0), (1, 0), (0, 1)]
LOWER, UPPER = np.array([0.0, 1.0]), np.array([2.0, 3.0])


def _plane(name, coef) -> Surrogate:
    return Surrogate(name, ["a", "b"], LINEAR, np.asarray(coef, float), np.zeros((3, 3)), 0.0, 7)


def _predict(coef, points) -> np.ndarray:
    return coef[0] + coef[1] * points[:, 0] + coef[2] * points[:, 1]


def _material(rng, reference):
    y = np.array([rng.uniform(-2, 2), rng.uniform(0.5, 2), rng.uniform(-2, -0.5)])
    z = np.array([rng.uniform(1, 3), rng.uniform(-1, 1), rng.uniform(0.5, 1.5)])
    centre = np.array([[1.0, 2.0]])
    ty = float(_predict(y, centre)[0]) * rng.uniform(0.9, 1.1)  # targets met near the middle of the box
    tz = float(_predict(z, centre)[0]) * rng.uniform(0.9, 1.1)
    own_z = float(rng.choice([0.01, 0.2]))
    spec = MaterialSpec.from_material("m", {
        "design": {"type": "ccd"}, "factors": {"a": {"lower": 0, "upper": 2}, "b": {"lower": 1, "upper": 3}},
        "responses": {"y": {"target": ty}, "z": {"target": tz, "tolerance": own_z}}, "reference_point": reference,
        "scenarios": {"both": {"observables": ["y", "z"], "tolerance": 0.05},
                      "y_alone": {"observables": ["y"], "tolerance": 0.1}}})
    return {"y": _plane("y", y), "z": _plane("z", z)}, spec, {"y": (y, ty), "z": (z, tz)}, own_z


@pytest.mark.parametrize("seed", range(5))
def test_the_reference_points_errors_inside_and_distance(seed):
    rng = np.random.default_rng(seed)
    reference = {"a": float(rng.uniform(0, 2)), "b": float(rng.uniform(1, 3))}
    surrogates, spec, planes, own_z = _material(rng, reference)
    rows = {r["scenario"]: r for r in reference_point_position(surrogates, spec, 101)}
    point = np.array([[reference["a"], reference["b"]]])
    errors = {o: float((_predict(c, point)[0] - t) / abs(t)) for o, (c, t) in planes.items()}
    tolerance = {"both": {"y": 0.05, "z": own_z}, "y_alone": {"y": 0.1}}
    for name, row in rows.items():
        assert row["errors"] == pytest.approx({o: errors[o] for o in tolerance[name]}, rel=1e-9)
        inside = all(abs(errors[o]) <= tol for o, tol in tolerance[name].items())
        assert row["inside"] is inside
        if row["nearest_admissible"] is None:
            continue
        near = np.array([[row["nearest_admissible"]["a"], row["nearest_admissible"]["b"]]])
        apart = 100 * np.linalg.norm((near[0] - point[0]) / (UPPER - LOWER))
        assert row["distance_pct_of_range"] == (0.0 if inside else pytest.approx(apart, abs=1e-6))
    # one slab: the distance to it in units of the ranges, where its nearest point lies inside the box
    (c, t), tol = planes["y"], 0.1
    gap = abs(_predict(c, point)[0] - t) - tol * abs(t)
    slope = np.hypot(c[1] * 2.0, c[2] * 2.0)  # the plane's gradient per unit of each range
    # the band's nearest point: a step of gap / |g| along the gradient in units of the ranges (both 2 wide)
    foot = point[0] - np.sign(_predict(c, point)[0] - t) * gap / slope ** 2 * np.array([c[1], c[2]]) * 4.0
    if gap > 0 and np.all((foot >= LOWER) & (foot <= UPPER)):
        assert rows["y_alone"]["distance_pct_of_range"] == pytest.approx(100 * gap / slope, rel=1e-3)
    if gap <= 0:
        assert rows["y_alone"]["inside"] and rows["y_alone"]["distance_pct_of_range"] == 0.0


def _dense(planes, tolerances, extended=None):
    a, b = np.meshgrid(np.linspace(0, 2, 301), np.linspace(1, 3, 301), indexing="ij")
    points = np.column_stack([a.ravel(), b.ravel()])
    inside = np.ones(len(points), bool)
    for o, tol in tolerances.items():
        c, t = planes[o]
        c = extended if (o == "y" and extended is not None) else c
        inside &= np.abs(_predict(c, points) - t) <= tol * abs(t)
    widths = [float(np.ptp(points[inside, k])) if inside.any() else 0.0 for k in range(2)]
    return 100 * inside.mean(), widths


@pytest.mark.parametrize("seed", range(4))
def test_an_extensions_effect_is_each_scenarios_fraction_and_widths_before_and_after(seed):
    rng = np.random.default_rng(10 + seed)
    surrogates, spec, planes, own_z = _material(rng, {})
    y, ty = planes["y"]
    extended = y * np.array([1.0, rng.uniform(0.3, 0.7), rng.uniform(0.3, 0.7)])  # a flatter y: a wider set
    extended[0] += ty - _predict(extended, np.array([[1.0, 2.0]]))[0] * ty / _predict(y, np.array([[1.0, 2.0]]))[0]
    rows = _identifiability_effect(surrogates, _plane("y", extended), "y", spec, 201)
    assert [r["scenario"] for r in rows] == ["both", "y_alone"]
    for row, tolerances in zip(rows, ({"y": 0.05, "z": own_z}, {"y": 0.1})):
        before, width_before = _dense(planes, tolerances)
        after, width_after = _dense(planes, tolerances, extended)
        assert row["fraction_pct_before"] == pytest.approx(before, abs=1.0)
        assert row["fraction_pct_after"] == pytest.approx(after, abs=1.0)
        assert [row["width_before"][f] for f in "ab"] == pytest.approx(width_before, abs=0.03)
        assert [row["width_after"][f] for f in "ab"] == pytest.approx(width_after, abs=0.03)
    assert _identifiability_effect(surrogates, _plane("z", planes["z"][0]), "z", spec, 51)[0]["scenario"] == "both"


def _four_factor_material(rng, offset):
    """y a plane over four factors of different ranges, its target met at the box's centre, and a reference point
    ``offset`` (units of the ranges) outside the band along the plane's gradient."""
    lower, upper = np.array([0.0, 1.0, -2.0, 10.0]), np.array([1.0, 3.0, 2.0, 20.0])
    coef = np.concatenate([[rng.uniform(1, 2)], rng.uniform(0.5, 1.5, 4) * rng.choice([-1, 1], 4) / (upper - lower)])
    centre = (lower + upper) / 2
    target = float(coef[0] + coef[1:] @ centre)
    target = target if abs(target) > 0.5 else target + 2.0 * np.sign(coef[0])
    coef[0] += target - (coef[0] + coef[1:] @ centre)
    tol = 0.1
    g = coef[1:] * (upper - lower)  # the plane's gradient per unit of each range
    step = (tol * abs(target) / np.linalg.norm(g) + offset) * g / np.linalg.norm(g)
    reference = dict(zip("abcd", centre + step * (upper - lower)))
    names = "abcd"
    spec = MaterialSpec.from_material("m", {
        "design": {"type": "ccd"}, "factors": {f: {"lower": lo, "upper": hi} for f, lo, hi in zip(names, lower, upper)},
        "responses": {"y": {"target": target}}, "reference_point": {f: float(v) for f, v in reference.items()},
        "scenarios": {"y": {"observables": ["y"], "tolerance": tol}}})
    terms = [(0, 0, 0, 0)] + [tuple(int(i == k) for i in range(4)) for k in range(4)]
    sur = Surrogate("y", list(names), terms, coef, np.zeros((5, 5)), 0.0, 20)
    return {"y": sur}, spec, coef, target, lower, upper


@pytest.mark.parametrize("seed", range(3))
def test_four_factors_reference_distance_and_fractions_on_sampled_sets(seed):
    from demid.criticism.material import _effect_points

    rng = np.random.default_rng(seed)
    offset = 0.1 + 0.1 * seed
    surrogates, spec, coef, target, lower, upper = _four_factor_material(rng, offset)
    n = _effect_points(10 ** 6, 4)  # what the criticism step evaluates a 4-factor set on
    (row,) = reference_point_position(surrogates, spec, n)
    assert not row["inside"] and row["nearest_admissible"] is not None
    near = np.array([row["nearest_admissible"][f] for f in "abcd"])
    assert abs(coef[0] + coef[1:] @ near - target) <= 0.1 * abs(target) + 1e-9  # an admissible point
    ref = np.array([spec.reference_point[f] for f in "abcd"])
    assert row["distance_pct_of_range"] == pytest.approx(100 * np.linalg.norm((near - ref) / (upper - lower)))
    # no closer than the band itself, and within a sampled set's spacing of it
    assert 100 * offset - 1e-6 <= row["distance_pct_of_range"] <= 100 * offset + 6.0
    # an extension that tilts the plane: the fraction before and after against 100 000 random points
    tilted = coef * np.array([1.0, 0.5, 0.5, 2.0, 1.0])
    tilted[0] += target - (tilted[0] + tilted[1:] @ ((lower + upper) / 2))
    extended = Surrogate("y", list("abcd"), surrogates["y"].terms, tilted, np.zeros((5, 5)), 0.0, 20)
    (effect,) = _identifiability_effect(surrogates, extended, "y", spec, n)
    points = lower + rng.random((100_000, 4)) * (upper - lower)
    for key, c in (("fraction_pct_before", coef), ("fraction_pct_after", tilted)):
        share = 100 * np.mean(np.abs(c[0] + points @ c[1:] - target) <= 0.1 * abs(target))
        assert effect[key] == pytest.approx(share, abs=1.5)


def _slab(rng, lower, upper, tolerance, flatten=1.0):
    """A plane in one factor whose band (relative ``tolerance`` about a target of either sign) is centred inside
    [lower, upper] and may run past an end; the plane's slope times ``flatten`` about the same centre."""
    target = float(rng.choice([-1, 1]) * rng.uniform(1, 3))
    centre = rng.uniform(lower + 0.15 * (upper - lower), upper - 0.15 * (upper - lower))
    half = rng.uniform(0.1, 0.6) * (upper - lower)  # the half-width of the band before flattening
    slope = float(rng.choice([-1, 1])) * tolerance * abs(target) / half * flatten
    interval = (max(lower, centre - half / flatten), min(upper, centre + half / flatten))
    return np.array([target - slope * centre, slope]), target, interval


@pytest.mark.parametrize("seed", range(6))
def test_an_extensions_effect_on_slabs_is_the_exact_fraction_and_widths_in_percent(seed):
    rng = np.random.default_rng(40 + seed)
    own_z = float(rng.choice([0.02, 0.3]))
    y, ty, a_before = _slab(rng, 0.0, 2.0, 0.05)
    z, tz, b_both = _slab(rng, 1.0, 3.0, own_z)
    spec = MaterialSpec.from_material("m", {
        "design": {"type": "ccd"}, "factors": {"a": {"lower": 0, "upper": 2}, "b": {"lower": 1, "upper": 3}},
        "responses": {"y": {"target": ty}, "z": {"target": tz, "tolerance": own_z}},
        "scenarios": {"both": {"observables": ["y", "z"], "tolerance": 0.05},
                      "y_alone": {"observables": ["y"], "tolerance": 0.1}}})
    surrogates = {"y": _plane("y", [y[0], y[1], 0.0]), "z": _plane("z", [z[0], 0.0, z[1]])}
    flatten = rng.uniform(0.3, 0.7)
    extended = _plane("y", [ty - flatten * y[1] * (ty - y[0]) / y[1], flatten * y[1], 0.0])
    rows = {r["scenario"]: r for r in _identifiability_effect(surrogates, extended, "y", spec, 51)}
    centre, slope = (ty - y[0]) / y[1], abs(y[1])

    def a_interval(tolerance, slope):
        half = tolerance * abs(ty) / slope
        return max(0.0, centre - half), min(2.0, centre + half)

    b_width = b_both[1] - b_both[0]
    for name, tolerance, b in (("both", 0.05, b_width), ("y_alone", 0.1, 2.0)):
        row = rows[name]
        for when, s in (("before", slope), ("after", flatten * slope)):
            lo, hi = a_interval(tolerance, s)
            assert row[f"fraction_pct_{when}"] == pytest.approx(100 * (hi - lo) / 2 * b / 2, rel=1e-6)
            assert row[f"width_{when}"] == pytest.approx({"a": hi - lo, "b": b}, rel=1e-6)
    assert a_before == pytest.approx(a_interval(0.05, slope))


@pytest.mark.parametrize("reverse", [False, True])
def test_a_table_without_a_run_column_is_judged_in_its_row_order(reverse):
    from demid.criticism.material import material_run_order
    from demid.design import Coding

    from ..helpers import make_ccd_table

    table = make_ccd_table(lambda x: {"y": 3.0 + x[:, 0] + 0.1 * x[:, 1]}, [0.0, 1.0], [2.0, 3.0], seed=4)
    table = table.rename(columns={"x1": "a", "x2": "b"})
    # rows listed by y (ascending or descending), the run numbers left out: the rows follow the response
    table = table.sort_values("y", ascending=not reverse, kind="stable").drop(columns="run")
    spec = MaterialSpec.from_material("m", {
        "design": {"type": "ccd"}, "factors": {"a": {"lower": 0, "upper": 2}, "b": {"lower": 1, "upper": 3}},
        "responses": {"y": {"target": 4.0}}, "scenarios": {"y": {"observables": ["y"], "tolerance": 0.1}}})
    coding = Coding.from_levels(["a", "b"], table[["a", "b"]].to_numpy(), 1.41421)
    order = material_run_order(table, spec, coding).to_json()
    # y's ties (the centre runs) share a rank: the rank correlation of 1..n with y is +-1 only up to them
    y = table["y"].to_numpy()
    ranks = np.argsort(np.argsort(y, kind="stable"), kind="stable") + 1.0
    ties = np.array([np.mean(ranks[y == v]) for v in y])
    position = np.arange(1.0, len(y) + 1)
    rho = np.corrcoef(position, ties)[0, 1]
    assert order["reason"] == "sorted_by_response" and order["follows_response"] == "y"
    assert order["rank_correlation"] == pytest.approx(rho, abs=1e-6) and not order["drift_tested"]
    assert bool(rho > 0) is (not reverse)
