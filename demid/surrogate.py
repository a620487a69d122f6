"""Quadratic response-surface surrogates fitted by statsmodels OLS, with diagnostics.

The fit keeps the statsmodels results object (``SurrogateFit.results``);
diagnostics are small dataclasses with ``to_frame()`` (:mod:`demid.fit_statistics`).  Everything downstream
of the fit (grids, admissibility, uncertainty) uses the light
:class:`Surrogate` predictor, which is what ``fits/{material}.parquet`` stores.
"""

from __future__ import annotations

import warnings
from dataclasses import dataclass, field
from functools import cached_property
from typing import TYPE_CHECKING

import numpy as np
import pandas as pd

from .blocks import block_columns, block_effects, block_labels, block_levels, pure_error_groups
from .design import LEVERAGE_UNPREDICTABLE, Coding, Term, model_matrix, model_units, parse_term, quadratic_terms, term_name
from .fit_statistics import Diagnostics, FitStatistics, LackOfFitAnova, pure_error_ss
from .precision import factor_round_off_sd, round_off_floor, round_off_only

if TYPE_CHECKING:
    from .spec import MaterialSpec


#: Up to this many runs the studentised residuals refit without each run (statsmodels' own loop).
LOO_REFIT_MAX_RUNS = 200


# --------------------------------------------------------------------------- predictor
@dataclass
class Surrogate:
    """A fitted polynomial in model units (actual units, or log10 for log-scale factors)."""

    response: str
    factors: list[str]
    terms: list[Term]
    coefficients: np.ndarray
    covariance: np.ndarray
    resid_var: float
    resid_df: int
    log_factors: tuple[str, ...] = field(default_factory=tuple)

    def model_units(self, points) -> np.ndarray:
        return model_units(points, self.factors, self.log_factors)

    def predict(self, points, chunk: int = 65_536) -> np.ndarray:
        return predict_all({self.response: self}, points, chunk)[self.response]

    def se_mean(self, points, chunk: int = 65_536) -> np.ndarray:
        """Standard error of the fitted mean (statsmodels' ``mean_se``)."""
        z = self.model_units(points)
        out = np.empty(z.shape[0])
        for start in range(0, z.shape[0], chunk):
            m = model_matrix(z[start:start + chunk], self.terms)
            out[start:start + chunk] = np.sqrt(np.einsum("ij,jk,ik->i", m, self.covariance, m))
        return out

    def se_prediction(self, points) -> np.ndarray:
        """Standard error for a new observation (``obs_se``): sqrt(se_mean^2 + sigma^2)."""
        return np.sqrt(self.se_mean(points) ** 2 + self.resid_var)

    @property
    def term_names(self) -> list[str]:
        return [term_name(t, self.factors) for t in self.terms]


def predict_all(surrogates: dict[str, Surrogate], points, chunk: int = 65_536) -> dict[str, np.ndarray]:
    """Every surrogate's :meth:`Surrogate.predict` at ``points``; surrogates on the same terms share
    one model matrix per chunk (the same numbers, built once: on a 3-factor grid of 8 million
    nodes each matrix costs a second).  Other fields with a ``predict`` method are asked directly."""
    groups: dict[tuple, list[str]] = {}
    out = {}
    for name, sur in surrogates.items():
        if isinstance(sur, Surrogate):
            key = (tuple(sur.factors), tuple(sur.log_factors), tuple(tuple(t) for t in sur.terms))
            groups.setdefault(key, []).append(name)
        else:
            out[name] = sur.predict(points)
    points = np.asarray(points, dtype=float)
    points = points.reshape(1, -1) if points.ndim == 1 else points
    for names in groups.values():
        first = surrogates[names[0]]
        for name in names:
            out[name] = np.empty(points.shape[0])
        for start in range(0, points.shape[0], chunk):  # model units a chunk at a time: no copy of all points
            matrix = model_matrix(first.model_units(points[start:start + chunk]), first.terms)
            for name in names:
                out[name][start:start + chunk] = matrix @ surrogates[name].coefficients
    return {name: out[name] for name in surrogates}


