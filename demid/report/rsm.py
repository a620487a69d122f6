"""Response-surface output as Design-Expert and R's rsm print it, from one fitted quadratic.

Per response: the fitted equation in coded and in actual units, the ANOVA by term block
(linear, two-factor interaction, pure quadratic; each block's partial sum of squares, i.e. the
extra sum of squares of dropping it from the full model), residual split into lack of fit and
pure error, the coefficient table and the stationary point of the surface.  Everything is
read off :class:`~demid.surrogate.SurrogateFit` (its statsmodels OLS in coded units) or, in the
report, off :class:`StoredFit`: the same numbers as the fit step stored them, without a refit.
"""

from __future__ import annotations

from dataclasses import dataclass
from types import SimpleNamespace

import numpy as np
import pandas as pd

BLOCKS = ("Linear", "Two-factor interaction", "Pure quadratic")


def term_block(term: tuple[int, ...]) -> str:
    """The block of one term: intercept, linear, two-factor interaction, pure quadratic, higher order."""
    order = sum(term)
    if order == 0:
        return "Intercept"
    if order == 1:
        return "Linear"
    if order == 2:
        return "Pure quadratic" if max(term) == 2 else "Two-factor interaction"
    return "Higher order"


def f_survival(f, dfn, dfd) -> np.ndarray:
    """``scipy.stats.f.sf(f, dfn, dfd)`` (:func:`demid.formulas.f_tail`, without importing scipy.stats, a
    second of the report kernel's start-up)."""
    from ..formulas import f_tail

    return f_tail(f, dfn, dfd)


class StoredFit:
    """One response's quadratic as the fit step stored it (``fits/{m}.parquet`` and
    ``fits/{m}_anova.parquet``), with the parts of :class:`~demid.surrogate.SurrogateFit` this
    module reads: the report prints the fits without fitting again (nor importing statsmodels).
    The design matrix is rebuilt from the validated table exactly as the fit built it."""

    def __init__(self, response: str, factors: list[str], coding, log_factors: tuple[str, ...],
                 coefficients: pd.DataFrame, anova: pd.DataFrame, table: pd.DataFrame):
        from ..blocks import block_columns, block_labels
        from ..design import model_matrix, model_units, parse_term

        self.response, self.factors, self.coding = response, list(factors), coding
        self.log_factors = tuple(log_factors)
        self._coefficients = coefficients.reset_index(drop=True)
        self.term_names = self._coefficients["term"].tolist()
        self.terms = [parse_term(n, self.factors) for n in self.term_names]
        rows = {r.source: r for r in anova.itertuples(index=False)}
        sub = table.loc[np.isfinite(table[response].to_numpy(dtype=float))]  # the runs fitted (fit_response)
        coded = coding.to_coded(model_units(sub[self.factors].to_numpy(dtype=float), self.factors, self.log_factors))
        column = {name: pd.Series(self._coefficients[name].to_numpy(), index=self.term_names)
                  for name in ("coefficient_coded", "std_err_coded", "t_value", "p_value")}
        residual = rows["Residual"]
        exog = model_matrix(coded, self.terms)
        labels = block_labels(sub)
        self.blocked = labels is not None
        if self.blocked:  # the fit's block terms (demid.blocks), after the polynomial's
            exog = np.column_stack([exog, block_columns(labels)])
        self.results = SimpleNamespace(
            params=column["coefficient_coded"], bse=column["std_err_coded"], tvalues=column["t_value"],
            pvalues=column["p_value"], ssr=float(residual.sum_sq), df_resid=float(residual.df),
            model=SimpleNamespace(exog=exog, endog=sub[response].to_numpy(dtype=float)))
        lof = rows["Lack of fit"]
        blocks = rows.get("Blocks")
        self._anova = SimpleNamespace(
            df_block=int(blocks.df) if blocks is not None else 0,
            ss_block=float(blocks.sum_sq) if blocks is not None else 0.0,
            df_model=int(rows["Model"].df), ss_model=float(rows["Model"].sum_sq),
            df_residual=int(residual.df), ss_residual=float(residual.sum_sq),
            df_lof=int(lof.df), ss_lof=float(lof.sum_sq), lof_f=(float(lof.F), float(lof.p_value)),
            df_pure_error=int(rows["Pure error"].df), ss_pure_error=float(rows["Pure error"].sum_sq),
            df_total=int(rows["Total (corrected)"].df), ss_total=float(rows["Total (corrected)"].sum_sq))

    def coefficients(self) -> pd.DataFrame:
        return self._coefficients

    def anova(self):
        return self._anova


