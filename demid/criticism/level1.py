"""Level 1: the quadratic surrogate confronted with the simulation runs of one response.

:func:`criticize` tests the catalogue, names the cause, adds its extension and tests
again on the extended model, reporting leave-one-out and AICc gains.
"""

from __future__ import annotations

import json
from dataclasses import dataclass, field, replace
from typing import TYPE_CHECKING

import numpy as np
import pandas as pd

from ..blocks import block_columns
from ..design import Coding, model_units, quadratic_terms, term_name
from ..io import json_ready
from ..surrogate import fit_response
from .aliasing import AliasSet, separating_runs
from .catalogue import Round
from .discrimination import AMBIGUOUS_AICC
from .extensions import catalogue_entry, detail_json, drift_per_run, step_size
from .messages import CAUSE_WORDS, finding_message
from .models import Data, Model, ModelForm, infer_axial_distance, json_number, run_label, transform_name
from .naming import ambiguity, honest_causes, name_cause, scatter_aliases, why_not_singled_out
from .run_order import RunOrder, assess_run_order
from .verdict import exact_fit_message, other_reading_of_the_run, replicate_runs, runs_for_next_wave, verdict_of

if TYPE_CHECKING:
    from ..surrogate import SurrogateFit
    from .catalogue import Hypothesis
    from .models import ExtendedSurrogate


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
               "p_value": json_number(self.p_value), "message": self.message,
               "p_nominal": json_number(self.p_nominal), "statistic": json_number(self.statistic),
               "loo_rmse_before": json_number(self.loo_rmse_baseline),
               "loo_rmse_after": json_number(self.loo_rmse_extended),
               "delta_aicc": json_number(self.delta_aicc), "compared_runs": self.compared_runs}
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
    _extended_model: Model = field(repr=False, default=None)
    _baseline_model: Model = field(repr=False, default=None)
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
        # the rows as iterrows gives them (one common dtype per row), without a Series per run
        return [{c: (run_label(v) if c == "run" else json_number(v)) for c, v in zip(cols, row)}
                for row in self.residuals[cols].values]

    def dumps(self) -> str:
        """The JSON document, every number to the last bit; NaN or infinity anywhere in it (a finding's t statistic
        of runs fitted exactly) as null, as the written file has them (io.json_ready, as write_json)."""
        return json.dumps(json_ready(self.to_json(), float_format=None), indent=2, allow_nan=False)

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
        if self.unexplained:
            u = self.unexplained
            rows.append({"response": self.response, "cause": "unexplained", "detail": u["detail"], "aliases": "",
                         "p_value": u["p_value"], "loo_rmse_baseline": self.baseline.get("loo_rmse"),
                         "loo_rmse_extended": self.baseline.get("loo_rmse"), "delta_aicc": 0.0,
                         "message": u["message"], "verdict": self.verdict})
        if self.runs_for_next_wave and rows:
            # on the row they serve (the ambiguous or unexplained one, or the finding they confirm); read by the next
            # wave (next_wave.deciding_runs)
            rows[0 if self.findings else -1]["discriminating_runs"] = json.dumps(self.discriminating_runs)
            cols = cols + ["discriminating_runs"]
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


def prepare_data(table: pd.DataFrame, factors: list[str], response: str, alpha: float | None,
                 log_factors: tuple[str, ...], fit: SurrogateFit | None = None) -> tuple[Data, SurrogateFit]:
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
    data = Data(response, list(factors), fit.coded, fit.y, runs, coding, float(alpha),
                tuple(log_factors), quadratic_terms(len(factors)), factor_round_off=fit.factor_round_off,
                blocks=blocks, block_labels=fit.blocks)
    return data, fit


