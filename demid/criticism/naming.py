"""Which cause level 1 names, and whether the runs can tell it from its rivals.

A round's rejected causes are each extended and compared (:func:`name_cause`); a cause is named only when it
is singled out (:func:`why_not_singled_out`), and named causes must leave no misfit behind
(:func:`honest_causes`).  Every cause of the first round, extended and priced for the place it was chosen
from (:func:`candidate_entries`), is then compared with the named one: causes the runs do not tell apart
make the verdict ambiguous, with the runs that would decide (:func:`ambiguity`); a named cause gets the
runs that would confirm it against its nearest rivals (:func:`confirming_rivals`).
"""

from __future__ import annotations

import math
from dataclasses import replace
from typing import TYPE_CHECKING

import numpy as np

from ..design import LEVERAGE_UNPREDICTABLE, term_name
from .catalogue import CAUSES, MISFIT_TESTS
from .step_changes import STEP_CHUNK, step_projections, step_starts
from .discrimination import (AMBIGUOUS_AICC, CONFIRM_AICC, CONFIRM_PURPOSE, PURPOSE, candidate_kind,
                             candidate_label, close_candidates, discriminating_runs)
from .extensions import RUN_ORDER_CAUSES, catalogue_entry, detail_json, extend_for, step_price
from .messages import corner_only_runs
from .models import (Data, Model, aicc_of_many, gaussian_loglik, json_number, orthonormal_basis, run_label,
                     transform_name)
from .slips import count_slip_candidates
from .verdict import (RESIDUAL_MISFIT_LEVEL, SLIP_BAYES_FACTOR, other_reading_of_the_run, rests_on_one_run,
                      strongest_rival, unexplained_evidence)

if TYPE_CHECKING:
    from .catalogue import Hypothesis


def name_cause(data: Data, model: Model, rejected: list[Hypothesis]) -> tuple:
    """The cause to name among the rejected ones, its extension, and the others as alternatives."""
    # The rejected cause with the strongest evidence (smallest nominal p-value) is named, except
    # that one wild run can be read as an outlier or as scatter growing towards its corner of the
    # design: between those two (and between variance covariates, often nearly collinear) the
    # better-fitting one-parameter extension (higher likelihood) decides; log-likelihoods equal to nine
    # decimals are a tie, which the stronger test (listed first) wins.  The other rejected causes are
    # fitted too and listed as alternatives.
    fitted_alternatives = []
    for cand in rejected:
        cand_spec, cand_info = extend_for(data, model, cand)
        fitted_alternatives.append((cand, cand_spec, cand_info, Model(data, cand_spec)))
    # A run that fits a slipped value of one factor explains its misfit without an added parameter, but
    # one run is weak evidence: the slip is named only when its Bayes factor against a mean shift of the
    # run reaches SLIP_BAYES_FACTOR and no other extension beats it by more than its added parameters.
    slips = [i for i, alt in enumerate(fitted_alternatives) if alt[0].cause == "factor_level"]
    if slips:
        i = slips[0]
        slip_model = fitted_alternatives[i][3]
        others = [alt[3].loglik - alt[3].n_params + slip_model.n_params
                  for j, alt in enumerate(fitted_alternatives)
                  if j != i and alt[0].cause != "outlier"]
        if fitted_alternatives[i][0].info["bayes_factor"] >= SLIP_BAYES_FACTOR and \
                (not others or slip_model.loglik >= max(others) - 1.0):
            return _with_alternatives(data, fitted_alternatives, i)
    named = [i for i, alt in enumerate(fitted_alternatives) if alt[0].cause != "factor_level"]
    if not named:
        return None
    best = named[0]
    if fitted_alternatives[best][0].cause in ("heteroscedasticity", "outlier"):
        rivals = [i for i, alt in enumerate(fitted_alternatives)
                  if alt[0].cause in ("heteroscedasticity", "outlier")]
        best = max(rivals, key=lambda i: (round(fitted_alternatives[i][3].loglik, 9), -i))
    if fitted_alternatives[best][0].cause in RUN_ORDER_CAUSES:
        # a trend or a step in run order: the better-fitting extension decides, the step paying for its
        # change-point (step_price)
        rivals = [i for i, alt in enumerate(fitted_alternatives) if alt[0].cause in RUN_ORDER_CAUSES]
        best = max(rivals, key=lambda i: (round(fitted_alternatives[i][3].loglik
                                                - step_price(fitted_alternatives[i][0]), 9), -i))
    return _with_alternatives(data, fitted_alternatives, best)


