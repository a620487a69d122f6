"""The criticism step's level 2 and identifiability effect on planes (criticism.material): whether every target
can be met, which ends of the search range the admissible set reaches and the "widen" advice that follows, judged
at the reference tolerance whether or not a scenario holds the targets at it (a scenario of the same observables
at another tolerance must not decide); and an extension's effect on every scenario of its response only.
Expected values come from linear programs over the box and a dense grid written here.  Level 1 is replaced by a
stand-in that names one finding, so that the step's own wiring is what is checked."""

from __future__ import annotations

import numpy as np
import pandas as pd
import pytest
from scipy.optimize import linprog

import demid.criticism.material as material
from demid.sampling.domain import BOUND_TOUCH
from demid.spec import MaterialSpec
from demid.surrogate import Surrogate

from ..helpers import make_ccd_table

LINEAR = [(0, 0), (1, 0), (0, 1)]
NO_FITS = {"y": None, "z": None}  # read by level 1 and the figure only, both stood in for


def _plane(name, coef) -> Surrogate:
    return Surrogate(name, ["a", "b"], LINEAR, np.asarray(coef, float), np.zeros((3, 3)), 0.0, 7)


class _Level1:
    """What level 1 hands the step: a finding for the responses in ``extended`` (with that extension)."""

    def __init__(self, response, extended):
        self.response, self.extended = response, extended
        self.findings = ["a finding"] if extended is not None else []
        self.verdict, self.verdict_message = ("defect" if self.findings else "adequate"), ""

    def to_json(self):
        return {"findings": [{"message": f"{self.response}: {f}."} for f in self.findings], "verdict": self.verdict,
                "verdict_detail": {}}

    def to_frame(self):
        return pd.DataFrame([{"response": self.response, "cause": "outlier", "detail": "1", "aliases": "",
                              "message": "x", "verdict": self.verdict}] if self.findings else [],
                            columns=["response", "cause", "detail", "aliases", "message", "verdict"])

    def extended_surrogate(self):
        return self.extended


@pytest.fixture
def level1_stand_in(monkeypatch):
    extensions = {}
    monkeypatch.setattr(material, "criticize", lambda table, factors, response, **kw:
                        _Level1(response, extensions.get(response)))
    monkeypatch.setattr(material, "residual_figure", lambda *a, **kw: None)
    return extensions


def _study(rng, lower, upper, scenarios):
    """Two planes over [lower, upper] whose targets are met at a random point of the box."""
    span = upper - lower
    coef = {o: np.concatenate([[rng.uniform(-3, 3)], rng.uniform(0.5, 2, 2) * rng.choice([-1, 1], 2) / span])
            for o in ("y", "z")}
    x0 = lower + rng.uniform(0.05, 0.95, 2) * span
    targets = {o: float(c[0] + c[1:] @ x0) for o, c in coef.items()}
    for o in coef:  # keep the targets away from zero: a relative band
        if abs(targets[o]) < 1.0:
            coef[o][0] += 2.0 * np.sign(targets[o] or 1.0)
            targets[o] += 2.0 * np.sign(targets[o] or 1.0)
    table = make_ccd_table(lambda x: {o: c[0] + x @ c[1:] for o, c in coef.items()}, lower, upper, seed=1)
    table = table.rename(columns={"x1": "a", "x2": "b"})
    spec = MaterialSpec.from_material("m", {
        "data": "x.csv", "design": {"type": "ccd", "alpha": 1.41421, "center_runs": 5},
        "factors": {f: {"lower": float(lo), "upper": float(hi)} for f, lo, hi in zip("ab", lower, upper)},
        "responses": {o: {"target": t} for o, t in targets.items()}, "scenarios": scenarios}, grid_points=41)
    return table, spec, coef, targets, x0


def _ends(coef, targets, tolerance, lower, upper):
    """(feasible, per factor (min, max) over the set {x in box: |c.x - t| <= tol |t| for y and z})."""
    rows, rhs = [], []
    for o, c in coef.items():
        band = tolerance * abs(targets[o])
        rows += [c[1:], -c[1:]]
        rhs += [targets[o] + band - c[0], -(targets[o] - band - c[0])]
    bounds = list(zip(lower, upper))
    ends = []
    for i in range(2):
        e = np.eye(2)[i]
        lo = linprog(e, A_ub=np.array(rows), b_ub=rhs, bounds=bounds)
        if lo.status == 2:
            return False, None
        hi = linprog(-e, A_ub=np.array(rows), b_ub=rhs, bounds=bounds)
        ends.append((lo.x[i], hi.x[i]))
    return True, ends


