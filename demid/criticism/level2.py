"""Level 2: the calibrated simulation confronted with the experiment.

:func:`calibration_check` finds the best point in the domain (minimax relative error),
the errors there and at the reference point, the bottleneck observable, and bias
(discrepancy) extensions with their cost in parameters.

Each observable is judged against its own tolerance ε_k (``responses.<r>.tolerance`` /
``tolerance_abs``, :func:`demid.tolerance.relative_tolerances`), as every set is: the searches
minimise the largest *weighted* relative error ε·|e_k|/ε_k (ε the scenario's tolerance), which is the
relative error of the rescaled surrogate the strict set is evaluated on
(:func:`demid.tolerance.scenario_surrogates`).  Without an override every weight is 1 and the
weighted error is the relative error itself.
"""

from __future__ import annotations

from dataclasses import dataclass, field, replace

import numpy as np
import pandas as pd

from ..tolerance import same_tolerances
from .edges import extrapolation_warnings, movable_sides, touching, widen_advice
from .messages import and_list, level2_miss_text, level2_tolerance_text, percent_text
from .models import json_number, short_number
from .reach import reach_beyond_bound, saturation_advice, saturation_finding
from .searches import Level2Problem, bottleneck_analysis, minimax, reference_point_errors


# =========================================================================== level 2
@dataclass
class Level2Result:
    """The calibrated simulation against the experiment for one material.

    Relative errors are (y_hat - y*) / |y*| as in :mod:`demid.admissibility`;
    ``best_*`` refers to the point of the domain minimising the largest weighted |relative
    error| ε·|e_k|/ε_k over all observables with targets (``tolerances``: ε_k per observable; the
    plain relative error when every ε_k is the scenario's ε).  ``best_max_error``, ``without`` and the
    shared bias's ``max_error`` are weighted errors, compared with ``tolerance``; ``best_errors``,
    ``reference_errors`` and ``implied_bias`` are plain relative errors.  ``without[k]`` is the smallest
    largest error when observable k is left out (equivalently: given a free bias).
    """

    factors: list[str]
    observables: list[str]
    targets: dict[str, float]
    tolerance: float
    best_point: dict[str, float]
    best_values: dict[str, float]
    best_errors: dict[str, float]
    best_max_error: float
    feasible: bool
    reference_point: dict[str, float] | None
    reference_values: dict[str, float] | None
    reference_errors: dict[str, float] | None
    bottleneck: str | None
    without: dict[str, float]
    implied_bias: dict[str, float]
    bias_candidates: list[str]
    biased_observable: str | None
    shared_bias: dict
    extensions: list[dict]
    message: str
    best_at_bound: dict[str, str] = field(default_factory=dict)  # factor -> none/lower/upper/both
    set_at_bound: dict[str, str] | None = None  # of the strict set, when it was given and is not empty
    widen: dict[str, list[str]] = field(default_factory=dict)  # factor -> bounds to move outwards
    extrapolation: list[str] = field(default_factory=list)
    unmoved: list[str] = field(default_factory=list)  # observables no factor moves anywhere in the domain
    finding: str = ""  # the message without its advice: the report adds the study's advice (demid.story)
    reach: list = field(default_factory=list)  # demid.criticism.reach.Reach per bound the missing best point sits on
    tolerances: dict[str, float] = field(default_factory=dict)  # observable -> its own relative tolerance ε_k

    def own_tolerance(self, observable: str) -> float:
        return float(self.tolerances.get(observable, self.tolerance))

    @property
    def uniform(self) -> bool:
        """Every observable is judged at the scenario's tolerance (no own tolerance differs from it)."""
        return same_tolerances(self.tolerance, {o: self.own_tolerance(o) for o in self.observables})

    def within(self, errors: dict[str, float]) -> bool:
        return all(abs(e) <= self.own_tolerance(o) + 1e-12 for o, e in errors.items())

    @property
    def reference_within(self) -> bool | None:
        return None if self.reference_errors is None else self.within(self.reference_errors)

    @property
    def reference_max_error(self) -> float | None:
        if self.reference_errors is None:
            return None
        return float(max(abs(v) for v in self.reference_errors.values()))

    def to_frame(self) -> pd.DataFrame:
        rows = []
        for o in self.observables:
            ref = self.reference_errors[o] if self.reference_errors else np.nan
            rows.append({
                "observable": o, "target": self.targets[o],
                "at_best": self.best_values[o], "rel_error_best": self.best_errors[o],
                "at_reference": self.reference_values[o] if self.reference_values else np.nan,
                "rel_error_reference": ref, "tolerance": self.own_tolerance(o),
                "within_tolerance": bool(abs(self.best_errors[o]) <= self.own_tolerance(o) + 1e-12),
                "within_tolerance_reference": (bool(abs(ref) <= self.own_tolerance(o) + 1e-12)
                                               if self.reference_errors else None),
                "bottleneck": o == self.bottleneck,
                "max_error_without": self.without.get(o, np.nan),
                "implied_bias": self.implied_bias.get(o, np.nan),
                "bias_candidate": o in self.bias_candidates,
            })
        return pd.DataFrame(rows)

    def to_json(self) -> dict:
        def clean(d):
            return None if d is None else {k: json_number(v) for k, v in d.items()}
        return {
            "observables": list(self.observables), "targets": clean(self.targets), "tolerance": self.tolerance,
            "tolerances": {o: self.own_tolerance(o) for o in self.observables},
            "best_point": clean(self.best_point), "best_values": clean(self.best_values),
            "best_errors": clean(self.best_errors), "best_max_error": json_number(self.best_max_error),
            "feasible": bool(self.feasible),
            "reference_point": clean(self.reference_point), "reference_values": clean(self.reference_values),
            "reference_errors": clean(self.reference_errors), "reference_max_error": self.reference_max_error,
            "reference_within": self.reference_within,
            "bottleneck": self.bottleneck, "max_error_without": clean(self.without),
            "implied_bias": clean(self.implied_bias), "bias_candidates": list(self.bias_candidates),
            "biased_observable": self.biased_observable, "shared_bias": self.shared_bias,
            "extensions": self.extensions, "message": self.message,
            "best_point_at_bound": dict(self.best_at_bound), "set_at_bound": self.set_at_bound,
            "widen": {f: list(v) for f, v in self.widen.items()}, "extrapolation": list(self.extrapolation),
            "unmoved": list(self.unmoved), "finding": self.finding,
            "reach": [r.to_json() for r in self.reach],
        }