def criticize(table: pd.DataFrame, factors: list[str], response: str, *, alpha: float | None = None,
              family_alpha: float = 0.05, log_factors: tuple[str, ...] = (), max_findings: int = 3,
              n_null: int = 1999, seed: int = 0, run_order: str | RunOrder = "performed",
              fit: SurrogateFit | None = None, run_candidates: np.ndarray | None = None,
              simulated: bool = False) -> CriticismResult:
    """Level-1 model criticism of the quadratic surrogate of one response.

    ``alpha`` is the CCD axial distance used for coding (None: inferred from the
    levels).  Runs with a missing response are dropped.  ``n_null`` Monte Carlo
    draws of the joint null (seeded with ``seed``: results are reproducible) give
    the family-adjusted p-values.  ``run_order`` is the declared order of the ``run`` column
    (``performed`` or ``unknown``), or the material's :class:`~demid.criticism.run_order.RunOrder`
    already assessed: drift is tested only where it can be believed.  ``fit`` is the response's
    quadratic fit already made (its coding is then the one used; None: fitted here).  ``run_candidates``
    (actual units) are the points the runs it proposes are chosen from (None: the design's levels within its
    reach).  ``simulated``: the table is demid's own simulations (a wave of a simulated material), so no run of it
    can carry a typing or export slip.  See the package docstring (demid.criticism) for the catalogue.
    """
    data, fit = prepare_data(table, list(factors), response, alpha, tuple(log_factors), fit)
    data = replace(data, simulated=simulated)
    if run_candidates is not None:
        actual = np.atleast_2d(np.asarray(run_candidates, dtype=float))
        data = replace(data, run_candidates=data.coding.to_coded(model_units(actual, list(factors),
                                                                            list(log_factors))))
    if not isinstance(run_order, RunOrder):
        run_order = assess_run_order(data.runs, data.coded, {response: data.y}, run_order)
    data = replace(data, drift_tested=run_order.drift_tested)
    base_model = Model(data, ModelForm())
    findings, model, catalogue, alias_sets, first_round, last_round, not_singled_out = _rounds(
        data, response, base_model, n_null, np.random.default_rng(seed), family_alpha, max_findings)
    findings, model, unexplained, naming = honest_causes(data, response, findings, model, base_model, first_round,
                                                         last_round, not_singled_out, family_alpha)
    candidates, runs = ambiguity(data, base_model, first_round, findings, not_singled_out)
    if candidates:  # the runs cannot tell these causes apart: none of them is named
        findings, model, unexplained = [], base_model, None
    else:  # a simulated run off the surface, or a misfit no cause explains: replicates let the next wave say why
        runs = replicate_runs(data, fit, findings, unexplained) or runs
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


def _rounds(data: Data, response: str, base_model: Model, n_null: int, rng: np.random.Generator,
            family_alpha: float, max_findings: int) -> tuple:
    """The catalogue's rounds: test, name the cause, add its extension, test again on the extended model.
    (findings, model, catalogue, alias sets, first round, last round, why the cause was not singled out)."""
    model = base_model
    findings: list[Finding] = []
    catalogue: list[dict] = []
    alias_sets: list[AliasSet] = []
    first_round = last_round = None
    not_singled_out = None
    for rnd_index in range(max_findings + 1):
        rnd = Round(data, model, n_null, rng)
        last_round = rnd
        if rnd_index == 0:
            first_round = rnd
            alias_sets = _alias_sets(data, rnd)
            catalogue = [catalogue_entry(data, h) for h in rnd.hypotheses]
        rejected = rnd.rejected(family_alpha)
        if not rejected or rnd_index == max_findings:
            break
        named = name_cause(data, model, rejected)
        if named is None:  # only a slip fits, and too weakly to be named: misfit without a cause
            break
        not_singled_out = why_not_singled_out(data, model, named[0], rnd.hypotheses)
        if not_singled_out is not None:
            break
        h, spec, info, new, alternatives = named
        both = new.predictable & model.predictable
        if findings and not new.loo_rmse_on(both) < model.loo_rmse_on(both):
            break  # a further extension must also predict left-out runs better
        findings.append(_finding(data, response, model, h, spec, info, new, alternatives,
                                 other_reading_of_the_run(h, rnd.hypotheses),
                                 scatter_aliases(data, model, h, new, rnd.hypotheses), first=not findings))
        model = new
        last_round = None
        if model.df_resid - 1 < 3 or model.spec.weight_on is not None:
            break  # too few spare runs, or estimated weights (further tests would not be exact)
    return findings, model, catalogue, alias_sets, first_round, last_round, not_singled_out