def _with_alternatives(data: Data, fitted_alternatives: list, best: int) -> tuple:
    h, spec, info, new = fitted_alternatives[best]
    alternatives = [{"cause": c.cause, "detail": detail_json(data, c) if c.cause != "response_transform"
                     else transform_name(sp.lam), "p_value": json_number(c.p_family),
                     "loglik_vs_named": json_number(mo.loglik - new.loglik),
                     "aicc_vs_named": json_number(mo.aicc - new.aicc)}
                    for c, sp, _, mo in fitted_alternatives if c is not h]
    return h, spec, info, new, alternatives


def why_not_singled_out(data: Data, model: Model, h: Hypothesis, hypotheses: list[Hypothesis]) -> dict | None:
    """Why cause h is not named, or None: a term only the corner runs carry (which any difference between
    the corners mimics, messages.corner_only_runs), another kind of misfit at least as strong, or evidence
    that hinges on one run (verdict.strongest_rival, verdict.rests_on_one_run)."""
    why = {"cause": h.cause, "detail": detail_json(data, h)}
    if h.cause == "missing_term":
        carried = corner_only_runs(data, h.detail.terms[0])
        if carried:
            return {**why, "corner_only": carried}
    rival = strongest_rival(h, hypotheses)
    if rival is not None:
        return {**why, "rival": catalogue_entry(data, rival)}
    one_run = rests_on_one_run(data, model, h)
    if one_run is not None:
        return {**why, "one_run": {"run": run_label(data.runs[one_run.row]), "p_without": one_run.p_without}}
    return None


def scatter_aliases(data: Data, model: Model, h: Hypothesis, new: Model, hypotheses: list) -> list[str]:
    """For unequal scatter: the covariates it follows as well as the named one or nearly so (their extension's
    AICc at most AMBIGUOUS_AICC above the named one's; a covariate not among the rejected tests may fit better),
    the named one first -- the runs do not tell which; [] when none is that close (or for another cause).  The
    fitted value is often nearly one factor on a small design."""
    if h.cause != "heteroscedasticity":
        return []
    close = _nearly_as_good(new.aicc, [(Model(data, extend_for(data, model, other)[0]).aicc, other.detail)
                                       for other in hypotheses if other.cause == h.cause and other.detail != h.detail])
    return [h.detail] + close if close else []


def _nearly_as_good(anchor_aicc: float, others: list[tuple[float, object]]) -> list:
    """Of ``others`` ((AICc, item) pairs), the items fitted as well as the anchor or nearly so (AICc at most
    AMBIGUOUS_AICC above it), best first: the covariates of unequal scatter the runs do not tell apart."""
    return [item for aicc, item in sorted(others, key=lambda pair: pair[0]) if aicc - anchor_aicc <= AMBIGUOUS_AICC]


def honest_causes(data: Data, response: str, findings: list, model: Model, base_model: Model, first_round,
                   last_round, not_singled_out: dict | None, family_alpha: float):
    """(findings, model, unexplained, naming): the named causes must leave no misfit behind.

    Misfit that no catalogue cause answers (lack of fit alone), or that remains after the named
    extensions (any family member still rejected at the stricter residual level), is reported as
    unexplained instead of a confident cause; the findings are then dropped and the model is the base one.
    """
    unexplained = None
    naming: dict = {}
    if not_singled_out:
        naming["not_singled_out"] = not_singled_out
    if findings and last_round is not None and last_round.hypotheses:
        naming["residual_min_p"] = min(h.p_family for h in last_round.hypotheses)
        naming["residual_tests"] = [catalogue_entry(data, h) for h in last_round.hypotheses
                                    if h.p_family <= family_alpha]
    if findings:
        alts = findings[0].info.get("alternatives", [])
        naming["first_alternatives"] = alts
        naming["first_cause"] = findings[0].cause
        naming["first_detail"] = findings[0].detail
    if first_round is not None:
        residual = []
        if findings and last_round is not None:
            residual = [h for h in last_round.hypotheses if h.p_family <= RESIDUAL_MISFIT_LEVEL * family_alpha]
        if (not findings and first_round.misfit(family_alpha)) or residual:
            unexplained = unexplained_evidence(
                response, [catalogue_entry(data, h) for h in first_round.misfit(family_alpha)],
                [{"cause": f.cause, "detail": f.detail} for f in findings],
                [catalogue_entry(data, h) for h in residual], family_alpha,
                candidate=not_singled_out if not findings else None)
            findings, model = [], base_model
    return findings, model, unexplained, naming