def stored_fits(fits: pd.DataFrame, anova: pd.DataFrame, table: pd.DataFrame, spec) -> list[StoredFit]:
    """Every response's :class:`StoredFit`, in the order of ``spec``'s responses (as the fit step
    fitted them), in the coding the fit step stored with them (validation's)."""
    from ..surrogate import coding_from_frame

    coding = coding_from_frame(fits, spec.factor_names)
    return [StoredFit(r, spec.factor_names, coding, spec.log_factors, fits[fits["response"] == r],
                      anova[anova["response"] == r], table)
            for r in spec.response_names if (fits["response"] == r).any()]


def block_anova(fit) -> pd.DataFrame:
    """ANOVA: model and its blocks (partial SS), residual, lack of fit, pure error, total."""
    res = fit.results
    x = res.model.exog
    y = res.model.endog
    sse_full = float(res.ssr)
    df_resid = int(round(res.df_resid))
    mse = sse_full / df_resid if df_resid > 0 else np.nan
    blocks = [term_block(t) for t in fit.terms]
    lof = fit.anova()
    # runs made in blocks (demid.blocks): their row first, their columns kept in every reduced fit
    rows = [("Blocks", lof.df_block, lof.ss_block)] if getattr(lof, "df_block", 0) else []
    rows.append(("Model", lof.df_model, lof.ss_model))
    beyond = list(range(len(blocks), x.shape[1]))
    for block in dict.fromkeys(b for b in blocks if b != "Intercept"):
        keep = [i for i, b in enumerate(blocks) if b != block] + beyond
        beta, *_ = np.linalg.lstsq(x[:, keep], y, rcond=None)
        sse_reduced = float(np.sum((y - x[:, keep] @ beta) ** 2))
        rows.append((f"↳ {block}", len(blocks) - len(keep), sse_reduced - sse_full))
    frame = pd.DataFrame(rows, columns=["source", "df", "sum_sq"])
    frame["mean_sq"] = frame["sum_sq"] / frame["df"]
    frame["F"] = frame["mean_sq"] / mse
    frame["p_value"] = f_survival(frame["F"], frame["df"], df_resid)
    lof_f, lof_p = lof.lof_f
    tail = pd.DataFrame([
        ("Residual", lof.df_residual, lof.ss_residual, np.nan, np.nan),
        ("↳ Lack of fit", lof.df_lof, lof.ss_lof, lof_f, lof_p),
        ("↳ Pure error", lof.df_pure_error, lof.ss_pure_error, np.nan, np.nan),
        ("Total (corrected)", lof.df_total, lof.ss_total, np.nan, np.nan),
    ], columns=["source", "df", "sum_sq", "F", "p_value"])
    tail["mean_sq"] = np.where(tail["df"] > 0, tail["sum_sq"] / tail["df"].clip(lower=1), np.nan)
    return pd.concat([frame, tail], ignore_index=True)[["source", "df", "sum_sq", "mean_sq", "F", "p_value"]]


def coefficient_table(fit) -> pd.DataFrame:
    """Estimate (coded units), standard error, t and p per term."""
    res = fit.results
    return pd.DataFrame({"term": fit.term_names, "estimate": res.params.to_numpy(), "std_error": res.bse.to_numpy(),
                         "t": res.tvalues.to_numpy(), "p_value": res.pvalues.to_numpy()})


def _symbol(name: str, symbols: dict[str, str]) -> str:
    return ":".join(symbols.get(p.split("^")[0], p.split("^")[0]) + ("²" if p.endswith("^2") else "")
                    for p in name.split(":"))


#: Coefficients smaller than this fraction of the largest are floating-point round-off of a term
#: the data do not carry (1.8e-12·A·B beside terms of order 1): left out of printed equations.
ROUND_OFF_FRACTION = 1e-9


def equation(names: list[str], coefficients, symbols: dict[str, str], response: str, digits: int = 4) -> str:
    """``y = b0 + b1·x1 − …`` with ``·`` between factors of a term; terms at round-off are left out."""
    floor = ROUND_OFF_FRACTION * max((abs(float(b)) for b in coefficients), default=0.0)
    b0 = float(coefficients[0])
    text = f"{response} = {0.0 if abs(b0) <= floor else b0:.{digits}g}"
    for name, b in zip(names[1:], coefficients[1:]):
        if abs(float(b)) <= floor:
            continue
        text += f" {'−' if b < 0 else '+'} {abs(b):.{digits}g}·" + _symbol(name, symbols).replace(":", "·")
    return text