def _touches(ends, lower, upper) -> dict:
    out = {}
    for f, (lo, hi), a, b in zip("ab", ends, lower, upper):
        tol = BOUND_TOUCH * (b - a)
        out[f] = {(False, False): "none", (True, False): "lower", (False, True): "upper",
                  (True, True): "both"}[(lo <= a + tol, hi >= b - tol)]
    return out


SCENARIOS = [
    # the targets' own scenario at the reference tolerance (the fullest scenario's, ties the smallest)
    {"both": {"observables": ["y", "z"], "tolerance": 0.05}, "y_alone": {"observables": ["y"], "tolerance": 0.1}},
    # no scenario holds both targets: level 2 judges them at the reference tolerance all the same
    {"y_alone": {"observables": ["y"], "tolerance": 0.05}, "z_alone": {"observables": ["z"], "tolerance": 0.1}},
    # the same observables at a looser tolerance first: only the one at the reference tolerance counts
    {"loose": {"observables": ["y", "z"], "tolerance": 0.2}, "both": {"observables": ["z", "y"], "tolerance": 0.05},
     "z_alone": {"observables": ["z"], "tolerance": 0.03}},
]


@pytest.mark.parametrize("seed", range(4))
def test_level2_says_which_bounds_the_set_at_the_reference_tolerance_reaches(level1_stand_in, seed):
    rng = np.random.default_rng(seed)
    lower = np.array([rng.uniform(-1, 1), rng.uniform(5, 10)])
    upper = lower + np.array([rng.uniform(0.5, 2), rng.uniform(10, 40)])
    table, spec, coef, targets, _ = _study(rng, lower, upper, SCENARIOS[seed % 3])
    assert spec.reference_tolerance == 0.05
    surrogates = {o: _plane(o, c) for o, c in coef.items()}
    level2 = material.criticize_material(table, surrogates, spec, fits=NO_FITS).summary["level2"]
    feasible, ends = _ends(coef, targets, 0.05, lower, upper)
    assert feasible and level2["feasible"]
    reached = _touches(ends, lower, upper)
    assert level2["set_at_bound"] == reached
    widen = {f: [s for s in ("lower", "upper") if where in (s, "both")] for f, where in reached.items()
             if where != "none"}
    assert level2["widen"] == widen
    for f, sides in widen.items():
        assert f"Widen the range of {f}: " in level2["message"]
        assert f"the admissible set reaches its {' and '.join(sides)} bound" in level2["message"]
    assert level2["best_max_error"] <= 0.05 + 1e-12


def _dense(coef, targets, tolerances, lower, upper):
    """Feasible fraction (%) and widths of the set on a 301² grid over the box."""
    a, b = np.meshgrid(np.linspace(lower[0], upper[0], 301), np.linspace(lower[1], upper[1], 301), indexing="ij")
    inside = np.ones(a.size, bool)
    for o, tol in tolerances.items():
        c = coef[o]
        inside &= np.abs(c[0] + c[1] * a.ravel() + c[2] * b.ravel() - targets[o]) <= tol * abs(targets[o])
    widths = [float(np.ptp(v[inside])) if inside.any() else 0.0 for v in (a.ravel(), b.ravel())]
    return 100 * inside.mean(), widths