def ambiguity(data: Data, base_model: Model, first_round, findings: list,
               not_singled_out: dict | None) -> tuple[list[dict], list[dict]]:
    """(candidates, discriminating runs) when the first cause named, or the candidate not singled out for
    a rival of another kind, does not lead every cause of another kind by discrimination.AMBIGUOUS_AICC in
    AICc (discrimination.close_candidates); a cause named: ([], the runs that would confirm it); ([], [])
    otherwise."""
    if first_round is None or not (findings or (not_singled_out and "rival" in not_singled_out)):
        return [], []
    if not_singled_out and not findings and not_singled_out["rival"]["cause"] not in CAUSES:
        return [], []
    first = (findings[0].cause, findings[0].detail) if findings else \
        (not_singled_out["cause"], not_singled_out["detail"])
    entries = candidate_entries(data, base_model, first_round)
    close = close_candidates(entries, named=first)
    if len(close) < 2 and findings:  # named: runs that would confirm it against its nearest rivals
        return [], _deciding_runs(data, confirming_rivals(entries, first), CONFIRM_PURPOSE, named=first)
    if len(close) < 2:
        return [], []
    if not findings:
        rival = not_singled_out["rival"]
        if not any((c["cause"], c["detail"]) == (rival["cause"], rival["detail"]) for c in close):
            return [], []
    base_aicc = base_model.aicc
    candidates = [{"cause": c["cause"], "detail": c["detail"], "gain": json_number(base_aicc - c["aicc"]),
                   "delta_aicc": json_number(c["aicc"] - close[0]["aicc"]), "aliases": c.get("aliases", [])}
                  for c in close]
    return candidates, _deciding_runs(data, close, PURPOSE)


def confirming_rivals(entries: list[dict], named: tuple) -> list[dict]:
    """The named cause and the rivals its confirming runs are to separate it from: every kind within
    CONFIRM_AICC of it, or else the nearest kind however far behind (a cause misnamed by a wide margin can
    only be corrected by runs that separate it from something; the nearest rival is the likeliest)."""
    rivals = close_candidates(entries, named=named, margin=CONFIRM_AICC)
    if len(rivals) > 1:
        return rivals
    every = close_candidates(entries, named=named, margin=math.inf)
    anchor = [e for e in every if (e["cause"], e["detail"]) == tuple(named)]
    others = [e for e in every if (e["cause"], e["detail"]) != tuple(named)]
    return anchor + others[:1]


def _deciding_runs(data: Data, close: list[dict], purpose: str, named: tuple | None = None) -> list[dict]:
    """The runs that separate the causes ``close`` (each missing term together with the terms the runs alias
    with it; the ``named`` cause's scatter with the covariates it follows about as well)."""
    models, labels, aiccs, kinds = [], [], [], []
    for c in close:
        # a rival's covariates are not: runs spent telling them apart would not decide the named cause
        aliased = c["cause"] == "missing_term" or (c["cause"], c["detail"]) == named
        model = c["model"] if "model" in c else Model(data, c["spec"])
        for j, (mo, detail) in enumerate(zip([model] + (c.get("aliased_models", []) if aliased else []),
                                             [c["detail"]] + c.get("aliased", []))):
            models.append(mo)
            labels.append(candidate_label(c["cause"], detail))
            aiccs.append(c["aicc"])
            # confirming a named term (or scatter's covariate): the runs also tell it from the terms (covariates)
            # they alias with it, or a term named right on these runs could be renamed as its alias on the new ones
            kinds.append(candidate_kind(c["cause"], c["detail"]) if j == 0 or purpose != CONFIRM_PURPOSE
                         else ("alias", labels[-1]))
    return discriminating_runs(data, models, labels, aiccs, kinds, purpose)