@dataclass(frozen=True)
class StationaryPoint:
    coded: np.ndarray
    actual: np.ndarray
    value: float
    kind: str          # maximum, minimum, saddle point, none (singular quadratic part)
    inside: bool       # within the search range Ω


def stationary_point(fit, lower, upper) -> StationaryPoint:
    """x_s = −½ B⁻¹ b of the coded quadratic; its kind from the eigenvalues of B; inside Ω or not."""
    k = len(fit.factors)
    params = fit.results.params.to_numpy()
    b = np.zeros(k)
    big_b = np.zeros((k, k))
    for term, coef in zip(fit.terms, params):
        idx = [i for i, p in enumerate(term) for _ in range(p)]
        if len(idx) == 1:
            b[idx[0]] = coef
        elif len(idx) == 2:
            i, j = idx
            big_b[i, j] += coef if i == j else coef / 2
            if i != j:
                big_b[j, i] += coef / 2
    eig = np.linalg.eigvalsh(big_b)
    if np.min(np.abs(eig)) < 1e-12 * max(1.0, np.max(np.abs(eig))):
        nan = np.full(k, np.nan)
        return StationaryPoint(nan, nan, float("nan"), "none (singular quadratic part)", False)
    xs = -0.5 * np.linalg.solve(big_b, b)
    actual_model = fit.coding.to_actual(xs[None, :])[0]
    actual = np.array([10 ** v if f in fit.log_factors else v for f, v in zip(fit.factors, actual_model)])
    value = float(params[0] + 0.5 * b @ xs)
    kind = "maximum" if np.all(eig < 0) else "minimum" if np.all(eig > 0) else "saddle point"
    inside = bool(np.all(actual >= np.asarray(lower) - 1e-12) and np.all(actual <= np.asarray(upper) + 1e-12))
    return StationaryPoint(xs, actual, value, kind, inside)


def canonical_text(canonical: dict | None, fit, spec, letters: dict[str, str], label: str) -> str:
    """The canonical analysis in words (as rsm's ``canonical()``): eigenvalues and eigenvectors of the
    quadratic part, the kind, the stationary point (coded and actual) and whether it lies inside the
    region of the runs; for a ridge, the ridge point nearest the design centre and the ridge direction.
    ``canonical`` is the fit JSON's entry (``fits/{material}.json``); computed here only when absent."""
    if canonical is None:
        from ..canonical import fit_canonical

        canonical = fit_canonical(fit).to_json()
    names = [letters[f] for f in fit.factors]

    def number(v, digits):  # the stored JSON writes NaN (and what overflowed) as null
        return "–" if v is None or v != v else f"{v:.{digits}g}"

    def point(coded, actual):
        return (", ".join(f"{n} = {number(v, 3)}" for n, v in zip(names, coded)) + " (coded), "
                + ", ".join(f"{spec.factor(f).label} = {number(v, 4)}" for f, v in zip(fit.factors, actual)))

    def vector(vec):
        return "(" + ", ".join(f"{n} {x:+.3f}" for n, x in zip(names, vec)) + ")"

    values = ", ".join(f"{v:.4g}" for v in canonical["eigenvalues"])
    text = (f"Canonical analysis (eigenvalues below {canonical['threshold']:.3g}, a tenth of the largest, count as "
            f"zero): eigenvalues {values}; eigenvectors " + "; ".join(vector(v) for v in canonical["eigenvectors"])
            + ". ")
    finite = all(v is not None and v == v for v in canonical["stationary_coded"])  # null/NaN: B is singular
    where = "inside" if canonical["inside"] else "outside"
    stationary = (f"stationary point {point(canonical['stationary_coded'], canonical['stationary_actual'])}, "
                  f"predicted {label} = {number(canonical['predicted'], 4)}, {where} the region of the runs" if finite
                  else "no stationary point (the quadratic part is singular)")
    if "ridge" in canonical["kind"]:
        ridge = "; ".join(vector(v) for v in canonical.get("ridge_directions", []))
        slope = ", ".join(f"{v:.3g}" for v in canonical.get("ridge_slopes", []))
        text += (f"A **{canonical['kind']}** along {ridge} (slope {slope} per coded unit): the response "
                 + ("keeps rising one way along it, up to the edge of the region" if canonical["kind"] == "rising ridge"
                    else "hardly changes along it, a line of near-equal responses")
                 + f"; {stationary}. The ridge point nearest the design centre, within the region: "
                 f"{point(canonical['ridge_point_coded'], canonical['ridge_point_actual'])}, predicted {label} = "
                 f"{number(canonical['ridge_predicted'], 4)}.")
    else:
        text += f"A **{canonical['kind']}**: {stationary}."
    return text
