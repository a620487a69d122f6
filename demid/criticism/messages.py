"""Level-1 and level-2 findings in words: what is wrong, why, and the gain of the fix."""

from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np

from .models import run_label, short_number, transform_name

if TYPE_CHECKING:
    from ..design import Term
    from .catalogue import Hypothesis
    from .models import Data, Model


CAUSE_WORDS = {"missing_term": "missing term", "response_transform": "transform", "outlier": "outlier run",
               "drift": "drift with", "heteroscedasticity": "unequal scatter with",
               "factor_level": "another factor level at run", "step": "a step in run order at run"}


def _gain_phrase(before: float, after: float) -> str:
    if not (np.isfinite(before) and np.isfinite(after)) or before <= 0:
        return "its effect on the leave-one-out error could not be computed"
    ratio = after / before
    if ratio < 0.995:
        return f"cuts the leave-one-out error by {100 * (1 - ratio):.0f} %"
    if ratio <= 1.005:
        return "leaves the leave-one-out error unchanged"
    return f"does not reduce the leave-one-out error (+{100 * (ratio - 1):.0f} %)"


def and_list(names: list[str]) -> str:
    """"a", "a and b", "a, b and c"."""
    return names[0] if len(names) == 1 else ", ".join(names[:-1]) + " and " + names[-1]


def _describe_term(term: Term, factors: list[str]) -> str:
    powers = {f: p for f, p in zip(factors, term) if p}
    if len(powers) == 1:
        return f"curvature along {next(iter(powers))}"
    if len(powers) == 3:
        return f"a three-factor interaction of {and_list(list(powers))}"
    sq = next(f for f, p in powers.items() if p == 2)
    lin = next(f for f, p in powers.items() if p == 1)
    return f"a change of the {sq} curvature with {lin}"


def corner_only_runs(data: Data, term) -> int:
    """How many corner runs carry ``term`` when they alone do (0 otherwise).

    In a 3-factor design, x1*x2*x3 is carried by the factorial (corner) runs alone, where main effects,
    two-factor interactions and that product span all 8 patterns: any difference between the corners the
    quadratic cannot follow, e.g. a change of regime where several factors are high, looks exactly like the
    product on these runs.  (With more factors other products share the corners, and the claim would not
    hold.)  Such a term is therefore never named (naming.why_not_singled_out): in benchmarks/honest_causes.py a
    corner step on a 3-factor CCD was called "missing term x1:x2:x3" in 15 of 20 tables; the rule lowers
    confidently wrong causes on off-catalogue defects from 0.171 to 0.131 (lenient: 0.129 to 0.090) and
    catalogue naming from 0.587 to 0.579 (planted x1:x2:x3 terms are reported unexplained instead)."""
    if len(term) != 3 or any(p != 1 for p in term):
        return 0
    column = np.prod(np.asarray(data.coded, float) ** np.asarray(term), axis=1)
    carried = int(np.sum(np.abs(column) > 1e-9))
    return carried if 0 < carried < data.n else 0  # some runs (axial, centre) must not carry it


def _points_text(points: list[dict]) -> str:
    return " and ".join("(" + ", ".join(f"{k}={v:g}" for k, v in p.items()) + ")" for p in points)