def calibration_check(surrogates: dict, domain, targets: dict[str, float], tolerance: float, n: int,
                      reference_point: dict | None = None, strict_set=None, runs=None,
                      tolerances: dict[str, float] | None = None, implausible=()) -> Level2Result:
    """Level-2 criticism: can any point of the domain meet every target, and if not, why not?

    ``surrogates`` maps observable -> object with ``predict(points_actual)``;
    observables are those with both a surrogate and a target.  The best point
    minimises the largest |relative error| (grid of ``n`` points per axis, then
    SLSQP polish).  Discrepancy extensions: a free bias on one observable (the
    bottleneck), a shared relative bias on all, a bias on each (saturated).
    ``strict_set`` (the strict set of these observables at ``tolerance``, from
    :func:`~demid.sampling.evaluate.evaluate_set`) decides feasibility when it is exact, so that
    level 2 and Table 3 never disagree on whether the set is empty, and its ``at_bound`` says whether
    the set reaches a search bound.  ``runs`` (the design runs' factor values, actual units, in
    ``domain`` order) locate search bounds and reference point relative to the simulated region.
    The message says "widen the range of X" when the best point or the set sits on a bound of X,
    and warns of extrapolation.  ``tolerances`` (observable -> its own relative tolerance ε_k, from
    :func:`demid.tolerance.relative_tolerances`; missing: ``tolerance``) weight each relative error by
    ε/ε_k, so that the best point, feasibility and the bottleneck are judged as the strict set is.
    ``implausible`` (observables whose target lies far from every simulated value,
    :func:`demid.data.implausible_targets`): no bound the best point sits on is followed outwards, since
    the best point only chases the slipped target.
    """
    observables = [o for o in targets if o in surrogates]
    if not observables:
        raise ValueError("no observable has both a surrogate and a target")
    factors = list(domain.factors)
    d, k = len(factors), len(observables)
    own = {o: float((tolerances or {}).get(o, tolerance)) for o in observables}
    problem = Level2Problem(surrogates, domain, targets, observables,
                             [float(tolerance) / own[o] for o in observables])
    axes = [np.linspace(0.0, 1.0, n)] * d
    grid_s = np.column_stack([m.ravel() for m in np.meshgrid(*axes, indexing="ij")])
    grid_err = problem.errors(grid_s)
    every = list(range(k))
    best_val, best_s, feasible, unmoved, movable = _best_point(problem, grid_s, grid_err, tolerance, strict_set)
    best_x = problem.actual(best_s)[0]
    best_values = dict(zip(observables, problem.values(best_s)[:, 0].tolist()))
    best_errors = dict(zip(observables, problem.errors(best_s)[:, 0].tolist()))

    ref_values, ref_errors = reference_point_errors(surrogates, targets, observables, factors, reference_point)
    without, implied, bottleneck, candidates, biased = bottleneck_analysis(problem, grid_s, grid_err, tolerance,
                                                                           feasible)

    shared_val, shared_s, shared_delta = minimax(problem, grid_s, grid_err, every, shared=True)
    shared = {"delta": json_number(shared_delta), "max_error": json_number(shared_val),
              "point": {f: json_number(v) for f, v in zip(factors, problem.actual(shared_s)[0])},
              "n_params": d + 1}
    extensions = _level2_extensions(d, k, best_val, shared_val, without, bottleneck)
    result = Level2Result(
        factors=factors, observables=observables, targets={o: float(targets[o]) for o in observables},
        tolerance=float(tolerance), best_point=dict(zip(factors, best_x.tolist())), best_values=best_values,
        best_errors=best_errors, best_max_error=float(best_val), feasible=bool(feasible),
        reference_point=None if reference_point is None else {f: float(reference_point[f]) for f in factors},
        reference_values=ref_values, reference_errors=ref_errors, bottleneck=bottleneck, without=without,
        implied_bias=implied, bias_candidates=candidates, biased_observable=biased, shared_bias=shared,
        extensions=extensions, message="", tolerances=own)
    result.unmoved = [observables[i] for i in unmoved]
    _bounds_and_message(result, surrogates, domain, strict_set, runs, reference_point, implausible,
                        [observables[i] for i in movable])
    return result