# --------------------------------------------------------------------------- fit
#: The term groups of a quadratic whose partial sums of squares the ANOVA gives (as Design-Expert and R's rsm).
TERM_BLOCKS = ("Linear", "Two-factor interaction", "Pure quadratic")


def term_block(term: tuple[int, ...]) -> str:
    """The group of one term: intercept, linear, two-factor interaction, pure quadratic, higher order."""
    order = sum(term)
    if order == 0:
        return "Intercept"
    if order == 1:
        return "Linear"
    if order == 2:
        return "Pure quadratic" if max(term) == 2 else "Two-factor interaction"
    return "Higher order"


class SurrogateFit:
    """OLS fit of one response on a polynomial (default: full quadratic) in coded units."""

    def __init__(self, response: str, factors: list[str], x_actual: np.ndarray, y: np.ndarray,
                 runs: np.ndarray, coding: Coding, terms: list[Term] | None = None,
                 log_factors: tuple[str, ...] = (), blocks=None):
        self.response = response
        self.factors = list(factors)
        self.x_actual = np.asarray(x_actual, dtype=float)
        self.y = np.asarray(y, dtype=float)
        self.runs = np.asarray(runs)
        self.coding = coding
        self.terms = list(terms) if terms is not None else quadratic_terms(len(factors))
        self.log_factors = tuple(log_factors)
        # statsmodels is imported here, not at module level: grid and scenario jobs only need
        # the light Surrogate predictor and should not pay for its import.
        # (the OLS class itself: statsmodels.api would also import its graphics and time-series modules)
        from statsmodels.regression.linear_model import OLS

        self.coded = coding.to_coded(model_units(self.x_actual, self.factors, self.log_factors))
        # runs in blocks (demid.blocks): effect-coded block terms after the polynomial's, so the
        # polynomial's intercept is the block average and its coefficients are what the predictor uses
        self.blocks = None if blocks is None or len(set(blocks)) < 2 else np.asarray(blocks, dtype=object)
        self.block_levels = block_levels(self.blocks) if self.blocks is not None else []
        columns = model_matrix(self.coded, self.terms)
        names = self.term_names
        if self.blocks is not None:
            columns = np.column_stack([columns, block_columns(self.blocks, self.block_levels)])
            names = names + [f"block[{lv}]" for lv in self.block_levels[:-1]]
        exog = pd.DataFrame(columns, columns=names)
        endog = pd.Series(self.y, name=response)
        self.results = OLS(endog, exog).fit()

    @property
    def term_names(self) -> list[str]:
        return [term_name(t, self.factors) for t in self.terms]

    @property
    def n_runs(self) -> int:
        return len(self.y)

    @property
    def n_params(self) -> int:
        """Coefficients fitted: the polynomial's and one per block beyond the first."""
        return len(self.terms) + self.n_block_params

    @property
    def n_block_params(self) -> int:
        return max(len(self.block_levels) - 1, 0)

    def block_effects(self) -> dict[str, tuple[float, float]]:
        """{block label: (shift from the block average, standard error)}; empty without blocks."""
        if self.blocks is None:
            return {}
        p = len(self.terms)
        cov = np.asarray(self.results.cov_params())[p:, p:]
        return block_effects(self.results.params.to_numpy()[p:], cov, self.block_levels)

    @cached_property
    def hat_diag(self) -> np.ndarray:
        x = self.results.model.exog
        q, _ = np.linalg.qr(x)
        return np.sum(q * q, axis=1)

    @cached_property
    def fitted_exactly(self) -> np.ndarray:
        """Runs the others do not predict (leverage 1, or 1 blurred by rounded levels): the fit follows
        them whatever their value, so their leave-one-out statistics are undefined."""
        return self.hat_diag >= LEVERAGE_UNPREDICTABLE

    @cached_property
    def factor_round_off(self) -> np.ndarray:
        """Per run, the standard deviation of the response error that the factors' printed precision adds
        (the fitted gradient times each factor's rounding): an exact polynomial whose factors were printed
        to 6 decimals misses by that much, and that is no defect."""
        beta = self.results.params.to_numpy()
        k = len(self.factors)
        gradient = np.zeros((self.n_runs, k))
        for j in range(k):
            lowered, weights = [], []
            for term, b in zip(self.terms, beta):
                if term[j]:
                    lowered.append(tuple(p - (i == j) for i, p in enumerate(term)))
                    weights.append(b * term[j])
            if lowered:
                gradient[:, j] = model_matrix(self.coded, lowered) @ np.array(weights)
        return factor_round_off_sd(gradient, self.x_actual, self.coding.unit,
                                   [f in self.log_factors for f in self.factors])

    @cached_property
    def loo_residuals(self) -> np.ndarray:
        """Leave-one-out (PRESS) residuals e / (1 - h); NaN for runs fitted exactly."""
        with np.errstate(divide="ignore", invalid="ignore"):
            return np.where(self.fitted_exactly, np.nan, self.results.resid.to_numpy() / (1.0 - self.hat_diag))

    @cached_property
    def press(self) -> float:
        return np.nan if self.fitted_exactly.any() else float(np.sum(self.loo_residuals ** 2))

    @cached_property
    def term_block_ss(self) -> list[tuple[str, int, float]]:
        """Per term group (:func:`term_block`), its degrees of freedom and partial sum of squares: the increase
        of the residual sum of squares when the group is dropped from the full model (block terms kept)."""
        res = self.results
        x, y = np.asarray(res.model.exog), np.asarray(res.model.endog)
        sse_full = float(res.ssr)
        blocks = [term_block(t) for t in self.terms]
        beyond = list(range(len(blocks), x.shape[1]))  # the block terms (demid.blocks): in every reduced fit
        out = []
        for block in dict.fromkeys(b for b in blocks if b != "Intercept"):
            dropped = [i for i, b in enumerate(blocks) if b == block]
            keep = [i for i, b in enumerate(blocks) if b != block] + beyond
            beta, *_ = np.linalg.lstsq(x[:, keep], y, rcond=None)
            sse_reduced = float(np.sum((y - x[:, keep] @ beta) ** 2))
            out.append((block, len(dropped), sse_reduced - sse_full))
        return out

    def anova_frame(self) -> pd.DataFrame:
        """The ANOVA the fit step stores (``fits/{material}_anova.parquet``): :meth:`anova`'s table with each
        term group's partial sum of squares, F and p after the Model row (the report renders it as it is)."""
        anova = self.anova()
        frame = anova.to_frame()
        groups = []
        for block, df, ss in self.term_block_ss:
            f, p = anova._f(ss, df, anova.ss_residual, anova.df_residual)
            groups.append({"response": self.response, "source": block, "df": df, "sum_sq": ss,
                           "mean_sq": ss / df if df > 0 else np.nan, "F": f, "p_value": p, "note": ""})
        if not groups:
            return frame
        at = int(np.flatnonzero(frame["source"].to_numpy() == "Model")[0]) + 1
        return pd.concat([frame.iloc[:at], pd.DataFrame(groups, columns=frame.columns), frame.iloc[at:]],
                         ignore_index=True)

    def anova(self) -> LackOfFitAnova:
        res = self.results
        sse = float(res.ssr)
        sst = float(np.sum((self.y - self.y.mean()) ** 2))
        groups = pure_error_groups(self.coded, self.blocks)  # replicates within their block
        n_unique = int(groups.max()) + 1 if len(groups) else 0
        ss_pe = pure_error_ss(self.y, groups)
        df_pe = self.n_runs - n_unique
        df_res = int(round(res.df_resid))
        ss_block = 0.0
        if self.blocks is not None:  # blocks first: the spread of the block means
            ss_block = sst - pure_error_ss(self.y, pure_error_groups(np.zeros((self.n_runs, 1)), self.blocks))
        return LackOfFitAnova(
            response=self.response,
            ss_model=sst - sse - ss_block, df_model=len(self.terms) - 1,
            ss_block=ss_block, df_block=self.n_block_params,
            ss_residual=sse, df_residual=df_res,
            ss_lof=sse - ss_pe, df_lof=df_res - df_pe,
            ss_pure_error=ss_pe, df_pure_error=df_pe,
            ss_total=sst, df_total=self.n_runs - 1,
            ss_floor=round_off_floor(self.y) ** 2,
        )

    def statistics(self) -> FitStatistics:
        res = self.results
        sse = float(res.ssr)
        sst = float(np.sum((self.y - self.y.mean()) ** 2))
        n, p = self.n_runs, self.n_params
        lof_f, lof_p = self.anova().lof_f
        return FitStatistics(
            response=self.response, n_runs=n, n_params=p,
            r2=1.0 - sse / sst if sst > 0 else np.nan,
            adj_r2=1.0 - (sse / (n - p)) / (sst / (n - 1)) if sst > 0 and n > p else np.nan,
            rmse=float(np.sqrt(sse / n)),
            resid_std=float(np.sqrt(sse / (n - p))) if n > p else np.nan,
            press=self.press,
            q2=1.0 - self.press / sst if sst > 0 else np.nan,
            lof_f=lof_f, lof_p=lof_p,
        )

    def influence(self) -> pd.DataFrame:
        """Per-run externally studentised residuals, leverage and Cook's distance (statsmodels)."""
        with warnings.catch_warnings(), np.errstate(divide="ignore", invalid="ignore"):
            warnings.simplefilter("ignore", RuntimeWarning)
            frame = self._influence_columns()
        if round_off_only(self.results.resid.to_numpy(), self.y):
            # 0/0: residuals and their scale are both round-off, their ratio is noise (up to 1e136)
            frame["student_resid"] = np.nan
            frame["cooks_d"] = np.nan
        # Dividing a leverage-1 run's round-off residual by 1 - h gives noise of any size (Cook's
        # d ~ 2e4 seen), not a statistic.
        frame.loc[self.fitted_exactly, ["student_resid", "cooks_d"]] = np.nan
        out = pd.DataFrame({
            "response": self.response,
            "run": self.runs,
            "observed": self.y,
            "fitted": self.results.fittedvalues.to_numpy(),
            "residual": self.results.resid.to_numpy(),
            "loo_residual": self.loo_residuals,
            "student_resid": frame["student_resid"].to_numpy(),
            "leverage": frame["hat_diag"].to_numpy(),
            "cooks_d": frame["cooks_d"].to_numpy(),
        })
        return out

    def _influence_columns(self) -> pd.DataFrame:
        """statsmodels' externally studentised residuals, leverage and Cook's distance.  Its studentised
        residuals refit without each run (n fits of n runs); above :data:`LOO_REFIT_MAX_RUNS` runs the
        scale without run i comes from the identity s_(i)^2 = (SSE - e_i^2 / (1 - h_i)) / (n - rank - 1)
        instead (equal to round-off), so that a large table costs one fit."""
        influence = self.results.get_influence()
        if self.n_runs <= LOO_REFIT_MAX_RUNS:
            return influence.summary_frame()
        e, h = self.results.resid.to_numpy(), influence.hat_matrix_diag
        scale_without = (float(np.sum(e ** 2)) - e ** 2 / (1.0 - h)) / (self.results.df_resid - 1)
        return pd.DataFrame({"student_resid": influence.get_resid_studentized_external(sigma=np.sqrt(scale_without)),
                             "hat_diag": h, "cooks_d": influence.cooks_distance[0]})

    def diagnostics(self) -> Diagnostics:
        from scipy import stats
        from statsmodels.stats.diagnostic import het_breuschpagan, linear_reset
        from statsmodels.stats.outliers_influence import variance_inflation_factor

        res = self.results
        exog = res.model.exog
        nan = float("nan")
        with warnings.catch_warnings(), np.errstate(all="ignore"):
            warnings.simplefilter("ignore")
            try:
                bp_lm, bp_p, _, _ = het_breuschpagan(res.resid, exog)
            except Exception:  # noqa: BLE001 - degenerate designs (e.g. perfect fit)
                bp_lm, bp_p = nan, nan
            try:
                reset = linear_reset(res, power=2, use_f=True)
                reset_f, reset_p = float(reset.fvalue), float(reset.pvalue)
            except Exception:  # noqa: BLE001
                reset_f, reset_p = nan, nan
            try:
                sw, sp = stats.shapiro(res.resid) if self.n_runs >= 3 else (nan, nan)
            except Exception:  # noqa: BLE001
                sw, sp = nan, nan
            vifs = [variance_inflation_factor(exog, j) for j in range(1, exog.shape[1])]
            infl = self.influence()
            if round_off_only(res.resid.to_numpy(), self.y):  # tests of round-off say nothing about the fit
                bp_lm = bp_p = reset_f = reset_p = sw = sp = nan
            max_cooks = float(np.nanmax(infl["cooks_d"])) if infl["cooks_d"].notna().any() else nan
            max_student = (float(np.nanmax(np.abs(infl["student_resid"])))
                           if infl["student_resid"].notna().any() else nan)
        return Diagnostics(
            response=self.response,
            breusch_pagan_lm=float(bp_lm), breusch_pagan_p=float(bp_p),
            reset_f=reset_f, reset_p=reset_p,
            shapiro_w=float(sw), shapiro_p=float(sp),
            max_vif=float(np.nanmax(vifs)) if vifs else nan,
            max_cooks_d=max_cooks,
            max_abs_student_resid=max_student,
        )

    # ---- coefficients in coded and model (actual) units
    def _coded_to_actual_matrix(self) -> np.ndarray:
        """Linear map M with beta_actual = M @ beta_coded (exact: same polynomial space)."""
        k = len(self.factors)
        degree = max(max(t) for t in self.terms) if self.terms else 0
        levels = np.linspace(-1, 1, degree + 1)
        pts = np.array(np.meshgrid(*[levels] * k, indexing="ij")).reshape(k, -1).T
        a_coded = model_matrix(pts, self.terms)
        a_actual = model_matrix(self.coding.to_actual(pts), self.terms)
        return np.linalg.lstsq(a_actual, a_coded, rcond=None)[0]

    def coefficients(self) -> pd.DataFrame:
        res = self.results
        m = self._coded_to_actual_matrix()
        p = len(self.terms)  # the block terms are reported by block_effects()
        return pd.DataFrame({
            "response": self.response,
            "term": self.term_names,
            "coefficient_coded": res.params.to_numpy()[:p],
            "std_err_coded": res.bse.to_numpy()[:p],
            "t_value": res.tvalues.to_numpy()[:p],
            "p_value": res.pvalues.to_numpy()[:p],
            "coefficient_actual": m @ res.params.to_numpy()[:p],
        })

    def surrogate(self) -> Surrogate:
        m = self._coded_to_actual_matrix()
        p = len(self.terms)  # with blocks: the block-averaged surface (the response at the mean block effect)
        cov = np.asarray(self.results.cov_params())[:p, :p]
        return Surrogate(
            response=self.response, factors=self.factors, terms=self.terms,
            coefficients=m @ self.results.params.to_numpy()[:p], covariance=m @ cov @ m.T,
            resid_var=float(self.results.scale), resid_df=int(round(self.results.df_resid)),
            log_factors=self.log_factors,
        )