def finding_message(data: Data, h: Hypothesis, info: dict, before: float, after: float,
                    n_compared: int, extra_runs: list[dict], model: Model) -> str:
    """A level-1 finding in words: what the model misses, the cause, and what its extension gains."""
    r = data.response
    gain = _gain_phrase(before, after)
    if h.cause == "missing_term":
        rep = h.aliases[0]
        others = h.aliases[1:]
        alias = f", aliased with {and_list(others)} in this design" if others else ""
        text = (f"{r}: the quadratic misses {_describe_term(h.detail.terms[0], data.factors)} "
                f"(term {rep}{alias}); adding it {gain}.")
        if others and extra_runs:
            what = "the two" if len(h.aliases) == 2 else f"the {len(h.aliases)}"
            text += f" Extra runs at {_points_text(extra_runs)} would tell {what} apart."
        return text
    if h.cause == "response_transform":
        lam = info["lam"]
        scale = {"log": "log", "sqrt": "square-root", "inverse": "reciprocal"}.get(transform_name(lam))
        on = f"on a {scale} scale" if scale else f"after a Box-Cox transform with lambda = {lam:g}"
        lo, hi = info["lambda_ci"]
        kind = "multiplicatively" if lam <= 0.5 else "non-additively"
        return (f"{r}: the response behaves {kind}: the quadratic fits better {on} "
                f"(Box-Cox lambda = {info['lambda_hat']:.2f}, 95 % interval {lo:.2f} to {hi:.2f}); "
                f"fitting there and transforming back {gain}.")
    if h.cause == "outlier":
        run = run_label(data.runs[int(h.detail)])
        if data.simulated:  # demid ran it and read its responses itself: nothing was typed or exported
            why = ("demid simulated that run itself, so it is no transcription or export error: either its "
                   "seed-to-seed scatter is larger than the other runs show, or the simulator failed quietly there "
                   "(a run that did not settle, a setting it did not take): check that run's log, and replicates of "
                   "it tell the two apart")
        else:
            why = ("a transcription or export error is the usual cause, or something that differed for that run "
                   "alone (an input, a setting, a version): check that run")
        return (f"{r}: run {run} does not fit the other runs (observed {short_number(info['observed'])}, "
                f"the other runs predict {short_number(info['predicted_without'])}, externally studentised "
                f"residual {h.statistic:.1f}); {why}. Refitting without it {gain} on the other {n_compared} runs.")
    if h.cause == "factor_level":
        run = run_label(data.runs[h.detail.row])
        f = info["factor"]
        return (f"{r}: run {run} fits {f} = {short_number(info['fitting_value'])} instead of the recorded "
                f"{short_number(info['recorded_value'])} ({info['slip'].replace('x1e', 'x 10^')}: a unit or decimal "
                f"slip in the "
                f"simulation input?): observed {short_number(info['observed'])}, the other runs predict it within "
                f"{abs(info['t_moved']):.1f} standard errors at {f} = {short_number(info['fitting_value'])} and "
                f"{abs(info['t_recorded']):.1f} at the recorded value (Bayes factor {info['bayes_factor']:.1f} "
                f"against a shift of that run alone). Check the input of that run: no further run tells a slip from "
                f"another error of that run alone (a new run at the recorded value or at "
                f"{short_number(info['fitting_value'])} "
                f"follows the surface either way), its input does; using "
                f"{f} = {short_number(info['fitting_value'])} for it {gain}.")
    if h.cause == "drift":
        slope = info.get("drift_per_run", float("nan"))
        span = slope * float(np.ptp(data.runs.astype(float)))
        return (f"{r}: the residuals trend with run order ({slope:+.3g} per run, {span:+.3g} from first to "
                f"last run): something changed while the runs were made (software version, settings, "
                f"seeds, hardware). Adding a run-order term {gain}; predictions refer to the mean run order.")
    if h.cause == "step":
        size, first = info.get("step_size", float("nan")), run_label(data.runs[int(h.detail)])
        return (f"{r}: the runs from run {first} on are shifted by {size:+.4g} against the {info.get('runs_before')} "
                f"runs before (a step in run order, not a gradual drift): something changed between runs — typically "
                f"a new block or wave of runs, a software version or a machine. If the runs were made in blocks, add a "
                f"'block' column to the table (any labels) so that every model carries the shift; adding the step "
                f"{gain}; predictions refer to the average run.")
    if h.cause == "heteroscedasticity":
        ratio = info["sd_ratio"]
        grows = ratio >= 1
        what = "the predicted value" if h.detail == "fitted" else str(h.detail)
        factor = ratio if grows else 1 / ratio
        return (f"{r}: the scatter of the runs {'grows' if grows else 'shrinks'} with {what} (residual "
                f"spread about {factor:.1f} times larger at the {'high' if grows else 'low'} end than at the "
                f"other); weighting the fit by the estimated variance {gain}. Uncertainty from the "
                f"unweighted fit is too wide where the runs agree and too narrow where they scatter.")
    raise ValueError(h.cause)


def percent_text(x: float) -> str:
    """A fraction as a percentage, two decimals below 10 %, one above; none, a trace or past 10× said so
    (:mod:`demid.precision`)."""
    from ..precision import FAR_RATIO
    from ..precision import percent_text as policy_percent_text

    if abs(x) < 5e-5 or abs(x) > FAR_RATIO:
        return policy_percent_text(x)
    return f"{100 * x:.2f} %" if abs(x) < 0.1 else f"{100 * x:.1f} %"


def level2_tolerance_text(tolerance: float, tolerances: dict[str, float] | None, brackets: bool = True) -> str:
    """"2.00 %", or with observables of their own tolerance "their own tolerances (d5 2.00 %, rho 0.33 %)"
    ("their own tolerances: d5 2.00 %, rho 0.33 %" inside brackets already)."""
    from ..tolerance import same_tolerances

    own = tolerances or {}
    if same_tolerances(tolerance, own):
        return percent_text(tolerance)
    listed = ", ".join(f"{o} {percent_text(v)}" for o, v in own.items())
    return f"their own tolerances ({listed})" if brackets else f"their own tolerances: {listed}"


def _times(ratio: float) -> str:
    return f"{ratio:.2g}" if ratio >= 0.005 else "0"


def level2_miss_text(errors: dict[str, float], tolerance: float, tolerances: dict[str, float] | None,
                     at_most: bool = False) -> str:
    """What follows "misses": "by 3.10 %" ("by at most 3.10 %"), or against each observable's own tolerance
    the worst relative to its tolerance: "rho by 3.10 % (9.3 times its tolerance of 0.33 %)"."""
    from ..tolerance import same_tolerances

    own = {o: float((tolerances or {}).get(o, tolerance)) for o in errors}
    if same_tolerances(tolerance, own):
        return f"by {'at most ' if at_most else ''}{percent_text(max(abs(e) for e in errors.values()))}"
    worst = max(errors, key=lambda o: abs(errors[o]) / own[o])
    ratio = abs(errors[worst]) / own[worst]
    times = f"{_times(ratio)} times" if ratio >= 0.005 else "a negligible fraction of"
    return f"{worst} by {percent_text(abs(errors[worst]))} ({times} its tolerance of {percent_text(own[worst])})"
