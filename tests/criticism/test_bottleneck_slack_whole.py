"""Level 2's bottleneck analysis (criticism.searches.bottleneck_analysis) on observables that no factor moves, so
that every error is a known constant: per observable the largest weighted error left when it is dropped (the
others' largest, computed here), the bias it would need (its own error), the bottleneck, the observables whose
bias alone would restore feasibility -- those whose error left is at most the tolerance plus 1e-12, tested with
the error left exactly at the tolerance, inside the 1e-12 slack, exactly at tolerance + 1e-12 and one step past
it -- and the biased observable when exactly one is; with signed errors, 2-4 observables and unequal weights."""

from __future__ import annotations

import numpy as np
import pytest

from demid.criticism.searches import Level2Problem, bottleneck_analysis


class _Constant:
    def __init__(self, value):
        self.value = value

    def predict(self, x):
        return np.full(len(np.atleast_2d(x)), self.value)


class _Box:
    factors = ("a", "b")

    def search_bounds(self):
        return np.zeros(2), np.ones(2)

    def to_actual(self, s):
        return np.asarray(s, dtype=float)


def _problem(errors, weights):
    names = [f"y{i}" for i in range(len(errors))]
    targets = {o: (-3.0 if i % 2 else 2.5) for i, o in enumerate(names)}
    surrogates = {o: _Constant(targets[o] + e * abs(targets[o])) for (o, e) in zip(names, errors)}
    problem = Level2Problem(surrogates, _Box(), targets, names, weights)
    axes = np.linspace(0.0, 1.0, 4)
    grid_s = np.column_stack([m.ravel() for m in np.meshgrid(axes, axes, indexing="ij")])
    return problem, grid_s, problem.errors(grid_s)


def _tolerance(worst, where):
    """A tolerance at ``worst``, 5e-13 inside it, the one whose + 1e-12 slack is exactly ``worst``
    (``at_slack``), or one step below that (``past``)."""
    if where == "at":
        return worst
    if where == "inside":
        return worst - 5e-13
    tol = worst - 1e-12
    for _ in range(64):
        if tol + 1e-12 == worst:
            break
        tol = np.nextafter(tol, np.inf if tol + 1e-12 < worst else -np.inf)
    assert tol + 1e-12 == worst
    if where == "past":
        tol = np.nextafter(tol, -np.inf)
        assert tol + 1e-12 < worst
    return tol


def _left(grid_err, weights, i):
    """The largest weighted |error| of the others, the same at every node."""
    others = [j for j in range(len(grid_err)) if j != i]
    return float(np.max(weights[others] * np.abs(grid_err[others, 0])))


CASES = [([0.1, -0.2, 0.4], [1.0, 1.0, 1.0]), ([-0.05, 0.3, -0.6, 0.15], [1.0, 0.5, 2.0, 1.0]),
         ([0.25, -0.35], [1.0, 1.0])]


@pytest.mark.parametrize("errors,weights", CASES)
@pytest.mark.parametrize("where", ["at", "inside", "at_slack", "past"])
def test_the_candidates_at_the_tolerance_and_its_slack(errors, weights, where):
    weights = np.asarray(weights)
    problem, grid_s, grid_err = _problem(errors, weights)
    names = problem.observables
    left = {o: _left(grid_err, weights, i) for i, o in enumerate(names)}
    low = min(left.values())
    tol = _tolerance(low, where)
    without, implied, bottleneck, candidates, biased = bottleneck_analysis(problem, grid_s, grid_err, tol, False)
    assert without == pytest.approx(left, rel=0, abs=0)
    assert implied == pytest.approx({o: float(grid_err[i, 0]) for i, o in enumerate(names)}, rel=1e-9, abs=1e-12)
    expect = [o for o in names if left[o] <= tol + 1e-12]
    assert expect == ([] if where == "past" else [o for o in names if left[o] == low])
    assert candidates == expect
    assert biased == (expect[0] if len(expect) == 1 else None)
    least = min(round(left[o] / (1e-3 * tol)) for o in names)
    tied = [o for o in names if round(left[o] / (1e-3 * tol)) == least]
    assert bottleneck == min(tied, key=lambda o: abs(implied[o]))


@pytest.mark.parametrize("errors,weights", CASES)
def test_where_every_target_is_met_no_observable_needs_a_bias(errors, weights):
    weights = np.asarray(weights)
    problem, grid_s, grid_err = _problem(errors, weights)
    without, implied, bottleneck, candidates, biased = bottleneck_analysis(problem, grid_s, grid_err, 1.0, True)
    assert without == {o: _left(grid_err, weights, i) for i, o in enumerate(problem.observables)}
    assert implied == {o: 0.0 for o in problem.observables}
    assert (bottleneck, candidates, biased) == (None, [], None)


def test_one_observable_has_no_error_left_to_drop_to():
    problem, grid_s, grid_err = _problem([0.3], np.ones(1))
    assert bottleneck_analysis(problem, grid_s, grid_err, 0.1, False) == ({}, {}, "y0", [], None)


@pytest.mark.parametrize("tolerance,bottleneck", [(0.1, "y1"), (0.01, "y0")])
def test_errors_left_within_a_thousandth_of_the_tolerance_tie_and_the_smaller_bias_is_the_bottleneck(
        tolerance, bottleneck):
    """y0 misses by 30.003 %, y1 by 30.001 %: dropping y0 leaves 30.001 %, dropping y1 30.003 %.  At a tolerance of
    10 % the two errors left fall in the same thousandth of the tolerance (3000.1 and 3000.3 of 1e-4): a tie, which
    goes to y1, the observable whose own miss (the bias it needs) is smaller.  At 1 % they are 30001 and 30003
    thousandths apart: y0, whose removal leaves less, is the bottleneck."""
    problem, grid_s, grid_err = _problem([0.30003, -0.30001], np.ones(2))
    without, implied, got, candidates, biased = bottleneck_analysis(problem, grid_s, grid_err, tolerance, False)
    assert without == pytest.approx({"y0": 0.30001, "y1": 0.30003}, rel=1e-12)
    assert implied == pytest.approx({"y0": 0.30003, "y1": -0.30001}, rel=1e-9)
    assert (got, candidates, biased) == (bottleneck, [], None)
