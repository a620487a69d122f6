"""Level 1: the quadratic surrogate confronted with the simulation runs of one response.

:func:`criticize` tests the catalogue, names the cause, adds its extension and tests
again on the extended model, reporting leave-one-out and AICc gains.
"""

from __future__ import annotations

import json
import math
from dataclasses import dataclass, field, replace
from typing import TYPE_CHECKING

import numpy as np
import pandas as pd
from scipy import optimize, stats

from ..blocks import block_columns
from ..design import LEVERAGE_UNPREDICTABLE, Coding, model_matrix, model_units, quadratic_terms, term_name
from ..surrogate import fit_response
from .aliasing import AliasSet, separating_runs
from .discrimination import (AMBIGUOUS_AICC, CONFIRM_AICC, CONFIRM_PURPOSE, PURPOSE, candidate_kind,
                             candidate_label, close_candidates, discriminating_runs)
from .catalogue import (CAUSES, MISFIT_TESTS, slip_candidates, step_direction_chunks,
                        step_starts, STEP_CHUNK, _GAMMA_BOUND, _LAMBDA_FINE_GRID,
                        _NICE_LAMBDAS, _Round, _boxcox_profile)
from .verdict import (RESIDUAL_MISFIT_LEVEL, SLIP_BAYES_FACTOR, exact_fit_message, other_reading_of_the_run,
                      rests_on_one_run, runs_for_next_wave, strongest_rival, unexplained_evidence, verdict_of)
from .messages import _CAUSE_WORDS, _message, corner_only_runs
from .models import (TRANSFORM_NAMES, _Data, _Model, _Spec, _aicc, _num, _orth, _run_value, _transform_name,
                     gaussian_loglik, infer_axial_distance)
from .run_order import RunOrder, assess_run_order

if TYPE_CHECKING:
    from ..surrogate import SurrogateFit
    from .catalogue import _Hypothesis
    from .models import ExtendedSurrogate


#: Causes that describe the run order: a linear drift or a step between two groups of runs.
RUN_ORDER_CAUSES = ("drift", "step")


# =========================================================================== findings
@dataclass
class Finding:
    """One named cause with its extension's gain over the model before it."""

    response: str
    cause: str
    detail: object
    aliases: list[str]
    p_value: float
    p_nominal: float
    statistic: float
    message: str
    loo_rmse_baseline: float
    loo_rmse_extended: float
    delta_aicc: float
    compared_runs: int
    extra_runs: list[dict] = field(default_factory=list)
    info: dict = field(default_factory=dict)

    def to_json(self) -> dict:
        out = {"cause": self.cause, "detail": self.detail, "aliases": list(self.aliases),
               "p_value": _num(self.p_value), "message": self.message,
               "p_nominal": _num(self.p_nominal), "statistic": _num(self.statistic),
               "loo_rmse_before": _num(self.loo_rmse_baseline), "loo_rmse_after": _num(self.loo_rmse_extended),
               "delta_aicc": _num(self.delta_aicc), "compared_runs": self.compared_runs}
        if self.extra_runs:
            out["extra_runs"] = self.extra_runs
        out.update({k: v for k, v in self.info.items()})
        return out