def _best_point(problem: Level2Problem, grid_s: np.ndarray, grid_err: np.ndarray, tolerance: float, strict_set):
    """(largest weighted error, point in unit search space, feasible, unmoved rows, movable rows) of the minimax
    search; an exact strict set decides feasibility, so that level 2 and Table 3 agree."""
    every = list(range(len(problem.observables)))
    # An observable no factor moves (a response the same in every run) misses its target by the same amount
    # everywhere: the largest error then ties over the whole domain and its minimiser is an arbitrary corner.
    # The best point is sought over the others; the largest error still counts every observable.
    spread = np.ptp(grid_err, axis=1)
    unmoved = [i for i in every if spread[i] <= 1e-9 * max(1.0, float(np.max(np.abs(grid_err[i]))))]
    movable = [i for i in every if i not in unmoved]
    best_val, best_s, _ = minimax(problem, grid_s, grid_err, movable if unmoved and movable else every)
    if unmoved and movable:
        best_val = float(np.max(problem.weights * np.abs(problem.errors(best_s)[:, 0])))
    feasible = best_val <= tolerance + 1e-12
    exact = getattr(strict_set, "exact", None)
    if exact is not None:
        feasible = exact.fraction > 0
        if feasible and best_val > tolerance:
            # the local search missed a thin set: its admissible point nearest the search's best
            near = replace(exact, reference=exact.to_model(best_s))
            best_s = np.clip((problem.domain.to_search(near.nearest_point[None, :])[0] - problem.lo)
                             / (problem.hi - problem.lo), 0.0, 1.0)
            best_val = float(np.max(problem.weights * np.abs(problem.errors(best_s)[:, 0])))
    return best_val, best_s, feasible, unmoved, movable