def fit_response(table: pd.DataFrame, factors: list[str], response: str, *, alpha: float = 1.0,
                 coding: Coding | None = None, terms: list[Term] | None = None,
                 log_factors: tuple[str, ...] = ()) -> SurrogateFit:
    """Fit one response, dropping runs where it is missing (failed simulations); a ``block`` column
    (demid.blocks) adds a block term."""
    if coding is None:
        coding = Coding.from_levels(factors, model_units(table[factors].to_numpy(), factors, log_factors), alpha)
    ok = np.isfinite(table[response].to_numpy(dtype=float))
    sub = table.loc[ok]
    runs = sub["run"].to_numpy() if "run" in sub.columns else np.arange(1, len(sub) + 1)
    return SurrogateFit(response, factors, sub[factors].to_numpy(dtype=float),
                        sub[response].to_numpy(dtype=float), runs, coding, terms, log_factors,
                        blocks=block_labels(sub))


# --------------------------------------------------------------------------- parquet round trip
def surrogates_to_frame(fits: list[SurrogateFit]) -> pd.DataFrame:
    """Long table: one row per response x term, coefficients and covariance in actual units, and the
    design coding the fit used (``center:<factor>``, ``unit:<factor>``; see :func:`coding_from_frame`)."""
    frames = []
    for fit in fits:
        coef = fit.coefficients()
        sur = fit.surrogate()
        cov = pd.DataFrame(sur.covariance, columns=[f"cov:{n}" for n in sur.term_names])
        coef["resid_var"] = sur.resid_var
        coef["resid_df"] = sur.resid_df
        coef["log_factors"] = ",".join(sur.log_factors)
        for factor, center, unit in zip(fit.coding.factors, fit.coding.center, fit.coding.unit):
            coef[f"center:{factor}"] = center
            coef[f"unit:{factor}"] = unit
        frames.append(pd.concat([coef.reset_index(drop=True), cov], axis=1))
    return pd.concat(frames, ignore_index=True)