@dataclass
class CriticismResult:
    """Level-1 result for one response; ``to_json()`` is the issue's contract (plus extra keys)."""

    response: str
    factors: list[str]
    baseline: dict
    findings: list[Finding]
    extended: dict
    gain: dict
    alias_sets: list[AliasSet]
    catalogue: list[dict]
    summary: str
    family_alpha: float
    unexplained: dict | None = None
    verdict: str = "adequate"
    verdict_detail: dict = field(default_factory=dict)
    naming: dict = field(default_factory=dict)
    residuals: pd.DataFrame = field(repr=False, default=None)
    _extended_model: _Model = field(repr=False, default=None)
    _baseline_model: _Model = field(repr=False, default=None)
    run_order: RunOrder | None = None
    candidates: list[dict] = field(default_factory=list)  # causes the runs cannot tell apart (discrimination)
    discriminating_runs: list[dict] = field(default_factory=list)

    def to_json(self) -> dict:
        """JSON-ready dict: response, baseline, findings, extended, gain (+ alias sets, catalogue, summary)."""
        out = {
            "response": self.response,
            "baseline": self.baseline,
            "findings": [f.to_json() for f in self.findings],
            "extended": self.extended,
            "gain": self.gain,
            "summary": self.summary,
            "family_alpha": self.family_alpha,
            "alias_sets": [a.to_json() for a in self.alias_sets],
            "catalogue": self.catalogue,
            "runs": self._runs_json(),
            "verdict": self.verdict,
            "verdict_detail": self.verdict_detail,
            "unexplained": self.unexplained,
        }
        if self.run_order is not None:
            out["run_order"] = self.run_order.to_json()
        out["candidates"] = self.candidates  # causes the runs cannot tell apart (empty unless ambiguous)
        out["discriminating_runs"] = self.discriminating_runs
        return out

    def _runs_json(self) -> list[dict]:
        if self.residuals is None:
            return []
        cols = ["run", "observed", "fitted", "residual", "loo_residual", "student_resid", "leverage"]
        return [{c: (_run_value(row[c]) if c == "run" else _num(row[c])) for c in cols}
                for _, row in self.residuals[cols].iterrows()]

    def dumps(self) -> str:
        return json.dumps(self.to_json(), indent=2, allow_nan=False)

    def to_frame(self) -> pd.DataFrame:
        """One row per finding (or one ``unexplained`` row); ``verdict`` repeats the response's verdict."""
        cols = ["response", "cause", "detail", "aliases", "p_value", "loo_rmse_baseline",
                "loo_rmse_extended", "delta_aicc", "message", "verdict"]
        rows = [{"response": self.response, "cause": f.cause, "detail": str(f.detail),
                 "aliases": ";".join(f.aliases), "p_value": f.p_value,
                 "loo_rmse_baseline": f.loo_rmse_baseline, "loo_rmse_extended": f.loo_rmse_extended,
                 "delta_aicc": f.delta_aicc, "message": f.message, "verdict": self.verdict} for f in self.findings]
        if self.candidates and not self.findings:
            rows.append({"response": self.response, "cause": "ambiguous",
                         "detail": ";".join(f"{c['cause']} ({c['detail']})" for c in self.candidates), "aliases": "",
                         "p_value": None, "loo_rmse_baseline": self.baseline.get("loo_rmse"),
                         "loo_rmse_extended": self.baseline.get("loo_rmse"), "delta_aicc": 0.0,
                         "message": self.verdict_message, "verdict": self.verdict})
        if self.runs_for_next_wave and rows:
            # on the row they serve (the ambiguous one, or the finding they confirm); read by the next wave
            # (next_wave.deciding_runs)
            rows[0 if self.findings else -1]["discriminating_runs"] = json.dumps(self.discriminating_runs)
            cols = cols + ["discriminating_runs"]
        if self.unexplained:
            u = self.unexplained
            rows.append({"response": self.response, "cause": "unexplained", "detail": u["detail"], "aliases": "",
                         "p_value": u["p_value"], "loo_rmse_baseline": self.baseline.get("loo_rmse"),
                         "loo_rmse_extended": self.baseline.get("loo_rmse"), "delta_aicc": 0.0,
                         "message": u["message"], "verdict": self.verdict})
        return pd.DataFrame(rows, columns=cols)

    @property
    def runs_for_next_wave(self) -> bool:
        """Whether a next wave makes the discriminating runs (verdict.runs_for_next_wave)."""
        return runs_for_next_wave(self.discriminating_runs, self.candidates, self.verdict)

    @property
    def verdict_message(self) -> str:
        """The verdict in words: what the user can do with this surrogate."""
        return self.verdict_detail.get("message", "")

    def extended_surrogate(self) -> ExtendedSurrogate:
        """Predictor of the extended model (the baseline quadratic when nothing was found)."""
        return self._extended_model.surrogate()

    def baseline_surrogate(self) -> ExtendedSurrogate:
        return self._baseline_model.surrogate()


def _prepare(table: pd.DataFrame, factors: list[str], response: str, alpha: float | None,
             log_factors: tuple[str, ...], fit: SurrogateFit | None = None) -> tuple[_Data, SurrogateFit]:
    """The data in coded units and the baseline fit: ``fit`` (the material's, in validation's coding)
    when given, else a fit in a coding from the table's extremes."""
    z = model_units(table[factors].to_numpy(), factors, log_factors)
    ok = np.isfinite(table[response].to_numpy(dtype=float))
    if alpha is None:
        alpha = infer_axial_distance(z[ok])
    if fit is None:
        fit = fit_response(table, factors, response, alpha=alpha,
                           coding=Coding.from_levels(factors, z, alpha), log_factors=tuple(log_factors))
    coding = fit.coding
    sub = table.loc[ok]
    runs = sub["run"].to_numpy() if "run" in sub.columns else np.arange(1, int(ok.sum()) + 1)
    blocks = None if fit.blocks is None else block_columns(fit.blocks, fit.block_levels)
    data = _Data(response, list(factors), fit.coded, fit.y, runs, coding, float(alpha),
                 tuple(log_factors), quadratic_terms(len(factors)), factor_round_off=fit.factor_round_off,
                 blocks=blocks, block_labels=fit.blocks)
    return data, fit