@pytest.mark.parametrize("seed", range(2))
def test_a_finding_reports_its_extensions_effect_on_every_scenario_of_its_response(level1_stand_in, seed):
    rng = np.random.default_rng(20 + seed)
    lower, upper = np.array([0.0, 1.0]), np.array([2.0, 3.0])
    scenarios = {"both": {"observables": ["y", "z"], "tolerance": 0.05}, "z_alone": {"observables": ["z"],
                                                                                      "tolerance": 0.1},
                 "y_alone": {"observables": ["y"], "tolerance": 0.1}}
    table, spec, coef, targets, x0 = _study(rng, lower, upper, scenarios)
    surrogates = {o: _plane(o, c) for o, c in coef.items()}
    which = ("y", "z")[seed % 2]
    flatter = coef[which] * np.array([1.0, rng.uniform(0.3, 0.7), rng.uniform(0.3, 0.7)])
    flatter[0] += targets[which] - (flatter[0] + flatter[1:] @ x0)  # still met at x0: a wider set
    level1_stand_in[which] = _plane(which, flatter)
    result = material.criticize_material(table, surrogates, spec, fits=NO_FITS)
    other = "z" if which == "y" else "y"
    assert "identifiability" not in result.response_json[other]
    rows = result.response_json[which]["identifiability"]
    expected = [s for s, sc in scenarios.items() if which in sc["observables"]]
    assert [r["scenario"] for r in rows] == expected
    for row in rows:
        tolerances = {o: scenarios[row["scenario"]]["tolerance"] for o in scenarios[row["scenario"]]["observables"]}
        before, width_before = _dense(coef, targets, tolerances, lower, upper)
        after, width_after = _dense({**coef, which: flatter}, targets, tolerances, lower, upper)
        assert row["fraction_pct_before"] == pytest.approx(before, abs=1.0)
        assert row["fraction_pct_after"] == pytest.approx(after, abs=1.0)
        assert [row["width_before"][f] for f in "ab"] == pytest.approx(width_before, abs=0.03)
        assert [row["width_after"][f] for f in "ab"] == pytest.approx(width_after, abs=0.03)
    assert result.summary["level1"][which]["findings"] == 1 and result.summary["level1"][other]["findings"] == 0
    for r in ("y", "z"):  # each response's scenarios, in the config's order
        assert result.summary["level1"][r]["scenarios"] == [s for s, sc in scenarios.items() if r in sc["observables"]]


@pytest.mark.parametrize("seed", range(2))
def test_level2_warns_of_the_search_range_beyond_the_runs_that_gave_a_response(level1_stand_in, seed):
    from demid.criticism.models import short_number

    rng = np.random.default_rng(30 + seed)
    lower, upper = np.array([0.0, 1.0]), np.array([2.0, 3.0])
    table, _, coef, targets, _ = _study(rng, lower, upper, SCENARIOS[0])
    wide = {"a": {"lower": -1.0, "upper": 2.0}, "b": {"lower": 1.0, "upper": 3.0 + 2.0 * seed}}
    spec = MaterialSpec.from_material("m", {
        "data": "x.csv", "design": {"type": "ccd", "alpha": 1.41421, "center_runs": 5}, "factors": wide,
        "responses": {o: {"target": t} for o, t in targets.items()}, "scenarios": SCENARIOS[0]}, grid_points=41)
    # a failed run (no response) out at the widened bounds covers nothing
    failed = pd.DataFrame([{"run": len(table) + 1, "a": -1.0, "b": 3.0 + 2.0 * seed, "y": np.nan, "z": np.nan}])
    table = pd.concat([table, failed], ignore_index=True)
    surrogates = {o: _plane(o, c) for o, c in coef.items()}
    level2 = material.criticize_material(table, surrogates, spec, fits=NO_FITS).summary["level2"]
    beyond = {"a": ("lower", lower[0], upper[0]), "b": ("upper", lower[1], upper[1])} if seed else \
        {"a": ("lower", lower[0], upper[0])}
    assert len(level2["extrapolation"]) == len(beyond)
    for sentence, (f, (side, lo, hi)) in zip(level2["extrapolation"], beyond.items()):
        assert sentence.startswith(f"Extrapolation: the search range of {f}, ")
        assert f"which cover {short_number(lo)} to {short_number(hi)};" in sentence
        assert sentence.endswith(f"simulate runs out to the {side} bound.")