def _bounds_and_message(result: Level2Result, surrogates, domain, strict_set, runs, reference_point,
                        implausible, movable: list[str]) -> None:
    """The bounds the best point and the set sit on, those worth widening, the extrapolation warnings, and
    the result's message and finding; ``movable``: the observables some factor moves."""
    factors, observables = result.factors, result.observables
    best_x = np.array([result.best_point[f] for f in factors])
    unmoved = result.unmoved
    result.best_at_bound = dict(zip(factors, domain.at_bound(best_x, best_x)))
    if result.feasible and getattr(strict_set, "at_bound", ()):
        result.set_at_bound = dict(zip(factors, strict_set.at_bound))
    best_touch, set_touch = touching(result.best_at_bound), touching(result.set_at_bound or {})
    if unmoved and movable and result.within({o: result.best_errors[o] for o in movable}):
        best_touch = {}  # the others are met: only the unmoved observables miss, and no range moves them
    if implausible and any(o in implausible for o in observables):
        best_touch = {}  # a target in another unit is missed everywhere: where the best point sits says nothing
    if not result.feasible and best_touch:
        best_touch = _worth_widening(result, surrogates, domain, best_touch, movable or observables)
    # the bounds to move outwards: not one at a physical limit (its reach above says so when it matters)
    moving_best, moving_set = movable_sides(domain, best_touch), movable_sides(domain, set_touch)
    result.widen = {f: sorted(set(moving_best.get(f, ())) | set(moving_set.get(f, ())), key=("lower", "upper").index)
                    for f in factors if f in moving_best or f in moving_set}
    result.extrapolation = extrapolation_warnings(domain, runs, reference_point)
    stuck = [f"{o} is predicted the same everywhere in the search range (no factor moves it), so no calibration "
             f"brings it nearer its target: check its simulation output." for o in unmoved]
    unreachable = [r for r in result.reach if not r.widen]
    result.message = " ".join([_level2_message(result), *stuck, *widen_advice(domain, best_touch, set_touch),
                               *(f"{saturation_finding(r, r.factor, r.observable)} "
                                 f"{saturation_advice(r, r.factor, r.observable)}" for r in unreachable),
                               *result.extrapolation])
    result.finding = " ".join([_level2_message(result), *stuck,
                               *(saturation_finding(r, r.factor, r.observable) for r in unreachable),
                               *result.extrapolation])


def _worth_widening(result: Level2Result, surrogates, domain, touch: dict, observables: list[str]) -> dict:
    """``touch`` without the bounds whose widening the surrogate says cannot reach the worst-missed target
    (or does not move it at all); the estimate per bound along which it moves is kept in ``result.reach``."""
    worst = max(observables, key=lambda o: abs(result.best_errors[o]) / result.own_tolerance(o))
    kept = {}
    for f, sides in touch.items():
        for side in sides:
            r = reach_beyond_bound(surrogates[worst], domain, f, side, result.best_point, worst,
                                   result.targets[worst], result.own_tolerance(worst))
            if r.flat:
                continue  # the worst-missed observable does not change along it: widening it buys nothing
            result.reach.append(r)
            if r.widen:
                kept[f] = (*kept.get(f, ()), side)
    return kept


def _level2_extensions(d: int, k: int, best: float, shared: float, without: dict, bottleneck) -> list[dict]:
    def row(model, n_params, max_error):
        spare = k - n_params
        note = ("testable: {} spare measurement(s)".format(spare) if spare > 0 else
                "saturated: as many unknowns as measurements, it fits whenever a solution lies in the domain, "
                "so the fit itself is no evidence" if spare == 0 else
                "not identifiable: more unknowns than measurements; any point fits and the biases are just "
                "the residuals there")
        return {"model": model, "n_params": n_params, "n_measurements": k, "spare_measurements": spare,
                "max_error": json_number(max_error), "note": note}

    rows = [row("simulation as calibrated (no discrepancy)", d, best)]
    if bottleneck is not None and without:
        rows.append(row(f"bias on {bottleneck}", d + 1, without[bottleneck]))
    rows.append(row("shared relative bias on all observables", d + 1, shared))
    rows.append(row("bias on every observable", d + k, 0.0))
    return rows