def _apply(data: _Data, model: _Model, h: _Hypothesis) -> tuple[_Spec, dict]:
    """Extension of ``model.spec`` that answers hypothesis h, and facts for the message."""
    spec = model.spec
    info: dict = {}
    if h.cause == "missing_term":
        return replace(spec, extra_terms=spec.extra_terms + (h.detail.terms[0],)), info
    if h.cause == "drift":
        return replace(spec, drift=True), info
    if h.cause == "step":
        return replace(spec, step=int(h.detail)), info
    if h.cause == "factor_level":
        c = h.detail
        row = model.coded[int(np.flatnonzero(np.flatnonzero(model.keep) == c.row)[0])].copy()
        recorded = float(data.to_actual(row)[0, c.factor])
        row[c.factor] = c.coded
        info.update(factor=data.factors[c.factor], recorded_value=recorded,
                    fitting_value=float(data.to_actual(row)[0, c.factor]), slip=f"x1e{c.power:+d}",
                    t_moved=h.info["t_moved"], bayes_factor=h.info["bayes_factor"],
                    t_recorded=h.info["t_recorded"], observed=float(data.y[c.row]))
        return replace(spec, moved=spec.moved + ((c.row, c.factor, c.coded),)), info
    if h.cause == "outlier":
        i = int(h.detail)
        pos = int(np.flatnonzero(np.flatnonzero(model.keep) == i)[0])
        info["observed"] = float(data.y[i])
        info["predicted_without"] = float(data.y[i] - model.loo_errors[pos])
        return replace(spec, dropped=spec.dropped + (i,)), info
    if h.cause == "response_transform":
        q = _orth(model.xw)
        prof = _boxcox_profile(model.y[:, None], q, _LAMBDA_FINE_GRID)[:, 0]
        best = int(np.argmax(prof))
        lam_hat = float(_LAMBDA_FINE_GRID[best])
        # Small-sample 95 % interval: the likelihood ratio in F form, F = df (exp(LR/n) - 1) ~ F(1, df)
        # (the chi-square(1) interval is far too narrow at a dozen runs).
        n, df = len(model.y), model.df_resid - 1
        f_ratio = df * np.expm1(2 * (prof[best] - prof) / n)
        inside = _LAMBDA_FINE_GRID[f_ratio <= stats.f.ppf(0.95, 1, df)]
        lo, hi = float(inside.min()), float(inside.max())
        # The transform used is the first convenient lambda (log, sqrt, inverse, then others)
        # that the data do not reject at the 1 % level; otherwise lambda-hat to one decimal.
        plausible = _LAMBDA_FINE_GRID[f_ratio <= stats.f.ppf(0.99, 1, df)]
        lo99, hi99 = float(plausible.min()), float(plausible.max())
        lam = next((v for v in (*TRANSFORM_NAMES, *_NICE_LAMBDAS) if lo99 <= v <= hi99), round(lam_hat, 1))
        if abs(lam - 1.0) < 1e-9:
            lam = round(lam_hat, 2)
        info.update(lambda_hat=lam_hat, lambda_ci=[lo, hi])
        return replace(spec, lam=float(lam)), info
    if h.cause == "heteroscedasticity":
        if h.detail == "fitted":  # excluded runs: their predicted value, same scaling
            k = len(model.mean_terms)
            fz_all = model_matrix(data.coded, model.mean_terms) @ model.beta[:k]
            if data.blocks is not None:
                fz_all = fz_all + data.blocks @ model.beta[k:k + data.blocks.shape[1]]
            fz = model.fitted_z
            values = (fz_all - (fz.max() + fz.min()) / 2) / (np.ptp(fz) / 2)
        else:
            values = data.coded[:, data.factors.index(h.detail)] / data.alpha
        base = replace(spec, weight_on=h.detail, weight_values=tuple(float(v) for v in values))

        def negll(g):
            return -_Model(data, replace(base, weight_gamma=float(g))).loglik

        res = optimize.minimize_scalar(negll, bounds=(-_GAMMA_BOUND, _GAMMA_BOUND), method="bounded",
                                       options={"xatol": 1e-6})
        gamma = float(res.x)
        info["sd_ratio"] = float(np.exp(gamma))  # sd at covariate +1 over sd at -1
        return replace(base, weight_gamma=gamma), info
    raise ValueError(h.cause)