def coding_from_frame(frame: pd.DataFrame, factors: list[str]) -> Coding:
    """The design coding stored with the fits (one coding per material: validation's)."""
    first = frame.iloc[0]
    return Coding(tuple(factors), tuple(float(first[f"center:{f}"]) for f in factors),
                  tuple(float(first[f"unit:{f}"]) for f in factors))


def surrogates_from_frame(frame: pd.DataFrame, factors: list[str]) -> dict[str, Surrogate]:
    out = {}
    for response, rows in frame.groupby("response", sort=False):
        names = rows["term"].tolist()
        cov = rows[[f"cov:{n}" for n in names]].to_numpy(dtype=float)
        logs = rows["log_factors"].iloc[0]
        out[response] = Surrogate(
            response=response, factors=list(factors), terms=[parse_term(n, factors) for n in names],
            coefficients=rows["coefficient_actual"].to_numpy(dtype=float), covariance=cov,
            resid_var=float(rows["resid_var"].iloc[0]), resid_df=int(rows["resid_df"].iloc[0]),
            log_factors=tuple(x for x in logs.split(",") if x),
        )
    return out


# --------------------------------------------------------------------------- per-material step
def fit_material(table: pd.DataFrame, spec: MaterialSpec, coding: Coding | None = None) -> list[SurrogateFit]:
    """Quadratic fit of every response of a validated table, in the declared design's coding.

    ``spec`` is the material's :class:`~demid.spec.MaterialSpec`; ``coding`` is the one validation
    inferred (None: inferred here the same way).
    """
    from .design_check import infer_coding

    factors, log_factors = spec.factor_names, spec.log_factors
    if coding is None:
        coding = infer_coding(table, factors, spec.design, spec.data, log_factors)
    return [fit_response(table, factors, r, coding=coding, log_factors=log_factors) for r in spec.response_names]


def fit_frames(fits: list[SurrogateFit]) -> dict[str, pd.DataFrame]:
    """The parquet intermediates of the fit step, keyed by output name."""
    return {
        "fits": surrogates_to_frame(fits),
        "statistics": pd.concat([f.statistics().to_frame() for f in fits], ignore_index=True),
        "anova": pd.concat([f.anova_frame() for f in fits], ignore_index=True),
        "diagnostics": pd.concat([f.diagnostics().to_frame() for f in fits], ignore_index=True),
    }