# =========================================================================== level 2 in words
def _weighted(r: Level2Result, value: float) -> str:
    """A weighted error (level 2's minimax values): a percentage, or a multiple of the own tolerances."""
    if r.uniform:
        return percent_text(value)
    ratio = value / r.tolerance
    return (f"{ratio:.2g} times their own tolerances" if ratio >= 0.005 else
            "a negligible fraction of their own tolerances")


def _level2_message(r: Level2Result) -> str:
    pt = ", ".join(f"{f}={short_number(v)}" for f, v in r.best_point.items())
    k, d = len(r.observables), len(r.factors)
    obs = and_list(r.observables)
    parts = []
    within = level2_tolerance_text(r.tolerance, r.tolerances)
    miss = level2_miss_text(r.best_errors, r.tolerance, r.tolerances, at_most=r.feasible)
    if r.feasible:
        parts.append(f"Every target ({obs}) can be met within {within}: the best point ({pt}) "
                     f"misses {miss}.")
    else:
        worst = max(r.best_errors, key=lambda o: abs(r.best_errors[o]) / r.own_tolerance(o))
        how = f"{'over' if r.best_errors[worst] > 0 else 'under'}-predicted"
        parts.append(f"No point of the domain meets every target ({obs}) within {within}; the "
                     f"closest point ({pt}) still misses "
                     + (f"{miss} ({worst} {how})." if r.uniform else f"{miss[:-1]}; {how})."))
        if r.bottleneck is not None and r.without:
            b = r.bottleneck
            parts.append(f"{b} is the bottleneck: without it the others can be met within "
                         f"{_weighted(r, r.without[b])}, and the simulation would then read {b} "
                         f"{percent_text(abs(r.implied_bias[b]))} {'high' if r.implied_bias[b] > 0 else 'low'}.")
            if r.biased_observable is not None:
                parts.append(f"{b} is the only observable whose removal makes the rest consistent, so a "
                             f"discrepancy (bias) in {b} explains the mismatch.")
            elif len(r.bias_candidates) > 1:
                parts.append(f"But removing any of {and_list(r.bias_candidates)} makes the rest consistent: with "
                             f"{k} measurements and {d} parameters the data cannot say which one is off "
                             f"({b} is named because it needs the smallest bias); a further independent "
                             f"measurement would.")
            else:
                parts.append("No single observable explains the mismatch on its own.")
    if r.reference_errors is not None:
        ref = ", ".join(f"{o} {100 * e:+.2f} %" for o, e in r.reference_errors.items())
        ok = r.reference_within
        parts.append(f"At the reference point the errors are {ref}: it {'meets' if ok else 'misses'} "
                     + (f"the {percent_text(r.tolerance)} tolerance." if r.uniform else f"{within}."))
    sb = r.shared_bias
    spare = k - d - 1
    meas = f"{k} measurement{'s' if k != 1 else ''} and {d} parameter{'s' if d != 1 else ''}"
    if r.feasible:
        return " ".join(parts)
    if spare < 0:
        parts.append(f"With {meas}, a shared relative bias on the targets is not identifiable (any point "
                     f"fits once it is free).")
    else:
        parts.append(f"A shared relative bias of {100 * sb['delta']:+.2f} % on all targets would leave "
                     f"{_weighted(r, sb['max_error'])} at one extra parameter; "
                     + (f"{spare} spare measurement{'s' if spare != 1 else ''} remain{'' if spare != 1 else 's'} "
                        f"to test it." if spare > 0 else
                        f"with {meas} it uses the last spare measurement, so its fit cannot be taken as "
                        f"evidence of a bias."))
    parts.append(f"A bias on every observable ({d + k} unknowns for {k} measurement{'s' if k != 1 else ''}) "
                 f"fits trivially and is not identifiable.")
    return " ".join(parts)