def criticize(table: pd.DataFrame, factors: list[str], response: str, *, alpha: float | None = None,
              family_alpha: float = 0.05, log_factors: tuple[str, ...] = (), max_findings: int = 3,
              n_null: int = 1999, seed: int = 0, run_order: str | RunOrder = "performed",
              fit: SurrogateFit | None = None, run_candidates: np.ndarray | None = None) -> CriticismResult:
    """Level-1 model criticism of the quadratic surrogate of one response.

    ``alpha`` is the CCD axial distance used for coding (None: inferred from the
    levels).  Runs with a missing response are dropped.  ``n_null`` Monte Carlo
    draws of the joint null (seeded with ``seed``: results are reproducible) give
    the family-adjusted p-values.  ``run_order`` is the declared order of the ``run`` column
    (``performed`` or ``unknown``), or the material's :class:`~demid.criticism.run_order.RunOrder`
    already assessed: drift is tested only where it can be believed.  ``fit`` is the response's
    quadratic fit already made (its coding is then the one used; None: fitted here).  ``run_candidates``
    (actual units) are the points the runs it proposes are chosen from (None: the design's levels within its
    reach).  See the package docstring (demid.criticism) for the catalogue.
    """
    data, fit = _prepare(table, list(factors), response, alpha, tuple(log_factors), fit)
    if run_candidates is not None:
        actual = np.atleast_2d(np.asarray(run_candidates, dtype=float))
        data = replace(data, run_candidates=data.coding.to_coded(model_units(actual, list(factors),
                                                                            list(log_factors))))
    if not isinstance(run_order, RunOrder):
        run_order = assess_run_order(data.runs, data.coded, {response: data.y}, run_order)
    data = replace(data, drift_tested=run_order.drift_tested)
    rng = np.random.default_rng(seed)
    base_model = _Model(data, _Spec())
    model = base_model
    findings: list[Finding] = []
    catalogue: list[dict] = []
    alias_sets: list[AliasSet] = []
    first_round = last_round = None
    not_singled_out = None
    for rnd_index in range(max_findings + 1):
        rnd = _Round(data, model, n_null, rng)
        last_round = rnd
        if rnd_index == 0:
            first_round = rnd
            alias_sets = _alias_sets(data, rnd)
            catalogue = [_catalogue_entry(data, h) for h in rnd.hypotheses]
        rejected = rnd.rejected(family_alpha)
        if not rejected or rnd_index == max_findings:
            break
        named = _name_cause(data, model, rejected)
        if named is None:  # only a slip fits, and too weakly to be named: misfit without a cause
            break
        not_singled_out = _not_singled_out(data, model, named[0], rnd.hypotheses)
        if not_singled_out is not None:
            break
        h, spec, info, new, alternatives = named
        both = new.predictable & model.predictable
        if findings and not new.loo_rmse_on(both) < model.loo_rmse_on(both):
            break  # a further extension must also predict left-out runs better
        findings.append(_finding(data, response, model, h, spec, info, new, alternatives,
                                 other_reading_of_the_run(h, rnd.hypotheses),
                                 _scatter_aliases(data, model, h, new, rnd.hypotheses), first=not findings))
        model = new
        last_round = None
        if model.df_resid - 1 < 3 or model.spec.weight_on is not None:
            break  # too few spare runs, or estimated weights (further tests would not be exact)

    findings, model, unexplained, naming = _honest_causes(data, response, findings, model, base_model, first_round,
                                                          last_round, not_singled_out, family_alpha)

    candidates, runs = _ambiguity(data, base_model, first_round, findings, not_singled_out)
    if candidates:  # the runs cannot tell these causes apart: none of them is named
        findings, model, unexplained = [], base_model, None
    baseline, extended, gain = _gain(table, factors, response, data, fit, base_model, model, bool(findings))
    summary = _summary(data, findings, catalogue, family_alpha, gain, exact_fit_message(response, fit))
    if unexplained:
        summary = unexplained["message"]
    if not run_order.drift_tested:
        summary += " " + run_order.message
    verdict, verdict_detail = verdict_of(data, fit, findings, unexplained, catalogue, family_alpha,
                                         candidates, runs)
    if candidates:
        summary = verdict_detail["message"]
    return CriticismResult(response=response, factors=list(factors), baseline=baseline, findings=findings,
                           extended=extended, gain=gain, alias_sets=alias_sets, catalogue=catalogue,
                           summary=summary, family_alpha=family_alpha, unexplained=unexplained, verdict=verdict,
                           verdict_detail=verdict_detail, naming=naming, residuals=_residual_frame(fit),
                           _extended_model=model, _baseline_model=base_model, run_order=run_order,
                           candidates=candidates, discriminating_runs=runs)