def _finding(data: Data, response: str, model: Model, h: Hypothesis, spec: ModelForm, info: dict, new: Model,
             alternatives: list[dict], other_reading: str | None = None,
             scatter_aliases: list[str] = (), first: bool = True) -> Finding:
    """The finding of one round: the named cause, its gain on the same runs, and its message; ``other_reading``
    of the same run (an outlier for a slip, a slip for an outlier) is listed as its alias, and so are the
    ``scatter_aliases`` of unequal scatter (the ``first`` finding's confirming runs separate them).  Alternatives
    less than 2 log-likelihood units below the named cause (not exactly 2) are quoted as almost as likely."""
    if h.cause == "response_transform":
        info["lam"] = spec.lam
    if h.cause == "drift":
        info["drift_per_run"] = drift_per_run(new)
    if h.cause == "step":
        info["step_size"] = step_size(new)
        info["runs_before"] = int(np.sum(data.runs.astype(float) < float(data.runs[int(h.detail)])))
    same = new.predictable & model.predictable
    before = model.loo_rmse_on(same)
    after = new.loo_rmse_on(same)
    extra_runs = []
    if h.cause == "missing_term" and len(h.detail.terms) > 1:
        pts = separating_runs(data.coded[model.keep], model.mean_terms, h.detail.terms, data.alpha)
        extra_runs = [data.point_dict(p) for p in pts]
    message = finding_message(data, h, info, before, after, int(same.sum()), extra_runs, model)
    if other_reading == "factor_level":
        message += (" A slipped factor value of the same run fits it too (a Bayes factor short of 20:1 either way): no "
                    "further run tells the two apart, the run's input does.")
    elif other_reading == "outlier":
        message += (f" The same evidence reads as an outlier of run {detail_json(data, h)} (the Bayes factor of the "
                    f"slip, {info['bayes_factor']:.1f}, is no decisive preference).")
    if scatter_aliases:
        others = ", ".join("the predicted value" if a == "fitted" else a for a in scatter_aliases[1:])
        message += (f" The scatter follows {others} as well or nearly so (AICc at most {AMBIGUOUS_AICC:g} worse): "
                    "these runs do not tell which" + ("; the runs proposed to confirm it are chosen to tell them "
                                                      "apart." if first else "."))
    close = [a for a in alternatives if a["loglik_vs_named"] is not None and a["loglik_vs_named"] > -2.0
             and not (a["cause"] == h.cause and a["detail"] in scatter_aliases)]
    if close:
        message += (" Almost as likely: " + "; ".join(f"{CAUSE_WORDS[a['cause']]} {a['detail']}" for a in close)
                    + ".")
    detail = transform_name(spec.lam) if h.cause == "response_transform" else detail_json(data, h)
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


def _gain(table: pd.DataFrame, factors: list[str], response: str, data: Data, fit, base_model: Model,
          model: Model, found: bool) -> tuple[dict, dict, dict]:
    """Baseline and extended model summaries and the gain of the extension (on the same runs)."""
    baseline = base_model.summary()
    stats_ = fit.statistics()
    baseline.update(lof_f=json_number(stats_.lof_f), lof_p=json_number(stats_.lof_p))
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
            extended.update(lof_f=json_number(st.lof_f), lof_p=json_number(st.lof_p))
    else:
        extended = dict(baseline)
    same = model.predictable & base_model.predictable
    loo_base_same = base_model.loo_rmse_on(same)
    loo_ext = model.loo_rmse_on(same)
    gain = {
        "loo_rmse_ratio": json_number(loo_ext / loo_base_same) if loo_base_same > 0 else None,
        "delta_aicc": json_number(model.aicc - base_model.aicc) if found else 0.0,
        "loo_rmse_baseline_same_runs": json_number(loo_base_same),
        "compared_runs": int(same.sum()),
    }
    if not found:
        gain["loo_rmse_ratio"] = 1.0
    return baseline, extended, gain


def _alias_sets(data: Data, rnd: Round) -> list[AliasSet]:
    out = []
    for c in rnd.classes:
        names = tuple(term_name(t, data.factors) for t in c.terms)
        runs = ()
        if len(c.terms) > 1 or c.direction is None:
            pts = separating_runs(data.coded[rnd.model.keep], rnd.model.mean_terms, c.terms, data.alpha)
            runs = tuple(data.point_dict(p) for p in pts)
        out.append(AliasSet(names[0], names, c.direction is not None, runs))
    return out


def _summary(data: Data, findings: list[Finding], catalogue: list[dict], family_alpha: float,
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