@pytest.mark.parametrize("seed", range(3))
def test_four_factors_level2_misses_by_the_targets_distance_from_the_planes_range_over_the_box(level1_stand_in,
                                                                                                 seed):
    rng = np.random.default_rng(50 + seed)
    names = "abcd"
    lower, upper = np.array([0.0, 1.0, -2.0, 10.0]), np.array([1.0, 3.0, 2.0, 20.0])
    coef = np.concatenate([[rng.uniform(-4, 4)], rng.uniform(0.5, 1.5, 4) * rng.choice([-1, 1], 4) / (upper - lower)])
    ends = coef[0] + np.sort([np.sum(np.minimum(coef[1:] * lower, coef[1:] * upper)),
                              np.sum(np.maximum(coef[1:] * lower, coef[1:] * upper))])
    # a target inside the plane's range over the box, 10 % beyond its upper end, or 10 % beyond its lower end
    target = [float(np.mean(ends)), 1.1 * ends[1] if ends[1] > 0 else 0.9 * ends[1],
              0.9 * ends[0] if ends[0] > 0 else 1.1 * ends[0]][seed]
    table = make_ccd_table(lambda x: {"y": coef[0] + x @ coef[1:]}, lower, upper, seed=1)
    table = table.rename(columns={f"x{i + 1}": f for i, f in enumerate(names)})
    spec = MaterialSpec.from_material("m", {
        "data": "x.csv", "design": {"type": "ccd", "alpha": 1.41421, "center_runs": 5},
        "factors": {f: {"lower": float(lo), "upper": float(hi)} for f, lo, hi in zip(names, lower, upper)},
        "responses": {"y": {"target": target}}, "scenarios": {"y": {"observables": ["y"], "tolerance": 0.05}}},
        grid_points=256)
    terms = [(0, 0, 0, 0)] + [tuple(int(i == k) for i in range(4)) for k in range(4)]
    surrogate = Surrogate("y", list(names), terms, coef, np.zeros((5, 5)), 0.0, 20)
    level2 = material.criticize_material(table, {"y": surrogate}, spec, fits={"y": None}).summary["level2"]
    miss = max(ends[0] - target, target - ends[1], 0.0) / abs(target)
    assert level2["best_max_error"] == pytest.approx(miss, rel=1e-6, abs=1e-9)
    assert level2["feasible"] is (seed == 0)
    best = np.array([level2["best_point"][f] for f in names])
    assert np.all((best >= lower) & (best <= upper))
    assert level2["best_errors"]["y"] == pytest.approx((coef[0] + coef[1:] @ best - target) / abs(target), abs=1e-12)
    if seed:  # the nearest end of the range is a corner of the box: the point where each term is at that end
        corner = np.where((coef[1:] > 0) == (seed == 1), upper, lower)
        assert best == pytest.approx(corner)


def test_four_factors_without_a_scenario_of_the_targets_level2_judges_no_sampled_set(level1_stand_in):
    """No scenario holds both targets at the reference tolerance and four factors have no exact set: level 2
    decides by its own search and says nothing of a set's bounds (no set of these targets is evaluated)."""
    rng = np.random.default_rng(7)
    names = "abcd"
    lower, upper = np.zeros(4), np.ones(4)
    coef = {"y": np.array([2.0, 1.0, 0.5, -0.5, 0.25]), "z": np.array([3.0, 0.1, 0.0, 0.0, 0.0])}
    x0 = rng.uniform(0.3, 0.7, 4)
    targets = {o: float(c[0] + c[1:] @ x0) for o, c in coef.items()}
    table = make_ccd_table(lambda x: {o: c[0] + x @ c[1:] for o, c in coef.items()}, lower, upper, seed=1)
    table = table.rename(columns={f"x{i + 1}": f for i, f in enumerate(names)})
    spec = MaterialSpec.from_material("m", {
        "data": "x.csv", "design": {"type": "ccd", "alpha": 1.41421, "center_runs": 5},
        "factors": {f: {"lower": 0.0, "upper": 1.0} for f in names},
        "responses": {o: {"target": t} for o, t in targets.items()},
        "scenarios": {"y_alone": {"observables": ["y"], "tolerance": 0.1},
                      "z_alone": {"observables": ["z"], "tolerance": 0.1}}}, grid_points=256)
    terms = [(0, 0, 0, 0)] + [tuple(int(i == k) for i in range(4)) for k in range(4)]
    surrogates = {o: Surrogate(o, list(names), terms, c, np.zeros((5, 5)), 0.0, 20) for o, c in coef.items()}
    level2 = material.criticize_material(table, surrogates, spec, fits=NO_FITS).summary["level2"]
    assert level2["feasible"] and level2["best_max_error"] <= 0.1
    assert level2["set_at_bound"] is None
    best = np.array([level2["best_point"][f] for f in names])
    on_bound = {f: ["lower"] if v <= BOUND_TOUCH else ["upper"] if v >= 1 - BOUND_TOUCH else []
                for f, v in zip(names, best)}
    assert level2["widen"] == {f: sides for f, sides in on_bound.items() if sides}