def _honest_causes(data: _Data, response: str, findings: list, model: _Model, base_model: _Model, first_round,
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
        naming["residual_tests"] = [_catalogue_entry(data, h) for h in last_round.hypotheses
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
                response, [_catalogue_entry(data, h) for h in first_round.misfit(family_alpha)],
                [{"cause": f.cause, "detail": f.detail} for f in findings],
                [_catalogue_entry(data, h) for h in residual], family_alpha,
                candidate=not_singled_out if not findings else None)
            findings, model = [], base_model
    return findings, model, unexplained, naming


def _ambiguity(data: _Data, base_model: _Model, first_round, findings: list,
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
    entries = _candidate_entries(data, base_model, first_round)
    close = close_candidates(entries, named=first)
    if len(close) < 2 and findings:  # named: runs that would confirm it against its nearest rivals
        return [], _deciding_runs(data, _confirming_rivals(entries, first), CONFIRM_PURPOSE, named=first)
    if len(close) < 2:
        return [], []
    if not findings:
        rival = not_singled_out["rival"]
        if not any((c["cause"], c["detail"]) == (rival["cause"], rival["detail"]) for c in close):
            return [], []
    base_aicc = base_model.aicc
    candidates = [{"cause": c["cause"], "detail": c["detail"], "gain": _num(base_aicc - c["aicc"]),
                   "delta_aicc": _num(c["aicc"] - close[0]["aicc"]), "aliases": c.get("aliases", [])}
                  for c in close]
    return candidates, _deciding_runs(data, close, PURPOSE)


def _confirming_rivals(entries: list[dict], named: tuple) -> list[dict]:
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


def _deciding_runs(data: _Data, close: list[dict], purpose: str, named: tuple | None = None) -> list[dict]:
    """The runs that separate the causes ``close`` (each missing term together with the terms the runs alias
    with it; the ``named`` cause's scatter with the covariates it follows about as well)."""
    models, labels, aiccs, kinds = [], [], [], []
    for c in close:
        # a rival's covariates are not: runs spent telling them apart would not decide the named cause
        aliased = c["cause"] == "missing_term" or (c["cause"], c["detail"]) == named
        model = c["model"] if "model" in c else _Model(data, c["spec"])
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


def _candidate_entries(data: _Data, base_model: _Model, first_round) -> list[dict]:
    """Each cause of the first round with its extension and its AICc, the extension paying for the place
    it was chosen from (a run, a change-point, a term, a covariate); a step also at every other change-point,
    so that a step whose first run is uncertain is not named at one of them."""
    entries = []
    choices = _choices(first_round)
    # every cause, not only the rejected ones: a Box-Cox test's bootstrap p-value is floored at 1/(B+1), so a
    # log response fitted far better than the cubic term named may not be rejected (benchmarks/decide_causes.py:
    # comparing the rejected causes only left strict wrong causes at 0.079, every cause 0.062, margin 2)
    for h in (h for h in first_round.hypotheses if h.cause not in MISFIT_TESTS):
        spec, info = _apply(data, base_model, h)
        mo = _Model(data, spec)
        detail = _transform_name(spec.lam) if h.cause == "response_transform" else _detail_json(data, h)
        price = 2.0 * math.log(choices.get(h.cause, 1))
        # a run's other reading (an outlier for a slip and back) is its alias here as in a named finding
        other = other_reading_of_the_run(h, first_round.hypotheses)
        entry = {"cause": h.cause, "detail": detail, "aicc": mo.aicc + price, "model": mo,
                 "aliases": list(h.aliases) + ([other] if other else [])}
        if h.cause == "missing_term":  # terms the runs alias with it: the deciding runs must not confuse them
            entry["aliased_models"] = [_Model(data, replace(base_model.spec, extra_terms=(t,)))
                                       for t in h.detail.terms[1:]]
            entry["aliased"] = [term_name(t, data.factors) for t in h.detail.terms[1:]]
        entries.append(entry)
        if h.cause == "step":
            for start, step_aicc in _step_aiccs(data, base_model):
                if start != int(h.detail):
                    # the spec, not the model: a model per change-point kept at once grows as runs squared;
                    # the few that come close are fitted (the same numbers) when their runs are chosen
                    entries.append({"cause": "step", "detail": _run_value(data.runs[start]),
                                    "aicc": step_aicc + price, "spec": replace(base_model.spec, step=start)})
    _alias_scatter_covariates(entries)
    return entries


def _step_aiccs(data: _Data, base_model: _Model):
    """(change-point, AICc) of the base model with a step at each change-point in run order.  On up to
    STEP_CHUNK runs each is fitted; on more, a fit per change-point would cost runs squared, and the residual
    sum of squares comes from the base fit: SSR = SSR_base - (u'e)^2, u the step column residualised on the
    model and normalised, e the base residuals (the same AICc to round-off)."""
    q = _orth(base_model.xw)
    if len(base_model.y) <= STEP_CHUNK:
        for start in step_starts(base_model, q):
            yield start, _Model(data, replace(base_model.spec, step=start)).aicc
        return
    n_params = base_model.n_params + 1  # the step's coefficient
    for starts, directions in step_direction_chunks(base_model, q):
        ssr = base_model.ssr - (directions.T @ base_model.resid_w) ** 2
        for start, step_ssr in zip(starts, ssr):
            loglik = gaussian_loglik(float(step_ssr), data.n) + 0.5 * float(np.sum(np.log(base_model.w)))
            yield start, _aicc(loglik, data.n, n_params)


def _alias_scatter_covariates(entries: list[dict]) -> None:
    """Each unequal-scatter entry carries the covariates fitted about as well (better, or within
    AMBIGUOUS_AICC) as its aliases, as a missing term carries the terms the runs alias with it."""
    scatter = [e for e in entries if e["cause"] == "heteroscedasticity"]
    for e in scatter:
        close = _nearly_as_good(e["aicc"], [(o["aicc"], o) for o in scatter if o is not e])
        if close:
            e.update(aliases=[e["detail"]] + [o["detail"] for o in close], aliased=[o["detail"] for o in close],
                     aliased_models=[o["model"] for o in close])


def _not_singled_out(data: _Data, model: _Model, h: _Hypothesis, hypotheses: list[_Hypothesis]) -> dict | None:
    """Why cause h is not named, or None: a term only the corner runs carry (which any difference between
    the corners mimics, messages.corner_only_runs), another kind of misfit at least as strong, or evidence
    that hinges on one run (verdict.strongest_rival, verdict.rests_on_one_run)."""
    why = {"cause": h.cause, "detail": _detail_json(data, h)}
    if h.cause == "missing_term":
        carried = corner_only_runs(data, h.detail.terms[0])
        if carried:
            return {**why, "corner_only": carried}
    rival = strongest_rival(h, hypotheses)
    if rival is not None:
        return {**why, "rival": _catalogue_entry(data, rival)}
    one_run = rests_on_one_run(data, model, h)
    if one_run is not None:
        return {**why, "one_run": {"run": _run_value(data.runs[one_run.row]), "p_without": one_run.p_without}}
    return None


def _name_cause(data: _Data, model: _Model, rejected: list[_Hypothesis]) -> tuple:
    """The cause to name among the rejected ones, its extension, and the others as alternatives."""
    # The rejected cause with the strongest evidence (smallest nominal p-value) is named, except
    # that one wild run can be read as an outlier or as scatter growing towards its corner of the
    # design: between those two (and between variance covariates, often nearly collinear) the
    # better-fitting one-parameter extension (higher likelihood) decides.  The other rejected
    # causes are fitted too and listed as alternatives.
    fitted_alternatives = []
    for cand in rejected:
        cand_spec, cand_info = _apply(data, model, cand)
        fitted_alternatives.append((cand, cand_spec, cand_info, _Model(data, cand_spec)))
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


def _with_alternatives(data: _Data, fitted_alternatives: list, best: int) -> tuple:
    h, spec, info, new = fitted_alternatives[best]
    alternatives = [{"cause": c.cause, "detail": _detail_json(data, c) if c.cause != "response_transform"
                     else _transform_name(sp.lam), "p_value": _num(c.p_family),
                     "loglik_vs_named": _num(mo.loglik - new.loglik), "aicc_vs_named": _num(mo.aicc - new.aicc)}
                    for c, sp, _, mo in fitted_alternatives if c is not h]
    return h, spec, info, new, alternatives


def _scatter_aliases(data: _Data, model: _Model, h: _Hypothesis, new: _Model, hypotheses: list) -> list[str]:
    """For unequal scatter: the covariates it follows as well as the named one or nearly so (their extension's
    AICc at most AMBIGUOUS_AICC above the named one's; a covariate not among the rejected tests may fit better),
    the named one first -- the runs do not tell which; [] when none is that close (or for another cause).  The
    fitted value is often nearly one factor on a small design."""
    if h.cause != "heteroscedasticity":
        return []
    close = _nearly_as_good(new.aicc, [(_Model(data, _apply(data, model, other)[0]).aicc, other.detail)
                                       for other in hypotheses if other.cause == h.cause and other.detail != h.detail])
    return [h.detail] + close if close else []


def _nearly_as_good(anchor_aicc: float, others: list[tuple[float, object]]) -> list:
    """Of ``others`` ((AICc, item) pairs), the items fitted as well as the anchor or nearly so (AICc at most
    AMBIGUOUS_AICC above it), best first: the covariates of unequal scatter the runs do not tell apart."""
    return [item for aicc, item in sorted(others, key=lambda pair: pair[0]) if aicc - anchor_aicc <= AMBIGUOUS_AICC]


def _finding(data: _Data, response: str, model: _Model, h: _Hypothesis, spec: _Spec, info: dict, new: _Model,
             alternatives: list[dict], other_reading: str | None = None,
             scatter_aliases: list[str] = (), first: bool = True) -> Finding:
    """The finding of one round: the named cause, its gain on the same runs, and its message; ``other_reading``
    of the same run (an outlier for a slip, a slip for an outlier) is listed as its alias, and so are the
    ``scatter_aliases`` of unequal scatter (the ``first`` finding's confirming runs separate them)."""
    if h.cause == "response_transform":
        info["lam"] = spec.lam
    if h.cause == "drift":
        info["drift_per_run"] = _drift_per_run(new)
    if h.cause == "step":
        info["step_size"] = _step_size(new)
        info["runs_before"] = int(np.sum(data.runs.astype(float) < float(data.runs[int(h.detail)])))
    same = new.predictable & model.predictable
    before = model.loo_rmse_on(same)
    after = new.loo_rmse_on(same)
    extra_runs = []
    if h.cause == "missing_term" and len(h.detail.terms) > 1:
        pts = separating_runs(data.coded[model.keep], model.mean_terms, h.detail.terms, data.alpha)
        extra_runs = [data.point_dict(p) for p in pts]
    message = _message(data, h, info, before, after, int(same.sum()), extra_runs, model)
    if other_reading == "factor_level":
        message += (" A slipped factor value of the same run fits it too (a Bayes factor short of 20:1 either way): no "
                    "further run tells the two apart, the run's input does.")
    elif other_reading == "outlier":
        message += (f" The same evidence reads as an outlier of run {_detail_json(data, h)} (the Bayes factor of the "
                    f"slip, {info['bayes_factor']:.1f}, is no decisive preference).")
    if scatter_aliases:
        others = ", ".join("the predicted value" if a == "fitted" else a for a in scatter_aliases[1:])
        message += (f" The scatter follows {others} as well or nearly so (AICc at most {AMBIGUOUS_AICC:g} worse): "
                    "these runs do not tell which" + ("; the runs proposed to confirm it are chosen to tell them "
                                                      "apart." if first else "."))
    close = [a for a in alternatives if a["loglik_vs_named"] is not None and a["loglik_vs_named"] > -2.0
             and not (a["cause"] == h.cause and a["detail"] in scatter_aliases)]
    if close:
        message += (" Almost as likely: " + "; ".join(f"{_CAUSE_WORDS[a['cause']]} {a['detail']}" for a in close)
                    + ".")
    detail = _transform_name(spec.lam) if h.cause == "response_transform" else _detail_json(data, h)
    public_info = {k: v for k, v in info.items() if k in ("lambda_hat", "lambda_ci", "sd_ratio",
                                                          "drift_per_run", "step_size", "runs_before",
                                                          "observed", "predicted_without",
                                                          "factor", "recorded_value", "fitting_value", "slip",
                                                          "t_moved", "t_recorded", "bayes_factor")}
    if alternatives:
        public_info["alternatives"] = alternatives
    return Finding(
        response=response, cause=h.cause, detail=detail,
        aliases=list(h.aliases) + ([other_reading] if other_reading else []) + list(scatter_aliases),
        p_value=h.p_family,
        p_nominal=float(np.exp(h.logp)), statistic=h.statistic, message=message,
        loo_rmse_baseline=before, loo_rmse_extended=after, delta_aicc=new.aicc - model.aicc,
        compared_runs=int(same.sum()), extra_runs=extra_runs, info=public_info)


def _gain(table: pd.DataFrame, factors: list[str], response: str, data: _Data, fit, base_model: _Model,
          model: _Model, found: bool) -> tuple[dict, dict, dict]:
    """Baseline and extended model summaries and the gain of the extension (on the same runs)."""
    baseline = base_model.summary()
    stats_ = fit.statistics()
    baseline.update(lof_f=_num(stats_.lof_f), lof_p=_num(stats_.lof_p))
    if found:
        extended = model.summary()
        extended.update(lof_f=None, lof_p=None)
        # only an extension made of terms is refitted for lack of fit: a moved factor value or a step in run
        # order is not in the table's columns, and a refit without it would print the baseline's test as its own
        if not model.spec.dropped and model.spec.lam is None and model.spec.weight_on is None \
                and not model.spec.drift and not model.spec.moved and model.spec.step is None:
            ext_fit = fit_response(table, factors, response, alpha=data.alpha, coding=data.coding,
                                   terms=model.mean_terms, log_factors=data.log_factors)
            st = ext_fit.statistics()
            extended.update(lof_f=_num(st.lof_f), lof_p=_num(st.lof_p))
    else:
        extended = dict(baseline)
    same = model.predictable & base_model.predictable
    loo_base_same = base_model.loo_rmse_on(same)
    loo_ext = model.loo_rmse_on(same)
    gain = {
        "loo_rmse_ratio": _num(loo_ext / loo_base_same) if loo_base_same > 0 else None,
        "delta_aicc": _num(model.aicc - base_model.aicc) if found else 0.0,
        "loo_rmse_baseline_same_runs": _num(loo_base_same),
        "compared_runs": int(same.sum()),
    }
    if not found:
        gain["loo_rmse_ratio"] = 1.0
    return baseline, extended, gain


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
        out["step"] = int(step[0].info.get("change_points", 1))
    out["factor_level"] = max(len(slip_candidates(rnd.data, rnd.model)), 1)
    return out


def step_price(h: _Hypothesis) -> float:
    """Log-likelihood a step pays for its change-point, chosen as the best of C positions: log C, the
    Bonferroni price its test pays too (a linear drift is then not read as a step at a dozen runs; in
    tests/criticism/test_criticism.py a 14-SD drift over 13 runs fits a step at run 9 better by 1.9).  0 for other
    causes."""
    return math.log(h.info.get("change_points", 1)) if h.cause == "step" else 0.0


def _step_size(model: _Model) -> float:
    """The shift of the runs after the step against those before (response units, or the transform's)."""
    return float(model.beta[model.names.index("step")])


def _drift_per_run(model: _Model) -> float:
    j = model.names.index("run")
    return float(model.beta[j] / model.run_scale)


def _detail_json(data: _Data, h: _Hypothesis):
    if h.cause == "missing_term":
        return h.aliases[0]
    if h.cause == "factor_level":
        return _run_value(data.runs[h.detail.row])
    if h.cause == "lack_of_fit":
        return ""
    if h.cause in ("outlier", "step"):
        return _run_value(data.runs[int(h.detail)])
    if h.cause == "response_transform":
        return "boxcox"
    return h.detail


def _alias_sets(data: _Data, rnd: _Round) -> list[AliasSet]:
    out = []
    for c in rnd.classes:
        names = tuple(term_name(t, data.factors) for t in c.terms)
        runs = ()
        if len(c.terms) > 1 or c.direction is None:
            pts = separating_runs(data.coded[rnd.model.keep], rnd.model.mean_terms, c.terms, data.alpha)
            runs = tuple(data.point_dict(p) for p in pts)
        out.append(AliasSet(names[0], names, c.direction is not None, runs))
    return out


def _catalogue_entry(data: _Data, h: _Hypothesis) -> dict:
    detail = _detail_json(data, h)
    return {"cause": h.cause, "detail": detail, "aliases": list(h.aliases),
            "statistic": _num(h.statistic), "p_nominal": _num(np.exp(h.logp)), "p_family": _num(h.p_family)}


def _summary(data: _Data, findings: list[Finding], catalogue: list[dict], family_alpha: float,
             gain: dict, exact: str = "") -> str:
    n_tests = len(catalogue)
    if not n_tests and exact:
        return exact
    if not n_tests:
        return (f"{data.response}: nothing could be tested: {data.n} runs leave too few spare runs beyond "
                f"the {len(data.base_terms)} quadratic coefficients.")
    if not findings:
        return (f"{data.response}: nothing found: none of the {n_tests} catalogue tests (missing term, "
                f"transform, outlier, drift, unequal scatter) is significant at a family-wise "
                f"{100 * family_alpha:g} % level. With {data.n} runs only clear defects are detectable.")
    names = ", ".join(f"{f.cause} ({f.detail})" for f in findings)
    ratio = gain.get("loo_rmse_ratio")
    tail = f"; together they change the leave-one-out error by {100 * (ratio - 1):+.0f} %" if ratio else ""
    return (f"{data.response}: {len(findings)} finding(s) at a family-wise {100 * family_alpha:g} % level: "
            f"{names}{tail}.")


def _residual_frame(fit: SurrogateFit) -> pd.DataFrame:
    return fit.influence()