def candidate_entries(data: Data, base_model: Model, first_round) -> list[dict]:
    """Each cause of the first round with its extension and its AICc, the extension paying for the place
    it was chosen from (a run, a change-point, a term, a covariate); a step also at every other change-point,
    so that a step whose first run is uncertain is not named at one of them."""
    entries = []
    choices = _choices(first_round)
    # every cause, not only the rejected ones: a Box-Cox test's bootstrap p-value is floored at 1/(B+1), so a
    # log response fitted far better than the cubic term named may not be rejected (benchmarks/decide_causes.py:
    # comparing the rejected causes only left strict wrong causes at 0.079, every cause 0.062, margin 2)
    for h in (h for h in first_round.hypotheses if h.cause not in MISFIT_TESTS):
        spec, info = extend_for(data, base_model, h)
        mo = Model(data, spec)
        detail = transform_name(spec.lam) if h.cause == "response_transform" else detail_json(data, h)
        price = 2.0 * math.log(choices.get(h.cause, 1))
        # a run's other reading (an outlier for a slip and back) is its alias here as in a named finding
        other = other_reading_of_the_run(h, first_round.hypotheses)
        entry = {"cause": h.cause, "detail": detail, "aicc": mo.aicc + price, "model": mo,
                 "aliases": list(h.aliases) + ([other] if other else [])}
        if h.cause == "missing_term":  # terms the runs alias with it: the deciding runs must not confuse them
            entry["aliased_models"] = [Model(data, replace(base_model.spec, extra_terms=(t,)))
                                       for t in h.detail.terms[1:]]
            entry["aliased"] = [term_name(t, data.factors) for t in h.detail.terms[1:]]
        entries.append(entry)
        if h.cause == "step":
            for start, step_aicc in _step_aiccs(data, base_model):
                if start != int(h.detail):
                    # the spec, not the model: a model per change-point kept at once grows as runs squared;
                    # the few that come close are fitted (the same numbers) when their runs are chosen
                    entries.append({"cause": "step", "detail": run_label(data.runs[start]),
                                    "aicc": step_aicc + price, "spec": replace(base_model.spec, step=start)})
    _alias_scatter_covariates(entries)
    return entries


def _step_aiccs(data: Data, base_model: Model):
    """(change-point, AICc) of the base model with a step at each change-point in run order.  On up to
    STEP_CHUNK runs each is fitted; on more, a fit per change-point would cost runs squared, and the residual
    sum of squares comes from the base fit: SSR = SSR_base - (u'e)^2, u the step column residualised on the
    model and normalised, e the base residuals (the same AICc to round-off), the projections u'e from running
    sums in run order (:func:`step_projections`: one pass over the runs, not one per change-point)."""
    q = orthonormal_basis(base_model.xw)
    if len(base_model.y) <= STEP_CHUNK:
        for start in step_starts(base_model, q):
            yield start, Model(data, replace(base_model.spec, step=start)).aicc
        return
    starts, proj = step_projections(base_model, q, base_model.resid_w[:, None])
    ssr = base_model.ssr - proj[:, 0] ** 2
    log_weights = 0.5 * float(np.sum(np.log(base_model.w)))
    loglik = gaussian_loglik(ssr, data.n) + log_weights
    aicc = aicc_of_many(loglik, data.n, base_model.n_params + 1)  # the step's coefficient
    yield from zip(starts, (float(a) for a in aicc))


def _alias_scatter_covariates(entries: list[dict]) -> None:
    """Each unequal-scatter entry carries the covariates fitted about as well (better, or within
    AMBIGUOUS_AICC) as its aliases, as a missing term carries the terms the runs alias with it."""
    scatter = [e for e in entries if e["cause"] == "heteroscedasticity"]
    for e in scatter:
        close = _nearly_as_good(e["aicc"], [(o["aicc"], o) for o in scatter if o is not e])
        if close:
            e.update(aliases=[e["detail"]] + [o["detail"] for o in close], aliased=[o["detail"] for o in close],
                     aliased_models=[o["model"] for o in close])


def _choices(rnd) -> dict[str, int]:
    """How many places each cause of a round chose its best from: runs for an outlier, change-points for a
    step, alias classes for a missing term, covariates for unequal scatter, candidate slips for a factor
    level (1 for drift and a transform, which choose nothing).  Comparing causes, each pays log of it in
    log-likelihood (a Bonferroni price, as the step's test and step_price): an outlier picked as the worst
    of 13 runs is not preferred to a step picked among 9 change-points for the picking alone."""
    out: dict[str, int] = {}
    for h in rnd.hypotheses:
        if h.cause in ("missing_term", "heteroscedasticity"):
            out[h.cause] = out.get(h.cause, 0) + 1
    out["outlier"] = int(np.sum(rnd.model.hat < LEVERAGE_UNPREDICTABLE))
    step = [h for h in rnd.hypotheses if h.cause == "step"]
    if step:
        out["step"] = int(step[0].info["change_points"])  # the catalogue's step test records them (Round._step)
    # read only for a slip hypothesis, which the round tests only when it has a candidate: never 0 when read
    out["factor_level"] = count_slip_candidates(rnd.data, rnd.model)
    return out
